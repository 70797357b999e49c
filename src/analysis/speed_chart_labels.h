// speed_chart_labels.h: where the speed chart's dot names go, the last step of layoutSpeedChart
// (speed_chart.h). Each name sits beside its own dot, in the plot, off every other name, dot and
// error bar, and nearer its own dot than any other; a name the chart must show (the front's, the
// ones a lesson step keeps) may sit farther out, with a leader back to its dot. No GL: the names
// are measured with the fonts.
#pragma once

#include <vector>

#include "analysis/speed_chart.h"

namespace pcf {

// How far from its dot's centre a label's box may start before a leader joins them, pixels:
// speedChartLeader draws one past it, and only a label the chart must show is looked for past it.
float speedChartLeaderReach(const SpeedChartLayout& layout);

// Sets layout.labels and layout.labelShown from the dots, error bars, label texts and front that
// layoutSpeedChart has laid out. needLabel: per row, whether its name must show (the front's and
// the kept rows'); keptLabelsOnly: no other is named. The front's labels are placed first, then
// the kept rows', then the rest; where a needed label found no clean spot, once more with those
// first (a crowd's few clean spots go to whoever comes first), keeping the placement that leaves
// fewer such labels.
void placeSpeedChartLabels(SpeedChartLayout& layout, const std::vector<bool>& needLabel,
                           bool keptLabelsOnly);

}  // namespace pcf
