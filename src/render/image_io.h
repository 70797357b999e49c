// image_io.h: PNG and EXR in and out (OpenImageIO), the way every intermediate buffer of
// pcfscope can be written to disk and a shadow map read back.
//
// Row order: the writers take rows TOP-DOWN (first row = top of the picture = first scanline
// in the file), which is what readPixelsRgba8 / readPixelsFloat (gl_objects.h) return.
// readDepthImage gives a ShadowMap whose row 0 is the file's first scanline (docs/methods.md,
// "Conventions").
//
// Writes are atomic: the image goes to PATH.tmp-XXXXXX in the same directory and is renamed
// over PATH only when complete, so a failed write never leaves a half-written PATH behind.
#pragma once

#include <cstddef>
#include <cstdint>
#include <shared_mutex>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/shadow_map.h"

namespace pcf {

// Bad image input or a failed write: one line, "PATH: what is wrong".
// (src/base/input_error.h is to take this role; until then this is what image_io throws.)
class ImageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Text written through a temporary file and a rename: never half a file. Throws ImageError.
void writeTextFile(const std::string& path, const std::string& text);

// An 8-bit RGBA PNG; rgba holds width * height * 4 bytes, rows top-down.
void writePngRgba8(const std::string& path, int width, int height, std::span<const uint8_t> rgba);

// A 32-bit float OpenEXR; data holds width * height * channels floats, rows top-down, channels
// interleaved and named by channelNames (e.g. {"R", "G", "B"}, {"Z"}).
void writeExr(const std::string& path, int width, int height, int channels,
              std::span<const float> data, const std::vector<std::string>& channelNames);

// The shadow map as a one-channel ("Z") float EXR, its row 0 as the first scanline: what
// readDepthImage reads back unchanged.
void writeDepthImage(const std::string& path, const ShadowMap& map);

// The largest side of an image readDepthImage and readFloatImage accept: GL's common
// GL_MAX_TEXTURE_SIZE (what llvmpipe and most GPUs report), 1 GiB of floats per channel at most.
// Checked on the file's header, before a pixel is allocated, so a small file claiming a huge
// image costs nothing.
constexpr int MAX_IMAGE_SIDE = 16384;
constexpr int MAX_DEPTH_IMAGE_SIDE = MAX_IMAGE_SIDE;
// The largest image file read: a 16384^2 depth map of uncompressed floats is 1 GiB; four such
// channels (a `render --raw` lightspace.exr at the largest frame is less) fit in 4 GiB.
constexpr std::uintmax_t MAX_IMAGE_FILE_BYTES = std::uintmax_t{4} << 30;

// A depth map: one channel of half or float, every texel in [0,1]. Row 0 = first scanline.
// Only regular files are read (a FIFO or device would block or never end); an EXR header
// attribute larger than the file is refused before OpenEXR allocates it.
// Throws ImageError: "PATH: is 20000 x 20000 texels; a depth map is at most 16384 on a side",
// "PATH: cannot read image (REASON)", "PATH: has 3 channels; a depth map has 1", "PATH: holds uint8
// integers; a depth map holds floats (half or float)", "PATH: texel (i, j) is NaN" (and the other
// ShadowMap::findInvalidTexel findings).
ShadowMap readDepthImage(const std::string& path);

// Any float image of 1 to 4 channels: width, height, channel count and the floats (rows as
// stored, first scanline first, channels interleaved). The same input checks as readDepthImage
// (regular file, size caps, EXR header attribute sizes). Throws ImageError "PATH: cannot read
// image (REASON)", "PATH: is 20000 x 20000 pixels; an image is at most 16384 on a side".
struct FloatImage {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> data;
};
FloatImage readFloatImage(const std::string& path);

// A map image of any kind: a depth map (readDepthImage) or a moments map of 2 or 4 float
// channels (M1 .. M4, as writeDepthImage writes them), labelled 32F; every value finite.
ShadowMap readMapImage(const std::string& path);
bool fileExists(const std::string& path);

// The file a write to `path` replaces: `path`, or where its chain of symbolic links ends. An
// output that is a link is written through (the file it points at is replaced, the link stays:
// a link the user made is theirs), by every writer here and by the staged outputs that
// app/output_files.h moves into place.
std::string outputTarget(const std::string& path);

// Writers (writeTextFile, writePngRgba8, writeExr) hold this shared from before the temporary
// file exists until after the rename. Whoever holds it exclusively (the interrupt cleanup of
// app/output_files.h) knows no write is half done and no temporary file is left.
std::shared_mutex& outputWriteGate();

}  // namespace pcf
