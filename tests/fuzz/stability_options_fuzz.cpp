// Fuzz target: `pcfscope stability`'s options. The input is a command line, one argument per
// line; it is parsed as `pcfscope stability ARGS` and given to the command's checks (no GL, no
// output). Options are accepted or refused with one line, never a crash, another exception or
// a sanitizer report.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/cli_util.h"
#include "app/commands.h"
#include "base/input_error.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> args = {"pcfscope", "stability"};
    std::string text(reinterpret_cast<const char*>(data), size);
    for (size_t start = 0; start <= text.size() && args.size() < 34;) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        args.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    CLI::App app{"fuzz"};
    pcf::Command stability = pcf::addStabilityCommand(app);
    try {
        app.parse(static_cast<int>(argv.size()), argv.data());
        if (!stability.sub->parsed()) return 0;
        stability.check();
    } catch (const CLI::ParseError&) {
        return 0;  // CLI11's own refusal (an unknown option, a missing value)
    } catch (const pcf::UsageError& e) {
        pcf::fuzz::requireOneLine(e.what());
    } catch (const pcf::InputError& e) {
        pcf::fuzz::requireOneLine(e.what());
    }
    return 0;
}
