// speed_chart_checks.h: what a speed chart's layout (speed_chart.h) must keep true for a reader,
// as readable lines (empty: all true). Shared by the stand-alone chart's tests
// (error_metrics_test) and the lesson frames' (layout_chart_test).
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "charts/speed_chart.h"
#include "charts/speed_chart_labels.h"

namespace pcf {

// A reader names a label by the nearest dot, whatever a leader says: every drawn name and badge
// is strictly nearer its own dot than any other (dots whose discs overlap excepted: no place
// names one of them), lies in the plot, on no dot or ring (its own too), no error bar and no
// other name or badge (a badge may lie on its own dot's rings); a name starts within
// speedChartNameReach of its dot, a badge touches its dot or lies within speedChartBadgeGap of
// its outer ring. Every row the chart must name has a
// name or a badge (not both), and the key lists each badge's number once, in order.
inline std::vector<std::string> speedChartLabelFaults(const SpeedChartLayout& L) {
    std::vector<std::string> out;
    auto boxDistance = [](const Rect& box, glm::vec2 p) {
        return glm::length(glm::clamp(p, box.position(), box.position() + box.size()) - p);
    };
    struct Mark {
        size_t row;
        Rect box;
        bool badge;
    };
    std::vector<Mark> marks;
    for (size_t k = 0; k < L.points.size(); ++k) {
        if (L.labelShown[k]) marks.push_back({k, L.labels[k], false});
        if (L.badge[k] > 0) marks.push_back({k, L.badgeBoxes[k], true});
    }
    for (size_t m = 0; m < marks.size(); ++m) {
        const auto& [k, box, badge] = marks[m];
        std::string name =
            (badge ? "badge " + std::to_string(L.badge[k]) + " of '" : "'") + L.labelTexts[k] + "'";
        // A badge is the disc in its box.
        auto distance = [&](glm::vec2 p) {
            return badge ? std::max(0.0f, glm::length(box.centre() - p) - 0.5f * box.w)
                         : boxDistance(box, p);
        };
        float own = distance(L.points[k]);
        Rect in = L.plot.intersect(box);
        if (in.w * in.h < box.w * box.h - 0.5f) {
            out.push_back(name + " leaves the plot");
        }
        float ownMark = speedChartMarkRadius(L, k);
        if (!badge && own > speedChartNameReach(L)) {
            out.push_back(name + " starts " + std::to_string(own) + " px from its dot");
        }
        if (badge && own > ownMark + speedChartBadgeGap(L) + 1.0f) {
            out.push_back(name + " lies " + std::to_string(own - ownMark) +
                          " px beyond its dot's ring");
        }
        // A badge in its dot's place is drawn over the dots and bars round it, so it may cover
        // their edges, but no other dot's centre (each still shows where it is), but for dots
        // whose discs overlap its dot's, which hide each other already.
        bool onDot = badge && L.badgeOnDot[k];
        for (size_t j = 0; onDot && j < L.points.size(); ++j) {
            float apart = glm::length(L.points[j] - L.points[k]);
            if (j != k && apart >= 2.0f * L.dotRadius &&
                glm::length(L.points[j] - box.centre()) < 0.5f * box.w) {
                out.push_back(name + " covers the centre of " + L.labelTexts[j] + "'s dot");
            }
        }
        if (onDot && glm::length(L.points[k] - box.centre()) > 1.0f) {
            out.push_back(name + " is drawn in its dot's place but not centred on it");
        }
        for (size_t j = 0; !onDot && j < L.points.size(); ++j) {
            if (!box.intersect(speedChartBarBox(L, j)).empty()) {
                out.push_back(name + " lies on the error bar of " + L.labelTexts[j]);
            }
            float d = distance(L.points[j]);
            // (A badge may lie on its own dot's rings, touching the dot.)
            if (d < (j == k && badge ? L.dotRadius : speedChartMarkRadius(L, j))) {
                out.push_back(name + " lies on the dot or ring of " + L.labelTexts[j]);
            }
            if (j == k || glm::length(L.points[j] - L.points[k]) < 2.0f * L.dotRadius) continue;
            if (d <= own) {
                out.push_back(name + " is nearer " + L.labelTexts[j] + "'s dot (" +
                              std::to_string(d) + " px) than its own (" + std::to_string(own) +
                              " px)");
            }
        }
        for (size_t o = m + 1; o < marks.size(); ++o) {
            if (!box.intersect(marks[o].box).empty()) {
                out.push_back(name + " lies on the name or badge of " + L.labelTexts[marks[o].row]);
            }
        }
    }
    for (size_t k : L.mustName) {
        if (L.labelShown[k] == (L.badge[k] > 0)) {
            out.push_back("'" + L.labelTexts[k] + "' has " +
                          (L.labelShown[k] ? "both a name and a badge" : "neither name nor badge"));
        }
    }
    size_t badges = 0;
    for (size_t k = 0; k < L.badge.size(); ++k) {
        if (L.badge[k] == 0) continue;
        ++badges;
        size_t line = static_cast<size_t>(L.badge[k]) - 1;
        if (line >= L.keyRows.size() || L.keyRows[line] != k) {
            out.push_back("badge " + std::to_string(L.badge[k]) + " of '" + L.labelTexts[k] +
                          "' is not its line of the key");
        }
    }
    if (badges != L.keyRows.size() || badges != L.keyBadges.size()) {
        out.push_back(std::to_string(badges) + " badges, " + std::to_string(L.keyRows.size()) +
                      " lines in the key");
    }
    return out;
}

// Every dot's time can be read off the log x axis: a labelled tick within a factor of
// SPEED_CHART_TICK_REACH of it and one in its decade; 3 labelled ticks at least.
inline std::vector<std::string> speedChartTickFaults(const SpeedChartLayout& L) {
    std::vector<std::string> out;
    std::vector<double> labelled;
    for (const ChartTick& t : L.xTicks) {
        if (!t.text.empty()) labelled.push_back(t.value);
    }
    if (labelled.size() < 3) {
        out.push_back(std::to_string(labelled.size()) + " labelled x ticks (3 at least)");
    }
    for (size_t k = 0; k < L.points.size(); ++k) {
        // The dot's time, read back from where it is drawn.
        double lv = L.xLogLo + (L.points[k].x - L.plot.x) / L.plot.w * (L.xLogHi - L.xLogLo);
        double decade = std::floor(lv + 1e-6);
        bool near = false, inDecade = false;
        for (double v : labelled) {
            near |= std::abs(std::log10(v) - lv) <= std::log10(SPEED_CHART_TICK_REACH) + 1e-3;
            inDecade |= std::floor(std::log10(v) + 1e-9) == decade;
        }
        if (!near || !inDecade) {
            out.push_back(L.labelTexts[k] + " at " + std::to_string(std::pow(10.0, lv)) +
                          " ms: no labelled tick " + (near ? "in its decade" : "near it"));
        }
    }
    return out;
}

}  // namespace pcf
