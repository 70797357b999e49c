#include "lesson/lesson_text_lines.h"

#include <algorithm>
#include <cstdlib>
#include <optional>

namespace pcf {

namespace {

// A string value's source, walked line by line as TOML decodes it.
struct ValueWalk {
    const std::vector<std::string_view>& lines;
    std::size_t line = 0;
    std::size_t pos = 0;
    std::string_view l;
    std::vector<std::size_t> starts;
    std::size_t out = 0;  // the value's bytes so far

    // At column `at` (0-based) of line `from` (0-based): the opening quote.
    ValueWalk(const std::vector<std::string_view>& fileLines, std::size_t from, std::size_t at)
        : lines(fileLines), line(from), pos(at), l(text(from)) {}

    std::string_view text(std::size_t k) const {
        std::string_view t = lines[k];
        if (!t.empty() && t.back() == '\r') t.remove_suffix(1);
        return t;
    }
    bool nextLine() {
        if (++line >= lines.size()) return false;
        l = text(line);
        pos = 0;
        starts.push_back(out);
        return true;
    }

    // One escape of a basic string at l[pos] (a backslash): its bytes added to out, or a
    // line-ending backslash with the whitespace and newlines after it skipped.
    bool escape(bool multi) {
        std::size_t rest = l.find_first_not_of(" \t", pos + 1);
        if (multi && rest == std::string_view::npos) {
            while (true) {
                if (!nextLine()) return false;
                std::size_t start = l.find_first_not_of(" \t");
                if (start != std::string_view::npos) {
                    pos = start;
                    return true;
                }
            }
        }
        if (pos + 1 >= l.size()) return false;
        char e = l[pos + 1];
        if (e == 'u' || e == 'U') {
            std::size_t digits = e == 'u' ? 4 : 8;
            if (pos + 2 + digits > l.size()) return false;
            unsigned long cp =
                std::strtoul(std::string(l.substr(pos + 2, digits)).c_str(), nullptr, 16);
            out += cp < 0x80 ? 1 : cp < 0x800 ? 2 : cp < 0x10000 ? 3 : 4;
            pos += 2 + digits;
            return true;
        }
        out += 1;
        pos += 2;
        return true;
    }

    // The walk from the opening quote at l[pos]; false: not a string the walk reads.
    bool run() {
        std::string_view delim = l.substr(pos, 3) == "\"\"\"" ? "\"\"\""
                                 : l.substr(pos, 3) == "'''"  ? "'''"
                                 : l.substr(pos, 1) == "\""   ? "\""
                                 : l.substr(pos, 1) == "'"    ? "'"
                                                              : "";
        if (delim.empty()) return false;
        bool multi = delim.size() == 3, basic = delim[0] == '"';
        pos += delim.size();
        // A newline right after the opening delimiter is not part of the value.
        if (multi && pos >= l.size() && !nextLine()) return false;
        while (true) {
            if (pos >= l.size()) {
                if (!multi) return false;
                ++out;  // the newline
                if (!nextLine()) return false;
                continue;
            }
            if (l.substr(pos, delim.size()) == delim) {
                // Up to two quotes of the delimiter's kind may end the value itself.
                std::size_t end = l.find_first_not_of(delim[0], pos);
                std::size_t quotes = (end == std::string_view::npos ? l.size() : end) - pos;
                out += std::min<std::size_t>(quotes - delim.size(), multi ? 2 : 0);
                return true;
            }
            if (basic && l[pos] == '\\') {
                if (!escape(multi)) return false;
                continue;
            }
            ++out;
            ++pos;
        }
    }
};

}  // namespace

std::vector<std::size_t> valueLineStarts(const std::vector<std::string_view>& fileLines, int line,
                                         int column, const std::string& value) {
    std::size_t first = static_cast<std::size_t>(std::max(1, line)) - 1;
    if (first < fileLines.size()) {
        ValueWalk walk(fileLines, first, static_cast<std::size_t>(std::max(1, column)) - 1);
        if (walk.run() && walk.out == value.size()) return walk.starts;
    }
    std::vector<std::size_t> starts;
    std::string_view opening = first < fileLines.size() ? fileLines[first] : "";
    std::size_t q = std::min(opening.find("\"\"\""), opening.find("'''"));
    if (q != std::string_view::npos &&
        opening.find_first_not_of(" \t\r", q + 3) == std::string_view::npos) {
        starts.push_back(0);
    }
    for (std::size_t k = 0; k < value.size(); ++k) {
        if (value[k] == '\n') starts.push_back(k + 1);
    }
    return starts;
}

}  // namespace pcf
