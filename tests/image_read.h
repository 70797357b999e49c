// image_read.h: reading images back in tests (OpenImageIO), rows as stored (first scanline first).
#pragma once

#include <OpenImageIO/imageio.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

struct ImageSize {
    int width = 0;
    int height = 0;
    int channels = 0;
};

inline ImageSize readImageSize(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    const OIIO::ImageSpec& spec = in->spec();
    return {spec.width, spec.height, spec.nchannels};
}

// The channel names in the order readImageFloats returns them.
inline std::vector<std::string> readImageChannelNames(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    return in->spec().channelnames;
}

// All pixels as floats; throws unless the image has `channels` channels.
inline std::vector<float> readImageFloats(const std::string& path, int channels) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels != channels) throw std::runtime_error(path + ": wrong channel count");
    std::vector<float> data(static_cast<size_t>(spec.width) * spec.height * channels);
    in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data());
    return data;
}

inline std::vector<unsigned char> readImageBytes(const std::string& path, int channels) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels != channels) throw std::runtime_error(path + ": wrong channel count");
    std::vector<unsigned char> data(static_cast<size_t>(spec.width) * spec.height * channels);
    in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, data.data());
    return data;
}
