#include "charts/step_chart.h"

#include <filesystem>
#include <stdexcept>
#include <utility>

#include "base/input_error.h"
#include "base/input_file.h"
#include "charts/chart_axes.h"
#include "charts/stability_figures.h"
#include "measure/stability_report.h"

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

std::string stabilitySubtitle(const StepChartRef& ref) {
    return "measured by pcfscope stability, " + std::filesystem::path(ref.path).filename().string();
}

// The sweep chart a stability chart's name names, or InputError.
const SweepChart& sweepChartOf(const StepChartRef& ref) {
    if (const SweepChart* c = sweepChartNamed(ref.view)) return *c;
    throw InputError(
        ref.path, 0,
        "unknown stability chart '#" + ref.view + "' (known: " + sweepChartNames() + ")");
}

// The chart's text and type for a speed chart.
SpeedChartText speedChartText(const StepChart& chart, const StepChartRef& ref,
                              const std::vector<BenchRow>& rows) {
    SpeedChartText labels;
    bool contact = ref.accuracy == ChartAccuracy::ContactRmse;
    // Short: the title and the axis's name are not wrapped, and a lesson frame's chart is narrow.
    labels.title = contact ? "Accuracy near the contacts" : "Speed against accuracy";
    if (contact) labels.yLabel = contactAxisLabel(rows, true);
    labels.xLabel = speedChartXLabel(rows, ChartTiming::Scene);
    // Which truth the errors are against (bench.csv's truth, when the file says), then on a line
    // of its own the renderer (its gl_renderer) and, on llvmpipe, what carries over to a GPU.
    std::string truth = speedChartTruth(rows);
    labels.subtitle = "measured by pcfscope bench (" + rows.front().timer + "), " +
                      std::filesystem::path(ref.path).filename().string() +
                      (truth.empty() ? "" : "; truth: " + truth) + "\n" +
                      chartRendererLine(speedChartRenderer(rows));
    if (!chart.highlight.empty()) labels.highlight = chartRowsMatching(rows, chart.highlight);
    labels.minFontPx = chart.minFontPx;
    labels.keptLabelsOnly = chart.keptLabelsOnly;
    return labels;
}

// A bench chart's rows, and none without the data its view draws (a contact chart of a bench
// run without --contact would be a row of zeros).
std::vector<BenchRow> readBenchChartRows(const StepChartRef& ref) {
    std::vector<BenchRow> rows = readChartRows(ref.path);
    if (rows.empty()) throw InputError(ref.path, 0, "no rows to chart");
    if (ref.accuracy == ChartAccuracy::ContactRmse && !(rows.front().contactDistance > 0.0)) {
        throw InputError(ref.path, 0,
                         "no contact error to chart (measured without bench --contact, or "
                         "older than bench.csv's contact_distance column)");
    }
    return rows;
}

}  // namespace

StepChartRef stepChartRef(const std::string& chart) {
    size_t hash = chart.rfind('#');
    if (hash == std::string::npos) return {chart, "", true, ChartAccuracy::EdgeRmse};
    std::string view = chart.substr(hash + 1);
    bool contact = view == CONTACT_CHART_VIEW;
    return {chart.substr(0, hash), view, contact,
            contact ? ChartAccuracy::ContactRmse : ChartAccuracy::EdgeRmse};
}

std::vector<BenchRow> readChartRows(const std::string& csvPath) {
    return limitChartRows(parseBenchCsv(readInputFile(csvPath), csvPath), csvPath);
}

void checkStepChart(const std::string& chart) {
    StepChartRef ref = stepChartRef(chart);
    if (ref.bench) {
        readBenchChartRows(ref);
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
    StepChartRef ref = stepChartRef(chart);
    if (!ref.bench) {
        throw std::invalid_argument("needs a bench chart (chart = \"....csv\" or \"....csv#" +
                                    std::string(CONTACT_CHART_VIEW) + "\")");
    }
    chartRowsMatching(readChartRows(ref.path), highlight);
}

std::vector<uint8_t> drawStepChart(const StepChart& chart, glm::ivec2 size) {
    StepChartRef ref = stepChartRef(chart.chart);
    if (ref.bench) {
        std::vector<BenchRow> rows = readBenchChartRows(ref);
        return drawSpeedChart(rows, size, speedChartText(chart, ref, rows), ChartTiming::Scene,
                              ref.accuracy);
    }
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    std::vector<uint8_t> rgba =
        sweepChartOf(ref).draw(rows, size, stabilitySubtitle(ref), chart.minFontPx);
    if (rgba.empty()) throw InputError(ref.path, 0, "no " + ref.view + " rows to chart");
    return rgba;
}

namespace {

// A bench chart's text as drawn and its layout at `size`.
std::pair<SpeedChartText, SpeedChartLayout> speedChartOf(const StepChart& chart,
                                                         const StepChartRef& ref, glm::ivec2 size) {
    std::vector<BenchRow> rows = readBenchChartRows(ref);
    SpeedChartText text = speedChartTextFor(rows, speedChartText(chart, ref, rows), size);
    SpeedChartLayout layout =
        layoutSpeedChart(rows, size, ChartTiming::Scene, ref.accuracy, text.highlight,
                         text.minFontPx, text.keptLabelsOnly, subtitleLineCount(text.subtitle));
    return {text, layout};
}

}  // namespace

std::optional<SpeedChartLayout> stepSpeedChartLayout(const StepChart& chart, glm::ivec2 size) {
    StepChartRef ref = stepChartRef(chart.chart);
    if (!ref.bench) return std::nullopt;
    return speedChartOf(chart, ref, size).second;
}

std::vector<ChartTextBox> stepChartTexts(const StepChart& chart, glm::ivec2 size) {
    StepChartRef ref = stepChartRef(chart.chart);
    if (ref.bench) {
        auto [text, layout] = speedChartOf(chart, ref, size);
        return speedChartTextBoxes(layout, text);
    }
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    return sweepChartOf(ref).texts(rows, size, stabilitySubtitle(ref), chart.minFontPx);
}

}  // namespace pcf
