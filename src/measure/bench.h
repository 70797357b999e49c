// bench.h: speed against accuracy. One sweep over methods x kernel sizes x weightings x
// shadow-map sizes on one scene: per point two GPU times (the camera pass, and the filter alone
// as a bare lookup pass), the CPU kernel's time per pixel, the texel reads per lookup, the error
// against the ground truth split by cause, and the shimmer as the map's grid slides.
//
// The error, split as the stability sweeps split it (failure_measures.h), so that the chart does
// not mix bias errors with filter errors:
//   aliasing     the edge band's RMSE (error_metrics.h): where the truth is partly lit, the
//                filter's own error;
//   acne         false shadow: over the CLEAN LIT pixels (fully lit in the truth over the whole
//                footprint of the method at that map size) the share with v < 0.99 and the mean
//                darkening 1 - v;
//   leak         false light: over the CLEAN UMBRA pixels the share with v > 0.01.
//   contact      (contactDistance > 0) the aliasing error over the edge band's pixels near a
//                caster only: the contacts, where a soft shadow's penumbra is narrowest.
// Shimmer, the second accuracy axis: the map's texel grid slid under the still world in steps of
// 1/32 texel (stability.h's SHIMMER_STEPS, light.h's shiftShadowOrigin), shimmerFrames frames;
// mean and 99th percentile of |v(t) - v(t-1)| over the pixels that flicker (failure_measures.h):
// how far a pixel jumps when it moves at all. (The mean over ALL receivers hardly tells filters
// apart: sliding any linear filter over an edge changes the picture by about the same total.)
//
// The ground truth is computed once per scene and frame size (the map size and method do not
// change it); the light-space target, which depends on neither either, is read back once.
//
// Two phases. First, per point (map sizes outer, so each shadow map is rendered and read back
// once): the camera pass, its error, its shimmer frames, the CPU kernel's time, and one untimed
// draw of each timed pass (shader compilation, first touch). Then the timing, ROUND-ROBIN:
// gpuRepeats rounds, each taking one sample of every point's camera pass and lookup pass, so a
// burst of load from elsewhere lands on every method alike instead of on whichever ran during
// it. Per point the median and the interquartile range of its samples (gpu_timer.h
// quartilesOf). A point whose IQR exceeds NOISY_IQR_SHARE of its median after those rounds is
// timed gpuRepeats rounds more (round-robin among such points), and is `noisy` only when either
// IQR over all its samples still does: a busy spell of the machine is not the point's noise.
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/methods.h"
#include "measure/error_metrics.h"
#include "measure/failure_measures.h"
#include "measure/ground_truth.h"
#include "render/render_settings.h"
#include "render/scene_renderer.h"

namespace pcf {

// RenderSettings{} with cull = CullMode::Front (see BenchOptions::base).
RenderSettings benchBaseSettings();

struct BenchOptions {
    std::vector<int> methods;           // method ids, in this order; empty = all
    std::vector<int> kernels{3, 5, 7};  // N for the methods that take one (tent: 3, 5, 7 only)
    std::vector<int> mapSizes{256, 512, 1024, 2048};
    // Weightings of the N x N lookups (PCF_WEIGHTS_*), for pcf-naive and pcf-gather; every
    // other method runs with the box only. sigma: the gaussian's, in texels.
    std::vector<int> weights{PCF_WEIGHTS_BOX};
    float sigma = 1.0f;
    glm::ivec2 frameSize{1280, 720};
    int truthSpp = DEFAULT_TRUTH_SPP;  // K x K first-pass samples of the ground truth (>= 2)
    // The truth against the light's disk (GroundTruthOptions::area), not its centre: the scene's
    // light must have a size (a directional light's angular diameter, a spot light's radius).
    bool areaTruth = false;
    // World units: also the edge error over the edge band's pixels within this distance of a
    // caster (failure_measures.h: nearContactMask), where a soft shadow is sharp (contact
    // hardening) and one fixed kernel width cannot be right both there and far away. 0: not
    // measured.
    float contactDistance = 0.0f;
    int shimmerFrames = 8;  // frames of the grid slid 1/32 texel apart (< 2: none)
    // The clean-pixel masks (acne, leak) test every stride-th pixel in x and y; 0 = the stride
    // that leaves about CLEAN_SAMPLE_TARGET compared pixels.
    int cleanStride = 0;
    int gpuRepeats = 9;      // timing rounds: samples per point of each pass (median, IQR)
    int cpuLookups = 32768;  // receiver pixels the CPU kernel is timed on, at most
    int cpuPasses = 3;       // passes over them (median)
    int cpuThreads = 0;      // threads sharing each pass (0 = all cores)
    // Also time each point's reference pass (GpuLookup::drawReference: the method written the
    // textbook way, no shared kernel) in the same rounds, right after its lookup pass.
    bool reference = false;
    // Bias, depth format, culling (method, kernel, map size and frame size are the sweep's).
    // The renderer's defaults but for culling: the map holds BACK faces (front faces culled),
    // which keeps shadow acne, a bias problem, off the single-sided ground and the lit faces
    // of closed objects, so the error measures the filter. (Culling back faces instead, a
    // constant bias of 0.002 leaves acne over the whole ground at 128..512 texel maps.)
    RenderSettings base = benchBaseSettings();
    // A method that wants the casters' lit faces in its map (kernel/methods.h:
    // MethodInfo::wantsLitFacesInMap, the moment methods) has back faces culled instead of
    // base.cull; false: base.cull for every method (bench --cull given).
    bool cullByMethod = true;
};

// The faces the shadow pass culls for `method` under `options` (cullByMethod).
CullMode benchCull(const BenchOptions& options, int method);

// A point is noisy when the IQR of a timing is above this share of its median.
constexpr double NOISY_IQR_SHARE = 0.10;
// Compared pixels the clean masks test at most (cleanStride 0), to keep their ray casts cheap.
constexpr int CLEAN_SAMPLE_TARGET = 60000;

// The --quick settings: 320x180 frame, maps 128 and 256, N = 3, 5 rounds, few CPU lookups,
// 2x2 truth samples, 4 shimmer frames, clean masks on every 2nd pixel.
BenchOptions quickBenchOptions();

struct BenchPoint {
    int method = PCF_NEAREST;
    int kernel = 0;  // N, or 0 for a method that takes none
    int mapSize = 0;
    int weights = PCF_WEIGHTS_BOX;  // pcf-naive, pcf-gather
    float sigma = 0.0f;             // gaussian weights' sigma in texels; 0 for the others
    bool operator==(const BenchPoint&) const = default;
};

// The points of the sweep in the order rows are reported: by method (options' order), kernel,
// weighting, map size. A method without a kernel appears once per map size; tent only with
// N = 3, 5, 7; only pcf-naive and pcf-gather once per weighting (the others with the box).
std::vector<BenchPoint> benchPoints(const BenchOptions& options);

// Why the options cannot run (a kernel or map size out of range, a method with no kernel left,
// no points at all), nullopt when they can: one sentence naming the option list at fault as
// its field's words ("kernels", "map_sizes", "spp"; the kernel's checkParams says "weights" and
// "sigma"), which the command line says as flags (app/cli_util.h: cliWords).
std::optional<ParamProblem> validateBenchOptions(const BenchOptions& options);

struct BenchRow {
    BenchPoint point;
    double gpuMs = 0.0;  // median camera-pass time (render/gpu_timer.h)
    double gpuMsIqr = 0.0;
    // The filter's own cost: the kernel as a bare full-screen lookup pass over the frame's
    // light-space target (render/gpu_lookup.h, as the parity tests run it), median and IQR.
    double lookupMs = 0.0;
    double lookupMsIqr = 0.0;
    // The reference pass over the same lookups (BenchOptions::reference; else 0), median and
    // IQR, and its process CPU time as lookupCpuMs.
    double referenceMs = 0.0;
    double referenceMsIqr = 0.0;
    double referenceCpuMs = 0.0;
    bool noisy = false;  // either IQR > NOISY_IQR_SHARE of its median
    // On software renderers, the medians of the process CPU time of the same samples
    // (render/gpu_timer.h: cpuSamplesMs): the passes' cost as work, steadier than the wall
    // clock on a busy machine. 0 when the GPU's own timer measured.
    double gpuCpuMs = 0.0;
    double lookupCpuMs = 0.0;
    // Their interquartile ranges (0 where unknown: a bench.csv before these columns).
    double gpuCpuMsIqr = 0.0;
    double lookupCpuMsIqr = 0.0;
    double cpuNsPerPixel = 0.0;
    int cpuPixels = 0;   // receiver pixels the CPU kernel was timed on
    int texelReads = 0;  // fetchCounts(method, N).texels
    ErrorStats error;    // error.edgeRmse: the aliasing error (see the top of this file)
    // The same over the edge band near the casters (BenchOptions::contactDistance; else zero).
    ErrorStats contact;
    // The run's BenchOptions::contactDistance, world units (0: the contact was not measured).
    double contactDistance = 0.0;
    FailureRate acne;  // false shadow over the clean lit pixels
    FailureRate leak;  // false light over the clean umbra pixels
    // How far the false light reaches from the casters (failure_measures.h: leakWidth, the
    // stability leak sweep's measure) over the same clean umbra pixels; zero without a scene.
    LeakWidth leakWidth;
    ShimmerStats shimmer;
    std::string timer;  // which timer gave gpuMs
    // GL_RENDERER of the run (every row of one run carries it: bench.csv has no other place);
    // empty when unknown (a bench.csv older than BENCH_CSV_HEADER_V4's successor).
    std::string glRenderer;
    // Which truth the errors are measured against, in the report's words (every row of a run):
    // "hard (the light's centre)" or "area (a sun disk of 2 degrees)" (benchTruthKind reads
    // which); empty when unknown (a bench.csv older than BENCH_CSV_HEADER_V6's successor).
    std::string truth;
};

// "pcf-gather N=3", "pcf-gather N=3 gaussian 1.5" or "nearest".
std::string pointName(const BenchPoint& point);

struct BenchContext {
    SceneRenderer* renderer = nullptr;   // the scene's renderer; its GL context current
    const GroundTruth* truth = nullptr;  // of the same scene at options.frameSize
    const Scene* scene = nullptr;        // the scene, for the clean masks (none: no acne/leak)
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

// The scene cannot be benched (no shadow receiver or no shadow edge in view: every method would
// score a perfect 0 on the chart's accuracy axis). what() is one line for the user.
class BenchSceneError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

// What the whole bench needs to know: the scene and the sweep's options.
struct BenchConfig {
    Scene scene;
    BenchOptions options;
};

struct BenchResult {
    std::vector<BenchRow> rows;
    GroundTruth truth;
    ErrorRegions regions;  // compared pixels and edge band the errors were measured over
};

// The ground truth of the config's scene at its frame size (no progress), checked to show a
// shadow edge: BenchSceneError when it shows no receiver or no edge.
GroundTruth benchGroundTruth(const BenchConfig& config);

// The whole bench, for a current GL context: the ground truth (its own progress: none), the
// check that the scene has a shadow edge in view (BenchSceneError before any callback runs),
// then `truthDone`, then runBench with the callbacks of `callbacks` (its renderer, truth and
// scene are set here).
BenchResult runBenchSweep(const BenchConfig& config, BenchContext callbacks,
                          const std::function<void(const GroundTruth&)>& truthDone = {});

}  // namespace pcf
