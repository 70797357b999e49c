// settings.h: pcfscope's settings in one place with no GL: the one settings struct every frame,
// trace and lesson step is made with (ShadowSettings), the table of its parameters (PARAMS:
// key, flag, uniform, unit, range, help), and the vocabulary the command line, lesson files and
// renderer parse and check through. Methods, their kernel sizes, weights and precision are in
// methods.h (with the kernel-size rule), bias modes in bias.h; both come with this header. Here:
// the depth formats, culling, the bias modes as an enum and the map-size range, with names <->
// enums.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "kernel/bias.h"
#include "kernel/cascades.h"
#include "kernel/methods.h"

namespace pcf {

enum class CullMode { Back, Front, None };
// What the camera pass draws on the receivers: `lit`, the picture (ambient plus the light times
// N.L times the visibility), or `visibility`, the filter's visibility alone as a grey level (0
// black, 1 white), with no N.L: under a low sun N.L is near 0 and the lit picture squeezes acne
// into a few grey levels, while the visibility alone shows it black on white.
// `cascades`: the lit picture tinted by the cascade each receiver reads (kernel/cascades.h; one
// colour per cascade, none past the last), to see where the splits fall.
enum class Shading { Lit, Visibility, Cascades };

// The shadow map is N x N texels, N in this range.
constexpr int MIN_MAP_SIZE = 4;
constexpr int MAX_MAP_SIZE = 4096;
// The largest light sizes, a directional light's angular diameter in degrees and a spot light's
// radius in world units: the ranges of light_size and light_radius, which scene files'
// angular_diameter and radius are read in too (scene/light.h). A sun disk wider than 10 degrees
// (19 suns) would no longer be a small light (the truth's disk is flat in angle, tan(r) ~ r); a
// spot disk 100 wide is larger than any teaching scene (the presets span 12).
constexpr float MAX_LIGHT_SIZE_DEG = 10.0f;
constexpr float MAX_LIGHT_RADIUS = 100.0f;
// The largest frame side (window, export, chart) in pixels.
constexpr int MAX_FRAME_SIDE = 8192;

// --depth-format: the texel kinds of a depth map (kernel/shadow_map.h) by name.
std::string_view depthFormatName(TexelKind format);                   // "16", "24", "32f"
std::optional<TexelKind> depthFormatFromName(std::string_view name);  // also "32", "32F"
std::string depthFormatNames();                                       // "16, 24, 32f"
// The depth format after `format` (after the last, the first): the viewer's D key.
TexelKind nextDepthFormat(TexelKind format);

// --evsm-exponents: "POS,NEG", each a number in (0, MAX_EVSM_EXPONENT].
constexpr float MAX_EVSM_EXPONENT = 100.0f;
std::string exponentsText(vec2 exponents);                     // "40,5"
std::optional<vec2> exponentsFromText(std::string_view text);  // nullopt: not two such numbers

// "none", "constant", "slope", ...: the names of kernel/bias.h, the one table of them.
std::string_view biasModeName(BiasMode mode);
std::optional<BiasMode> biasModeFromName(std::string_view name);

std::string_view cullModeName(CullMode mode);  // "back", "front", "none"
std::optional<CullMode> cullModeFromName(std::string_view name);
constexpr std::string_view CULL_MODE_NAMES = "back, front, none";

std::string_view shadingName(Shading shading);  // "lit", "visibility", "cascades"
std::optional<Shading> shadingFromName(std::string_view name);
constexpr std::string_view SHADING_NAMES = "lit, visibility, cascades";

// The settings one frame, one trace or one lesson step is made with: the filter, the bias and
// the shadow map. Declared once here, the bias's in BiasSettings (kernel/bias.h), which the
// kernel and the trace take alone; the renderer (RenderSettings) and the lessons
// (LessonSettings) add what only they need. Each field's key, flag, uniform, unit, range and
// help are its row of PARAMS (allParams()).
struct ShadowSettings : BiasSettings {
    int method = PCF_GATHER;  // a kernel id, PCF_NEAREST .. (methods.h)
    int kernel = 3;           // N
    float radius = 1.0f;      // poisson, texels
    bool rotate = false;      // poisson, pcss: rotate the disk per pixel
    // The light's size where it is used (pcss, the area-light truth), instead of the scene
    // light's: a directional light's angular diameter in degrees (lightSize) or a spot light's
    // radius in world units (lightRadius); 0 keeps the scene light's. Each applies to its own kind
    // of light only (scene/light.h lightSizeProblem, applyLightSize).
    float lightSize = 0.0f;
    float lightRadius = 0.0f;
    int weights = PCF_WEIGHTS_BOX;        // pcf-naive, pcf-gather: PCF_WEIGHTS_*
    float sigma = 1.0f;                   // gaussian weights, texels
    int precision = PCF_PRECISION_EXACT;  // hardware taps and gathers: PCF_PRECISION_*
    TexelKind depthFormat = TexelKind::D32F;
    int mapSize = 1024;              // the shadow map is mapSize x mapSize texels
    CullMode cull = CullMode::Back;  // faces culled in the shadow pass
    Shading shading = Shading::Lit;  // what the camera pass draws (the picture, not the lookup)
    // The moment methods (vsm .. msm-hausdorff): the light-bleeding reduction, the variance's
    // floor (light depth squared), the EVSM exponents (positive, negative) as asked (pcfParams
    // clamps them to evsmExponentLimit), MSM's moment bias, the moments' float bits (16, 32).
    float lbr = 0.0f;
    float minVariance = 1.0e-7f;
    vec2 evsmExponents = vec2(40.0f, 5.0f);
    float momentBias = 3.0e-5f;
    int momentBits = 32;

    // The EVSM exponents pcfParams hands the kernel: evsmExponents, each clamped to what
    // momentBits holds (evsmExponentLimit).
    vec2 evsmExponentsUsed() const;

    // Cascades of a directional light's map (kernel/cascades.h, scene/cascade_fit.h): how many
    // (1: one map fitted to the whole scene, no cascades), where they split the view depths
    // [camera near, shadowDistance] (0: the camera's far plane), how each light box is fitted
    // to its slice of the camera frustum, and how the last part of each fades into the next.
    int cascades = 1;
    int cascadeSplit = CASCADE_SPLIT_PRACTICAL;
    float cascadeLambda = 0.5f;
    float shadowDistance = 0.0f;
    int cascadeFit = CASCADE_FIT_BOX;
    bool cascadeSnap = false;
    // The blend band (shared/pcf_shading.h pcfCascadeBlendWeight): the fraction of each
    // cascade's view depths, at its far end, whose visibility fades into the next cascade's.
    float cascadeBlend = 0.0f;
    // The view depths the splits share out (kernel/cascades.h CASCADE_BOUNDS_*): [n, f] fixed, or
    // tightened to the frame's visible receivers (depth), measured by the renderer's prepass.
    int cascadeBounds = CASCADE_BOUNDS_FIXED;

    // The kernel's parameters; `rotation` is the Poisson disk's (cos, sin), when rotate says so
    // the caller's per-pixel one.
    // pcss's penumbraScale (texels per light depth) depends on the scene and the map: the
    // caller's, from scene/pcss.h penumbraScale(); 0 without a scene.
    PcfParams pcfParams(vec2 rotation = vec2(1.0f, 0.0f), float penumbraScale = 0.0f) const;

    bool operator==(const ShadowSettings&) const = default;
};

// A named setting's field and its names: a method, a bias mode, ... `noun` is what an unknown
// name is called in errors ("unknown bias mode 'x' (known: none, constant, ...)").
template <class T>
struct NamedField {
    T ShadowSettings::*field;
    std::string (*name)(T value);
    std::optional<T> (*fromName)(std::string_view name);
    std::string (*known)();  // "none, constant, ...": every name, for errors and help
    std::string_view noun;
};

// A parameter's field, by how it is written: a number, a flag (true/false) or a name.
using ParamField =
    std::variant<int ShadowSettings::*, float ShadowSettings::*, bool ShadowSettings::*,
                 NamedField<int>, NamedField<BiasMode>, NamedField<CullMode>, NamedField<TexelKind>,
                 NamedField<Shading>, NamedField<vec2>>;

// Which of the command line's option groups a parameter is in (render_options.h). View: what the
// frame draws of the lookups, which changes no lookup (commands that measure do not take it).
enum class ParamGroup { Filter, Bias, Map, View };

// The member of the kernel's structs (shaders/shared/pcf_kernel.h) that a parameter's uniform
// fills, the same member in C++ and GLSL: PcfParams's or PcfBias's. None (monostate) for a
// uniform that only the scene pass reads, around the filter (its per-lookup bias).
using KernelMember = std::variant<std::monostate, float PcfParams::*, float PcfBias::*>;

// One user-visible parameter: its row of the one parameter table. The default is the
// ShadowSettings member's; the lesson files' key is also the JSON sidecars' key, and the
// command line's flag is the key spelt with '-' (settingFlag).
struct ParamInfo {
    std::string_view key;  // "constant_bias"
    ParamField field;      // &ShadowSettings::constantBias
    ParamGroup group;
    // The shaders' uniform, "" when none: "u" and the kernel member's name, capitalised
    // ("uRpdbMax" fills PcfBias's rpdbMax). Declared and set from this table, in every program
    // that filters (render/pcf_programs.h: paramUniformsGlsl, setParamUniforms).
    std::string_view uniform;
    std::string_view unit;  // "texels", "light depth units", "" for counts and names
    double min = 0.0;       // numbers: the range, [min, max] (or (min, max] when minOpen)
    double max = 0.0;
    bool minOpen = false;
    std::string_view help;  // one line, the command line's help
    bool rawJson = false;   // in render --raw's render.json (what `verify` repeats)
    KernelMember member{};  // what the uniform fills in the kernel's structs
    // A rawJson parameter that render.json files written before it existed lack: `verify` then
    // takes its default (the value those folders were rendered with). The others are required.
    bool rawJsonMayLack = false;
    // The bias modes this parameter acts under, one bit per mode (biasModeBit); 0 for the
    // parameters that are no bias's. The trace's words, the status line and `verify` ask it
    // which parameters a mode reads.
    unsigned biasModes = 0;
    // The methods it acts for, a question to their table entries (methods.h); nullptr for a
    // parameter of every method (what is looked up, the map, the bias). The moment methods' own
    // parameters answer it (the bleed sweep sweeps a setting only where it acts).
    bool (*actsFor)(const MethodInfo& method) = nullptr;
};

// A bias mode's bit in ParamInfo::biasModes.
constexpr unsigned biasModeBit(BiasMode mode) { return 1u << static_cast<unsigned>(mode); }
// Whether parameter p acts under bias mode `mode` (its biasModes column).
inline bool paramActsUnder(const ParamInfo& p, BiasMode mode) {
    return (p.biasModes & biasModeBit(mode)) != 0;
}

// Whether parameter p acts for kernel id `method` (its actsFor column).
inline bool paramActsFor(const ParamInfo& p, int method) {
    return !p.actsFor || p.actsFor(methodInfo(method));
}

// Every parameter, in the order the JSON sidecars write them.
std::span<const ParamInfo> allParams();
// The row of `key`, or nullptr.
const ParamInfo* findParam(std::string_view key);
// "--constant-bias" for "constant_bias": the command line says each setting so (cliWords).
std::string settingFlag(std::string_view key);
// The parameter's value in `s` as text: "pcf-gather", "3", "0.002", "true".
std::string settingText(const ParamInfo& p, const ShadowSettings& s);

// The shortest text that reads back as exactly v: "89.0000000001", "1e-300", "0.002". Values in
// messages are printed so, never rounded to a limit they exceed.
std::string exactNumberText(double v);

// The one range check of a parameter: why v is outside p's range (a number's [min, max] or
// (min, max]; an integer's min..max, whole), or nullopt; names and flags have no range. In the
// kernel's words, the setting named as the lesson files' key ("light_size must be in [0, 10]
// degrees, got 11", "kernel must be 1..8, got 9"); the command line says it as its flag
// (app/cli_util.h: cliWords, "--light-size"). `given` is the value as the user wrote it, printed
// instead of exactNumberText(v) when not empty.
std::optional<ParamProblem> paramRangeProblem(const ParamInfo& p, double v,
                                              std::string_view given = {});
// Every numeric parameter of `s` in its range: the first that is not, or nullopt.
std::optional<ParamProblem> checkSettingRanges(const ShadowSettings& s);

// Sets parameter p of `s` from its text as written in a lesson's compare or on the command line
// ("0.002", "3", "true", "pcf-gather"): a number in decimal (no hex, no inf or nan) in its range,
// true or false, or a name in its canonical spelling. The problem, or nullopt with `s` set.
std::optional<ParamProblem> setParamFromText(ShadowSettings& s, const ParamInfo& p,
                                             std::string_view text);

}  // namespace pcf
