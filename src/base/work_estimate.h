// work_estimate.h: what a long job will take, said before it starts. A command that renders many
// frames or large ones (animate, bench, stability, export) estimates its time and memory from its
// frame size, its frame count and its sweep, prints the estimate when the job is long or large,
// and refuses it when the memory will not fit the machine, unless forced (-f/--force).
#pragma once

#include <cstdint>
#include <string>

namespace pcf {

// The work, in the units its cost is measured in: frames rendered (composed, read back and
// written) and ground-truth pixels, each at a frame size.
struct WorkEstimate {
    std::string what;           // "3600 frames of 8192x8192", for the messages
    double frameNs = 0.0;       // all the frames: pixels x frames x RENDER_NS_PER_PIXEL_FRAME
    double truthNs = 0.0;       // all the truths: pixels x truths x TRUTH_NS_PER_PIXEL
    double fixedSeconds = 0.0;  // start-up, shader compiles: what no size changes
    std::uint64_t bytes = 0;    // the peak memory
};

// What one pixel of a rendered frame costs, in ns of wall time on 2 cores of llvmpipe (the
// machine the constants were measured on: `animate` at 1280x720 composes, reads back and encodes
// 10 frames a second, 108 ns a pixel; a bench run's frames 40 ns). Scaled by the core count.
constexpr double RENDER_NS_PER_PIXEL_FRAME = 110.0;
// A hard ground truth, per pixel (2 x 2 first-pass samples, edges refined): 2.2 us a pixel at
// 640x360 on 2 cores. An area-light truth costs more; the estimate is a floor for it.
constexpr double TRUTH_NS_PER_PIXEL = 2200.0;
// The cores the constants were measured with.
constexpr int ESTIMATE_MEASURED_CORES = 2;

// Seconds of wall time the work will take on this machine: the constants scaled by its cores.
double estimatedSeconds(const WorkEstimate& work);
// "7.2 h", "25 min", "40 s".
std::string durationText(double seconds);

// Says the estimate on stderr ("animate: 3600 frames of 8192x8192: about 7.2 h and 12.9 GiB of
// memory (an estimate; Ctrl-C stops it and leaves nothing)") when the work takes over a minute or
// a GiB, and throws InputError(what) naming the memory it needs and what is available when that
// exceeds availableMemoryBytes() (base/memory_budget.h), unless `force`: then it says so and
// goes on.
void announceWork(const std::string& command, const WorkEstimate& work, bool force);

}  // namespace pcf
