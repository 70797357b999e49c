// inspector_moments.cpp: the numbers of a moment method's figure (inspector_moments.h), taken
// from the trace and the shared kernel; inspector_moment_page.cpp lays them out.
#include "overlay/inspector_moments.h"

#include <algorithm>
#include <cmath>

#include "kernel/methods.h"
#include "kernel/trace.h"

namespace pcf {

namespace {

// The depth axis: every depth the figure marks (the footprint's, the receiver's, vsm's and msm's
// mean, msm's points), a tenth of their span added each side, kept in [0, 1].
void fitAxis(MomentFigure& f, const Trace& tr) {
    const MethodInfo& info = methodInfo(tr.params.method);
    std::vector<float> marks{f.receiver};
    for (const FootprintTexel& t : tr.depths.texels) marks.push_back(t.depth);
    if (info.warps == 0) marks.push_back(tr.moments.mean);  // evsm's mean is of a warp
    for (glm::vec2 p : f.points) marks.push_back(p.x);
    std::erase_if(marks, [](float v) { return !std::isfinite(v); });
    auto [lo, hi] = std::minmax_element(marks.begin(), marks.end());
    float span = std::max(*hi - *lo, 0.02f);
    f.axisLo = std::clamp(*lo - 0.1f * span, 0.0f, 1.0f);
    f.axisHi = std::clamp(*hi + 0.1f * span, 0.0f, 1.0f);
    if (f.axisHi - f.axisLo < 0.01f) f.axisHi = std::min(1.0f, f.axisLo + 0.02f);
}

void fillBins(MomentFigure& f, const Trace& tr, int count) {
    count = std::max(1, count);
    float width = (f.axisHi - f.axisLo) / static_cast<float>(count);
    for (int k = 0; k < count; ++k) {
        float lo = f.axisLo + width * static_cast<float>(k);
        f.bins.push_back({lo, k + 1 == count ? f.axisHi : lo + width, 0, 0.0f});
    }
    for (const FootprintTexel& t : tr.depths.texels) {
        int k = static_cast<int>(std::floor((t.depth - f.axisLo) / width));
        MomentFigure::Bin& b = f.bins[static_cast<size_t>(std::clamp(k, 0, count - 1))];
        ++b.texels;
        b.weight += t.weight;
    }
}

// The depths the curves are drawn at: `samples` over the axis and the receiver's own t.
std::vector<float> curveDepths(const MomentFigure& f, int samples) {
    std::vector<float> ts;
    for (int k = 0; k < samples; ++k) {
        float a = static_cast<float>(k) / static_cast<float>(std::max(1, samples - 1));
        ts.push_back(f.axisLo + a * (f.axisHi - f.axisLo));
    }
    ts.push_back(f.receiver);
    std::sort(ts.begin(), ts.end());
    return ts;
}

// vsm, evsm2, evsm4: the bound at every depth of the axis, the lookup's moments held: the
// kernel's own estimate (pcfVarianceEstimate: Chebyshev's inequality on each warp, Donnelly and
// Lauritzen, "Variance Shadow Maps", 2006; Lauritzen and McCool, "Layered Variance Shadow Maps",
// 2008), run at each t; and, with light-bleeding reduction, the visibility it leaves.
void fillCurves(MomentFigure& f, const Trace& tr, int samples) {
    const MethodInfo& info = methodInfo(tr.params.method);
    vec2 c = tr.params.evsmExponents;
    MomentFigure::Curve pos;
    pos.warp = info.warps > 0 ? 1 : 0;
    pos.exponent = info.warps > 0 ? c.x : 0.0f;
    MomentFigure::Curve neg;
    neg.warp = -1;
    neg.exponent = c.y;
    MomentFigure::Curve lbr;
    lbr.afterLbr = true;
    for (float t : curveDepths(f, samples)) {
        PcfMomentEstimate e = pcfVarianceEstimate(tr.moments.moments, t, tr.params);
        pos.points.push_back({t, e.bound});
        neg.points.push_back({t, e.negBound});
        lbr.points.push_back({t, e.visibility});
        if (t == f.receiver) {
            pos.atReceiver = e.bound;
            neg.atReceiver = e.negBound;
            lbr.atReceiver = e.visibility;
        }
    }
    bool two = info.warps == 2;
    pos.taken = !two || pos.atReceiver <= neg.atReceiver;
    neg.taken = !pos.taken;
    f.curves.push_back(std::move(pos));
    if (two) f.curves.push_back(std::move(neg));
    if (tr.params.lbr > 0.0f) f.curves.push_back(std::move(lbr));
}

}  // namespace

MomentFigure momentFigure(const Trace& tr, int bins, int samples) {
    MomentFigure f;
    const MethodInfo& info = methodInfo(tr.params.method);
    f.receiver = std::clamp(tr.ref, 0.0f, 1.0f);  // where the kernel takes the receiver
    f.hasFootprint = tr.depths.present;
    f.pcfVisibility = tr.depths.pcfVisibility;
    if (info.reconstructs) {
        // msm: the trace's points; Hausdorff's four end with the depth 1 (pcfHausdorffEstimate).
        int count = tr.moments.points.w == 1.0f ? 4 : 3;
        for (int k = 0; k < count; ++k) {
            f.points.push_back({tr.moments.points[k], tr.moments.weights[k]});
        }
    }
    fitAxis(f, tr);
    if (f.hasFootprint) fillBins(f, tr, bins);
    if (!info.reconstructs) fillCurves(f, tr, samples);
    return f;
}

}  // namespace pcf
