#include "analysis/step_chart.h"

#include <filesystem>

#include "analysis/chart_axes.h"
#include "analysis/stability_figures.h"
#include "analysis/stability_report.h"
#include "base/input_error.h"
#include "base/input_file.h"

namespace pcf {

namespace {

// Refuses a chart of more rows than one frame can show.
template <class Row>
std::vector<Row> limitChartRows(std::vector<Row> rows, const std::string& csvPath) {
    if (rows.size() > MAX_CHART_ROWS) {
        throw InputError(csvPath, 0,
                         std::to_string(rows.size()) + " rows; a chart shows at most " +
                             std::to_string(MAX_CHART_ROWS));
    }
    return rows;
}

std::vector<StabilityRow> readStabilityRows(const std::string& csvPath) {
    return limitChartRows(parseStabilityCsv(readInputFile(csvPath), csvPath), csvPath);
}

// A step's chart: "PATH" (a bench.csv) or "PATH#NAME" (a stability.csv and which of its charts).
struct ChartRef {
    std::string path;
    std::string view;  // empty for a bench chart
};

ChartRef chartRef(const std::string& chart) {
    size_t hash = chart.rfind('#');
    if (hash == std::string::npos) return {chart, ""};
    return {chart.substr(0, hash), chart.substr(hash + 1)};
}

std::string stabilitySubtitle(const ChartRef& ref) {
    return "measured by pcfscope stability, " + std::filesystem::path(ref.path).filename().string();
}

// The sweep chart a stability chart's name names, or InputError.
const SweepChart& sweepChartOf(const ChartRef& ref) {
    if (const SweepChart* c = sweepChartNamed(ref.view)) return *c;
    throw InputError(
        ref.path, 0,
        "unknown stability chart '#" + ref.view + "' (known: " + sweepChartNames() + ")");
}

// The chart's text and type for a speed chart.
SpeedChartText speedChartText(const StepChart& chart, const std::vector<BenchRow>& rows) {
    SpeedChartText labels;
    labels.title = "Speed against accuracy";
    // The renderer (bench.csv's gl_renderer) and, on llvmpipe, what carries over to a GPU.
    labels.subtitle = "measured by pcfscope bench (" + rows.front().timer + "), " +
                      std::filesystem::path(chart.chart).filename().string() + "; " +
                      chartRendererLine(speedChartRenderer(rows), true);
    if (!chart.highlight.empty()) labels.highlight = chartRowsMatching(rows, chart.highlight);
    labels.minFontPx = chart.minFontPx;
    labels.keptLabelsOnly = chart.keptLabelsOnly;
    return labels;
}

}  // namespace

std::vector<BenchRow> readChartRows(const std::string& csvPath) {
    return limitChartRows(parseBenchCsv(readInputFile(csvPath), csvPath), csvPath);
}

void checkStepChart(const std::string& chart) {
    ChartRef ref = chartRef(chart);
    if (ref.view.empty()) {
        if (readChartRows(ref.path).empty()) throw InputError(ref.path, 0, "no rows to chart");
        return;
    }
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    sweepChartOf(ref);
    for (const StabilityRow& r : rows) {
        if (r.sweep == ref.view) return;
    }
    throw InputError(ref.path, 0, "no " + ref.view + " rows to chart");
}

void checkStepChartHighlight(const std::string& chart, const std::string& highlight) {
    chartRowsMatching(readChartRows(chartRef(chart).path), highlight);
}

std::vector<uint8_t> drawStepChart(const StepChart& chart, glm::ivec2 size) {
    ChartRef ref = chartRef(chart.chart);
    if (ref.view.empty()) {
        std::vector<BenchRow> rows = readChartRows(chart.chart);
        return drawSpeedChart(rows, size, speedChartText(chart, rows));
    }
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    std::vector<uint8_t> rgba =
        sweepChartOf(ref).draw(rows, size, stabilitySubtitle(ref), chart.minFontPx);
    if (rgba.empty()) throw InputError(ref.path, 0, "no " + ref.view + " rows to chart");
    return rgba;
}

std::vector<ChartTextBox> stepChartTexts(const StepChart& chart, glm::ivec2 size) {
    ChartRef ref = chartRef(chart.chart);
    if (ref.view.empty()) {
        std::vector<BenchRow> rows = readChartRows(chart.chart);
        SpeedChartText text = speedChartTextFor(rows, speedChartText(chart, rows), size);
        SpeedChartLayout layout = layoutSpeedChart(
            rows, size, ChartTiming::Scene, ChartAccuracy::EdgeRmse, text.highlight, text.minFontPx,
            text.keptLabelsOnly, subtitleLineCount(text.subtitle));
        return speedChartTextBoxes(layout, text);
    }
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    return sweepChartOf(ref).texts(rows, size, stabilitySubtitle(ref), chart.minFontPx);
}

}  // namespace pcf
