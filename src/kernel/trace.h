// trace.h: everything one PCF lookup did, in order, for the inspector, `pcfscope trace` and the
// lessons. Built by running the shared kernel over a recording map (see pcf.h): the numbers
// shown are the numbers computed, never a second derivation of them.
//
// Three files, one job each: this one records (traceLookup), trace_explain.h words the record
// as steps in English, trace_json.h writes it as JSON or as the text `pcfscope trace` prints.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/moment_footprint.h"
#include "kernel/pcf.h"
#include "kernel/shadow_map.h"

namespace pcf {

// Merged weight per distinct texel over the bounding box of the taps, row-major from origin
// (values[(j - origin.y) * size.x + (i - origin.x)]).
struct WeightGrid {
    ivec2 origin{0, 0};
    ivec2 size{0, 0};
    std::vector<float> values;
    float at(ivec2 texel) const;
};

// What a step explains. Consumers (the inspector, lessons, tests) switch on the kind, never on
// the English title, which may be reworded. trace_explain.h names each kind (title, JSON id).
enum class TraceStepKind {
    Project,              // the pixel's uv, z and what the bias did to ref
    PerTapRef,            // receiver-plane bias: every tap's own ref
    TexelPosition,        // p = uv * size - 0.5, base and frac
    ReadTexel,            // nearest: the one texel
    CompareTexels,        // the 2x2 texels, each compared with ref
    HardwareTap,          // hw2x2: the one hardware comparison tap
    AverageBits,          // box2x2: the bits averaged
    Lerp,                 // bilinear: the bits lerped by the sub-texel fraction
    KernelLookups,        // pcf-naive: the N x N bilinear lookups
    KernelHardwareTaps,   // pcf-hw: the N x N hardware taps
    CountReads,           // pcf-naive / pcf-hw: reads against distinct texels
    WeightTable,          // pcf-gather: the footprint's weight table
    Gather,               // pcf-gather: the comparison gathers
    TentTaps,             // tent: where its taps sit and what they weigh
    TentHardwareTaps,     // tent: the taps taken
    DiskPoints,           // poisson, pcss: the disk's points
    BlockerSearch,        // pcss: the search disk's texels, the blockers and their mean depth
    PenumbraWidth,        // pcss: the penumbra's width from the blocker's depth, the filter radius
    InterpolatedCompare,  // interpolated depth: one comparison against the lerped depth
    MomentsRead,          // the moment methods: the filtered moments read, mean and variance
    MomentBound,          // vsm, evsm: Chebyshev's bound (each warp), the light-bleeding cut
    MomentReconstruct,    // msm: the depths and weights of the reconstructed distribution
    Precision,            // hw8: the texture unit's 1/256 texel steps
    Result,               // the visibility: the last step (box2x2 ends with AverageBits)
};

struct TraceStep {
    TraceStepKind kind;
    std::string title;  // stepTitle(kind), for readers; never matched on
    std::string text;
};

// A cascaded map's blend band at the lookup (shared/pcf_shading.h pcfCascadeBlendWeight): the
// next cascade blended in (-1: none, outside the band), its weight, the next cascade's own
// visibility of the point and the blended result pcfCascadeBlend gives. Filled by whoever traces
// a cascaded frame's point (scene/cascade_fit.h cascadeVisibilityAt finds them); the taps are
// the layer read's.
struct TraceCascadeBlend {
    int next = -1;
    float weight = 0.0f;
    float nextVisibility = 1.0f;
    float blended = 1.0f;
};

struct Trace {
    PcfParams params{};
    // The map looked up, as a value (kernel/shadow_map.h): its size, texel kind and layers with
    // their fits; and the layer this lookup read.
    MapSpec map;
    int layer = 0;
    // A cascaded map (more than one layer): the cascade read is `layer`, its view depths and
    // texel size are map.layers[layer]'s (cascadeOfTrace). Its texel density as measured on the
    // frame the lookup was traced on (measure/cascade_density.h: the most map texels per screen
    // pixel over that cascade's receivers); negative when no frame measured it (`trace --map`).
    float cascadeTexelsPerPixelMax = -1.0f;
    // Where cascades blend (cascade_blend, a band at each cascade's end), the second lookup, in
    // the next cascade, and the blend weight beside the taps of the layer read.
    TraceCascadeBlend cascadeBlend{};
    vec2 uv{0.0f};
    float z = 0.0f;    // receiver depth in the light's [0,1] depth, before bias
    float ref = 0.0f;  // the depth compared with the map, after bias
    // The bias mode and its parameters. Each tap's own ref (TapRecord::ref) differs from `ref`
    // under receiver-plane bias.
    BiasSettings bias{};
    vec2 dzduv{0.0f};  // receiver-plane: the receiver's plane given, light depth per uv unit
    // What every tap's comparison starts from, as the kernel derived it from ref, uv, the bias
    // and dzduv (pcfLookupRef, the first thing pcfFilterRef does): under receiver-plane bias its
    // bias.dzduv is the slope the taps used (capped). The words and the JSON print these values,
    // never a second derivation of them.
    PcfRef lookup{0.0f, vec2(0.0f), PcfBias(PCF_BIAS_NONE, vec2(0.0f), 0.0f, 0.0f)};
    PcfTexelPos pos{};                 // GL bilinear position of uv: p, base, frac
    std::vector<TapRecord> taps;       // one per texel read, in read order, duplicates kept
    std::vector<FetchRecord> fetches;  // one per fetch instruction, in issue order
    WeightGrid weights;
    FetchCounts counts{};
    float visibility = 1.0f;  // what the kernel returned
    // The footprint the method floors, as the kernel computed it (never derived again here):
    // pcf-gather: pcfKernelFootprint (origin, g); tent: pcfTentBase (b, (s, t)). Zero otherwise.
    PcfFootprint footprint{ivec2(0), vec2(0.0f)};
    // pcss: what its blocker search and penumbra estimate found, as the kernel computed them
    // (pcfPcssEstimate). Its first PCF_PCSS_TAPS taps are the search's (weight 0; 1/16 each
    // when none blocks and they alone give the visibility, 1), the rest the filter's. Zero
    // otherwise.
    PcfPcssEstimate pcss{0.0f, 0, 0.0f, 0.0f, 0.0f};
    // The moment methods: what the filtered moments at the lookup say, as the kernel computed
    // it (pcfMomentEstimate): the moments, mean, variance, the bounds, msm's points and weights.
    // The exponents used are params.evsmExponents. Zero otherwise.
    PcfMomentEstimate moments{vec4(0.0f), 0.0f,       0.0f,       0.0f, 0.0f,
                              0.0f,       vec4(0.0f), vec4(0.0f), 0.0f};
    // The moment methods, when the depth map under the moments is known (addMomentFootprint):
    // the depth texels the lookup's moments average, with their weights, and PCF of them.
    MomentFootprint depths;
    // The texture unit's precision (issue 10): the lookup's sub-texel fraction as a float and
    // rounded to 1/256 texel (hw8), and the visibility the kernel gives under each model.
    bool usesTextureUnit = false;  // the method issues hardware taps or gathers
    vec2 fracHw8{0.0f};
    float visibilityExact = 1.0f;
    float visibilityHw8 = 1.0f;
};

// Runs the kernel at (uv, ref) with recording on (trace_explain.h: explainTrace puts it in words).
// z is the receiver's depth before bias (shown to the student; the kernel only sees ref).
// Without a mode: bias "none" when ref == z, else "constant" with b = z - ref.
Trace traceLookup(const ShadowMap& map, vec2 uv, float z, float ref, const PcfParams& prm);
// Under a bias mode: ref is the lookup's ref with the per-lookup bias applied (for normal offset,
// uv and ref are the moved point's and z the receiver's own depth); `bias` and, under
// receiver-plane bias, the receiver's plane dzduv (light depth per uv unit) say how each tap's
// comparison varies from it. `layer`: the map's layer looked up (a cascade; Trace::layer);
// std::invalid_argument when the map has no such layer.
Trace traceLookup(const ShadowMap& map, vec2 uv, float z, float ref, const PcfParams& prm,
                  const BiasSettings& bias, vec2 dzduv = vec2(0.0f), int layer = 0);

// The cascade a lookup read, from its trace: its index and count, the view depths it covers
// (scene units along the camera's view direction) and one texel's side in world units, and the
// texel density measured on the frame (negative: not measured). nullopt for a map of one layer.
struct TraceCascade {
    int index = 0;
    int count = 0;
    float nearZ = 0.0f;
    float farZ = 0.0f;
    float texelWs = 0.0f;
    float texelsPerPixelMax = -1.0f;
};
std::optional<TraceCascade> cascadeOfTrace(const Trace& trace);

// How many taps a single ref for every tap would have judged otherwise (receiver-plane bias:
// the taps the plane rescued from acne, or darkened). 0 for the other modes.
int tapsChangedByPlane(const Trace& trace);

// Sum of weight * lit over the taps: equals visibility up to float rounding.
float weightedTapSum(const Trace& trace);

}  // namespace pcf
