#include "kernel/settings.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <span>
#include <sstream>
#include <type_traits>

#include "kernel/shading.h"
#include "kernel/sigma_limits.h"

namespace pcf {

namespace {

constexpr std::string_view TEXELS = "texels";

// A name function of the table's: the text of a value.
template <class T, std::string_view (*F)(T)>
std::string nameOf(T value) {
    return std::string(F(value));
}
constexpr std::string_view DEPTH_UNITS = "light depth units";

// Every mode but none subtracts the constant bias (kernel/bias.h).
constexpr unsigned BIASED_MODES = ((1u << PCF_BIAS_COUNT) - 1u) & ~biasModeBit(BiasMode::None);

// What the moment methods' own parameters act for, asked of the methods' table entries: the
// Chebyshev bound's (moments read without a reconstruction: vsm, evsm2, evsm4), the warps' (evsm),
// the reconstruction's (msm) and the moments map's (every moment method).
bool boundsByChebyshev(const MethodInfo& m) {
    return m.mapPass != MapPass::Depth && !m.reconstructs;
}
bool warpsDepths(const MethodInfo& m) { return m.warps > 0; }
bool reconstructsDepths(const MethodInfo& m) { return m.reconstructs; }
bool readsMomentsMap(const MethodInfo& m) { return m.mapPass != MapPass::Depth; }

// The one parameter table (settings.h ParamInfo). Ranges are the named limits of methods.h and
// this header, checked by paramRangeProblem; what depends on the method (tent's sizes) by
// checkParams. After a row's kernel member come rawJsonMayLack, the bias modes it acts under and
// the methods it acts for.
// clang-format off
const ParamInfo PARAMS[] = {
    {"method", NamedField<int>{&ShadowSettings::method,
        [](int m) { return std::string(methodInfo(m).name); },
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
     "pcss, the area-light truth: a directional light's angular diameter in degrees (0: the "
     "scene light's; pcss takes the sun's 0.53 when it has none)", true, {}, true},
    {"light_radius", &ShadowSettings::lightRadius, ParamGroup::Filter, "", "world units", 0.0,
     MAX_LIGHT_RADIUS, false,
     "pcss, the area-light truth: a spot light's radius in world units (0: the scene light's)",
     true, {}, true},
    {"weights", NamedField<int>{&ShadowSettings::weights, nameOf<int, weightsName>, weightsFromName,
        [] { return std::string("box, binomial, gaussian"); }, "weights"}, ParamGroup::Filter,
     "", "", 0, 0, false,
     "pcf-naive, pcf-gather: weights of the N x N lookups: box, binomial, gaussian", true},
    {"sigma", &ShadowSettings::sigma, ParamGroup::Filter, "uSigma", TEXELS, MIN_SIGMA, MAX_SIGMA, false,
     "gaussian weights: standard deviation in texels", true, &PcfParams::sigma},
    {"precision", NamedField<int>{&ShadowSettings::precision, nameOf<int, precisionName>,
        precisionFromName,
        [] { return std::string("exact, hw8"); }, "precision"}, ParamGroup::Filter,
     "", "", 0, 0, false,
     "texel position inside hardware taps and gathers: exact, hw8 (1/256 texel)", true},
    {"depth_format", NamedField<TexelKind>{&ShadowSettings::depthFormat,
        nameOf<TexelKind, depthFormatName>,
        depthFormatFromName, depthFormatNames, "depth format"},
     ParamGroup::Map, "", "", 0, 0, false, "shadow map depth format", true},
    {"map_size", &ShadowSettings::mapSize, ParamGroup::Map, "", TEXELS, MIN_MAP_SIZE,
     MAX_MAP_SIZE, false, "shadow map size in texels (4..4096)", true, {}, true},
    {"bias", NamedField<BiasMode>{&ShadowSettings::bias, nameOf<BiasMode, biasModeName>,
        biasModeFromName,
        biasNameList, "bias mode"}, ParamGroup::Bias, "", "", 0, 0, false,
     "bias mode (README \"Bias modes\"; every mode but none subtracts --constant-bias)", true,
     {}, true},
    {"constant_bias", &ShadowSettings::constantBias, ParamGroup::Bias, "uConstantBias",
     DEPTH_UNITS, -1.0, 1.0, false,
     "depth subtracted from z in light depth units (ref = z - B)", true, {}, false,
     BIASED_MODES},
    {"slope_bias", &ShadowSettings::slopeBias, ParamGroup::Bias, "uSlopeBias",
     "light depth units per unit of tan(theta)", 0.0, 1.0, false,
     "slope: S in ref = z - min(B + S * tan(theta), M)", true, {}, false,
     biasModeBit(BiasMode::Slope)},
    {"slope_max", &ShadowSettings::slopeMax, ParamGroup::Bias, "uSlopeMax", DEPTH_UNITS, 0.0, 1.0,
     false, "slope: the cap M, light depth units", true, {}, false, biasModeBit(BiasMode::Slope)},
    {"normal_offset", &ShadowSettings::normalOffset, ParamGroup::Bias, "uNormalOffset", TEXELS,
     0.0, 64.0, false,
     "normal: K, texels the receiver moves along its normal (times sin(theta))", true, {}, true,
     biasModeBit(BiasMode::Normal)},
    {"soft_scale", &ShadowSettings::softScale, ParamGroup::Bias, "uSoftScale",
     "1 / light depth units", 1.0, 1.0e9, false,
     "soft: lit = (depth > ref) * saturate((depth - ref) * SCALE)", true, &PcfBias::softScale,
     true, biasModeBit(BiasMode::Soft)},
    {"rpdb_max", &ShadowSettings::rpdbMax, ParamGroup::Bias, "uRpdbMax",
     "light depth per uv unit", 0.0, 1.0e9, false,
     "receiver-plane: cap M on each component of dz/duv, light depth per uv unit (the whole map)",
     true, &PcfBias::rpdbMax, true, biasModeBit(BiasMode::ReceiverPlane)},
    {"cull", NamedField<CullMode>{&ShadowSettings::cull, nameOf<CullMode, cullModeName>,
        cullModeFromName,
        [] { return std::string(CULL_MODE_NAMES); }, "cull mode"}, ParamGroup::Map, "", "", 0, 0,
     false, "faces culled in the shadow pass: back, front, none", false},
    {"shading", NamedField<Shading>{&ShadowSettings::shading, nameOf<Shading, shadingName>,
        shadingFromName,
        [] { return std::string(SHADING_NAMES); }, "shading"}, ParamGroup::View, "uShading", "",
     0, 0, false,
     "what the receivers show: lit (ambient + N.L x visibility), visibility (alone, 0 black "
     "to 1 white, no N.L) or cascades (lit, tinted by the cascade read)", true, {}, true},
    {"lbr", &ShadowSettings::lbr, ParamGroup::Filter, "uLbr", "", 0.0, 0.99, false,
     "vsm, evsm2, evsm4: light-bleeding reduction, the bound's cut (linstep(lbr, 1, p))", true,
     &PcfParams::lbr, true, 0, boundsByChebyshev},
    {"min_variance", &ShadowSettings::minVariance, ParamGroup::Filter, "uMinVariance",
     "light depth squared", 0.0, 0.01, false,
     "vsm, evsm2, evsm4: the variance's floor (the warps' scaled by their slope)", true,
     &PcfParams::minVariance, true, 0, boundsByChebyshev},
    {"evsm_exponents", NamedField<vec2>{&ShadowSettings::evsmExponents, exponentsText,
        exponentsFromText, [] { return std::string("POS,NEG, each in (0, 100]"); },
        "EVSM exponents"}, ParamGroup::Filter, "", "", 0, 0, false,
     "evsm2, evsm4: the warps' exponents POS,NEG (used up to 42 in 32f, 5.54 in 16f)", true, {},
     true, 0, warpsDepths},
    {"moment_bias", &ShadowSettings::momentBias, ParamGroup::Filter, "uMomentBias", "", 0.0, 0.5,
     false, "msm, msm-hausdorff: the moment bias alpha, b' = lerp(b, 0.5, alpha)", true,
     &PcfParams::momentBias, true, 0, reconstructsDepths},
    {"moment_format", NamedField<int>{&ShadowSettings::momentBits, nameOf<int, momentFormatName>,
        momentFormatFromName, [] { return std::string("16f, 32f"); }, "moment format"},
     ParamGroup::Map, "", "", 0, 0, false,
     "the moment methods: the moments map's floats, 16f or 32f", true, {}, true, 0,
     readsMomentsMap},
    {"cascades", &ShadowSettings::cascades, ParamGroup::Map, "", "", 1, MAX_CASCADES, false,
     "directional light: cascades of the map, 1..4 (1: one map over the whole scene)", true, {},
     true},
    {"cascade_split", NamedField<int>{&ShadowSettings::cascadeSplit, nameOf<int, cascadeSplitName>,
        cascadeSplitFromName, cascadeSplitNames, "cascade split"}, ParamGroup::Map, "", "", 0, 0,
     false, "cascades: where the view depth splits: uniform, log, practical (by --cascade-lambda)",
     true, {}, true},
    {"cascade_lambda", &ShadowSettings::cascadeLambda, ParamGroup::Map, "", "", 0.0, 1.0, false,
     "cascades, practical split: 0 uniform .. 1 log (Zhang et al. 2006)", true, {}, true},
    {"shadow_distance", &ShadowSettings::shadowDistance, ParamGroup::Map, "", "scene units", 0.0,
     1.0e6, false, "cascades: the view depth the last one ends at (0: the camera's far plane)",
     true, {}, true},
    {"cascade_fit", NamedField<int>{&ShadowSettings::cascadeFit, nameOf<int, cascadeFitName>,
        cascadeFitFromName, cascadeFitNames, "cascade fit"}, ParamGroup::Map, "", "", 0, 0, false,
     "cascades: the light box around each slice: box (tight) or sphere (the same size as the "
     "camera turns)", true, {}, true},
    {"cascade_snap", &ShadowSettings::cascadeSnap, ParamGroup::Map, "", "", 0, 0, false,
     "cascades: move each light box's origin to whole texels", true, {}, true},
    {"cascade_blend", &ShadowSettings::cascadeBlend, ParamGroup::Map, "uCascadeBlend", "", 0.0,
     1.0, false,
     "cascades: the last B of each cascade's view depths fades into the next one's lookup (0: "
     "none)", true, {}, true},
    {"cascade_bounds", NamedField<int>{&ShadowSettings::cascadeBounds,
        nameOf<int, cascadeBoundsName>, cascadeBoundsFromName, cascadeBoundsNames,
        "cascade bounds"}, ParamGroup::Map, "", "", 0, 0, false,
     "cascades: the view depths they split: fixed (the camera's near plane to the shadow "
     "distance) or depth (tightened to the frame's visible receivers, measured by a prepass)",
     true, {}, true},
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
    p.lbr = lbr;
    p.minVariance = minVariance;
    p.evsmExponents = evsmExponentsUsed();
    p.momentBias = momentBias;
    return p;
}

vec2 ShadowSettings::evsmExponentsUsed() const {
    return glm::min(evsmExponents, vec2(evsmExponentLimit(momentBits)));
}

std::string exponentsText(vec2 exponents) {
    return numberText(exponents.x) + "," + numberText(exponents.y);
}

std::optional<vec2> exponentsFromText(std::string_view text) {
    size_t comma = text.find(',');
    if (comma == std::string_view::npos) return std::nullopt;
    vec2 out(0.0f);
    for (int k = 0; k < 2; ++k) {
        std::string part(k == 0 ? text.substr(0, comma) : text.substr(comma + 1));
        char* end = nullptr;
        double v = std::strtod(part.c_str(), &end);
        if (part.empty() || end != part.c_str() + part.size() || !std::isfinite(v) || v <= 0.0 ||
            v > MAX_EVSM_EXPONENT) {
            return std::nullopt;
        }
        out[k] = static_cast<float>(v);
    }
    return out;
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

std::string exactNumberText(double v) {
    char text[32];
    auto [end, ec] = std::to_chars(text, text + sizeof text, v);
    return ec == std::errc() ? std::string(text, end) : numberText(v);
}

namespace {

// A float limit as the decimal it was written as: MIN_SIGMA (0.05f) is 0.0500000007 as a double,
// which a typed 0.05 is below. The shortest decimal that reads back as the float is 0.05.
double decimalLimit(double limit) {
    char text[32];
    auto [end, ec] = std::to_chars(text, text + sizeof text, static_cast<float>(limit));
    double v = limit;
    if (ec == std::errc()) std::from_chars(text, end, v);
    return v;
}

std::string floatText(float v) {
    char text[32];
    auto [end, ec] = std::to_chars(text, text + sizeof text, v);
    return ec == std::errc() ? std::string(text, end) : numberText(v);
}

// Whether v is in p's range: an integer's, whole; a float parameter's, either as a decimal
// against the decimal limits (a typed 10.000000001 is above 10, though its float is 10), or, for
// a value that is a float already (a setting as stored), as a float against the float limits
// (0.3f is above the decimal 0.3 but is the limit itself).
bool inRange(const ParamInfo& p, double v, bool whole) {
    if (!std::isfinite(v)) return false;
    if (whole) return v >= p.min && v <= p.max && v == std::floor(v);
    double lo = decimalLimit(p.min), hi = decimalLimit(p.max);
    if ((p.minOpen ? v > lo : v >= lo) && v <= hi) return true;
    auto f = static_cast<float>(v);
    if (static_cast<double>(f) != v) return false;
    auto flo = static_cast<float>(p.min), fhi = static_cast<float>(p.max);
    return (p.minOpen ? f > flo : f >= flo) && f <= fhi;
}

}  // namespace

std::optional<ParamProblem> paramRangeProblem(const ParamInfo& p, double v,
                                              std::string_view given) {
    bool whole = std::holds_alternative<int ShadowSettings::*>(p.field);
    if (!whole && !std::holds_alternative<float ShadowSettings::*>(p.field)) return std::nullopt;
    if (inRange(p, v, whole)) return std::nullopt;
    std::string got = given.empty() ? exactNumberText(v) : std::string(given);
    std::string lo = exactNumberText(whole ? p.min : decimalLimit(p.min));
    std::string hi = exactNumberText(whole ? p.max : decimalLimit(p.max));
    if (whole)
        return ParamProblem{std::string(p.key), "", " must be " + lo + ".." + hi + ", got " + got};
    return ParamProblem{std::string(p.key), "",
                        " must be in " + std::string(p.minOpen ? "(" : "[") + lo + ", " + hi + "]" +
                            (p.unit.empty() ? "" : " ") + std::string(p.unit) + ", got " + got};
}

std::optional<ParamProblem> checkSettingRanges(const ShadowSettings& s) {
    for (const ParamInfo& p : PARAMS) {
        std::optional<ParamProblem> problem;
        if (const auto* f = std::get_if<float ShadowSettings::*>(&p.field)) {
            // A stored float printed as the float it is ("0.3", not "0.30000001192092896").
            problem = paramRangeProblem(p, static_cast<double>(s.*(*f)), floatText(s.*(*f)));
        } else if (const auto* i = std::get_if<int ShadowSettings::*>(&p.field)) {
            problem = paramRangeProblem(p, static_cast<double>(s.*(*i)));
        }
        if (problem) return problem;
    }
    return std::nullopt;
}

namespace {

// A decimal number filling all of `text` (from_chars: no leading +, no hex), or nullopt.
std::optional<double> decimalNumber(std::string_view text) {
    double v = 0.0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return v;
}

}  // namespace

std::optional<ParamProblem> setParamFromText(ShadowSettings& s, const ParamInfo& p,
                                             std::string_view text) {
    std::string key(p.key);
    auto problem = [&](std::string after) { return ParamProblem{key, "", std::move(after)}; };
    return std::visit(
        [&](const auto& field) -> std::optional<ParamProblem> {
            using F = std::decay_t<decltype(field)>;
            if constexpr (std::is_same_v<F, bool ShadowSettings::*>) {
                if (text != "true" && text != "false") {
                    return problem(" must be true or false, got '" + std::string(text) + "'");
                }
                s.*field = text == "true";
            } else if constexpr (std::is_same_v<F, int ShadowSettings::*> ||
                                 std::is_same_v<F, float ShadowSettings::*>) {
                std::optional<double> v = decimalNumber(text);
                if (!v) {
                    return problem(" must be a decimal number, got '" + std::string(text) + "'");
                }
                if (auto why = paramRangeProblem(p, *v, text)) return why;
                using T = std::remove_reference_t<decltype(s.*field)>;
                s.*field = static_cast<T>(*v);
            } else {
                auto v = field.fromName(text);
                if (!v || field.name(*v) != text) {
                    return ParamProblem{"",
                                        "unknown " + std::string(field.noun) + " '" +
                                            std::string(text) + "' (known: " + field.known() + ")",
                                        ""};
                }
                s.*field.field = *v;
            }
            return std::nullopt;
        },
        p.field);
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
              static_cast<int>(Shading::Visibility) == PCF_SHADING_VISIBILITY &&
              static_cast<int>(Shading::Cascades) == PCF_SHADING_CASCADES);

std::string_view shadingName(Shading shading) {
    switch (shading) {
        case Shading::Lit:
            return "lit";
        case Shading::Visibility:
            return "visibility";
        case Shading::Cascades:
            return "cascades";
    }
    return "?";
}

std::optional<Shading> shadingFromName(std::string_view name) {
    if (name == "lit") return Shading::Lit;
    if (name == "visibility") return Shading::Visibility;
    if (name == "cascades") return Shading::Cascades;
    return std::nullopt;
}

std::optional<CullMode> cullModeFromName(std::string_view name) {
    if (name == "back") return CullMode::Back;
    if (name == "front") return CullMode::Front;
    if (name == "none") return CullMode::None;
    return std::nullopt;
}

}  // namespace pcf
