#include "kernel/bias.h"

#include <array>
#include <cmath>

#include "kernel/methods.h"

namespace pcf {

static_assert(static_cast<int>(BiasMode::None) == PCF_BIAS_NONE &&
              static_cast<int>(BiasMode::ReceiverPlane) == PCF_BIAS_RECEIVER_PLANE &&
              static_cast<int>(BiasMode::Interpolated) == PCF_BIAS_INTERPOLATED);

namespace {

constexpr std::array<std::string_view, PCF_BIAS_COUNT> BIAS_NAMES = {
    "none", "constant", "slope", "normal", "receiver-plane", "soft", "interpolated"};

// In the order of BIAS_NAMES; the formulas of the comment on BiasSettings (bias.h).
constexpr std::array<std::string_view, PCF_BIAS_COUNT> BIAS_FORMULAS = {
    "ref = z",
    "ref = z - constant_bias",
    "ref = z - min(constant_bias + slope_bias * tan(theta), slope_max), theta the angle between "
    "the surface normal and the light",
    "the receiver point moves along its normal by normal_offset texels * sin(theta) before "
    "projection (so uv is the moved point's), then ref = z' - constant_bias with z' the moved "
    "point's depth",
    "ref = z - constant_bias at uv; each tap compares against ref + dot(dz/duv, tap uv - uv), "
    "each component of dz/duv clamped to [-rpdb_max, rpdb_max]",
    "ref = z - constant_bias; a tap is lit by (depth > ref) * saturate((depth - ref) * "
    "soft_scale), so a texel just beyond ref counts in part (\"PCF Shadow Acne\" part 2)",
    "ref = z - constant_bias, compared once with the map's depth lerped at uv (\"PCF Shadow "
    "Acne\", Solution 2)"};

}  // namespace

std::string_view biasFormula(int mode) {
    if (mode < 0 || mode >= PCF_BIAS_COUNT) return "?";
    return BIAS_FORMULAS[static_cast<size_t>(mode)];
}

float BiasSettings::lookupBias(float cosTheta) const {
    if (bias == BiasMode::Slope) return pcfSlopeBias(cosTheta, constantBias, slopeBias, slopeMax);
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
    if (mode == PCF_BIAS_SOFT && methodInfo(method).reads == MethodReads::HwTaps) {
        return "bias soft compares depths in the shader, but " + name +
               " gets its comparisons from the texture unit (hardware taps); use nearest, "
               "box2x2, bilinear2x2, pcf-naive, pcf-gather or poisson";
    }
    if ((mode == PCF_BIAS_SOFT || mode == PCF_BIAS_RECEIVER_PLANE) && readsMoments(method)) {
        return "bias " + std::string(biasName(mode)) + " changes each tap's comparison, but " +
               name +
               " compares no taps: it reads the filtered moments once; use none, constant, "
               "slope or normal";
    }
    if (mode == PCF_BIAS_INTERPOLATED && !methodInfo(method).hard) {
        return "bias interpolated compares one bilinearly interpolated depth, a hard edge; " +
               name +
               " lerps comparison bits by the same sub-texel fraction, so the two cannot "
               "combine (\"PCF Shadow Acne\", Solution 2); use --method nearest";
    }
    return std::nullopt;
}

}  // namespace pcf
