// advise_measure.h: the advise search's measurements (advise.h) on a scene, with bench's own sweep
// (bench.h: runBench) over one point at a time: the ground truth computed once, then per
// setting the edge band's RMSE, the acne share over the clean lit pixels at the scene's light,
// the leak width over the clean umbra pixels (the stability leak sweep's measure), the shimmer
// p99 as the map's grid creeps 1/32 texel a frame, and the lookup pass's process CPU time
// (median and IQR of the timing rounds). Needs a current OpenGL 4.5 context.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "measure/advise.h"
#include "measure/bench.h"
#include "scene/scene.h"

namespace pcf {

struct AdviseMeasureOptions {
    glm::ivec2 frameSize{480, 270};
    bool areaTruth = false;  // BenchOptions::areaTruth
    int truthSpp = 2;
    int repeats = 5;  // timing rounds per setting
    int shimmerFrames = 8;
    int threads = 0;  // the truth's and the clean masks' (0 = all cores)
    // Culling, depth format, the bias parameters the search leaves alone (bench's base: front
    // faces culled).
    RenderSettings base = benchBaseSettings();
};

// The bench options that measure one setting (one point: its filter, map size and bias).
BenchOptions adviseBenchOptions(const AdviseMeasureOptions& options, const AdviseSetting& s);
// The base settings with the setting's bias mode and amount (its parameter table's field).
RenderSettings adviseBiasSettings(RenderSettings base, const AdviseBias& bias);
// The search's measures of one bench row: the cost is the lookup pass's CPU time where measured
// (software GL), else the pass's own time.
AdviseMetrics adviseMetricsOf(const BenchRow& row);

class AdviseBench {
  public:
    // Computes the ground truth; throws BenchSceneError when the frame shows no shadow edge.
    AdviseBench(const Scene& scene, const AdviseMeasureOptions& options);
    ~AdviseBench();
    AdviseBench(const AdviseBench&) = delete;
    AdviseBench& operator=(const AdviseBench&) = delete;

    // Measures one setting; its bench row is kept (rows(), in the order measured).
    AdviseMetrics measure(const AdviseSetting& s);
    // Times the settings again, `rounds` rounds each timing every setting once (bench's passes,
    // one sample each: the lookup pass's process CPU time, else its own time): the search's
    // AdviseRetime.
    std::vector<AdviseCost> retime(const std::vector<AdviseSetting>& settings, int rounds);
    const std::vector<BenchRow>& rows() const { return mRows; }
    const GroundTruth& truth() const { return mTruth; }

  private:
    const Scene& mScene;
    AdviseMeasureOptions mOptions;
    GroundTruth mTruth;
    std::unique_ptr<SceneRenderer> mRenderer;
    std::vector<BenchRow> mRows;
};

}  // namespace pcf
