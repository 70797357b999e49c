// stability_bleed.h: where filtering the depths mixes two occluders, measured (stability.h's
// bleed sweep). On the stacked-cards preset (presets.h: a small card above a larger one, the
// gap between them swept), per method (the run's methods and StabilityOptions::bleedMethods) at
// the run's settings and at each value of each setting swept that acts for it (by its key in the
// settings table, kernel/settings.h: paramActsFor), against the area-light truth
// (ground_truth.h):
//   leak            visibility over the lower card's CLEAN UMBRA: the pixels whose ray toward
//                   the light's centre hits the lower card (lowerCardUmbra) and that the truth
//                   calls fully shadowed at the pixel and over the method's whole footprint
//                   (failure_measures.h: cleanPixelMask, reach as the other sweeps'), so a
//                   filter's legitimate softening of the lower card's own edge is not counted;
//                   the mean ("leak_mean") and the 99th percentile ("leak_p99").
//   penumbra_error  the mean of v - truth over the truth's penumbra (PCSS_PENUMBRA_LO < truth <
//                   PCSS_PENUMBRA_HI, compared pixels): negative = darkened.
// The rows (stability.csv, x_name "gap") carry the setting in the metric's prefix,
// "KEY=VALUE:leak_mean" (a comma in VALUE written ';'), none for a method no swept setting acts for
// (measured at the run's settings alone); stability_bleed.csv lays them out one line per point
// (bleedCsv).
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/settings.h"
#include "measure/stability.h"

namespace pcf {

// The preset the sweep runs on and its two cards (presets.cpp).
inline constexpr std::string_view BLEED_PRESET = "stacked-cards";
inline constexpr std::string_view BLEED_LOWER_CARD = "lower-card";

// stacked-cards at `gap` (presets.h: its gap parameter).
Scene bleedScene(double gap);

// Per pixel of a `size` frame (rows top-down, as centreHits): 1 where the surface seen at the
// centre is not `object` and its ray toward the light's centre hits `object`.
std::vector<uint8_t> objectUmbra(const Scene& scene, const std::vector<std::optional<Hit>>& hits,
                                 int object);

// The bleed options' problem (gaps out of the preset's range, a setting key not in the table or
// a value it refuses), nullopt when none: part of validateStabilityOptions.
std::optional<ParamProblem> validateBleedOptions(const StabilityOptions& options);

// Runs the sweep and appends its rows. Needs a current OpenGL 4.5 context.
void runBleedSweep(const StabilityOptions& options,
                   const std::function<void(const std::string&)>& say,
                   std::vector<StabilityRow>& rows);

// One point of the sweep, as stability_bleed.csv has it.
struct BleedPoint {
    int method = -1;
    int kernel = 0;
    double gap = 0.0;
    std::string key;    // the swept setting's key, "" at the method's defaults
    std::string value;  // its value's text
    double leakMean = 0.0;
    double leakP99 = 0.0;
    double penumbraError = 0.0;
};

// The bleed rows' points, in the rows' order.
std::vector<BleedPoint> bleedPoints(std::span<const StabilityRow> rows);

// The leak (99th percentile) the chart and the report call clean.
inline constexpr double BLEED_LEAK_TARGET = 1e-3;

// The gap the chart and the report show: the stacked-cards preset's default when the sweep ran
// it, else the nearest it ran (0 when the rows hold no bleed point).
double bleedChartGap(std::span<const StabilityRow> rows);

// One method's points at one gap over one swept setting's values, in the sweep's order (`key`
// "": the method measured at the run's settings alone, one point).
struct BleedSeries {
    int method = -1;
    int kernel = 0;
    std::string key;
    std::vector<BleedPoint> points;
};

// The series of the points at `gap`, in the order they were measured.
std::vector<BleedSeries> bleedSeries(std::span<const BleedPoint> points, double gap);

// The swept settings' keys at `gap`, in the order they were swept.
std::vector<std::string> bleedKeys(std::span<const BleedSeries> series);

// The first point of `s` whose leak's 99th percentile is under BLEED_LEAK_TARGET, nullptr when
// none is.
const BleedPoint* firstCleanPoint(const BleedSeries& s);

// stability.md's light-bleeding paragraph (empty without bleed rows): at the chart's gap, per
// method and setting swept, the leak at its first value, the first value whose leak is under
// BLEED_LEAK_TARGET and the penumbra darkening there.
std::string bleedMarkdown(std::span<const StabilityRow> rows);

// The file `pcfscope stability` writes bleedCsv into, beside stability.csv.
inline constexpr std::string_view BLEED_CSV_NAME = "stability_bleed.csv";

// The CSV's first line, exactly (no trailing newline).
inline constexpr std::string_view BLEED_CSV_HEADER =
    "sweep,method,kernel,gap,lbr,exponents,moment_bias,moment_format,leak_mean,leak_p99,"
    "penumbra_error";

// The header, then one line per point: the method's name, its kernel (0 for none), the gap; in
// each setting's column the swept value, or the run's (`base`) where the setting acts for the
// method (kernel/settings.h: paramActsFor), empty where it does not (every setting column of a
// method that compares depths); the exponents as used, clamped to what the point's moment
// format holds (ShadowSettings::evsmExponentsUsed), not as asked; the three numbers with 9
// significant digits.
std::string bleedCsv(std::span<const StabilityRow> rows, const ShadowSettings& base);

}  // namespace pcf
