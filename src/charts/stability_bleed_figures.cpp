// The bleed sweep's chart (stability_bleed_figures.h): leak against penumbra darkening.
#include "charts/stability_bleed_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "charts/chart_axes.h"
#include "charts/stability_figures.h"
#include "kernel/methods.h"
#include "measure/number_text.h"
#include "measure/stability_bleed.h"
#include "measure/stability_report.h"
#include "scene/presets.h"

namespace pcf {

namespace {

// "lbr 0 to 0.5 (6 values), moment_format 16f, 32f": each setting swept at `gap`, the values
// as the command line writes them.
std::string bleedSweptSettings(std::span<const BleedSeries> series) {
    std::string out;
    for (const std::string& key : bleedKeys(series)) {
        std::vector<std::string> values;
        for (const BleedSeries& s : series) {
            if (s.key != key) continue;
            for (const BleedPoint& p : s.points) {
                if (std::find(values.begin(), values.end(), p.value) == values.end()) {
                    values.push_back(p.value);
                }
            }
        }
        if (!out.empty()) out += "; ";
        out += key + " ";
        if (values.size() <= 2) {
            out += values.front() + (values.size() == 2 ? ", " + values.back() : "");
        } else {
            out += values.front() + " to " + values.back() + " (" + std::to_string(values.size()) +
                   " values)";
        }
    }
    return out.empty() ? "no setting swept" : "swept: " + out;
}

// "stacked-cards, gap G; frame, map; bias, cull", the settings swept, over the renderer's line;
// `source` alone without a setup.
std::string bleedSubtitle(std::span<const StabilityRow> rows, std::span<const BleedSeries> series,
                          double gap, const std::string& source) {
    std::optional<StabilitySetup> setup = stabilitySetupOf(rows);
    if (!setup) return source + "\n" + bleedSweptSettings(series);
    const StabilitySetup& s = *setup;
    std::string bias;
    for (const StabilityRow& r : rows) {
        if (r.sweep == sweepName(Sweep::Bleed)) bias = r.bias;
    }
    return std::string(BLEED_PRESET) + ", gap " + chartTickText(gap) + " between the cards, " +
           "1 degree sun; " + std::to_string(s.frameSize.x) + "x" + std::to_string(s.frameSize.y) +
           " frame, map " + std::to_string(s.mapSize) + "^2; bias mode " + bias + ", " +
           s.settings + "\n" + bleedSweptSettings(series) + "\n" + chartRendererLine(s.glRenderer);
}

ChartLine bleedChartLine(const BleedSeries& s) {
    ChartLine l{chartMethodLabel(s.method, s.kernel), methodInfo(s.method).chartColour, false, {}};
    for (const BleedPoint& p : s.points) {
        // x to a thousandth: the chart's x ticks stand at the points' own values, and
        // darkening read closer than that says nothing (the CSV keeps every digit).
        l.points.emplace_back(std::round(-p.penumbraError * 1000.0) / 1000.0, p.leakP99);
    }
    return l;
}

// "vsm 5x5: leak < 0.001 from lbr 0.3, darkening 0.052" (or "leak >= 0.001 at every lbr").
std::string bleedCleanNote(const BleedSeries& s) {
    std::string name = chartMethodLabel(s.method, s.kernel);
    std::string target = chartTickText(BLEED_LEAK_TARGET);
    const BleedPoint* clean = firstCleanPoint(s);
    if (!clean) return name + ": leak >= " + target + " at every " + s.key;
    char darkening[32];
    std::snprintf(darkening, sizeof darkening, "%.2g", -clean->penumbraError);
    return name + ": leak < " + target + " from " + s.key + " " + clean->value + ", darkening " +
           darkening;
}

}  // namespace

LineChartSpec bleedChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                             float minFontPx) {
    std::vector<BleedPoint> points = bleedPoints(rows);
    if (points.empty()) return emptySweepChartSpec(minFontPx);
    const double gap = bleedChartGap(rows);
    std::vector<BleedSeries> series = bleedSeries(points, gap);
    LineChartSpec spec = logSweepChartSpec(
        "Light bleeding: leak in the lower card's umbra against penumbra darkening",
        bleedSubtitle(rows, series, gap, subtitle),
        "penumbra darkening: mean of truth - v over the area truth's penumbra",
        "leak: 99th percentile of v over the lower card's clean umbra", 1e-4, minFontPx);
    std::vector<std::string> keys = bleedKeys(series);
    // A panel per setting swept; the methods no setting acts for, dots in each.
    if (keys.empty()) keys.push_back("");
    for (const std::string& key : keys) {
        ChartPanel panel{key.empty() ? "at the run's settings" : "over " + key, {}};
        panel.name = key;
        for (const BleedSeries& s : series) {
            if (s.key.empty() || s.key == key) panel.lines.push_back(bleedChartLine(s));
        }
        spec.panels.push_back(std::move(panel));
    }
    // Short lines: the notes stand under the legend, beside the plots.
    spec.notesPanel = keys.front();
    for (const BleedSeries& s : series) {
        if (!s.key.empty() && s.key == keys.front()) spec.notes.push_back(bleedCleanNote(s));
    }
    return spec;
}

}  // namespace pcf
