// Fuzz target: the placeholders of lesson text ({uv.x:.3f}, {tap[K].depth}, ...). Text that
// checkPlaceholders accepts must fill without throwing; text it refuses names an offset inside
// the text.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "kernel/methods.h"
#include "kernel/shadow_map.h"
#include "kernel/trace.h"
#include "lesson/lesson_text.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // The first byte picks the method, so placeholders meet taps of every count.
    if (size == 0) return 0;
    int method = pcf::allMethods()[data[0] % pcf::allMethods().size()].id;
    std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    static const pcf::ShadowMap map = pcf::exampleShadowMap();
    pcf::PcfParams params = pcf::makeParams(method, 3);
    pcf::Trace trace = pcf::traceLookup(map, pcf::vec2(0.4625f, 0.3875f), 0.5f, 0.498f, params);
    int taps = static_cast<int>(trace.taps.size());
    int fetches = static_cast<int>(trace.fetches.size());
    std::optional<pcf::PlaceholderProblem> problem = pcf::checkPlaceholders(text, taps, fetches);
    if (problem) {
        if (problem->offset > text.size()) std::abort();
        pcf::fuzz::requireOneLine(problem->problem);
        return 0;
    }
    std::string filled = pcf::fillText(text, trace, pcf::StepContext{});
    (void)filled;
    return 0;
}
