// kernel/cascades.h: where the cascades split the view depth (Zhang et al. 2006's practical
// scheme and its two ends), and the settings rows that choose it.
#include "kernel/cascades.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "kernel/settings.h"

namespace pcf {
namespace {

// The issue's numbers: n 0.1, f 100, four cascades.
TEST(CascadeSplits, PracticalWithLambdaHalfGivesTheIssuesSplits) {
    std::vector<double> c = cascadeSplits(0.1, 100.0, 4, CASCADE_SPLIT_PRACTICAL, 0.5);
    ASSERT_EQ(c.size(), 4u);
    EXPECT_NEAR(c[0], 12.8187, 1e-3);
    EXPECT_NEAR(c[1], 26.6061, 1e-3);
    EXPECT_NEAR(c[2], 46.4039, 1e-3);
    EXPECT_NEAR(c[3], 100.0, 1e-3);
}

TEST(CascadeSplits, LambdaOneAndTheLogSchemeGiveEqualRatios) {
    for (std::vector<double> c : {cascadeSplits(0.1, 100.0, 4, CASCADE_SPLIT_PRACTICAL, 1.0),
                                  cascadeSplits(0.1, 100.0, 4, CASCADE_SPLIT_LOG, 0.3)}) {
        ASSERT_EQ(c.size(), 4u);
        EXPECT_NEAR(c[0], 0.5623, 1e-3);
        EXPECT_NEAR(c[1], 3.1623, 1e-3);
        EXPECT_NEAR(c[2], 17.7828, 1e-3);
        EXPECT_NEAR(c[3], 100.0, 1e-3);
        // Each cascade is f/n^(1/4) = 5.6234 times as deep as the one before it.
        EXPECT_NEAR(c[1] / c[0], c[2] / c[1], 1e-9);
        EXPECT_NEAR(c[0] / 0.1, std::pow(1000.0, 0.25), 1e-9);
    }
}

TEST(CascadeSplits, TheUniformSchemeTakesEqualStepsWhateverLambdaSays) {
    std::vector<double> c = cascadeSplits(0.1, 100.0, 4, CASCADE_SPLIT_UNIFORM, 0.9);
    ASSERT_EQ(c.size(), 4u);
    EXPECT_NEAR(c[0], 25.075, 1e-9);
    EXPECT_NEAR(c[1], 50.05, 1e-9);
    EXPECT_NEAR(c[2], 75.025, 1e-9);
    EXPECT_EQ(c[3], 100.0);
    EXPECT_EQ(cascadeSplits(0.1, 100.0, 4, CASCADE_SPLIT_PRACTICAL, 0.0), c);
}

TEST(CascadeSplits, OneCascadeCoversItAllAndTheEndsAreNearAndFar) {
    EXPECT_EQ(cascadeSplits(0.5, 40.0, 1, CASCADE_SPLIT_LOG, 1.0), std::vector<double>{40.0});
    EXPECT_DOUBLE_EQ(cascadeSplitDistance(0.5, 40.0, 0, 3, 0.7), 0.5);
    EXPECT_DOUBLE_EQ(cascadeSplitDistance(0.5, 40.0, 3, 3, 0.7), 40.0);
    // Rising in i, and a larger lambda pulls every inner split toward the camera.
    std::vector<double> a = cascadeSplits(0.5, 40.0, 4, CASCADE_SPLIT_PRACTICAL, 0.2);
    std::vector<double> b = cascadeSplits(0.5, 40.0, 4, CASCADE_SPLIT_PRACTICAL, 0.8);
    for (size_t i = 0; i + 1 < a.size(); ++i) {
        EXPECT_LT(a[i], a[i + 1]);
        EXPECT_LT(b[i], a[i]) << i;
    }
}

TEST(CascadeSettings, NamesRoundTripAndUnknownOnesAreRefused) {
    for (int split : {CASCADE_SPLIT_UNIFORM, CASCADE_SPLIT_LOG, CASCADE_SPLIT_PRACTICAL}) {
        EXPECT_EQ(cascadeSplitFromName(cascadeSplitName(split)), split);
        EXPECT_NE(cascadeSplitNames().find(cascadeSplitName(split)), std::string::npos);
    }
    for (int fit : {CASCADE_FIT_BOX, CASCADE_FIT_SPHERE}) {
        EXPECT_EQ(cascadeFitFromName(cascadeFitName(fit)), fit);
    }
    EXPECT_FALSE(cascadeSplitFromName("pssm").has_value());
    EXPECT_FALSE(cascadeFitFromName("Sphere").has_value());
}

TEST(CascadeSettings, TheRowsHoldTheirRanges) {
    ShadowSettings s;
    EXPECT_EQ(s.cascades, 1);
    ASSERT_NE(findParam("cascades"), nullptr);
    EXPECT_FALSE(setParamFromText(s, *findParam("cascades"), "4").has_value());
    EXPECT_EQ(s.cascades, MAX_CASCADES);
    auto tooMany = setParamFromText(s, *findParam("cascades"), "5");
    ASSERT_TRUE(tooMany.has_value());
    EXPECT_EQ(tooMany->after, " must be 1..4, got 5");
    EXPECT_TRUE(setParamFromText(s, *findParam("cascades"), "0").has_value());
    EXPECT_TRUE(setParamFromText(s, *findParam("cascade_lambda"), "1.5").has_value());
    EXPECT_FALSE(setParamFromText(s, *findParam("cascade_lambda"), "0.25").has_value());
    EXPECT_EQ(s.cascadeLambda, 0.25f);
    EXPECT_TRUE(setParamFromText(s, *findParam("shadow_distance"), "-1").has_value());
    EXPECT_FALSE(setParamFromText(s, *findParam("cascade_split"), "log").has_value());
    EXPECT_EQ(s.cascadeSplit, CASCADE_SPLIT_LOG);
    EXPECT_TRUE(setParamFromText(s, *findParam("cascade_fit"), "circle").has_value());
    EXPECT_FALSE(setParamFromText(s, *findParam("cascade_snap"), "true").has_value());
    EXPECT_TRUE(s.cascadeSnap);
}

// --cascade-bounds is a row of the table: a named field, fixed by default.
TEST(CascadeSettings, TheBoundsRowNamesFixedAndDepth) {
    ShadowSettings s;
    EXPECT_EQ(s.cascadeBounds, CASCADE_BOUNDS_FIXED);
    ASSERT_NE(findParam("cascade_bounds"), nullptr);
    EXPECT_TRUE(isCascadeSetting("cascade_bounds"));
    EXPECT_FALSE(setParamFromText(s, *findParam("cascade_bounds"), "depth").has_value());
    EXPECT_EQ(s.cascadeBounds, CASCADE_BOUNDS_DEPTH);
    EXPECT_TRUE(setParamFromText(s, *findParam("cascade_bounds"), "sdsm").has_value());
    EXPECT_EQ(cascadeBoundsName(CASCADE_BOUNDS_FIXED), "fixed");
    EXPECT_EQ(cascadeBoundsFromName("depth"), CASCADE_BOUNDS_DEPTH);
}

// The reduction of a hand-made 4 x 3 frame of view depths: 0 where no receiver is drawn (and a
// negative value or a NaN, which no receiver writes, counts as none).
TEST(CascadeBounds, TheReductionFindsTheNearestAndFarthestReceiver) {
    const float nan = std::nanf("");
    std::vector<float> frame = {0.0f,  0.0f,  41.5f,   0.0f,   //
                                7.25f, 12.0f, 0.0f,    -3.0f,  //
                                nan,   9.0f,  63.125f, 0.0f};
    std::optional<glm::vec2> range = visibleDepthRange(frame.data(), frame.size());
    ASSERT_TRUE(range.has_value());
    EXPECT_EQ(range->x, 7.25f);
    EXPECT_EQ(range->y, 63.125f);
    // One receiver pixel: both ends are its depth.
    std::vector<float> one(12, 0.0f);
    one[5] = 2.5f;
    EXPECT_EQ(visibleDepthRange(one.data(), one.size()), glm::vec2(2.5f, 2.5f));
    // None: nothing to bound.
    std::vector<float> none(12, 0.0f);
    EXPECT_FALSE(visibleDepthRange(none.data(), none.size()).has_value());
}

// The span the splits share out: [n, f] tightened to the visible receivers, widened by the
// margin, never beyond [n, f], and [n, f] when no visible receiver lies in it.
TEST(CascadeBounds, TheSpanIsTheVisibleDepthsWidenedWithinNearAndFar) {
    EXPECT_EQ(cascadeSplitSpan(0.1, 400.0, std::nullopt), glm::dvec2(0.1, 400.0));
    glm::dvec2 tight = cascadeSplitSpan(0.1, 400.0, glm::vec2(4.0f, 100.0f));
    EXPECT_DOUBLE_EQ(tight.x, 4.0 * 0.999);
    EXPECT_DOUBLE_EQ(tight.y, 100.0 * 1.001);
    glm::dvec2 capped = cascadeSplitSpan(0.1, 60.0, glm::vec2(4.0f, 100.0f));
    EXPECT_DOUBLE_EQ(capped.x, 3.996);
    EXPECT_EQ(capped.y, 60.0);
    EXPECT_EQ(cascadeSplitSpan(0.1, 60.0, glm::vec2(0.05f, 50.0f)).x, 0.1);
    EXPECT_EQ(cascadeSplitSpan(0.1, 60.0, glm::vec2(70.0f, 90.0f)), glm::dvec2(0.1, 60.0));
}

}  // namespace
}  // namespace pcf
