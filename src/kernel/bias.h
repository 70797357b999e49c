// bias.h: the bias modes by name (the command line's, the lesson files': docs/methods.md, "Bias
// modes"), their parameters, and which methods each can combine with. The per-tap math is in
// shaders/shared/pcf_kernel.h (pcfRefAt, pcfCompareSoft, pcfInterpolatedCompare); the per-lookup
// part (constant, slope, normal offset) is applied where the normal is known: shaders/scene.frag.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "kernel/methods.h"
#include "kernel/pcf.h"

namespace pcf {

// Defaults of the bias parameters, in one place for every command and the lesson files.
constexpr float DEFAULT_CONSTANT_BIAS = 0.002f;  // light depth units
constexpr float DEFAULT_SLOPE_BIAS = 0.001f;     // light depth units per unit of tan(theta)
constexpr float DEFAULT_SLOPE_MAX = 0.01f;       // light depth units
constexpr float DEFAULT_NORMAL_OFFSET = 1.5f;    // texels
// receiver-plane: the cap on |dz/du| and |dz/dv|, light depth per uv unit (pcfClampDzDuv). The
// ground of `grazing` (82 degrees from the light) has 1.3, at 88 degrees about 5; the cap binds
// where the screen-space derivative is no slope (outlines, faces edge-on to the light).
constexpr float DEFAULT_RPDB_MAX = 100.0f;  // light depth units per uv unit
// "PCF Shadow Acne 2" used the literal 2048 before naming it
// Z_CMP_CORRECTION_SCALE.
constexpr float DEFAULT_SOFT_SCALE = 2048.0f;  // 1 / light depth units

// The bias modes, in the kernel's order (the value is PCF_BIAS_NONE ..).
enum class BiasMode { None, Constant, Slope, Normal, ReceiverPlane, Soft, Interpolated };

// The bias mode and every parameter any mode reads, declared once: ShadowSettings
// (kernel/settings.h) is made of these and the filter's settings, and the parameter table
// (PARAMS) names each field's key, flag, uniform, unit and range. The kernel and the trace take
// them as they are, with the receiver's plane (dzduv), which is no setting: it comes with each
// pixel. Every mode but `none` subtracts `constantBias` from the receiver's depth; the mode
// says what it does besides:
//   constant        ref = z - constantBias
//   slope           ref = z - min(constantBias + slopeBias * tan(theta), slopeMax)
//   normal          the receiver moved along its normal by normalOffset texels * sin(theta)
//                   before projection, then ref = z' - constantBias
//   receiver-plane  ref = z - constantBias; each tap: ref + dot(dzduv', tap uv - uv), with dzduv'
//                   each component of dzduv clamped to [-rpdbMax, rpdbMax] (depth per uv unit)
//   soft            ref = z - constantBias; lit = (depth > ref) * saturate((depth - ref) *
//                   softScale)
//   interpolated    ref = z - constantBias, compared with the bilinearly interpolated depth
struct BiasSettings {
    BiasMode bias = BiasMode::Constant;
    float constantBias = DEFAULT_CONSTANT_BIAS;
    float slopeBias = DEFAULT_SLOPE_BIAS;
    float slopeMax = DEFAULT_SLOPE_MAX;
    float normalOffset = DEFAULT_NORMAL_OFFSET;
    float softScale = DEFAULT_SOFT_SCALE;
    float rpdbMax = DEFAULT_RPDB_MAX;

    // The mode as the kernel's id, PCF_BIAS_NONE ..
    int modeId() const { return static_cast<int>(bias); }
    // What the kernel needs per tap. dzduv: receiver-plane's d(depth)/d(u, v) of the receiver
    // at the lookup, as the renderer measured it (light depth per uv unit).
    PcfBias kernelBias(vec2 dzduv = vec2(0.0f)) const {
        return PcfBias(modeId(), dzduv, softScale, rpdbMax);
    }
    // The depth every mode but none subtracts first: 0 for none, else `constantBias`.
    float baseBias() const { return bias == BiasMode::None ? 0.0f : constantBias; }
    // The per-lookup bias for a surface at angle theta to the light (cos given): what is
    // subtracted from z to give ref. Normal offset moves the point instead: baseBias() here.
    float lookupBias(float cosTheta) const;

    bool operator==(const BiasSettings&) const = default;
};

// "none", "constant", ... by id (PCF_BIAS_NONE ..), and back.
std::string_view biasName(int mode);
std::optional<int> biasFromName(std::string_view name);
// "none, constant, slope, ..." for error messages.
std::string biasNameList();
// What the mode does, in the parameter table's keys (the table above, spelt as the lesson files
// and the trace's words spell them): "ref = z - min(constant_bias + slope_bias * tan(theta),
// slope_max)". The trace's words print it with the values of every row acting under the mode.
std::string_view biasFormula(int mode);

// Why this bias mode cannot combine with this method (one sentence, no trailing period), or
// nullopt when it can. soft needs the depths in the shader (not hw2x2, pcf-hw, tent);
// interpolated is a hard comparison (nearest only).
std::optional<std::string> validateBias(int mode, int method);

// Their ranges are the parameter table's: checkSettingRanges (kernel/settings.h).

}  // namespace pcf
