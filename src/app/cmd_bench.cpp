// pcfscope bench: speed against accuracy (analysis/bench.h). Sweeps methods x kernel sizes x
// shadow-map sizes on one scene and writes, into DIR:
//   bench.csv               one row per run (analysis/bench_report.h has the columns)
//   bench.md                the same as a table, with the machine and the timer
//   speed_vs_accuracy.png   GPU time (log; --timing scene or lookup) with IQR bars against
//                           edge-band RMSE, the Pareto front drawn
//   diff/NAME.png           each run's signed error against the ground truth
// Everything is written into a staging folder inside DIR and moved into place only once the
// whole sweep has succeeded, so a failure leaves no partial output behind.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "analysis/bench.h"
#include "analysis/bench_report.h"
#include "analysis/difference_image.h"
#include "analysis/error_metrics.h"
#include "analysis/ground_truth.h"
#include "analysis/speed_chart.h"
#include "app/cli_util.h"
#include "app/commands.h"
#include "app/output_files.h"
#include "app/render_options.h"
#include "kernel/methods.h"
#include "render/gl_context.h"
#include "render/image_io.h"
#include "render/scene_renderer.h"

namespace pcf {

namespace {

namespace fs = std::filesystem;

constexpr const char* DEFAULT_SCENE = "box-on-plane";
constexpr int QUICK_TRUTH_SPP = 2;

struct BenchCommandOptions {
    std::string scene;
    std::string sceneFile;
    std::string methods;
    std::string kernels;
    std::string mapSizes;
    std::string out = "bench";
    bool quick = false;
    std::string size;
    std::string chartSize;
    int spp = DEFAULT_TRUTH_SPP;  // 2 with --quick unless given
    int repeats = 9;              // timing rounds; 5 with --quick unless given
    std::string timing = "lookup";
    int threads = 0;
    std::string bias = "constant";
    float constantBias = 0.002f;
    std::string cull = "front";
    std::string depthFormat = "32f";
    std::string weights = "box";      // pcf-naive, pcf-gather
    float sigma = 1.0f;               // gaussian weights, texels
    std::string precision = "exact";  // hardware taps and gathers
    bool force = false;
    CLI::App* sub = nullptr;  // to tell options the user gave from defaults

    bool given(const char* option) const { return sub != nullptr && sub->count(option) > 0; }
};

template <class T>
void appendUnique(std::vector<T>& list, const T& value) {
    if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}

std::vector<int> parseIntList(const std::string& option, const std::string& text) {
    std::vector<int> values;
    for (const std::string& item : splitList(option, text)) {
        char* end = nullptr;
        long v = std::strtol(item.c_str(), &end, 10);
        if (end != item.c_str() + item.size() || v < -1000000 || v > 1000000) {
            throw UsageError(option + " expects integers separated by commas, got '" + item + "'");
        }
        appendUnique(values, static_cast<int>(v));
    }
    return values;
}

// "pcf-gather-n3-map1024.png": one difference image per run.
std::string diffFileName(const BenchPoint& p) {
    std::string name(methodInfo(p.method).name);
    if (p.kernel > 0) name += "-n" + std::to_string(p.kernel);
    return name + "-map" + std::to_string(p.mapSize) + ".png";
}

int runBenchCommand(const BenchCommandOptions& o) {
    // Every check first: nothing is computed or written unless all of it can be.
    BenchOptions options = o.quick ? quickBenchOptions() : BenchOptions{};
    if (!o.methods.empty()) {
        options.methods.clear();
        for (const std::string& name : splitList("--methods", o.methods)) {
            std::optional<int> id = methodFromName(name);
            if (!id) {
                throw UsageError("unknown method '" + name +
                                 "' in --methods (known: " + methodNameList() + ")");
            }
            appendUnique(options.methods, *id);
        }
    }
    if (!o.kernels.empty()) options.kernels = parseIntList("--kernels", o.kernels);
    if (!o.mapSizes.empty()) options.mapSizes = parseIntList("--map-sizes", o.mapSizes);
    if (!o.size.empty()) options.frameSize = parseSize("--size", o.size, MAX_FRAME_SIDE);
    // At least 960x540, so a --quick chart of a 320x180 frame is still readable.
    glm::ivec2 chartSize = glm::max(options.frameSize, glm::ivec2(960, 540));
    if (!o.chartSize.empty()) chartSize = parseSize("--chart-size", o.chartSize, MAX_FRAME_SIDE);
    if (chartSize.x < 64 || chartSize.y < 64) {
        throw UsageError("--chart-size " + o.chartSize + " is too small (64x64 at least)");
    }
    int spp = o.quick && !o.given("--spp") ? QUICK_TRUTH_SPP : o.spp;
    requireIntRange("--spp", spp, 2, MAX_TRUTH_SPP);  // 1: an all-or-nothing truth, no edge band
    if (!o.quick || o.given("--repeats")) options.gpuRepeats = o.repeats;
    requireIntRange("--repeats", options.gpuRepeats, 1, 1000);
    requireIntRange("--threads", o.threads, 0, 1024);
    options.cpuThreads = o.threads;
    if (o.timing != "scene" && o.timing != "lookup") {
        throw UsageError("unknown --timing '" + o.timing + "' (known: scene, lookup)");
    }
    ChartTiming timing = o.timing == "scene" ? ChartTiming::Scene : ChartTiming::Lookup;
    std::optional<BiasMode> bias = biasModeFromName(o.bias);
    if (!bias)
        throw UsageError("unknown bias mode '" + o.bias + "' (known: " + biasNameList() + ")");
    options.base.bias = *bias;
    requireRange("--constant-bias", o.constantBias, -1.0f, 1.0f);
    options.base.constantBias = o.constantBias;
    std::optional<CullMode> cull = cullModeFromName(o.cull);
    if (!cull) throw UsageError("unknown --cull '" + o.cull + "' (known: back, front, none)");
    options.base.shadowCull = *cull;
    std::optional<DepthFormat> format = depthFormatFromName(o.depthFormat);
    if (!format) {
        throw UsageError("unknown --depth-format '" + o.depthFormat + "' (known: 16, 24, 32f)");
    }
    options.base.depthFormat = *format;
    // Issue 10: weights (pcf-naive, pcf-gather only) and the texture unit's precision model.
    std::optional<int> weights = weightsFromName(o.weights);
    if (!weights) {
        throw UsageError("unknown --weights '" + o.weights + "' (known: box, binomial, gaussian)");
    }
    std::optional<int> precision = precisionFromName(o.precision);
    if (!precision) throw UsageError("unknown --precision '" + o.precision + "' (known: exact, hw8)");
    options.base.weights = *weights;
    options.base.sigma = o.sigma;
    options.base.precision = *precision;
    if (*weights != PCF_WEIGHTS_BOX) {
        if (options.methods.empty()) options.methods = {PCF_NAIVE, PCF_GATHER};
        for (int m : options.methods) {
            PcfParams p = makeParams(m, 3);
            p.weights = *weights;
            p.sigma = o.sigma;
            if (auto why = validateParams(p)) throw UsageError(*why + " (give --methods)");
        }
    }
    if (auto why = validateBenchOptions(options)) throw UsageError(*why);
    if (!o.scene.empty() && !o.sceneFile.empty()) {
        throw UsageError("give --scene or --scene-file, not both");
    }
    RenderOptions sceneOptions;
    sceneOptions.scene = o.scene;
    sceneOptions.sceneFile = o.sceneFile;
    if (o.scene.empty() && o.sceneFile.empty()) sceneOptions.scene = DEFAULT_SCENE;
    Scene scene = sceneOptions.loadScene();

    if (o.out.empty()) throw UsageError("-o needs a directory");
    fs::path outDir(o.out);
    std::vector<BenchPoint> points = benchPoints(options);
    const std::string csvName = "bench.csv", mdName = "bench.md",
                      chartName = "speed_vs_accuracy.png";
    std::vector<std::string> finalNames = {csvName, mdName, chartName};
    for (const BenchPoint& p : points) finalNames.push_back("diff/" + diffFileName(p));
    OutputFiles outputs(o.force);
    outputs.addDirectory("-o", outDir);
    for (const std::string& name : finalNames) outputs.add("-o", outDir / name);

    auto started = std::chrono::steady_clock::now();
    auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    };
    StagingDir staging(outDir, "bench", "diff");

    double loadStart = -1.0;
    double loadEnd = -1.0;
    getloadavg(&loadStart, 1);
    std::unique_ptr<GlContext> context = createHeadlessContext();
    int threads = resolveThreadCount(o.threads);
    std::fprintf(stderr,
                 "bench: %s, %dx%d, %zu runs on %s; ground truth: %dx%d first-pass samples per "
                 "pixel, edges refined, on %d thread%s\n",
                 scene.name.c_str(), options.frameSize.x, options.frameSize.y, points.size(),
                 context->renderer().c_str(), spp, spp, threads, threads == 1 ? "" : "s");
    GroundTruthOptions truthOptions;
    truthOptions.spp = spp;
    truthOptions.threads = o.threads;
    int lastQuarter = 0;
    truthOptions.progress = [&](int done, int total) {
        int quarter = done * 4 / total;
        if (quarter > lastQuarter && quarter < 4) {
            std::fprintf(stderr, "bench: ground truth %d%%\n", quarter * 25);
            lastQuarter = quarter;
        }
    };
    GroundTruth truth = computeGroundTruth(scene, options.frameSize, truthOptions);
    std::fprintf(stderr,
                 "bench: ground truth done (%.1f s, %d pixels refined, largest bound %.5f)\n",
                 seconds(), truth.refinedPixels, truth.maxBound);
    // The chart's accuracy axis is the edge band's error: without a shadow edge in view every
    // method would score a perfect 0 and the chart would say nothing. Refuse instead.
    ErrorRegions truthRegions = errorRegions(truth);
    if (truthRegions.comparedCount == 0 || truthRegions.edgeCount == 0) {
        throw UsageError(
            "scene '" + scene.name + "' shows " +
            (truthRegions.comparedCount == 0 ? std::string("no shadow receiver")
                                             : std::string("no shadow edge")) +
            " at " + std::to_string(options.frameSize.x) + "x" +
            std::to_string(options.frameSize.y) +
            ", so there is no edge band to measure error over; bench needs a shadow edge in view");
    }

    SceneRenderer renderer(scene);
    BenchContext bench;
    bench.renderer = &renderer;
    bench.truth = &truth;
    bench.progress = [&](int index, int total, const BenchPoint& p) {
        std::fprintf(stderr, "bench: %d/%d %s map %d ...", index + 1, total, pointName(p).c_str(),
                     p.mapSize);
        std::fflush(stderr);
    };
    ErrorRegions measuredOver;
    bench.onPoint = [&](const BenchRow& row, std::span<const float> visibility,
                        const ErrorRegions& regions) {
        std::fprintf(stderr, " edge RMSE %.4f\n", row.error.edgeRmse);
        writePngRgba8((staging.path() / "diff" / diffFileName(row.point)).string(), truth.size.x,
                      truth.size.y, differenceImage(truth, regions, visibility));
        if (measuredOver.compared.empty()) measuredOver = regions;
    };
    bench.roundProgress = [&](int round, int rounds) {
        std::fprintf(stderr, "bench: timing round %d/%d (every run once, %.1f s)\n", round + 1,
                     rounds, seconds());
    };
    std::vector<BenchRow> rows = runBench(bench, options);
    getloadavg(&loadEnd, 1);

    BenchSetup setup;
    setup.sceneName = scene.name;
    setup.glRenderer = context->renderer();
    setup.glVersion = context->version();
    setup.frameSize = options.frameSize;
    setup.gpuRepeats = options.gpuRepeats;
    setup.cpuLookups = rows.empty() ? 0 : rows.front().cpuPixels;
    setup.cpuPasses = options.cpuPasses;
    setup.cpuThreads = resolveThreadCount(o.threads);
    setup.truthSpp = spp;
    setup.comparedPixels = measuredOver.comparedCount;
    setup.edgePixels = measuredOver.edgeCount;
    setup.truthMaxBound = truth.maxBound;
    setup.truthRefined = truth.refinedPixels;
    setup.loadStart = loadStart;
    setup.loadEnd = loadEnd;
    setup.cores = resolveThreadCount(0);
    setup.frontByLookup = timing == ChartTiming::Lookup;
    std::string markdown = benchMarkdown(rows, setup);
    writeTextFile((staging.path() / csvName).string(), benchCsv(rows));
    writeTextFile((staging.path() / mdName).string(), markdown);
    SpeedChartText chartText;
    chartText.title = std::string("Speed against accuracy") +
                      (o.quick ? " (--quick: timings indicative only)" : "") + ": " + scene.name +
                      ", " + std::to_string(options.frameSize.x) + "x" +
                      std::to_string(options.frameSize.y);
    std::string timer = rows.empty() ? std::string() : rows.front().timer;
    chartText.subtitle = context->renderer() + "; median of " + std::to_string(options.gpuRepeats) +
                         " round-robin samples, " + timer +
                         "; bars: IQR; ! noisy (IQR > 10 % of median)";
    chartText.xLabel = timing == ChartTiming::Lookup
                           ? "filter time: bare lookup pass, ms (log scale)"
                           : "camera pass time, ms (log scale)";
    writePngRgba8((staging.path() / chartName).string(), chartSize.x, chartSize.y,
                  drawSpeedChart(rows, chartSize, chartText, timing));
    if (benchMachineBusy(rows, setup)) {
        std::fprintf(stderr,
                     "bench: the machine was busy (load average %.2f -> %.2f on %d cores); %.0f %% "
                     "of the points are noisy\n",
                     loadStart, loadEnd, setup.cores, 100.0 * noisyShare(rows));
    }

    // All written: move into place.
    for (const std::string& name : finalNames) {
        fs::rename(staging.path() / name, outDir / name);
    }
    outputs.commit();
    std::fputs(markdown.c_str(), stdout);
    std::fprintf(stderr,
                 "bench: %zu runs in %.1f s; wrote %s/{%s, %s, %s} and %zu images in "
                 "%s/diff\n",
                 rows.size(), seconds(), o.out.c_str(), csvName.c_str(), mdName.c_str(),
                 chartName.c_str(), points.size(), o.out.c_str());
    return 0;
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
    auto o = std::make_shared<BenchCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "bench", "speed against accuracy: sweep methods x kernels x map sizes; CSV, table, chart");
    o->sub = sub;
    sub->add_option("--scene", o->scene,
                    "built-in scene (default box-on-plane): box-on-plane, sphere-over-plane, pole, "
                    "grazing, stairs");
    sub->add_option("--scene-file", o->sceneFile, "scene file (TOML)");
    sub->add_option("--methods", o->methods, "method ids, comma-separated (default: all)");
    sub->add_option("--kernels", o->kernels,
                    "N for the methods that take one, comma-separated (default 3,5,7; tent runs "
                    "only 3, 5, 7)");
    sub->add_option("--map-sizes", o->mapSizes,
                    "shadow map sizes, comma-separated (default 256,512,1024,2048)");
    sub->add_option("-o,--out", o->out, "output directory (default: bench)");
    sub->add_flag("--quick", o->quick,
                  "a few seconds, for CI: 320x180 frame, maps 128,256, N = 3, 5 timing rounds "
                  "(explicit options still win); its timings are indicative only");
    sub->add_option("--size", o->size, "frame size WxH (default 1280x720)");
    sub->add_option("--chart-size", o->chartSize,
                    "speed_vs_accuracy.png size WxH (default: the frame size, at least 960x540)");
    sub->add_option("--spp", o->spp,
                    "ground truth: K x K first-pass samples per pixel (default 2); edges are then "
                    "integrated to a 1/512 bound");
    sub->add_option("--repeats", o->repeats,
                    "timing rounds (default 9): each times every run once, round-robin; median "
                    "and IQR per run");
    sub->add_option("--timing", o->timing,
                    "the chart's time axis: lookup (default: the filter alone, a bare lookup "
                    "pass) or scene (the camera pass)");
    sub->add_option("--threads", o->threads,
                    "CPU threads for the ground truth and the CPU kernel timing (0 = all cores, "
                    "the default)");
    sub->add_option("--bias", o->bias,
                    "bias mode: " + biasNameList() + " (default constant, with its default "
                    "parameters)");
    sub->add_option("--constant-bias", o->constantBias,
                    "constant bias in light depth units (ref = z - bias; default 0.002)");
    sub->add_option("--cull", o->cull,
                    "faces culled in the shadow pass: front (the default: the map holds back "
                    "faces, which keeps acne out of the error), back, none");
    sub->add_option("--depth-format", o->depthFormat, "shadow map depth format: 16, 24, 32f");
    sub->add_option("--weights", o->weights,
                    "pcf-naive, pcf-gather: box, binomial, gaussian (default methods: those two)");
    sub->add_option("--sigma", o->sigma, "gaussian weights: standard deviation in texels");
    sub->add_option("--precision", o->precision,
                    "texel position inside hardware taps and gathers: exact, hw8");
    sub->add_flag("-f,--force", o->force, "overwrite existing output files");
    return {sub, [o] { return runBenchCommand(*o); }};
}

}  // namespace pcf
