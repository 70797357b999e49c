#include "kernel/moment_footprint.h"

#include <stdexcept>

#include "kernel/methods.h"
#include "kernel/trace.h"

namespace pcf {

int sameFootprintPcfMethod() { return PCF_NAIVE; }

void addMomentFootprint(Trace& tr, const ShadowMap& depthMap) {
    if (!readsMoments(tr.params.method)) return;
    if (depthMap.size() != tr.map.size || depthMap.spec().texel().channels != 1) {
        throw std::invalid_argument("addMomentFootprint: not the depth map of the moments map");
    }
    PcfParams prm = tr.params;
    prm.method = sameFootprintPcfMethod();
    Trace pcfTrace = traceLookup(depthMap, tr.uv, tr.z, tr.ref, prm, tr.bias, tr.dzduv, tr.layer);
    MomentFootprint out;
    out.present = true;
    out.pcfMethod = prm.method;
    out.pcfVisibility = pcfTrace.visibility;
    const WeightGrid& g = pcfTrace.weights;
    for (int j = 0; j < g.size.y; ++j) {
        for (int i = 0; i < g.size.x; ++i) {
            ivec2 texel = g.origin + ivec2(i, j);
            float w = g.at(texel);
            // Every texel of the grid is read (the lookups tile it); its depth is its first read's.
            for (const TapRecord& tap : pcfTrace.taps) {
                if (tap.texel == texel) {
                    out.texels.push_back({texel, tap.depth, w});
                    break;
                }
            }
        }
    }
    tr.depths = std::move(out);
}

}  // namespace pcf
