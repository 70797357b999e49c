// image_codec.h: the OpenImageIO side of image_io, reached through one table of functions. The
// table lives in a shared module of its own (render/oiio/image_codec_oiio.cpp, built as
// libpcfscope_oiio.so next to pcfscope) that image_io opens on the first image read or written:
// OpenImageIO needs some 260 shared objects (OpenCV, GStreamer, GDAL, codecs), and resolving
// them at start-up cost every command 0.4 s of CPU, `pcfscope methods` included.
//
// Everything that is not OpenImageIO (the input checks, atomic writes, the messages) stays in
// image_io.cpp; the module only encodes and decodes. Both sides are built from this tree with
// the same compiler, so the table passes C++ types.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pcf {

// What an image file holds, read from its header.
struct ImageCodecSpec {
    int width = 0;
    int height = 0;
    int depth = 1;  // slices: 1 for a flat image
    int channels = 0;
    bool deep = false;
    bool floats = false;     // half, float or double samples
    std::string formatName;  // the sample type as OpenImageIO names it: "uint8", "half"
};

// Each function returns "" on success or the library's reason (possibly several lines; the
// caller makes it one).
struct ImageCodec {
    // sizeof(ImageCodec) where the module was built: a module from another build is refused.
    std::size_t tableSize = 0;
    // An 8-bit RGBA PNG (rows top-down, straight alpha) encoded into `bytes`; `path` names the
    // file in messages and picks nothing.
    std::string (*encodePng)(const std::string& path, int width, int height, const uint8_t* rgba,
                             std::vector<unsigned char>& bytes) = nullptr;
    // A float OpenEXR of `names.size()` interleaved channels encoded into `bytes`.
    std::string (*encodeExr)(const std::string& path, int width, int height, const float* data,
                             const std::vector<std::string>& names,
                             std::vector<unsigned char>& bytes) = nullptr;
    // Opens `path` and reads its header; on success `handle` is to be given to readFloats or
    // close.
    std::string (*open)(const std::string& path, void*& handle, ImageCodecSpec& spec) = nullptr;
    // The first `channels` channels of every pixel as floats, first scanline first.
    std::string (*readFloats)(void* handle, int channels, float* out) = nullptr;
    void (*close)(void* handle) = nullptr;
};

// The module's one exported symbol.
extern "C" const ImageCodec* pcfscopeImageCodec();
using ImageCodecEntry = const ImageCodec* (*)();

// The table, the module opened on the first call: next to the running executable, else where
// the build put it. Throws ImageError naming the module and the loader's reason.
const ImageCodec& imageCodec();

}  // namespace pcf
