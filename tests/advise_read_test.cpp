// An advise folder read back (measure/advise_read.h) and shown as a lesson step's chart
// (charts/step_chart.h, "DIR/advise.csv"): what advise_report.h writes reads back to the same
// settings, measures, budget and choice; a folder whose marks disagree with its own budget, or
// that lacks advise.json, is refused in one line naming the file (and the CSV's line).
#include "measure/advise_read.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "charts/step_chart.h"
#include "measure/advise_report.h"
#include "run_command.h"

namespace pcf {
namespace {

// Three settings of box-on-plane's shape of numbers: nearest breaks the edge and the shimmer,
// hw2x2 on 256 the edge, hw2x2 on 512 meets the budget (the choice), tent on 512 meets it too
// at a higher cost (the runner-up).
struct Written {
    AdviseResult result;
    std::vector<BenchRow> rows;
    AdviseBudget budget;
    std::string csv, json;
};

Written written() {
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

// The CSV with one field of one data line (1-based, the header line 1) replaced.
std::string withField(const std::string& csv, int line, size_t field, const std::string& value) {
    std::vector<std::string> lines;
    size_t start = 0;
    for (size_t nl; (nl = csv.find('\n', start)) != std::string::npos; start = nl + 1) {
        lines.push_back(csv.substr(start, nl - start));
    }
    std::string& l = lines[static_cast<size_t>(line - 1)];
    size_t from = 0;
    for (size_t k = 0; k < field; ++k) from = l.find(',', from) + 1;
    l.replace(from, l.find(',', from) - from, value);
    std::string out;
    for (const std::string& s : lines) out += s + "\n";
    return out;
}

TEST(AdviseRead, ReadsBackWhatAdviseWrote) {
    Written w = written();
    AdviseReport a = parseAdviseReport(w.csv, "advise.csv", w.json, "advise.json");
    ASSERT_EQ(a.result.measured.size(), w.result.measured.size());
    for (size_t k = 0; k < w.result.measured.size(); ++k) {
        const AdviseCandidate &got = a.result.measured[k], &want = w.result.measured[k];
        EXPECT_EQ(got.setting, want.setting) << k;
        EXPECT_EQ(got.broken, want.broken) << k;
        EXPECT_EQ(got.texelReads, want.texelReads) << k;
        EXPECT_NEAR(got.metrics.edgeRmse, want.metrics.edgeRmse, 1e-6) << k;
        EXPECT_NEAR(got.metrics.costMs, want.metrics.costMs, 1e-5) << k;
        EXPECT_EQ(a.rows[k].point, w.rows[k].point) << k;
        EXPECT_EQ(a.rows[k].glRenderer, "llvmpipe");
    }
    EXPECT_EQ(a.result.gridSize, 24u);
    EXPECT_EQ(a.result.choice, w.result.choice);
    EXPECT_EQ(a.result.runnerUp, w.result.runnerUp);
    EXPECT_DOUBLE_EQ(a.budget.maxEdgeRmse, static_cast<float>(0.1));
    EXPECT_FALSE(a.budget.maxAcne.has_value());
    EXPECT_TRUE(a.budget.maxShimmer.has_value());
    EXPECT_EQ(a.binding, adviseBinding(w.result, w.budget));
    EXPECT_EQ(a.scene, "box-on-plane");
}

// Marks edited by hand into saying something the measures and the budget do not: the broken
// budgets of a line, the choice moved to another line, a budget changed under the marks.
TEST(AdviseRead, RefusesMarksItsOwnBudgetDoesNotGive) {
    Written w = written();
    auto refusal = [&](const std::string& csv, const std::string& json) {
        try {
            parseAdviseReport(csv, "advise.csv", json, "advise.json");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    // Line 3: hw2x2 on 256 breaks the edge; marked as breaking nothing.
    std::string r = refusal(withField(withField(w.csv, 3, 15, "-"), 3, 14, "1"), w.json);
    EXPECT_EQ(r.rfind("advise.csv:3: marked '-'", 0), 0u) << r;
    // The chosen mark on tent (line 5) instead of hw2x2 512 (line 4).
    r = refusal(withField(withField(w.csv, 4, 16, "0"), 5, 16, "1"), w.json);
    EXPECT_NE(r.find("advise.csv: the setting marked chosen is not the one"), std::string::npos)
        << r;
    // An edge budget of 0.3 in advise.json: hw2x2 on 256 (0.25, line 3) meets it, but its line
    // is marked as breaking the edge.
    std::string json = w.json;
    json.replace(json.find("\"edge\": 0.1"), 11, "\"edge\": 0.3");
    r = refusal(w.csv, json);
    EXPECT_EQ(r.rfind("advise.csv:3: marked 'edge'", 0), 0u) << r;
    EXPECT_EQ(refusal("method,kernel\n", w.json).rfind("advise.csv:1: not an advise.csv", 0), 0u);
    EXPECT_EQ(refusal(w.csv, "[]").rfind("advise.json: not a JSON object", 0), 0u);
}

TEST(AdviseRead, AFileNamedAdviseCsvIsAnAdviseChart) {
    EXPECT_EQ(stepChartRef("figures/box_advise/advise.csv").kind, StepChartKind::Advise);
    EXPECT_EQ(stepChartRef("figures/bench.csv").kind, StepChartKind::Bench);
    EXPECT_EQ(stepChartRef("figures/bench.csv#contact").kind, StepChartKind::Bench);
    EXPECT_EQ(stepChartRef("figures/stability.csv#acne").kind, StepChartKind::Stability);
    std::string figures = PCFSCOPE_SOURCE_DIR "/lessons/figures/box_advise/advise.csv";
    EXPECT_NO_THROW(checkStepChart(figures));
    EXPECT_THROW(checkStepChart(figures + "#acne"), InputError);
    // No highlight on it: the chart rings its own choice.
    EXPECT_THROW(checkStepChartHighlight(figures, "hw2x2 512"), std::invalid_argument);
}

class AdviseStepChart : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("advise-step"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    // A one-step lesson charting `folder`/advise.csv; the chart line is line 6.
    std::string lesson(const std::filesystem::path& folder, const std::string& claims = "") {
        std::string path = (mDir / "advise.toml").string();
        std::ofstream(path) << "title = \"Advice\"\n"                 // 1
                               "scene = \"box-on-plane\"\n"           // 2
                               "[[step]]\n"                           // 3
                               "title = \"The chart\"\n"              // 4
                               "text = \"The settings measured.\"\n"  // 5
                               "chart = \""
                            << (folder / "advise.csv").string() << "\"\n"  // 6
                            << claims;                                     // 7..
        return path;
    }
    std::filesystem::path mDir;
};

// A folder without its advise.json, or one whose CSV is not advise's, is a bad lesson: one line
// at the chart's line, exit 2, from `lesson check` and from `export`.
TEST_F(AdviseStepChart, ABadFolderIsRefusedAtTheChartsLine) {
    Written w = written();
    std::filesystem::path folder = mDir / "run";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "advise.csv") << w.csv;
    std::string path = lesson(folder);
    std::string out = (mDir / "out-advise").string();
    for (std::string command :
         {std::string("lesson check "), "export -o " + out + " --size 640x360 "}) {
        testutil::CommandResult r = testutil::runPcfscope(command + path);
        EXPECT_EQ(r.exitCode, 2) << command << r.out << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(path + ":6:"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("advise.json"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(mDir / "out-advise"));
    std::ofstream(folder / "advise.json") << w.json;
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
}

// A claim false for the committed figures fails at its line with what the chart shows (exit 1);
// one this chart's facts do not know is a bad file (exit 2).
TEST_F(AdviseStepChart, AFalseClaimAboutTheCommittedFiguresFailsAtItsLine) {
    std::filesystem::path figures = PCFSCOPE_SOURCE_DIR "/lessons/figures/box_advise";
    std::string path =
        lesson(figures,
               "claims = [\"chart: the choice is nearest map 256 bias none\",\n"  // 7
               "  \"chart: nearest map 256 bias none meets the budget\",\n"       // 8
               "  \"chart: the budget is edge 0.2\"]\n");                         // 9
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_EQ(testutil::lineCount(r.out), 3) << r.out;
    EXPECT_NE(r.out.find(path + ":7: step 1 claim \"chart: the choice is nearest map 256 bias "
                                "none\" fails: the choice is "),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(path + ":8: step 1 claim \"chart: nearest map 256 bias none meets the "
                                "budget\" fails: nearest map 256 bias none breaks edge"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(path + ":9: step 1 claim \"chart: the budget is edge 0.2\" fails: the "
                                "budget is edge 0.1, "),
              std::string::npos)
        << r.out;
    path = lesson(figures, "claims = [\"chart: the front is nearest 256\"]\n");
    r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(path + ":7: step 1 claim \"chart: the front is nearest 256\": unknown "
                                "chart fact"),
              std::string::npos)
        << r.err;
}

}  // namespace
}  // namespace pcf
