// The advise search on a real scene (measure/advise_measure.h, llvmpipe): a small grid measured
// whole, then searched through those very measurements, so the search and the full grid see the
// same numbers: no setting of the grid whose whole cost spread lies below the choice's meets the
// budget, the search measures at most a quarter of the grid, and the chosen setting measured
// again from scratch meets every bound. Also the chart's layout and picture.
#include <gtest/gtest.h>

#include <map>
#include <memory>

#include "charts/advise_chart.h"
#include "measure/advise.h"
#include "measure/advise_measure.h"
#include "measure/advise_report.h"
#include "measure/bench_report.h"
#include "render/gl_context.h"
#include "scene/presets.h"

namespace pcf {
namespace {

class AdviseGl : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        sContext = createHeadlessContext();
        sScene = *presetScene("box-on-plane");
        sBench = std::make_unique<AdviseBench>(sScene, options());
        std::vector<AdviseSetting> grid = adviseGrid(space());
        for (const AdviseSetting& s : grid) sGrid.push_back({s, sBench->measure(s)});
        // The whole grid's costs from one round-robin timing, as the search's retiming gives
        // the settings that meet the budget: costs that can be compared across the grid.
        std::vector<AdviseCost> costs = sBench->retime(grid, 5);
        for (size_t k = 0; k < grid.size(); ++k) {
            sGrid[k].second.costMs = costs[k].ms;
            sGrid[k].second.costIqr = costs[k].iqr;
        }
    }
    static void TearDownTestSuite() {
        sBench.reset();
        sContext.reset();
    }

    static AdviseMeasureOptions options() {
        AdviseMeasureOptions o;
        o.frameSize = {160, 90};
        o.repeats = 3;
        o.shimmerFrames = 4;
        return o;
    }
    // 5 filters x 4 map sizes x 3 biases: 60 settings.
    static AdviseSpace space() {
        AdviseSpace s;
        s.filters = {
            {PCF_NEAREST, 0}, {PCF_HW2X2, 0}, {PCF_GATHER, 3}, {PCF_TENT, 3}, {PCF_GATHER, 5}};
        s.mapSizes = {128, 256, 512, 1024};
        s.biases = {{BiasMode::None, 0.0f}, {BiasMode::Constant, 0.002f}, {BiasMode::Normal, 1.5f}};
        return s;
    }
    // Stable edges and a bounded shimmer: a hard filter's p99 jump of 1 breaks it at any size.
    static AdviseBudget budget() {
        AdviseBudget b;
        b.maxEdgeRmse = 0.1;
        b.maxAcne = 0.01;
        b.maxLeakTexels = 3.0;
        b.maxShimmer = 0.5;
        return b;
    }
    static const AdviseMetrics& measured(const AdviseSetting& s) {
        for (const auto& [setting, metrics] : sGrid) {
            if (setting == s) return metrics;
        }
        throw std::logic_error("not in the grid: " + adviseSettingName(s));
    }
    static std::vector<AdviseCost> retimed(const std::vector<AdviseSetting>& settings) {
        std::vector<AdviseCost> costs;
        for (const AdviseSetting& s : settings) {
            costs.push_back({measured(s).costMs, measured(s).costIqr});
        }
        return costs;
    }
    static AdviseResult search() { return searchAdvice(space(), budget(), measured, retimed); }

    static std::unique_ptr<GlContext> sContext;
    static Scene sScene;
    static std::unique_ptr<AdviseBench> sBench;
    static std::vector<std::pair<AdviseSetting, AdviseMetrics>> sGrid;
};

std::unique_ptr<GlContext> AdviseGl::sContext;
Scene AdviseGl::sScene;
std::unique_ptr<AdviseBench> AdviseGl::sBench;
std::vector<std::pair<AdviseSetting, AdviseMetrics>> AdviseGl::sGrid;

TEST_F(AdviseGl, NoCheaperSettingOfTheGridMeetsTheBudgetAndAQuarterIsMeasured) {
    ASSERT_EQ(sGrid.size(), 60u);
    int calls = 0;
    AdviseResult r = searchAdvice(
        space(), budget(),
        [&](const AdviseSetting& s) {
            ++calls;
            return measured(s);
        },
        retimed);
    ASSERT_TRUE(r.choice.has_value());
    const AdviseMetrics& choice = r.measured[*r.choice].metrics;
    int feasible = 0;
    const AdviseSetting& chosen = r.measured[*r.choice].setting;
    for (const auto& [s, m] : sGrid) {
        if (!adviseBroken(budget(), m).empty()) continue;
        ++feasible;
        // The same filter at the same map size runs the same lookup pass whatever the bias
        // (the bias moves the comparison, not the taps): the two differ in time by noise alone.
        if (s.filter == chosen.filter && s.mapSize == chosen.mapSize) continue;
        EXPECT_GE(m.costMs + m.costIqr / 2, choice.costMs - choice.costIqr / 2)
            << adviseSettingName(s) << " meets the budget for less than the choice, "
            << adviseSettingName(r.measured[*r.choice].setting);
    }
    EXPECT_GT(feasible, 1);
    // Some setting of the grid breaks the budget: the search had something to rule out.
    EXPECT_LT(feasible, static_cast<int>(sGrid.size()));
    EXPECT_EQ(r.gridSize, sGrid.size());
    std::string walk;
    for (const AdviseCandidate& c : r.measured) {
        walk += "\n" + adviseSettingName(c.setting) + (c.feasible() ? " meets it" : " breaks it") +
                ", cost " + std::to_string(c.metrics.costMs) + " IQR " +
                std::to_string(c.metrics.costIqr);
    }
    EXPECT_LE(4 * calls, static_cast<int>(r.gridSize)) << calls << " measured:" << walk;
}

TEST_F(AdviseGl, TheChoiceMeasuredAgainMeetsEveryBound) {
    AdviseResult r = search();
    ASSERT_TRUE(r.choice.has_value());
    const AdviseSetting& s = r.measured[*r.choice].setting;
    AdviseBench fresh(sScene, options());
    AdviseMetrics again = fresh.measure(s);
    EXPECT_TRUE(adviseBroken(budget(), again).empty()) << adviseSettingName(s);
    // The measures other than time do not depend on the run.
    EXPECT_DOUBLE_EQ(again.edgeRmse, measured(s).edgeRmse);
    EXPECT_DOUBLE_EQ(again.shimmerP99, measured(s).shimmerP99);
}

TEST_F(AdviseGl, TheChartDrawsTheBudgetAndLabelsWhatEachBreaks) {
    AdviseResult r = search();
    std::vector<BenchRow> rows;
    for (const AdviseCandidate& c : r.measured) {
        BenchRow row;
        row.point = {c.setting.filter.method, c.setting.filter.kernel, c.setting.mapSize};
        row.error.edgeRmse = c.metrics.edgeRmse;
        rows.push_back(row);
    }
    glm::ivec2 size(960, 540);
    AdviseChartOverlay o = layoutAdviseChart(r, rows, budget(), size, "t", "llvmpipe");
    ASSERT_TRUE(o.budgetShown);
    EXPECT_GT(o.budgetY, o.chart.plot.y);
    EXPECT_LT(o.budgetY, o.chart.plot.bottom());
    for (size_t k = 0; k < r.measured.size(); ++k) {
        const AdviseCandidate& c = r.measured[k];
        // A setting that meets the budget lies on its good side: below the line (y grows down).
        if (c.feasible()) {
            EXPECT_GE(o.chart.points[k].y, o.budgetY);
        }
        if (r.choice && *r.choice == k) {
            EXPECT_EQ(o.labels[k].rfind("choice: ", 0), 0u) << o.labels[k];
        } else if (c.feasible()) {
            EXPECT_TRUE(o.labels[k].empty());
        } else {
            EXPECT_NE(o.labels[k].find(adviseConstraintName(c.broken.front())), std::string::npos);
            EXPECT_FALSE(o.labelBoxes[k].empty());
        }
    }
    // No label on another.
    for (size_t a = 0; a < o.labelBoxes.size(); ++a) {
        for (size_t b = a + 1; b < o.labelBoxes.size(); ++b) {
            EXPECT_TRUE(o.labelBoxes[a].intersect(o.labelBoxes[b]).empty())
                << o.labels[a] << " on " << o.labels[b];
        }
    }
    std::vector<uint8_t> png = drawAdviseChart(r, rows, budget(), size, "t", "llvmpipe");
    ASSERT_EQ(png.size(), static_cast<size_t>(size.x * size.y * 4));
    // The budget's line is red where it is drawn: its first dash starts at the plot's left.
    int x = static_cast<int>(o.chart.plot.x) + 3, y = static_cast<int>(o.budgetY);
    const uint8_t* p = &png[(static_cast<size_t>(y) * size.x + x) * 4];
    EXPECT_GT(p[0], 150);
    EXPECT_LT(p[1], 80);
}

// The chart draws each setting at the cost the search compared (the feasible ones timed again),
// in the field the speed chart reads: process CPU time on a CPU rasteriser, wall time on a GPU.
TEST(AdviseChart, DotsSitAtTheCostTheSearchCompared) {
    AdviseResult result;
    result.measured.resize(2);
    result.measured[0].metrics.costMs = 3.0;
    result.measured[0].metrics.costIqr = 0.25;
    result.measured[1].metrics.costMs = 7.0;
    result.measured[1].metrics.costIqr = 0.5;
    BenchRow cpu;
    cpu.glRenderer = "llvmpipe (LLVM 15.0.6; 256 bits)";
    cpu.gpuCpuMs = 9.0;
    cpu.lookupCpuMs = 5.0;  // the first timing, before the round-robin one
    cpu.lookupMs = 11.0;
    BenchRow gpu;
    gpu.glRenderer = "NVIDIA H200/PCIe/SSE2";
    gpu.lookupMs = 4.0;
    std::vector<BenchRow> rows = adviseChartRows(result, {cpu, gpu});
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(benchPassMs(rows[0], true), 3.0);
    EXPECT_EQ(benchPassIqr(rows[0], true), 0.25);
    EXPECT_EQ(benchPassMs(rows[1], true), 7.0);
    EXPECT_EQ(benchPassIqr(rows[1], true), 0.5);
}

TEST_F(AdviseGl, TheSettingsTableAndJsonNameTheChoice) {
    AdviseResult r = search();
    ASSERT_TRUE(r.choice.has_value());
    const AdviseSetting& s = r.measured[*r.choice].setting;
    std::string toml = adviseSettingsToml(s, options().base);
    EXPECT_NE(toml.find("[settings]\nmethod = \"" + std::string(methodInfo(s.filter.method).name) +
                        "\"\n"),
              std::string::npos)
        << toml;
    EXPECT_NE(toml.find("map_size = " + std::to_string(s.mapSize) + "\n"), std::string::npos);
    EXPECT_NE(toml.find("cull = \"front\"\n"), std::string::npos) << toml;
    AdviseContext context{"box-on-plane", 160, 90, "hard", "llvmpipe", options().base};
    std::string json = adviseJson(r, budget(), context);
    EXPECT_NE(json.find("\"grid_size\": 60"), std::string::npos);
    EXPECT_NE(json.find("\"binding\": \"" + adviseBinding(r, budget()) + "\""), std::string::npos);
}

}  // namespace
}  // namespace pcf
