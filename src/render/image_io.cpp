#include "render/image_io.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <random>
#include <system_error>

namespace pcf {

namespace {

// OIIO's messages can run over several lines; ours are one line.
std::string firstLine(std::string s) {
    size_t end = s.find('\n');
    if (end != std::string::npos) s.resize(end);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.pop_back();
    return s.empty() ? "unknown error" : s;
}

// PATH.tmp-XXXXXX next to PATH (same directory, so the rename is atomic). Not mkstemp: that
// creates the file 0600, and the rename would carry those permissions to the image.
std::string tempPathFor(const std::string& path) {
    static const char LETTERS[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    static std::mutex mutex;
    static std::mt19937 random{std::random_device{}()};
    std::lock_guard lock(mutex);
    std::uniform_int_distribution<int> pick(0, static_cast<int>(sizeof LETTERS) - 2);
    for (;;) {
        std::string temp = path + ".tmp-";
        for (int k = 0; k < 6; ++k) temp += LETTERS[pick(random)];
        std::error_code ec;
        if (std::filesystem::symlink_status(temp, ec).type() ==
            std::filesystem::file_type::not_found) {
            return temp;
        }
    }
}

// Writes through a temporary file and renames it over `path`. The plugin is chosen from the
// final path's extension: the temporary name has none OIIO knows.
void writeImageAtomically(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                          const void* data) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) throw ImageError(path + ": cannot write image (" + firstLine(OIIO::geterror()) + ")");
    std::string temp = tempPathFor(path);
    std::string reason;
    if (!out->open(temp, spec) || !out->write_image(type, data) || !out->close()) {
        reason = firstLine(out->geterror());
        // The temporary name is ours, not the user's: report the path they asked for.
        for (size_t at; (at = reason.find(temp)) != std::string::npos;) {
            reason.replace(at, temp.size(), path);
        }
    }
    out.reset();
    std::error_code ec;
    if (reason.empty()) {
        std::filesystem::rename(temp, path, ec);
        if (ec) reason = ec.message();
    }
    if (!reason.empty()) {
        std::filesystem::remove(temp, ec);
        throw ImageError(path + ": cannot write image (" + reason + ")");
    }
}

}  // namespace

void writeTextFile(const std::string& path, const std::string& text) {
    std::string temp = tempPathFor(path);
    std::error_code ec;
    {
        std::ofstream f(temp, std::ios::binary | std::ios::trunc);
        f << text;
        f.close();
        if (!f) {
            std::filesystem::remove(temp, ec);
            throw ImageError(path + ": cannot write file");
        }
    }
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        throw ImageError(path + ": cannot write file (" + ec.message() + ")");
    }
}

namespace {

void checkSize(const std::string& path, int width, int height, size_t have, size_t perPixel) {
    if (width <= 0 || height <= 0) {
        throw ImageError(path + ": cannot write image (size " + std::to_string(width) + " x " +
                         std::to_string(height) + ")");
    }
    size_t need = static_cast<size_t>(width) * height * perPixel;
    if (have != need) {
        throw ImageError(path + ": cannot write image (" + std::to_string(have) + " values for " +
                         std::to_string(need) + ")");
    }
}

}  // namespace

void writePngRgba8(const std::string& path, int width, int height, std::span<const uint8_t> rgba) {
    checkSize(path, width, height, rgba.size(), 4);
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
    // The bytes are PNG's own straight (unassociated) alpha: without this OIIO would take them
    // as premultiplied and divide the colour by alpha on the way out.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    // zlib level 1: exported frames are flat UI colours and compress well anyway, and at the
    // default level 6 compression was a third of an export's time.
    spec.attribute("png:compressionLevel", 1);
    writeImageAtomically(path, spec, OIIO::TypeDesc::UINT8, rgba.data());
}

void writeExr(const std::string& path, int width, int height, int channels,
              std::span<const float> data, const std::vector<std::string>& channelNames) {
    if (channels < 1 || static_cast<size_t>(channels) != channelNames.size()) {
        throw ImageError(path + ": cannot write image (" + std::to_string(channels) +
                         " channels, " + std::to_string(channelNames.size()) + " names)");
    }
    checkSize(path, width, height, data.size(), static_cast<size_t>(channels));
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
    spec.channelnames = channelNames;
    spec.alpha_channel = -1;
    spec.z_channel = -1;
    for (int c = 0; c < channels; ++c) {
        if (channelNames[c] == "A") spec.alpha_channel = c;
        if (channelNames[c] == "Z") spec.z_channel = c;
    }
    writeImageAtomically(path, spec, OIIO::TypeDesc::FLOAT, data.data());
}

void writeDepthImage(const std::string& path, const ShadowMap& map) {
    writeExr(path, map.width(), map.height(), 1, map.depths(), {"Z"});
}

FloatImage readFloatImage(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) throw ImageError(path + ": cannot read image (" + firstLine(OIIO::geterror()) + ")");
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.deep || spec.width <= 0 || spec.height <= 0 || spec.depth > 1) {
        throw ImageError(path + ": cannot read image (not a flat 2D image)");
    }
    FloatImage img{spec.width, spec.height, spec.nchannels, {}};
    img.data.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.data.data())) {
        throw ImageError(path + ": cannot read image (" + firstLine(in->geterror()) + ")");
    }
    return img;
}

ShadowMap readDepthImage(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) throw ImageError(path + ": cannot read image (" + firstLine(OIIO::geterror()) + ")");
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels != 1) {
        throw ImageError(path + ": has " + std::to_string(spec.nchannels) +
                         " channels; a depth map has 1");
    }
    OIIO::TypeDesc::BASETYPE base = static_cast<OIIO::TypeDesc::BASETYPE>(spec.format.basetype);
    if (base != OIIO::TypeDesc::HALF && base != OIIO::TypeDesc::FLOAT &&
        base != OIIO::TypeDesc::DOUBLE) {
        throw ImageError(path + ": holds " + std::string(spec.format.c_str()) +
                         " integers; a depth map holds floats (half or float)");
    }
    if (spec.deep || spec.width <= 0 || spec.height <= 0 || spec.depth > 1) {
        throw ImageError(path + ": cannot read image (not a flat 2D image)");
    }
    std::vector<float> depths(static_cast<size_t>(spec.width) * spec.height);
    // OIIO hands scanlines in file order, first scanline first: that is ShadowMap's row 0.
    if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, depths.data())) {
        throw ImageError(path + ": cannot read image (" + firstLine(in->geterror()) + ")");
    }
    ShadowMap map(spec.width, spec.height, std::move(depths));
    if (std::optional<std::string> bad = map.findInvalidTexel()) {
        throw ImageError(path + ": " + *bad);
    }
    return map;
}

bool fileExists(const std::string& path) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

}  // namespace pcf
