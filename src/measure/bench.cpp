#include "measure/bench.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "kernel/methods.h"
#include "kernel/settings.h"
#include "measure/cpu_timing.h"
#include "measure/stability.h"
#include "render/frame_ops.h"
#include "render/gpu_lookup.h"
#include "render/gpu_timer.h"
#include "scene/light.h"

namespace pcf {

namespace {

std::vector<int> methodsOf(const BenchOptions& options) {
    if (!options.methods.empty()) return options.methods;
    std::vector<int> all;
    for (const MethodInfo& m : allMethods()) all.push_back(m.id);
    return all;
}

// The kernel sizes a method runs with: the options' (tent: those it takes), or {0}.
std::vector<int> kernelsOf(int method, const BenchOptions& options) {
    if (!methodInfo(method).usesKernel) return {0};
    std::vector<int> kernels;
    for (int n : options.kernels) {
        if (methodInfo(method).kernelSizes.empty() || kernelFits(method, n)) kernels.push_back(n);
    }
    return kernels;
}

RenderSettings settingsFor(const BenchOptions& options, const BenchPoint& p) {
    RenderSettings s = options.base;
    s.method = p.method;
    // Methods without a kernel ignore it; 3 is what makeParams gives them.
    s.kernel = p.kernel > 0 ? p.kernel : 3;
    s.mapSize = p.mapSize;
    s.cull = benchCull(options, p.method);
    s.frameSize = options.frameSize;
    s.weights = p.weights;
    if (p.weights == PCF_WEIGHTS_GAUSSIAN) s.sigma = p.sigma;
    return s;
}

// The weightings a method runs with: the options' for pcf-naive and pcf-gather, else the box.
std::vector<int> weightsOf(int method, const BenchOptions& options) {
    if (methodInfo(method).takesWeights) return options.weights;
    return {PCF_WEIGHTS_BOX};
}

}  // namespace

CullMode benchCull(const BenchOptions& options, int method) {
    if (options.cullByMethod && methodInfo(method).wantsLitFacesInMap) return CullMode::Back;
    return options.base.cull;
}

RenderSettings benchBaseSettings() {
    RenderSettings s;
    s.cull = CullMode::Front;
    return s;
}

BenchOptions quickBenchOptions() {
    BenchOptions o;
    o.kernels = {3};
    o.mapSizes = {128, 256};
    o.frameSize = {320, 180};
    o.gpuRepeats = 5;
    o.cpuLookups = 8192;
    o.cpuPasses = 1;
    o.truthSpp = 2;
    o.shimmerFrames = 4;
    o.cleanStride = 2;
    return o;
}

std::vector<BenchPoint> benchPoints(const BenchOptions& options) {
    std::vector<BenchPoint> points;
    for (int method : methodsOf(options)) {
        for (int n : kernelsOf(method, options)) {
            for (int w : weightsOf(method, options)) {
                float sigma = w == PCF_WEIGHTS_GAUSSIAN ? options.sigma : 0.0f;
                for (int size : options.mapSizes) points.push_back({method, n, size, w, sigma});
            }
        }
    }
    return points;
}

namespace {

// The weights: each known, with a valid sigma, and only box for a method that takes no other.
std::optional<ParamProblem> validateBenchWeights(const BenchOptions& options) {
    if (options.weights.empty()) return ParamProblem{"weights", "", " is empty"};
    bool box = false;
    for (int w : options.weights) {
        if (w < PCF_WEIGHTS_BOX || w > PCF_WEIGHTS_GAUSSIAN) {
            return ParamProblem{"", "unknown weights id " + std::to_string(w), ""};
        }
        box = box || w == PCF_WEIGHTS_BOX;
        PcfParams p = makeParams(PCF_GATHER, 3);
        p.weights = w;
        p.sigma = options.sigma;
        if (auto problem = checkParams(p)) return problem;  // weights or sigma
    }
    for (int method : methodsOf(options)) {
        if (!box && !methodInfo(method).takesWeights) {
            return ParamProblem{
                "weights", std::string(methodInfo(method).name) + " weighs its taps as it must: ",
                " other than box apply to pcf-naive and pcf-gather only (list "
                "only those methods)"};
        }
    }
    return std::nullopt;
}

}  // namespace

std::optional<ParamProblem> validateBenchOptions(const BenchOptions& options) {
    // A sentence naming no option, and one naming an option list once (said as its flag by the
    // command line: app/cli_util.h's cliWords).
    auto plain = [](std::string sentence) { return ParamProblem{"", std::move(sentence), ""}; };
    auto outOfRange = [](const char* setting, int v, int lo, int hi) {
        return ParamProblem{setting, "",
                            " " + std::to_string(v) + " is out of range (" + std::to_string(lo) +
                                ".." + std::to_string(hi) + ")"};
    };
    for (int method : options.methods) {
        if (method < 0 || method >= PCF_METHOD_COUNT) {
            return plain("unknown method id " + std::to_string(method));
        }
    }
    if (options.kernels.empty()) return ParamProblem{"kernels", "", " is empty"};
    for (int n : options.kernels) {
        if (n < MIN_KERNEL || n > MAX_KERNEL) {
            return outOfRange("kernels", n, MIN_KERNEL, MAX_KERNEL);
        }
    }
    if (options.mapSizes.empty()) return ParamProblem{"map_sizes", "", " is empty"};
    for (int size : options.mapSizes) {
        if (size < MIN_MAP_SIZE || size > MAX_MAP_SIZE) {
            return outOfRange("map_sizes", size, MIN_MAP_SIZE, MAX_MAP_SIZE);
        }
    }
    for (int method : methodsOf(options)) {
        if (kernelsOf(method, options).empty()) {
            return ParamProblem{"kernels", std::string(methodInfo(method).name) + " takes ",
                                " " + kernelSizesText(method) + " and none of those was given"};
        }
    }
    if (options.frameSize.x < 1 || options.frameSize.y < 1 ||
        options.frameSize.x > MAX_FRAME_SIDE || options.frameSize.y > MAX_FRAME_SIDE) {
        return plain("the frame size is out of range");
    }
    if (auto problem = validateBenchWeights(options)) return problem;
    if (options.truthSpp < 2 || options.truthSpp > MAX_TRUTH_SPP) {
        // One sample per pixel makes a truth of only 0 and 1: no edge band to measure.
        return outOfRange("spp", options.truthSpp, 2, MAX_TRUTH_SPP);
    }
    if (options.gpuRepeats < 1) return plain("the GPU repeats must be at least 1");
    if (options.cpuPasses < 1) return plain("the CPU passes must be at least 1");
    return std::nullopt;
}

std::string pointName(const BenchPoint& point) {
    std::string name(methodInfo(point.method).name);
    if (point.kernel > 0) name += " N=" + std::to_string(point.kernel);
    if (point.weights != PCF_WEIGHTS_BOX) name += " " + std::string(weightsName(point.weights));
    if (point.weights == PCF_WEIGHTS_GAUSSIAN) {
        char sigma[32];
        std::snprintf(sigma, sizeof sigma, " %g", point.sigma);
        name += sigma;
    }
    return name;
}

namespace {

// The light-space readback (top-down) as the lookup pass takes it: GL rows, bottom-up.
std::vector<glm::vec4> glRowLookups(const std::vector<float>& lightSpace, glm::ivec2 size) {
    std::vector<glm::vec4> lookups(static_cast<size_t>(size.x) * size.y);
    for (int y = 0; y < size.y; ++y) {
        const float* src = lightSpace.data() + static_cast<size_t>(size.y - 1 - y) * size.x * 4;
        for (int x = 0; x < size.x; ++x) {
            lookups[static_cast<size_t>(y) * size.x + x] =
                glm::vec4(src[4 * x], src[4 * x + 1], src[4 * x + 2], src[4 * x + 3]);
        }
    }
    return lookups;
}

// The receiver target's dz/du, dz/dv (top-down), the renderer's own receiver plane per pixel, in
// the lookup pass's GL row order: the bare pass repeats a per-tap bias exactly as the frame did.
std::vector<glm::vec2> glRowDzDuv(const std::vector<float>& receiver, glm::ivec2 size) {
    std::vector<glm::vec2> planes(static_cast<size_t>(size.x) * size.y);
    for (int y = 0; y < size.y; ++y) {
        const float* src = receiver.data() + static_cast<size_t>(size.y - 1 - y) * size.x * 4;
        for (int x = 0; x < size.x; ++x) {
            planes[static_cast<size_t>(y) * size.x + x] = glm::vec2(src[4 * x], src[4 * x + 1]);
        }
    }
    return planes;
}

// The run order: map size outer (each map rendered and read once), then the report order.
std::vector<size_t> runOrder(const std::vector<BenchPoint>& points, const BenchOptions& options) {
    std::vector<size_t> order(points.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    auto mapRank = [&](int size) {
        return std::find(options.mapSizes.begin(), options.mapSizes.end(), size) -
               options.mapSizes.begin();
    };
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return mapRank(points[a].mapSize) < mapRank(points[b].mapSize);
    });
    return order;
}

// One bench run over its points: phase 1 (measurePoint per point), then the timing rounds.
class BenchRun {
  public:
    BenchRun(BenchContext& context, const BenchOptions& options)
        : mContext(context),
          mOptions(options),
          mRenderer(*context.renderer),
          mTruth(*context.truth),
          mPoints(benchPoints(options)),
          mOrder(runOrder(mPoints, options)),
          mRows(mPoints.size()) {}

    std::vector<BenchRow> run() {
        for (size_t run = 0; run < mOrder.size(); ++run) {
            const BenchPoint& p = mPoints[mOrder[run]];
            if (mContext.progress) {
                mContext.progress(static_cast<int>(run), static_cast<int>(mOrder.size()), p);
            }
            measurePoint(mRows[mOrder[run]], p);
        }
        timeRounds();
        return std::move(mRows);
    }

  private:
    BenchContext& mContext;
    const BenchOptions& mOptions;
    SceneRenderer& mRenderer;
    const GroundTruth& mTruth;
    std::vector<BenchPoint> mPoints;
    std::vector<size_t> mOrder;
    std::vector<BenchRow> mRows;
    ErrorRegions mRegions;
    ErrorRegions mContactRegions;        // the edge band near the casters (contactDistance > 0)
    std::vector<glm::vec4> mCpuLookups;  // receiver pixels the CPU kernel is timed on
    // What a point's map depends on: its size, and for a method that reads moments the moments
    // pass's inputs (the method: its texel kind and warp; the blur's kernel and weights). Points
    // with equal keys read one map.
    using MapKey = std::tuple<int, int, int, int, float>;
    static MapKey mapKeyOf(const BenchPoint& p) {
        if (!readsMoments(p.method)) return {p.mapSize, -1, 0, 0, 0.0f};
        return {p.mapSize, p.method, p.kernel, p.weights, p.sigma};
    }
    ShadowMap mMap;  // the map of mCurrentMap, read back (the lookup pass's, the CPU kernel's)
    GpuLookup mLookupPass;
    std::optional<MapKey> mCurrentMap;

    // Draws the point's map, unless the map drawn last is the one it reads.
    void useMap(const BenchPoint& p, const RenderSettings& s) {
        MapKey key = mapKeyOf(p);
        if (mCurrentMap == key) return;
        mRenderer.renderShadowPass(s);
        mMap = mRenderer.readShadowMap();
        mLookupPass.setMap(mMap);
        mCurrentMap = key;
    }
    std::vector<std::optional<Hit>> mHits;  // the clean masks' surface points, once
    // Clean lit and clean umbra masks per (footprint reach, map size).
    std::map<std::pair<float, int>, std::pair<std::vector<uint8_t>, std::vector<uint8_t>>> mClean;
    std::map<int, CasterDistances> mDistances;  // per map size: the leak width's distances

    // The umbra pixels' distances from the casters at the point's map size (its fitted map).
    const CasterDistances& distancesFor(int mapSize) {
        auto it = mDistances.find(mapSize);
        if (it != mDistances.end()) return it->second;
        return mDistances[mapSize] = casterDistances(*mContext.scene, mTruth, mRegions, mHits,
                                                     mRenderer.shadowClipFromWorld(), mapSize);
    }

    // The first camera pass fixes what depends on the geometry only: the regions, the lookups.
    void readGeometry() {
        std::vector<float> lightSpace = mRenderer.readLightSpace();
        mRegions = errorRegions(mTruth, receiverMaskFromLightSpace(lightSpace));
        mCpuLookups = receiverLookups(lightSpace, static_cast<size_t>(mOptions.cpuLookups));
        mLookupPass.setLookups(glRowLookups(lightSpace, mOptions.frameSize), mOptions.frameSize.x,
                               glRowDzDuv(mRenderer.readReceiver(), mOptions.frameSize));
        if (mOptions.contactDistance > 0.0f && mContext.scene != nullptr) {
            if (mHits.empty())
                mHits = centreHits(*mContext.scene, mTruth.size, mOptions.cpuThreads);
            mContactRegions = mRegions;
            mContactRegions.edge =
                nearContactMask(*mContext.scene, mHits, mRegions.edge, mOptions.contactDistance);
            mContactRegions.edgeCount = static_cast<int>(
                std::count(mContactRegions.edge.begin(), mContactRegions.edge.end(), 1));
        }
    }

    void measurePoint(BenchRow& row, const BenchPoint& p) {
        RenderSettings s = settingsFor(mOptions, p);
        useMap(p, s);
        mRenderer.renderCameraPass(s);
        if (mRegions.compared.empty()) readGeometry();
        std::vector<float> visibility = mRenderer.readVisibility();
        row.point = p;
        row.error = measureError(mTruth, mRegions, visibility);
        if (!mContactRegions.edge.empty()) {
            row.contact = measureError(mTruth, mContactRegions, visibility);
            row.contactDistance = mOptions.contactDistance;
        }
        if (mContext.scene != nullptr) {
            const auto& [lit, umbra] = cleanMasks(p);
            row.acne = falseShadow(visibility, lit);
            row.leak = falseLight(visibility, umbra);
            const CasterDistances& d = distancesFor(p.mapSize);
            row.leakWidth = leakWidth(visibility, umbra, d.texels, d.world, mOptions.frameSize,
                                      LEAK_MIN_RUN, cleanStride());
        }
        row.shimmer = measureShimmer(s);
        // One untimed draw of each timed pass: compiles its programs before the rounds.
        row.timer = mRenderer.timeCameraPass(s, 1).timer;
        PcfParams prm = mRenderer.pcfParams(s);  // pcss: the scene light's size in the map
        mLookupPass.draw(prm, s.rotate, s.kernelBias());
        if (mOptions.reference) mLookupPass.drawReference(prm);
        finishGpu();
        row.cpuNsPerPixel =
            timeCpuKernel(mMap, mCpuLookups, prm, mOptions.cpuPasses, mOptions.cpuThreads)
                .nsPerPixel;
        row.cpuPixels = static_cast<int>(mCpuLookups.size());
        row.texelReads = fetchCounts(p.method, s.kernel).texels;
        if (mContext.onPoint) mContext.onPoint(row, visibility, mRegions);
    }

    int cleanStride() const {
        if (mOptions.cleanStride > 0) return mOptions.cleanStride;
        double ratio = static_cast<double>(mRegions.comparedCount) / CLEAN_SAMPLE_TARGET;
        return std::max(1, static_cast<int>(std::ceil(std::sqrt(ratio))));
    }

    // The clean masks of the point's footprint (the stability sweeps' reach: the method's own
    // footprint + half a texel for the bilinear taps' rounding) at its map size.
    const std::pair<std::vector<uint8_t>, std::vector<uint8_t>>& cleanMasks(const BenchPoint& p) {
        StabilityMethod m{p.method, p.kernel};
        float reach = footprintReachTexels(m, mOptions.base.radius) + 0.5f;
        auto key = std::make_pair(reach, p.mapSize);
        auto it = mClean.find(key);
        if (it != mClean.end()) return it->second;
        const Scene& scene = *mContext.scene;
        if (mHits.empty()) mHits = centreHits(scene, mTruth.size, mOptions.cpuThreads);
        glm::mat4 clip = mRenderer.shadowClipFromWorld();
        int stride = cleanStride();
        auto mask = [&](bool lit) {
            return cleanPixelMask(scene, mTruth, mRegions, mHits, clip, p.mapSize, reach, lit,
                                  mOptions.cpuThreads, stride);
        };
        return mClean[key] = {mask(true), mask(false)};
    }

    // The map's grid slid 1/32 texel a frame along its diagonal, the world still (the fit shrunk
    // by 2 texels a side so no shift pushes the scene off the map, as the stability sweep does).
    ShimmerStats measureShimmer(const RenderSettings& s) {
        if (mOptions.shimmerFrames < 2) return {};
        glm::mat4 fitted = mRenderer.shadowClipFromWorld();
        float n = static_cast<float>(s.mapSize);
        glm::mat4 shrink(1.0f);
        shrink[0][0] = shrink[1][1] = (n - 4.0f) / n;
        std::vector<std::vector<float>> frames;
        for (int t = 0; t < mOptions.shimmerFrames; ++t) {
            float step = static_cast<float>(t) / SHIMMER_STEPS;
            mRenderer.setShadowClipFromWorld(
                shiftShadowOrigin(shrink * fitted, glm::vec2(step), s.mapSize, false));
            mRenderer.renderShadowPass(s);
            mRenderer.renderCameraPass(s);
            frames.push_back(mRenderer.readVisibility());
        }
        mRenderer.setShadowClipFromWorld(fitted);
        mRenderer.renderShadowPass(s);  // the point's own map again, for what follows
        return shimmerStats(frames, mRegions.compared);
    }

    // One pass's samples of one point: wall clock, and process CPU time on software GL.
    struct PassSamples {
        std::vector<double> wall;
        std::vector<double> cpu;
        void add(const TimingResult& t) {
            wall.push_back(t.samplesMs.front());
            cpu.insert(cpu.end(), t.cpuSamplesMs.begin(), t.cpuSamplesMs.end());
        }
    };
    struct PointSamples {
        PassSamples scene, lookup, reference;
    };

    // One sample of each of the point's passes, back to back.
    void timePoint(const RenderSettings& s, PointSamples& samples) {
        samples.scene.add(mRenderer.timeCameraPass(s, 1, false));
        PcfParams prm = mRenderer.pcfParams(s);
        PcfBias bias = s.kernelBias();
        samples.lookup.add(timeGpu([&] { mLookupPass.draw(prm, s.rotate, bias); }, 1, false));
        if (mOptions.reference) {
            samples.reference.add(timeGpu([&] { mLookupPass.drawReference(prm); }, 1, false));
        }
    }

    // One timing round: each point of `order` once, in that order.
    void timeRound(const std::vector<size_t>& order, std::vector<PointSamples>& samples) {
        mCurrentMap.reset();
        for (size_t k : order) {
            const BenchPoint& p = mPoints[k];
            RenderSettings s = settingsFor(mOptions, p);
            useMap(p, s);
            finishGpu();
            timePoint(s, samples[k]);
        }
    }

    static bool noisyTimes(const PointSamples& s) {
        Quartiles scene = quartilesOf(s.scene.wall), lookup = quartilesOf(s.lookup.wall);
        return scene.iqr() > NOISY_IQR_SHARE * scene.median ||
               lookup.iqr() > NOISY_IQR_SHARE * lookup.median;
    }

    // The timing rounds (see bench.h): every point once per round, in run order; then the
    // points that came out noisy as many rounds again, round-robin among themselves, before
    // they are flagged: a busy spell of the machine during the first rounds is not the point's.
    void timeRounds() {
        std::vector<PointSamples> samples(mPoints.size());
        for (int round = 0; round < mOptions.gpuRepeats; ++round) {
            if (mContext.roundProgress) mContext.roundProgress(round, mOptions.gpuRepeats);
            timeRound(mOrder, samples);
        }
        std::vector<size_t> again;
        for (size_t k : mOrder) {
            if (noisyTimes(samples[k])) again.push_back(k);
        }
        for (int round = 0; round < mOptions.gpuRepeats && !again.empty(); ++round) {
            timeRound(again, samples);
        }
        for (size_t k = 0; k < mPoints.size(); ++k) {
            BenchRow& row = mRows[k];
            Quartiles scene = quartilesOf(samples[k].scene.wall);
            Quartiles lookup = quartilesOf(samples[k].lookup.wall);
            row.gpuMs = scene.median;
            row.gpuMsIqr = scene.iqr();
            row.lookupMs = lookup.median;
            row.lookupMsIqr = lookup.iqr();
            Quartiles sceneCpu = quartilesOf(samples[k].scene.cpu);
            Quartiles lookupCpu = quartilesOf(samples[k].lookup.cpu);
            row.gpuCpuMs = sceneCpu.median;
            row.gpuCpuMsIqr = sceneCpu.iqr();
            row.lookupCpuMs = lookupCpu.median;
            row.lookupCpuMsIqr = lookupCpu.iqr();
            row.noisy = noisyTimes(samples[k]);
            if (mOptions.reference) {
                Quartiles reference = quartilesOf(samples[k].reference.wall);
                row.referenceMs = reference.median;
                row.referenceMsIqr = reference.iqr();
                row.referenceCpuMs = medianOf(samples[k].reference.cpu);
            }
        }
    }
};

}  // namespace

std::vector<BenchRow> runBench(BenchContext& context, const BenchOptions& options) {
    if (auto why = validateBenchOptions(options)) throw std::invalid_argument(why->text());
    if (context.renderer == nullptr || context.truth == nullptr) {
        throw std::invalid_argument("runBench: the context needs a renderer and a truth");
    }
    if (context.truth->size != options.frameSize) {
        throw std::invalid_argument("runBench: the ground truth is not of the frame's size");
    }
    return BenchRun(context, options).run();
}

GroundTruth benchGroundTruth(const BenchConfig& config) {
    const BenchOptions& options = config.options;
    GroundTruthOptions truthOptions;
    truthOptions.spp = options.truthSpp;
    truthOptions.threads = options.cpuThreads;
    truthOptions.area = options.areaTruth;
    GroundTruth truth = computeGroundTruth(config.scene, options.frameSize, truthOptions);
    // The chart's accuracy axis is the edge band's error: without a shadow edge in view every
    // method would score a perfect 0 and the chart would say nothing. Refuse instead.
    ErrorRegions truthRegions = errorRegions(truth);
    if (truthRegions.comparedCount == 0 || truthRegions.edgeCount == 0) {
        throw BenchSceneError(
            "scene '" + config.scene.name + "' shows " +
            (truthRegions.comparedCount == 0 ? std::string("no shadow receiver")
                                             : std::string("no shadow edge")) +
            " at " + std::to_string(options.frameSize.x) + "x" +
            std::to_string(options.frameSize.y) +
            ", so there is no edge band to measure error over; bench needs a shadow edge in view");
    }
    return truth;
}

BenchResult runBenchSweep(const BenchConfig& config, BenchContext callbacks,
                          const std::function<void(const GroundTruth&)>& truthDone) {
    const BenchOptions& options = config.options;
    if (auto why = validateBenchOptions(options)) throw std::invalid_argument(why->text());
    BenchResult result;
    result.truth = benchGroundTruth(config);
    if (truthDone) truthDone(result.truth);
    SceneRenderer renderer(config.scene);
    callbacks.renderer = &renderer;
    callbacks.truth = &result.truth;
    callbacks.scene = &config.scene;
    auto onPoint = callbacks.onPoint;
    callbacks.onPoint = [&](const BenchRow& row, std::span<const float> visibility,
                            const ErrorRegions& regions) {
        if (result.regions.compared.empty()) result.regions = regions;
        if (onPoint) onPoint(row, visibility, regions);
    };
    result.rows = runBench(callbacks, options);
    return result;
}

}  // namespace pcf
