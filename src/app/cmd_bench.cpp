// pcfscope bench: speed against accuracy. The sweep is measure/bench.h's (truth, error split,
// shimmer, round-robin timing); this file parses the options (the shared ones through
// RenderOptions), checks the outputs, reports progress and writes, into DIR:
//   bench.csv                one row per run (measure/bench_report.h has the columns)
//   bench.md                 the same as a table, with the machine and the timer
//   speed_vs_accuracy.png    GPU time (log; --timing scene or lookup) with IQR bars against
//                            edge-band RMSE, the Pareto front of the medians drawn
//   speed_vs_stability.png   the same against shimmer
//   speed_vs_contact.png     with --contact D: the same against the edge-band RMSE within D
//                            world units of a caster (the contacts, where soft shadows are sharp)
//   diff/NAME.png            each run's signed error against the ground truth
//   reference.csv            with --reference: per run the lookup pass against the method's
//                            hand-written reference pass (shaders/reference/), timed in the
//                            same rounds, and their ratio (scripts/pass-overhead prints it)
// Everything is written into a staging folder inside DIR and moved into place only once the
// whole sweep has succeeded, so a failure or an interrupt leaves no partial output behind.
// `bench --replot CSV` measures nothing: it draws the charts of an existing bench.csv into DIR
// (the titles' scene, frame, repeats, timing and contact distance from the options, as the run
// was given them), so a chart whose drawing changed can be redrawn from a quiet run.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/output_files.h"
#include "app/render_options.h"
#include "app/truth_option.h"
#include "base/input_error.h"
#include "base/memory_budget.h"
#include "base/work_estimate.h"
#include "charts/chart_axes.h"
#include "charts/speed_chart.h"
#include "charts/step_chart.h"
#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "measure/bench.h"
#include "measure/bench_report.h"
#include "measure/difference_image.h"
#include "measure/light_visibility.h"
#include "measure/stability.h"
#include "render/gl_context.h"
#include "render/image_io.h"
#include "scene/pcss.h"

namespace pcf {

namespace {

namespace fs = std::filesystem;

constexpr const char* BENCH_DEFAULT_SCENE = "box-on-plane";
constexpr const char* CSV_NAME = "bench.csv";
constexpr const char* MD_NAME = "bench.md";
constexpr const char* ACCURACY_CHART = "speed_vs_accuracy.png";
constexpr const char* STABILITY_CHART = "speed_vs_stability.png";
constexpr const char* CONTACT_CHART = "speed_vs_contact.png";
constexpr const char* REFERENCE_CSV_NAME = "reference.csv";
// RenderOptions' options for one run, which the sweep's lists replace.
constexpr const char* SINGLE_RUN_OPTIONS[] = {"--method", "--kernel", "--map-size", "--radius",
                                              "--rotate", "--lesson", "--step"};

struct BenchCommandOptions {
    // Scene, bias and its parameters, culling, polygon offset, depth format, frame size,
    // weights (here a list), sigma, precision: the options every rendering command shares.
    RenderOptions render;
    std::string methods;
    std::string kernels;
    std::string mapSizes;
    std::string out = "bench";
    bool quick = false;
    bool full = false;
    std::string chartSize;
    int spp = DEFAULT_TRUTH_SPP;
    std::string truth = "hard";  // --truth hard|area
    float contact = 0.0f;        // --contact D, world units (0: not measured)
    int repeats = 9;             // timing rounds; 5 with --quick unless given
    int shimmerFrames = 8;
    std::string timing = "lookup";
    bool reference = false;
    int threads = 0;
    bool force = false;
    std::string replot;       // --replot CSV: draw that bench.csv's charts, measure nothing
    CLI::App* sub = nullptr;  // to tell options the user gave from defaults

    bool given(const char* option) const { return sub != nullptr && sub->count(option) > 0; }
};

// What the command runs: the sweep's config and how to draw it.
struct BenchPlan {
    BenchConfig config;
    glm::ivec2 chartSize{960, 540};
    ChartTiming timing = ChartTiming::Lookup;
};

// "pcf-gather-n3-map1024.png", "pcf-gather-n3-gaussian-map1024.png": one image per run.
std::string diffFileName(const BenchPoint& p) {
    std::string name(methodInfo(p.method).name);
    if (p.kernel > 0) name += "-n" + std::to_string(p.kernel);
    if (p.weights != PCF_WEIGHTS_BOX) name += "-" + std::string(weightsName(p.weights));
    return name + "-map" + std::to_string(p.mapSize) + ".png";
}

// reference.csv: per run the lookup pass and the reference pass, medians and IQRs in ms, the
// ratio lookup / reference, and the process CPU times (0 when the GPU's own timer measured).
std::string referenceCsv(const std::vector<BenchRow>& rows) {
    std::string csv =
        "method,kernel,map_size,lookup_ms,lookup_iqr_ms,reference_ms,reference_iqr_ms,ratio,"
        "lookup_cpu_ms,reference_cpu_ms\n";
    char line[256];
    for (const BenchRow& r : rows) {
        std::snprintf(line, sizeof line, "%s,%d,%d,%.4f,%.4f,%.4f,%.4f,%.3f,%.4f,%.4f\n",
                      std::string(methodInfo(r.point.method).name).c_str(), r.point.kernel,
                      r.point.mapSize, r.lookupMs, r.lookupMsIqr, r.referenceMs, r.referenceMsIqr,
                      r.lookupMs / r.referenceMs, r.lookupCpuMs, r.referenceCpuMs);
        csv += line;
    }
    return csv;
}

std::vector<int> parseMethods(const std::string& text) {
    std::vector<int> ids;
    for (const std::string& name : splitList("--methods", text)) {
        std::optional<int> id = methodFromName(name);
        if (!id) {
            throw UsageError("unknown method '" + name +
                             "' in --methods (known: " + methodNameList() + ")");
        }
        ids.push_back(*id);
    }
    return ids;
}

std::vector<int> parseWeightsList(const std::string& text) {
    std::vector<int> ids;
    for (const std::string& name : splitList("--weights", text)) ids.push_back(weightsOption(name));
    return ids;
}

// The shared options' checks (RenderOptions::settings) for the bias, culling, polygon offset,
// depth format, frame size, sigma and precision. The single method and weights there are
// stand-ins: bench checks its lists itself.
RenderSettings baseSettings(const BenchCommandOptions& o) {
    for (const char* single : SINGLE_RUN_OPTIONS) {
        if (o.given(single)) {
            throw UsageError(std::string(single) +
                             " does not apply to bench (use --methods, --kernels, --map-sizes, "
                             "--scene)");
        }
    }
    RenderOptions stand = o.render;
    stand.shadow.name("method") = "nearest";
    stand.shadow.name("weights") = "box";
    return stand.settings();
}

// The methods the bias can combine with (kernel/bias.h): given methods must all combine; of
// the default (all) methods those that cannot are left out.
void applyBias(BenchOptions& options, const RenderSettings& base, bool methodsGiven) {
    if (!methodsGiven) {
        for (const MethodInfo& m : allMethods()) {
            if (!validateBias(static_cast<int>(base.bias), m.id)) options.methods.push_back(m.id);
        }
        return;
    }
    for (int m : options.methods) {
        if (auto why = validateBias(static_cast<int>(base.bias), m)) throw UsageError(*why);
    }
}

// The reference passes compare plainly (one ref for every tap) on a float map with box weights
// (shaders/reference/README.md): against anything else they would time less work.
void checkReference(const RenderSettings& base, const BenchOptions& options) {
    bool perTapBias = base.bias == BiasMode::ReceiverPlane || base.bias == BiasMode::Soft ||
                      base.bias == BiasMode::Interpolated;
    bool weighted = options.weights != std::vector<int>{PCF_WEIGHTS_BOX};
    if (perTapBias || weighted || base.depthFormat != TexelKind::D32F) {
        throw UsageError(
            "--reference times the methods' plain textbook passes: it needs a bias without "
            "per-tap work (none, constant, slope, normal), --weights box and --depth-format 32f");
    }
}

// The command's own defaults: every method at N = 3, 5 on a 1024 map, a run per method and N,
// so that `pcfscope bench` answers in about a minute on 2 cores (issue 23); --full (the
// library's BenchOptions) sweeps N = 3, 5, 7 over maps 256..2048, five times the runs.
constexpr int DEFAULT_KERNELS[] = {3, 5};
constexpr int DEFAULT_MAP_SIZE = 1024;

BenchOptions parseSweep(const BenchCommandOptions& o) {
    if (o.quick && o.full) throw UsageError("--quick and --full exclude each other");
    BenchOptions options = o.quick ? quickBenchOptions() : BenchOptions{};
    if (!o.quick && !o.full) {
        options.kernels.assign(std::begin(DEFAULT_KERNELS), std::end(DEFAULT_KERNELS));
        options.mapSizes = {DEFAULT_MAP_SIZE};
    }
    RenderSettings base = baseSettings(o);
    options.base = base;
    if (!o.quick || o.given("--size")) options.frameSize = base.frameSize;
    if (o.given("--methods")) options.methods = parseMethods(o.methods);
    // A named culling holds for every method; else each method's (bench.h: cullByMethod).
    options.cullByMethod = !o.given("--cull");
    if (o.given("--kernels")) options.kernels = parseIntList("--kernels", o.kernels);
    if (o.given("--map-sizes")) options.mapSizes = parseIntList("--map-sizes", o.mapSizes);
    if (o.given("--weights")) options.weights = parseWeightsList(o.render.shadow.name("weights"));
    options.sigma = base.sigma;
    bool weightedOnly = std::find(options.weights.begin(), options.weights.end(),
                                  PCF_WEIGHTS_BOX) == options.weights.end();
    if (weightedOnly && !o.given("--methods")) options.methods = {PCF_NAIVE, PCF_GATHER};
    applyBias(options, base, o.given("--methods") || weightedOnly);
    if (!o.quick || o.given("--spp")) options.truthSpp = o.spp;
    if (!o.quick || o.given("--repeats")) options.gpuRepeats = o.repeats;
    if (!o.quick || o.given("--shimmer-frames")) options.shimmerFrames = o.shimmerFrames;
    requireIntRange("--spp", options.truthSpp, 2, MAX_TRUTH_SPP);  // 1: no edge band
    requireIntRange("--repeats", options.gpuRepeats, 1, 1000);
    requireIntRange("--shimmer-frames", options.shimmerFrames, 0, SHIMMER_STEPS);
    requireIntRange("--threads", o.threads, 0, 1024);
    options.cpuThreads = o.threads;
    options.reference = o.reference;
    if (o.reference) checkReference(base, options);
    if (auto why = validateBenchOptions(options)) throw UsageError(cliWords(*why));
    return options;
}

// Measured peaks of `bench --quick`: 306 MB at 320x180, 353 MB at 960x540, so 105 bytes a
// frame pixel; issue 24's run at 8192x8192 had reached 9.8 GiB (157 a pixel) and not finished.
constexpr std::uint64_t BENCH_BYTES_PER_PIXEL = 160;

// --truth area: the truth integrates over the light's disk: a sun's, the one pcss filters for
// (scene/pcss.h effectiveLightSizeDeg: --light-size, else the scene's, else the sun's), or a
// spot's of --light-radius or the scene's radius (light_visibility.h). Either size given for the
// other kind of light is refused, whichever truth.
void applyTruth(const BenchCommandOptions& o, BenchPlan& plan) {
    plan.config.options.areaTruth =
        applyTruthOption(o.truth, plan.config.scene, plan.config.options.base);
}

// Which truth the report and the charts say they measured against.
std::string truthWords(const BenchPlan& plan) {
    return truthWordsFor(plan.config.scene, plan.config.options.areaTruth);
}

BenchPlan parsePlan(const BenchCommandOptions& o) {
    BenchPlan plan;
    plan.config.options = parseSweep(o);
    // At least 960x540, so a --quick chart of a 320x180 frame is still readable.
    plan.chartSize = glm::max(plan.config.options.frameSize, glm::ivec2(960, 540));
    if (o.given("--chart-size")) {
        plan.chartSize = parseSize("--chart-size", o.chartSize, CHART_SIZE_RANGE);
    }
    if (o.timing != "scene" && o.timing != "lookup") {
        throw UsageError("unknown --timing '" + o.timing + "' (known: scene, lookup)");
    }
    plan.timing = o.timing == "scene" ? ChartTiming::Scene : ChartTiming::Lookup;
    plan.config.scene = o.render.loadScene();
    applyTruth(o, plan);
    if (!(o.contact >= 0.0f && o.contact <= 1e6f)) {
        throw UsageError("--contact must be a distance in world units, 0 or more");
    }
    plan.config.options.contactDistance = o.contact;
    return plan;
}

// The files the bench writes, relative to -o, checked (and the folders made) before any work;
// none may be the scene file it reads, --force or not.
std::vector<std::string> checkOutputs(const BenchCommandOptions& o, const BenchPlan& plan,
                                      OutputFiles& outputs) {
    if (o.out.empty()) throw UsageError("-o needs a directory");
    std::vector<std::string> names = {CSV_NAME, MD_NAME, ACCURACY_CHART, STABILITY_CHART};
    if (plan.config.options.contactDistance > 0.0f) names.push_back(CONTACT_CHART);
    if (o.reference) names.push_back(REFERENCE_CSV_NAME);
    for (const BenchPoint& p : benchPoints(plan.config.options)) {
        names.push_back("diff/" + diffFileName(p));
    }
    outputs.addInput("--scene-file", o.render.sceneFile);
    outputs.addFilesIn("-o", o.out, names);
    return names;
}

class Stopwatch {
  public:
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
    }

  private:
    std::chrono::steady_clock::time_point mStart = std::chrono::steady_clock::now();
};

// Progress on stderr, and each run's difference image into the staging folder. Says nothing
// before the truth has passed its checks, so a refusal is the only line on stderr.
class BenchReporter {
  public:
    BenchReporter(const BenchPlan& plan, const GlContext& gl, fs::path staging)
        : mPlan(plan), mGl(gl), mStaging(std::move(staging)) {}

    const Stopwatch& clock() const { return mClock; }

    void truthDone(const GroundTruth& truth) {
        mTruth = &truth;
        const BenchOptions& o = mPlan.config.options;
        int threads = resolveThreadCount(o.cpuThreads);
        std::fprintf(stderr,
                     "bench: %s, %dx%d, %zu runs on %s; ground truth %s: %dx%d first-pass "
                     "samples per pixel, edges refined, on %d thread%s\n",
                     mPlan.config.scene.name.c_str(), o.frameSize.x, o.frameSize.y,
                     benchPoints(o).size(), mGl.renderer().c_str(), truthWords(mPlan).c_str(),
                     o.truthSpp, o.truthSpp, threads, threads == 1 ? "" : "s");
        std::fprintf(stderr,
                     "bench: ground truth done (%.1f s, %d pixels refined, largest bound %.5f)\n",
                     mClock.seconds(), truth.refinedPixels, truth.maxBound);
    }

    BenchContext callbacks() {
        BenchContext c;
        c.progress = [](int index, int total, const BenchPoint& p) {
            std::fprintf(stderr, "bench: %d/%d %s map %d ...", index + 1, total,
                         pointName(p).c_str(), p.mapSize);
            std::fflush(stderr);
        };
        c.onPoint = [this](const BenchRow& row, std::span<const float> visibility,
                           const ErrorRegions& regions) {
            std::fprintf(stderr, " edge RMSE %.4f, acne %.2f %%, leak %.2f %%, shimmer p99 %.3f\n",
                         row.error.edgeRmse, 100.0 * row.acne.share, 100.0 * row.leak.share,
                         row.shimmer.flickerP99);
            writePngRgba8((mStaging / "diff" / diffFileName(row.point)).string(), mTruth->size.x,
                          mTruth->size.y, differenceImage(*mTruth, regions, visibility));
        };
        c.roundProgress = [this](int round, int rounds) {
            std::fprintf(stderr, "bench: timing round %d/%d (every run once, %.1f s)\n", round + 1,
                         rounds, mClock.seconds());
        };
        return c;
    }

  private:
    const BenchPlan& mPlan;
    const GlContext& mGl;
    fs::path mStaging;
    Stopwatch mClock;
    const GroundTruth* mTruth = nullptr;
};

BenchSetup setupOf(const BenchPlan& plan, const BenchResult& result, const GlContext& gl,
                   double loadStart, double loadEnd) {
    const BenchOptions& o = plan.config.options;
    BenchSetup setup;
    setup.sceneName = plan.config.scene.name;
    setup.glRenderer = gl.renderer();
    setup.glVersion = gl.version();
    setup.frameSize = o.frameSize;
    setup.gpuRepeats = o.gpuRepeats;
    setup.cpuLookups = result.rows.empty() ? 0 : result.rows.front().cpuPixels;
    setup.cpuPasses = o.cpuPasses;
    setup.cpuThreads = resolveThreadCount(o.cpuThreads);
    setup.truthSpp = o.truthSpp;
    setup.truthLight = truthWords(plan);
    setup.comparedPixels = result.regions.comparedCount;
    setup.edgePixels = result.regions.edgeCount;
    setup.truthMaxBound = result.truth.maxBound;
    setup.truthRefined = result.truth.refinedPixels;
    setup.loadStart = loadStart;
    setup.loadEnd = loadEnd;
    setup.cores = resolveThreadCount(0);
    setup.shimmerFrames = o.shimmerFrames;
    setup.frontByLookup = plan.timing == ChartTiming::Lookup;
    return setup;
}

// The two charts into the staging folder: time against edge RMSE, and against shimmer (and
// with --contact, against the edge RMSE near the casters).
void writeCharts(const BenchPlan& plan, const std::vector<BenchRow>& rows, bool quick,
                 const fs::path& staging) {
    const BenchOptions& o = plan.config.options;
    std::string where = plan.config.scene.name + ", " + std::to_string(o.frameSize.x) + "x" +
                        std::to_string(o.frameSize.y) +
                        (o.areaTruth ? ", truth: " + truthWords(plan) : std::string());
    std::string indicative = quick ? " (--quick: timings indicative only)" : "";
    std::string timer = rows.empty() ? std::string() : rows.front().timer;
    SpeedChartText text;
    text.minFontPx = STANDALONE_CHART_MIN_PX;
    text.subtitle = chartRendererLine(speedChartRenderer(rows)) + "\nmedian of " +
                    std::to_string(o.gpuRepeats) + " round-robin samples (" +
                    std::to_string(2 * o.gpuRepeats) + " where the first were noisy), " + timer;
    text.xLabel = speedChartXLabel(rows, plan.timing);
    text.title = "Speed against accuracy" + indicative + ": " + where;
    text.yLabel = "aliasing: edge-band RMSE of visibility";
    writePngRgba8((staging / ACCURACY_CHART).string(), plan.chartSize.x, plan.chartSize.y,
                  drawSpeedChart(rows, plan.chartSize, text, plan.timing));
    text.title = "Speed against stability" + indicative + ": " + where;
    text.yLabel =
        "shimmer: 99th percentile of a flickering pixel's change per 1/32-texel "
        "slide of the map (" +
        std::to_string(o.shimmerFrames) + " frames)";
    writePngRgba8((staging / STABILITY_CHART).string(), plan.chartSize.x, plan.chartSize.y,
                  drawSpeedChart(rows, plan.chartSize, text, plan.timing, ChartAccuracy::Shimmer));
    if (plan.config.options.contactDistance > 0.0f) {
        text.title = "Speed against accuracy near the contacts" + indicative + ": " + where;
        text.yLabel = contactAxisLabel(rows);
        writePngRgba8(
            (staging / CONTACT_CHART).string(), plan.chartSize.x, plan.chartSize.y,
            drawSpeedChart(rows, plan.chartSize, text, plan.timing, ChartAccuracy::ContactRmse));
    }
}

// The options that choose or tune what is measured and that no chart title names: --replot
// measures nothing, so they would be silently ignored there.
constexpr const char* MEASURING_OPTIONS[] = {"--methods", "--kernels", "--map-sizes",
                                             "--weights", "--quick",   "--full",
                                             "--spp",     "--threads", "--reference"};

// bench --replot CSV: the charts of an existing bench.csv, into -o, nothing measured. The CSV is
// read with every input check (one line naming the file and the problem); the charts are staged
// and moved into place together, as a run's are.
int runReplot(const BenchCommandOptions& o) {
    for (const char* option : MEASURING_OPTIONS) {
        if (o.given(option)) {
            throw UsageError(std::string(option) +
                             " does not apply to --replot, which draws an existing bench.csv "
                             "and measures nothing");
        }
    }
    BenchPlan plan = parsePlan(o);
    std::vector<BenchRow> rows = readChartRows(o.replot);
    if (rows.empty()) throw InputError(o.replot, 0, "no rows to chart");
    bool contact = plan.config.options.contactDistance > 0.0f;
    if (contact && rows.front().contact.edgePixels <= 0) {
        throw UsageError("--contact: " + o.replot +
                         " has no contact columns measured (its run had no --contact)");
    }
    if (o.out.empty()) throw UsageError("-o needs a directory");
    std::vector<std::string> names = {ACCURACY_CHART, STABILITY_CHART};
    if (contact) names.push_back(CONTACT_CHART);
    OutputFiles outputs(o.force);
    outputs.addInput("--replot", o.replot);
    outputs.addFilesIn("-o", o.out, names);
    StagingDir staging(o.out, "bench");
    std::unique_ptr<GlContext> gl = createHeadlessContext();
    writeCharts(plan, rows, false, staging.path());
    outputs.commitStaged(staging.path(), o.out, names);
    std::fprintf(stderr, "bench: drew %zu rows of %s into %s/{%s}\n", rows.size(), o.replot.c_str(),
                 o.out.c_str(),
                 contact ? "speed_vs_accuracy.png, speed_vs_stability.png, speed_vs_contact.png"
                         : "speed_vs_accuracy.png, speed_vs_stability.png");
    return 0;
}

// The sweep's work: each run renders its timing rounds of both passes (and the reference pass's),
// its shimmer frames and a few more (the error, the clean masks' frames), over one ground truth.
WorkEstimate benchEstimate(const BenchOptions& b) {
    double pixels = static_cast<double>(b.frameSize.x) * b.frameSize.y;
    double perRun = b.gpuRepeats * (b.reference ? 3.0 : 2.0) + std::max(b.shimmerFrames, 0) + 4.0;
    double runs = static_cast<double>(benchPoints(b).size());
    WorkEstimate w;
    w.what = std::to_string(static_cast<long>(runs)) + " runs at " + std::to_string(b.frameSize.x) +
             "x" + std::to_string(b.frameSize.y);
    w.frameNs = pixels * runs * perRun * RENDER_NS_PER_PIXEL_FRAME;
    w.truthNs = pixels * TRUTH_NS_PER_PIXEL;
    w.fixedSeconds = 10.0;  // the methods' shaders compiled
    w.bytes = memoryEstimate(256 * MIB, BENCH_BYTES_PER_PIXEL, b.frameSize.x, b.frameSize.y);
    return w;
}

int runBenchCommand(const BenchCommandOptions& o) {
    if (o.given("--replot")) return runReplot(o);
    // Every check first: nothing is computed or written unless all of it can be.
    BenchPlan plan = parsePlan(o);
    announceWork("bench", benchEstimate(plan.config.options), o.force);
    OutputFiles outputs(o.force);
    std::vector<std::string> names = checkOutputs(o, plan, outputs);
    StagingDir staging(o.out, "bench", "diff");
    double loadStart = -1.0, loadEnd = -1.0;
    getloadavg(&loadStart, 1);
    std::unique_ptr<GlContext> gl = createHeadlessContext();
    BenchReporter reporter(plan, *gl, staging.path());
    BenchResult result;
    try {
        result = runBenchSweep(plan.config, reporter.callbacks(),
                               [&](const GroundTruth& t) { reporter.truthDone(t); });
    } catch (const BenchSceneError& e) {
        throw UsageError(e.what());
    }
    getloadavg(&loadEnd, 1);
    // Every row names the renderer it was timed on (bench.csv's gl_renderer, the charts' subtitle)
    // and the truth it was measured against (bench.csv's truth: a lesson's chart says it).
    for (BenchRow& row : result.rows) {
        row.glRenderer = gl->renderer();
        row.truth = truthWords(plan);
    }
    BenchSetup setup = setupOf(plan, result, *gl, loadStart, loadEnd);
    std::string markdown = benchMarkdown(result.rows, setup);
    writeTextFile((staging.path() / CSV_NAME).string(), benchCsv(result.rows));
    writeTextFile((staging.path() / MD_NAME).string(), markdown);
    writeCharts(plan, result.rows, o.quick, staging.path());
    if (o.reference) {
        writeTextFile((staging.path() / REFERENCE_CSV_NAME).string(), referenceCsv(result.rows));
    }
    if (benchTimingNote(result.rows, setup)) {
        std::fprintf(
            stderr,
            "bench: %s%.0f %% of the points are noisy (load average %.2f -> %.2f on %d cores)\n",
            benchMachineBusy(setup) ? "the machine was busy when the bench began; " : "",
            100.0 * noisyShare(result.rows), loadStart, loadEnd, setup.cores);
    }
    outputs.commitStaged(staging.path(), o.out, names);
    std::fputs(markdown.c_str(), stdout);
    std::string charts = std::string(ACCURACY_CHART) + ", " + STABILITY_CHART;
    if (plan.config.options.contactDistance > 0.0f) charts += ", " + std::string(CONTACT_CHART);
    std::fprintf(stderr,
                 "bench: %zu runs in %.1f s; wrote %s/{%s, %s, %s} and %zu images in %s/diff\n",
                 result.rows.size(), reporter.clock().seconds(), o.out.c_str(), CSV_NAME, MD_NAME,
                 charts.c_str(), result.rows.size(), o.out.c_str());
    return 0;
}

// What bench sweeps: the methods, kernels and map sizes, and the two presets of them.
void addBenchSweepOptions(CLI::App* sub, BenchCommandOptions& o) {
    sub->add_option("--methods", o.methods,
                    "method ids, comma-separated (default: all that combine with --bias)");
    sub->add_option("--kernels", o.kernels,
                    "N for the methods that take one, comma-separated (default 3,5; --full "
                    "3,5,7; tent runs only " +
                        kernelSizesText(PCF_TENT) + ")");
    sub->add_option("--map-sizes", o.mapSizes,
                    "shadow map sizes, comma-separated (default 1024; --full 256,512,1024,2048)");
    sub->add_option("-o,--out", o.out, "output directory (default: bench)");
    sub->add_flag("--quick", o.quick,
                  "a few seconds, for CI: 320x180 frame, maps 128,256, N = 3, 5 timing rounds, "
                  "4 shimmer frames (explicit options still win); its timings are indicative "
                  "only");
    sub->add_flag("--full", o.full,
                  "the whole sweep: N = 3,5,7 and maps 256,512,1024,2048, five times the default's "
                  "runs (explicit options still win)");
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
    auto o = std::make_shared<BenchCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "bench",
        "speed against accuracy and stability: sweep methods x kernels x weights x map sizes; "
        "CSV, table, charts");
    o->sub = sub;
    // The map holds back faces by default (front faces culled): shadow acne, a bias problem,
    // stays off the lit faces, so the edge error measures the filter (measure/bench.h).
    o->render.defaults.cull = CullMode::Front;
    o->render.addTo(sub, BENCH_DEFAULT_SCENE);
    // The single-run options bench refuses (baseSettings) stay out of its help.
    for (const char* single : SINGLE_RUN_OPTIONS) sub->get_option(single)->group("");
    sub->get_option("--weights")
        ->description(
            "pcf-naive, pcf-gather: weightings of the N x N lookups, comma-separated: box, "
            "binomial, gaussian (default box; each given is a run)");
    sub->get_option("--cull")->description(
        "faces culled in the shadow pass, for every method: front, back, none (default: front, "
        "and back for the moment methods, whose bound wants the casters' lit faces)");
    addBenchSweepOptions(sub, *o);
    sub->add_option("--chart-size", o->chartSize,
                    sizeHelp("size of the two charts", CHART_SIZE_RANGE,
                             "default: the frame size, at least 960x540"));
    sub->add_option("--spp", o->spp,
                    "ground truth: K x K first-pass samples per pixel (2..64, default 2); edges "
                    "are then integrated to a 1/512 bound");
    sub->add_option("--truth", o->truth,
                    "hard: the truth of the light's centre (default); area: integrated over the "
                    "light's disk (a sun's: --light-size, else the scene's angular_diameter, else "
                    "the sun's 0.53 degrees; a spot's: the scene's radius), the truth soft "
                    "shadows and pcss are measured against");
    sub->add_option("--contact", o->contact,
                    "D: also the edge-band RMSE within D world units of a caster (bench.csv's "
                    "contact_edge_rmse) and its chart, speed_vs_contact.png: where a soft "
                    "shadow is sharp (default 0: not measured)");
    sub->add_option("--repeats", o->repeats,
                    "timing rounds (default 9): each times every run once, round-robin; median "
                    "and IQR per run");
    sub->add_option("--shimmer-frames", o->shimmerFrames,
                    "frames of the map's grid slid 1/32 texel apart, per run (default 8; --quick "
                    "4; 0 or 1: no shimmer)");
    sub->add_option("--timing", o->timing,
                    "the charts' time axis: lookup (default: the filter alone, a bare lookup "
                    "pass) or scene (the camera pass)");
    sub->add_flag("--reference", o->reference,
                  "also time each run's hand-written reference pass (shaders/reference/) in the "
                  "same rounds, right after its lookup pass; writes reference.csv");
    sub->add_option("--threads", o->threads,
                    "CPU threads for the ground truth, the clean masks and the CPU kernel "
                    "timing (0 = all cores, the default)");
    sub->add_option("--replot", o->replot,
                    "CSV: measure nothing, draw the charts of this bench.csv into -o (give the "
                    "run's --scene, --size, --repeats, --timing and --contact: the titles say "
                    "them)");
    sub->add_flag("-f,--force", o->force,
                  "overwrite existing output files; start work larger than the memory estimate "
                  "says the machine holds");
    return {sub, [o] { return runBenchCommand(*o); }};
}

}  // namespace pcf
