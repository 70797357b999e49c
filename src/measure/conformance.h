// conformance.h: what any conformant texture unit may return for a PCF lookup, as an interval.
//
// Modelled on Khronos VK-GL-CTS's texture-compare verifier (framework/common/
// tcuTexCompareVerifier.cpp, isTexCompareResultValid): instead of one exact answer, the
// verifier allows every result a texture unit with a given precision could produce:
//   - sub-texel bits: the texel position p = uv * size - 0.5 is known to +-2^-subTexelBits texel
//     (Vulkan guarantees subTexelPrecisionBits >= 4; D3D12 and NVIDIA/AMD use 8);
//   - weight bits: the lerp weights are rounded to weightBits (CTS's pcfBits), moving a hardware
//     tap's result by up to 2^-weightBits;
//   - reference bits: D_ref and D_t may be compared at referenceBits (16, 24 for fixed-point
//     maps, 22 for 32F here), so a comparison with |D_ref - D_t| <= 2^-referenceBits may go
//     either way.
// Texel fetches in the shader (nearest, box2x2, bilinear2x2, pcf-naive, poisson) are float
// arithmetic, exact up to that reference tolerance; hardware taps (hw2x2, pcf-hw, tent) and
// gathers (pcf-gather) get the texture unit's freedom. The lookup's interval is the weighted sum
// of its fetches' intervals.
#pragma once

#include <string>

#include "kernel/pcf.h"
#include "kernel/shadow_map.h"

namespace pcf {

// The moment methods (vsm .. msm-hausdorff) compare nothing in the texture unit: the GPU's
// visibility is the kernel's float arithmetic on the moments it read (the same moments the CPU
// reads back), so it is held to the CPU's within this much, what exp, division and sqrt on a
// GPU may differ by (measured on llvmpipe: tests/gpu_parity_test.cpp).
constexpr float MOMENT_TOLERANCE = 1.0e-4f;

struct ConformancePrecision {
    int subTexelBits = 4;   // Vulkan's minimum subTexelPrecisionBits
    int weightBits = 8;     // filtering weight precision (CTS: pcfBits)
    int referenceBits = 0;  // 0: from the map (16 or 24 fixed-point, 22 for 32F)
};

struct VisibilityEnvelope {
    float lo = 0.0f;
    float hi = 1.0f;
    bool contains(float v, float tolerance = 1e-5f) const {
        return v >= lo - tolerance && v <= hi + tolerance;
    }
};

// The interval of visibilities a conformant GPU may return for pcfFilter(map, uv, ref, prm).
// Always contains the exact CPU result (precision `exact`) and the hw8 one.
VisibilityEnvelope visibilityEnvelope(const ShadowMap& map, vec2 uv, float ref,
                                      const PcfParams& prm, const ConformancePrecision& prec = {});
// The same under a bias mode that acts per tap (receiver-plane: each tap's own ref from the
// plane; soft: fractional comparisons; interpolated: one comparison against the bilinear depth),
// as pcfFilter(map, uv, ref, prm, bias) computes it.
VisibilityEnvelope visibilityEnvelope(const ShadowMap& map, vec2 uv, float ref,
                                      const PcfParams& prm, const PcfBias& bias,
                                      const ConformancePrecision& prec = {});

// The interval of one hardware comparison tap at uv (bilinear of the four bits).
VisibilityEnvelope hwTapEnvelope(const ShadowMap& map, vec2 uv, float ref,
                                 const ConformancePrecision& prec);

}  // namespace pcf
