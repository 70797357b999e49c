// The facts a lesson step states about its bench chart (charts/chart_facts.h), read from the
// CSV the chart draws: the truth it was measured against, the most and least accurate dot on
// the chart's own accuracy axis (the edge band's RMSE, or near the casters on a "#contact"
// chart, step_chart.h).
#include "charts/chart_facts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "base/input_error.h"
#include "charts/speed_chart.h"
#include "charts/step_chart.h"
#include "kernel/methods.h"
#include "measure/bench_report.h"
#include "measure/stability_report.h"
#include "run_command.h"

namespace pcf {
namespace {

// gather 3x3, 5x5, 7x7 and pcss on one map with post-in-sun's shape of numbers: over the whole
// edge band the widest fixed kernel beats the narrowest and pcss beats both; near the contact
// the order of the fixed widths turns over and pcss is second.
std::vector<BenchRow> contactRows() {
    struct Dot {
        int method, kernel;
        double edge, contact;
    };
    const Dot dots[] = {{PCF_GATHER, 3, 0.104, 0.073},
                        {PCF_GATHER, 5, 0.078, 0.102},
                        {PCF_GATHER, 7, 0.075, 0.139},
                        {PCF_PCSS, 0, 0.058, 0.076}};
    std::vector<BenchRow> rows;
    for (const Dot& d : dots) {
        BenchRow r;
        r.point = {d.method, d.kernel, 512};
        r.gpuMs = 1.0 + d.kernel;
        r.lookupMs = 0.5 + d.kernel;
        r.timer = "glFinish+steady_clock";
        r.error.edgeRmse = d.edge;
        r.contact.edgeRmse = d.contact;
        r.contact.edgePixels = 676;
        r.contactDistance = 1.0;
        r.truth = "area (a sun disk of 2 degrees)";
        r.glRenderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
        rows.push_back(r);
    }
    return rows;
}

class ChartFacts : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("chart-facts"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    std::string write(const std::string& name, const std::string& text) const {
        std::string path = (mDir / name).string();
        std::ofstream(path) << text;
        return path;
    }
    std::filesystem::path mDir;
};

TEST_F(ChartFacts, TheTruthIsTheOneTheCsvRecords) {
    std::string csv = write("bench.csv", benchCsv(contactRows()));
    ChartFactAnswer area = chartFactHolds(csv, "measured against the area truth");
    EXPECT_TRUE(area.holds) << area.why;
    EXPECT_EQ(area.why, "truth: area (a sun disk of 2 degrees)");
    EXPECT_FALSE(chartFactHolds(csv, "measured against the hard truth").holds);
    EXPECT_TRUE(chartFactHolds(csv + "#contact", "measured against the area truth").holds);
    EXPECT_THROW(chartFactHolds(csv, "measured against the soft truth"), std::invalid_argument);
    // A file from before the truth column cannot say: the fact does not hold, and says why.
    std::vector<BenchRow> rows = contactRows();
    for (BenchRow& r : rows) r.truth.clear();
    std::string old = write("old.csv", benchCsv(rows));
    ChartFactAnswer unknown = chartFactHolds(old, "measured against the area truth");
    EXPECT_FALSE(unknown.holds);
    EXPECT_NE(unknown.why.find("records no truth"), std::string::npos) << unknown.why;
}

TEST_F(ChartFacts, MostAndLeastAccurateReadTheChartsOwnAxis) {
    std::string csv = write("bench.csv", benchCsv(contactRows()));
    // The whole edge band: pcss lowest, gather 3x3 highest.
    EXPECT_TRUE(chartFactHolds(csv, "pcss is the most accurate").holds);
    EXPECT_TRUE(chartFactHolds(csv, "gather3 is the least accurate").holds);
    EXPECT_FALSE(chartFactHolds(csv, "gather7 is the least accurate").holds);
    // Near the contact: gather 7x7 highest; pcss is not the lowest, gather 3x3 is.
    std::string contact = csv + "#contact";
    EXPECT_TRUE(chartFactHolds(contact, "gather7 is the least accurate").holds);
    EXPECT_TRUE(chartFactHolds(contact, "gather3 is the most accurate").holds);
    ChartFactAnswer pcss = chartFactHolds(contact, "pcss is the most accurate");
    EXPECT_FALSE(pcss.holds);
    EXPECT_EQ(pcss.why, "gather3 512 0.073, pcss 0.076") << pcss.why;
    // A label must name one dot.
    std::vector<BenchRow> two = contactRows();
    two.push_back(two.front());
    two.back().point.mapSize = 1024;
    std::string twoMaps = write("two.csv", benchCsv(two));
    EXPECT_THROW(chartFactHolds(twoMaps, "gather3 is the most accurate"), std::invalid_argument);
    EXPECT_THROW(chartFactHolds(csv, "nothing3 is the most accurate"), std::invalid_argument);
    // These are bench facts: a stability chart does not know them.
    EXPECT_THROW(checkChartFactKnown("stability.csv#tradeoff", "pcss is the most accurate"),
                 std::invalid_argument);
    EXPECT_NO_THROW(checkChartFactKnown("bench.csv#contact", "pcss is the most accurate"));
}

// The contact chart of a lesson step: its title says near the contacts and the truth, its y
// axis the distance and the pixels (from the CSV); a CSV measured without --contact is refused.
TEST_F(ChartFacts, AContactChartSaysWhatItMeasured) {
    std::string csv = write("bench.csv", benchCsv(contactRows()));
    StepChartRef ref = stepChartRef(csv + "#contact");
    EXPECT_TRUE(ref.bench());
    EXPECT_EQ(ref.accuracy, ChartAccuracy::ContactRmse);
    EXPECT_EQ(ref.path, csv);
    EXPECT_FALSE(stepChartRef(csv + "#tradeoff").bench());
    EXPECT_NO_THROW(checkStepChart(csv + "#contact"));
    std::string title, subtitle, axis;
    for (const ChartTextBox& b :
         stepChartTexts(StepChart{csv + "#contact", "", 18.0f, true}, {1280, 720})) {
        if (b.role == "chart-title") title += b.text;
        if (b.role == "chart-subtitle") subtitle += b.text + " ";
        if (b.role == "chart-axis") axis += b.text + "|";
    }
    std::replace(subtitle.begin(), subtitle.end(), '\n', ' ');  // wrapped at spaces
    EXPECT_EQ(title, "Accuracy near the contacts");
    EXPECT_NE(subtitle.find("truth: area (a sun disk of 2 degrees)"), std::string::npos)
        << subtitle;
    EXPECT_NE(axis.find("edge-band RMSE within 1 world unit of a caster|"), std::string::npos)
        << axis;
    EXPECT_EQ(contactAxisLabel(contactRows()),
              "aliasing near the contacts: edge-band RMSE over the 676 edge pixels within 1 world "
              "unit of a caster");
    std::vector<BenchRow> rows = contactRows();
    for (BenchRow& r : rows) {
        r.contactDistance = 0.0;
        r.contact = {};
    }
    std::string plain = write("plain.csv", benchCsv(rows));
    EXPECT_NO_THROW(checkStepChart(plain));
    EXPECT_THROW(checkStepChart(plain + "#contact"), InputError);
    EXPECT_THROW(checkStepChartHighlight(plain + "#tradeoff", "front"), std::invalid_argument);
    EXPECT_NO_THROW(checkStepChartHighlight(csv + "#contact", "pcss"));
}

// The acne chart's lines as the sun sets (elevations 90 down to 5): a line over the onset from
// the zenith on, one that crosses it early, one that crosses it late, one that never does, and a
// hump that rises over it and falls back.
std::string acneCsv() {
    std::string csv = "sweep,method,kernel,bias,x_name,x,metric,y\n";
    struct Line {
        const char* method;
        int kernel;
        const char* bias;
        double rates[5];
    };
    const Line lines[] = {{"nearest", 0, "none", {0.21, 0.5, 0.5, 0.5, 0.5}},
                          {"nearest", 0, "constant", {0, 0.002, 0.009, 0.004, 0.04}},
                          {"pcf-gather", 5, "constant", {0, 0.4, 1, 1, 1}},
                          {"pcf-gather", 5, "receiver-plane", {0, 0, 0.005, 0, 0}},
                          {"pcf-gather", 5, "normal", {0, 0.011, 0.18, 0.0055, 0.004}}};
    const int elevations[] = {90, 87, 60, 25, 5};
    for (const Line& l : lines) {
        for (int k = 0; k < 5; ++k) {
            csv += std::string("acne,") + l.method + "," + std::to_string(l.kernel) + "," + l.bias +
                   ",elevation_deg," + std::to_string(elevations[k]) + ",false_shadow_rate," +
                   std::to_string(l.rates[k]) + "\n";
        }
    }
    return csv;
}

TEST_F(ChartFacts, AcneLinesAreReadAsTheSunSets) {
    std::string chart = write("stability.csv", acneCsv()) + "#acne";
    auto holds = [&](const std::string& fact) { return chartFactHolds(chart, fact).holds; };
    EXPECT_TRUE(holds("nearest none: over the onset at every elevation"));
    EXPECT_FALSE(holds("nearest constant: over the onset at every elevation"));
    // 0.9 % at 60 degrees is under the 1 % onset: nearest's constant line first reaches it at 5.
    EXPECT_TRUE(holds("nearest constant: crosses the onset below 10 degrees"));
    EXPECT_FALSE(holds("nearest constant: crosses the onset above 10 degrees"));
    EXPECT_FALSE(holds("nearest constant: crosses the onset below 5 degrees"));
    EXPECT_TRUE(holds("pcf-gather 5x5 constant: crosses the onset above 85 degrees"));
    EXPECT_FALSE(holds("pcf-gather 5x5 constant: crosses the onset above 87 degrees"));
    // Never over the onset: below every elevation, above none.
    EXPECT_TRUE(holds("pcf-gather 5x5 receiver-plane: crosses the onset below 1 degrees"));
    EXPECT_FALSE(holds("pcf-gather 5x5 receiver-plane: crosses the onset above 1 degrees"));
    EXPECT_TRUE(holds("pcf-gather 5x5 normal: rises over the onset and falls back"));
    // A climb that stays, a line that never climbs, one that starts over it: no hump.
    EXPECT_FALSE(holds("pcf-gather 5x5 constant: rises over the onset and falls back"));
    EXPECT_FALSE(holds("pcf-gather 5x5 receiver-plane: rises over the onset and falls back"));
    EXPECT_FALSE(holds("nearest none: rises over the onset and falls back"));
    ChartFactAnswer hump = chartFactHolds(chart,
                                          "pcf-gather 5x5 normal: rises over the onset and "
                                          "falls back");
    EXPECT_EQ(hump.why, "0% at 90 degrees, peak 18% at 60 degrees, 0.4% at 5 degrees");
    // Lines are named by panel and bias mode; a wrong name or number says what is known.
    EXPECT_THROW(holds("pcf-gather 5x5 slope: rises over the onset and falls back"),
                 std::invalid_argument);
    EXPECT_THROW(holds("nearest constant: crosses the onset below ten degrees"),
                 std::invalid_argument);
    EXPECT_THROW(holds("nearest constant: sinks under 10 degrees"), std::invalid_argument);
    // These facts belong to the acne chart, not to another view of the same file.
    EXPECT_THROW(checkChartFactKnown(write("s2.csv", acneCsv()) + "#leak",
                                     "nearest none: over the onset at every elevation"),
                 std::invalid_argument);
}

// A bleed sweep's rows (stability.csv): vsm 5x5 over lbr, its leak (99th percentile) under 1e-3
// from 0.3; evsm2 5x5 over lbr, never.
std::string bleedCsv() {
    std::vector<StabilityRow> rows;
    const std::tuple<const char*, int, const char*, double> points[] = {
        {"vsm", PCF_VSM, "0", 0.25},     {"vsm", PCF_VSM, "0.2", 0.01},
        {"vsm", PCF_VSM, "0.3", 0.0},    {"vsm", PCF_VSM, "0.5", 0.0},
        {"evsm2", PCF_EVSM2, "0", 0.02}, {"evsm2", PCF_EVSM2, "0.5", 0.002}};
    for (const auto& [name, method, lbr, leak] : points) {
        for (const char* metric : {"leak_mean", "leak_p99", "penumbra_error"}) {
            rows.push_back({"bleed", method, 5, "constant", "gap", 1.0,
                            std::string("lbr=") + lbr + ":" + metric, leak});
        }
    }
    return stabilityCsv(rows);
}

TEST_F(ChartFacts, BleedLinesNameTheFirstValueUnderTheLeakTarget) {
    std::string chart = write("stability.csv", bleedCsv()) + "#bleed";
    auto holds = [&](const std::string& fact) { return chartFactHolds(chart, fact).holds; };
    EXPECT_TRUE(holds("vsm 5x5: leak falls under 0.001 from lbr 0.3"));
    EXPECT_FALSE(holds("vsm 5x5: leak falls under 0.001 from lbr 0.2"));
    EXPECT_FALSE(holds("vsm 5x5: leak falls under 0.001 from lbr 0.5"));
    EXPECT_FALSE(holds("evsm2 5x5: leak falls under 0.001 from lbr 0.5"));
    EXPECT_EQ(chartFactHolds(chart, "vsm 5x5: leak falls under 0.001 from lbr 0.2").why,
              "first under it at 0.3 (leak 0)");
    // A line or setting the chart does not have is refused with the lines it has.
    EXPECT_THROW(holds("msm 5x5: leak falls under 0.001 from lbr 0"), std::invalid_argument);
    EXPECT_THROW(holds("vsm 5x5: leak falls under 0.001 from moment_bias 3e-5"),
                 std::invalid_argument);
    EXPECT_THROW(checkChartFactKnown(write("s2.csv", bleedCsv()) + "#acne",
                                     "vsm 5x5: leak falls under 0.001 from lbr 0.3"),
                 std::invalid_argument);
}

// The cascades chart's lines (texels per pixel against the split's lambda, sphere fit snapped):
// at lambda 0 cascade 0 reads far fewer texels per pixel than cascade 3, at 0.5 the spread is
// narrower, and at 1 the first two cascades hold no receiver. A box fit's row (100 texels per
// pixel in cascade 0) is not on the chart and changes none of its facts.
std::string cascadesCsv() {
    std::string csv = "sweep,method,kernel,bias,x_name,x,metric,y\n";
    const double lambdas[] = {0.0, 0.5, 1.0};
    const double medians[4][3] = {{0.2, 0.6, -1}, {3, 1.5, -1}, {9, 4, 0.4}, {14, 5, 0.8}};
    for (int c = 0; c < 4; ++c) {
        for (int k = 0; k < 3; ++k) {
            if (medians[c][k] < 0.0) continue;
            csv += "cascades,pcf-gather,3,normal,lambda," + std::to_string(lambdas[k]) +
                   ",sphere:snap:c" + std::to_string(c) + ":texels_per_pixel_median," +
                   std::to_string(medians[c][k]) + "\n";
        }
    }
    return csv + "cascades,pcf-gather,3,normal,lambda,0,box:free:c0:texels_per_pixel_median,100\n";
}

TEST_F(ChartFacts, CascadeLinesAreReadAtEachLambda) {
    std::string chart = write("stability.csv", cascadesCsv()) + "#cascades";
    auto holds = [&](const std::string& fact) { return chartFactHolds(chart, fact).holds; };
    EXPECT_TRUE(holds("at lambda 0, cascade 0 reads the fewest texels per pixel"));
    EXPECT_FALSE(holds("at lambda 0, cascade 1 reads the fewest texels per pixel"));
    EXPECT_TRUE(holds("at lambda 0, cascade 3 reads the most texels per pixel"));
    EXPECT_FALSE(holds("at lambda 0, cascade 0 reads the most texels per pixel"));
    EXPECT_TRUE(holds("at lambda 1, cascade 2 reads the fewest texels per pixel"));
    // A cascade with no receiver at that lambda is neither.
    EXPECT_FALSE(holds("at lambda 1, cascade 0 reads the fewest texels per pixel"));
    EXPECT_TRUE(holds("at lambda 1, cascade 0 holds no receiver"));
    EXPECT_TRUE(holds("at lambda 1, cascade 1 holds no receiver"));
    EXPECT_FALSE(holds("at lambda 1, cascade 2 holds no receiver"));
    EXPECT_FALSE(holds("at lambda 0.5, cascade 0 holds no receiver"));
    // 14 / 0.2 = 70x at lambda 0, 5 / 0.6 = 8.3x at 0.5.
    EXPECT_TRUE(holds("the cascades spread less at lambda 0.5 than at lambda 0"));
    EXPECT_FALSE(holds("the cascades spread less at lambda 0 than at lambda 0.5"));
    EXPECT_EQ(chartFactHolds(chart, "the cascades spread less at lambda 0.5 than at lambda 0").why,
              "at lambda 0.5 0.6 to 5 (8.33x); at lambda 0 0.2 to 14 (70x)");
    EXPECT_THROW(holds("at lambda 0, cascade 7 reads the most texels per pixel"),
                 std::invalid_argument);
    EXPECT_THROW(holds("at lambda zero, cascade 0 holds no receiver"), std::invalid_argument);
    EXPECT_THROW(holds("at lambda 0, cascade 0 reads the best texels per pixel"),
                 std::invalid_argument);
    // These facts belong to the cascades chart.
    EXPECT_THROW(checkChartFactKnown(write("s2.csv", cascadesCsv()) + "#acne",
                                     "at lambda 1, cascade 0 holds no receiver"),
                 std::invalid_argument);
}

}  // namespace
}  // namespace pcf
