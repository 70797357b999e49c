// fuzz_check.h: what every fuzz target asserts besides "no crash": a refusal is one of the
// exceptions the app turns into exit 2, and its message is one line (README "Reliability").
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace pcf::fuzz {

// Aborts (a libFuzzer finding) when a refusal's message spans lines or is empty.
inline void requireOneLine(std::string_view message) {
    if (message.empty() || message.find('\n') != std::string_view::npos) {
        std::fprintf(stderr, "fuzz: refusal is not one line: '%.*s'\n",
                     static_cast<int>(message.size()), message.data());
        std::abort();
    }
}

}  // namespace pcf::fuzz
