// speed_chart_labels.h: where the speed chart's dot names go, the last step of layoutSpeedChart
// (speed_chart.h). A name sits beside its own dot, in the plot, on no other name or badge, no
// dot or ring (its own too) and no error bar, and nearer its own dot than any other by a dot
// radius: a reader takes a name for the nearest dot's, whatever a leader says (lesson 11 at
// 1024x768 on a projector read "nearest 2048" as the name of the nearest-256 dot it sat by,
// 160 px from its own). A dot the chart must name whose name finds no such spot within
// speedChartNameReach gets a numbered badge instead, touching the dot or its outer ring where
// such a spot is clean, else drawn in the dot's place (a badge centred on its dot names no other),
// and the key under the x axis gives the number its name. Also every other text the chart draws,
// with the names (speedChartTextBoxes, speed_chart.h). No GL: the texts are measured with the
// fonts.
#pragma once

#include <string>
#include <vector>

#include "charts/speed_chart.h"
#include "draw/canvas.h"

namespace pcf {

// How far from its dot's centre a name the chart must show may lie (its box's nearest point),
// pixels: four dot diameters. Any other name is shown only within a dot radius of the dot's
// outer ring.
float speedChartNameReach(const SpeedChartLayout& layout);

// How far beyond the dot's outer ring (speedChartMarkRadius) a badge's disc may lie, pixels (a
// dot diameter, or a badge radius where that is more): it touches the dot or the ring where a
// clean spot does, else lies at most this far out.
float speedChartBadgeGap(const SpeedChartLayout& layout);

// Sets layout.labels, labelShown, badge, badgeBoxes, badgeOnDot and keyRows from the dots, rings,
// error bars, label texts and layout.mustName that layoutSpeedChart has laid out. keptLabelsOnly:
// no row but mustName's is named. mustName's rows are placed first (greedily, in row order; where
// some got badges, once more with those first, keeping the placement with fewer badges), then
// the rest where they fit; badges are numbered in the order of their dots' times.
void placeSpeedChartLabels(SpeedChartLayout& layout, bool keptLabelsOnly);

// A text box of `words` at `px` whose anchor `pos` is its left, centre or right end (align) at its
// top, appended to `out`.
ChartTextBox& addChartTextBox(std::vector<ChartTextBox>& out, glm::vec2 pos, TextAlign align,
                              float px, const std::string& role, const std::string& words);

// The dots' names, their badges and the key's badges and names, as speedChartTextBoxes lists them.
void speedChartNameBoxes(const SpeedChartLayout& layout, std::vector<ChartTextBox>& out);

// The gap between a legend's or key's mark and its words (speed_chart.cpp).
float speedChartLegendGap(const SpeedChartLayout& layout);

}  // namespace pcf
