// speed_chart_checks.h: what a speed chart's layout (speed_chart.h) must keep true for a reader,
// as readable lines (empty: all true). Shared by the stand-alone chart's tests
// (error_metrics_test) and the lesson frames' (layout_test).
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "analysis/speed_chart.h"

namespace pcf {

// A reader names a label by the nearest dot: every drawn label is nearer its own dot than any
// other (dots whose discs overlap excepted: no place names one of them), or else has a leader that
// crosses no other dot and no other dot next to it (within the 2.5 dot radii where leaders start);
// no error bar runs through a label.
inline std::vector<std::string> speedChartLabelFaults(const SpeedChartLayout& L) {
    std::vector<std::string> out;
    auto distance = [](const Rect& box, glm::vec2 p) {
        return glm::length(glm::clamp(p, box.position(), box.position() + box.size()) - p);
    };
    for (size_t k = 0; k < L.points.size(); ++k) {
        if (!L.labelShown[k]) continue;
        const Rect& box = L.labels[k];
        const std::string& name = L.labelTexts[k];
        float own = distance(box, L.points[k]);
        std::optional<ChartLeader> leader = speedChartLeader(L, k);
        std::string nearer, crossed;  // the first other dot nearer (or as near), next to, crossed
        bool nextTo = false;
        for (size_t j = 0; j < L.points.size(); ++j) {
            if (!box.intersect(speedChartBarBox(L, j)).empty()) {
                out.push_back("'" + name + "' lies on the error bar of " + L.labelTexts[j]);
            }
            if (j == k || glm::length(L.points[j] - L.points[k]) < 2.0f * L.dotRadius) continue;
            float other = distance(box, L.points[j]);
            if (other <= own && nearer.empty()) {
                nearer = L.labelTexts[j] + "'s dot at " + std::to_string(other) +
                         " px, its own at " + std::to_string(own) + " px";
            }
            nextTo |= other <= 2.5f * L.dotRadius;
            if (leader && crossed.empty()) {
                glm::vec2 ab = leader->to - leader->from;
                float t = std::clamp(glm::dot(L.points[j] - leader->from, ab) / glm::dot(ab, ab),
                                     0.0f, 1.0f);
                if (glm::length(leader->from + t * ab - L.points[j]) < L.dotRadius) {
                    crossed = L.labelTexts[j];
                }
            }
        }
        if (nearer.empty()) continue;
        if (!leader) {
            out.push_back("'" + name + "' has no leader and is nearer " + nearer);
        } else if (nextTo || !crossed.empty()) {
            out.push_back(
                "'" + name + "' is nearer " + nearer + ", and its leader " +
                (crossed.empty() ? "ends next to another dot" : "crosses " + crossed + "'s dot"));
        }
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
