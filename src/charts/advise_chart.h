// advise_chart.h: advise.png, the settings `pcfscope advise` measured (advise.h): the speed
// chart's picture (speed_chart.h: each setting's lookup-pass cost with its IQR bar on a log x
// axis against its edge-band RMSE, dots coloured by method, the Pareto front of the medians,
// named), and over it the choice ringed in orange and the budget: the edge-RMSE bound as a dashed
// line, a green ring round every setting that meets the whole budget, and beside every other one
// the budgets it breaks ("leak", "edge+shimmer").
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "charts/speed_chart.h"
#include "draw/rect.h"
#include "measure/advise.h"
#include "measure/bench.h"

namespace pcf {

// The chart's rows: the bench rows (rows[k] measured[k]'s) with the lookup time replaced by the
// search's cost (its median and IQR), so that the x axis is the cost the search compared.
std::vector<BenchRow> adviseChartRows(const AdviseResult& result,
                                      const std::vector<BenchRow>& rows);

// The speed chart's text for advise.png: the title, the subtitle (renderer, what the marks
// mean), the cost axis's name.
SpeedChartText adviseChartText(const AdviseResult& result, const AdviseBudget& budget,
                               const std::string& title, const std::string& glRenderer);
// Whether the budget's line is drawn: some setting's error reaches it (else the line would lie
// above the plot, and the subtitle says every dot is within the budget).
bool adviseBudgetLineShown(const AdviseResult& result, const AdviseBudget& budget);

// Where the overlay goes (no GL): per measured setting its label and box: the budgets it breaks,
// "choice: tent3 1024" for the choice, empty for the others that meet the budget; and the budget
// line's y (budgetShown: adviseBudgetLineShown).
struct AdviseChartOverlay {
    SpeedChartLayout chart;
    std::vector<std::string> labels;
    std::vector<Rect> labelBoxes;
    float budgetY = 0.0f;
    bool budgetShown = false;
    float fontPx = 14.0f;
};
AdviseChartOverlay layoutAdviseChart(const AdviseResult& result, const std::vector<BenchRow>& rows,
                                     const AdviseBudget& budget, glm::ivec2 size,
                                     const std::string& title, const std::string& glRenderer);

// The chart as RGBA8, rows top-down. Needs a current OpenGL 4.5 context.
std::vector<uint8_t> drawAdviseChart(const AdviseResult& result, const std::vector<BenchRow>& rows,
                                     const AdviseBudget& budget, glm::ivec2 size,
                                     const std::string& title, const std::string& glRenderer);

}  // namespace pcf
