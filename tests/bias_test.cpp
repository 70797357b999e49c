// Properties of the bias modes (src/kernel/bias.h, the per-tap part in
// shaders/shared/pcf_kernel.h), and the command line's answer to combinations that cannot exist.
#include "kernel/bias.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "json_lite.h"
#include "kernel/methods.h"
#include "kernel/trace.h"
#include "kernel/trace_json.h"
#include "random_map.h"
#include "run_command.h"

namespace pcf {
namespace {

std::vector<PcfParams> everyMethod() {
    std::vector<PcfParams> all;
    for (const MethodInfo& m : allMethods()) {
        if (m.id == PCF_TENT) {
            for (int n : {3, 5, 7}) all.push_back(makeParams(m.id, n));
        } else if (m.usesKernel) {
            for (int n : {1, 2, 3, 5}) all.push_back(makeParams(m.id, n));
        } else {
            all.push_back(makeParams(m.id, 3, 1.5f));
        }
    }
    return all;
}

TEST(Bias, NamesRoundTripAndUnknownNamesAreRefused) {
    for (int mode = 0; mode < PCF_BIAS_COUNT; ++mode) {
        EXPECT_EQ(biasFromName(biasName(mode)), mode);
    }
    EXPECT_EQ(biasFromName("receiver-plane"), PCF_BIAS_RECEIVER_PLANE);
    EXPECT_FALSE(biasFromName("Constant"));
    EXPECT_FALSE(biasFromName("receiver_plane"));
    EXPECT_EQ(biasNameList(), "none, constant, slope, normal, receiver-plane, soft, interpolated");
}

TEST(Bias, CombinationsThatCannotExistAreNamed) {
    for (const MethodInfo& m : allMethods()) {
        bool hardwareCompare = m.id == PCF_HW2X2 || m.id == PCF_HW || m.id == PCF_TENT;
        EXPECT_EQ(validateBias(PCF_BIAS_SOFT, m.id).has_value(), hardwareCompare) << m.name;
        EXPECT_EQ(validateBias(PCF_BIAS_INTERPOLATED, m.id).has_value(), m.id != PCF_NEAREST)
            << m.name;
        for (int mode : {PCF_BIAS_NONE, PCF_BIAS_CONSTANT, PCF_BIAS_SLOPE, PCF_BIAS_NORMAL,
                         PCF_BIAS_RECEIVER_PLANE}) {
            EXPECT_FALSE(validateBias(mode, m.id)) << biasName(mode) << " " << m.name;
        }
    }
}

// The modes whose per-tap part is nothing (and receiver-plane on a flat receiver) give exactly
// what the kernel gave before there were modes.
TEST(Bias, ConstantAndFlatReceiverPlaneLeaveEveryMethodUnchanged) {
    ShadowMap map = randomMap(19, 13, 3);
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(-0.05f, 1.05f);
    for (const PcfParams& prm : everyMethod()) {
        for (int k = 0; k < 300; ++k) {
            vec2 uv(u(rng), u(rng));
            float ref = u(rng);
            float plain = filterVisibility(map, uv, ref, prm);
            for (int mode : {PCF_BIAS_NONE, PCF_BIAS_CONSTANT, PCF_BIAS_SLOPE, PCF_BIAS_NORMAL,
                             PCF_BIAS_RECEIVER_PLANE}) {
                EXPECT_EQ(filterVisibility(map, uv, ref, prm, PcfBias(mode, vec2(0.0f), 7.0f)),
                          plain)
                    << biasName(mode) << " " << methodInfo(prm.method).name;
            }
        }
    }
}

// Receiver-plane bias: every texel a method compares in the shader gets ref + dot(dz/duv, its
// centre - uv); a gather's four texels share the plane's depth at the gather's centre, and a
// hardware tap's at the tap's uv.
TEST(Bias, ReceiverPlaneGivesEachTapTheRefOfThePlaneWhereItReads) {
    ShadowMap map = randomMap(16, 16, 5);
    const vec2 uv(0.431f, 0.577f);
    const float ref = 0.5f;
    const vec2 dzduv(0.8f, -1.3f);
    BiasParams b;
    b.mode = PCF_BIAS_RECEIVER_PLANE;
    b.dzduv = dzduv;
    int checked = 0;
    for (const PcfParams& prm : everyMethod()) {
        Trace tr = traceLookup(map, uv, ref + b.constant, ref, prm, b);
        ASSERT_FALSE(tr.taps.empty());
        for (const TapRecord& t : tr.taps) {
            vec2 at;
            int kind = tr.fetches[static_cast<size_t>(t.fetch)].kind;
            if (kind == PCF_FETCH_GATHER || kind == PCF_FETCH_HW) {
                at = tr.fetches[static_cast<size_t>(t.fetch)].uv;
            } else if (t.texel.x > 0 && t.texel.y > 0 && t.texel.x < 15 && t.texel.y < 15) {
                at = (vec2(t.texel) + 0.5f) / 16.0f;  // not clamped: the texel's own centre
            } else {
                continue;
            }
            float expected = ref + dot(dzduv, at - uv);
            EXPECT_NEAR(t.ref, expected, 1e-6f) << methodInfo(prm.method).name;
            EXPECT_EQ(t.lit, t.ref <= t.depth ? 1.0f : 0.0f);
            ++checked;
        }
        EXPECT_NEAR(weightedTapSum(tr), tr.visibility, 1e-5f) << methodInfo(prm.method).name;
    }
    EXPECT_GT(checked, 500);
}

// The acne the plane removes: a receiver lying exactly on a sloped surface, looked up 3x3. With
// one ref for every tap, the neighbours on the near side of the slope are "in front" of it and
// shadow it; each tap with its own ref on the plane sees the surface at its own depth.
TEST(Bias, ReceiverPlaneRemovesTheAcneOfOneRefForAllNeighbours) {
    const int size = 32;
    const float slopePerTexel = 0.01f;  // depth rises with i: a receiver tilted from the light
    ShadowMap map(size, size);
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) map.setDepth(i, j, 0.2f + slopePerTexel * i);
    }
    const vec2 dzduv(slopePerTexel * size, 0.0f);
    int acneConstant = 0;
    int acnePlane = 0;
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> u(0.25f, 0.75f);
    for (int k = 0; k < 200; ++k) {
        vec2 uv(u(rng), u(rng));
        float surface = 0.2f + slopePerTexel * (uv.x * size - 0.5f);
        float ref = surface - 0.001f;  // a constant bias far below one texel's depth step
        PcfParams prm = makeParams(PCF_GATHER, 3);
        acneConstant += filterVisibility(map, uv, ref, prm) < 0.99f ? 1 : 0;
        PcfBias plane(PCF_BIAS_RECEIVER_PLANE, dzduv, 0.0f);
        acnePlane += filterVisibility(map, uv, ref, makeParams(PCF_NAIVE, 3), plane) < 0.99f;
    }
    EXPECT_GT(acneConstant, 150);  // nearly every lookup darkened by its own surface
    EXPECT_EQ(acnePlane, 0);
}

// "PCF Shadow Acne 2"'s soft comparison at a scale beyond any depth step is the hard one (away from
// depth == ref, where the soft one says 0 and GL_LEQUAL says 1).
TEST(Bias, SoftComparisonAtHugeScaleEqualsTheHardOne) {
    ShadowMap map = randomMap(23, 17, 7);
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(-0.05f, 1.05f);
    PcfBias soft(PCF_BIAS_SOFT, vec2(0.0f), 1.0e9f);
    int checked = 0;
    for (const PcfParams& prm : everyMethod()) {
        if (validateBias(PCF_BIAS_SOFT, prm.method)) continue;
        for (int k = 0; k < 300; ++k) {
            vec2 uv(u(rng), u(rng));
            float ref = u(rng);
            EXPECT_FLOAT_EQ(filterVisibility(map, uv, ref, prm, soft),
                            filterVisibility(map, uv, ref, prm))
                << methodInfo(prm.method).name;
            ++checked;
        }
    }
    EXPECT_GT(checked, 1000);
    // And its ramp: a texel 1/scale beyond ref is fully lit, half that half lit, at ref dark.
    EXPECT_EQ(pcfCompareSoft(0.5f, 0.5f, 100.0f), 0.0f);
    EXPECT_NEAR(pcfCompareSoft(0.505f, 0.5f, 100.0f), 0.5f, 1e-4f);
    EXPECT_EQ(pcfCompareSoft(0.52f, 0.5f, 100.0f), 1.0f);
    EXPECT_EQ(pcfCompareSoft(0.4f, 0.5f, 100.0f), 0.0f);
}

TEST(Bias, SoftComparisonDarkensTexelsJustBeyondTheReceiver) {
    ShadowMap map(4, 4, 0.5f);
    vec2 uv(0.5f);
    PcfParams prm = makeParams(PCF_GATHER, 3);
    EXPECT_EQ(filterVisibility(map, uv, 0.499f, prm), 1.0f);
    float soft = filterVisibility(map, uv, 0.499f, prm, PcfBias(PCF_BIAS_SOFT, vec2(0.0f), 500.0f));
    EXPECT_NEAR(soft, 0.5f, 1e-4f);  // depth - ref = 0.001, times 500
}

// "PCF Shadow Acne", Solution 2: on a sloped surface the interpolated depth follows it, so a
// receiver on the surface is lit wherever it looks it up; the nearest texel alone shadows half of
// them.
TEST(Bias, InterpolatedDepthFollowsAPlanarSurfaceWhereNearestMakesAcne) {
    const int size = 32;
    ShadowMap map(size, size);
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) map.setDepth(i, j, 0.2f + 0.01f * i + 0.004f * j);
    }
    PcfBias interp(PCF_BIAS_INTERPOLATED, vec2(0.0f), 0.0f);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.1f, 0.9f);
    int acneNearest = 0;
    int acneInterp = 0;
    for (int k = 0; k < 400; ++k) {
        vec2 uv(u(rng), u(rng));
        vec2 p = uv * float(size) - 0.5f;
        float ref = 0.2f + 0.01f * p.x + 0.004f * p.y - 1e-5f;
        acneNearest += filterVisibility(map, uv, ref, makeParams(PCF_NEAREST)) < 1.0f;
        acneInterp += filterVisibility(map, uv, ref, makeParams(PCF_NEAREST), interp) < 1.0f;
    }
    EXPECT_GT(acneNearest, 100);
    EXPECT_EQ(acneInterp, 0);
}

TEST(Bias, SlopeBiasGrowsWithTheAngleUpToItsCap) {
    BiasParams b;
    b.mode = PCF_BIAS_SLOPE;
    b.constant = 0.001f;
    b.slope = 0.002f;
    b.slopeMax = 0.01f;
    EXPECT_FLOAT_EQ(b.lookupBias(1.0f), 0.001f);                       // facing the light
    EXPECT_NEAR(b.lookupBias(std::cos(0.785398163f)), 0.003f, 1e-6f);  // 45 degrees: tan 1
    EXPECT_FLOAT_EQ(b.lookupBias(0.0f), 0.01f);                        // edge-on: the cap
    float last = 0.0f;
    for (int deg = 0; deg <= 90; deg += 5) {
        float v = b.lookupBias(std::cos(deg * 0.0174532925f));
        EXPECT_GE(v, last) << deg;
        last = v;
    }
    BiasParams c = b;
    c.mode = PCF_BIAS_CONSTANT;
    EXPECT_FLOAT_EQ(c.lookupBias(0.1f), 0.001f);
    c.mode = PCF_BIAS_NONE;
    EXPECT_FLOAT_EQ(c.lookupBias(0.1f), 0.0f);
}

TEST(Bias, NormalOffsetMovesBySineTimesTexels) {
    EXPECT_FLOAT_EQ(pcfNormalOffsetDistance(1.0f, 2.0f, 0.1f), 0.0f);
    EXPECT_NEAR(pcfNormalOffsetDistance(0.0f, 2.0f, 0.1f), 0.2f, 1e-7f);
    EXPECT_NEAR(pcfNormalOffsetDistance(0.5f, 2.0f, 0.1f), 0.2f * std::sqrt(0.75f), 1e-6f);
}

// The Jacobian inverse recovers a plane's dz/duv from any two independent screen steps.
TEST(Bias, ReceiverPlaneSlopeFromScreenDerivatives) {
    const vec2 g(0.37f, -1.9f);  // the plane: dz = g.x du + g.y dv
    std::mt19937 rng(10);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int k = 0; k < 50; ++k) {
        vec2 ax(u(rng), u(rng));
        vec2 ay(u(rng), u(rng));
        if (std::fabs(ax.x * ay.y - ax.y * ay.x) < 0.05f) continue;
        vec3 dx(ax.x, ax.y, dot(g, ax));
        vec3 dy(ay.x, ay.y, dot(g, ay));
        vec2 got = pcfReceiverPlaneDzDuv(dx, dy);
        EXPECT_NEAR(got.x, g.x, 1e-4f);
        EXPECT_NEAR(got.y, g.y, 1e-4f);
    }
    EXPECT_EQ(pcfReceiverPlaneDzDuv(vec3(1, 2, 3), vec3(2, 4, 6)), vec2(0.0f));  // degenerate
}

TEST(Bias, TraceJsonCarriesTheModeItsParametersAndEachTapsShift) {
    ShadowMap map = randomMap(8, 8, 11);
    BiasParams b;
    b.mode = PCF_BIAS_RECEIVER_PLANE;
    b.dzduv = vec2(0.5f, 0.25f);
    Trace tr = traceLookup(map, vec2(0.5f), 0.5f, 0.498f, makeParams(PCF_BILINEAR2X2), b);
    std::string json = traceToJson(tr);
    EXPECT_NE(json.find("\"bias\":{\"mode\":\"receiver-plane\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"dzduv\":[0.5,0.25]"), std::string::npos) << json;
    EXPECT_NE(json.find("\"per_tap\":\"per texel, at its centre\""), std::string::npos);
    // Texel (3,3)'s centre is half a texel left and below uv 0.5: shift -(0.5 + 0.25) / 16.
    EXPECT_NE(json.find("\"ref_shift\":-0.046875"), std::string::npos) << json;
    bool perTapStep = false;
    for (const TraceStep& s : tr.steps)
        perTapStep = perTapStep || s.kind == TraceStepKind::PerTapRef;
    EXPECT_TRUE(perTapStep);
}

// ---- The command line ----

class BiasCli : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("bias"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    std::filesystem::path mDir;
};

TEST_F(BiasCli, CombinationsThatCannotExistExitTwoAndWriteNothing) {
    struct Case {
        std::string args;
        std::string expect;
    };
    std::string out = (mDir / "f.png").string();
    std::string raw = (mDir / "raw").string();
    std::vector<Case> cases = {
        {"render --scene grazing --method tent --kernel 5 --bias soft -o " + out + " --raw " + raw,
         "bias soft compares depths in the shader, but tent"},
        {"render --scene grazing --method hw2x2 --bias soft -o " + out, "hw2x2"},
        {"render --scene grazing --method pcf-gather --bias interpolated -o " + out,
         "bias interpolated"},
        {"render --scene grazing --bias fancy -o " + out, "unknown bias mode 'fancy'"},
        {"render --scene grazing --bias slope --slope-max 2 -o " + out,
         "--slope-max must be in [0, 1], got 2"},
        {"trace --example --method tent --bias soft", "tent gets its comparisons"},
        {"trace --example --method poisson --bias interpolated", "use --method nearest"},
        {"trace --example --bias 0.002", "unknown bias mode '0.002'"},
        {"trace --example --constant-bias 0.01", "--constant-bias needs --bias NAME"},
        {"trace --example --bias constant --dzduv 1,2", "--dzduv is for --bias receiver-plane"},
        {"trace --example --bias slope --angle 95", "--angle 95 is out of range"},
    };
    for (const Case& c : cases) {
        auto r = testutil::runPcfscope(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_TRUE(r.out.empty()) << c.args;
        EXPECT_TRUE(std::filesystem::is_empty(mDir)) << c.args;
    }
}

TEST_F(BiasCli, TraceTakesTheModeByNameAndItsParameters) {
    auto plane = testutil::runPcfscope(
        "trace --example --json --bias receiver-plane --constant-bias 0.001 --dzduv 0.4,-0.2");
    ASSERT_EQ(plane.exitCode, 0) << plane.err;
    EXPECT_NE(plane.out.find("\"mode\":\"receiver-plane\""), std::string::npos) << plane.out;
    EXPECT_NE(plane.out.find("\"ref\":0.499"), std::string::npos) << plane.out;
    auto slope = testutil::runPcfscope(
        "trace --example --bias slope --constant-bias 0.001 "
        "--slope-bias 0.002 --slope-max 0.1 --angle 45");
    ASSERT_EQ(slope.exitCode, 0) << slope.err;
    EXPECT_NE(slope.out.find("= 0.497 (z - 0.003)"), std::string::npos) << slope.out;
    // The built-in worked example keeps its number with no bias.
    auto none = testutil::runPcfscope("trace --example");
    EXPECT_NE(none.out.find("visibility = 0.8"), std::string::npos) << none.out;
}

TEST_F(BiasCli, RenderRawWritesTheReceiverPlaneTarget) {
    std::string raw = (mDir / "raw").string();
    auto r = testutil::runPcfscope(
        "render --scene grazing --size 64x36 --map-size 64 "
        "--bias receiver-plane --raw " +
        raw);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::is_regular_file(mDir / "raw" / "dzduv.exr"));
}

}  // namespace
}  // namespace pcf
