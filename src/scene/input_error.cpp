#include "scene/input_error.h"

#include <sstream>
#include <utility>

namespace pcf {

namespace {

// The message must stay one line even when a parser's description spans several.
std::string oneLine(std::string text) {
    for (char& c : text) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    return text;
}

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
