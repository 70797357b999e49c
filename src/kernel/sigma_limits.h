// sigma_limits.h: the smallest sigma of gaussian weights (the largest, MAX_SIGMA, is in
// methods.h beside the weights' names). Its own header so that the few files checking sigma
// (methods.cpp, the lesson reader) include it, not every user of methods.h.
#pragma once

namespace pcf {

// The smallest sigma whose weights stay normal floats: an even kernel's nearest taps sit 0.5
// texels off, exp(-0.25 / (2 sigma^2)) = exp(-50) at 0.05, far above FLT_MIN (exp(-87.3)), so
// the weights never all flush to 0 (0 / 0 was a NaN visibility; GPUs flush denormals).
constexpr float MIN_SIGMA = 0.05f;  // texels

}  // namespace pcf
