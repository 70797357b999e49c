// The charts of pcss's four sweeps (stability_pcss.h), one population and one metric each.
#include "charts/stability_pcss_figures.h"

#include <cstdio>

#include "charts/chart_axes.h"
#include "kernel/methods.h"
#include "measure/failure_measures.h"
#include "measure/stability_pcss.h"
#include "measure/stability_report.h"

namespace pcf {

namespace {

// "where; frame, map; bias" over the renderer's line; `source` alone without a setup.
std::string pcssSubtitle(std::span<const StabilityRow> rows, const std::string& where,
                         const std::string& bias, const std::string& source) {
    std::optional<StabilitySetup> setup = stabilitySetupOf(rows);
    if (!setup) return source;
    const StabilitySetup& s = *setup;
    return where + ", " + std::to_string(s.frameSize.x) + "x" + std::to_string(s.frameSize.y) +
           " frame, map " + std::to_string(s.mapSize) + "^2; " + bias + ", constant bias " +
           chartTickText(s.constantBias) + "; cull " + s.cull + "\n" +
           chartRendererLine(s.glRenderer);
}

// The (x, y) of the rows of one sweep, method and metric, in order.
ChartLine pcssLineOf(std::span<const StabilityRow> rows, std::string_view sweep, int method,
                     std::string_view bias, const std::string& metric, ChartLine line) {
    for (const StabilityRow& r : rows) {
        if (r.sweep == sweep && r.method == method && r.metric == metric &&
            (bias.empty() || r.bias == bias)) {
            line.points.emplace_back(r.x, r.y);
        }
    }
    return line;
}

const glm::vec4 PCSS_COLOUR{0.0f, 0.45f, 0.70f, 1.0f};        // Okabe-Ito blue
const glm::vec4 PCSS_OTHER_COLOUR{0.84f, 0.37f, 0.0f, 1.0f};  // Okabe-Ito vermillion

LineChartSpec finishPcssChart(LineChartSpec spec, float minFontPx) {
    for (auto it = spec.panels.front().lines.begin(); it != spec.panels.front().lines.end();) {
        it = it->points.empty() ? spec.panels.front().lines.erase(it) : it + 1;
    }
    if (spec.panels.front().lines.empty()) spec.panels.clear();
    spec.minFontPx = minFontPx;
    return spec;
}

}  // namespace

LineChartSpec pcssThinChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                float minFontPx) {
    LineChartSpec spec;
    spec.title =
        "Thin occluders: share of the area truth's shadowed pixels (< 1/2) that come out "
        "fully lit, by pole width";
    spec.subtitle =
        pcssSubtitle(rows, "a 3-unit pole under an 8 degree sun", "receiver-plane bias", subtitle);
    spec.xLabel = "the pole's width, shadow-map texels (log scale)";
    spec.yLabel = "missed share (truth-shadowed pixels returned >= 0.99)";
    spec.logX = true;
    spec.percentY = true;
    ChartPanel panel{"pcss and pcf-gather 5x5", {}};
    panel.lines.push_back(pcssLineOf(rows, "pcss-thin", PCF_PCSS, "", "missed_share_mean",
                                     {"pcss, mean of 4 grids", PCSS_COLOUR, false, {}}));
    panel.lines.push_back(pcssLineOf(rows, "pcss-thin", PCF_PCSS, "", "missed_share_max",
                                     {"pcss, worst grid", PCSS_COLOUR, true, {}}));
    panel.lines.push_back(pcssLineOf(rows, "pcss-thin", PCF_GATHER, "", "missed_share_mean",
                                     {"pcf-gather 5x5", PCSS_OTHER_COLOUR, false, {}}));
    spec.panels.push_back(panel);
    // The notes: the search radius at the pole's foot per width (the 16 taps lie about 0.44 r
    // apart: a disk of radius r shared by 16 points, sqrt(pi / 16) r each).
    std::string radii;
    for (const StabilityRow& r : rows) {
        if (r.sweep == "pcss-thin" && r.metric == "search_radius_texels") {
            char buf[48];
            std::snprintf(buf, sizeof buf, "%s%.1f", radii.empty() ? "" : ", ", r.y);
            radii += buf;
        }
    }
    if (!radii.empty()) spec.notes.push_back("search radius r at the foot: " + radii + " tx");
    if (!radii.empty()) spec.notes.push_back("16 taps, about 0.44 r apart");
    return finishPcssChart(spec, minFontPx);
}

LineChartSpec pcssOverlapChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                   float minFontPx) {
    LineChartSpec spec;
    spec.title =
        "Overlapping occluders: pcss's penumbra pixels over the area truth's, by the "
        "plank's height";
    spec.subtitle = pcssSubtitle(rows, "a plank over the ground under a 4 degree sun",
                                 "receiver-plane bias", subtitle);
    spec.xLabel = "the plank's height above the ground, world units";
    spec.yLabel = "penumbra pixels (0.02 < v < 0.98), pcss / area truth";
    ChartPanel panel{"pcss", {}};
    panel.lines.push_back(pcssLineOf(rows, "pcss-overlap", PCF_PCSS, "",
                                     "alone:penumbra_pixels_ratio",
                                     {"the plank alone", PCSS_COLOUR, false, {}}));
    panel.lines.push_back(pcssLineOf(
        rows, "pcss-overlap", PCF_PCSS, "", "stacked:penumbra_pixels_ratio",
        {"with a 0.3-unit block under its shadow's edge", PCSS_OTHER_COLOUR, false, {}}));
    spec.panels.push_back(panel);
    spec.notes.push_back("1 = as many penumbra pixels as the truth");
    return finishPcssChart(spec, minFontPx);
}

LineChartSpec pcssNoiseChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                 float minFontPx) {
    LineChartSpec spec;
    spec.title =
        "Few samples: pixel-to-pixel RMS of pcss's error in the area truth's penumbra, "
        "by sun size";
    spec.subtitle = pcssSubtitle(rows, "post-in-sun's post", "receiver-plane bias", subtitle);
    spec.xLabel = "the sun's angular diameter, degrees (log scale)";
    spec.yLabel = "RMS of e(x+1) - e(x), e = pcss - truth, neighbours in the penumbra";
    spec.logX = true;
    ChartPanel panel{"pcss, 16 search + 16 filter taps", {}};
    panel.lines.push_back(pcssLineOf(rows, "pcss-noise", PCF_PCSS, "", "rotated:penumbra_roughness",
                                     {"disk rotated per pixel (noise)", PCSS_COLOUR, false, {}}));
    panel.lines.push_back(pcssLineOf(rows, "pcss-noise", PCF_PCSS, "", "fixed:penumbra_roughness",
                                     {"disk not rotated (banding)", PCSS_OTHER_COLOUR, false, {}}));
    spec.panels.push_back(panel);
    return finishPcssChart(spec, minFontPx);
}

LineChartSpec pcssBiasChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                float minFontPx) {
    LineChartSpec spec;
    spec.title =
        "The bias a wider filter needs: share of clean-lit receivers darker than 0.99, "
        "by filter radius";
    std::optional<StabilitySetup> setup = stabilitySetupOf(rows);
    std::string where = setup ? setup->sceneName : std::string("the scene");
    spec.subtitle =
        pcssSubtitle(rows,
                     where + ", light " + chartTickText(StabilityOptions{}.pcssBiasElevation) +
                         " deg above the ground",
                     "poisson (pcss's filter) at each radius", subtitle);
    spec.xLabel = "poisson's radius, shadow-map texels (log scale)";
    spec.yLabel = "false-shadow rate (clean-lit pixels darker than 0.99)";
    spec.logX = true;
    spec.percentY = true;
    ChartPanel panel{"poisson, 16 taps", {}};
    for (const char* bias : {"constant", "receiver-plane"}) {
        panel.lines.push_back(pcssLineOf(rows, "pcss-bias", PCF_POISSON, bias, "false_shadow_rate",
                                         {bias, biasColour(bias), false, {}}));
    }
    spec.panels.push_back(panel);
    spec.notes.push_back("1% = acne onset");
    return finishPcssChart(spec, minFontPx);
}

std::vector<uint8_t> drawPcssChart(const LineChartSpec& spec, glm::ivec2 size) {
    if (spec.panels.empty()) return {};
    return drawLineChart(spec, size);
}

}  // namespace pcf
