// kernel/cascades.h: where the cascades split the view depth (Zhang et al. 2006's practical
// scheme and its two ends), and the settings rows that choose it.
#include "kernel/cascades.h"

#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
}  // namespace pcf
