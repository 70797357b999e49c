// A line chart's texts checked the way a reader sees them: each inside the frame and none on
// another (two legend marks may touch: a column of marks). Shared by the stability charts' tests.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "charts/speed_chart.h"

namespace pcf::testutil {

// One line per text outside the frame or on another text; empty when every text is whole and
// apart.
inline std::vector<std::string> chartTextFaults(const std::vector<ChartTextBox>& boxes,
                                                glm::ivec2 size) {
    std::vector<std::string> faults;
    const std::string at = " at " + std::to_string(size.x) + "x" + std::to_string(size.y);
    for (size_t i = 0; i < boxes.size(); ++i) {
        const Rect& a = boxes[i].rect;
        if (!(a.x >= 0.0f && a.right() <= size.x && a.y >= 0.0f && a.bottom() <= size.y)) {
            faults.push_back("'" + boxes[i].text + "' leaves the frame" + at);
        }
        for (size_t j = i + 1; j < boxes.size(); ++j) {
            if (boxes[i].role == "chart-swatch" && boxes[j].role == "chart-swatch") continue;
            const Rect& b = boxes[j].rect;
            if (!(a.right() <= b.x || b.right() <= a.x || a.bottom() <= b.y || b.bottom() <= a.y)) {
                faults.push_back("'" + boxes[i].text + "' overlaps '" + boxes[j].text + "'" + at);
            }
        }
    }
    return faults;
}

}  // namespace pcf::testutil
