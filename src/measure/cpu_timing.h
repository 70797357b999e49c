// cpu_timing.h: how long the CPU kernel's batch path (filterVisibility, pcf.h) takes per pixel,
// on the very lookups a rendered frame made: the (u, v, ref) of its receiver pixels.
#pragma once

#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "kernel/pcf.h"
#include "kernel/shadow_map.h"

namespace pcf {

// The receiver pixels' lookups of a light-space readback (4 floats per pixel: u, v, ref, alpha
// 1 on receivers), at most maxCount of them, evenly strided over the frame so the subsample
// covers lit, shadowed and penumbra pixels in the frame's own proportions. (u, v, ref, 0) each.
std::vector<glm::vec4> receiverLookups(std::span<const float> lightSpace, size_t maxCount);

struct CpuTiming {
    // median over the passes of wall time / lookups, steady clock: with T threads, the
    // machine's throughput (T threads share the lookups), not one lookup's latency
    double nsPerPixel = 0.0;
    double checksum = 0.0;  // sum of the visibilities of one pass (keeps the work observable)
};

// Runs filterVisibility over all lookups `passes` times (after one warm-up pass over up to 1024
// of them) and reports the median time per lookup. threads: workers sharing each pass in equal
// contiguous slices (0 = all cores, ground_truth.h resolveThreadCount); 1 gives the cost of
// the math on one core. Throws std::invalid_argument when passes < 1 or threads < 0.
CpuTiming timeCpuKernel(const ShadowMap& map, std::span<const glm::vec4> lookups,
                        const PcfParams& params, int passes = 3, int threads = 1);

}  // namespace pcf
