// The bleed sweep (measure/stability_bleed.h) on llvmpipe: the lower card's umbra is where the
// geometry puts it; pcf-gather compares depths, so no light reaches the clean umbra at any gap;
// the points come back as stability_bleed.csv's lines and as the chart's dots.
#include "measure/stability_bleed.h"

#include <gtest/gtest.h>

#include <memory>
#include <sstream>

#include "chart_text_checks.h"
#include "charts/chart_axes.h"
#include "charts/stability_bleed_figures.h"
#include "charts/stability_chart.h"
#include "kernel/methods.h"
#include "measure/failure_measures.h"
#include "measure/ground_truth.h"
#include "measure/stability_report.h"
#include "render/gl_context.h"
#include "scene/presets.h"

namespace pcf {
namespace {

const Box& boxNamed(const Scene& scene, std::string_view name) {
    for (const SceneObject& o : scene.objects) {
        if (o.name == name) return std::get<Box>(o.shape);
    }
    throw std::runtime_error("no box " + std::string(name));
}

// The hard truth's umbra of the lower card is where the geometry says: a ground point is in it
// when the line from it toward the light crosses the card's underside or top inside its square.
// Pixels whose crossing lies within 1e-3 of a square's edge are left out (a pixel centre on the
// edge can go either way in float).
TEST(StabilityBleedScene, TheLowerCardsUmbraIsWhereItsSquareProjects) {
    for (double gap : {0.25, 1.0}) {
        SCOPED_TRACE(gap);
        Scene scene = bleedScene(gap);
        const glm::ivec2 size(160, 90);
        std::vector<std::optional<Hit>> hits = centreHits(scene, size, 0);
        int lowerIndex = 0;
        while (scene.objects[static_cast<size_t>(lowerIndex)].name != BLEED_LOWER_CARD) {
            ++lowerIndex;
        }
        std::vector<uint8_t> umbra = objectUmbra(scene, hits, lowerIndex);
        GroundTruthOptions hard;
        hard.spp = 1;
        GroundTruth truth = computeGroundTruth(scene, size, hard);
        const Box& card = boxNamed(scene, BLEED_LOWER_CARD);
        glm::vec3 toLight = -glm::normalize(scene.light.directionWs);
        int inside = 0, checked = 0;
        for (size_t k = 0; k < hits.size(); ++k) {
            if (!hits[k] || scene.objects[static_cast<size_t>(hits[k]->object)].name != "ground") {
                continue;
            }
            // The card is a thin box: the line crosses it when it crosses its underside's square
            // or its top's (the two squares, offset along the light, cover its shadow).
            glm::vec3 p = hits[k]->posWs;
            float margin = -1.0f;
            bool nearEdge = false;
            for (float face : {-1.0f, 1.0f}) {
                float y = card.centreWs.y + face * card.halfExtents.y;
                glm::vec3 q = p + toLight * ((y - p.y) / toLight.y);
                glm::vec2 off = glm::abs(glm::vec2(q.x - card.centreWs.x, q.z - card.centreWs.z));
                float m = card.halfExtents.x - std::max(off.x, off.y);
                nearEdge = nearEdge || std::abs(m) < 1e-3f;
                margin = std::max(margin, m);
            }
            if (nearEdge) continue;
            ++checked;
            bool projects = margin > 0.0f;
            EXPECT_EQ(umbra[k] != 0, projects) << "pixel " << k;
            inside += projects;
            // The truth integrates over the pixel: wholly shadowed a pixel's width (under 0.03
            // here) inside the edge.
            if (margin > 0.05f) {
                EXPECT_EQ(truth.visibility[k], 0.0f) << "pixel " << k;
            }
        }
        // The umbra is a sizeable patch of the frame's ground.
        EXPECT_GT(inside, 150);
        EXPECT_GT(checked, 4 * inside);
    }
}

class StabilityBleed : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> StabilityBleed::sContext;

TEST_F(StabilityBleed, PcfGatherLeaksNothingIntoTheCleanUmbraAtEveryGap) {
    StabilityOptions o = quickStabilityOptions();
    o.sweeps = {Sweep::Bleed};
    o.methods = {{PCF_GATHER, 3}, {PCF_NEAREST, 0}};
    o.bleedMethods = {};
    o.bleedGaps = {0.05f, 1.0f, 2.0f};
    ASSERT_FALSE(validateStabilityOptions(o));
    Scene scene = *presetScene("box-on-plane");
    StabilityContext context;
    context.scene = &scene;
    std::vector<StabilityRow> rows = runStability(context, o).rows;
    for (float gap : o.bleedGaps) {
        for (const StabilityMethod& m : o.methods) {
            SCOPED_TRACE(stabilityMethodName(m) + " at gap " + std::to_string(gap));
            auto v = [&](const char* metric) {
                return stabilityValue(rows, "bleed", m, "constant", metric, gap).value_or(-1.0);
            };
            EXPECT_GT(v("umbra_pixels"), 100.0);
            EXPECT_GT(v("penumbra_pixels"), 10.0);
            EXPECT_EQ(v("leak_mean"), 0.0);
            EXPECT_EQ(v("leak_p99"), 0.0);
            // A filter of the hard map against the area truth: neither far off in the penumbra.
            EXPECT_LT(std::abs(v("penumbra_error")), 0.5);
        }
    }

    // stability_bleed.csv: its header, a line per point, the setting columns empty for methods
    // at their defaults.
    std::istringstream csv(bleedCsv(rows, o.base));
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line,
              "sweep,method,kernel,gap,lbr,exponents,moment_bias,moment_format,leak_mean,"
              "leak_p99,penumbra_error");
    std::getline(csv, line);
    EXPECT_EQ(line.substr(0, 35), "bleed,pcf-gather,3,0.0500000007,,,,");
    int lines = 1;
    while (std::getline(csv, line)) ++lines;
    EXPECT_EQ(lines, 6);

    // The chart: at the preset's default gap (1), a dot per method, no leak above the floor.
    LineChartSpec spec = bleedChartSpec(rows, "source");
    EXPECT_EQ(bleedChartGap(rows), 1.0);
    ASSERT_EQ(spec.panels.size(), 1u);
    ASSERT_EQ(spec.panels[0].lines.size(), 2u);
    for (const ChartLine& l : spec.panels[0].lines) {
        ASSERT_EQ(l.points.size(), 1u);
        EXPECT_EQ(l.points[0].y, 0.0);
    }
    EXPECT_EQ(spec.panels[0].title, "at the run's settings");
    EXPECT_EQ(spec.panels[0].lines[0].label, "pcf-gather 3x3");
}

// The measure of light bleeding: at the preset's default gap vsm lets more than a tenth
// of the light through in the lower card's clean umbra (its 99th percentile) with no
// light-bleeding reduction, and under 1e-3 from a reduction the chart names, which darkens the
// penumbra more than none does; the chart's vsm line has a point per reduction.
TEST_F(StabilityBleed, VsmLeaksAtTheDefaultGapUntilTheReductionTheChartNames) {
    StabilityOptions o = quickStabilityOptions();
    o.sweeps = {Sweep::Bleed};
    o.methods = {{PCF_GATHER, 3}};
    o.bleedGaps = {static_cast<float>(presetParams(BLEED_PRESET).front().defaultValue)};
    o.bleedMethods = {{PCF_VSM, 3}};
    o.bleedSettings = {{"lbr", {"0", "0.1", "0.2", "0.3", "0.5"}}};
    ASSERT_FALSE(validateStabilityOptions(o));
    Scene scene = *presetScene("box-on-plane");
    StabilityContext context;
    context.scene = &scene;
    std::vector<StabilityRow> rows = runStability(context, o).rows;
    const StabilityMethod vsm{PCF_VSM, 3};
    const double gap = o.bleedGaps.front();
    auto v = [&](const std::string& metric) {
        return stabilityValue(rows, "bleed", vsm, "constant", metric, gap).value_or(-1.0);
    };
    EXPECT_GT(v("lbr=0:leak_p99"), 0.1);
    EXPECT_GT(v("lbr=0:leak_mean"), 0.0);
    // Measured over the swept settings only: no line at the run's values besides them.
    EXPECT_FALSE(stabilityValue(rows, "bleed", vsm, "constant", "leak_p99", gap));
    std::string cut;
    for (const std::string& lbr : o.bleedSettings.front().values) {
        if (cut.empty() && v("lbr=" + lbr + ":leak_p99") < BLEED_LEAK_TARGET) cut = lbr;
    }
    ASSERT_FALSE(cut.empty()) << "no reduction brings vsm's leak under 1e-3";
    EXPECT_NE(cut, "0");
    // Its price: the penumbra darker than with no reduction.
    EXPECT_LT(v("lbr=" + cut + ":penumbra_error"), v("lbr=0:penumbra_error"));

    LineChartSpec spec = bleedChartSpec(rows, "source");
    ASSERT_EQ(spec.panels.size(), 1u);
    const ChartLine* line = nullptr;
    for (const ChartLine& l : spec.panels[0].lines) {
        if (l.label == "vsm 3x3") line = &l;
    }
    ASSERT_TRUE(line);
    EXPECT_EQ(line->points.size(), o.bleedSettings.front().values.size());
    EXPECT_DOUBLE_EQ(line->points.front().y, v("lbr=0:leak_p99"));
    EXPECT_NEAR(line->points.front().x, -v("lbr=0:penumbra_error"), 5e-4);
    ASSERT_EQ(spec.notes.size(), 1u);
    EXPECT_TRUE(
        spec.notes.front().starts_with("vsm 3x3: leak < 0.001 from lbr " + cut + ", darkening "))
        << "the chart names lbr " << cut << ": " << spec.notes.front();
    EXPECT_NE(spec.subtitle.find("swept: lbr 0 to 0.5 (5 values)"), std::string::npos)
        << spec.subtitle;
    // stability.md's paragraph names the same reduction.
    EXPECT_NE(bleedMarkdown(rows).find("- vsm N=3, lbr 0 to 0.5: leak "), std::string::npos)
        << bleedMarkdown(rows);
    EXPECT_NE(bleedMarkdown(rows).find("under 0.001 from " + cut + ", darkening"),
              std::string::npos)
        << bleedMarkdown(rows);
    // Whole and apart at --quick's chart size and the default one: no text on another (the
    // panel's title ran under the legend at 640x360).
    // The long subtitle a run writes, and the stand-alone type floor `stability` draws with.
    LineChartSpec drawn = bleedChartSpec(
        rows, "rendered on llvmpipe (LLVM 15.0.6; 256 bits) (llvmpipe: a CPU rasteriser)",
        STANDALONE_CHART_MIN_PX);
    for (glm::ivec2 size : {glm::ivec2(640, 360), glm::ivec2(1280, 720)}) {
        std::vector<ChartTextBox> boxes = lineChartTextBoxes(drawn, size);
        ASSERT_GT(boxes.size(), 5u);
        std::vector<std::string> faults = testutil::chartTextFaults(boxes, size);
        EXPECT_TRUE(faults.empty()) << faults.front();
    }

    // stability_bleed.csv: vsm's lines carry the swept lbr, and the run's moment format where it
    // was not swept; exponents and moment bias do not act for vsm.
    std::string csv = bleedCsv(rows, o.base);
    EXPECT_NE(csv.find("bleed,vsm,3,1,0.3,,,32f,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("bleed,pcf-gather,3,1,,,,,0,0,"), std::string::npos) << csv;
}

// A setting whose value holds a comma (evsm's exponents POS,NEG) travels through stability.csv
// as POS;NEG (its fields hold no comma, so the CSV reads back) and comes out of
// stability_bleed.csv quoted as the command line writes it.
TEST(StabilityBleedRows, ExponentsKeepTheirCommaOutOfStabilityCsv) {
    std::vector<StabilityRow> rows;
    for (const char* metric : {"leak_mean", "leak_p99", "penumbra_error"}) {
        rows.push_back({"bleed", PCF_EVSM2, 5, "constant", "gap", 1.0,
                        std::string("evsm_exponents=20;5:") + metric, 0.5});
    }
    std::vector<StabilityRow> back = parseStabilityCsv(stabilityCsv(rows), "stability.csv");
    std::vector<BleedPoint> points = bleedPoints(back);
    ASSERT_EQ(points.size(), 1u);
    EXPECT_EQ(points[0].key, "evsm_exponents");
    EXPECT_EQ(points[0].value, "20,5");
    std::string csv = bleedCsv(back, ShadowSettings{});
    EXPECT_NE(csv.find("\nbleed,evsm2,5,1,0,\"20,5\",,32f,0.5,0.5,0.5\n"), std::string::npos)
        << csv;
}

// Rows of a sweep over every setting, as runBleedSweep writes them: per method and swept value,
// the three measures (leak falling and darkening growing along each setting's values).
std::vector<StabilityRow> sweptRows() {
    struct Point {
        int method;
        const char* setting;  // "" at the run's settings
        double leak, error;
    };
    const Point points[] = {{PCF_GATHER, "", 0.0, -0.01},
                            {PCF_VSM, "lbr=0:", 0.3, -0.004},
                            {PCF_VSM, "lbr=0.2:", 0.01, -0.03},
                            {PCF_VSM, "lbr=0.3:", 0.0005, -0.05},
                            {PCF_VSM, "moment_format=16f:", 0.35, -0.004},
                            {PCF_VSM, "moment_format=32f:", 0.3, -0.004},
                            {PCF_EVSM2, "lbr=0:", 0.02, -0.01},
                            {PCF_EVSM2, "lbr=0.3:", 0.002, -0.06},
                            {PCF_EVSM2, "evsm_exponents=5;5:", 0.1, -0.002},
                            {PCF_EVSM2, "evsm_exponents=50;50:", 0.0001, -0.01},
                            {PCF_EVSM2, "moment_format=16f:", 0.2, -0.003},
                            {PCF_MSM, "moment_bias=3e-5:", 0.002, -0.01},
                            {PCF_MSM, "moment_bias=3e-3:", 0.0002, -0.02}};
    std::vector<StabilityRow> rows;
    for (const Point& p : points) {
        const int kernel = p.method == PCF_GATHER ? 3 : 5;
        const std::pair<const char*, double> measures[] = {
            {"leak_mean", p.leak / 2}, {"leak_p99", p.leak}, {"penumbra_error", p.error}};
        for (auto [metric, y] : measures) {
            rows.push_back({"bleed", p.method, kernel, "constant", "gap", 1.0,
                            std::string(p.setting) + metric, y});
        }
    }
    return rows;
}

// The chart shows the trade-off over every setting swept, not the first alone: a panel per
// setting in the sweep's order, in each a line per method it was swept for through all its
// values and the depth-comparing method's dot; the subtitle lists the settings; the notes name
// the first reduction that brings each line of the first panel under 1e-3.
TEST(StabilityBleedChart, APanelPerSettingSweptWithEveryValue) {
    std::vector<StabilityRow> rows = sweptRows();
    LineChartSpec spec = bleedChartSpec(rows, "source");
    ASSERT_EQ(spec.panels.size(), 4u);
    const char* titles[] = {"over lbr", "over moment_format", "over evsm_exponents",
                            "over moment_bias"};
    // (label, points) per panel, in order.
    const std::vector<std::vector<std::pair<std::string, size_t>>> lines = {
        {{"pcf-gather 3x3", 1}, {"vsm 5x5", 3}, {"evsm2 5x5", 2}},
        {{"pcf-gather 3x3", 1}, {"vsm 5x5", 2}, {"evsm2 5x5", 1}},
        {{"pcf-gather 3x3", 1}, {"evsm2 5x5", 2}},
        {{"pcf-gather 3x3", 1}, {"msm 5x5", 2}}};
    for (size_t k = 0; k < 4; ++k) {
        SCOPED_TRACE(titles[k]);
        EXPECT_EQ(spec.panels[k].title, titles[k]);
        ASSERT_EQ(spec.panels[k].lines.size(), lines[k].size());
        for (size_t j = 0; j < lines[k].size(); ++j) {
            EXPECT_EQ(spec.panels[k].lines[j].label, lines[k][j].first);
            EXPECT_EQ(spec.panels[k].lines[j].points.size(), lines[k][j].second);
        }
    }
    // vsm over lbr: leak against darkening, point by point.
    const ChartLine& vsm = spec.panels[0].lines[1];
    EXPECT_EQ(vsm.points[2], glm::dvec2(0.05, 0.0005));
    EXPECT_EQ(vsm.points[0], glm::dvec2(0.004, 0.3));
    EXPECT_EQ(spec.subtitle,
              "source\nswept: lbr 0 to 0.3 (3 values); moment_format 16f, 32f; evsm_exponents "
              "5,5, 50,50; moment_bias 3e-5, 3e-3");
    ASSERT_EQ(spec.notes.size(), 2u);
    EXPECT_EQ(spec.notes[0], "vsm 5x5: leak < 0.001 from lbr 0.3, darkening 0.05");
    EXPECT_EQ(spec.notes[1], "evsm2 5x5: leak >= 0.001 at every lbr");

    std::string md = bleedMarkdown(rows);
    EXPECT_NE(md.find("- vsm N=5, lbr 0 to 0.3: leak 0.3 (darkening 0.004) at 0; under 0.001 "
                      "from 0.3, darkening 0.05 there\n"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("- evsm2 N=5, lbr 0 to 0.3: leak 0.02 (darkening 0.01) at 0; never under "
                      "0.001\n"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("- pcf-gather N=3: leak 0 (darkening 0.01)\n"), std::string::npos) << md;
}

// stability_bleed.csv's exponents column says what the warps used: the asked 50,50 clamped to
// 42 in 32F, the run's 40,5 clamped to 5.54 on the 16F line; where exponents do not act, empty.
TEST(StabilityBleedRows, TheExponentsColumnHoldsTheExponentsUsed) {
    std::string csv = bleedCsv(sweptRows(), ShadowSettings{});
    EXPECT_NE(csv.find("\nbleed,evsm2,5,1,0,\"42,42\",,32f,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nbleed,evsm2,5,1,0,\"5,5\",,32f,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nbleed,evsm2,5,1,0,\"5.54,5\",,16f,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nbleed,evsm2,5,1,0.3,\"40,5\",,32f,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nbleed,vsm,5,1,0,,,16f,"), std::string::npos) << csv;
    EXPECT_EQ(csv.find("50,50"), std::string::npos) << csv;
}

}  // namespace
}  // namespace pcf
