// pcss's failure sweeps (measure/stability_pcss.h) on llvmpipe, as properties at --quick sizes:
// a pole thinner than the search's tap spacing drops out where pcf-gather 5x5 still sees it; a
// low block under a plank's shadow edge makes pcss's penumbra worse than the plank's alone; a
// wider filter needs more than the constant bias (and receiver-plane cures the small ones). Plus
// the sweeps' own checks and their charts' rows.
#include "measure/stability_pcss.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "charts/stability_pcss_figures.h"
#include "kernel/methods.h"
#include "measure/stability_report.h"
#include "render/gl_context.h"
#include "scene/presets.h"

namespace pcf {
namespace {

class StabilityPcss : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;

    static std::vector<StabilityRow> run(Sweep sweep, const StabilityOptions& o) {
        Scene scene = *presetScene("box-on-plane");
        StabilityContext context;
        context.scene = &scene;
        StabilityOptions one = o;
        one.sweeps = {sweep};
        return runStability(context, one).rows;
    }
};
std::unique_ptr<GlContext> StabilityPcss::sContext;

const StabilityMethod PCSS{PCF_PCSS, 0};
const StabilityMethod GATHER5{PCF_GATHER, 5};
const StabilityMethod POISSON{PCF_POISSON, 0};

double value(const std::vector<StabilityRow>& rows, std::string_view sweep,
             const StabilityMethod& m, std::string_view bias, std::string_view metric, double x) {
    std::optional<double> v = stabilityValue(rows, sweep, m, bias, metric, x);
    EXPECT_TRUE(v.has_value()) << sweep << " " << stabilityMethodName(m) << " " << bias << " "
                               << metric << " at " << x;
    return v.value_or(std::nan(""));
}

TEST_F(StabilityPcss, AThinPoleDropsOutOfTheBlockerSearchButNotOutOfTheMap) {
    StabilityOptions o = quickStabilityOptions();
    o.pcssPoleWidths = {1, 4};
    o.frameSize = {240, 135};  // the 1-texel pole's shadow: about 25 truth-shadowed pixels
    std::vector<StabilityRow> rows = run(Sweep::PcssThin, o);
    const char* rp = "receiver-plane";
    double radius = value(rows, "pcss-thin", PCSS, rp, "search_radius_texels", 1);
    // The 16 search taps lie further apart than the 1-texel pole is wide.
    EXPECT_GT(radius * 0.443, 1.0);
    double thin = value(rows, "pcss-thin", PCSS, rp, "missed_share_mean", 1);
    double wide = value(rows, "pcss-thin", PCSS, rp, "missed_share_mean", 4);
    double gather = value(rows, "pcss-thin", GATHER5, rp, "missed_share_max", 1);
    EXPECT_GT(value(rows, "pcss-thin", PCSS, rp, "shadowed_pixels", 1), 10.0);
    EXPECT_GT(thin, 0.2);
    EXPECT_LT(wide, thin / 2.0);
    EXPECT_LT(gather, 0.02);  // the map holds the pole: pcf-gather 5x5 sees it
    EXPECT_GE(value(rows, "pcss-thin", PCSS, rp, "missed_share_max", 1), thin);
}

TEST_F(StabilityPcss, ALowBlockUnderThePlanksEdgeMakesThePenumbraWorse) {
    StabilityOptions o = quickStabilityOptions();
    std::vector<StabilityRow> rows = run(Sweep::PcssOverlap, o);
    const char* rp = "receiver-plane";
    double alone = value(rows, "pcss-overlap", PCSS, rp, "alone:penumbra_rmse", 3);
    double stacked = value(rows, "pcss-overlap", PCSS, rp, "stacked:penumbra_rmse", 3);
    EXPECT_GT(stacked, alone * 1.1);
    EXPECT_GT(value(rows, "pcss-overlap", PCSS, rp, "alone:truth_penumbra_pixels", 3), 100.0);
}

TEST_F(StabilityPcss, AWiderFilterNeedsMoreThanTheConstantBias) {
    StabilityOptions o = quickStabilityOptions();
    // --quick's 128 map is so coarse that the 87-degree light's slope across one texel already
    // exceeds the constant bias; on 512 the smallest disk passes (the hard truth is cheap).
    o.mapSize = 512;
    std::vector<StabilityRow> rows = run(Sweep::PcssBias, o);
    double narrow = value(rows, "pcss-bias", POISSON, "constant", "false_shadow_rate", 1);
    double wide = value(rows, "pcss-bias", POISSON, "constant", "false_shadow_rate", 16);
    EXPECT_LT(narrow, 0.01);
    EXPECT_GT(wide, 0.05);
    EXPECT_LT(value(rows, "pcss-bias", POISSON, "receiver-plane", "false_shadow_rate", 4), 0.01);
}

TEST_F(StabilityPcss, TheNoiseSweepMeasuresBothDisksAndItsChartHasTheirLines) {
    StabilityOptions o = quickStabilityOptions();
    o.pcssLightSizes = {4};
    std::vector<StabilityRow> rows = run(Sweep::PcssNoise, o);
    double rotated = value(rows, "pcss-noise", PCSS, "receiver-plane", "rotated:penumbra_rmse", 4);
    double fixed = value(rows, "pcss-noise", PCSS, "receiver-plane", "fixed:penumbra_rmse", 4);
    // Rotating the disk changes which texels the taps read, so the error differs, but both are
    // pcss's approximation of the same penumbra: neither is off by more than a quarter.
    EXPECT_NE(rotated, fixed);
    EXPECT_GT(rotated, 0.0);
    EXPECT_LT(rotated, 0.25);
    EXPECT_LT(fixed, 0.25);
    LineChartSpec spec = pcssNoiseChartSpec(rows, "src");
    ASSERT_EQ(spec.panels.size(), 1u);
    ASSERT_EQ(spec.panels[0].lines.size(), 2u);
    EXPECT_EQ(spec.panels[0].lines[0].points.size(), 1u);
    EXPECT_TRUE(pcssThinChartSpec(rows, "src").panels.empty());
}

TEST(StabilityPcssOptions, OutOfRangeListsAreNamed) {
    StabilityOptions o;
    EXPECT_FALSE(validateStabilityOptions(o).has_value());
    o.pcssPlankHeights = {1, 7};
    ASSERT_TRUE(validateStabilityOptions(o).has_value());
    EXPECT_EQ(validateStabilityOptions(o)->setting, "pcss_plank_heights");
    o = StabilityOptions{};
    o.pcssPoleWidths = {0.1f};
    ASSERT_TRUE(validateStabilityOptions(o).has_value());
    EXPECT_EQ(validateStabilityOptions(o)->setting, "pcss_pole_widths");
    EXPECT_EQ(sweepFromName("pcss-thin"), Sweep::PcssThin);
    EXPECT_EQ(sweepName(Sweep::PcssBias), "pcss-bias");
}

TEST(StabilityPcssScenes, TheOverlapSceneAddsOneBlockAndTheSunsAreTheStatedOnes) {
    Scene alone = pcssOverlapScene(2.0f, false);
    Scene stacked = pcssOverlapScene(2.0f, true);
    EXPECT_EQ(alone.objects.size() + 1, stacked.objects.size());
    EXPECT_FLOAT_EQ(alone.light.angularDiameterDeg, 4.0f);
    Scene pole = pcssThinPoleScene(0.05f);
    EXPECT_FLOAT_EQ(pole.light.angularDiameterDeg, 8.0f);
}

}  // namespace
}  // namespace pcf
