// stability_bleed_figures.h: the bleed sweep's chart (stability_bleed.h), listed in
// stability_figures.h's sweepCharts: at one gap (the stacked-cards preset's default when the
// sweep ran it, else the nearest it ran), each method's leak in the lower card's clean umbra
// (99th percentile, log scale) against how much it darkens the truth's penumbra (the mean of
// truth - v there): a dot per method measured at the run's settings, and a line per method
// through the values of the first setting swept for it (the light-bleeding reduction where it
// acts: leak falls, darkening grows); the notes name, per line, its values, the first whose
// leak is under BLEED_LEAK_TARGET and the darkening it costs.
#pragma once

#include <span>
#include <string>

#include "charts/stability_chart.h"
#include "measure/stability.h"

namespace pcf {

constexpr double BLEED_LEAK_TARGET = 1e-3;

// Empty of panels when the rows hold no bleed point. `subtitle`: the source line, used when the
// rows carry no setup.
LineChartSpec bleedChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                             float minFontPx = 8.0f);

// The gap the chart shows (0 when the rows hold no bleed point).
double bleedChartGap(std::span<const StabilityRow> rows);

}  // namespace pcf
