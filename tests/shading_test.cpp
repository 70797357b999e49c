// shaders/shared/pcf_shading.h: the camera pass's gamma encoding, the same source the fragment
// shader runs, bounded against the pow it stands for over the whole range scene.frag feeds it.
#include "kernel/shading.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// scene.frag's light factor: ambient 0.25 plus 0.75 of the sun, so x in [0.25, 1].
constexpr double LIGHT_MIN = 0.25;
constexpr int SAMPLES = 200000;

TEST(GammaEncode, StaysWithinItsStatedBoundOfPowOverTheLightRange) {
    double worst = 0.0;
    for (int i = 0; i <= SAMPLES; ++i) {
        float x = static_cast<float>(LIGHT_MIN + (1.0 - LIGHT_MIN) * i / SAMPLES);
        double exact = std::pow(static_cast<double>(x), 1.0 / 2.2);
        worst = std::max(worst, std::abs(pcf::pcfGammaEncode(x) - exact));
    }
    EXPECT_LT(worst, 6e-6);  // the bound pcf_shading.h states
}

TEST(GammaEncode, IsIncreasingSoBrighterLightNeverReadsDarker) {
    float previous = pcf::pcfGammaEncode(static_cast<float>(LIGHT_MIN));
    for (int i = 1; i <= SAMPLES; ++i) {
        float x = static_cast<float>(LIGHT_MIN + (1.0 - LIGHT_MIN) * i / SAMPLES);
        float g = pcf::pcfGammaEncode(x);
        ASSERT_GE(g, previous) << "at x = " << x;
        previous = g;
    }
}

TEST(GammaEncode, EndsOfTheRangeRoundToThePowsEightBitValues) {
    // Full sun is white and ambient alone is pow(0.25, 1/2.2) = 0.5325: in an 8-bit frame both
    // ends land on the same byte as the exact power.
    for (float x : {0.25f, 0.5f, 1.0f}) {
        long exact = std::lround(255.0 * std::pow(static_cast<double>(x), 1.0 / 2.2));
        EXPECT_EQ(std::lround(255.0 * pcf::pcfGammaEncode(x)), exact) << "x = " << x;
    }
}

}  // namespace
