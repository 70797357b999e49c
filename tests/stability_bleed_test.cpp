// The bleed sweep (measure/stability_bleed.h) on llvmpipe: the lower card's umbra is where the
// geometry puts it; pcf-gather compares depths, so no light reaches the clean umbra at any gap;
// the points come back as stability_bleed.csv's lines and as the chart's dots.
#include "measure/stability_bleed.h"

#include <gtest/gtest.h>

#include <memory>
#include <sstream>

#include "charts/stability_bleed_figures.h"
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
    std::istringstream csv(bleedCsv(rows));
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
    EXPECT_EQ(spec.panels[0].lines[0].label, "pcf-gather 3x3");
}

}  // namespace
}  // namespace pcf
