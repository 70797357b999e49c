// step_chart.h: the chart a lesson step shows in the scene's place (lesson.h: LessonStep::chart
// and chart_highlight): "PATH", a bench.csv's speed against accuracy (speed_chart.h, the edge
// band's RMSE: speed_vs_accuracy.png), "PATH#contact", the same bench.csv's speed against the
// edge RMSE near the casters (speed_vs_contact.png: bench --contact D), "PATH#NAME", one of a
// stability.csv's sweep charts (stability_figures.h: sweepCharts), "PATH#NAME:P1,P2" only its
// panels named so (ChartPanel::name, the bleed chart's settings), each given the plot area, or
// "DIR/advise.csv", an advise output folder (advise.csv with advise.json beside it:
// measure/advise_read.h) drawn as advise.png is (advise_chart.h). Read, checked, drawn and its
// texts placed here, for every command that shows a step.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "charts/speed_chart.h"
#include "measure/advise_read.h"
#include "measure/bench_report.h"

namespace pcf {

// A chart step draws one point per bench.csv row; a bench of every method, kernel and map size
// has a few hundred. More is refused with one line (a 50,000-row chart took 80 s and 2.3 GB).
constexpr std::size_t MAX_CHART_ROWS = 2000;

// The smallest chart the chart drawers lay out (speed_chart.cpp, stability_chart.cpp refuse
// less): a command that draws a step's chart checks its size against this first.
constexpr int MIN_CHART_SIDE = 64;

// Which measurements a step's chart draws: a bench.csv, a stability.csv's sweep, an advise folder.
enum class StepChartKind { Bench, Stability, Advise };

// A step's chart as its name says: the file, the view after '#', its kind (a file named
// advise.csv is an advise folder's), and for a bench.csv which accuracy its y axis shows.
struct StepChartRef {
    std::string path;
    std::string view;  // "" or "contact" for a bench chart, a stability chart's name, else ""
    StepChartKind kind = StepChartKind::Bench;
    ChartAccuracy accuracy = ChartAccuracy::EdgeRmse;
    // A stability chart's panels the step shows ("PATH#bleed:lbr,moment_format"); empty: all.
    std::vector<std::string> panels = {};
    bool bench() const { return kind == StepChartKind::Bench; }
};
// The bench chart's view of its contact chart: "PATH#contact".
inline constexpr std::string_view CONTACT_CHART_VIEW = "contact";
StepChartRef stepChartRef(const std::string& chart);
// "lbr, moment_format": panel names as a message lists them.
std::string chartPanelList(const std::vector<std::string>& names);

struct StepChart {
    std::string chart;      // "PATH" or "PATH#NAME"
    std::string highlight;  // the rows ringed (chartRowsMatching); empty: none
    float minFontPx = 8.0f;
    // Only the dots the highlight names (and the Pareto front) labelled: a projector's chart.
    bool keptLabelsOnly = false;
};

// A bench.csv's rows, read with the checks of every input file and at most MAX_CHART_ROWS.
// Throws InputError.
std::vector<BenchRow> readChartRows(const std::string& csvPath);

// An advise chart's folder read back (advise.csv and the advise.json beside it). Throws
// InputError.
AdviseReport readStepAdvise(const StepChartRef& ref);

// Throws InputError unless `chart` can be drawn: its file is read, has rows (for a sweep chart,
// of that sweep) and names a sweep chart that exists; an advise folder's two files agree.
void checkStepChart(const std::string& chart);
// Throws std::invalid_argument unless the chart is a bench chart and `highlight` names rows of
// its bench.csv (chartRowsMatching), InputError for the file.
void checkStepChartHighlight(const std::string& chart, const std::string& highlight);

// The chart as RGBA8 of `size`, rows top-down. Throws InputError for a bad chart file.
std::vector<uint8_t> drawStepChart(const StepChart& chart, glm::ivec2 size);
// A bench chart's layout at `size` (its dots, bars, labels and leaders: speed_chart.h), as
// drawStepChart draws it (for an advise chart, the speed chart under its marks); nullopt for a
// stability chart. Throws InputError.
std::optional<SpeedChartLayout> stepSpeedChartLayout(const StepChart& chart, glm::ivec2 size);
// The texts it draws, placed in a chart of `size` (origin top-left). Throws InputError.
std::vector<ChartTextBox> stepChartTexts(const StepChart& chart, glm::ivec2 size);

}  // namespace pcf
