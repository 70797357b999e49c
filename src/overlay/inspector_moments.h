// inspector_moments.h: what the inspector shows of a moment method's lookup (vsm, evsm2, evsm4,
// msm, msm-hausdorff) instead of cells of comparison bits: the depths its moments average as a
// histogram over depth, the receiver's t on it, the bound as a curve over depth (each warp's for
// evsm4, before and after the light-bleeding linstep), msm's reconstructed points over the
// histogram, and PCF of the same footprint. Every value is the trace's or the shared kernel's
// (pcfVarianceEstimate run at each depth of the curve); nothing here derives a moment again.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace pcf {

struct Trace;

struct MomentFigure {
    // A bin of the depth axis: the footprint's texels whose depth falls in [lo, hi) (the last
    // bin holds hi too), how many, and their summed weight in the moments.
    struct Bin {
        float lo = 0.0f, hi = 0.0f;
        int texels = 0;
        float weight = 0.0f;
    };
    // The bound as a function of the receiver's depth t, the lookup's moments held: (t, value)
    // with t rising over the axis, the receiver's own t among them.
    struct Curve {
        int warp = 0;           // 0: vsm's depth; 1: evsm's positive warp; -1: its negative one
        bool afterLbr = false;  // linstep(lbr, 1, p) of the bound (of the smaller one, evsm4)
        float exponent = 0.0f;  // the warp's exponent as used (after the format's clamp)
        std::vector<glm::vec2> points;
        float atReceiver = 1.0f;  // its value at the receiver's t
        bool taken = true;        // evsm4: this warp's bound is the smaller at t
    };
    float axisLo = 0.0f, axisHi = 1.0f;  // the depth axis, in the map's [0, 1] depth
    float receiver = 0.0f;      // t: the lookup's ref, clamped to [0, 1] as the kernel does
    bool hasFootprint = false;  // the depths under the moments are known
    std::vector<Bin> bins;
    std::vector<Curve> curves;
    std::vector<glm::vec2> points;  // msm: the reconstructed depths and their weights
    float pcfVisibility = 1.0f;     // PCF of the same footprint at the same ref
};

// The figure of a moment method's trace with `bins` bins over its depth axis and `samples`
// depths along its curves (the receiver's t added).
MomentFigure momentFigure(const Trace& tr, int bins, int samples = 96);

}  // namespace pcf
