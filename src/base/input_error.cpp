#include "base/input_error.h"

#include <sstream>
#include <string_view>
#include <utility>

namespace pcf {

std::string oneLine(std::string_view text) {
    static const char HEX[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        auto u = static_cast<unsigned char>(c);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else if (u < 0x20 || u == 0x7f) {
            out += "\\x";
            out += HEX[u >> 4];
            out += HEX[u & 15];
        } else {
            out += c;
        }
    }
    return out;
}

namespace {

std::string formatMessage(const std::string& source, int line, const std::string& problem) {
    // A stream, not string appends: GCC 12 at -O3 warns (-Wrestrict, a false positive) on those.
    std::ostringstream message;
    message << source;
    if (line > 0) message << ":" << line;
    message << ": " << problem;
    return oneLine(message.str());
}

}  // namespace

InputError::InputError(std::string source, int line, std::string problem)
    : std::runtime_error(formatMessage(source, line, problem)),
      mSource(std::move(source)),
      mLine(line),
      mProblem(oneLine(std::move(problem))) {}

}  // namespace pcf
