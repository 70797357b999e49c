// lesson_text_lines.h: which line of a lesson file holds a given character of a step's text, so
// that a problem found in the text (a placeholder, a typed number) is reported at its file:line.
// A TOML string's value is not its source: a line-ending backslash joins lines with no newline
// in the value, and escapes are shorter in the value than in the file.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace pcf {

// The offsets in `value` at which each file line after the value's first begins, for a string
// value whose source starts at `line`, `column` (1-based, its opening quote) in `fileLines` (the
// file split at '\n'). The source is walked as TOML decodes it; where the walk does not come out
// at the value's length (a source it does not read), the value's own newlines are counted.
// The line of offset k is `line` + the number of offsets <= k.
std::vector<std::size_t> valueLineStarts(const std::vector<std::string_view>& fileLines, int line,
                                         int column, const std::string& value);

}  // namespace pcf
