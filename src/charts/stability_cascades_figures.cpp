// The cascades sweep's chart (stability_cascades_figures.h): texels per pixel against lambda.
#include "charts/stability_cascades_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "charts/chart_axes.h"
#include "charts/stability_figures.h"
#include "kernel/methods.h"
#include "measure/stability_cascades.h"
#include "measure/stability_report.h"

namespace pcf {

namespace {

// The cascades' colours: the `--shading cascades` tints (red, green, blue, yellow), darkened to
// read as lines on white.
const glm::vec4 CASCADE_LINE_COLOURS[CASCADE_SWEEP_CASCADES] = {
    {0.80f, 0.15f, 0.15f, 1.0f},
    {0.15f, 0.60f, 0.15f, 1.0f},
    {0.20f, 0.30f, 0.85f, 1.0f},
    {0.75f, 0.60f, 0.00f, 1.0f},
};

// "scene; frame, map; method, bias; path" over the renderer's line; `source` alone without a
// setup.
std::string cascadeSubtitle(std::span<const StabilityRow> rows, const CascadePoint& first,
                            const std::string& source) {
    std::optional<StabilitySetup> setup = stabilitySetupOf(rows);
    if (!setup) return source;
    const StabilitySetup& s = *setup;
    char distance[32];
    std::snprintf(distance, sizeof distance, "%g", static_cast<double>(CASCADE_SWEEP_DISTANCE));
    std::string method = chartMethodLabel(first.method, first.kernel);
    return "a wall and posts along a ground, " + std::to_string(CASCADE_SWEEP_CASCADES) +
           " cascades to " + distance + "; " + std::to_string(s.frameSize.x) + "x" +
           std::to_string(s.frameSize.y) + " frame, map " + std::to_string(s.mapSize) +
           "^2 a cascade; " + method + ", bias mode normal\n" + chartRendererLine(s.glRenderer);
}

}  // namespace

LineChartSpec cascadeChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                               float minFontPx) {
    std::vector<CascadePoint> points = cascadePoints(rows);
    if (points.empty()) return emptySweepChartSpec(minFontPx);
    const CascadePoint& first = points.front();
    double lowest = 1e30;
    for (const CascadePoint& p : points) {
        if (p.texelsPerPixelMedian > 0.0) lowest = std::min(lowest, p.texelsPerPixelMedian);
    }
    // The floor: the decade at or below the smallest value measured.
    LineChartSpec spec = logSweepChartSpec(
        "Cascades: texel density against where the splits fall",
        cascadeSubtitle(rows, first, subtitle),
        "split lambda: 0 uniform .. 1 log (Zhang et al.'s practical split between)",
        "texels per screen pixel, median over the cascade's receivers",
        lowest < 1e30 ? std::pow(10.0, std::floor(std::log10(lowest))) : 1e-3, minFontPx);
    // The sphere fit, snapped: its texels are the same along the whole path. (A box fit's
    // farthest cascade, with smaller texels, has most of its ground pixels more than 32 texels
    // from their neighbours near the horizon, which are not measured: the median there is over
    // another population.)
    for (const char* fit : {"sphere"}) {
        ChartPanel panel{std::string(fit) + " fit, snapped", {}};
        for (int c = 0; c < CASCADE_SWEEP_CASCADES; ++c) {
            ChartLine line{"cascade " + std::to_string(c), CASCADE_LINE_COLOURS[c], false, {}};
            for (const CascadePoint& p : points) {
                if (p.method != first.method || p.kernel != first.kernel || p.fit != fit ||
                    !p.snap || p.cascade != c || !(p.texelsPerPixelMedian > 0.0)) {
                    continue;
                }
                line.points.emplace_back(p.lambda, p.texelsPerPixelMedian);
            }
            std::sort(line.points.begin(), line.points.end(),
                      [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x; });
            if (!line.points.empty()) panel.lines.push_back(std::move(line));
        }
        if (!panel.lines.empty()) spec.panels.push_back(std::move(panel));
    }
    spec.notes.push_back("below 1: a texel spreads over several pixels");
    spec.notes.push_back("a line ends where its cascade");
    spec.notes.push_back("holds no receiver on screen");
    return spec;
}

}  // namespace pcf
