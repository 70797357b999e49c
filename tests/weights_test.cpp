// Weighted kernels for pcf-naive and pcf-gather ("PCF Shadow Acne": binomial or Gaussian
// instead of the box), issue 10.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "kernel/methods.h"
#include "kernel/pcf.h"
#include "kernel/trace.h"
#include "kernel/trace_json.h"

namespace pcf {
namespace {

PcfParams weighted(int method, int n, int weights, float sigma = 1.0f) {
    PcfParams p = makeParams(method, n);
    p.weights = weights;
    p.sigma = sigma;
    return p;
}

TEST(Weights, AxisWeightsSumToOneAndAreSymmetric) {
    for (int w : {PCF_WEIGHTS_BOX, PCF_WEIGHTS_BINOMIAL, PCF_WEIGHTS_GAUSSIAN}) {
        for (int n = 1; n <= 8; ++n) {
            for (float sigma : {0.3f, 1.0f, 2.5f}) {
                float sum = 0.0f;
                for (int k = 0; k < n; ++k) {
                    float a = pcfAxisWeight(k, n, w, sigma);
                    EXPECT_GT(a, 0.0f);
                    EXPECT_NEAR(a, pcfAxisWeight(n - 1 - k, n, w, sigma), 1e-7f);
                    sum += a;
                }
                EXPECT_NEAR(sum, 1.0f, 1e-6f) << w << " N=" << n;
            }
        }
    }
    // Pascal's row over 2^(N-1).
    EXPECT_FLOAT_EQ(pcfAxisWeight(0, 3, PCF_WEIGHTS_BINOMIAL, 1.0f), 0.25f);
    EXPECT_FLOAT_EQ(pcfAxisWeight(1, 3, PCF_WEIGHTS_BINOMIAL, 1.0f), 0.5f);
    EXPECT_FLOAT_EQ(pcfAxisWeight(2, 5, PCF_WEIGHTS_BINOMIAL, 1.0f), 6.0f / 16.0f);
    // A Gaussian peaks in the middle and widens with sigma.
    EXPECT_GT(pcfAxisWeight(2, 5, PCF_WEIGHTS_GAUSSIAN, 1.0f),
              pcfAxisWeight(2, 5, PCF_WEIGHTS_GAUSSIAN, 3.0f));
}

// The heart of it: the gather reads each distinct texel once, with the footprint weights
// generalised to any separable weights, and gives pcf-naive's result.
TEST(Weights, PcfNaiveEqualsPcfGatherForEveryWeighting) {
    ShadowMap map(37, 23);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int j = 0; j < 23; ++j) {
        for (int i = 0; i < 37; ++i) map.setDepth(i, j, u(rng));
    }
    std::uniform_real_distribution<float> around(-0.02f, 1.02f);
    for (int w : {PCF_WEIGHTS_BOX, PCF_WEIGHTS_BINOMIAL, PCF_WEIGHTS_GAUSSIAN}) {
        for (int n = 1; n <= 8; ++n) {
            float worst = 0.0f;
            for (int k = 0; k < 5000; ++k) {
                vec2 uv(around(rng), around(rng));
                float ref = u(rng);
                float a = filterVisibility(map, uv, ref, weighted(PCF_NAIVE, n, w, 1.3f));
                float b = filterVisibility(map, uv, ref, weighted(PCF_GATHER, n, w, 1.3f));
                worst = std::max(worst, std::fabs(a - b));
            }
            EXPECT_LE(worst, 1e-6f) << weightsName(w) << " N=" << n;
        }
    }
}

TEST(Weights, SameFetchesAndWeightsThatSumToOne) {
    ShadowMap map(16, 16, 0.7f);
    for (int w : {PCF_WEIGHTS_BINOMIAL, PCF_WEIGHTS_GAUSSIAN}) {
        for (int method : {PCF_NAIVE, PCF_GATHER}) {
            Trace box = traceLookup(map, vec2(0.41f, 0.53f), 0.5f, 0.5f, makeParams(method, 4));
            Trace t = traceLookup(map, vec2(0.41f, 0.53f), 0.5f, 0.5f, weighted(method, 4, w));
            EXPECT_EQ(t.counts, box.counts);
            float sum = 0.0f;
            for (float v : t.weights.values) sum += v;
            EXPECT_NEAR(sum, 1.0f, 1e-6f);
            EXPECT_NEAR(t.visibility, weightedTapSum(t), 1e-6f);
            // Centre texels weigh more than the box gives them.
            EXPECT_GT(*std::max_element(t.weights.values.begin(), t.weights.values.end()),
                      *std::max_element(box.weights.values.begin(), box.weights.values.end()));
            EXPECT_NE(traceToText(t).find(std::string(weightsName(w))), std::string::npos);
        }
    }
}

TEST(Weights, ValidationNamesTheOption) {
    EXPECT_FALSE(validateParams(weighted(PCF_GATHER, 3, PCF_WEIGHTS_BINOMIAL)).has_value());
    EXPECT_EQ(
        validateParams(weighted(PCF_TENT, 3, PCF_WEIGHTS_BINOMIAL)).value(),
        "weights binomial applies to pcf-naive, pcf-gather, vsm, evsm2, evsm4, msm, msm-hausdorff, "
        "not tent");
    EXPECT_EQ(validateParams(weighted(PCF_NAIVE, 3, PCF_WEIGHTS_GAUSSIAN, 0.0f)).value(),
              "sigma 0 is out of range [0.05, 16] texels");
    EXPECT_EQ(weightsFromName("gaussian"), PCF_WEIGHTS_GAUSSIAN);
    EXPECT_FALSE(weightsFromName("tent").has_value());
}

}  // namespace
}  // namespace pcf
