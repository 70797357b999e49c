// An advise folder read back (measure/advise_read.h): what advise_report.h writes reads back to
// the same settings, measures, budget and choice; marks that disagree with the folder's own
// budget are refused in one line naming the file and the CSV's line. No GL context: it runs in
// CI's sanitized list (scripts/test); advise_step_chart_test draws the folder as a lesson step.
#include "measure/advise_read.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "advise_written.h"
#include "base/input_error.h"
#include "charts/step_chart.h"

namespace pcf {
namespace {

using advise_test::Written;
using advise_test::written;

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

}  // namespace
}  // namespace pcf
