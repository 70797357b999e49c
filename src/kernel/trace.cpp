// trace.cpp: recording one lookup (trace.h). The words are in trace_explain.cpp, the JSON and
// text in trace_json.cpp.
#include "kernel/trace.h"

#include <stdexcept>

namespace pcf {

float WeightGrid::at(ivec2 texel) const {
    ivec2 local = texel - origin;
    if (local.x < 0 || local.y < 0 || local.x >= size.x || local.y >= size.y) return 0.0f;
    return values[static_cast<size_t>(local.y) * size.x + local.x];
}

namespace {

WeightGrid mergeWeights(const std::vector<TapRecord>& taps) {
    WeightGrid grid;
    if (taps.empty()) return grid;
    ivec2 lo = taps.front().texel;
    ivec2 hi = lo;
    for (const TapRecord& t : taps) {
        lo = glm::min(lo, t.texel);
        hi = glm::max(hi, t.texel);
    }
    grid.origin = lo;
    grid.size = hi - lo + ivec2(1);
    grid.values.assign(static_cast<size_t>(grid.size.x) * grid.size.y, 0.0f);
    for (const TapRecord& t : taps) {
        ivec2 local = t.texel - lo;
        grid.values[static_cast<size_t>(local.y) * grid.size.x + local.x] += t.weight;
    }
    return grid;
}

FetchCounts countFetches(const Trace& tr) {
    FetchCounts c{static_cast<int>(tr.taps.size()), 0, 0};
    for (const FetchRecord& f : tr.fetches) {
        if (f.kind == PCF_FETCH_GATHER) ++c.gathers;
        if (f.kind == PCF_FETCH_HW) ++c.hwTaps;
    }
    return c;
}

}  // namespace

float weightedTapSum(const Trace& trace) {
    float sum = 0.0f;
    for (const TapRecord& t : trace.taps) sum += t.weight * t.lit;
    return sum;
}

int tapsChangedByPlane(const Trace& tr) {
    if (tr.bias.bias != BiasMode::ReceiverPlane) return 0;
    int changed = 0;
    for (const TapRecord& t : tr.taps) changed += pcfCompare(t.depth, tr.ref) != t.lit ? 1 : 0;
    return changed;
}

namespace {

// pcss records its search taps with weight 0 (pcf_disk.h pcfPcssEstimate): they choose the
// filter's width, the filter's taps make the visibility. When no search tap blocks there is no
// filter and the visibility, 1, is the mean of the 16 search bits (all 1): the search taps then
// weigh 1/16 each, so visibility = sum(weight * lit) holds for every lookup (docs/user-guide.md,
// "trace").
void weighPcssSearch(Trace& tr) {
    if (tr.taps.size() != static_cast<size_t>(PCF_PCSS_TAPS)) return;
    float w = 1.0f / static_cast<float>(PCF_PCSS_TAPS);
    for (TapRecord& t : tr.taps) t.weight = w;
    for (FetchRecord& f : tr.fetches) f.weight = w;
}

}  // namespace

std::optional<TraceCascade> cascadeOfTrace(const Trace& trace) {
    if (trace.map.layers.size() < 2) return std::nullopt;
    const PcfMapLayer& layer = trace.map.layers[static_cast<size_t>(trace.layer)];
    return TraceCascade{trace.layer,       static_cast<int>(trace.map.layers.size()),
                        layer.viewDepth.x, layer.viewDepth.y,
                        layer.texelWs,     trace.cascadeTexelsPerPixelMax};
}

Trace traceLookup(const ShadowMap& map, vec2 uv, float z, float ref, const PcfParams& prm) {
    BiasSettings b;
    b.bias = ref == z ? BiasMode::None : BiasMode::Constant;
    b.constantBias = z - ref;
    return traceLookup(map, uv, z, ref, prm, b);
}

Trace traceLookup(const ShadowMap& map, vec2 uv, float z, float ref, const PcfParams& prm,
                  const BiasSettings& bias, vec2 dzduv, int layer) {
    if (layer < 0 || layer >= map.layers()) throw std::invalid_argument("no such map layer");
    Trace tr;
    tr.params = prm;
    tr.map = map.spec();
    tr.layer = layer;
    tr.uv = uv;
    tr.z = z;
    tr.ref = ref;
    tr.bias = bias;
    tr.dzduv = dzduv;
    tr.pos = pcfTexelPos(uv, map.size());
    tr.lookup = pcfLookupRef(PcfRef(ref, uv, bias.kernelBias(dzduv)));
    Recording rec;
    PcfRef at(ref, uv, bias.kernelBias(dzduv));
    tr.visibility = pcfFilterRef(recordingMap(map, prm, rec, layer), uv, at, prm);
    tr.taps = std::move(rec.taps);
    tr.fetches = std::move(rec.fetches);
    if (methodInfo(prm.method).searchesBlockers) weighPcssSearch(tr);
    tr.weights = mergeWeights(tr.taps);
    tr.counts = countFetches(tr);
    tr.usesTextureUnit = tr.counts.gathers > 0 || tr.counts.hwTaps > 0;
    tr.fracHw8 = glm::fract(pcfQuantiseTexelPos(tr.pos.p));
    PcfParams exact = prm;
    exact.precision = PCF_PRECISION_EXACT;
    PcfParams hw8 = prm;
    hw8.precision = PCF_PRECISION_HW8;
    tr.visibilityExact = pcfFilterRef(plainMap(map, exact, layer), uv, at, exact);
    tr.visibilityHw8 = pcfFilterRef(plainMap(map, hw8, layer), uv, at, hw8);

    // The footprint the method floors: a gather kernel's (N+1)^2 block, tent's base.
    switch (methodOf(prm.method)) {
        case Method::Gather:
            tr.footprint = pcfKernelFootprint(uv, map.size(), prm.kernel);
            break;
        case Method::Tent:
            tr.footprint = pcfTentBase(uv, map.size());
            break;
        case Method::Pcss:
            tr.pcss = pcfPcssEstimate(plainMap(map, prm, layer), uv, tr.lookup, prm.penumbraScale,
                                      prm.depthNear, prm.depthFar, prm.rotation);
            break;
        case Method::Vsm:
        case Method::Evsm2:
        case Method::Evsm4:
        case Method::Msm:
        case Method::MsmHausdorff:
            tr.moments = pcfMomentEstimate(plainMap(map, prm, layer), uv, ref, prm);
            break;
        case Method::Nearest:
        case Method::Box2x2:
        case Method::Bilinear2x2:
        case Method::Hw2x2:
        case Method::Naive:
        case Method::Hw:
        case Method::Poisson:
            break;
    }
    return tr;
}

}  // namespace pcf
