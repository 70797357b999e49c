// stability_chart.h: the stability command's pictures, drawn with the overlay's Canvas into an
// offscreen target (as speed_chart.h does for the bench):
//   line charts in small multiples: one panel per method, one line per bias (its colour), a
//   second scene dashed: acne rate against elevation, leak width against the constant bias;
//   a bar chart: shimmer per method and bias.
// Coordinates are the canvas's: pixels, origin top-left, y down.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <vector>

#include "analysis/speed_chart.h"
#include "analysis/stability.h"

namespace pcf {

struct ChartLine {
    std::string label;  // legend entry; lines with the same label share one entry
    glm::vec4 colour{0.0f, 0.0f, 0.0f, 1.0f};
    bool dashed = false;
    std::vector<glm::dvec2> points;  // (x, y), drawn in this order
};

struct ChartPanel {
    std::string title;
    std::vector<ChartLine> lines;
};

struct LineChartSpec {
    std::string title;
    std::string subtitle;
    std::string xLabel;
    std::string yLabel;
    bool logX = false;
    bool reverseX = false;  // largest x on the left
    bool percentY = false;  // y is a share: ticks as percents
    double yFloor = 0.0;    // y axis starts here; its top is the data's maximum, rounded up
    std::vector<ChartPanel> panels;
    std::vector<std::string> notes;  // legend lines without a swatch (e.g. "dashed: pole")
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

// Every text the chart draws, where it is drawn (pixels from the chart's top left; one code path
// lays out and draws), with its role: "chart-title" (the chart's and each small multiple's),
// "chart-subtitle", "chart-axis", "chart-tick", "chart-label" (a bar group's name),
// "chart-legend". Needs the fonts, not GL; throws as the draw functions do.
std::vector<ChartTextBox> lineChartTextBoxes(const LineChartSpec& spec, glm::ivec2 size);
std::vector<ChartTextBox> barChartTextBoxes(const BarChartSpec& spec, glm::ivec2 size);

// The colour of a bias mode's lines and bars (by its name; an unknown name gets ink).
glm::vec4 biasColour(std::string_view bias);

// The specs of the charts below (no panel or group when the rows have none of that sweep).
LineChartSpec acneChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                            float minFontPx = 8.0f);
LineChartSpec leakChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                            float minFontPx = 8.0f);
BarChartSpec shimmerChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                              float minFontPx = 8.0f);

// The charts `pcfscope stability` writes, from its rows: acne rate against elevation (empty when
// no acne row), leak width against bias, shimmer per method. Each is RGBA8 of `size`, no text
// below minFontPx.
std::vector<uint8_t> drawAcneChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                   const std::string& subtitle, float minFontPx = 8.0f);
std::vector<uint8_t> drawLeakChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                   const std::string& subtitle, float minFontPx = 8.0f);
std::vector<uint8_t> drawShimmerChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                      const std::string& subtitle, float minFontPx = 8.0f);

}  // namespace pcf
