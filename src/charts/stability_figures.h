// stability_figures.h: the charts `pcfscope stability` writes and lessons 13 and 14 show, built
// from stability.csv's rows (stability.h, stability_report.h) and drawn by stability_chart.h:
//   acne       false-shadow rate against the light's elevation: one panel per method, a line per
//              bias;
//   leak       leak width against the constant bias: a panel per method, a line per bias, the
//              second contact scene dashed;
//   tradeoff   acne (at one elevation) and leak (at the contacts) against the constant bias, as
//              shares of their clean pixels on a log axis (0.1 % to 100 %): a panel per method,
//              the good biases shaded;
//   precision  false-shadow rate against the light's depth range: a panel per bias, a line per
//              depth format, the second method dashed;
//   shimmer    mean change per frame over the same edge pixels, per method and bias;
//   aliasing   the heat map of screen pixels per shadow-map texel, with its colour scale.
// Each states its one population and metric in its title and the settings it was measured with
// in its subtitle.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "charts/stability_chart.h"
#include "measure/stability.h"

namespace pcf {

// Lines of one panel whose points all equal an earlier line's (same style) would hide under it:
// each such line is drawn COINCIDENT_OFFSET_PX lower per earlier twin, and a note names them
// ("pcf-gather 5x5: constant = none, drawn 4 px lower").
constexpr float COINCIDENT_OFFSET_PX = 4.0f;
void markCoincidentLines(LineChartSpec& spec);

// A method's name on the sweep charts: "vsm 5x5", "nearest" (kernel 0).
std::string chartMethodLabel(int method, int kernel);

// A sweep's line chart on a log y axis from yFloor (a power of ten): its texts set, no panel yet
// (the bleed and cascades charts start from it).
LineChartSpec logSweepChartSpec(std::string title, std::string subtitle, std::string xLabel,
                                std::string yLabel, double yFloor, float minFontPx);
// The spec of a sweep chart whose rows hold no point: no panel, nothing to draw.
LineChartSpec emptySweepChartSpec(float minFontPx);

// The lines under a stability chart's title: the scene, frame, map and bias settings the rows
// were measured with and the renderer (from the rows' setup, stability_report.h), and for
// llvmpipe what carries over to a GPU (chart_axes.h: chartRendererLine). `source` (e.g.
// "measured by pcfscope stability, stability.csv") only when the rows carry no setup: the setup
// says it all, and a lesson's smaller chart keeps the room for its plot.
std::string stabilityChartSubtitle(std::span<const StabilityRow> rows, Sweep sweep,
                                   const std::string& source);

// The specs of the charts below (no panel or group when the rows have none of that sweep). Each
// states its one population and metric in its title, and its settings in its subtitle
// (stabilityChartSubtitle with `subtitle` as the source).
LineChartSpec acneChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                            float minFontPx = 8.0f);
LineChartSpec leakChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                            float minFontPx = 8.0f);
LineChartSpec precisionChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                 float minFontPx = 8.0f);
BarChartSpec shimmerChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                              float minFontPx = 8.0f);

// Acne or leak on more than this share of their clean pixels counts (the acne chart's onset
// line: "1% = acne onset").
constexpr double TRADEOFF_ONSET = 0.01;

// One method's trade-off, read from the tradeoff rows (acne) and the leak rows (constant mode):
// at each swept constant bias, ascending, the false-shadow rate at the tradeoff elevation and
// the leak rate of each contact scene (a bias the leak sweep did not run: no leak there).
struct TradeoffSeries {
    StabilityMethod method;
    std::string name;  // the panel's title: "pcf-gather 5x5"
    std::vector<double> biases;
    std::vector<double> acne;
    std::vector<std::string> leakScenes;
    std::vector<std::vector<std::optional<double>>> leak;  // [scene][bias]
    // The good biases: the first run of swept biases where acne and every scene's leak stay
    // under TRADEOFF_ONSET (lowest, highest); nullopt when there is none.
    std::optional<glm::dvec2> good;
};
std::vector<TradeoffSeries> tradeoffSeries(std::span<const StabilityRow> rows);

LineChartSpec tradeoffChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                float minFontPx = 8.0f);
std::vector<uint8_t> drawTradeoffChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                       const std::string& subtitle, float minFontPx = 8.0f);

// The charts `pcfscope stability` writes, from its rows: acne rate against elevation (empty when
// no acne row), leak width against bias, false-shadow rate against the depth range per depth
// format, shimmer per method. Each is RGBA8 of `size`, no text
// below minFontPx.
std::vector<uint8_t> drawAcneChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                   const std::string& subtitle, float minFontPx = 8.0f);
std::vector<uint8_t> drawLeakChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                   const std::string& subtitle, float minFontPx = 8.0f);
std::vector<uint8_t> drawPrecisionChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                        const std::string& subtitle, float minFontPx = 8.0f);
std::vector<uint8_t> drawShimmerChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                      const std::string& subtitle, float minFontPx = 8.0f);

// aliasing_heatmap.png as a chart: the sweep's heat map (stability.h: aliasingHeatColour per
// pixel, at the run's map size) with its colour scale, the map size and the median and 99th
// percentile from the rows in the title and subtitle.
// The sweep charts, one entry per charted sweep (the aliasing heat map is an image, not a chart):
// the file `pcfscope stability` writes it to, and how it is drawn and where its texts go. A lesson
// step shows one as "stability.csv#NAME" (step_chart.h), NAME its sweep's name. A new chart is
// one entry here.
struct SweepChart {
    Sweep sweep;
    std::string_view file;  // "stability_acne.png"
    std::vector<uint8_t> (*draw)(std::span<const StabilityRow> rows, glm::ivec2 size,
                                 const std::string& subtitle, float minFontPx);
    std::vector<ChartTextBox> (*texts)(std::span<const StabilityRow> rows, glm::ivec2 size,
                                       const std::string& subtitle, float minFontPx);
    // Whether `rows` hold anything the chart plots (a point, a bar): rows of its sweep whose
    // metrics it does not read would draw an empty chart.
    bool (*hasData)(std::span<const StabilityRow> rows);
    // The chart's spec, for a line chart whose panels have names (ChartPanel::name) a lesson may
    // pick ("#bleed:lbr"); nullptr for the others.
    LineChartSpec (*lineSpec)(std::span<const StabilityRow> rows, const std::string& subtitle,
                              float minFontPx) = nullptr;
};
std::span<const SweepChart> sweepCharts();
// The entry of the sweep named so ("acne"); nullptr when no chart is.
const SweepChart* sweepChartNamed(std::string_view name);
// "#acne, #leak, #tradeoff, #shimmer, #precision": the names a lesson's chart may end in.
std::string sweepChartNames();

ImageChartSpec aliasingHeatmapSpec(const StabilityImage& heatmap,
                                   std::span<const StabilityRow> rows, const std::string& source,
                                   float minFontPx = 8.0f);

}  // namespace pcf
