// The texture unit's own arithmetic in the shared kernel (issue 10): hw8's 256 steps, and the
// [0,1] clamp of D_ref on fixed-point maps in every method.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "kernel/methods.h"
#include "kernel/pcf.h"
#include "kernel/trace.h"
#include "kernel/trace_json.h"
#include "random_map.h"

namespace pcf {
namespace {

PcfParams withPrecision(PcfParams p, int precision) {
    p.precision = precision;
    return p;
}

TEST(TextureUnit, Hw8PositionsAreWholeStepsOf1Over256WithinHalfAStep) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(-3.0f, 2000.0f);
    for (int k = 0; k < 100000; ++k) {
        vec2 p(u(rng), u(rng));
        vec2 q = pcfQuantiseTexelPos(p);
        for (int c = 0; c < 2; ++c) {
            float steps = q[c] * 256.0f;
            EXPECT_EQ(steps, std::floor(steps)) << p[c];
            EXPECT_LE(std::fabs(q[c] - p[c]), 1.0f / 512.0f) << p[c];
        }
    }
    // Round to nearest, ties up: 1/512 past a step goes to the next one.
    EXPECT_EQ(pcfQuantiseTexelPos(vec2(1.0f / 512.0f, 3.0f / 512.0f - 1e-5f)),
              vec2(1.0f / 256.0f, 1.0f / 256.0f));
}

// A 2x2 edge (lit | shadowed): a hardware tap sweeping across one texel takes exactly 257
// values (0/256 .. 256/256) with hw8, each within 1/512 of the exact one; the texelFetch methods
// do not change at all.
TEST(TextureUnit, Hw8HardwareTapSweepsAnEdgeIn256Steps) {
    ShadowMap map(4, 4, 0.9f);
    for (int j = 0; j < 4; ++j) {
        for (int i = 2; i < 4; ++i) map.setDepth(i, j, 0.1f);
    }
    std::set<float> values;
    const int samples = 4096;
    for (int k = 0; k <= samples; ++k) {
        float px = 1.0f + static_cast<float>(k) / samples;  // texel position p.x from 1 to 2
        vec2 uv((px + 0.5f) / 4.0f, 0.5f);
        float exact = filterVisibility(map, uv, 0.5f, makeParams(PCF_HW2X2));
        float hw8 = filterVisibility(map, uv, 0.5f,
                                     withPrecision(makeParams(PCF_HW2X2), PCF_PRECISION_HW8));
        EXPECT_NEAR(hw8, exact, 1.0f / 512.0f + 1e-6f) << px;
        EXPECT_EQ(hw8 * 256.0f, std::round(hw8 * 256.0f)) << px;
        values.insert(hw8);
        EXPECT_EQ(filterVisibility(map, uv, 0.5f,
                                   withPrecision(makeParams(PCF_BILINEAR2X2), PCF_PRECISION_HW8)),
                  filterVisibility(map, uv, 0.5f, makeParams(PCF_BILINEAR2X2)));
    }
    EXPECT_EQ(values.size(), 257u);
}

// Every method stays within the bound a 1/512-texel position error allows: the weights of a
// lookup move by at most 2 * 1/512 (both axes), so each lookup by at most 1/256.
TEST(TextureUnit, Hw8MovesEveryMethodByLessThanOneStep) {
    ShadowMap map = randomMap(37, 23, 4);
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> u(-0.05f, 1.05f);
    for (const MethodInfo& m : allMethods()) {
        PcfParams prm = makeParams(m.id, m.id == PCF_TENT ? 5 : 3);
        float worst = 0.0f;
        for (int k = 0; k < 20000; ++k) {
            vec2 uv(u(rng), u(rng));
            float ref = u(rng);
            float a = filterVisibility(map, uv, ref, prm);
            float b = filterVisibility(map, uv, ref, withPrecision(prm, PCF_PRECISION_HW8));
            worst = std::max(worst, std::fabs(a - b));
        }
        EXPECT_LE(worst, 1.0f / 256.0f + 1e-6f) << m.name;
        bool unit = m.id == PCF_HW2X2 || m.id == PCF_HW || m.id == PCF_TENT;
        if (unit) {
            EXPECT_GT(worst, 1e-4f) << m.name << ": hw8 should show";
        }
        if (!unit) {
            EXPECT_EQ(worst, 0.0f) << m.name << ": no texture-unit arithmetic";
        }
    }
}

// The gathers of pcf-gather sit on texel corners (p = k + 0.5), which 8 bits hold exactly: the
// texture unit cannot pick another block, so hw8 changes nothing.
TEST(TextureUnit, CornerPlacedGathersAreImmuneToHw8) {
    ShadowMap map = randomMap(29, 31, 5);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int n = 1; n <= 8; ++n) {
        for (int k = 0; k < 3000; ++k) {
            vec2 uv(u(rng), u(rng));
            float ref = u(rng);
            EXPECT_EQ(
                filterVisibility(map, uv, ref, makeParams(PCF_GATHER, n)),
                filterVisibility(map, uv, ref,
                                 withPrecision(makeParams(PCF_GATHER, n), PCF_PRECISION_HW8)));
        }
    }
}

// GL 4.5 section 8.23.1: on a fixed-point map D_ref is clamped to [0,1]. A ref below 0 is lit
// everywhere, a ref above 1 is lit only on texels at 1, in every method; on 32F it is not.
TEST(TextureUnit, FixedPointMapsClampTheReferenceInEveryMethod) {
    ShadowMap map = randomMap(16, 16, 6);
    map.setDepth(5, 5, 1.0f);
    ShadowMap fixed = map;
    fixed.setTexelKind(TexelKind::D16);
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const MethodInfo& m : allMethods()) {
        // A moment method reads a float moments map, never a fixed-point one.
        if (readsMoments(m.id)) continue;
        PcfParams prm = makeParams(m.id, m.id == PCF_TENT ? 5 : 3);
        for (int k = 0; k < 500; ++k) {
            vec2 uv(u(rng), u(rng));
            EXPECT_NEAR(filterVisibility(fixed, uv, -0.5f, prm), 1.0f, 1e-6f) << m.name;
            EXPECT_EQ(filterVisibility(fixed, uv, 1.5f, prm),
                      filterVisibility(fixed, uv, 1.0f, prm))
                << m.name;
            EXPECT_EQ(filterVisibility(map, uv, 1.5f, prm), 0.0f) << m.name;
            EXPECT_NEAR(filterVisibility(map, uv, -0.5f, prm), 1.0f, 1e-6f) << m.name;
        }
    }
    // hw2x2 is bilinear2x2 again with clamped refs (issue 10's 31-pixel disagreement).
    for (int k = 0; k < 2000; ++k) {
        vec2 uv(u(rng), u(rng));
        float ref = 3.0f * u(rng) - 1.0f;
        EXPECT_EQ(filterVisibility(fixed, uv, ref, makeParams(PCF_HW2X2)),
                  filterVisibility(fixed, uv, ref, makeParams(PCF_BILINEAR2X2)));
    }
    // The trace shows the clamped ref on each tap.
    Trace tr = traceLookup(fixed, vec2(0.5f), 1.5f, 1.5f, makeParams(PCF_BILINEAR2X2));
    for (const TapRecord& t : tr.taps) EXPECT_EQ(t.ref, 1.0f);
    EXPECT_TRUE(tr.map.texel().fixedPoint);
}

TEST(TextureUnit, TraceShowsBothFractionsAndBothVisibilities) {
    ShadowMap map = exampleShadowMap();
    vec2 uv(0.4625f, 0.3875f);  // "What Is PCF"'s example: fx = 0.2, which 8 bits cannot hold
    PcfParams prm = withPrecision(makeParams(PCF_HW2X2), PCF_PRECISION_HW8);
    Trace tr = traceLookup(map, uv, 0.5f, 0.5f, prm);
    EXPECT_TRUE(tr.usesTextureUnit);
    EXPECT_EQ(tr.fracHw8 * 256.0f, glm::round(tr.fracHw8 * 256.0f));
    EXPECT_NEAR(tr.fracHw8.x, tr.pos.frac.x, 1.0f / 512.0f);
    EXPECT_EQ(tr.visibility, tr.visibilityHw8);
    EXPECT_EQ(tr.visibilityExact, filterVisibility(map, uv, 0.5f, makeParams(PCF_HW2X2)));
    EXPECT_NE(tr.visibilityExact, tr.visibilityHw8);
    std::string json = traceToJson(tr);
    EXPECT_NE(json.find("\"frac_hw8\":"), std::string::npos);
    EXPECT_NE(json.find("\"precision\":\"hw8\""), std::string::npos);
    EXPECT_NE(traceToText(tr).find("256 steps"), std::string::npos);
}

// Any finite uv: outside the map the taps clamp to the edge, and the trace says which did.
TEST(TextureUnit, TraceMarksTapsClampedToTheEdge) {
    ShadowMap map = randomMap(8, 8, 7);
    Trace inside = traceLookup(map, vec2(0.5f), 0.5f, 0.5f, makeParams(PCF_NAIVE, 3));
    for (const TapRecord& t : inside.taps) EXPECT_FALSE(t.clamped);
    Trace out = traceLookup(map, vec2(1.02f, 0.6f), 0.5f, 0.5f, makeParams(PCF_NAIVE, 3));
    int clamped = 0;
    for (const TapRecord& t : out.taps) {
        EXPECT_LT(t.texel.x, 8);
        if (t.clamped) {
            ++clamped;
            EXPECT_EQ(t.texel.x, 7);
        }
    }
    EXPECT_GT(clamped, 0);
    EXPECT_NE(traceToJson(out).find("\"clamped\":true"), std::string::npos);
    EXPECT_NE(traceToText(out).find("clamped to the edge"), std::string::npos);
    // Far outside, every tap is the edge: the same as just outside.
    EXPECT_EQ(filterVisibility(map, vec2(19.0f, 0.6f), 0.5f, makeParams(PCF_NAIVE, 3)),
              filterVisibility(map, vec2(1.5f, 0.6f), 0.5f, makeParams(PCF_NAIVE, 3)));
}

}  // namespace
}  // namespace pcf
