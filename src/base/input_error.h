// input_error.h: the one exception for bad input (a malformed or missing scene or lesson file, a
// value out of range). The app maps it to exit code 2 (docs/user-guide.md, "Files, errors and
// interrupts").
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace pcf {

// what() is one line, `source:line: what is wrong` (e.g. `box.toml:7: sphere radius must be
// positive, got -1`), or `source: what is wrong` when no line applies (line <= 0), e.g.
// `scenes/missing.toml: cannot open file`. Lines count from 1, as editors and toml++ do.
class InputError : public std::runtime_error {
  public:
    InputError(std::string source, int line, std::string problem);

    const std::string& source() const { return mSource; }
    int line() const { return mLine; }
    // The problem without the `source:line: ` prefix.
    const std::string& problem() const { return mProblem; }

  private:
    std::string mSource;
    int mLine;
    std::string mProblem;
};

// Text made to fit on one line: newlines, tabs and other control characters written as \n, \r,
// \t, \xNN (backslashes are kept as they are). Every message pcfscope prints goes through it,
// so a newline inside an option value or a file name cannot split an error over lines.
std::string oneLine(std::string_view text);

}  // namespace pcf
