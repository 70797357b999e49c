// Fuzz target: the bench.csv reader behind a lesson's `chart` step.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "base/input_error.h"
#include "measure/bench_report.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        (void)pcf::parseBenchCsv(text, "fuzz.csv");
    } catch (const pcf::InputError& e) {
        pcf::fuzz::requireOneLine(e.what());
    }
    return 0;
}
