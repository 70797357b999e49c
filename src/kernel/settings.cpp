#include "kernel/settings.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <sstream>
#include <type_traits>

#include "kernel/shading.h"
#include "kernel/sigma_limits.h"

namespace pcf {

namespace {

constexpr std::string_view TEXELS = "texels";
constexpr std::string_view DEPTH_UNITS = "light depth units";

// The one parameter table (settings.h ParamInfo). Ranges are the named limits of methods.h and
// this header; checkBiasSettings checks the bias parameters' here, checkParams the filter's.
// clang-format off
const ParamInfo PARAMS[] = {
    {"method", NamedField<int>{&ShadowSettings::method, [](int m) { return methodInfo(m).name; },
        methodFromName, methodNameList, "method"}, ParamGroup::Filter, "", "", 0, 0, false,
     "PCF method id (see `pcfscope methods`)", true},
    {"kernel", &ShadowSettings::kernel, ParamGroup::Filter, "", "", MIN_KERNEL, MAX_KERNEL, false,
     "kernel size N (tent: 3, 5 or 7)", true},
    {"radius", &ShadowSettings::radius, ParamGroup::Filter, "uRadius", TEXELS, 0.0,
     MAX_POISSON_RADIUS, true, "poisson: disk radius in texels", true, &PcfParams::radius},
    {"rotate", &ShadowSettings::rotate, ParamGroup::Filter, "", "", 0, 0, false,
     "poisson, pcss: rotate the disk per pixel", true},
    {"light_size", &ShadowSettings::lightSize, ParamGroup::Filter, "", "degrees", 0.0,
     MAX_LIGHT_SIZE_DEG, false,
     "pcss: the light's angular diameter in degrees (0: the scene light's, or the sun's 0.53)",
     true},
    {"weights", NamedField<int>{&ShadowSettings::weights, weightsName, weightsFromName,
        [] { return std::string("box, binomial, gaussian"); }, "weights"}, ParamGroup::Filter,
     "", "", 0, 0, false,
     "pcf-naive, pcf-gather: weights of the N x N lookups: box, binomial, gaussian", true},
    {"sigma", &ShadowSettings::sigma, ParamGroup::Filter, "uSigma", TEXELS, MIN_SIGMA, MAX_SIGMA, false,
     "gaussian weights: standard deviation in texels", true, &PcfParams::sigma},
    {"precision", NamedField<int>{&ShadowSettings::precision, precisionName, precisionFromName,
        [] { return std::string("exact, hw8"); }, "precision"}, ParamGroup::Filter,
     "", "", 0, 0, false,
     "texel position inside hardware taps and gathers: exact, hw8 (1/256 texel)", true},
    {"depth_format", NamedField<TexelKind>{&ShadowSettings::depthFormat, depthFormatName,
        depthFormatFromName, depthFormatNames, "depth format"},
     ParamGroup::Map, "", "", 0, 0, false, "shadow map depth format", true},
    {"map_size", &ShadowSettings::mapSize, ParamGroup::Map, "", TEXELS, MIN_MAP_SIZE,
     MAX_MAP_SIZE, false, "shadow map size in texels (4..4096)", true},
    {"bias", NamedField<BiasMode>{&ShadowSettings::bias, biasModeName, biasModeFromName,
        biasNameList, "bias mode"}, ParamGroup::Bias, "", "", 0, 0, false,
     "bias mode (README \"Bias modes\"; every mode but none subtracts --constant-bias)", true},
    {"constant_bias", &ShadowSettings::constantBias, ParamGroup::Bias, "uConstantBias",
     DEPTH_UNITS, -1.0, 1.0, false,
     "depth subtracted from z in light depth units (ref = z - B)", true},
    {"slope_bias", &ShadowSettings::slopeBias, ParamGroup::Bias, "uSlopeBias",
     "light depth units per unit of tan(theta)", 0.0, 1.0, false,
     "slope: S in ref = z - min(B + S * tan(theta), M)", true},
    {"slope_max", &ShadowSettings::slopeMax, ParamGroup::Bias, "uSlopeMax", DEPTH_UNITS, 0.0, 1.0,
     false, "slope: the cap M, light depth units", true},
    {"normal_offset", &ShadowSettings::normalOffset, ParamGroup::Bias, "uNormalOffset", TEXELS,
     0.0, 64.0, false,
     "normal: K, texels the receiver moves along its normal (times sin(theta))", true},
    {"soft_scale", &ShadowSettings::softScale, ParamGroup::Bias, "uSoftScale",
     "1 / light depth units", 1.0, 1.0e9, false,
     "soft: lit = (depth > ref) * saturate((depth - ref) * SCALE)", true, &PcfBias::softScale},
    {"rpdb_max", &ShadowSettings::rpdbMax, ParamGroup::Bias, "uRpdbMax",
     "light depth per uv unit", 0.0, 1.0e9, false,
     "receiver-plane: cap M on each component of dz/duv, light depth per uv unit (the whole map)",
     true, &PcfBias::rpdbMax},
    {"cull", NamedField<CullMode>{&ShadowSettings::cull, cullModeName, cullModeFromName,
        [] { return std::string(CULL_MODE_NAMES); }, "cull mode"}, ParamGroup::Map, "", "", 0, 0,
     false, "faces culled in the shadow pass: back, front, none", false},
    {"shading", NamedField<Shading>{&ShadowSettings::shading, shadingName, shadingFromName,
        [] { return std::string(SHADING_NAMES); }, "shading"}, ParamGroup::View, "uShading", "",
     0, 0, false,
     "what the receivers show: lit (ambient + N.L x visibility) or visibility (alone, 0 black "
     "to 1 white, no N.L)", true},
};
// clang-format on

std::string numberText(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

}  // namespace

PcfParams ShadowSettings::pcfParams(vec2 rotation, float penumbraScale) const {
    PcfParams p = makeParams(method, kernel, radius, rotation);
    p.penumbraScale = penumbraScale;
    p.weights = weights;
    p.sigma = sigma;
    p.precision = precision;
    return p;
}

std::span<const ParamInfo> allParams() { return PARAMS; }

const ParamInfo* findParam(std::string_view key) {
    for (const ParamInfo& p : PARAMS) {
        if (p.key == key) return &p;
    }
    return nullptr;
}

std::string settingFlag(std::string_view key) {
    std::string flag = "--" + std::string(key);
    std::replace(flag.begin(), flag.end(), '_', '-');
    return flag;
}

std::string settingText(const ParamInfo& p, const ShadowSettings& s) {
    return std::visit(
        [&](const auto& field) -> std::string {
            using F = std::decay_t<decltype(field)>;
            if constexpr (std::is_same_v<F, bool ShadowSettings::*>) {
                return s.*field ? "true" : "false";
            } else if constexpr (std::is_same_v<F, int ShadowSettings::*> ||
                                 std::is_same_v<F, float ShadowSettings::*>) {
                return numberText(static_cast<double>(s.*field));
            } else {
                return std::string(field.name(s.*field.field));
            }
        },
        p.field);
}

std::optional<ParamProblem> checkBiasSettings(const ShadowSettings& s) {
    for (const ParamInfo& p : PARAMS) {
        const auto* field = std::get_if<float ShadowSettings::*>(&p.field);
        if (p.group != ParamGroup::Bias || !field) continue;
        double v = static_cast<double>(s.*(*field));
        if (std::isfinite(v) && (p.minOpen ? v > p.min : v >= p.min) && v <= p.max) continue;
        return ParamProblem{std::string(p.key), "",
                            " must be in " + std::string(p.minOpen ? "(" : "[") +
                                numberText(p.min) + ", " + numberText(p.max) + "], got " +
                                numberText(v)};
    }
    return std::nullopt;
}

std::string_view depthFormatName(TexelKind format) { return texelKindName(format); }

std::optional<TexelKind> depthFormatFromName(std::string_view name) {
    std::optional<TexelKind> kind = texelKindFromName(name);
    if (!kind || !texelKindInfo(*kind).depth) return std::nullopt;
    return kind;
}

std::string depthFormatNames() {
    std::string out;
    for (TexelKind k : allTexelKinds()) {
        if (!texelKindInfo(k).depth) continue;
        out += (out.empty() ? "" : ", ") + std::string(texelKindName(k));
    }
    return out;
}

TexelKind nextDepthFormat(TexelKind format) {
    std::span<const TexelKind> kinds = allTexelKinds();
    auto at = std::find(kinds.begin(), kinds.end(), format);
    for (size_t k = 1; k <= kinds.size(); ++k) {
        TexelKind next = kinds[(static_cast<size_t>(at - kinds.begin()) + k) % kinds.size()];
        if (texelKindInfo(next).depth) return next;
    }
    return format;
}

std::string_view biasModeName(BiasMode mode) { return biasName(static_cast<int>(mode)); }

std::optional<BiasMode> biasModeFromName(std::string_view name) {
    std::optional<int> id = biasFromName(name);
    if (!id) return std::nullopt;
    return static_cast<BiasMode>(*id);
}

std::string_view cullModeName(CullMode mode) {
    switch (mode) {
        case CullMode::Back:
            return "back";
        case CullMode::Front:
            return "front";
        case CullMode::None:
            return "none";
    }
    return "?";
}

// The shader tests the setting's uniform against the shared header's ids.
static_assert(static_cast<int>(Shading::Lit) == PCF_SHADING_LIT &&
              static_cast<int>(Shading::Visibility) == PCF_SHADING_VISIBILITY);

std::string_view shadingName(Shading shading) {
    switch (shading) {
        case Shading::Lit:
            return "lit";
        case Shading::Visibility:
            return "visibility";
    }
    return "?";
}

std::optional<Shading> shadingFromName(std::string_view name) {
    if (name == "lit") return Shading::Lit;
    if (name == "visibility") return Shading::Visibility;
    return std::nullopt;
}

std::optional<CullMode> cullModeFromName(std::string_view name) {
    if (name == "back") return CullMode::Back;
    if (name == "front") return CullMode::Front;
    if (name == "none") return CullMode::None;
    return std::nullopt;
}

}  // namespace pcf
