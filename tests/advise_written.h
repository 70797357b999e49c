// What advise writes for three settings of box-on-plane's shape of numbers, shared by
// advise_read_test (read back, refused when edited) and advise_step_chart_test (drawn as a
// lesson step's chart).
#pragma once

#include <string>
#include <vector>

#include "measure/advise_report.h"

namespace pcf::advise_test {

// Three settings of box-on-plane's shape of numbers: nearest breaks the edge and the shimmer,
// hw2x2 on 256 the edge, hw2x2 on 512 meets the budget (the choice), tent on 512 meets it too
// at a higher cost (the runner-up).
struct Written {
    AdviseResult result;
    std::vector<BenchRow> rows;
    AdviseBudget budget;
    std::string csv, json;
};

inline Written written() {
    Written w;
    w.budget.maxEdgeRmse = 0.1;
    w.budget.maxShimmer = 0.5;
    w.budget.maxLeakTexels = 2.0;
    struct Dot {
        int method, kernel, map;
        double edge, shimmer, cost;
    };
    const Dot dots[] = {{PCF_NEAREST, 0, 256, 0.33, 1.0, 0.8},
                        {PCF_HW2X2, 0, 256, 0.25, 0.4, 0.9},
                        {PCF_HW2X2, 0, 512, 0.09, 0.4, 1.0},
                        {PCF_TENT, 3, 512, 0.08, 0.1, 2.5}};
    for (const Dot& d : dots) {
        AdviseCandidate c;
        c.setting.filter = {d.method, d.kernel};
        c.setting.mapSize = d.map;
        c.texelReads = adviseTexelReads(c.setting.filter);
        c.metrics.edgeRmse = d.edge;
        c.metrics.shimmerP99 = d.shimmer;
        c.metrics.leakTexels = 0.5;
        c.metrics.costMs = d.cost;
        c.metrics.costIqr = 0.05;
        c.broken = adviseBroken(w.budget, c.metrics);
        w.result.measured.push_back(c);
        BenchRow r;
        r.point = {d.method, d.kernel, d.map};
        r.error.edgeRmse = d.edge;
        w.rows.push_back(r);
    }
    w.result.gridSize = 24;
    chooseAdvice(w.result, w.budget);
    AdviseContext context{"box-on-plane", 480, 270, "hard (the light's centre)", "llvmpipe", {}};
    w.csv = adviseCsv(w.result, w.rows);
    w.json = adviseJson(w.result, w.budget, context);
    return w;
}

}  // namespace pcf::advise_test
