// Fuzz target: the scene file parser (--scene-file, a lesson's scene tables) on arbitrary bytes.
// A parsed scene must also survive being written back out and parsed again.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "base/input_error.h"
#include "scene/scene_file.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    pcf::Scene scene;
    try {
        scene = pcf::parseSceneString(text, "fuzz.toml");
    } catch (const pcf::InputError& e) {
        pcf::fuzz::requireOneLine(e.what());
        return 0;
    }
    // What formatSceneToml writes, parseSceneString must read back.
    std::string again = pcf::formatSceneToml(scene);
    try {
        (void)pcf::parseSceneString(again, "fuzz-again.toml");
    } catch (const pcf::InputError& e) {
        std::fprintf(stderr, "fuzz: formatted scene refused: %s\n%s\n", e.what(), again.c_str());
        std::abort();
    }
    return 0;
}
