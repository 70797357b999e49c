#include "measure/conformance.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace pcf {

namespace {

int referenceBitsFor(const ShadowMap& map, const ConformancePrecision& prec) {
    if (prec.referenceBits > 0) return prec.referenceBits;
    return map.isFixedPoint() ? map.fixedPointBits() : 22;
}

// The comparison bit of one texel, as an interval: {0,0}, {1,1}, or {0,1} when D_ref is within
// the reference tolerance of D_t (GL_LEQUAL: lit when ref <= depth).
struct BitRange {
    float lo;
    float hi;
};

BitRange compareRange(const ShadowMap& map, ivec2 texel, float ref, float eps) {
    ivec2 t = pcfClampTexel(texel, map.size());
    float depth = map.depth(t.x, t.y);
    float r = map.isFixedPoint() ? std::clamp(ref, 0.0f, 1.0f) : ref;
    if (std::fabs(r - depth) <= eps) return {0.0f, 1.0f};
    float lit = pcfCompare(depth, r);
    return {lit, lit};
}

// The soft comparison of one texel (bias soft): shader arithmetic, one value.
BitRange softRange(const ShadowMap& map, ivec2 texel, float ref, const PcfBias& bias) {
    ivec2 t = pcfClampTexel(texel, map.size());
    float r = map.isFixedPoint() ? std::clamp(ref, 0.0f, 1.0f) : ref;
    float lit = pcfCompareBiased(map.depth(t.x, t.y), r, bias);
    return {lit, lit};
}

float bilinear(float b00, float b10, float b01, float b11, vec2 f) {
    return glm::mix(glm::mix(b00, b10, f.x), glm::mix(b01, b11, f.x), f.y);
}

// The x (or y) values at which the piecewise-bilinear tap function can take its extremes inside
// [c - e, c + e]: the two ends and every integer (cell edge) between them.
std::vector<float> candidates(float c, float e) {
    std::vector<float> xs = {c - e, c + e};
    for (float k = std::ceil(c - e); k < c + e; k += 1.0f) xs.push_back(k);
    return xs;
}

}  // namespace

VisibilityEnvelope hwTapEnvelope(const ShadowMap& map, vec2 uv, float ref,
                                 const ConformancePrecision& prec) {
    float eps = std::ldexp(1.0f, -referenceBitsFor(map, prec));
    float e = std::ldexp(1.0f, -prec.subTexelBits);
    vec2 p = pcfTexelPos(uv, map.size()).p;
    // The tap is V(p) = sum of bit * tent weights: continuous and bilinear inside each texel
    // cell, so over the box p +- e its extremes lie at the box corners or where the box crosses
    // a cell edge. Uncertain bits take 0 for the low end and 1 for the high end (V grows with
    // every bit).
    VisibilityEnvelope env{1.0f, 0.0f};
    for (float x : candidates(p.x, e)) {
        for (float y : candidates(p.y, e)) {
            vec2 b = glm::floor(vec2(x, y));
            ivec2 base = ivec2(b);
            vec2 f = vec2(x, y) - b;
            BitRange r00 = compareRange(map, base, ref, eps);
            BitRange r10 = compareRange(map, base + ivec2(1, 0), ref, eps);
            BitRange r01 = compareRange(map, base + ivec2(0, 1), ref, eps);
            BitRange r11 = compareRange(map, base + ivec2(1, 1), ref, eps);
            env.lo = std::min(env.lo, bilinear(r00.lo, r10.lo, r01.lo, r11.lo, f));
            env.hi = std::max(env.hi, bilinear(r00.hi, r10.hi, r01.hi, r11.hi, f));
        }
    }
    // Rounded weights move a lerp between different bits by up to one weight step; four equal
    // bits stay that bit (the weights f and 1 - f still sum to 1).
    bool uniform = env.lo == env.hi && (env.lo == 0.0f || env.lo == 1.0f);
    float w = uniform ? 0.0f : std::ldexp(1.0f, -prec.weightBits);
    return {std::max(0.0f, env.lo - w), std::min(1.0f, env.hi + w)};
}

// pcss (Fernando, "Percentage-Closer Soft Shadows", NVIDIA, 2005): the blocker search's taps
// (recorded with weight 0) decide whether the filter runs and how wide it is, a jump rather
// than a weight. A search bit that may go either way on some GPU leaves no claim ([0, 1]);
// with no blocker certain the result is exactly 1 (the early out). Otherwise the filter's taps
// are judged like any other reads.
std::optional<VisibilityEnvelope> pcssSearchEnvelope(const ShadowMap& map, const Recording& rec,
                                                     float eps) {
    int blockers = 0;
    for (const TapRecord& t : rec.taps) {
        if (t.weight != 0.0f) continue;
        BitRange r = compareRange(map, t.texel, t.ref, eps);
        if (r.lo != r.hi) return VisibilityEnvelope{0.0f, 1.0f};
        blockers += r.lo == 0.0f;
    }
    if (blockers == 0) return VisibilityEnvelope{1.0f, 1.0f};
    return std::nullopt;
}

VisibilityEnvelope visibilityEnvelope(const ShadowMap& map, vec2 uv, float ref,
                                      const PcfParams& prm, const ConformancePrecision& prec) {
    return visibilityEnvelope(
        map, uv, ref, prm, PcfBias(PCF_BIAS_CONSTANT, vec2(0.0f), 0.0f, PCF_DZDUV_UNCLAMPED), prec);
}

namespace {

// The sums of weight * bit over one fetch's taps, lowest and highest (visibilityEnvelope).
struct WeightedRange {
    double lo = 0.0;
    double hi = 0.0;
};

// One comparison gather: four bits with the method's weights, in GL's order x = (0,1),
// y = (1,1), z = (1,0), w = (0,0) from the block's base; the unit may pick its base from any
// position within p +- e (a corner-placed gather is at p = k + 0.5: never moves).
WeightedRange gatherRange(const ShadowMap& map, const FetchRecord& fr,
                          const std::vector<TapRecord>& taps, const PcfBias& bias, float e,
                          float eps) {
    const ivec2 order[4] = {ivec2(0, 1), ivec2(1, 1), ivec2(1, 0), ivec2(0, 0)};
    float tapRef = taps.front().ref;
    vec2 p = pcfTexelPos(fr.uv, map.size()).p;
    double glo = 1e30;
    double ghi = -1e30;
    for (float x : candidates(p.x, e)) {
        for (float y : candidates(p.y, e)) {
            ivec2 base = ivec2(glm::floor(vec2(x, y)));
            double sl = 0.0;
            double sh = 0.0;
            for (size_t c = 0; c < 4 && c < taps.size(); ++c) {
                // Soft bias gathers raw depths and compares in the shader ("PCF Shadow Acne 2"):
                // a ramp, not a bit, whichever block the unit picks.
                BitRange r = bias.mode == PCF_BIAS_SOFT
                                 ? softRange(map, base + order[c], tapRef, bias)
                                 : compareRange(map, base + order[c], tapRef, eps);
                sl += taps[c].weight * r.lo;
                sh += taps[c].weight * r.hi;
            }
            glo = std::min(glo, sl);
            ghi = std::max(ghi, sh);
        }
    }
    return {glo, ghi};
}

// Texel fetches and shader arithmetic: exact but for near-equal comparisons. Soft and
// interpolated comparisons are shader arithmetic on fetched texels: their recorded values are
// what any GPU computes, but for float rounding (a continuous ramp, or one comparison against a
// lerped depth that the reference tolerance covers). The interpolated mode compares once,
// against the lerp of the fetch's depths: a lerped depth within the tolerance of ref may go
// either way. Adds each tap's weighted bit to `sum`, one at a time.
void addTexelFetchRange(const ShadowMap& map, const std::vector<TapRecord>& taps,
                        const PcfBias& bias, float eps, WeightedRange& sum) {
    bool shaderCompare = bias.mode == PCF_BIAS_SOFT || bias.mode == PCF_BIAS_INTERPOLATED;
    bool uncertainLerp = false;
    if (bias.mode == PCF_BIAS_INTERPOLATED) {
        double wsum = 0.0;
        double dsum = 0.0;
        for (const TapRecord& t : taps) {
            wsum += t.weight;
            dsum += static_cast<double>(t.weight) * t.depth;
        }
        uncertainLerp = wsum > 0.0 && std::fabs(dsum / wsum - taps.front().ref) <= 2 * eps;
    }
    for (const TapRecord& t : taps) {
        BitRange r = uncertainLerp   ? BitRange{0.0f, 1.0f}
                     : shaderCompare ? BitRange{t.lit, t.lit}
                                     : compareRange(map, t.texel, t.ref, eps);
        sum.lo += t.weight * r.lo;
        sum.hi += t.weight * r.hi;
    }
}

}  // namespace

VisibilityEnvelope visibilityEnvelope(const ShadowMap& map, vec2 uv, float ref,
                                      const PcfParams& prm, const PcfBias& bias,
                                      const ConformancePrecision& prec) {
    float eps = std::ldexp(1.0f, -referenceBitsFor(map, prec));
    float e = std::ldexp(1.0f, -prec.subTexelBits);
    PcfParams exact = prm;
    exact.precision = PCF_PRECISION_EXACT;
    // A moment method makes no comparison a texture unit could round: its visibility is float
    // arithmetic on the moments read, which the GPU's exp, division and sqrt do to within
    // MOMENT_TOLERANCE of the CPU's.
    if (readsMoments(prm.method)) {
        float v = filterVisibility(map, uv, ref, exact, bias);
        return VisibilityEnvelope{std::max(v - MOMENT_TOLERANCE, 0.0f),
                                  std::min(v + MOMENT_TOLERANCE, 1.0f)};
    }
    Recording rec;
    filterRecorded(map, uv, ref, exact, bias, rec);
    if (methodInfo(prm.method).searchesBlockers) {
        if (std::optional<VisibilityEnvelope> env = pcssSearchEnvelope(map, rec, eps)) return *env;
    }
    WeightedRange sum;
    for (size_t f = 0; f < rec.fetches.size(); ++f) {
        const FetchRecord& fr = rec.fetches[f];
        std::vector<TapRecord> taps;
        for (const TapRecord& t : rec.taps) {
            if (t.fetch == static_cast<int>(f)) taps.push_back(t);
        }
        if (taps.empty()) continue;
        if (fr.kind == PCF_FETCH_HW) {
            // The method weighs the tap's result by fr.weight (tent: w_i w_j / D).
            VisibilityEnvelope t = hwTapEnvelope(map, fr.uv, taps.front().ref, prec);
            double a = fr.weight * t.lo;
            double b = fr.weight * t.hi;
            sum.lo += std::min(a, b);
            sum.hi += std::max(a, b);
        } else if (fr.kind == PCF_FETCH_GATHER) {
            WeightedRange g = gatherRange(map, fr, taps, bias, e, eps);
            sum.lo += g.lo;
            sum.hi += g.hi;
        } else {
            addTexelFetchRange(map, taps, bias, eps, sum);
        }
    }
    VisibilityEnvelope env;
    env.lo = static_cast<float>(std::clamp(sum.lo, 0.0, 1.0));
    env.hi = static_cast<float>(std::clamp(sum.hi, 0.0, 1.0));
    return env;
}

}  // namespace pcf
