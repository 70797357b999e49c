#include "measure/csv_lines.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "base/input_error.h"

namespace pcf {

std::vector<CsvLine> csvLines(std::string_view text) {
    std::vector<CsvLine> lines;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        CsvLine line{static_cast<int>(lines.size()) + 1, std::string(text.substr(pos, end - pos))};
        if (!line.text.empty() && line.text.back() == '\r') line.text.pop_back();
        lines.push_back(std::move(line));
        pos = end + 1;
    }
    return lines;
}

CsvFields::CsvFields(const std::string& row, const std::string& source, int line)
    : mSource(source), mLine(line) {
    size_t start = 0;
    for (size_t comma; (comma = row.find(',', start)) != std::string::npos; start = comma + 1) {
        mFields.push_back(row.substr(start, comma - start));
    }
    mFields.push_back(row.substr(start));
}

void CsvFields::fail(const std::string& problem) const {
    throw InputError(mSource, mLine, problem);
}

double CsvFields::number(size_t k) const {
    // from_chars, not strtod: strtod also reads hex ("0x1p3"), leading spaces and a '+'.
    const std::string& text = mFields[k];
    double v = 0.0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() ||
        !std::isfinite(v)) {
        fail("field " + std::to_string(k + 1) + " '" + text + "' is not a number");
    }
    return v;
}

double CsvFields::measure(size_t k) const {
    double v = number(k);
    if (v < 0.0) {
        fail("field " + std::to_string(k + 1) + " '" + mFields[k] +
             "' is negative; it is a measure, 0 or more");
    }
    return v;
}

int CsvFields::count(size_t k) const {
    int v = integer(k);
    if (v < 0) {
        fail("field " + std::to_string(k + 1) + " '" + mFields[k] +
             "' is negative; it is a count or a size, 0 or more");
    }
    return v;
}

int CsvFields::integer(size_t k) const {
    double v = number(k);
    if (v != std::floor(v) || std::fabs(v) > 1.0e9) {
        fail("field " + std::to_string(k + 1) + " '" + mFields[k] + "' is not a whole number");
    }
    return static_cast<int>(v);
}

bool CsvFields::flag(size_t k) const {
    double v = number(k);
    if (v != 0.0 && v != 1.0) {
        fail("field " + std::to_string(k + 1) + " '" + mFields[k] + "' is not 0 or 1");
    }
    return v == 1.0;
}

}  // namespace pcf
