#include "lesson/lesson_keys.h"

#include <algorithm>

#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"

namespace pcf {

namespace {

// The next method (back: the previous), its kernel fitted to it; a bias the new method cannot
// take (soft on hardware taps) falls back to constant.
void nextMethod(LessonSettings& s, bool back) {
    s.method = (s.method + (back ? PCF_METHOD_COUNT - 1 : 1)) % PCF_METHOD_COUNT;
    s.kernel = fitKernel(s.method, s.kernel);
    if (validateBias(static_cast<int>(s.bias), s.method)) s.bias = BiasMode::Constant;
}

// Every bias mode in turn (back: backwards), skipping those the method cannot take.
void nextBias(LessonSettings& s, bool back) {
    int mode = static_cast<int>(s.bias);
    do {
        mode = (mode + (back ? PCF_BIAS_COUNT - 1 : 1)) % PCF_BIAS_COUNT;
    } while (validateBias(mode, s.method));
    s.bias = static_cast<BiasMode>(mode);
}

}  // namespace

const std::vector<std::string>& settingKeyNames() {
    static const std::vector<std::string> names = {"M", "Shift+M", "[", "]", "-",       "+",
                                                   "B", "Shift+B", "Q", "O", "Shift+O", "S"};
    return names;
}

std::optional<LessonSettings> settingsAfterKey(const LessonSettings& settings,
                                               std::string_view key) {
    LessonSettings s = settings;
    if (key == "M" || key == "Shift+M") {
        nextMethod(s, key != "M");
    } else if (key == "[" || key == "]") {
        s.kernel = stepKernel(s.method, s.kernel, key == "]" ? 1 : -1);
    } else if (key == "-") {
        s.mapSize = std::max(MIN_MAP_SIZE, s.mapSize / 2);
    } else if (key == "+") {
        s.mapSize = std::min(MAX_MAP_SIZE, s.mapSize * 2);
    } else if (key == "B" || key == "Shift+B") {
        nextBias(s, key != "B");
    } else if (key == "Q") {
        s.precision = s.precision == PCF_PRECISION_HW8 ? PCF_PRECISION_EXACT : PCF_PRECISION_HW8;
    } else if (key == "O" || key == "Shift+O") {
        // Slide the map's texel grid by 1/8 texel (lesson 13).
        s.originShift = std::clamp(s.originShift + (key == "O" ? 0.125f : -0.125f), -64.0f, 64.0f);
    } else if (key == "S") {
        s.snap = !s.snap;
    } else {
        return std::nullopt;
    }
    return s;
}

bool reachableByKeys(const LessonSettings& from, const LessonSettings& to,
                     const std::vector<std::string>& keys, int presses) {
    std::vector<LessonSettings> front{from};
    std::vector<LessonSettings> seen{from};
    for (int n = 0; n <= presses && !front.empty(); ++n) {
        std::vector<LessonSettings> next;
        for (const LessonSettings& s : front) {
            if (s == to) return true;
            for (const std::string& key : keys) {
                std::optional<LessonSettings> after = settingsAfterKey(s, key);
                if (!after || std::find(seen.begin(), seen.end(), *after) != seen.end()) continue;
                seen.push_back(*after);
                next.push_back(*after);
            }
        }
        front = std::move(next);
    }
    return false;
}

}  // namespace pcf
