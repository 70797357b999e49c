#include "lesson/lesson_keys.h"

#include <algorithm>

#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "scene/cascade_view.h"

namespace pcf {

namespace {

// The next method (back: the previous), its kernel fitted to it; a bias the new method cannot
// take (soft on hardware taps) falls back to constant, weights it cannot take to box.
// With cascades, the methods cascades cannot take (scene/cascade_view.h
// cascadeMethodProblem) are skipped.
void nextMethod(LessonSettings& s, bool back) {
    do {
        s.method = (s.method + (back ? PCF_METHOD_COUNT - 1 : 1)) % PCF_METHOD_COUNT;
    } while (cascadeMethodProblem(s));
    s.kernel = fitKernel(s.method, s.kernel);
    if (validateBias(static_cast<int>(s.bias), s.method)) s.bias = BiasMode::Constant;
    if (!methodInfo(s.method).takesWeights) s.weights = PCF_WEIGHTS_BOX;
}

// The next step of `steps` above v (up) or below it (down), staying at the ends: a value between
// two steps goes to the nearer one that way, so V then Shift+V returns to a step exactly.
template <size_t N>
float nextStep(const float (&steps)[N], float v, bool up) {
    if (up) {
        for (float step : steps) {
            if (step > v) return step;
        }
        return steps[N - 1];
    }
    for (size_t k = N; k-- > 0;) {
        if (steps[k] < v) return steps[k];
    }
    return steps[0];
}

// The settings keys that came with the live controls: the bias amount, the sun, the weights,
// culling, the depth format and the shading. nullopt for another name.
std::optional<LessonSettings> afterLiveKey(LessonSettings s, std::string_view key) {
    bool back = key.starts_with("Shift+");
    std::string_view letter = back ? key.substr(6) : key;
    if (letter == "V") {
        // An amount is what every mode but none subtracts: none becomes constant, as the bias
        // sweep of `animate` does.
        if (s.bias == BiasMode::None) s.bias = BiasMode::Constant;
        s.constantBias = nextStep(BIAS_AMOUNT_STEPS, s.constantBias, !back);
    } else if (letter == "U") {
        s.sunTilt =
            std::clamp(s.sunTilt + (back ? -SUN_TILT_STEP_DEG : SUN_TILT_STEP_DEG), -90.0f, 90.0f);
    } else if (letter == "T") {
        s.sunTurn += back ? -SUN_TURN_STEP_DEG : SUN_TURN_STEP_DEG;
        if (s.sunTurn > 180.0f) s.sunTurn -= 360.0f;
        if (s.sunTurn <= -180.0f) s.sunTurn += 360.0f;
    } else if (letter == "W") {
        // Only the methods that take weights have any (methods.h: takesWeights).
        if (methodInfo(s.method).takesWeights) {
            constexpr int count = PCF_WEIGHTS_GAUSSIAN + 1;  // box, binomial, gaussian
            s.weights = (s.weights + (back ? count - 1 : 1)) % count;
        }
    } else if (letter == "I") {
        if (s.weights == PCF_WEIGHTS_GAUSSIAN) s.sigma = nextStep(SIGMA_STEPS, s.sigma, !back);
    } else if (key == "K") {
        s.cull = static_cast<CullMode>((static_cast<int>(s.cull) + 1) % 3);
    } else if (key == "D") {
        s.depthFormat = nextDepthFormat(s.depthFormat);
    } else if (key == "N") {
        s.shading = s.shading == Shading::Lit ? Shading::Visibility : Shading::Lit;
    } else if (key == "J") {
        // The colour of the cascade each receiver reads over the lit picture, and back.
        s.shading = s.shading == Shading::Cascades ? Shading::Lit : Shading::Cascades;
    } else if (key == "Y") {
        // Frozen cascades need some: with one map the key does nothing.
        if (s.cascades > 1) s.freezeCascades = !s.freezeCascades;
    } else {
        return std::nullopt;
    }
    return s;
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
    static const std::vector<std::string> names = {
        "M", "Shift+M", "[", "]",       "-",       "+", "B",       "Shift+B", "Q",
        "O", "Shift+O", "S", "V",       "Shift+V", "U", "Shift+U", "T",       "Shift+T",
        "W", "Shift+W", "I", "Shift+I", "K",       "D", "N",       "J",       "Y"};
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
        return afterLiveKey(s, key);
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
