#include "charts/stability_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "charts/chart_axes.h"
#include "charts/stability_bleed_figures.h"
#include "charts/stability_cascades_figures.h"
#include "charts/stability_pcss_figures.h"
#include "kernel/methods.h"
#include "measure/failure_measures.h"
#include "measure/stability_report.h"

namespace pcf {

namespace {

std::string shortMethod(const StabilityMethod& m) { return chartMethodLabel(m.method, m.kernel); }

// The (method, kernel) pairs of the rows of one sweep, in order of appearance.
std::vector<StabilityMethod> methodsOf(std::span<const StabilityRow> rows, std::string_view sweep) {
    std::vector<StabilityMethod> out;
    for (const StabilityRow& r : rows) {
        if (r.sweep != sweep || r.method < 0) continue;
        StabilityMethod m{r.method, r.kernel};
        if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
    }
    return out;
}

std::vector<std::string> biasesOf(std::span<const StabilityRow> rows, std::string_view sweep) {
    std::vector<std::string> out;
    for (const StabilityRow& r : rows) {
        if (r.sweep != sweep || r.method < 0) continue;
        if (std::find(out.begin(), out.end(), r.bias) == out.end()) out.push_back(r.bias);
    }
    return out;
}

// The y of one (sweep, method, bias, metric) row at any x; 0 when there is none.
double valueOf(std::span<const StabilityRow> rows, std::string_view sweep, const StabilityMethod& m,
               const std::string& bias, std::string_view metric) {
    for (const StabilityRow& r : rows) {
        if (r.sweep == sweep && r.method == m.method && r.kernel == m.kernel && r.bias == bias &&
            r.metric == metric) {
            return r.y;
        }
    }
    return 0.0;
}

bool samePoints(const ChartLine& a, const ChartLine& b) {
    if (a.points.size() != b.points.size() || a.dashed != b.dashed) return false;
    for (size_t i = 0; i < a.points.size(); ++i) {
        glm::dvec2 d = glm::abs(a.points[i] - b.points[i]);
        if (d.x > 1e-9 * std::max(1.0, std::abs(a.points[i].x)) ||
            d.y > 1e-9 * std::max(1.0, std::abs(a.points[i].y))) {
            return false;
        }
    }
    return true;
}

}  // namespace

void markCoincidentLines(LineChartSpec& spec) {
    for (ChartPanel& panel : spec.panels) {
        for (size_t i = 1; i < panel.lines.size(); ++i) {
            ChartLine& line = panel.lines[i];
            if (line.points.empty()) continue;
            int twins = 0;
            std::string under;
            for (size_t j = 0; j < i; ++j) {
                if (!samePoints(panel.lines[j], line)) continue;
                if (twins++ == 0) under = panel.lines[j].label;
            }
            if (twins == 0) continue;
            line.offsetPx = COINCIDENT_OFFSET_PX * static_cast<float>(twins);
            char px[16];
            std::snprintf(px, sizeof px, "%g", line.offsetPx);
            spec.notes.push_back(panel.title + ": " + line.label + " = " + under + " (" +
                                 (line.dashed ? "dashed, " : "") + "drawn " + px + " px lower)");
        }
    }
}

std::string stabilityChartSubtitle(std::span<const StabilityRow> rows, Sweep sweep,
                                   const std::string& source) {
    std::optional<StabilitySetup> setup = stabilitySetupOf(rows);
    if (!setup) return source;
    const StabilitySetup& s = *setup;
    std::string where =
        sweep == Sweep::Leak ? "the pole's and box-on-plane's contacts" : s.sceneName;
    if (sweep == Sweep::Tradeoff) {
        where = "acne: " + s.sceneName + ", light " + chartTickText(s.tradeoffElevation) +
                " deg above the ground; leak: the pole's and box-on-plane's contacts";
    }
    if (sweep == Sweep::Precision) {
        where += ", light " + chartTickText(s.precisionElevation) + " deg above the ground";
    }
    std::string frame = std::to_string(s.frameSize.x) + "x" + std::to_string(s.frameSize.y) +
                        " frame, map " + std::to_string(s.mapSize) + "^2";
    // Every mode but none subtracts the constant bias (kernel/bias.h: baseBias).
    std::string bias = sweep == Sweep::Leak || sweep == Sweep::Tradeoff
                           ? "the constant bias is the x axis (every mode but none subtracts it)"
                       : sweep == Sweep::Precision
                           ? "constant bias " + chartTickText(s.constantBias) +
                                 " at depth range 1, divided by the range (fixed in world units)"
                           : "constant bias " + chartTickText(s.constantBias);
    // The heat map depends on the camera and the light's fit alone, no bias or depth format.
    std::string line1 = sweep == Sweep::Aliasing ? where + ", " + frame
                                                 : where + ", " + frame + "; " + bias + "; cull " +
                                                       s.cull + ", depth " + s.depthFormat;
    return line1 + "\n" + chartRendererLine(s.glRenderer);
}

LineChartSpec acneChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                            float minFontPx) {
    LineChartSpec spec;
    spec.title = "Shadow acne: share of clean-lit receivers darker than 0.99, by light elevation";
    spec.subtitle = stabilityChartSubtitle(rows, Sweep::Acne, subtitle);
    // A linear axis: the onset, between 90 and 75 degrees for most pairs, keeps its width.
    spec.xLabel = "light elevation above the ground, degrees (the sun sets to the right)";
    spec.yLabel = "false-shadow rate (clean-lit pixels darker than 0.99)";
    spec.reverseX = true;
    spec.percentY = true;
    for (const StabilityMethod& m : methodsOf(rows, "acne")) {
        ChartPanel panel{shortMethod(m), {}};
        for (const std::string& bias : biasesOf(rows, "acne")) {
            ChartLine line{bias, biasColour(bias), false, {}};
            for (const StabilityRow& r : rows) {
                if (r.sweep == "acne" && r.metric == "false_shadow_rate" && r.method == m.method &&
                    r.kernel == m.kernel && r.bias == bias) {
                    line.points.emplace_back(r.x, r.y);
                }
            }
            panel.lines.push_back(line);
        }
        spec.panels.push_back(panel);
    }
    if (spec.panels.empty()) return spec;
    spec.notes.push_back("1% = acne onset");
    markCoincidentLines(spec);
    spec.minFontPx = minFontPx;
    return spec;
}

std::vector<uint8_t> drawAcneChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                   const std::string& subtitle, float minFontPx) {
    LineChartSpec spec = acneChartSpec(rows, subtitle, minFontPx);
    if (spec.panels.empty()) return {};
    return drawLineChart(spec, size);
}

LineChartSpec leakChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                            float minFontPx) {
    LineChartSpec spec;
    spec.title = "Peter panning: leak width under the caster (runs of " +
                 std::to_string(LEAK_MIN_RUN) + "+ leaking pixels) against the bias";
    spec.subtitle = stabilityChartSubtitle(rows, Sweep::Leak, subtitle);
    spec.xLabel = "constant bias, light depth units (log scale)";
    spec.yLabel = "leak width from the contact, shadow-map texels (clean umbra pixels > 0.01)";
    spec.logX = true;
    std::vector<std::string> scenes;
    for (const StabilityRow& r : rows) {
        if (r.sweep != "leak") continue;
        std::string scene = r.metric.substr(0, r.metric.find(':'));
        if (std::find(scenes.begin(), scenes.end(), scene) == scenes.end()) scenes.push_back(scene);
    }
    for (const StabilityMethod& m : methodsOf(rows, "leak")) {
        ChartPanel panel{shortMethod(m), {}};
        for (size_t k = 0; k < scenes.size(); ++k) {
            for (const std::string& bias : biasesOf(rows, "leak")) {
                ChartLine line{bias, biasColour(bias), k > 0, {}};
                for (const StabilityRow& r : rows) {
                    if (r.sweep == "leak" && r.metric == scenes[k] + ":leak_width_texels" &&
                        r.method == m.method && r.kernel == m.kernel && r.bias == bias) {
                        line.points.emplace_back(r.x, r.y);
                    }
                }
                panel.lines.push_back(line);
            }
        }
        spec.panels.push_back(panel);
    }
    if (spec.panels.empty()) return spec;
    for (size_t k = 0; k < scenes.size(); ++k) {
        spec.notes.push_back((k == 0 ? "solid: " : "dashed: ") + scenes[k]);
    }
    markCoincidentLines(spec);
    spec.minFontPx = minFontPx;
    return spec;
}

std::vector<uint8_t> drawLeakChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                   const std::string& subtitle, float minFontPx) {
    LineChartSpec spec = leakChartSpec(rows, subtitle, minFontPx);
    if (spec.panels.empty()) return {};
    return drawLineChart(spec, size);
}

namespace {

// The leak rates of one method in constant mode, per contact scene, at each bias of `biases`.
void readTradeoffLeak(std::span<const StabilityRow> rows, TradeoffSeries& t) {
    const std::string suffix = ":leak_rate";
    for (const StabilityRow& r : rows) {
        if (r.sweep != "leak" || !r.metric.ends_with(suffix)) continue;
        std::string scene = r.metric.substr(0, r.metric.size() - suffix.size());
        if (std::find(t.leakScenes.begin(), t.leakScenes.end(), scene) == t.leakScenes.end()) {
            t.leakScenes.push_back(scene);
        }
    }
    for (const std::string& scene : t.leakScenes) {
        std::vector<std::optional<double>> leak;
        for (double b : t.biases) {
            leak.push_back(stabilityValue(rows, "leak", t.method, "constant", scene + suffix, b));
        }
        t.leak.push_back(leak);
    }
}

// The first run of biases where acne and every scene's leak stay under the onset.
std::optional<glm::dvec2> goodBiases(const TradeoffSeries& t) {
    std::optional<glm::dvec2> good;
    for (size_t k = 0; k < t.biases.size(); ++k) {
        bool ok = t.acne[k] < TRADEOFF_ONSET && !t.leak.empty();
        for (const auto& scene : t.leak) ok = ok && scene[k] && *scene[k] < TRADEOFF_ONSET;
        if (ok && !good) good = glm::dvec2(t.biases[k]);
        if (ok) good->y = t.biases[k];
        if (!ok && good) break;
    }
    return good;
}

}  // namespace

std::vector<TradeoffSeries> tradeoffSeries(std::span<const StabilityRow> rows) {
    std::vector<TradeoffSeries> out;
    for (const StabilityMethod& m : methodsOf(rows, "tradeoff")) {
        TradeoffSeries t{m, shortMethod(m), {}, {}, {}, {}, std::nullopt};
        std::vector<glm::dvec2> acne;
        for (const StabilityRow& r : rows) {
            if (r.sweep == "tradeoff" && r.metric == "false_shadow_rate" && r.method == m.method &&
                r.kernel == m.kernel) {
                acne.emplace_back(r.x, r.y);
            }
        }
        std::sort(acne.begin(), acne.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x; });
        for (glm::dvec2 p : acne) {
            t.biases.push_back(p.x);
            t.acne.push_back(p.y);
        }
        readTradeoffLeak(rows, t);
        t.good = goodBiases(t);
        out.push_back(t);
    }
    return out;
}

LineChartSpec tradeoffChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                float minFontPx) {
    LineChartSpec spec;
    spec.title = "The bias trade-off: share of clean pixels wrong (acne, leak) by constant bias";
    spec.subtitle = stabilityChartSubtitle(rows, Sweep::Tradeoff, subtitle);
    spec.xLabel = "constant bias, light depth units (log scale)";
    spec.yLabel =
        "share of clean pixels wrong (log scale): acne = clean-lit pixels darker than 0.99, "
        "leak = clean umbra pixels above 0.01";
    spec.logX = true;
    spec.percentY = true;
    // A log axis: acne reaches 100 % where leak stays under 10 %, and both must be read against
    // the 1 % onset; a decade under it, the floor holds the zeros.
    spec.logY = true;
    spec.yFloor = TRADEOFF_ONSET / 10.0;
    const glm::vec4 ACNE{0.84f, 0.37f, 0.0f, 1.0f};  // Okabe-Ito, as the biases'
    const glm::vec4 LEAK[] = {{0.0f, 0.45f, 0.70f, 1.0f}, {0.0f, 0.62f, 0.45f, 1.0f}};
    std::optional<StabilitySetup> setup = stabilitySetupOf(rows);
    std::string acneName = "acne";
    if (setup && setup->tradeoffElevation > 0.0) {
        acneName += ", light " + chartTickText(setup->tradeoffElevation) + " deg";
    }
    for (const TradeoffSeries& t : tradeoffSeries(rows)) {
        ChartPanel panel{t.name, {}, t.good};
        ChartLine acne{acneName, ACNE, false, {}};
        for (size_t k = 0; k < t.biases.size(); ++k)
            acne.points.emplace_back(t.biases[k], t.acne[k]);
        panel.lines.push_back(acne);
        for (size_t si = 0; si < t.leakScenes.size(); ++si) {
            ChartLine leak{"leak: " + t.leakScenes[si], LEAK[si % 2], true, {}};
            for (size_t k = 0; k < t.biases.size(); ++k) {
                if (t.leak[si][k]) leak.points.emplace_back(t.biases[k], *t.leak[si][k]);
            }
            panel.lines.push_back(leak);
        }
        spec.panels.push_back(panel);
    }
    if (spec.panels.empty()) return spec;
    spec.notes.push_back("green: a good bias (both < " + chartTickText(100.0 * TRADEOFF_ONSET) +
                         "%)");
    spec.minFontPx = minFontPx;
    return spec;
}

std::vector<uint8_t> drawTradeoffChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                       const std::string& subtitle, float minFontPx) {
    LineChartSpec spec = tradeoffChartSpec(rows, subtitle, minFontPx);
    if (spec.panels.empty()) return {};
    return drawLineChart(spec, size);
}

LineChartSpec precisionChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                 float minFontPx) {
    LineChartSpec spec;
    spec.title =
        "Depth precision: share of clean-lit receivers darker than 0.99 as the light's "
        "depth range deepens";
    spec.subtitle = stabilityChartSubtitle(rows, Sweep::Precision, subtitle);
    spec.xLabel = "light depth range / the scene's depth extent (log scale)";
    spec.yLabel = "false-shadow rate (clean-lit pixels darker than 0.99)";
    spec.logX = true;
    spec.percentY = true;
    std::vector<std::string> formats;
    const std::string prefix = "false_shadow_rate_d";
    for (const StabilityRow& r : rows) {
        if (r.sweep != "precision" || r.metric.rfind(prefix, 0) != 0) continue;
        std::string f = r.metric.substr(prefix.size());
        if (std::find(formats.begin(), formats.end(), f) == formats.end()) formats.push_back(f);
    }
    // One colour per depth format (Okabe-Ito, as the biases').
    const glm::vec4 FORMAT_COLOURS[] = {
        {0.84f, 0.37f, 0.0f, 1.0f}, {0.0f, 0.45f, 0.70f, 1.0f}, {0.0f, 0.62f, 0.45f, 1.0f}};
    std::vector<StabilityMethod> methods = methodsOf(rows, "precision");
    for (const std::string& bias : biasesOf(rows, "precision")) {
        ChartPanel panel{"bias " + bias, {}};
        for (size_t mi = 0; mi < methods.size() && mi < 2; ++mi) {
            for (size_t f = 0; f < formats.size(); ++f) {
                ChartLine line{"depth " + formats[f], FORMAT_COLOURS[f % 3], mi > 0, {}};
                for (const StabilityRow& r : rows) {
                    if (r.sweep == "precision" && r.metric == prefix + formats[f] &&
                        r.method == methods[mi].method && r.kernel == methods[mi].kernel &&
                        r.bias == bias) {
                        line.points.emplace_back(r.x, r.y);
                    }
                }
                panel.lines.push_back(line);
            }
        }
        spec.panels.push_back(panel);
    }
    if (spec.panels.empty()) return spec;
    for (size_t mi = 0; mi < methods.size() && mi < 2; ++mi) {
        spec.notes.push_back((mi == 0 ? "solid: " : "dashed: ") + shortMethod(methods[mi]));
    }
    markCoincidentLines(spec);
    spec.minFontPx = minFontPx;
    return spec;
}

std::vector<uint8_t> drawPrecisionChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                        const std::string& subtitle, float minFontPx) {
    LineChartSpec spec = precisionChartSpec(rows, subtitle, minFontPx);
    if (spec.panels.empty()) return {};
    return drawLineChart(spec, size);
}

BarChartSpec shimmerChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                              float minFontPx) {
    BarChartSpec spec;
    std::vector<StabilityMethod> methods = methodsOf(rows, "shimmer");
    double edgePixels = methods.empty()
                            ? 0.0
                            : valueOf(rows, "shimmer", methods.front(),
                                      biasesOf(rows, "shimmer").front(), "light_edge_pixels");
    spec.title = "Shimmer at the shadow edges: how far pixels jump, over the same " +
                 chartTickText(edgePixels) + " pixels for every bar";
    spec.subtitle = stabilityChartSubtitle(rows, Sweep::Shimmer, subtitle);
    spec.yLabel =
        "an edge pixel's largest jump between frames, 99th percentile over the edge pixels "
        "(acne on the lit ground left out)";
    spec.series = {"texel grid slid 1/32 texel a frame", "the same, snapped to whole texels",
                   "camera slid by sub-pixel steps (error change)"};
    for (const StabilityMethod& m : methods) {
        for (const std::string& bias : biasesOf(rows, "shimmer")) {
            spec.groups.push_back({shortMethod(m) + " " + bias,
                                   {valueOf(rows, "shimmer", m, bias, "light_edge_peak_p99"),
                                    valueOf(rows, "shimmer", m, bias, "snapped_edge_peak_p99"),
                                    valueOf(rows, "shimmer", m, bias, "camera_edge_peak_p99")}});
        }
    }
    if (spec.groups.empty()) return spec;
    spec.minFontPx = minFontPx;
    return spec;
}

std::vector<uint8_t> drawShimmerChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                      const std::string& subtitle, float minFontPx) {
    BarChartSpec spec = shimmerChartSpec(rows, subtitle, minFontPx);
    if (spec.groups.empty()) return {};
    return drawBarChart(spec, size);
}

ImageChartSpec aliasingHeatmapSpec(const StabilityImage& heatmap,
                                   std::span<const StabilityRow> rows, const std::string& source,
                                   float minFontPx) {
    ImageChartSpec spec;
    std::optional<StabilitySetup> setup = stabilitySetupOf(rows);
    int mapSize = setup ? setup->mapSize : 0;
    double median = -1.0, p99 = -1.0;
    for (const StabilityRow& r : rows) {
        if (r.sweep != "aliasing" || static_cast<int>(r.x) != mapSize) continue;
        if (r.metric == "pixels_per_texel_median") median = r.y;
        if (r.metric == "pixels_per_texel_p99") p99 = r.y;
    }
    spec.title = "Perspective aliasing: screen pixels per shadow-map texel at each pixel, map " +
                 std::to_string(mapSize) + "^2";
    spec.subtitle = stabilityChartSubtitle(rows, Sweep::Aliasing, source);
    if (median >= 0.0) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "; over the receivers: median %.2f, 99th percentile %.2f",
                      median, p99);
        spec.subtitle.insert(std::min(spec.subtitle.find('\n'), spec.subtitle.size()), buf);
    }
    spec.imageSize = heatmap.size;
    spec.rgba = heatmap.rgba;
    spec.minFontPx = minFontPx;
    ColourScale& scale = spec.scale;
    scale.label = "pixels per texel (log scale)";
    // The heat map's own colours (aliasingHeatColour), log2 from -RANGE to +RANGE.
    const int STEPS = 64;
    const float range = ALIASING_HEAT_LOG2_RANGE;
    for (int i = 0; i < STEPS; ++i) {
        float l = -range + 2.0f * range * (i + 0.5f) / STEPS;
        scale.colours.emplace_back(aliasingHeatColour(std::exp2(l)), 1.0f);
    }
    auto at = [&](float log2v) { return (log2v + range) / (2.0f * range); };
    std::string most = chartTickText(std::exp2(range));
    scale.ticks = {{at(range), most + " or more: a texel smeared over " + most + " pixels"},
                   {at(range / 2), chartTickText(std::exp2(range / 2))},
                   {at(0.0f), "1: a texel per pixel"},
                   {at(-range / 2), "1/" + chartTickText(std::exp2(range / 2))},
                   {at(-range), "1/" + most + " or less: " + most + " texels in a pixel"}};
    scale.swatches = {{glm::vec4(ALIASING_HEAT_NONE, 1.0f), "not measured (no receiver)"}};
    return spec;
}

namespace {

template <LineChartSpec (*SPEC)(std::span<const StabilityRow>, const std::string&, float)>
std::vector<ChartTextBox> lineTexts(std::span<const StabilityRow> rows, glm::ivec2 size,
                                    const std::string& subtitle, float minFontPx) {
    return lineChartTextBoxes(SPEC(rows, subtitle, minFontPx), size);
}

std::vector<ChartTextBox> shimmerTexts(std::span<const StabilityRow> rows, glm::ivec2 size,
                                       const std::string& subtitle, float minFontPx) {
    return barChartTextBoxes(shimmerChartSpec(rows, subtitle, minFontPx), size);
}

template <LineChartSpec (*SPEC)(std::span<const StabilityRow>, const std::string&, float)>
bool linePoints(std::span<const StabilityRow> rows) {
    for (const ChartPanel& panel : SPEC(rows, "", 8.0f).panels) {
        for (const ChartLine& line : panel.lines) {
            if (!line.points.empty()) return true;
        }
    }
    return false;
}

bool shimmerBars(std::span<const StabilityRow> rows) {
    for (const BarGroup& group : shimmerChartSpec(rows, "", 8.0f).groups) {
        if (!group.values.empty()) return true;
    }
    return false;
}

// In the order `pcfscope stability` lists its charts.
constexpr SweepChart SWEEP_CHARTS[] = {
    {Sweep::Acne, "stability_acne.png", drawAcneChart, lineTexts<acneChartSpec>,
     linePoints<acneChartSpec>},
    {Sweep::Leak, "stability_leak.png", drawLeakChart, lineTexts<leakChartSpec>,
     linePoints<leakChartSpec>},
    {Sweep::Tradeoff, "stability_tradeoff.png", drawTradeoffChart, lineTexts<tradeoffChartSpec>,
     linePoints<tradeoffChartSpec>},
    {Sweep::Shimmer, "stability_shimmer.png", drawShimmerChart, shimmerTexts, shimmerBars},
    {Sweep::Precision, "stability_precision.png", drawPrecisionChart, lineTexts<precisionChartSpec>,
     linePoints<precisionChartSpec>},
    {Sweep::PcssThin, "stability_pcss_thin.png", drawPcssSweepChart<pcssThinChartSpec>,
     lineTexts<pcssThinChartSpec>, linePoints<pcssThinChartSpec>},
    {Sweep::PcssOverlap, "stability_pcss_overlap.png", drawPcssSweepChart<pcssOverlapChartSpec>,
     lineTexts<pcssOverlapChartSpec>, linePoints<pcssOverlapChartSpec>},
    {Sweep::PcssNoise, "stability_pcss_noise.png", drawPcssSweepChart<pcssNoiseChartSpec>,
     lineTexts<pcssNoiseChartSpec>, linePoints<pcssNoiseChartSpec>},
    {Sweep::PcssBias, "stability_pcss_bias.png", drawPcssSweepChart<pcssBiasChartSpec>,
     lineTexts<pcssBiasChartSpec>, linePoints<pcssBiasChartSpec>},
    {Sweep::Bleed, "stability_bleed.png", drawPcssSweepChart<bleedChartSpec>,
     lineTexts<bleedChartSpec>, linePoints<bleedChartSpec>, bleedChartSpec},
    {Sweep::Cascades, "stability_cascades.png", drawPcssSweepChart<cascadeChartSpec>,
     lineTexts<cascadeChartSpec>, linePoints<cascadeChartSpec>},
};

}  // namespace

std::string chartMethodLabel(int method, int kernel) {
    std::string label(methodInfo(method).name);
    if (kernel > 0) label += " " + std::to_string(kernel) + "x" + std::to_string(kernel);
    return label;
}

LineChartSpec logSweepChartSpec(std::string title, std::string subtitle, std::string xLabel,
                                std::string yLabel, double yFloor, float minFontPx) {
    LineChartSpec spec;
    spec.title = std::move(title);
    spec.subtitle = std::move(subtitle);
    spec.xLabel = std::move(xLabel);
    spec.yLabel = std::move(yLabel);
    spec.logY = true;
    spec.yFloor = yFloor;
    spec.minFontPx = minFontPx;
    return spec;
}

LineChartSpec emptySweepChartSpec(float minFontPx) {
    LineChartSpec spec;
    spec.minFontPx = minFontPx;
    return spec;
}

std::span<const SweepChart> sweepCharts() { return SWEEP_CHARTS; }

const SweepChart* sweepChartNamed(std::string_view name) {
    for (const SweepChart& c : SWEEP_CHARTS) {
        if (sweepName(c.sweep) == name) return &c;
    }
    return nullptr;
}

std::string sweepChartNames() {
    std::string names;
    for (const SweepChart& c : SWEEP_CHARTS) {
        names += (names.empty() ? "#" : ", #") + std::string(sweepName(c.sweep));
    }
    return names;
}

}  // namespace pcf
