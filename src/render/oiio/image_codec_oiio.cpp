// image_codec_oiio.cpp: the module libpcfscope_oiio.so, the only code of pcfscope that calls
// OpenImageIO (render/image_codec.h says why it is a module). It encodes into memory and
// decodes; the files, their checks and the messages are image_io.cpp's.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <memory>

#include "render/image_codec.h"

namespace pcf {

namespace {

// Encodes the image into memory: OIIO's writers do not all report a failed fwrite (a PNG on a
// full disk came out as 0 bytes with success), so image_io writes the bytes itself. The plugin
// is chosen from the path's extension.
std::string encode(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                   const void* data, std::vector<unsigned char>& bytes) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) return OIIO::geterror();
    OIIO::Filesystem::IOVecOutput memory;
    if (!out->supports("ioproxy") || !out->set_ioproxy(&memory) || !out->open(path, spec) ||
        !out->write_image(type, data) || !out->close()) {
        return out->geterror();
    }
    out.reset();
    bytes = std::move(memory.buffer());
    return "";
}

std::string encodePng(const std::string& path, int width, int height, const uint8_t* rgba,
                      std::vector<unsigned char>& bytes) {
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
    // The bytes are PNG's own straight (unassociated) alpha: without this OIIO would take them
    // as premultiplied and divide the colour by alpha on the way out.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    // zlib level 1: exported frames are flat UI colours and compress well anyway, and at the
    // default level 6 compression was a third of an export's time.
    spec.attribute("png:compressionLevel", 1);
    // One row filter, "up" (each byte minus the one above: flat panels and vertical gradients
    // become runs of zeros), instead of libpng's per-row trial of all five, which cost more
    // than the compression (22 % of an export's CPU against zlib's 11 %, perf). 0x20 is
    // libpng's PNG_FILTER_UP.
    spec.attribute("png:filter", 0x20);
    return encode(path, spec, OIIO::TypeDesc::UINT8, rgba, bytes);
}

std::string encodeExr(const std::string& path, int width, int height, const float* data,
                      const std::vector<std::string>& names, std::vector<unsigned char>& bytes) {
    int channels = static_cast<int>(names.size());
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
    // OIIO stamps "DateTime" (the time of writing) into every EXR unless told otherwise: with
    // it two runs of the same command give different bytes. An empty value writes no header.
    spec.attribute("DateTime", "");
    spec.channelnames = names;
    spec.alpha_channel = -1;
    spec.z_channel = -1;
    for (int c = 0; c < channels; ++c) {
        if (names[c] == "A") spec.alpha_channel = c;
        if (names[c] == "Z") spec.z_channel = c;
    }
    return encode(path, spec, OIIO::TypeDesc::FLOAT, data, bytes);
}

std::string open(const std::string& path, void*& handle, ImageCodecSpec& spec) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) return OIIO::geterror();
    const OIIO::ImageSpec& s = in->spec();
    auto base = static_cast<OIIO::TypeDesc::BASETYPE>(s.format.basetype);
    spec = ImageCodecSpec{s.width,
                          s.height,
                          s.depth,
                          s.nchannels,
                          s.deep,
                          base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::FLOAT ||
                              base == OIIO::TypeDesc::DOUBLE,
                          s.format.c_str()};
    handle = in.release();
    return "";
}

std::string readFloats(void* handle, int channels, float* out) {
    auto* in = static_cast<OIIO::ImageInput*>(handle);
    // OIIO hands scanlines in file order, first scanline first.
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, out)) return in->geterror();
    return "";
}

void close(void* handle) { delete static_cast<OIIO::ImageInput*>(handle); }

const ImageCodec CODEC{sizeof(ImageCodec), encodePng, encodeExr, open, readFloats, close};

}  // namespace

extern "C" __attribute__((visibility("default"))) const ImageCodec* pcfscopeImageCodec() {
    return &CODEC;
}

}  // namespace pcf
