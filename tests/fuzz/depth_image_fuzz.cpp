// Fuzz target: the depth-image loader (--map, readDepthImage) on arbitrary file contents. The
// bytes go to a file named .exr, so OpenImageIO tries its EXR reader first and every other
// reader after it. A map loads or is refused with one ImageError line.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "render/image_io.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = "/tmp/pcfscope-fuzz-" + std::to_string(getpid()) + ".exr";
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return 0;
    std::fwrite(data, 1, size, f);
    std::fclose(f);
    try {
        pcf::ShadowMap map = pcf::readDepthImage(path);
        if (map.width() > pcf::MAX_DEPTH_IMAGE_SIDE || map.height() > pcf::MAX_DEPTH_IMAGE_SIDE) {
            std::abort();
        }
    } catch (const pcf::ImageError& e) {
        pcf::fuzz::requireOneLine(e.what());
    }
    std::remove(path.c_str());
    return 0;
}
