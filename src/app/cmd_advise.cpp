// pcfscope advise: the cheapest shadow settings, by the lookup pass's CPU time, that meet an error
// and stability budget on one scene, and why. The search is measure/advise.h's, measured by
// measure/advise_measure.h (bench's sweep, one setting at a time); this file parses the budget
// and the space, checks the outputs, reports progress and writes, into DIR:
//   advise.csv      every setting measured, every measure, the cost's median and IQR
//   advise.json     the choice, the runner-up, the binding constraint, the candidates
//   settings.toml   the choice as a [settings] table, also printed on stdout
//   advise.png      cost against edge error, the budget drawn, each setting marked
// Everything is written into a staging folder inside DIR and moved into place at the end; a
// budget nothing meets is refused (exit 2) with the closest setting, and writes nothing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/output_files.h"
#include "app/render_options.h"
#include "app/truth_option.h"
#include "base/usage_error.h"
#include "charts/advise_chart.h"
#include "measure/advise.h"
#include "measure/advise_measure.h"
#include "measure/advise_report.h"
#include "render/gl_context.h"
#include "render/image_io.h"

namespace pcf {

namespace {

namespace fs = std::filesystem;

constexpr const char* ADVISE_CSV = "advise.csv";
constexpr const char* ADVISE_JSON = "advise.json";
constexpr const char* ADVISE_TOML = "settings.toml";
constexpr const char* ADVISE_CHART = "advise.png";
// The options the search sets itself; RenderOptions registers them for the commands that render.
constexpr const char* SEARCHED_OPTIONS[] = {
    "--method",        "--kernel", "--map-size", "--bias",   "--constant-bias",
    "--normal-offset", "--radius", "--rotate",   "--lesson", "--step"};

struct AdviseCommandOptions {
    RenderOptions render;  // scene, frame size, culling, depth format, the other bias parameters
    double maxEdgeRmse = 0.0, maxAcne = 0.0, maxLeakTexels = 0.0, maxShimmer = 0.0;
    std::string methods = "nearest,hw2x2,pcf-gather,tent";
    std::string kernels = "3,5,7";
    std::string mapSizes = "256,512,1024,2048";
    std::string biases = "none,constant:0.001,constant:0.004,normal:1.5";
    std::string truth = "hard";
    int spp = 2;
    int repeats = 5;
    int shimmerFrames = 8;
    int threads = 0;
    std::string chartSize = "960x540";
    std::string out;
    bool force = false;
    CLI::App* sub = nullptr;
    bool given(const char* option) const { return sub != nullptr && sub->count(option) > 0; }
};

struct AdvisePlan {
    Scene scene;
    AdviseSpace space;
    AdviseBudget budget;
    AdviseMeasureOptions measure;
    glm::ivec2 chartSize{960, 540};
};

// An optional bound: nullopt when not given, else checked against [0, hi].
std::optional<double> bound(const AdviseCommandOptions& o, const char* option, double v,
                            double hi) {
    if (!o.given(option)) return std::nullopt;
    requireRange(option, static_cast<float>(v), 0.0f, static_cast<float>(hi));
    return v;
}

AdviseBudget parseBudget(const AdviseCommandOptions& o) {
    if (!o.given("--max-edge-rmse")) {
        throw UsageError(
            "advise needs a budget: --max-edge-rmse E (and optionally --max-acne, "
            "--max-leak-texels, --max-shimmer)");
    }
    AdviseBudget b;
    b.maxEdgeRmse = *bound(o, "--max-edge-rmse", o.maxEdgeRmse, 1.0);
    b.maxAcne = bound(o, "--max-acne", o.maxAcne, 1.0);
    b.maxLeakTexels = bound(o, "--max-leak-texels", o.maxLeakTexels, 1e6);
    b.maxShimmer = bound(o, "--max-shimmer", o.maxShimmer, 1.0);
    return b;
}

// "none,constant:0.002,normal:1.5": each mode with its amount (its parameter's range).
std::vector<AdviseBias> parseBiases(const std::string& text, const RenderSettings& base) {
    std::vector<AdviseBias> biases;
    for (const std::string& item : splitList("--biases", text)) {
        size_t colon = item.find(':');
        AdviseBias b{biasModeOption(item.substr(0, colon)), 0.0f};
        if (b.mode == BiasMode::None && colon != std::string::npos) {
            throw UsageError("--biases: none takes no amount ('" + item + "')");
        }
        if (b.mode != BiasMode::None) {
            if (colon == std::string::npos) {
                throw UsageError("--biases: " + item + " needs an amount (" + item + ":0.002)");
            }
            std::string amount = item.substr(colon + 1);
            char* end = nullptr;
            b.amount = std::strtof(amount.c_str(), &end);
            if (amount.empty() || *end != '\0' || !std::isfinite(b.amount)) {
                throw UsageError("--biases: '" + amount + "' in '" + item + "' is not a number");
            }
            try {
                checkBiasOptions(adviseBiasSettings(base, b));
            } catch (const UsageError& e) {
                throw UsageError("--biases " + item + ": " + e.what());
            }
        }
        biases.push_back(b);
    }
    return biases;
}

// The filters: bench's points of the methods x kernels x weights (one map size).
std::vector<AdviseFilter> parseFilters(const AdviseCommandOptions& o, std::vector<int> mapSizes) {
    BenchOptions lists;
    for (const std::string& name : splitList("--methods", o.methods)) {
        lists.methods.push_back(methodOption(name));
    }
    lists.kernels = parseIntList("--kernels", o.kernels);
    lists.mapSizes = std::move(mapSizes);
    lists.weights.clear();
    for (const std::string& w : splitList("--weights", o.render.shadow.name("weights"))) {
        lists.weights.push_back(weightsOption(w));
    }
    lists.sigma = o.render.shadow.values().sigma;
    if (auto why = validateBenchOptions(lists)) throw UsageError(cliWords(*why));
    lists.mapSizes.resize(1);
    std::vector<AdviseFilter> filters;
    for (const BenchPoint& p : benchPoints(lists)) {
        filters.push_back({p.method, p.kernel, p.weights, p.sigma});
    }
    return filters;
}

RenderSettings baseSettings(const AdviseCommandOptions& o) {
    for (const char* searched : SEARCHED_OPTIONS) {
        if (o.given(searched)) {
            throw UsageError(std::string(searched) +
                             " does not apply to advise: it searches that (use --methods, "
                             "--kernels, --weights, --map-sizes, --biases)");
        }
    }
    RenderOptions stand = o.render;
    stand.shadow.name("method") = "nearest";
    stand.shadow.name("weights") = "box";
    stand.shadow.name("bias") = "none";
    return stand.settings();
}

AdvisePlan parsePlan(const AdviseCommandOptions& o) {
    AdvisePlan plan;
    plan.budget = parseBudget(o);
    RenderSettings base = baseSettings(o);
    std::vector<int> sizes = parseIntList("--map-sizes", o.mapSizes);
    std::sort(sizes.begin(), sizes.end());
    plan.space.filters = parseFilters(o, sizes);
    plan.space.mapSizes = sizes;
    plan.space.biases = parseBiases(o.biases, base);
    if (adviseGrid(plan.space).empty()) {
        throw UsageError("--biases: none of them combines with any of --methods");
    }
    requireIntRange("--spp", o.spp, 2, MAX_TRUTH_SPP);
    requireIntRange("--repeats", o.repeats, 1, 1000);
    requireIntRange("--shimmer-frames", o.shimmerFrames, 2, SHIMMER_STEPS);
    requireIntRange("--threads", o.threads, 0, 1024);
    plan.chartSize = parseSize("--chart-size", o.chartSize, CHART_SIZE_RANGE);
    plan.scene = o.render.loadScene();
    AdviseMeasureOptions& m = plan.measure;
    m.areaTruth = applyTruthOption(o.truth, plan.scene, base);
    m.frameSize = base.frameSize;
    m.truthSpp = o.spp;
    m.repeats = o.repeats;
    m.shimmerFrames = o.shimmerFrames;
    m.threads = o.threads;
    m.base = base;
    return plan;
}

// The closest setting when nothing met the budget, in one line.
std::string nothingMet(const AdviseResult& r, const AdviseBudget& budget) {
    std::string line = "advise: none of the " + std::to_string(r.measured.size()) +
                       " settings measured met the budget";
    if (!r.closest) return line;
    const AdviseCandidate& c = r.measured[*r.closest];
    line += "; the closest, " + adviseSettingName(c.setting) + ",";
    for (size_t k = 0; k < c.broken.size(); ++k) {
        line += (k == 0 ? " " : " and ") + adviseBreakText(c, c.broken[k], budget);
    }
    return line;
}

void printSummary(const AdviseResult& r, const AdviseBudget& budget, const std::string& toml) {
    const AdviseCandidate& c = r.measured[*r.choice];
    std::printf("# choice: %s, %.3f ms (IQR %.3f) lookup CPU time, %d texel reads\n",
                adviseSettingName(c.setting).c_str(), c.metrics.costMs, c.metrics.costIqr,
                c.texelReads);
    if (r.runnerUp) {
        const AdviseCandidate& u = r.measured[*r.runnerUp];
        std::printf("# runner-up: %s, %.3f ms (IQR %.3f)\n", adviseSettingName(u.setting).c_str(),
                    u.metrics.costMs, u.metrics.costIqr);
    }
    std::printf("# why: %s\n", adviseBinding(r, budget).c_str());
    if (std::string tie = adviseTieNote(r); !tie.empty()) std::printf("# tie: %s\n", tie.c_str());
    std::printf("# measured %zu of the %zu settings in the grid\n", r.measured.size(), r.gridSize);
    std::fputs(toml.c_str(), stdout);
}

int runAdvise(const AdviseCommandOptions& o) {
    AdvisePlan plan = parsePlan(o);
    if (o.out.empty()) throw UsageError("advise needs -o DIR");
    OutputFiles outputs(o.force);
    std::vector<std::string> names = {ADVISE_CSV, ADVISE_JSON, ADVISE_TOML, ADVISE_CHART};
    outputs.addInput("--scene-file", o.render.sceneFile);
    outputs.addFilesIn("-o", o.out, names);
    StagingDir staging(o.out, "advise");
    std::unique_ptr<GlContext> gl = createHeadlessContext();
    std::unique_ptr<AdviseBench> bench;
    try {
        bench = std::make_unique<AdviseBench>(plan.scene, plan.measure);
    } catch (const BenchSceneError& e) {
        throw UsageError(e.what());
    }
    int count = 0;
    auto measure = [&](const AdviseSetting& s) {
        std::fprintf(stderr, "advise: %d: %s\n", ++count, adviseSettingName(s).c_str());
        return bench->measure(s);
    };
    auto retime = [&](const std::vector<AdviseSetting>& settings) {
        std::fprintf(stderr,
                     "advise: timing the %zu settings that meet the budget again, %d "
                     "rounds round-robin\n",
                     settings.size(), o.repeats);
        return bench->retime(settings, o.repeats);
    };
    AdviseResult r = searchAdvice(plan.space, plan.budget, measure, retime);
    if (!r.choice) throw UsageError(nothingMet(r, plan.budget));
    AdviseContext context{
        plan.scene.name,          plan.measure.frameSize.x,
        plan.measure.frameSize.y, truthWordsFor(plan.scene, plan.measure.areaTruth),
        gl->renderer(),           plan.measure.base};
    std::string toml = adviseSettingsToml(r.measured[*r.choice].setting, plan.measure.base);
    writeTextFile((staging.path() / ADVISE_CSV).string(), adviseCsv(r, bench->rows()));
    writeTextFile((staging.path() / ADVISE_JSON).string(), adviseJson(r, plan.budget, context));
    writeTextFile((staging.path() / ADVISE_TOML).string(), toml);
    std::string title = "Settings measured for " + plan.scene.name + " against the budget";
    std::vector<uint8_t> png =
        drawAdviseChart(r, bench->rows(), plan.budget, plan.chartSize, title, gl->renderer());
    writePngRgba8((staging.path() / ADVISE_CHART).string(), plan.chartSize.x, plan.chartSize.y,
                  png);
    outputs.commitStaged(staging.path(), o.out, names);
    printSummary(r, plan.budget, toml);
    return 0;
}

void addBudgetOptions(CLI::App* sub, AdviseCommandOptions& o) {
    sub->add_option("--max-edge-rmse", o.maxEdgeRmse,
                    "E: the largest edge-band RMSE of visibility against the truth (required)");
    sub->add_option("--max-acne", o.maxAcne,
                    "A: the largest share (0..1) of clean lit pixels darkened below 0.99 at the "
                    "scene's light (default: not bounded)");
    sub->add_option("--max-leak-texels", o.maxLeakTexels,
                    "K: how far false light may reach from a caster, in map texels (default: "
                    "not bounded)");
    sub->add_option("--max-shimmer", o.maxShimmer,
                    "S: the largest p99 jump (0..1) of a flickering pixel as the map's grid "
                    "creeps 1/32 texel a frame (default: not bounded)");
}

void addSpaceOptions(CLI::App* sub, AdviseCommandOptions& o) {
    sub->add_option("--methods", o.methods,
                    "methods to choose from, comma-separated (default " + o.methods + ")");
    sub->add_option("--kernels", o.kernels,
                    "N to choose from, comma-separated (default " + o.kernels + ")");
    sub->add_option("--map-sizes", o.mapSizes,
                    "map sizes to choose from, comma-separated (default " + o.mapSizes + ")");
    sub->add_option("--biases", o.biases,
                    "bias modes with their amounts (the constant bias, normal: the offset in "
                    "texels), in the order to try, comma-separated (default " +
                        o.biases + ")");
}

}  // namespace

Command addAdviseCommand(CLI::App& app) {
    auto o = std::make_shared<AdviseCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "advise",
        "the cheapest shadow settings (by the lookup pass's CPU time) that meet an error and "
        "stability budget on a scene, and why");
    o->sub = sub;
    o->render.defaults.cull = CullMode::Front;  // bench's: the map holds back faces
    o->render.size = "480x270";
    o->render.addTo(sub, "");
    for (const char* searched : SEARCHED_OPTIONS) sub->get_option(searched)->group("");
    sub->get_option("--weights")
        ->description(
            "pcf-naive, pcf-gather: weightings to choose from, comma-separated: box, "
            "binomial, gaussian (default box)");
    addBudgetOptions(sub, *o);
    addSpaceOptions(sub, *o);
    sub->add_option("--truth", o->truth,
                    "hard: the light's centre (default); area: its disk (as bench's --truth)");
    sub->add_option("--spp", o->spp, "ground truth: K x K first-pass samples (default 2)");
    sub->add_option("--repeats", o->repeats, "timing rounds per setting (default 5)");
    sub->add_option("--shimmer-frames", o->shimmerFrames,
                    "frames of the creeping grid per setting (2..32, default 8)");
    sub->add_option("--threads", o->threads, "CPU threads of the truth and masks (0 = all)");
    sub->add_option("--chart-size", o->chartSize,
                    sizeHelp("size of advise.png", CHART_SIZE_RANGE, "default 960x540"));
    sub->add_option("-o,--out", o->out, "output directory (required)");
    sub->add_flag("-f,--force", o->force, "overwrite existing output files");
    return {sub, [o] { return runAdvise(*o); }, [o] { parsePlan(*o); }};
}

}  // namespace pcf
