// stability_bleed_figures.h: the bleed sweep's chart (stability_bleed.h), listed in
// stability_figures.h's sweepCharts: at one gap (stability_bleed.h: bleedChartGap), each
// method's leak in the lower card's clean umbra (99th percentile, log scale) against how much it
// darkens the truth's penumbra (the mean of truth - v there). A panel per setting swept, in the
// sweep's order (lbr, evsm_exponents, moment_bias, moment_format by default): in it a line per
// method the setting acts for, through the setting's values (the trade-off: lbr lowers the leak
// and darkens the penumbra), and a dot per method measured at the run's settings alone (those
// that compare depths), the same dots in every panel. The subtitle lists the settings swept and
// their values; the notes name, for each line of the first panel (the light-bleeding reduction
// in the default sweep), the first value whose leak is under BLEED_LEAK_TARGET and the darkening
// it costs.
#pragma once

#include <span>
#include <string>

#include "charts/stability_chart.h"
#include "measure/stability.h"
#include "measure/stability_bleed.h"

namespace pcf {

// Empty of panels when the rows hold no bleed point. `subtitle`: the source line, used when the
// rows carry no setup.
LineChartSpec bleedChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                             float minFontPx = 8.0f);

}  // namespace pcf
