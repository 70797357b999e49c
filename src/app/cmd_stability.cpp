// pcfscope stability: where methods fail (measure/stability.h). Runs the sweeps (acne, leak,
// tradeoff, shimmer, precision, aliasing) for a list of methods and bias modes and writes, into
// DIR:
//   stability.csv          one row per measured point: sweep,method,kernel,bias,x_name,x,metric,y
//   stability.md           per method and bias: acne onset, leak width, shimmer
//   stability_acne.png     false-shadow rate against the light's elevation, a line per bias
//   stability_leak.png     leak width against the constant bias, a line per bias
//   stability_tradeoff.png acne at one elevation and leak against the constant bias
//   stability_shimmer.png  shimmer at the shadow edges per method and bias
//   stability_precision.png false-shadow rate against the light's depth range, per format
//   aliasing_heatmap.png   screen pixels per shadow-map texel over the frame, with its scale
//   stability_bleed.csv    the bleed sweep's points, one line each (stability_bleed.h: bleedCsv)
//   stability_bleed.png    leak against penumbra darkening on stacked-cards
//   stability_cascades.csv the cascades sweep's points, one line per cascade (cascadeCsv)
//   stability_cascades.png texels per pixel of each cascade against the split's lambda
// (a chart only when its sweep ran). `stability --replot CSV -o DIR` measures nothing: it draws
// the charts of an existing stability.csv into DIR (at --chart-size), every chart whose sweep has
// rows, all but the heat map (an image, not in the CSV). As `bench` does, everything is written
// into a staging folder inside DIR and moved into place once the whole run has succeeded.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/output_files.h"
#include "app/render_options.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/memory_budget.h"
#include "base/work_estimate.h"
#include "charts/chart_axes.h"
#include "charts/stability_figures.h"
#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "measure/ground_truth.h"
#include "measure/stability.h"
#include "measure/stability_bleed.h"
#include "measure/stability_cascades.h"
#include "measure/stability_report.h"
#include "render/gl_context.h"
#include "render/image_io.h"

namespace pcf {

namespace {

namespace fs = std::filesystem;

constexpr const char* STABILITY_DEFAULT_SCENE = "box-on-plane";

struct StabilityCommandOptions {
    RenderOptions render;  // scene, bias parameters, culling, polygon offset, map, format, size
    std::string methods;
    std::string kernels;
    std::string biases;
    std::string sweeps;
    std::string out = "stability";
    std::string chartSize = "1280x720";
    bool quick = false;
    int spp = 2;
    int threads = 0;
    std::string pixel;
    std::string replot;  // --replot CSV: draw that stability.csv's charts, measure nothing
    bool force = false;
    CLI::App* sub = nullptr;

    bool given(const char* option) const { return sub != nullptr && sub->count(option) > 0; }
};

bool has(const std::vector<Sweep>& sweeps, Sweep s) {
    return std::find(sweeps.begin(), sweeps.end(), s) != sweeps.end();
}

// --methods with --kernels: each method that takes a kernel once per size it can take.
std::vector<StabilityMethod> parseMethods(const std::vector<std::string>& names,
                                          const std::vector<int>& kernels) {
    std::vector<StabilityMethod> methods;
    for (const std::string& name : names) {
        std::optional<int> id = methodFromName(name);
        if (!id) {
            throw UsageError("unknown method '" + name +
                             "' in --methods (known: " + methodNameList() + ")");
        }
        if (!methodInfo(*id).usesKernel) {
            methods.push_back({*id, 0});
            continue;
        }
        bool any = false;
        for (int n : kernels) {
            if (!methodInfo(*id).kernelSizes.empty() && !kernelFits(*id, n)) continue;
            methods.push_back({*id, n});
            any = true;
        }
        if (!any) {
            throw UsageError(name + " takes --kernels " + kernelSizesText(*id) +
                             " and none was given");
        }
    }
    return methods;
}

std::vector<BiasMode> parseBiases(const std::string& text) {
    std::vector<BiasMode> biases;
    for (const std::string& name : splitList("--biases", text)) {
        std::optional<BiasMode> b = biasModeFromName(name);
        if (!b) {
            throw UsageError("unknown bias mode '" + name +
                             "' in --biases (known: " + biasNameList() + ")");
        }
        biases.push_back(*b);
    }
    return biases;
}

std::vector<Sweep> parseSweeps(const std::string& text) {
    std::vector<Sweep> sweeps;
    for (const std::string& name : splitList("--sweep", text)) {
        std::optional<Sweep> s = sweepFromName(name);
        if (!s) {
            throw UsageError("unknown sweep '" + name + "' in --sweep (known: " + sweepNameList() +
                             ")");
        }
        sweeps.push_back(*s);
    }
    return sweeps;
}

// The shared render options that name one lookup; stability sweeps lists of them instead.
constexpr const char* SINGLE_LOOKUP_OPTIONS[] = {"--method", "--kernel", "--bias", "--lesson",
                                                 "--step"};

StabilityOptions parseOptions(const StabilityCommandOptions& o) {
    StabilityOptions options = o.quick ? quickStabilityOptions() : StabilityOptions{};
    for (const char* single : SINGLE_LOOKUP_OPTIONS) {
        if (o.given(single)) {
            throw UsageError(std::string(single) +
                             " does not apply to stability (use --methods, --kernels, --biases, "
                             "--scene)");
        }
    }
    // Base settings: the shared options' checks (bias parameters, culling, map, format, size).
    RenderSettings base = o.render.settings();
    options.base = base;
    if (!o.quick || o.given("--size")) options.frameSize = base.frameSize;
    if (!o.quick || o.given("--map-size")) options.mapSize = base.mapSize;
    std::vector<int> kernels = {o.quick ? 3 : 5};
    if (o.given("--kernels")) {
        kernels = parseIntList("--kernels", o.kernels);
        for (int n : kernels) requireIntRange("--kernels", n, MIN_KERNEL, MAX_KERNEL);
    }
    if (o.given("--methods") || o.given("--kernels")) {
        std::vector<std::string> names;
        if (!o.given("--methods")) {
            for (const StabilityMethod& m : options.methods) {
                std::string n(methodInfo(m.method).name);
                if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
            }
        } else {
            names = splitList("--methods", o.methods);
        }
        options.methods = parseMethods(names, kernels);
    }
    // The aliasing sweep draws its heat map at the map size the other sweeps use, so that size
    // is always among the sizes it measures (else the heat map promised in -o never came).
    std::vector<int>& sizes = options.aliasingMapSizes;
    if (std::find(sizes.begin(), sizes.end(), options.mapSize) == sizes.end()) {
        sizes.insert(std::upper_bound(sizes.begin(), sizes.end(), options.mapSize),
                     options.mapSize);
    }
    if (o.given("--biases")) options.biases = parseBiases(o.biases);
    if (o.given("--sweep")) options.sweeps = parseSweeps(o.sweeps);
    if (o.quick && !o.given("--spp")) {
        options.truthSpp = 1;
    } else {
        requireIntRange("--spp", o.spp, 1, MAX_TRUTH_SPP);
        options.truthSpp = o.spp;
    }
    requireIntRange("--threads", o.threads, 0, 1024);
    options.threads = o.threads;
    if (o.given("--pixel")) {
        glm::ivec2 p = parseIvec2("--pixel", o.pixel);
        requireIntRange("--pixel x", p.x, 0, options.frameSize.x - 1);
        requireIntRange("--pixel y", p.y, 0, options.frameSize.y - 1);
        options.pinnedPixel = p;
    }
    if (auto why = validateStabilityOptions(options)) throw UsageError(cliWords(*why));
    return options;
}

std::string settingsLine(const StabilityOptions& o) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", o.base.constantBias);
    std::string s = std::string("constant bias ") + buf + ", cull " +
                    std::string(cullModeName(o.base.cull)) + " faces in the shadow pass";
    if (o.base.polygonOffset != glm::vec2(0.0f)) {
        std::snprintf(buf, sizeof buf, "%g, %g", o.base.polygonOffset.x, o.base.polygonOffset.y);
        s += std::string(", polygon offset ") + buf;
    }
    s += ", depth " + std::string(depthFormatName(o.base.depthFormat));
    return s;
}

// What the command writes into -o: the CSV, the Markdown, and each chart its sweeps draw.
// The charts of `sweeps`, the files writeCharts writes them to.
std::vector<std::string> chartNames(const std::vector<Sweep>& sweeps) {
    std::vector<std::string> names;
    for (const SweepChart& c : sweepCharts()) {
        if (has(sweeps, c.sweep)) names.emplace_back(c.file);
    }
    return names;
}

std::vector<std::string> outputNames(const std::vector<Sweep>& sweeps) {
    std::vector<std::string> names = {"stability.csv", "stability.md"};
    for (const std::string& chart : chartNames(sweeps)) names.push_back(chart);
    if (has(sweeps, Sweep::Aliasing)) names.push_back("aliasing_heatmap.png");
    if (has(sweeps, Sweep::Bleed)) names.emplace_back(BLEED_CSV_NAME);
    if (has(sweeps, Sweep::Cascades)) names.emplace_back(CASCADE_CSV_NAME);
    return names;
}

// The sweeps' charts and the images (a run's heat map; none for --replot), into dir. Each chart's
// subtitle states the settings the rows carry (their setup rows); stand-alone charts keep every
// text at STANDALONE_CHART_MIN_PX or more.
void writeCharts(const fs::path& dir, const std::vector<StabilityRow>& rows,
                 std::span<const StabilityImage> images, const std::vector<Sweep>& sweeps,
                 glm::ivec2 chartSize) {
    const std::string source = "pcfscope stability";
    const float minPx = STANDALONE_CHART_MIN_PX;
    auto chart = [&](const std::string& name, const std::vector<uint8_t>& rgba) {
        if (rgba.empty()) throw std::runtime_error("no rows for " + name);
        writePngRgba8((dir / name).string(), chartSize.x, chartSize.y, rgba);
    };
    for (const SweepChart& c : sweepCharts()) {
        if (has(sweeps, c.sweep))
            chart(std::string(c.file), c.draw(rows, chartSize, source, minPx));
    }
    // The heat map with its colour scale and map size, at the charts' size.
    for (const StabilityImage& image : images) {
        chart(image.name,
              drawImageChart(aliasingHeatmapSpec(image, rows, source, minPx), chartSize));
    }
}

// The CSV files of the sweeps that lay their points out one line each (bleed, cascades), into
// dir, for the sweeps run.
void writeSweepCsvs(const fs::path& dir, const std::vector<StabilityRow>& rows,
                    const StabilityOptions& options) {
    if (has(options.sweeps, Sweep::Bleed)) {
        writeTextFile((dir / BLEED_CSV_NAME).string(), bleedCsv(rows, options.base));
    }
    if (has(options.sweeps, Sweep::Cascades)) {
        writeTextFile((dir / CASCADE_CSV_NAME).string(), cascadeCsv(rows));
    }
}

// The command's checks, in order: its options, the chart size, the scene, -o.
struct CheckedStability {
    StabilityOptions options;
    glm::ivec2 chartSize;
    Scene scene;
};

// The sweeps' work, counted from their options: each point's frames (method x bias x the swept
// value) and the ground truths under them (an area truth, pcss's, at AREA_TRUTH_FACTOR a hard
// one's cost). An estimate to say before a long run, not a measurement.
WorkEstimate stabilityEstimate(const StabilityOptions& s) {
    constexpr double AREA_TRUTH_FACTOR = 20.0;
    double m = static_cast<double>(s.methods.size()), b = static_cast<double>(s.biases.size());
    double frames = 0.0, truths = 0.0;
    auto n = [](const auto& list) { return static_cast<double>(list.size()); };
    for (Sweep sweep : s.sweeps) {
        switch (sweep) {
            case Sweep::Acne:
            case Sweep::Tradeoff:
                frames += n(s.elevations) * m * b;
                truths += n(s.elevations);
                break;
            case Sweep::Leak:
                frames += n(s.leakScenes) * n(s.leakBiases) * m;
                truths += n(s.leakScenes);
                break;
            case Sweep::Shimmer:
                frames += (2.0 * s.shimmerFrames + s.cameraFrames) * m * b;
                truths += 1.0;
                break;
            case Sweep::Precision:
                frames += n(s.depthRanges) * n(s.depthFormats) * m;
                truths += 1.0;
                break;
            case Sweep::Aliasing:
                frames += n(s.aliasingMapSizes);
                break;
            case Sweep::PcssThin:
            case Sweep::PcssOverlap:
            case Sweep::PcssNoise:
            case Sweep::PcssBias:
                frames += 4.0 * (n(s.pcssPoleWidths) + n(s.pcssRadii));
                truths += AREA_TRUTH_FACTOR * 4.0;
                break;
            case Sweep::Bleed:
                frames += n(s.bleedGaps) * (m + 1.0);
                truths += AREA_TRUTH_FACTOR * n(s.bleedGaps);
                break;
            case Sweep::Cascades:  // a frame and a path of depth passes per lambda, fit, snap
                frames += 4.0 * n(s.cascadeLambdas) * (1.0 + 0.25 * s.cascadePathSteps);
                break;
        }
    }
    double pixels = static_cast<double>(s.frameSize.x) * s.frameSize.y;
    WorkEstimate w;
    w.what = std::to_string(s.sweeps.size()) + " sweeps at " + std::to_string(s.frameSize.x) + "x" +
             std::to_string(s.frameSize.y);
    w.frameNs = frames * pixels * RENDER_NS_PER_PIXEL_FRAME;
    w.truthNs = truths * pixels * TRUTH_NS_PER_PIXEL;
    w.fixedSeconds = 10.0;  // the methods' shaders compiled
    // Measured peaks of `stability --quick`: 245 MB at 320x180, 432 MB at 960x540, so 414 bytes
    // a frame pixel (truth, error regions and a frame's targets for each sweep point at once).
    w.bytes = memoryEstimate(256 * MIB, 420, s.frameSize.x, s.frameSize.y);
    return w;
}

CheckedStability checkStabilityCommand(const StabilityCommandOptions& o) {
    CheckedStability c{parseOptions(o), {}, {}};
    // --quick draws its charts at half size unless told otherwise.
    std::string chartText = o.quick && !o.given("--chart-size") ? "640x360" : o.chartSize;
    c.chartSize = parseSize("--chart-size", chartText, CHART_SIZE_RANGE);
    c.scene = o.render.loadScene();
    if (o.out.empty()) throw UsageError("-o needs a directory");
    announceWork("stability", stabilityEstimate(c.options), o.force);
    return c;
}

// The options --replot takes: the others choose or tune what is measured, and would be silently
// ignored by a run that measures nothing.
constexpr const char* REPLOT_OPTIONS[] = {"--replot", "--out", "--chart-size", "--force", "--help"};

// The sweeps --replot draws from `rows`: each charted sweep with rows.
std::vector<Sweep> chartedSweeps(const std::vector<StabilityRow>& rows) {
    std::vector<Sweep> sweeps;
    for (const SweepChart& c : sweepCharts()) {
        bool any = std::any_of(rows.begin(), rows.end(), [&](const StabilityRow& r) {
            return r.sweep == sweepName(c.sweep);
        });
        if (any) sweeps.push_back(c.sweep);
    }
    return sweeps;
}

struct CheckedReplot {
    glm::ivec2 chartSize;
    std::vector<StabilityRow> rows;
    std::vector<Sweep> sweeps;  // the charts it draws
};

// --replot's checks, in order: no measuring option, the chart size, the CSV (every input check:
// one line naming the file and the problem), -o.
CheckedReplot checkReplot(const StabilityCommandOptions& o) {
    for (const CLI::Option* option : o.sub->get_options()) {
        if (option->count() == 0) continue;
        std::string name = option->get_name();
        bool allowed = std::any_of(std::begin(REPLOT_OPTIONS), std::end(REPLOT_OPTIONS),
                                   [&](const char* n) { return option->check_name(n); });
        if (!allowed) {
            throw UsageError(name +
                             " does not apply to --replot, which draws an existing stability.csv "
                             "and measures nothing");
        }
    }
    CheckedReplot c;
    c.chartSize = parseSize("--chart-size", o.chartSize, CHART_SIZE_RANGE);
    c.rows = parseStabilityCsv(readInputFile(o.replot), o.replot);
    c.sweeps = chartedSweeps(c.rows);
    if (c.sweeps.empty()) throw InputError(o.replot, 0, "no sweep rows to chart");
    // A sweep whose rows name metrics its chart does not read would draw an empty chart.
    for (Sweep sweep : c.sweeps) {
        for (const SweepChart& chart : sweepCharts()) {
            if (chart.sweep != sweep || chart.hasData(c.rows)) continue;
            throw InputError(o.replot, 0,
                             "the " + std::string(sweepName(sweep)) +
                                 " rows hold no metric its "
                                 "chart draws (" +
                                 std::string(chart.file) + " would be empty)");
        }
    }
    if (o.out.empty()) throw UsageError("-o needs a directory");
    return c;
}

// stability --replot CSV: the charts of an existing stability.csv, into -o, nothing measured;
// staged and moved into place together, as a run's are.
int runReplot(const StabilityCommandOptions& o) {
    auto [chartSize, rows, sweeps] = checkReplot(o);
    std::vector<std::string> names = chartNames(sweeps);
    OutputFiles outputs(o.force);
    outputs.addInput("--replot", o.replot);
    outputs.addFilesIn("-o", o.out, names);
    StagingDir staging(o.out, "stability");
    std::unique_ptr<GlContext> context = createHeadlessContext();
    writeCharts(staging.path(), rows, {}, sweeps, chartSize);
    outputs.commitStaged(staging.path(), o.out, names);
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    std::fprintf(stderr, "stability: drew %s's charts into %s/{%s} (the heat map needs a run)\n",
                 o.replot.c_str(), o.out.c_str(), list.c_str());
    return 0;
}

int runStabilityCommand(const StabilityCommandOptions& o) {
    if (o.given("--replot")) return runReplot(o);
    // Every check first: nothing is computed or written unless all of it can be.
    CheckedStability checked = checkStabilityCommand(o);
    const StabilityOptions& options = checked.options;
    glm::ivec2 chartSize = checked.chartSize;
    const Scene& scene = checked.scene;
    fs::path outDir(o.out);
    const std::string csvName = "stability.csv", mdName = "stability.md";
    std::vector<std::string> finalNames = outputNames(options.sweeps);
    OutputFiles outputs(o.force);
    outputs.addFilesIn("-o", outDir, finalNames);

    auto started = std::chrono::steady_clock::now();
    auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    };
    StagingDir staging(outDir, "stability");
    std::unique_ptr<GlContext> context = createHeadlessContext();
    std::fprintf(stderr,
                 "stability: %s, %dx%d frame, %d^2 map, %zu method(s) x %zu bias(es) on %s; "
                 "truth %dx%d samples per pixel\n",
                 scene.name.c_str(), options.frameSize.x, options.frameSize.y, options.mapSize,
                 options.methods.size(), options.biases.size(), context->renderer().c_str(),
                 options.truthSpp, options.truthSpp);
    StabilityContext sc;
    sc.scene = &scene;
    sc.progress = [&](const std::string& line) {
        std::fprintf(stderr, "stability: [%5.1f s] %s\n", seconds(), line.c_str());
    };
    StabilityResult result = runStability(sc, options);

    StabilitySetup setup;
    setup.sceneName = scene.name;
    setup.glRenderer = context->renderer();
    setup.frameSize = options.frameSize;
    setup.mapSize = options.mapSize;
    setup.truthSpp = options.truthSpp;
    setup.constantBias = options.base.constantBias;
    setup.cull = std::string(cullModeName(options.base.cull));
    setup.depthFormat = std::string(depthFormatName(options.base.depthFormat));
    setup.precisionElevation = options.precisionElevation;
    setup.tradeoffElevation = options.tradeoffElevation;
    setup.settings = settingsLine(options);
    // The setup first, then the measured rows: the CSV says what it was measured with.
    std::vector<StabilityRow> rows = stabilitySetupRows(setup);
    rows.insert(rows.end(), result.rows.begin(), result.rows.end());
    std::string markdown = stabilityMarkdown(rows, setup, options.base.constantBias);
    writeTextFile((staging.path() / csvName).string(), stabilityCsv(rows));
    writeTextFile((staging.path() / mdName).string(), markdown);
    writeSweepCsvs(staging.path(), rows, options);
    writeCharts(staging.path(), rows, result.images, options.sweeps, chartSize);
    outputs.commitStaged(staging.path(), outDir, finalNames);
    std::fputs(markdown.c_str(), stdout);
    std::fprintf(stderr, "stability: %zu rows in %.1f s; wrote %zu files in %s\n",
                 result.rows.size(), seconds(), finalNames.size(), o.out.c_str());
    return 0;
}

}  // namespace

Command addStabilityCommand(CLI::App& app) {
    auto o = std::make_shared<StabilityCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "stability",
        "where methods fail: acne, peter panning, shimmer, depth precision, aliasing; CSV, table, "
        "charts");
    o->sub = sub;
    o->render.size = "480x270";
    o->render.defaults.mapSize = 512;
    o->render.frameRange.min = glm::ivec2(MIN_STABILITY_FRAME_SIDE);
    // The pcss sweeps set their lights' sizes themselves (the suns of pcss-noise, the presets'
    // lights): a light size option would be read by nothing.
    o->render.addTo(sub, STABILITY_DEFAULT_SCENE, {"light_size", "light_radius"});
    // The single-lookup options of the shared set do not apply here (parseOptions says so when
    // given): out of --help, which listed them as if they did.
    for (const char* single : SINGLE_LOOKUP_OPTIONS) {
        if (CLI::Option* option = sub->get_option_no_throw(single)) option->group("");
    }
    sub->add_option("--methods", o->methods,
                    "method ids, comma-separated (default nearest,pcf-gather)");
    sub->add_option("--kernels", o->kernels,
                    "N for the methods that take one, comma-separated (default 5; --quick 3)");
    sub->add_option("--biases", o->biases,
                    "bias modes, comma-separated (default none,constant,normal,receiver-plane; "
                    "--quick none,constant; pairs that cannot exist are skipped)");
    sub->add_option("--sweep", o->sweeps,
                    "sweeps, comma-separated: " + sweepNameList() + " (default all)");
    sub->add_option("-o,--out", o->out, "output directory (default: stability)");
    sub->add_option("--chart-size", o->chartSize,
                    sizeHelp("chart size", CHART_SIZE_RANGE, "default 1280x720; --quick 640x360"));
    sub->add_option("--spp", o->spp, "ground truth: K x K samples per pixel (default 2)");
    sub->add_option("--threads", o->threads, "ground truth threads (0 = all cores, the default)");
    sub->add_option("--pixel", o->pixel,
                    "X,Y: a pinned pixel; shimmer also writes its curve's flicker "
                    "(light_pinned_flicker, snapped_pinned_flicker), as animate's trace shows it");
    sub->add_flag("--quick", o->quick,
                  "a few seconds, for CI: 160x90 frame, 128^2 map, 1 truth sample, nearest and "
                  "pcf-gather 3x3, fewer points per sweep (explicit options still win)");
    sub->add_option("--replot", o->replot,
                    "CSV: draw an existing stability.csv's charts into -o (at --chart-size), "
                    "measure nothing; all but the heat map");
    sub->add_flag("-f,--force", o->force,
                  "overwrite existing output files; start work larger than the memory estimate "
                  "says the machine holds");
    return {sub, [o] { return runStabilityCommand(*o); },
            [o] {
                if (o->given("--replot")) {
                    checkReplot(*o);
                } else {
                    checkStabilityCommand(*o);
                }
            }};
}

}  // namespace pcf
