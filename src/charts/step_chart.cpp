#include "charts/step_chart.h"

#include <algorithm>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <utility>

#include "base/input_error.h"
#include "base/input_file.h"
#include "charts/advise_chart.h"
#include "charts/chart_axes.h"
#include "charts/stability_figures.h"
#include "charts/stability_pcss_figures.h"
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

// The sweep chart's spec with only the panels `ref` names, each in its given order; InputError
// for a name no panel has, listing the names there are.
LineChartSpec namedPanelsSpec(const StepChartRef& ref, std::span<const StabilityRow> rows,
                              float minFontPx) {
    const SweepChart& chart = sweepChartOf(ref);
    LineChartSpec spec;
    if (chart.lineSpec) spec = chart.lineSpec(rows, stabilitySubtitle(ref), minFontPx);
    std::vector<std::string> names;
    for (const ChartPanel& p : spec.panels) {
        if (!p.name.empty()) names.push_back(p.name);
    }
    std::vector<ChartPanel> kept;
    for (const std::string& want : ref.panels) {
        auto it = std::find_if(spec.panels.begin(), spec.panels.end(),
                               [&](const ChartPanel& p) { return p.name == want; });
        if (want.empty() || it == spec.panels.end()) {
            throw InputError(ref.path, 0,
                             "no panel '" + want + "' in the chart '#" + ref.view +
                                 "' (its panels: " + chartPanelList(names) + ")");
        }
        kept.push_back(*it);
    }
    // The notes speak of one panel: gone with it.
    if (!spec.notesPanel.empty() &&
        std::find(ref.panels.begin(), ref.panels.end(), spec.notesPanel) == ref.panels.end()) {
        spec.notes.clear();
    }
    spec.panels = std::move(kept);
    return spec;
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
    std::string path = chart.substr(0, hash);
    std::string view = hash == std::string::npos ? "" : chart.substr(hash + 1);
    if (std::filesystem::path(path).filename() == ADVISE_CSV_NAME) {
        return {path, view, StepChartKind::Advise, ChartAccuracy::EdgeRmse};
    }
    if (hash == std::string::npos)
        return {chart, "", StepChartKind::Bench, ChartAccuracy::EdgeRmse};
    bool contact = view == CONTACT_CHART_VIEW;
    StepChartRef ref{path, view, contact ? StepChartKind::Bench : StepChartKind::Stability,
                     contact ? ChartAccuracy::ContactRmse : ChartAccuracy::EdgeRmse};
    // "bleed:lbr,moment_format": the sweep chart's name, then the panels shown.
    size_t colon = view.find(':');
    if (!contact && colon != std::string::npos) {
        ref.view = view.substr(0, colon);
        std::string list = view.substr(colon + 1);
        for (size_t at = 0; at <= list.size();) {
            size_t comma = std::min(list.find(',', at), list.size());
            ref.panels.push_back(list.substr(at, comma - at));
            at = comma + 1;
        }
    }
    return ref;
}

std::string chartPanelList(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

AdviseReport readStepAdvise(const StepChartRef& ref) {
    if (!ref.view.empty()) {
        throw InputError(
            ref.path, 0,
            "an advise chart has no views ('#" + ref.view + "'): name its " + ADVISE_CSV_NAME);
    }
    std::string json = (std::filesystem::path(ref.path).parent_path() / ADVISE_JSON_NAME).string();
    return parseAdviseReport(readInputFile(ref.path), ref.path, readInputFile(json), json);
}

std::vector<BenchRow> readChartRows(const std::string& csvPath) {
    return limitChartRows(parseBenchCsv(readInputFile(csvPath), csvPath), csvPath);
}

void checkStepChart(const std::string& chart) {
    StepChartRef ref = stepChartRef(chart);
    if (ref.kind == StepChartKind::Advise) {
        readStepAdvise(ref);
        return;
    }
    if (ref.bench()) {
        readBenchChartRows(ref);
        return;
    }
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    sweepChartOf(ref);
    if (!ref.panels.empty()) namedPanelsSpec(ref, rows, 8.0f);
    for (const StabilityRow& r : rows) {
        if (r.sweep == ref.view) return;
    }
    throw InputError(ref.path, 0, "no " + ref.view + " rows to chart");
}

void checkStepChartHighlight(const std::string& chart, const std::string& highlight) {
    StepChartRef ref = stepChartRef(chart);
    if (!ref.bench()) {
        throw std::invalid_argument("needs a bench chart (chart = \"....csv\" or \"....csv#" +
                                    std::string(CONTACT_CHART_VIEW) + "\")");
    }
    chartRowsMatching(readChartRows(ref.path), highlight);
}

std::vector<uint8_t> drawStepChart(const StepChart& chart, glm::ivec2 size) {
    StepChartRef ref = stepChartRef(chart.chart);
    if (ref.kind == StepChartKind::Advise) {
        AdviseReport a = readStepAdvise(ref);
        return drawAdviseChart(a.result, a.rows, a.budget, size, adviseChartTitle(a.scene),
                               a.glRenderer, chart.minFontPx);
    }
    if (ref.bench()) {
        std::vector<BenchRow> rows = readBenchChartRows(ref);
        return drawSpeedChart(rows, size, speedChartText(chart, ref, rows), ChartTiming::Scene,
                              ref.accuracy);
    }
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    if (!ref.panels.empty()) {
        return drawPcssChart(namedPanelsSpec(ref, rows, chart.minFontPx), size);
    }
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

// An advise chart's layout at `size`: the speed chart under it and its marks' labels.
AdviseChartOverlay adviseChartOf(const StepChart& chart, const StepChartRef& ref, glm::ivec2 size) {
    AdviseReport a = readStepAdvise(ref);
    return layoutAdviseChart(a.result, a.rows, a.budget, size, adviseChartTitle(a.scene),
                             a.glRenderer, chart.minFontPx);
}

}  // namespace

std::optional<SpeedChartLayout> stepSpeedChartLayout(const StepChart& chart, glm::ivec2 size) {
    StepChartRef ref = stepChartRef(chart.chart);
    if (ref.kind == StepChartKind::Advise) return adviseChartOf(chart, ref, size).chart;
    if (!ref.bench()) return std::nullopt;
    return speedChartOf(chart, ref, size).second;
}

std::vector<ChartTextBox> stepChartTexts(const StepChart& chart, glm::ivec2 size) {
    StepChartRef ref = stepChartRef(chart.chart);
    if (ref.kind == StepChartKind::Advise) {
        return adviseChartTextBoxes(adviseChartOf(chart, ref, size));
    }
    if (ref.bench()) {
        auto [text, layout] = speedChartOf(chart, ref, size);
        return speedChartTextBoxes(layout, text);
    }
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    if (!ref.panels.empty()) {
        return lineChartTextBoxes(namedPanelsSpec(ref, rows, chart.minFontPx), size);
    }
    return sweepChartOf(ref).texts(rows, size, stabilitySubtitle(ref), chart.minFontPx);
}

}  // namespace pcf
