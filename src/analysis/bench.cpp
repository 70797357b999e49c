#include "analysis/bench.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "analysis/cpu_timing.h"
#include "kernel/methods.h"
#include "render/gpu_lookup.h"
#include "render/gpu_timer.h"

namespace pcf {

namespace {

const ShadowMap& map(const std::map<int, ShadowMap>& maps, int size) { return maps.at(size); }

bool tentTakes(int n) { return n == 3 || n == 5 || n == 7; }

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
        if (method != PCF_TENT || tentTakes(n)) kernels.push_back(n);
    }
    return kernels;
}

RenderSettings settingsFor(const BenchOptions& options, const BenchPoint& p) {
    RenderSettings s = options.base;
    s.method = p.method;
    // Methods without a kernel ignore it; 3 is what makeParams gives them.
    s.kernel = p.kernel > 0 ? p.kernel : 3;
    s.mapSize = p.mapSize;
    s.frameSize = options.frameSize;
    return s;
}

}  // namespace

RenderSettings benchBaseSettings() {
    RenderSettings s;
    s.shadowCull = CullMode::Front;
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
    return o;
}

std::vector<BenchPoint> benchPoints(const BenchOptions& options) {
    std::vector<BenchPoint> points;
    for (int method : methodsOf(options)) {
        for (int n : kernelsOf(method, options)) {
            for (int size : options.mapSizes) points.push_back({method, n, size});
        }
    }
    return points;
}

std::optional<std::string> validateBenchOptions(const BenchOptions& options) {
    for (int method : options.methods) {
        if (method < 0 || method >= PCF_METHOD_COUNT) {
            return "unknown method id " + std::to_string(method);
        }
    }
    if (options.kernels.empty()) return std::string("--kernels is empty");
    for (int n : options.kernels) {
        if (n < MIN_KERNEL || n > MAX_KERNEL) {
            return "--kernels " + std::to_string(n) + " is out of range (" +
                   std::to_string(MIN_KERNEL) + ".." + std::to_string(MAX_KERNEL) + ")";
        }
    }
    if (options.mapSizes.empty()) return std::string("--map-sizes is empty");
    for (int size : options.mapSizes) {
        if (size < MIN_MAP_SIZE || size > MAX_MAP_SIZE) {
            return "--map-sizes " + std::to_string(size) + " is out of range (" +
                   std::to_string(MIN_MAP_SIZE) + ".." + std::to_string(MAX_MAP_SIZE) + ")";
        }
    }
    for (int method : methodsOf(options)) {
        if (kernelsOf(method, options).empty()) {
            return std::string(methodInfo(method).name) +
                   " takes --kernels 3, 5 or 7 and none of those was given";
        }
    }
    if (options.frameSize.x < 1 || options.frameSize.y < 1 ||
        options.frameSize.x > MAX_FRAME_SIDE || options.frameSize.y > MAX_FRAME_SIDE) {
        return std::string("the frame size is out of range");
    }
    if (options.gpuRepeats < 1) return std::string("the GPU repeats must be at least 1");
    if (options.cpuPasses < 1) return std::string("the CPU passes must be at least 1");
    return std::nullopt;
}

std::string pointName(const BenchPoint& point) {
    std::string name(methodInfo(point.method).name);
    if (point.kernel > 0) name += " N=" + std::to_string(point.kernel);
    return name;
}

std::vector<BenchRow> runBench(BenchContext& context, const BenchOptions& options) {
    if (auto why = validateBenchOptions(options)) throw std::invalid_argument(*why);
    if (context.renderer == nullptr || context.truth == nullptr) {
        throw std::invalid_argument("runBench: the context needs a renderer and a truth");
    }
    const GroundTruth& truth = *context.truth;
    if (truth.size != options.frameSize) {
        throw std::invalid_argument("runBench: the ground truth is not of the frame's size");
    }
    SceneRenderer& renderer = *context.renderer;
    std::vector<BenchPoint> points = benchPoints(options);

    // Run order: map size outer, then the report order within it.
    std::vector<size_t> order(points.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    auto mapRank = [&](int size) {
        return std::find(options.mapSizes.begin(), options.mapSizes.end(), size) -
               options.mapSizes.begin();
    };
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return mapRank(points[a].mapSize) < mapRank(points[b].mapSize);
    });

    std::vector<BenchRow> rows(points.size());
    ErrorRegions regions;
    std::vector<glm::vec4> lookups;
    std::vector<glm::vec4> frameLookups;  // every pixel of the light-space target, GL row order
    std::map<int, ShadowMap> maps;
    GpuLookup lookupPass;
    int currentMap = -1;
    for (size_t run = 0; run < order.size(); ++run) {
        const BenchPoint& p = points[order[run]];
        if (context.progress) {
            context.progress(static_cast<int>(run), static_cast<int>(order.size()), p);
        }
        RenderSettings s = settingsFor(options, p);
        if (p.mapSize != currentMap) {
            renderer.renderShadowPass(s);
            maps[p.mapSize] = renderer.readShadowMap();
            lookupPass.setMap(maps[p.mapSize]);
            currentMap = p.mapSize;
        }
        renderer.renderCameraPass(s);
        if (lookups.empty() && regions.compared.empty()) {
            // Depends on the geometry only: the same for every method and map size.
            std::vector<float> lightSpace = renderer.readLightSpace();
            regions = errorRegions(truth, receiverMaskFromLightSpace(lightSpace));
            lookups = receiverLookups(lightSpace, static_cast<size_t>(options.cpuLookups));
            // readLightSpace is top-down; the lookup pass takes GL rows (bottom-up).
            int w = options.frameSize.x;
            int h = options.frameSize.y;
            frameLookups.resize(static_cast<size_t>(w) * h);
            for (int y = 0; y < h; ++y) {
                const float* src = lightSpace.data() + static_cast<size_t>(h - 1 - y) * w * 4;
                for (int x = 0; x < w; ++x) {
                    frameLookups[static_cast<size_t>(y) * w + x] =
                        glm::vec4(src[4 * x], src[4 * x + 1], src[4 * x + 2], src[4 * x + 3]);
                }
            }
            lookupPass.setLookups(frameLookups, w);
        }
        std::vector<float> visibility = renderer.readVisibility();

        BenchRow& row = rows[order[run]];
        row.point = p;
        row.error = measureError(truth, regions, visibility);
        // One untimed draw of each timed pass: compiles its programs before the rounds.
        row.timer = renderer.timeCameraPass(s, 1).timer;
        lookupPass.draw(s.pcfParams(), s.rotatePerPixel);
        glFinish();
        row.cpuNsPerPixel = timeCpuKernel(map(maps, p.mapSize), lookups, s.pcfParams(),
                                          options.cpuPasses, options.cpuThreads)
                                .nsPerPixel;
        row.cpuPixels = static_cast<int>(lookups.size());
        row.texelReads = fetchCounts(p.method, s.kernel).texels;
        if (context.onPoint) context.onPoint(row, visibility, regions);
    }

    // The timing rounds (see bench.h): every point once per round, in run order.
    std::vector<std::vector<double>> sceneSamples(points.size());
    std::vector<std::vector<double>> lookupSamples(points.size());
    for (int round = 0; round < options.gpuRepeats; ++round) {
        if (context.roundProgress) context.roundProgress(round, options.gpuRepeats);
        currentMap = -1;
        for (size_t run = 0; run < order.size(); ++run) {
            size_t k = order[run];
            const BenchPoint& p = points[k];
            RenderSettings s = settingsFor(options, p);
            if (p.mapSize != currentMap) {
                renderer.renderShadowPass(s);
                lookupPass.setMap(maps[p.mapSize]);
                glFinish();
                currentMap = p.mapSize;
            }
            sceneSamples[k].push_back(renderer.timeCameraPass(s, 1, false).samplesMs.front());
            PcfParams prm = s.pcfParams();
            lookupSamples[k].push_back(
                timeGpu([&] { lookupPass.draw(prm, s.rotatePerPixel); }, 1, false)
                    .samplesMs.front());
        }
    }
    for (size_t k = 0; k < points.size(); ++k) {
        BenchRow& row = rows[k];
        Quartiles scene = quartilesOf(sceneSamples[k]);
        Quartiles lookup = quartilesOf(lookupSamples[k]);
        row.gpuMs = scene.median;
        row.gpuMsIqr = scene.iqr();
        row.lookupMs = lookup.median;
        row.lookupMsIqr = lookup.iqr();
        row.noisy = row.gpuMsIqr > NOISY_IQR_SHARE * row.gpuMs ||
                    row.lookupMsIqr > NOISY_IQR_SHARE * row.lookupMs;
    }
    return rows;
}

}  // namespace pcf
