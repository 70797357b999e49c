#include "measure/advise_measure.h"

#include <stdexcept>
#include <string>
#include <variant>

#include "kernel/settings.h"
#include "render/gpu_timer.h"

namespace pcf {

BenchOptions adviseBenchOptions(const AdviseMeasureOptions& options, const AdviseSetting& s) {
    BenchOptions o;
    o.methods = {s.filter.method};
    // A method without a kernel runs once whatever the list holds.
    o.kernels = {s.filter.kernel > 0 ? s.filter.kernel : 3};
    o.mapSizes = {s.mapSize};
    o.weights = {s.filter.weights};
    if (s.filter.weights == PCF_WEIGHTS_GAUSSIAN) o.sigma = s.filter.sigma;
    o.frameSize = options.frameSize;
    o.truthSpp = options.truthSpp;
    o.areaTruth = options.areaTruth;
    o.shimmerFrames = options.shimmerFrames;
    o.gpuRepeats = options.repeats;
    // The CPU kernel's time is not the search's cost: a token pass.
    o.cpuLookups = 256;
    o.cpuPasses = 1;
    o.cpuThreads = options.threads;
    o.base = adviseBiasSettings(options.base, s.bias);
    // One culling for the whole search, the one advise's [settings] table states.
    o.cullByMethod = false;
    return o;
}

RenderSettings adviseBiasSettings(RenderSettings base, const AdviseBias& bias) {
    base.bias = bias.mode;
    std::string key = adviseBiasKey(bias.mode);
    if (key.empty()) return base;
    const ParamInfo* p = findParam(key);
    if (p == nullptr) throw std::logic_error("no parameter " + key);
    base.*std::get<float ShadowSettings::*>(p->field) = bias.amount;
    return base;
}

AdviseMetrics adviseMetricsOf(const BenchRow& row) {
    AdviseMetrics m;
    m.edgeRmse = row.error.edgeRmse;
    m.acneShare = row.acne.share;
    m.leakTexels = row.leakWidth.texels;
    m.shimmerP99 = row.shimmer.flickerP99;
    bool cpu = row.lookupCpuMs > 0.0;
    m.costMs = cpu ? row.lookupCpuMs : row.lookupMs;
    m.costIqr = cpu ? row.lookupCpuMsIqr : row.lookupMsIqr;
    return m;
}

AdviseBench::AdviseBench(const Scene& scene, const AdviseMeasureOptions& options)
    : mScene(scene), mOptions(options) {
    // A setting's bench options carry the truth's: any one gives the truth.
    BenchConfig config{scene, adviseBenchOptions(options, {{PCF_NEAREST, 0}, MIN_MAP_SIZE, {}})};
    mTruth = benchGroundTruth(config);
    mRenderer = std::make_unique<SceneRenderer>(scene);
}

AdviseBench::~AdviseBench() = default;

AdviseMetrics AdviseBench::measure(const AdviseSetting& s) {
    BenchContext context;
    context.renderer = mRenderer.get();
    context.truth = &mTruth;
    context.scene = &mScene;
    std::vector<BenchRow> rows = runBench(context, adviseBenchOptions(mOptions, s));
    if (rows.size() != 1) throw std::logic_error("advise: one setting gave several bench rows");
    mRows.push_back(rows.front());
    return adviseMetricsOf(rows.front());
}

std::vector<AdviseCost> AdviseBench::retime(const std::vector<AdviseSetting>& settings,
                                            int rounds) {
    BenchContext context;  // no scene: no clean masks, no acne or leak measured
    context.renderer = mRenderer.get();
    context.truth = &mTruth;
    std::vector<std::vector<double>> samples(settings.size());
    for (int round = 0; round < rounds; ++round) {
        for (size_t k = 0; k < settings.size(); ++k) {
            BenchOptions o = adviseBenchOptions(mOptions, settings[k]);
            o.gpuRepeats = 1;
            o.shimmerFrames = 0;
            AdviseMetrics m = adviseMetricsOf(runBench(context, o).front());
            samples[k].push_back(m.costMs);
        }
    }
    std::vector<AdviseCost> costs;
    for (const std::vector<double>& s : samples) {
        Quartiles q = quartilesOf(s);
        costs.push_back({q.median, q.iqr()});
    }
    return costs;
}

}  // namespace pcf
