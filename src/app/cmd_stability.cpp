// pcfscope stability: where methods fail (analysis/stability.h). Runs the sweeps (acne, leak,
// shimmer, precision, aliasing) for a list of methods and bias modes and writes, into DIR:
//   stability.csv          one row per measured point: sweep,method,kernel,bias,x_name,x,metric,y
//   stability.md           per method and bias: acne onset, leak width, shimmer
//   stability_acne.png     false-shadow rate against the light's elevation, a line per bias
//   stability_leak.png     leak width against the constant bias, a line per bias
//   stability_shimmer.png  shimmer per method and bias
//   aliasing_heatmap.png   screen pixels per shadow-map texel over the frame
// (a chart only when its sweep ran). As `bench` does, everything is written into a staging
// folder inside DIR and moved into place once the whole run has succeeded.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "analysis/ground_truth.h"
#include "analysis/stability.h"
#include "analysis/stability_chart.h"
#include "analysis/stability_report.h"
#include "app/cli_util.h"
#include "app/commands.h"
#include "app/output_files.h"
#include "app/render_options.h"
#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "render/gl_context.h"
#include "render/image_io.h"

namespace pcf {

namespace {

namespace fs = std::filesystem;

constexpr const char* DEFAULT_SCENE = "box-on-plane";

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
            if (*id == PCF_TENT && !kernelFits(*id, n)) continue;
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
            throw UsageError("unknown sweep '" + name +
                             "' in --sweep (known: acne, leak, shimmer, precision, aliasing)");
        }
        sweeps.push_back(*s);
    }
    return sweeps;
}

StabilityOptions parseOptions(const StabilityCommandOptions& o) {
    StabilityOptions options = o.quick ? quickStabilityOptions() : StabilityOptions{};
    for (const char* single : {"--method", "--kernel", "--bias", "--lesson", "--step"}) {
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
                    std::string(cullModeName(o.base.shadowCull)) + " faces in the shadow pass";
    if (o.base.polygonOffset != glm::vec2(0.0f)) {
        std::snprintf(buf, sizeof buf, "%g, %g", o.base.polygonOffset.x, o.base.polygonOffset.y);
        s += std::string(", polygon offset ") + buf;
    }
    s += ", depth " + std::string(depthFormatName(o.base.depthFormat));
    return s;
}

// What the command writes into -o: the CSV, the Markdown, and each chart its sweeps draw.
std::vector<std::string> outputNames(const std::vector<Sweep>& sweeps) {
    std::vector<std::string> names = {"stability.csv", "stability.md"};
    if (has(sweeps, Sweep::Acne)) names.push_back("stability_acne.png");
    if (has(sweeps, Sweep::Leak)) names.push_back("stability_leak.png");
    if (has(sweeps, Sweep::Shimmer)) names.push_back("stability_shimmer.png");
    if (has(sweeps, Sweep::Aliasing)) names.push_back("aliasing_heatmap.png");
    return names;
}

// The sweeps' charts and images, into dir; detail (frame, map, settings, renderer) goes under
// each chart's title.
void writeCharts(const fs::path& dir, const StabilityResult& result,
                 const std::vector<Sweep>& sweeps, glm::ivec2 chartSize,
                 const std::string& sceneName, const std::string& detail) {
    std::string subtitle = sceneName + ", " + detail;
    auto chart = [&](const std::string& name, const std::vector<uint8_t>& rgba) {
        if (rgba.empty()) throw std::runtime_error("no rows for " + name);
        writePngRgba8((dir / name).string(), chartSize.x, chartSize.y, rgba);
    };
    if (has(sweeps, Sweep::Acne)) {
        chart("stability_acne.png", drawAcneChart(result.rows, chartSize, subtitle));
    }
    if (has(sweeps, Sweep::Leak)) {
        chart("stability_leak.png",
              drawLeakChart(result.rows, chartSize, "pole and box-on-plane, " + detail));
    }
    if (has(sweeps, Sweep::Shimmer)) {
        chart("stability_shimmer.png", drawShimmerChart(result.rows, chartSize, subtitle));
    }
    for (const StabilityImage& image : result.images) {
        writePngRgba8((dir / image.name).string(), image.size.x, image.size.y, image.rgba);
    }
}

int runStabilityCommand(const StabilityCommandOptions& o) {
    // Every check first: nothing is computed or written unless all of it can be.
    StabilityOptions options = parseOptions(o);
    // --quick draws its charts at half size unless told otherwise.
    std::string chartText = o.quick && !o.given("--chart-size") ? "640x360" : o.chartSize;
    glm::ivec2 chartSize = parseSize("--chart-size", chartText, MAX_FRAME_SIDE, glm::ivec2(64));
    Scene scene = o.render.loadScene();
    if (o.out.empty()) throw UsageError("-o needs a directory");
    fs::path outDir(o.out);
    const std::string csvName = "stability.csv", mdName = "stability.md";
    std::vector<std::string> finalNames = outputNames(options.sweeps);
    OutputFiles outputs(o.force);
    outputs.addDirectory("-o", outDir);
    for (const std::string& name : finalNames) outputs.add("-o", outDir / name);

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
    setup.settings = settingsLine(options);
    std::string markdown = stabilityMarkdown(result.rows, setup, options.base.constantBias);
    writeTextFile((staging.path() / csvName).string(), stabilityCsv(result.rows));
    writeTextFile((staging.path() / mdName).string(), markdown);
    std::string detail = std::to_string(options.frameSize.x) + "x" +
                         std::to_string(options.frameSize.y) + ", " +
                         std::to_string(options.mapSize) + "^2 map, " + settingsLine(options) +
                         "; " + context->renderer();
    writeCharts(staging.path(), result, options.sweeps, chartSize, scene.name, detail);
    for (const std::string& name : finalNames) fs::rename(staging.path() / name, outDir / name);
    outputs.commit();
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
    o->render.mapSize = 512;
    o->render.addTo(sub, DEFAULT_SCENE);
    sub->add_option("--methods", o->methods,
                    "method ids, comma-separated (default nearest,pcf-gather)");
    sub->add_option("--kernels", o->kernels,
                    "N for the methods that take one, comma-separated (default 5; --quick 3)");
    sub->add_option("--biases", o->biases,
                    "bias modes, comma-separated (default none,constant,normal,receiver-plane; "
                    "--quick none,constant; pairs that cannot exist are skipped)");
    sub->add_option("--sweep", o->sweeps,
                    "sweeps, comma-separated: acne, leak, shimmer, precision, aliasing (default "
                    "all)");
    sub->add_option("-o,--out", o->out, "output directory (default: stability)");
    sub->add_option("--chart-size", o->chartSize,
                    "chart size WxH (default 1280x720; --quick 640x360)");
    sub->add_option("--spp", o->spp, "ground truth: K x K samples per pixel (default 2)");
    sub->add_option("--threads", o->threads, "ground truth threads (0 = all cores, the default)");
    sub->add_option("--pixel", o->pixel,
                    "X,Y: a pinned pixel; shimmer also writes its curve's flicker "
                    "(light_pinned_flicker, snapped_pinned_flicker), as animate's trace shows it");
    sub->add_flag("--quick", o->quick,
                  "a few seconds, for CI: 160x90 frame, 128^2 map, 1 truth sample, nearest and "
                  "pcf-gather 3x3, fewer points per sweep (explicit options still win)");
    sub->add_flag("-f,--force", o->force, "overwrite existing output files");
    return {sub, [o] { return runStabilityCommand(*o); }};
}

}  // namespace pcf
