// trace_moments.h: the words of a moment method's trace (vsm, evsm2, evsm4, msm,
// msm-hausdorff): the moments read, the bound or the reconstruction, the result. Every number
// is the kernel's (Trace::moments, pcfMomentEstimate).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "kernel/trace.h"

namespace pcf {

// The steps after the texel position, in order, the last the Result.
std::vector<std::pair<TraceStepKind, std::string>> momentSteps(const Trace& trace);

}  // namespace pcf
