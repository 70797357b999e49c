// Fuzz target: the depth-image loader (--map, readDepthImage) on arbitrary file contents. The
// first byte picks the file name's extension (.exr, .tif, .png, .hdr), the rest is the file. Only
// that extension's reader is tried (OIIO "try_all_readers" 0): trying every reader OpenImageIO
// has made one run take a second. A map loads or is refused with one ImageError line.
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "render/image_io.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    OIIO::attribute("try_all_readers", 0);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const char* const EXTENSIONS[] = {".exr", ".tif", ".png", ".hdr"};
    if (size == 0) return 0;
    static bool initialised = (LLVMFuzzerInitialize(nullptr, nullptr), true);
    (void)initialised;
    const std::string path = "/tmp/pcfscope-fuzz-" + std::to_string(getpid()) +
                             EXTENSIONS[data[0] % (sizeof EXTENSIONS / sizeof *EXTENSIONS)];
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return 0;
    std::fwrite(data + 1, 1, size - 1, f);
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
