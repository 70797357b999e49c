#include "kernel/bias.h"

#include <array>
#include <cmath>
#include <cstdio>

#include "kernel/methods.h"

namespace pcf {

namespace {

constexpr std::array<std::string_view, PCF_BIAS_COUNT> BIAS_NAMES = {
    "none", "constant", "slope", "normal", "receiver-plane", "soft", "interpolated"};

std::string formatValue(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", static_cast<double>(v));
    return buf;
}

}  // namespace

float BiasParams::lookupBias(float cosTheta) const {
    if (mode == PCF_BIAS_SLOPE) return pcfSlopeBias(cosTheta, constant, slope, slopeMax);
    return baseBias();
}

std::string_view biasName(int mode) {
    if (mode < 0 || mode >= PCF_BIAS_COUNT) return "?";
    return BIAS_NAMES[static_cast<size_t>(mode)];
}

std::optional<int> biasFromName(std::string_view name) {
    for (size_t k = 0; k < BIAS_NAMES.size(); ++k) {
        if (BIAS_NAMES[k] == name) return static_cast<int>(k);
    }
    return std::nullopt;
}

std::string biasNameList() {
    std::string out;
    for (std::string_view n : BIAS_NAMES) out += (out.empty() ? "" : ", ") + std::string(n);
    return out;
}

std::optional<std::string> validateBias(int mode, int method) {
    std::string name(methodInfo(method).name);
    if (mode == PCF_BIAS_SOFT && (method == PCF_HW2X2 || method == PCF_HW || method == PCF_TENT)) {
        return "bias soft compares depths in the shader, but " + name +
               " gets its comparisons from the texture unit (hardware taps); use nearest, "
               "box2x2, bilinear2x2, pcf-naive, pcf-gather or poisson";
    }
    if (mode == PCF_BIAS_INTERPOLATED && method != PCF_NEAREST) {
        return "bias interpolated compares one bilinearly interpolated depth, a hard edge; " +
               name +
               " lerps comparison bits by the same sub-texel fraction, so the two cannot "
               "combine (\"PCF Shadow Acne\", Solution 2); use --method nearest";
    }
    return std::nullopt;
}

std::optional<ParamProblem> checkBiasParams(const BiasParams& b) {
    auto range = [](const char* setting, float v, float lo,
                    float hi) -> std::optional<ParamProblem> {
        if (std::isfinite(v) && v >= lo && v <= hi) return std::nullopt;
        return ParamProblem{setting, "",
                            " must be in [" + formatValue(lo) + ", " + formatValue(hi) + "], got " +
                                formatValue(v)};
    };
    if (auto e = range("constant_bias", b.constant, -1.0f, 1.0f)) return e;
    if (auto e = range("slope_bias", b.slope, 0.0f, 1.0f)) return e;
    if (auto e = range("slope_max", b.slopeMax, 0.0f, 1.0f)) return e;
    if (auto e = range("normal_offset", b.normalOffset, 0.0f, 64.0f)) return e;
    if (auto e = range("soft_scale", b.softScale, 1.0f, 1.0e9f)) return e;
    if (auto e = range("rpdb_max", b.rpdbMax, 0.0f, 1.0e9f)) return e;
    return std::nullopt;
}

}  // namespace pcf
