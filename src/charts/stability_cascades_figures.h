// stability_cascades_figures.h: the cascades sweep's chart (stability_cascades.h), listed in
// stability_figures.h's sweepCharts: texel density against the split's lambda, measured on the
// sweep's first frame, a line per cascade (its texels per screen pixel, the median over the
// receivers that read it, log scale), for the sphere fit, snapped, and the first method the sweep
// ran. A uniform split (lambda 0) gives the near cascade far fewer texels per pixel than the far
// ones; a log split (lambda 1) evens them out.
#pragma once

#include <span>
#include <string>

#include "charts/stability_chart.h"
#include "measure/stability.h"

namespace pcf {

// Empty of panels when the rows hold no cascades point. `subtitle`: the source line, used when
// the rows carry no setup.
LineChartSpec cascadeChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                               float minFontPx = 8.0f);

}  // namespace pcf
