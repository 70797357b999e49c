// speed_chart.h: the bench's picture, speed_vs_accuracy.png. Camera-pass or lookup-pass time
// (ChartTiming) with an error bar as wide as its IQR on a LOG x axis
// (each run's cost spans 1 to ~200 texel reads), edge-band RMSE on a linear y axis from 0, one
// solid dot per run coloured by method and labelled "gather3 1024" (method, N, map size), and the
// Pareto front of the medians (runs no other run beats on both median time and error), its dots
// ringed and joined by a line where their bars are apart. On a CPU rasteriser the times are the
// process CPU time (bench_report.h: benchTimesByCpu), and the x axis's name says so. The spread
// is drawn, not judged: every dot has its bar, so where two bars overlap the reader sees that
// another run of the bench could order those dots the other way, and no front line claims an
// order between them (on llvmpipe sharing two cores most wall-clock IQRs exceed a tenth of the
// median, and a mark for "noisy" would have been on nearly every dot).
// Drawn with the overlay's Canvas (src/draw/canvas.h) into an offscreen target.
//
// The layout is computed apart from the drawing (no GL), so where things go can be tested
// without reading pixels; the dots' names are placed by speed_chart_labels.h. Coordinates are the
// canvas's: pixels, origin top-left, y down.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "draw/rect.h"
#include "measure/bench.h"

namespace pcf {

// Which time the x axis shows (bench.h): the camera pass, or the filter alone as a bare lookup
// pass.
enum class ChartTiming { Scene, Lookup };
// The row's median and IQR of that time, ms.
double chartMs(const BenchRow& row, ChartTiming timing);
double chartIqr(const BenchRow& row, ChartTiming timing);

// Which accuracy the y axis shows: the edge band's RMSE (the filter's aliasing error,
// speed_vs_accuracy.png), or the shimmer as the map's grid slides (bench.h; the 99th percentile
// of a flickering pixel's change per 1/32-texel step, speed_vs_stability.png), or the edge
// band's RMSE near the casters only (bench.h: contactDistance, speed_vs_contact.png).
enum class ChartAccuracy { EdgeRmse, Shimmer, ContactRmse };
double chartAccuracy(const BenchRow& row, ChartAccuracy accuracy);

// Every dot's time has a labelled x tick within this factor of it, and each decade that holds a
// dot a labelled tick in it (3 labels at least): a dot past the last label (17.4's four dots past
// "10") cannot be read off the axis.
constexpr double SPEED_CHART_TICK_REACH = 1.25;

struct ChartTick {
    double value = 0.0;
    float pixel = 0.0f;  // x for the x axis, y for the y axis
    std::string text;    // empty: a gridline without a label
};

struct SpeedChartText {
    std::string title;     // e.g. "Speed against accuracy: box-on-plane, 1280x720"
    std::string subtitle;  // e.g. the GL_RENDERER and the timer
    std::string xLabel = "camera pass time, ms (log scale)";
    std::string yLabel = "edge-band RMSE of visibility";
    // Rows ringed in orange: the dots a lesson step talks about (chartRowsMatching). The chart
    // names them (and not the front's, which are named where nothing is ringed).
    std::vector<size_t> highlight;
    // No text below this many pixels (a lesson frame asks for its type floor; a projector needs
    // 14 or more), and with keptLabelsOnly only the dots the chart must name are named (the
    // ringed ones, else the front's): large labels for every dot would bury the plot.
    float minFontPx = 8.0f;
    bool keptLabelsOnly = false;
};

// One text the chart draws, where it goes (pixels from the chart's top left) and its size.
struct ChartTextBox {
    Rect rect;
    float fontPx = 0.0f;
    std::string role;  // "chart-title", "chart-subtitle", "chart-axis", "chart-tick",
                       // "chart-label" (a dot's name), "chart-badge" (a badge's number, its
                       // box the badge's disc's: by its dot, and again in the key),
                       // "chart-key" (a dot's name in the key, beside its badge),
                       // "chart-legend"; "chart-swatch": not a text but the box a legend
                       // entry's mark covers (text: the entry's words, fontPx 0), which no
                       // text may cover
    std::string text;
    int row = -1;     // chart-label, chart-badge, chart-key: the row it names
    int method = -1;  // chart-legend: the method it names (-1: the front's entry)
};

struct SpeedChartLayout {
    glm::ivec2 size{0, 0};
    float scale = 1.0f;                 // 1 at 1280x720; fonts and strokes grow with it
    int subtitleLines = 1;              // the room the title leaves under it for the subtitle
    Rect plot;                          // the plotting area
    double xLogLo = 0.0, xLogHi = 1.0;  // log10(ms) at the plot's left and right edges
    double yLo = 0.0, yHi = 1.0;        // RMSE at the plot's bottom and top edges
    std::vector<ChartTick> xTicks;
    std::vector<ChartTick> yTicks;
    std::vector<glm::vec2> points;  // per row: the dot's centre
    // per row: the error bar's left and right x, the time's median -/+ half its IQR (a bar
    // as wide as the IQR, centred on the median; the CSV keeps the IQR, not the quartiles)
    std::vector<glm::vec2> errorBars;
    std::vector<std::string> labelTexts;  // per row
    std::vector<Rect> labels;             // per row: where its label's box goes
    // per row: whether its label is drawn, only where it finds a clean spot
    // (speed_chart_labels.h): in the plot, on no other name or badge, no dot or ring (its own
    // too) and no error bar, and nearer its own dot than any other. A row the chart must name
    // looks within speedChartNameReach of its dot, any other only right beside it.
    std::vector<bool> labelShown;
    // Rows ringed in orange (SpeedChartText::highlight), and the rows the chart must name: the
    // ringed ones, or the front's where none is ringed.
    std::vector<size_t> highlight;
    std::vector<size_t> mustName;
    // per row: its badge's number (1, 2, ... in the order of the dots' times; 0: none) and the
    // box of its disc: a row the chart must name whose name found no clean spot within reach.
    // The badge touches the dot (or its outer ring) where a clean spot does; in a crowd where
    // none does, it is centred on the dot and drawn in its place (badgeOnDot), covering no
    // other dot's centre. The key, under the x axis, gives each number its name.
    std::vector<int> badge;
    std::vector<Rect> badgeBoxes;
    std::vector<bool> badgeOnDot;
    float badgeRadius = 0.0f;     // pixels; its number is labelPx
    int keyLines = 0;             // the lines kept for the key under the x axis's name
    std::vector<size_t> keyRows;  // per key entry (badge number - 1): the row
    std::vector<Rect> keyBadges;  // per key entry: its badge's box; the name follows it
    std::vector<size_t> front;    // rows on the Pareto front, fastest first
    // Per step of the front (front[k - 1] to front[k], k >= 1): whether the line joins them. Not
    // where their time bars overlap (bench_report.h: benchSpreadsOverlap): a line from one to the
    // next says the second costs more, which such spreads do not support.
    std::vector<bool> frontJoined;
    std::vector<int> legendMethods;  // methods present, in the rows' order of appearance
    Rect legend;
    // Per legend line (the methods', then the front's): the box its mark covers (a dot; the
    // front's line through a ringed dot) grown by CHART_MARK_CLEARANCE (chart_axes.h), in a
    // column wide enough for the dot at its size; the names start right of it, at legendTextX.
    std::vector<Rect> legendSwatches;
    float legendTextX = 0.0f;
    // The type sizes, pixels: scaled with the chart, none below the minimum asked for.
    float titlePx = 0, subtitlePx = 0, axisPx = 0, tickPx = 0, labelPx = 0, legendPx = 0;
    float dotRadius = 4.5f;  // pixels; a quarter of the label size at least, to see from afar
};

// What the bars through the dots are: "bars: IQR of the repeated times, centred on the median"
// (bench.csv keeps each time's median and IQR, not its quartiles). The subtitle says it (a legend
// line wrapped to the names' width took seven lines and ran off a lesson frame's chart).
std::string spreadNote();

// The legend's line for the front's mark, which states its rule: the front of the medians.
inline constexpr const char* FRONT_LEGEND = "Pareto front of medians";
// The legend's entry for the orange rings of a lesson's chart_highlight: they mark the dots the
// step's words name, not a front (16.6 ringed pcss, off the front, with nothing to say why).
inline constexpr const char* HIGHLIGHT_LEGEND = "named in the text";

// The x axis's name: the pass (timing) and the clock its times are by (bench_report.h:
// benchTimesByCpu of the rows), e.g. "camera pass, process CPU time, ms (log scale)".
std::string speedChartXLabel(std::span<const BenchRow> rows, ChartTiming timing);

// The GL_RENDERER the rows were measured on (bench.csv's gl_renderer), "" when not recorded.
std::string speedChartRenderer(std::span<const BenchRow> rows);
// The truth the rows' errors are against, in the report's words (bench.csv's truth: "area (a
// sun disk of 2 degrees)"), "" when not recorded.
std::string speedChartTruth(std::span<const BenchRow> rows);

// The contact chart's y axis (ChartAccuracy::ContactRmse): "aliasing near the contacts:
// edge-band RMSE over the 676 edge pixels within 1 world unit of a caster" (the rows'
// contact_edge_pixels and contact_distance); brief: "edge-band RMSE within 1 world unit of a
// caster", for a lesson frame's narrow chart.
std::string contactAxisLabel(std::span<const BenchRow> rows, bool brief = false);

// The text as drawn: when any row has a bar (an IQR above 0 in the timing), spreadNote ends the
// subtitle; the subtitle is wrapped at spaces to the chart's width at its type size ('\n' still
// breaks: a lesson frame's chart is narrow). drawSpeedChart draws this; a caller that lays the
// texts out itself lays out this.
SpeedChartText speedChartTextFor(std::span<const BenchRow> rows, const SpeedChartText& text,
                                 glm::ivec2 size, ChartTiming timing = ChartTiming::Scene);

// The lines a subtitle takes ('\n' separates them): layoutSpeedChart's subtitleLines.
int subtitleLineCount(const std::string& subtitle);

// "gather3 1024", "nearest 256", "gather3 gauss1.5 1024": the label of one run.
std::string chartLabel(const BenchPoint& point);
// The rows a lesson's `chart_highlight` names, in row order: a comma-separated list of "front"
// (the Pareto front of the scene timing), full labels ("gather3 256") and label first words
// ("gather3": that method and N at every map size). Throws std::invalid_argument naming a
// selector that matches no row.
std::vector<size_t> chartRowsMatching(std::span<const BenchRow> rows, const std::string& selectors);
// The colour of a method's dots and legend swatch.
glm::vec4 methodColour(int method);

// Where everything goes. Needs the fonts (to measure labels), not GL. Times <= 0 are drawn at
// the axis's low end. Throws std::invalid_argument for a side < 64 pixels.
// The Pareto front is of median time against the chosen accuracy, over every row. highlight:
// the rows ringed in orange, which the chart names (where empty, it names the front's).
SpeedChartLayout layoutSpeedChart(std::span<const BenchRow> rows, glm::ivec2 size,
                                  ChartTiming timing = ChartTiming::Scene,
                                  ChartAccuracy accuracy = ChartAccuracy::EdgeRmse,
                                  std::span<const size_t> highlight = {}, float minFontPx = 8.0f,
                                  bool keptLabelsOnly = false, int subtitleLines = 1);

// The marks a label must keep off and by: a row's dot (its disc's box), the outer radius of the
// dot with the rings drawn round it (the front's black ring, a highlighted dot's orange one),
// its error bar (the line and its end ticks; empty where the IQR is under a pixel and no bar is
// drawn), and the leader drawLeaders draws from a dot's outer ring to its label's nearest point,
// only where the label is shown and lies more than a dot radius beyond that ring.
Rect speedChartDotBox(const SpeedChartLayout& layout, size_t row);
float speedChartMarkRadius(const SpeedChartLayout& layout, size_t row);
Rect speedChartBarBox(const SpeedChartLayout& layout, size_t row);
struct ChartLeader {
    glm::vec2 from, to;
};
std::optional<ChartLeader> speedChartLeader(const SpeedChartLayout& layout, size_t row);

// Every text the chart draws (drawSpeedChart sets them where these say): the boxes a lesson
// frame lists in its layout.
std::vector<ChartTextBox> speedChartTextBoxes(const SpeedChartLayout& layout,
                                              const SpeedChartText& text);

// The chart as RGBA8, rows top-down (for writePngRgba8), size.x * size.y * 4 bytes. Needs a
// current OpenGL 4.5 context; leaves its framebuffer bindings as it found them.
std::vector<uint8_t> drawSpeedChart(std::span<const BenchRow> rows, glm::ivec2 size,
                                    const SpeedChartText& text,
                                    ChartTiming timing = ChartTiming::Scene,
                                    ChartAccuracy accuracy = ChartAccuracy::EdgeRmse);

}  // namespace pcf
