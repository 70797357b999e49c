#include "app/cli_util.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "kernel/methods.h"
#include "kernel/settings.h"

namespace pcf {

namespace {

bool parseFloat(const std::string& text, float& out) {
    if (text.empty()) return false;
    errno = 0;
    char* end = nullptr;
    out = std::strtof(text.c_str(), &end);
    return end == text.c_str() + text.size() && errno == 0 && std::isfinite(out);
}

bool parseInt(const std::string& text, int& out) {
    if (text.empty()) return false;
    errno = 0;
    char* end = nullptr;
    long v = std::strtol(text.c_str(), &end, 10);
    if (end != text.c_str() + text.size() || errno != 0 || v < -1000000000L || v > 1000000000L) {
        return false;
    }
    out = static_cast<int>(v);
    return true;
}

}  // namespace

glm::vec2 parseVec2(const std::string& option, const std::string& text) {
    size_t comma = text.find(',');
    glm::vec2 v;
    if (comma == std::string::npos || !parseFloat(text.substr(0, comma), v.x) ||
        !parseFloat(text.substr(comma + 1), v.y)) {
        throw UsageError(option + " expects two finite numbers as A,B, got '" + text + "'");
    }
    return v;
}

glm::ivec2 parseIvec2(const std::string& option, const std::string& text) {
    size_t comma = text.find(',');
    glm::ivec2 v;
    if (comma == std::string::npos || !parseInt(text.substr(0, comma), v.x) ||
        !parseInt(text.substr(comma + 1), v.y)) {
        throw UsageError(option + " expects two integers as X,Y, got '" + text + "'");
    }
    return v;
}

std::string SizeRange::text() const {
    return std::to_string(min.x) + "x" + std::to_string(min.y) + " up to " +
           std::to_string(maxSide) + "x" + std::to_string(maxSide);
}

std::string sizeHelp(const std::string& what, SizeRange range, const std::string& note) {
    return what + " WxH, " + range.text() + (note.empty() ? "" : " (" + note + ")");
}

glm::ivec2 parseSize(const std::string& option, const std::string& text, SizeRange range) {
    size_t x = text.find('x');
    glm::ivec2 v;
    if (x == std::string::npos || !parseInt(text.substr(0, x), v.x) ||
        !parseInt(text.substr(x + 1), v.y)) {
        throw UsageError(option + " expects WxH, got '" + text + "'");
    }
    if (v.x < range.min.x || v.y < range.min.y || v.x > range.maxSide || v.y > range.maxSide)
        throw UsageError(option + " " + text + " is out of range (" + range.text() + ")");
    return v;
}

void requireRange(const std::string& option, float v, float lo, float hi) {
    if (!std::isfinite(v) || v < lo || v > hi) {
        // Each number the shortest text of its float: 1.0000001 is not printed as 1.
        auto text = [](float x) {
            char buf[32];
            auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
            return std::string(buf, ec == std::errc() ? end : buf);
        };
        throw UsageError(option + " " + text(v) + " is out of range [" + text(lo) + ", " +
                         text(hi) + "]");
    }
}

void requireIntRange(const std::string& option, int v, int lo, int hi) {
    if (v < lo || v > hi) {
        throw UsageError(option + " " + std::to_string(v) + " is out of range (" +
                         std::to_string(lo) + ".." + std::to_string(hi) + ")");
    }
}

std::vector<std::string> splitList(const std::string& option, const std::string& text) {
    std::vector<std::string> items;
    size_t start = 0;
    for (;;) {
        size_t comma = text.find(',', start);
        std::string item = text.substr(start, comma == std::string::npos ? comma : comma - start);
        if (item.empty()) throw UsageError(option + " has an empty item in '" + text + "'");
        if (std::find(items.begin(), items.end(), item) == items.end()) items.push_back(item);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return items;
}

std::vector<int> parseIntList(const std::string& option, const std::string& text) {
    std::vector<int> values;
    for (const std::string& item : splitList(option, text)) {
        char* end = nullptr;
        long v = std::strtol(item.c_str(), &end, 10);
        if (end != item.c_str() + item.size() || v < -1000000 || v > 1000000) {
            throw UsageError(option + " expects integers separated by commas, got '" + item + "'");
        }
        if (std::find(values.begin(), values.end(), static_cast<int>(v)) == values.end()) {
            values.push_back(static_cast<int>(v));
        }
    }
    return values;
}

namespace {

std::atomic<bool>& progressLineOpen() {
    static std::atomic<bool> open{false};
    return open;
}

}  // namespace

void setProgressLineOpen(bool open) { progressLineOpen() = open; }

void endProgressLine() {
    if (progressLineOpen().exchange(false)) std::fputc('\n', stderr);
}

std::string cliWords(const ParamProblem& problem) {
    if (problem.setting.empty()) return problem.text();
    return problem.say(settingFlag(problem.setting));
}

std::optional<std::string> cliParamsProblem(const PcfParams& prm) {
    if (std::optional<ParamProblem> p = checkParams(prm)) return cliWords(*p);
    return std::nullopt;
}

std::optional<std::string> cliRangeProblem(const ShadowSettings& s) {
    if (std::optional<ParamProblem> p = checkSettingRanges(s)) return cliWords(*p);
    return std::nullopt;
}

}  // namespace pcf
