// stability_chart.h: the stability command's pictures, drawn with the overlay's Canvas into an
// offscreen target (as speed_chart.h does for the bench):
//   line charts in small multiples (panels of lines) and bar charts (groups of bars, one colour
//   per series); which charts the stability command draws is stability_figures.h's.
// Coordinates are the canvas's: pixels, origin top-left, y down.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "charts/speed_chart.h"

namespace pcf {

struct ChartLine {
    std::string label;  // legend entry; lines with the same label share one entry
    glm::vec4 colour{0.0f, 0.0f, 0.0f, 1.0f};
    bool dashed = false;
    std::vector<glm::dvec2> points;  // (x, y), drawn in this order
    // Drawn this many pixels (at 1280x720; scaled with the chart) below its place: a line that
    // coincides with an earlier one of its panel stays visible (markCoincidentLines).
    float offsetPx = 0.0f;
};

struct ChartPanel {
    std::string title;
    std::vector<ChartLine> lines;
    // An x range shaded behind the lines (lowest, highest x; e.g. the trade-off chart's good
    // biases), at least a few pixels wide where the two are one point; a note names it.
    std::optional<glm::dvec2> band = std::nullopt;
    // The name a lesson's chart anchor picks the panel by ("lbr" in "#bleed:lbr"); empty: none.
    std::string name = {};
};

// The shade of a panel's band.
inline const glm::vec4 CHART_BAND{0.80f, 0.93f, 0.80f, 1.0f};

struct LineChartSpec {
    std::string title;
    std::string subtitle;
    std::string xLabel;
    std::string yLabel;
    bool logX = false;
    bool reverseX = false;  // largest x on the left
    bool percentY = false;  // y is a share: ticks as percents
    double yFloor = 0.0;    // y axis starts here; its top is the data's maximum, rounded up
    // A log y axis from yFloor (> 0, a power of ten) up to the decade above the data (a share: to
    // 100 %), a tick per decade. Values at or under the floor, 0 among them, lie on the floor's
    // line, whose tick says so ("<=0.1%"): small shares and large ones read on one axis.
    bool logY = false;
    std::vector<ChartPanel> panels;
    std::vector<std::string> notes;  // legend lines without a swatch (e.g. "dashed: pole")
    std::string notesPanel;          // the named panel the notes speak of; empty: the whole chart
    float minFontPx = 8.0f;          // no text below this (a lesson frame asks for its floor)
};

// The chart as RGBA8, rows top-down. Needs a current OpenGL 4.5 context; leaves its framebuffer
// bindings as it found them. Throws std::invalid_argument for a side < 64 or no panel.
std::vector<uint8_t> drawLineChart(const LineChartSpec& spec, glm::ivec2 size);

struct BarGroup {
    std::string label;           // under the group, e.g. "gather5 constant"
    std::vector<double> values;  // one bar per series
};

struct BarChartSpec {
    std::string title;
    std::string subtitle;
    std::string yLabel;
    std::vector<std::string> series;  // legend, one colour each
    std::vector<BarGroup> groups;
    float minFontPx = 8.0f;  // no text below this (a lesson frame asks for its floor)
};

std::vector<uint8_t> drawBarChart(const BarChartSpec& spec, glm::ivec2 size);

// A picture with a colour scale: the image scaled to fit (nearest pixel, the same factor on both
// axes), at its right a vertical colour bar with its ticks and label, and swatches below it.
struct ColourScale {
    std::string label;                                        // above the bar
    std::vector<glm::vec4> colours;                           // bottom to top, evenly spaced
    std::vector<std::pair<double, std::string>> ticks;        // position in [0,1] from the bottom
    std::vector<std::pair<glm::vec4, std::string>> swatches;  // e.g. grey: "not measured"
};

struct ImageChartSpec {
    std::string title;
    std::string subtitle;
    glm::ivec2 imageSize{0, 0};
    std::vector<uint8_t> rgba;  // imageSize, rows top-down
    ColourScale scale;
    float minFontPx = 8.0f;
};

std::vector<uint8_t> drawImageChart(const ImageChartSpec& spec, glm::ivec2 size);

// Every text the chart draws, where it is drawn (pixels from the chart's top left; one code path
// lays out and draws), with its role: "chart-title" (the chart's and each small multiple's),
// "chart-subtitle", "chart-axis", "chart-tick", "chart-label" (a bar group's name), "chart-value"
// (a "0" over a bar of height 0), "chart-legend" (also a colour scale's label, ticks and swatches'
// words); and where each legend entry's mark goes, "chart-swatch" (no text to draw: the entry's
// words, font size 0), which no text may cover. Needs the fonts, not GL; throws as the draw
// functions do.
std::vector<ChartTextBox> lineChartTextBoxes(const LineChartSpec& spec, glm::ivec2 size);
std::vector<ChartTextBox> barChartTextBoxes(const BarChartSpec& spec, glm::ivec2 size);
std::vector<ChartTextBox> imageChartTextBoxes(const ImageChartSpec& spec, glm::ivec2 size);

// The colour of a bias mode's lines and bars (by its name; an unknown name gets ink).
glm::vec4 biasColour(std::string_view bias);

}  // namespace pcf
