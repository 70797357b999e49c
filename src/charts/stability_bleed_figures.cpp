// The bleed sweep's chart (stability_bleed_figures.h): leak against penumbra darkening.
#include "charts/stability_bleed_figures.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

#include "charts/chart_axes.h"
#include "kernel/methods.h"
#include "measure/number_text.h"
#include "measure/stability_bleed.h"
#include "measure/stability_report.h"
#include "scene/presets.h"

namespace pcf {

namespace {

std::string methodLabel(int method, int kernel) {
    std::string label(methodInfo(method).name);
    if (kernel > 0) label += " " + std::to_string(kernel) + "x" + std::to_string(kernel);
    return label;
}

// "stacked-cards, gap G; frame, map; bias, cull" over the renderer's line; `source` alone
// without a setup.
std::string bleedSubtitle(std::span<const StabilityRow> rows, double gap,
                          const std::string& source) {
    std::optional<StabilitySetup> setup = stabilitySetupOf(rows);
    if (!setup) return source;
    const StabilitySetup& s = *setup;
    std::string bias;
    for (const StabilityRow& r : rows) {
        if (r.sweep == sweepName(Sweep::Bleed)) bias = r.bias;
    }
    return std::string(BLEED_PRESET) + ", gap " + chartTickText(gap) + " between the cards, " +
           "1 degree sun; " + std::to_string(s.frameSize.x) + "x" + std::to_string(s.frameSize.y) +
           " frame, map " + std::to_string(s.mapSize) + "^2; bias mode " + bias + ", " +
           s.settings + "\n" + chartRendererLine(s.glRenderer);
}

}  // namespace

double bleedChartGap(std::span<const StabilityRow> rows) {
    const double preferred = presetParams(BLEED_PRESET).front().defaultValue;
    double best = 0.0;
    for (const BleedPoint& p : bleedPoints(rows)) {
        if (best == 0.0 || std::abs(p.gap - preferred) < std::abs(best - preferred)) best = p.gap;
    }
    return best;
}

LineChartSpec bleedChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                             float minFontPx) {
    LineChartSpec spec;
    spec.minFontPx = minFontPx;
    std::vector<BleedPoint> points = bleedPoints(rows);
    if (points.empty()) return spec;
    const double gap = bleedChartGap(rows);
    spec.title = "Light bleeding: leak in the lower card's umbra against penumbra darkening";
    spec.subtitle = bleedSubtitle(rows, gap, subtitle);
    spec.xLabel = "penumbra darkening: mean of truth - v over the area truth's penumbra";
    spec.yLabel = "leak: 99th percentile of v over the lower card's clean umbra";
    spec.logY = true;
    spec.yFloor = 1e-4;
    ChartPanel panel{"a line per method over its first setting swept", {}};
    // A line per method over the first setting swept for it (the sweep's order: the
    // light-bleeding reduction first; the others are in stability_bleed.csv), in the rows' order;
    // a method measured at the run's settings alone, a dot.
    std::vector<std::pair<std::string, std::vector<const BleedPoint*>>> lines;
    std::map<std::pair<int, int>, std::string> firstKey;
    for (const BleedPoint& p : points) {
        if (p.gap != gap) continue;
        if (firstKey.try_emplace({p.method, p.kernel}, p.key).first->second != p.key) continue;
        std::string label = methodLabel(p.method, p.kernel) + (p.key.empty() ? "" : ", " + p.key);
        if (lines.empty() || lines.back().first != label) lines.push_back({label, {}});
        lines.back().second.push_back(&p);
    }
    for (const auto& [label, line] : lines) {
        ChartLine l{label, methodInfo(line.front()->method).chartColour, false, {}};
        const BleedPoint* under = nullptr;
        for (const BleedPoint* p : line) {
            // x to a thousandth: the chart's x ticks stand at the points' own values, and
            // darkening read closer than that says nothing (the CSV keeps every digit).
            l.points.emplace_back(std::round(-p->penumbraError * 1000.0) / 1000.0, p->leakP99);
            if (!under && p->leakP99 < BLEED_LEAK_TARGET) under = p;
        }
        panel.lines.push_back(std::move(l));
        const BleedPoint& first = *line.front();
        if (first.key.empty()) continue;
        // Short lines: the notes stand under the legend, beside the plot.
        spec.notes.push_back(methodLabel(first.method, first.kernel) + ": " + first.key + " " +
                             first.value + " to " + line.back()->value);
        if (under) {
            char darkening[32];
            std::snprintf(darkening, sizeof darkening, "%.2g", -under->penumbraError);
            spec.notes.push_back("  leak < " + chartTickText(BLEED_LEAK_TARGET) + " from " +
                                 under->value + ", darkening " + darkening);
        }
    }
    spec.panels.push_back(std::move(panel));
    return spec;
}

}  // namespace pcf
