// The cascades sweep (measure/stability_cascades.h) on llvmpipe, at a small size: along the
// turning path the sphere fit's texel is constant and the box fit's swings by 1.2x or more; with
// sphere and snapping no static receiver that stays in one cascade flickers, while the free box
// fit's do; across a split on the wall's shadow edge the two cascades disagree by more than 0.05
// without a blend band and by less with one, on the same frame; the rows come back as
// stability_cascades.csv's lines and as the chart's lines.
#include "measure/stability_cascades.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>

#include "chart_text_checks.h"
#include "charts/chart_axes.h"
#include "charts/stability_cascades_figures.h"
#include "kernel/cascades.h"
#include "kernel/methods.h"
#include "render/gl_context.h"
#include "render/scene_renderer.h"

namespace pcf {
namespace {

class StabilityCascades : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        sContext = createHeadlessContext();
        StabilityOptions o = quickStabilityOptions();
        o.sweeps = {Sweep::Cascades};
        o.methods = {{PCF_GATHER, 3}};
        o.frameSize = {192, 108};
        o.mapSize = 256;
        o.cascadeLambdas = {0.5f};
        o.cascadePathSteps = 5;
        ASSERT_FALSE(validateStabilityOptions(o));
        sOptions = o;
        runCascadeSweep(o, {}, sRows);
    }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
    static StabilityOptions sOptions;
    static std::vector<StabilityRow> sRows;
};
std::unique_ptr<GlContext> StabilityCascades::sContext;
StabilityOptions StabilityCascades::sOptions;
std::vector<StabilityRow> StabilityCascades::sRows;

TEST_F(StabilityCascades, EveryFitAndSnapHasARowPerCascade) {
    std::vector<CascadePoint> points = cascadePoints(sRows);
    ASSERT_EQ(points.size(), 4u * CASCADE_SWEEP_CASCADES);
    for (const CascadePoint& p : points) {
        EXPECT_EQ(p.method, PCF_GATHER);
        EXPECT_DOUBLE_EQ(p.lambda, 0.5);
        EXPECT_GT(p.texelWorldMin, 0.0);
        EXPECT_GE(p.texelWorldMax, p.texelWorldMin);
        EXPECT_GT(p.texelsPerPixelMedian, 0.0) << p.fit << " " << p.cascade;
        // A seam at every split, none after the last cascade.
        EXPECT_EQ(p.seamDifference.has_value(), p.cascade + 1 < CASCADE_SWEEP_CASCADES);
    }
}

TEST_F(StabilityCascades, TheSphereKeepsItsTexelAndTheBoxDoesNot) {
    for (const CascadePoint& p : cascadePoints(sRows)) {
        double swing = p.texelWorldMax / p.texelWorldMin;
        if (p.fit == "sphere") {
            EXPECT_LE(swing - 1.0, 1e-4) << "cascade " << p.cascade;
        } else {
            EXPECT_GE(swing, 1.2) << "cascade " << p.cascade << (p.snap ? " snapped" : "");
        }
        std::printf("%s %s cascade %d: texel %.5f .. %.5f (x%.3f), flicker %.4f of %g\n",
                    p.fit.c_str(), p.snap ? "snap" : "free", p.cascade, p.texelWorldMin,
                    p.texelWorldMax, swing, p.flickerRate, p.staticReceivers);
    }
}

TEST_F(StabilityCascades, SphereAndSnapNeverFlickerWhereTheFreeBoxDoes) {
    double freeBoxFlicker = 0.0;
    for (const CascadePoint& p : cascadePoints(sRows)) {
        // Enough receivers stay in each cascade for the rate to mean something.
        EXPECT_GT(p.staticReceivers, 20.0) << p.fit << " cascade " << p.cascade;
        if (p.fit == "sphere" && p.snap) {
            EXPECT_EQ(p.flickerRate, 0.0) << "cascade " << p.cascade;
        }
        if (p.fit == "box" && !p.snap) freeBoxFlicker = std::max(freeBoxFlicker, p.flickerRate);
    }
    // The measure sees flicker where there is some: the free box's texels slide and resize.
    EXPECT_GT(freeBoxFlicker, 0.01);
}

TEST_F(StabilityCascades, TheBlendBandClosesTheSeamOnTheSameFrame) {
    double worstOff = 0.0;
    for (const CascadePoint& p : cascadePoints(sRows)) {
        if (!p.seamDifference) continue;
        ASSERT_TRUE(p.seamDifferenceBlended.has_value());
        EXPECT_LT(*p.seamDifferenceBlended, 0.05) << p.fit << " cascade " << p.cascade;
        worstOff = std::max(worstOff, *p.seamDifference);
    }
    EXPECT_GT(worstOff, 0.05);
}

// The probe itself, on one frame: the points it takes lie on the wall's shadow edge where it
// crosses the split, and a blend band of any width closes it.
TEST_F(StabilityCascades, TheSeamProbeFindsTheWallsEdgeAtEverySplit) {
    Scene scene = cascadeSweepScene();
    SceneRenderer renderer(scene);
    RenderSettings s;
    s.method = PCF_GATHER;
    s.bias = BiasMode::Normal;
    s.cascades = CASCADE_SWEEP_CASCADES;
    s.shadowDistance = CASCADE_SWEEP_DISTANCE;
    s.cascadeFit = CASCADE_FIT_SPHERE;
    s.cascadeSnap = true;
    s.mapSize = 256;
    s.frameSize = {320, 180};
    s.writePositions = true;
    renderer.render(s);
    FrameSurfaces frame{renderer.frameSize(), renderer.readLightSpace(), renderer.readPositions(),
                        renderer.readNormals()};
    ShadowMap map = renderer.readShadowMap();
    for (int split = 0; split + 1 < CASCADE_SWEEP_CASCADES; ++split) {
        SeamProbe off = seamProbe(map, scene.camera, s, renderer.pcfParams(s), frame, split);
        EXPECT_GT(off.points, 10) << split;
        EXPECT_GT(off.edgePoints, 0) << split;
        std::printf("split %d: %d points, %d on an edge, seam without a band %.4f\n", split,
                    off.points, off.edgePoints, off.difference);
        for (float blend : {0.05f, 0.3f, 1.0f}) {
            RenderSettings b = s;
            b.cascadeBlend = blend;
            SeamProbe on = seamProbe(map, scene.camera, b, renderer.pcfParams(b), frame, split);
            EXPECT_EQ(on.points, off.points);
            EXPECT_LT(on.difference, 0.05) << split << " blend " << blend;
        }
    }
    // No split after the last cascade.
    EXPECT_EQ(seamProbe(map, scene.camera, s, renderer.pcfParams(s), frame, 3).points, 0);
}

TEST_F(StabilityCascades, TheCsvAndTheChartCarryThePoints) {
    std::string csv = cascadeCsv(sRows);
    std::istringstream lines(csv);
    std::string line;
    std::getline(lines, line);
    EXPECT_EQ(line, CASCADE_CSV_HEADER);
    int count = 0;
    while (std::getline(lines, line)) {
        ++count;
        EXPECT_TRUE(line.starts_with("pcf-gather,3,practical,0.5,")) << line;
        // The last cascade's seams are empty.
        if (line.find(",3,") != std::string::npos && line.find("true,3,") != std::string::npos) {
            EXPECT_NE(line.find(",,,"), std::string::npos) << line;
        }
    }
    EXPECT_EQ(count, 4 * CASCADE_SWEEP_CASCADES);
    EXPECT_EQ(cascadeSplitOfLambda(0.0), "uniform");
    EXPECT_EQ(cascadeSplitOfLambda(1.0), "log");

    LineChartSpec spec = cascadeChartSpec(
        sRows, "rendered on llvmpipe (LLVM 15.0.6; 256 bits) (llvmpipe: a CPU rasteriser)",
        STANDALONE_CHART_MIN_PX);
    ASSERT_EQ(spec.panels.size(), 1u);  // the sphere fit, snapped
    for (const ChartPanel& panel : spec.panels) {
        ASSERT_EQ(panel.lines.size(), static_cast<size_t>(CASCADE_SWEEP_CASCADES));
        for (const ChartLine& l : panel.lines) ASSERT_EQ(l.points.size(), 1u);
        // Halfway to the log split the near cascade still has fewer texels per pixel than the far
        // one, whose pixels cover more of the world.
        EXPECT_LT(panel.lines[0].points[0].y, panel.lines[3].points[0].y) << panel.title;
    }
    for (glm::ivec2 size : {glm::ivec2(640, 360), glm::ivec2(1280, 720)}) {
        std::vector<ChartTextBox> boxes = lineChartTextBoxes(spec, size);
        ASSERT_GT(boxes.size(), 5u);
        std::vector<std::string> faults = testutil::chartTextFaults(boxes, size);
        EXPECT_TRUE(faults.empty()) << faults.front();
    }
}

TEST(StabilityCascadeOptions, BadOptionsAreNamed) {
    StabilityOptions o = quickStabilityOptions();
    o.sweeps = {Sweep::Cascades};
    o.cascadeLambdas = {0.5f, 1.5f};
    ASSERT_TRUE(validateStabilityOptions(o));
    EXPECT_NE(validateStabilityOptions(o)->text().find("1.5"), std::string::npos);
    o.cascadeLambdas = {0.5f};
    o.cascadePathSteps = 1;
    EXPECT_TRUE(validateStabilityOptions(o));
    o.cascadePathSteps = 4;
    o.methods = {{PCF_PCSS, 0}};
    ASSERT_TRUE(validateStabilityOptions(o));
    EXPECT_NE(validateStabilityOptions(o)->text().find("cascades"), std::string::npos);
}

}  // namespace
}  // namespace pcf
