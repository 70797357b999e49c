// The moment methods (issue 33): vsm, evsm2, evsm4, msm and msm-hausdorff, through
// `pcfscope trace --map` as a user runs them, and the kernel's moments pass and estimates.
#include "kernel/moments.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "json_lite.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "kernel/trace.h"
#include "render/image_io.h"
#include "run_command.h"

namespace pcf {
namespace {

using testutil::runPcfscope;

class MomentsTest : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("moments"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    // A 128 x 128 map: columns 0-63 at depth `left`, 64-127 at `right`, written as EXR.
    std::string twoColumnMap(float left, float right) {
        ShadowMap map(128, 128);
        for (int j = 0; j < 128; ++j) {
            for (int i = 0; i < 128; ++i) map.setDepth(i, j, i < 64 ? left : right);
        }
        std::string file = path("map.exr");
        writeDepthImage(file, map);
        return file;
    }
    // `trace --json` at uv (0.5, 0.5), receiver z 0.6, no bias, with `args`.
    jsonlite::Value trace(const std::string& file, const std::string& args) {
        auto r = runPcfscope("trace --map " + file + " --uv 0.5,0.5 --z 0.6 --json " + args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        mLastErr = r.err;
        return jsonlite::parse(r.out);
    }
    double visibility(const std::string& file, const std::string& args) {
        return trace(file, args)["visibility"].number;
    }
    std::filesystem::path mDir;
    std::string mLastErr;
};

// Issue 33's numbers. Two occluders at 0.2 and 0.5 under a receiver at 0.6: the footprint (a
// 3 x 3 box blur, then the bilinear read, half on each) has mean 0.35 and variance 0.0225, so
// Chebyshev's bound is 0.0225 / (0.0225 + 0.25^2) = 0.2647 although every depth is in front of
// the receiver: light bleeding. LBR 0.3 cuts it to 0; EVSM's warps and MSM see through it.
TEST_F(MomentsTest, TwoOccludersBleedThroughVsmAndNotThroughTheOthers) {
    std::string file = twoColumnMap(0.2f, 0.5f);
    EXPECT_NEAR(visibility(file, "--method vsm --lbr 0"), 0.2647, 2e-3);
    EXPECT_EQ(visibility(file, "--method vsm --lbr 0.3"), 0.0);
    EXPECT_LT(visibility(file, "--method evsm4 --evsm-exponents 40,5"), 1e-3);
    EXPECT_NEAR(visibility(file, "--method msm --moment-bias 3e-5"), 0.0016, 5e-4);
    // Box PCF of the same footprint says what is true: every depth occludes.
    EXPECT_EQ(visibility(file, "--method pcf-naive"), 0.0);
}

// One occluder at 0.3 beside a lit receiver at 0.6 (0.6 <= 0.6 is lit): the bound is exact,
// vsm gives box PCF's 0.5.
TEST_F(MomentsTest, OneOccluderVsmEqualsBoxPcf) {
    std::string file = twoColumnMap(0.3f, 0.6f);
    EXPECT_NEAR(visibility(file, "--method vsm"), 0.5, 2e-3);
    EXPECT_NEAR(visibility(file, "--method pcf-naive"), 0.5, 1e-6);
    jsonlite::Value j = trace(file, "--method vsm");
    EXPECT_NEAR(j["moments"]["mean"].number, 0.45, 1e-5);
    EXPECT_NEAR(j["moments"]["variance"].number, 0.0225, 1e-5);
    EXPECT_NEAR(j["moments"]["bound"].number, 0.5, 2e-3);
}

// --evsm-exponents beyond what the floats hold are used clamped, and the trace says so.
TEST_F(MomentsTest, ExponentsAreClampedToTheFormatAndTheTraceSaysSo) {
    std::string file = twoColumnMap(0.2f, 0.5f);
    jsonlite::Value j32 = trace(file, "--method evsm4 --evsm-exponents 50,50");
    EXPECT_FLOAT_EQ(static_cast<float>(j32["moments"]["exponents_used"][0].number), 42.0f);
    EXPECT_FLOAT_EQ(static_cast<float>(j32["moments"]["exponents_used"][1].number), 42.0f);
    EXPECT_NE(mLastErr.find("--evsm-exponents 50,50 used as 42,42"), std::string::npos) << mLastErr;
    jsonlite::Value j16 = trace(file, "--method evsm4 --evsm-exponents 50,50 --moment-format 16f");
    EXPECT_FLOAT_EQ(static_cast<float>(j16["moments"]["exponents_used"][0].number), 5.54f);
    EXPECT_FLOAT_EQ(static_cast<float>(j16["moments"]["exponents_used"][1].number), 5.54f);
    EXPECT_EQ(j16["map"]["texels"].string, "moments4-16f");
    EXPECT_NE(mLastErr.find("used as 5.54,5.54"), std::string::npos) << mLastErr;
    // Within the limit nothing is said.
    trace(file, "--method evsm4 --evsm-exponents 40,5");
    EXPECT_EQ(mLastErr, "");
}

TEST_F(MomentsTest, BadMomentOptionsExitTwoWithOneLine) {
    std::string file = twoColumnMap(0.2f, 0.5f);
    for (const char* args : {"--method evsm2 --evsm-exponents 40",
                             "--method evsm2 --evsm-exponents 0,5", "--method vsm --lbr 1.5",
                             "--method msm --moment-bias -1", "--method vsm --moment-format 8f",
                             "--method vsm --kernel 4", "--method vsm --bias receiver-plane"}) {
        auto r = runPcfscope("trace --map " + file + " --uv 0.5,0.5 --z 0.6 " + args);
        EXPECT_EQ(r.exitCode, 2) << args;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << args << ": " << r.err;
        EXPECT_EQ(r.out, "") << args;
    }
}

// Every depth in [0, 1], in 16F and 32F, exponents at the limits: no Inf or NaN in the moments
// map nor in any visibility, every visibility in [0, 1].
TEST(Moments, ADenseSweepOfDepthsGivesNoInfOrNan) {
    std::mt19937 rng(33);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    ShadowMap depth(16, 16);
    for (int j = 0; j < 16; ++j) {
        for (int i = 0; i < 16; ++i) depth.setDepth(i, j, (i + j) % 5 == 0 ? float(i % 2) : u(rng));
    }
    for (const MethodInfo& m : allMethods()) {
        if (!readsMoments(m.id)) continue;
        for (int bits : {16, 32}) {
            ShadowSettings s;
            s.method = m.id;
            s.momentBits = bits;
            s.evsmExponents = vec2(50.0f, 50.0f);
            PcfParams prm = s.pcfParams();
            ShadowMap moments = momentsMap(depth, prm, mapTexelKind(m.id, s.depthFormat, bits));
            for (float t : moments.depths()) ASSERT_TRUE(std::isfinite(t)) << m.name << bits;
            for (int k = 0; k <= 512; ++k) {
                float z = static_cast<float>(k) / 512.0f;
                vec2 uv(u(rng), u(rng));
                float v = filterVisibility(moments, uv, z, prm);
                ASSERT_TRUE(v >= 0.0f && v <= 1.0f)
                    << m.name << " " << bits << " z " << z << ": " << v;
            }
        }
    }
}

// MSM's reconstruction is a distribution with the (biased) moments read: its points and weights
// give back b1 .. b4 (Hamburger: three points; Hausdorff: four where three leave [0, 1]).
TEST(Moments, MsmPointsAndWeightsGiveBackTheMoments) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int hausdorffFour = 0;
    int fourthHeld = 0;
    for (int trial = 0; trial < 200; ++trial) {
        ShadowMap depth(8, 8);
        for (int j = 0; j < 8; ++j) {
            for (int i = 0; i < 8; ++i) depth.setDepth(i, j, u(rng));
        }
        for (int method : {PCF_MSM, PCF_MSM_HAUSDORFF}) {
            PcfParams prm = makeParams(method, 3);
            prm.momentBias = 3.0e-3f;
            ShadowMap moments = momentsMap(depth, prm, TexelKind::Moments4F32);
            vec2 uv(u(rng), u(rng));
            float z = u(rng);
            Trace tr = traceLookup(moments, uv, z, z, prm);
            const PcfMomentEstimate& e = tr.moments;
            vec4 b = mix(pcfMomentsRead(plainMap(moments, prm), uv), vec4(0.5f), prm.momentBias);
            int points = e.points.w == 1.0f ? 4 : 3;
            if (points == 4) ++hausdorffFour;
            EXPECT_TRUE(method == PCF_MSM_HAUSDORFF || points == 3);
            // A nearly two-point footprint puts a tiny weight on a far point (c2 of the
            // quadratic near 0): b4 = sum w z^4 is then beyond float's reach, so the fourth
            // moment is held only where every point lies within [-1, 2].
            bool near = true;
            for (int p = 0; p < points; ++p) near = near && std::abs(e.points[p] - 0.5f) <= 1.5f;
            for (int k = 0; k <= (near ? 4 : 3); ++k) {
                double sum = 0.0;
                for (int p = 0; p < points; ++p) sum += e.weights[p] * std::pow(e.points[p], k);
                double want = k == 0 ? 1.0 : b[k - 1];
                EXPECT_NEAR(sum, want, 2e-3) << "moment " << k << " trial " << trial;
            }
            fourthHeld += near ? 1 : 0;
            EXPECT_NEAR(tr.visibility, e.visibility, 0.0f);
        }
    }
    EXPECT_GT(hausdorffFour, 0);  // the four-point case was reached
    EXPECT_GT(fourthHeld, 300);   // and most lookups hold all four moments
}

}  // namespace
}  // namespace pcf
