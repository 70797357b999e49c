// Fuzz target: `pcfscope verify`'s inputs. A valid `render --raw` folder is made once; each input
// replaces one of its files (the first byte picks which: render.json, shadowmap.exr,
// lightspace.exr, visibility.exr, dzduv.exr) with the rest of the bytes, and verify runs on the
// folder. It returns 0 or 1, or refuses with one line (UsageError, InputError, ImageError);
// anything else (a crash, another exception, a sanitizer report) is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/cli_util.h"
#include "app/commands.h"
#include "base/input_error.h"
#include "render/image_io.h"
#include "tests/fuzz/fuzz_check.h"

namespace {

namespace fs = std::filesystem;

const char* const FILES[] = {"render.json", "shadowmap.exr", "lightspace.exr", "visibility.exr",
                             "dzduv.exr"};

// A 2 x 2 frame over a 4 x 4 map, nearest, constant bias 0.01: every pixel lit, ref = z - 0.01.
fs::path makeFolder() {
    fs::path dir = fs::temp_directory_path() / ("pcfscope-fuzz-verify-" + std::to_string(getpid()));
    fs::create_directories(dir);
    pcf::writeDepthImage((dir / "shadowmap.exr").string(), pcf::ShadowMap(4, 4, 0.75f));
    std::vector<float> ls, vis, planes;
    for (int k = 0; k < 4; ++k) {
        float z = 0.5f;
        ls.insert(ls.end(), {0.3f + 0.1f * k, 0.4f, z - 0.01f, 1.0f});
        vis.push_back(1.0f);
        planes.insert(planes.end(), {0.0f, 0.0f, z, 1.0f});
    }
    pcf::writeExr((dir / "lightspace.exr").string(), 2, 2, 4, ls, {"R", "G", "B", "A"});
    pcf::writeExr((dir / "visibility.exr").string(), 2, 2, 1, vis, {"Y"});
    pcf::writeExr((dir / "dzduv.exr").string(), 2, 2, 4, planes, {"R", "G", "B", "A"});
    pcf::writeTextFile((dir / "render.json").string(),
                       R"({"method":"nearest","kernel":1,"radius":1,"rotate":false,)"
                       R"("weights":"box","sigma":1,"precision":"exact","depth_format":"32f",)"
                       R"("map_size":4,"bias":"constant","soft_scale":2048,"rpdb_max":0.5,)"
                       R"("constant_bias":0.01,"slope_bias":0,"slope_max":0.01,)"
                       R"("normal_offset":0})"
                       "\n");
    return dir;
}

std::string readBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const fs::path dir = makeFolder();
    static std::vector<std::string> originals = [] {
        std::vector<std::string> all;
        for (const char* name : FILES) all.push_back(readBytes(dir / name));
        return all;
    }();
    if (size == 0) return 0;
    size_t pick = data[0] % (sizeof FILES / sizeof *FILES);
    fs::path file = dir / FILES[pick];
    std::ofstream(file, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    try {
        int code = pcf::verifyFolder(dir.string());
        if (code != 0 && code != 1) std::abort();
    } catch (const pcf::UsageError& e) {
        pcf::fuzz::requireOneLine(e.what());
    } catch (const pcf::InputError& e) {
        pcf::fuzz::requireOneLine(e.what());
    } catch (const pcf::ImageError& e) {
        pcf::fuzz::requireOneLine(e.what());
    }
    std::ofstream(file, std::ios::binary | std::ios::trunc) << originals[pick];
    return 0;
}
