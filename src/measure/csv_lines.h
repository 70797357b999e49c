// csv_lines.h: reading back the comma-separated files pcfscope writes (stability.csv,
// bench.csv): the text cut into numbered lines, a data line cut at its commas, and field readers
// that name file:line (InputError) when a field is not what the file promises. No quoting: the
// files pcfscope writes never put a comma inside a field.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pcf {

struct CsvLine {
    int number = 0;    // 1-based
    std::string text;  // without its '\n', and without a '\r' before it
};

// Every line of `text`, numbered; a last line without '\n' counts, an empty text has none.
std::vector<CsvLine> csvLines(std::string_view text);

// One data line split at commas; the readers throw InputError(source, line, ...) on failure.
class CsvFields {
  public:
    CsvFields(const std::string& row, const std::string& source, int line);
    size_t size() const { return mFields.size(); }
    const std::string& text(size_t k) const { return mFields[k]; }
    [[noreturn]] void fail(const std::string& problem) const;
    // A finite number in decimal, as pcfscope writes them (no hex, no leading + or spaces), or
    // "field k 'x' is not a number".
    double number(size_t k) const;
    // A number that is 0 or more: a time, a share, an error, a count.
    double measure(size_t k) const;
    // Counts and sizes: a whole number an int holds (a cast of 1e30 is undefined behaviour).
    int integer(size_t k) const;
    // A count or size: a whole number 0 or more.
    int count(size_t k) const;
    // 0 or 1.
    bool flag(size_t k) const;

  private:
    std::vector<std::string> mFields;
    std::string mSource;
    int mLine;
};

}  // namespace pcf
