#include "kernel/trace_moments.h"

#include <sstream>

#include "kernel/settings.h"
#include "kernel/trace_explain.h"

namespace pcf {

namespace {

using MomentStep = std::pair<TraceStepKind, std::string>;

std::string n4(float v) { return formatNumber(v); }

// Small and large moments (EVSM's warps) in a form that keeps their digits.
std::string sci(float v) {
    std::ostringstream s;
    s.precision(4);
    s << v;
    return s.str();
}

bool isMsm(const Trace& tr) { return methodInfo(tr.params.method).reconstructs; }

std::string readText(const Trace& tr) {
    const PcfMomentEstimate& e = tr.moments;
    const MethodInfo& info = methodInfo(tr.params.method);
    int channels = texelKindInfo(tr.map.texels).channels;
    std::ostringstream s;
    s << "The moments pass blurred every texel's moments over " << tr.params.kernel << " x "
      << tr.params.kernel << " texels (" << weightsName(tr.params.weights)
      << "); one bilinear read at p = " << formatPair(tr.pos.p) << " gives m = ("
      << sci(e.moments.x) << ", " << sci(e.moments.y);
    if (channels == 4) s << ", " << sci(e.moments.z) << ", " << sci(e.moments.w);
    s << ")" << (isMsm(tr) ? " after the moment bias" : "") << " in "
      << texelKindName(tr.map.texels) << ".";
    if (info.warps > 0) {
        s << " The depths were warped to exp(" << n4(tr.params.evsmExponents.x) << " (2z - 1))";
        if (info.warps == 2) s << " and -exp(-" << n4(tr.params.evsmExponents.y) << " (2z - 1))";
        s << " first.";
    }
    s << " Mean " << sci(e.mean) << ", variance m2 - m1^2 = " << sci(e.variance) << ".";
    return s.str();
}

std::string boundText(const Trace& tr) {
    const PcfMomentEstimate& e = tr.moments;
    std::ostringstream s;
    s << "The receiver's t = " << sci(e.receiver)
      << ". Chebyshev: p_max = s^2 / (s^2 + (t - mean)^2)"
      << " = " << n4(e.bound) << (e.receiver <= e.mean ? " (t at or before the mean: 1)" : "")
      << ".";
    if (methodInfo(tr.params.method).warps == 2) {
        s << " The negative warp's bound: " << n4(e.negBound) << "; the smaller is taken.";
    }
    if (tr.params.lbr > 0.0f) {
        s << " Light-bleeding reduction linstep(" << n4(tr.params.lbr)
          << ", 1, p) = " << n4(e.visibility) << ".";
    }
    return s.str();
}

std::string reconstructText(const Trace& tr) {
    const PcfMomentEstimate& e = tr.moments;
    bool four = e.points.w == 1.0f;  // Hausdorff's four points end with the depth 1
    std::ostringstream s;
    s << "Moment bias " << sci(tr.params.momentBias)
      << " pulled the moments towards 0.5. The distribution with them that puts the least "
         "weight before the receiver's z = "
      << n4(e.points.x) << ": ";
    if (four) {
        s << "z_f " << n4(e.points.x) << " (weight " << n4(e.weights.x) << "), z_free "
          << n4(e.points.y) << " (" << n4(e.weights.y) << "), 0 (" << n4(e.weights.z) << "), 1 ("
          << n4(e.weights.w) << ").";
    } else {
        s << "z_f " << n4(e.points.x) << " (weight " << n4(e.weights.x) << "), " << n4(e.points.y)
          << " (" << n4(e.weights.y) << "), " << n4(e.points.z) << " (" << n4(e.weights.z) << ").";
    }
    s << " The weight before z_f is the shadow.";
    return s.str();
}

}  // namespace

std::vector<MomentStep> momentSteps(const Trace& tr) {
    std::vector<MomentStep> out;
    out.emplace_back(TraceStepKind::MomentsRead, readText(tr));
    if (isMsm(tr)) {
        out.emplace_back(TraceStepKind::MomentReconstruct, reconstructText(tr));
    } else {
        out.emplace_back(TraceStepKind::MomentBound, boundText(tr));
    }
    std::string result = "visibility = " + n4(tr.visibility) + ".";
    // PCF of the very depths the moments average (kernel/moment_footprint.h), when known.
    if (tr.depths.present) {
        result += " " + std::string(methodInfo(tr.depths.pcfMethod).name) + " of the same " +
                  std::to_string(tr.depths.texels.size()) +
                  " depth texels at the same ref: " + n4(tr.depths.pcfVisibility) + ".";
    }
    out.emplace_back(TraceStepKind::Result, result);
    return out;
}

}  // namespace pcf
