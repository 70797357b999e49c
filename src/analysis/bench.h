// bench.h: speed against accuracy. One sweep over methods x kernel sizes x shadow-map sizes on
// one scene: per point two GPU times (the camera pass, and the filter alone as a bare lookup
// pass), the CPU kernel's time per pixel, the texel reads per lookup, and the error against the
// ground truth (error_metrics.h).
//
// The ground truth is computed once per scene and frame size (the map size and method do not
// change it); the light-space target, which depends on neither either, is read back once.
//
// Two phases. First, per point (map sizes outer, so each shadow map is rendered and read back
// once): the camera pass, its error, the CPU kernel's time, and one untimed draw of each timed
// pass (shader compilation, first touch). Then the timing, ROUND-ROBIN: gpuRepeats rounds, each
// taking one sample of every point's camera pass and lookup pass, so a burst of load from
// elsewhere lands on every method alike instead of on whichever ran during it. Per point the
// median and the interquartile range of its samples (gpu_timer.h quartilesOf); a point is
// `noisy` when either IQR exceeds NOISY_IQR_SHARE of its median.
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/error_metrics.h"
#include "analysis/ground_truth.h"
#include "render/render_settings.h"
#include "render/scene_renderer.h"

namespace pcf {

// RenderSettings{} with shadowCull = CullMode::Front (see BenchOptions::base).
RenderSettings benchBaseSettings();

struct BenchOptions {
    std::vector<int> methods;           // method ids, in this order; empty = all
    std::vector<int> kernels{3, 5, 7};  // N for the methods that take one (tent: 3, 5, 7 only)
    std::vector<int> mapSizes{256, 512, 1024, 2048};
    glm::ivec2 frameSize{1280, 720};
    int gpuRepeats = 9;      // timing rounds: samples per point of each pass (median, IQR)
    int cpuLookups = 32768;  // receiver pixels the CPU kernel is timed on, at most
    int cpuPasses = 3;       // passes over them (median)
    int cpuThreads = 0;      // threads sharing each pass (0 = all cores)
    // Bias, depth format, culling (method, kernel, map size and frame size are the sweep's).
    // The renderer's defaults but for culling: the map holds BACK faces (front faces culled),
    // which keeps shadow acne, a bias problem, off the single-sided ground and the lit faces
    // of closed objects, so the error measures the filter. (Culling back faces instead, a
    // constant bias of 0.002 leaves acne over the whole ground at 128..512 texel maps.)
    RenderSettings base = benchBaseSettings();
};

// A point is noisy when the IQR of a timing is above this share of its median.
constexpr double NOISY_IQR_SHARE = 0.10;

// The --quick settings: 320x180 frame, maps 128 and 256, N = 3, 5 rounds, few CPU lookups.
BenchOptions quickBenchOptions();

struct BenchPoint {
    int method = PCF_NEAREST;
    int kernel = 0;  // N, or 0 for a method that takes none
    int mapSize = 0;
    bool operator==(const BenchPoint&) const = default;
};

// The points of the sweep in the order rows are reported: by method (options' order), kernel,
// map size. A method without a kernel appears once per map size; tent only with N = 3, 5, 7.
std::vector<BenchPoint> benchPoints(const BenchOptions& options);

// Why the options cannot run (a kernel or map size out of range, a method with no kernel left,
// no points at all), in one line naming the option; nullopt when they can.
std::optional<std::string> validateBenchOptions(const BenchOptions& options);

struct BenchRow {
    BenchPoint point;
    double gpuMs = 0.0;  // median camera-pass time (render/gpu_timer.h)
    double gpuMsIqr = 0.0;
    // The filter's own cost: the kernel as a bare full-screen lookup pass over the frame's
    // light-space target (render/gpu_lookup.h, as the parity tests run it), median and IQR.
    double lookupMs = 0.0;
    double lookupMsIqr = 0.0;
    bool noisy = false;  // either IQR > NOISY_IQR_SHARE of its median
    double cpuNsPerPixel = 0.0;
    int cpuPixels = 0;   // receiver pixels the CPU kernel was timed on
    int texelReads = 0;  // fetchCounts(method, N).texels
    ErrorStats error;
    std::string timer;  // which timer gave gpuMs
};

// "pcf-gather N=3" or "nearest".
std::string pointName(const BenchPoint& point);

struct BenchContext {
    SceneRenderer* renderer = nullptr;   // the scene's renderer; its GL context current
    const GroundTruth* truth = nullptr;  // of the same scene at options.frameSize
    // Before each point is measured: index (0-based, in run order), total, the point.
    std::function<void(int index, int total, const BenchPoint& point)> progress;
    // Before each timing round: round (0-based), rounds.
    std::function<void(int round, int rounds)> roundProgress;
    // After each point, with its rendered visibility (top-down) and the regions it was measured
    // over, e.g. to write a difference image.
    std::function<void(const BenchRow& row, std::span<const float> visibility,
                       const ErrorRegions& regions)>
        onPoint;
};

// Runs the sweep. Throws std::invalid_argument when validateBenchOptions objects, when a pointer
// in the context is null, or when the truth's size is not the frame's.
std::vector<BenchRow> runBench(BenchContext& context, const BenchOptions& options);

}  // namespace pcf
