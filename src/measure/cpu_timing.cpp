#include "measure/cpu_timing.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "measure/ground_truth.h"
#include "render/gpu_timer.h"

namespace pcf {

std::vector<glm::vec4> receiverLookups(std::span<const float> lightSpace, size_t maxCount) {
    std::vector<size_t> receivers;
    for (size_t k = 0; k < lightSpace.size() / 4; ++k) {
        if (lightSpace[4 * k + 3] == 1.0f) receivers.push_back(k);
    }
    // count of them, the i-th at floor(i * receivers / count): evenly spread over the frame.
    size_t count = std::min(receivers.size(), maxCount);
    std::vector<glm::vec4> lookups;
    lookups.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        size_t k = receivers[i * receivers.size() / count];
        lookups.emplace_back(lightSpace[4 * k], lightSpace[4 * k + 1], lightSpace[4 * k + 2], 0.0f);
    }
    return lookups;
}

CpuTiming timeCpuKernel(const ShadowMap& map, std::span<const glm::vec4> lookups,
                        const PcfParams& params, int passes, int threads) {
    if (passes < 1) throw std::invalid_argument("timeCpuKernel: passes must be at least 1");
    if (threads < 0) throw std::invalid_argument("timeCpuKernel: threads must be >= 0");
    size_t workers = std::min(static_cast<size_t>(resolveThreadCount(threads)),
                              std::max<size_t>(lookups.size(), 1));
    CpuTiming result;
    if (lookups.empty()) return result;
    double sink = 0.0;
    size_t warm = std::min<size_t>(lookups.size(), 1024);
    for (size_t k = 0; k < warm; ++k) {
        sink += filterVisibility(map, glm::vec2(lookups[k]), lookups[k].z, params);
    }
    std::vector<double> nsPerPixel;
    for (int p = 0; p < passes; ++p) {
        std::vector<double> sums(workers, 0.0);
        auto slice = [&](size_t w) {
            size_t lo = lookups.size() * w / workers;
            size_t hi = lookups.size() * (w + 1) / workers;
            double s = 0.0;
            for (size_t k = lo; k < hi; ++k) {
                s += filterVisibility(map, glm::vec2(lookups[k]), lookups[k].z, params);
            }
            sums[w] = s;
        };
        auto start = std::chrono::steady_clock::now();
        if (workers == 1) {
            slice(0);
        } else {
            std::vector<std::thread> pool;
            for (size_t w = 1; w < workers; ++w) pool.emplace_back(slice, w);
            slice(0);
            for (std::thread& t : pool) t.join();
        }
        auto end = std::chrono::steady_clock::now();
        double sum = 0.0;
        for (double s : sums) sum += s;
        nsPerPixel.push_back(std::chrono::duration<double, std::nano>(end - start).count() /
                             static_cast<double>(lookups.size()));
        result.checksum = sum;
    }
    // The warm-up's sum joins the checksum with weight 0 so that it, too, must be computed.
    result.checksum += sink * 0.0;
    result.nsPerPixel = medianOf(nsPerPixel);
    return result;
}

}  // namespace pcf
