// gpu_timer.h: how long GL work takes, measured the way that is honest on the machine at hand
// (docs/measurement.md, "Speed against accuracy: bench").
//
// llvmpipe (and softpipe) run the work when it is flushed, not when it is submitted, so a
// GL_TIME_ELAPSED query there measures submission only (0.02 ms for a 3 ms pass). On those,
// each repetition is timed on the CPU around draw() + glFinish(); on real GPUs with
// GL_TIME_ELAPSED queries, which leave out the CPU and the pipeline bubbles.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace pcf {

struct TimingResult {
    double medianMs = 0.0;          // the median of samplesMs
    std::vector<double> samplesMs;  // one per repetition, in the order they ran
    // On software renderers, the CPU time the process spent on each repetition, all threads
    // (llvmpipe's rasteriser threads are the process's own): the work a pass costs, which other
    // processes on a busy machine do not inflate as they do the wall clock. Empty on real GPUs.
    std::vector<double> cpuSamplesMs;
    std::string timer;  // "glFinish+steady_clock" or "GL_TIME_ELAPSED"
};

inline constexpr std::string_view TIMER_WALL_CLOCK = "glFinish+steady_clock";
inline constexpr std::string_view TIMER_GPU_QUERY = "GL_TIME_ELAPSED";

// True for Mesa's CPU rasterisers, whose GL_RENDERER names "llvmpipe" or "softpipe".
bool isSoftwareRenderer(std::string_view renderer);

// Runs draw() once to warm up (shader compilation, first-touch allocations; skipped when warmUp
// is false, for callers that warmed up already and take one sample at a time), then `repeats`
// times measured, on the current context. draw() must not use GL_TIME_ELAPSED queries itself.
// Throws std::invalid_argument when repeats < 1.
TimingResult timeGpu(const std::function<void()>& draw, int repeats, bool warmUp = true);

// The median of `samples` (the mean of the middle two for an even count); 0 when empty.
double medianOf(std::vector<double> samples);

// The quartiles of `samples` by linear interpolation between order statistics (Hyndman and Fan
// 1996, "Sample quantiles in statistical packages", definition 7, R's and NumPy's default):
//   q(p) = x[floor(h)] + (h - floor(h)) (x[floor(h) + 1] - x[floor(h)]),  h = (n - 1) p
// over the sorted samples x[0..n-1]. All 0 when empty; q1 = q3 = the sample when n = 1.
struct Quartiles {
    double q1 = 0.0;
    double median = 0.0;
    double q3 = 0.0;
    double iqr() const { return q3 - q1; }
};
Quartiles quartilesOf(std::vector<double> samples);

}  // namespace pcf
