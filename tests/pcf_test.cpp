// Properties of the shared PCF kernel (shaders/shared/pcf_kernel.h via src/kernel/pcf.h).
#include "kernel/pcf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "kernel/methods.h"
#include "kernel/moments.h"
#include "kernel/trace.h"
#include "random_map.h"

namespace pcf {
namespace {

std::vector<PcfParams> everyMethodAndKernel() {
    std::vector<PcfParams> all;
    for (const MethodInfo& m : allMethods()) {
        if (m.id == PCF_TENT) {
            for (int n : {3, 5, 7}) all.push_back(makeParams(m.id, n));
        } else if (m.usesKernel) {
            for (int n = MIN_KERNEL; n <= MAX_KERNEL; ++n) all.push_back(makeParams(m.id, n));
        } else if (m.id == PCF_POISSON) {
            all.push_back(makeParams(m.id, 3, 1.0f));
            all.push_back(makeParams(m.id, 3, 2.5f, PCF_ROTATIONS[3]));
        } else {
            all.push_back(makeParams(m.id));
        }
    }
    return all;
}

TEST(Pcf, Seed000WorkedExampleBitsOneAndZeroAtFractionPointTwoGivePointEight) {
    // Two columns: texel 0 lit (far depth), texel 1 shadowed (occluder). A lookup with
    // fx = 0.2 between their centres lerps 1 -> 0 by 0.2.
    ShadowMap map(2, 2, std::vector<float>{0.9f, 0.1f, 0.9f, 0.1f});
    float u = (0.2f + 0.5f) / 2.0f;  // p = uv * size - 0.5 = 0.2
    float v = 0.5f / 2.0f;           // fy = 0
    PcfParams prm = makeParams(PCF_BILINEAR2X2);
    EXPECT_NEAR(filterVisibility(map, vec2(u, v), 0.5f, prm), 0.8f, 1e-6f);
    // The hardware tap is modelled as the very same lerp.
    EXPECT_NEAR(filterVisibility(map, vec2(u, v), 0.5f, makeParams(PCF_HW2X2)), 0.8f, 1e-6f);
    // The built-in example reproduces it in 2D (both rows 1 | 0).
    Trace tr = traceLookup(exampleShadowMap(), vec2(0.4625f, 0.3875f), 0.5f, 0.5f, prm);
    EXPECT_NEAR(tr.pos.frac.x, 0.2f, 1e-5f);
    EXPECT_EQ(tr.pos.base, ivec2(3, 2));
    EXPECT_NEAR(tr.visibility, 0.8f, 1e-6f);
}

TEST(Pcf, ComparisonIsLessOrEqual) {
    ShadowMap map(1, 1, 0.5f);
    PcfParams prm = makeParams(PCF_NEAREST);
    EXPECT_EQ(filterVisibility(map, vec2(0.5f), 0.5f, prm), 1.0f);  // ref == depth: lit
    EXPECT_EQ(filterVisibility(map, vec2(0.5f), std::nextafter(0.5f, 1.0f), prm), 0.0f);
}

TEST(Pcf, NearestReadsTheTexelUnderTheLookup) {
    ShadowMap map(4, 4, 1.0f);
    map.setDepth(2, 1, 0.0f);
    PcfParams prm = makeParams(PCF_NEAREST);
    // Anywhere inside texel (2, 1), including its lower edge, is shadowed; just outside is lit.
    EXPECT_EQ(filterVisibility(map, vec2(2.0f / 4, 1.0f / 4), 0.5f, prm), 0.0f);
    EXPECT_EQ(filterVisibility(map, vec2(2.99f / 4, 1.99f / 4), 0.5f, prm), 0.0f);
    EXPECT_EQ(filterVisibility(map, vec2(3.01f / 4, 1.5f / 4), 0.5f, prm), 1.0f);
    EXPECT_EQ(filterVisibility(map, vec2(2.5f / 4, 0.99f / 4), 0.5f, prm), 1.0f);
}

TEST(Pcf, Box2x2HasOnlyFiveLevels) {
    ShadowMap map = randomMap(16, 16, 7);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    PcfParams prm = makeParams(PCF_BOX2X2);
    std::set<float> seen;
    for (int k = 0; k < 20000; ++k) {
        float v = filterVisibility(map, vec2(u(rng), u(rng)), u(rng), prm);
        EXPECT_TRUE(v == 0.0f || v == 0.25f || v == 0.5f || v == 0.75f || v == 1.0f) << v;
        seen.insert(v);
    }
    EXPECT_EQ(seen.size(), 5u);  // and all five occur
}

TEST(Pcf, NaiveEqualsGatherOverRandomLookups) {
    ShadowMap map = randomMap(37, 23, 3);  // odd, non-square: catches axis mix-ups
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-0.02f, 1.02f);  // a little outside: clamping
    std::uniform_real_distribution<float> z(0.0f, 1.0f);
    for (int n = MIN_KERNEL; n <= MAX_KERNEL; ++n) {
        PcfParams naive = makeParams(PCF_NAIVE, n);
        PcfParams gather = makeParams(PCF_GATHER, n);
        float worst = 0.0f;
        for (int k = 0; k < 100000; ++k) {
            vec2 uv(u(rng), u(rng));
            float ref = z(rng);
            float a = filterVisibility(map, uv, ref, naive);
            float b = filterVisibility(map, uv, ref, gather);
            worst = std::max(worst, std::fabs(a - b));
        }
        EXPECT_LE(worst, 1e-6f) << "N = " << n;
    }
}

// pcf-hw hands each tap to the texture unit as uv + offset / size, one rounding away from
// pcf-naive's texel-space steps: equal to a few float ulps of the texel position.
TEST(Pcf, PcfHwEqualsPcfNaiveOnTheCpu) {
    ShadowMap map = randomMap(19, 31, 9);
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int n = MIN_KERNEL; n <= MAX_KERNEL; ++n) {
        for (int k = 0; k < 5000; ++k) {
            vec2 uv(u(rng), u(rng));
            float ref = u(rng);
            EXPECT_NEAR(filterVisibility(map, uv, ref, makeParams(PCF_HW, n)),
                        filterVisibility(map, uv, ref, makeParams(PCF_NAIVE, n)), 1e-5f);
        }
    }
}

TEST(Pcf, MergedThreeByThreeWeightsAreTheSeed001TableOverNine) {
    ShadowMap map = randomMap(16, 16, 1);
    vec2 uv(0.4321f, 0.5678f);
    for (int method : {PCF_NAIVE, PCF_GATHER, PCF_HW}) {
        Trace tr = traceLookup(map, uv, 0.5f, 0.5f, makeParams(method, 3));
        float x = tr.pos.frac.x;
        float y = tr.pos.frac.y;
        // "PCF Shadow Acne 2"'s 4 x 4 table is the outer product of these per-axis weights: corners
        // (1-x)(1-y) .. xy, edges (1-x), x, (1-y), y, and 1 in the middle four.
        const float ax[4] = {1 - x, 1, 1, x};
        const float ay[4] = {1 - y, 1, 1, y};
        float table[4][4];
        for (int j = 0; j < 4; ++j) {
            for (int i = 0; i < 4; ++i) table[j][i] = ax[i] * ay[j];
        }
        ASSERT_EQ(tr.weights.size, ivec2(4, 4)) << methodInfo(method).name;
        EXPECT_EQ(tr.weights.origin, tr.pos.base - ivec2(1));
        for (int j = 0; j < 4; ++j) {
            for (int i = 0; i < 4; ++i) {
                EXPECT_NEAR(tr.weights.values[j * 4 + i], table[j][i] / 9.0f, 1e-6f)
                    << methodInfo(method).name << " texel " << i << "," << j;
            }
        }
    }
}

TEST(Pcf, FetchCountsMatchTheMethodTable) {
    ShadowMap map = randomMap(32, 32, 2);
    vec2 uv(0.37f, 0.61f);
    auto counts = [&](int method, int n) {
        return traceLookup(map, uv, 0.5f, 0.5f, makeParams(method, n)).counts;
    };
    EXPECT_EQ(counts(PCF_NAIVE, 3), (FetchCounts{36, 0, 0}));
    EXPECT_EQ(counts(PCF_GATHER, 3), (FetchCounts{16, 4, 0}));
    EXPECT_EQ(counts(PCF_TENT, 5).hwTaps, 9);
    EXPECT_EQ(counts(PCF_TENT, 3).hwTaps, 4);
    EXPECT_EQ(counts(PCF_TENT, 7).hwTaps, 16);
    EXPECT_EQ(counts(PCF_HW2X2, 1).hwTaps, 1);
    EXPECT_EQ(counts(PCF_NEAREST, 1).texels, 1);
    EXPECT_EQ(counts(PCF_POISSON, 1).texels, 16);
    for (const PcfParams& prm : everyMethodAndKernel()) {
        EXPECT_EQ(counts(prm.method, prm.kernel), fetchCounts(prm.method, prm.kernel))
            << methodInfo(prm.method).name << " N = " << prm.kernel;
    }
    // pcf-gather: ceil((N+1)/2)^2 gathers for every N.
    for (int n = MIN_KERNEL; n <= MAX_KERNEL; ++n) {
        int blocks = (n + 2) / 2;
        EXPECT_EQ(counts(PCF_GATHER, n).gathers, blocks * blocks);
        EXPECT_EQ(counts(PCF_NAIVE, n).texels, 4 * n * n);
    }
}

// Castano's tent: the hardware taps' weights, spread over the texels by each tap's lerp, must
// give these per-axis texel weights (derived by hand from the tap formulas; s = tent fraction).
std::vector<float> tentAxisWeights(int n, float s) {
    if (n == 3) return {(1 - s) / 4, (2 - s) / 4, (1 + s) / 4, s / 4};
    if (n == 5) {
        return {(1 - s) / 12, (3 - 2 * s) / 12, (4 - s) / 12,
                (3 + s) / 12, (1 + 2 * s) / 12, s / 12};
    }
    return {(1 - s) / 52,      (5 - 4 * s) / 52, (12 - 7 * s) / 52, (16 - 4 * s) / 52,
            (12 + 4 * s) / 52, (5 + 7 * s) / 52, (1 + 4 * s) / 52,  s / 52};
}

TEST(Pcf, TentTapsReproduceItsMergedTexelWeights) {
    ShadowMap map = randomMap(64, 64, 4);
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(0.2f, 0.8f);
    for (int n : {3, 5, 7}) {
        for (int k = 0; k < 200; ++k) {
            vec2 uv(u(rng), u(rng));
            Trace tr = traceLookup(map, uv, 0.5f, 0.5f, makeParams(PCF_TENT, n));
            PcfFootprint tb = pcfTentBase(uv, map.size());
            std::vector<float> wx = tentAxisWeights(n, tb.frac.x);
            std::vector<float> wy = tentAxisWeights(n, tb.frac.y);
            int half = static_cast<int>(wx.size()) / 2;  // texels b-half .. b+half-1
            for (int j = 0; j < static_cast<int>(wy.size()); ++j) {
                for (int i = 0; i < static_cast<int>(wx.size()); ++i) {
                    ivec2 texel = tb.origin + ivec2(i - half, j - half);
                    ASSERT_NEAR(tr.weights.at(texel), wx[i] * wy[j], 2e-6f)
                        << "N = " << n << " s = " << tb.frac.x << " t = " << tb.frac.y << " texel "
                        << i << "," << j;
                }
            }
            float total = 0.0f;
            for (float w : tr.weights.values) total += w;
            EXPECT_NEAR(total, 1.0f, 1e-5f);
        }
    }
}

TEST(Pcf, WeightsSumToOneAndVisibilityStaysInRangeEverywhere) {
    ShadowMap map = randomMap(8, 8, 12);
    std::vector<vec2> uvs = {
        vec2(0.0f),
        vec2(1.0f),
        vec2(0.0f, 1.0f),
        vec2(1.0f, 0.0f),          // corners: clamp to edge
        vec2(0.5f / 8, 0.5f / 8),  // a centre: frac exactly 0
        vec2(3.5f / 8, 6.5f / 8),  // frac exactly 0 inside
        vec2(std::nextafter(4.5f / 8, 0.0f), std::nextafter(2.5f / 8, 0.0f)),  // frac ~ 1
        vec2(std::nextafter(8.5f / 8, 0.0f), 0.03f),
        vec2(0.999f, 0.001f),
        vec2(0.5f, 0.5f),
    };
    for (const PcfParams& prm : everyMethodAndKernel()) {
        for (vec2 uv : uvs) {
            for (float ref : {0.0f, 0.3f, 0.5f, 0.77f, 1.0f}) {
                Trace tr = traceLookup(map, uv, ref, ref, prm);
                float total = 0.0f;
                for (const TapRecord& t : tr.taps) total += t.weight;
                std::string where = std::string(methodInfo(prm.method).name) +
                                    " N=" + std::to_string(prm.kernel) +
                                    " uv=" + std::to_string(uv.x) + "," + std::to_string(uv.y);
                EXPECT_NEAR(total, 1.0f, 1e-5f) << where;
                EXPECT_GE(tr.visibility, 0.0f) << where;
                EXPECT_LE(tr.visibility, 1.0f) << where;
                EXPECT_NEAR(weightedTapSum(tr), tr.visibility, 1e-5f) << where;
                EXPECT_EQ(filterVisibility(map, uv, ref, prm), tr.visibility) << where;
                for (const TapRecord& t : tr.taps) {
                    EXPECT_TRUE(t.texel.x >= 0 && t.texel.y >= 0 && t.texel.x < 8 && t.texel.y < 8)
                        << where;
                }
            }
        }
    }
}

TEST(Pcf, FractionExactlyZeroAndJustBelowOne) {
    ShadowMap map = randomMap(8, 8, 13);
    PcfTexelPos at0 = pcfTexelPos(vec2(3.5f / 8, 6.5f / 8), map.size());
    EXPECT_EQ(at0.frac, vec2(0.0f));
    EXPECT_EQ(at0.base, ivec2(3, 6));
    PcfTexelPos below1 = pcfTexelPos(
        vec2(std::nextafter(4.5f / 8, 0.0f), std::nextafter(2.5f / 8, 0.0f)), map.size());
    EXPECT_EQ(below1.base, ivec2(3, 1));
    EXPECT_GT(below1.frac.x, 0.9999f);
    EXPECT_LT(below1.frac.x, 1.0f);
    // At frac 0 the bilinear result is exactly the base texel's bit.
    float ref = 0.5f;
    float expected = map.depth(3, 6) >= ref ? 1.0f : 0.0f;
    EXPECT_EQ(filterVisibility(map, vec2(3.5f / 8, 6.5f / 8), ref, makeParams(PCF_BILINEAR2X2)),
              expected);
}

TEST(Pcf, OutOfRangeTexelsClampToTheEdge) {
    ShadowMap map(4, 4, 1.0f);
    map.setDepth(0, 0, 0.0f);  // only the corner texel is an occluder
    // At uv (0,0) the 2x2 is texels (-1,-1)..(0,0): all four clamp to (0,0).
    Trace tr = traceLookup(map, vec2(0.0f), 0.5f, 0.5f, makeParams(PCF_BOX2X2));
    for (const TapRecord& t : tr.taps) EXPECT_EQ(t.texel, ivec2(0, 0));
    EXPECT_EQ(tr.visibility, 0.0f);
    EXPECT_EQ(tr.weights.size, ivec2(1, 1));
    EXPECT_FLOAT_EQ(tr.weights.values[0], 1.0f);
}

TEST(Pcf, PoissonCountsLitPointsOnTheScaledDisk) {
    ShadowMap map(64, 64, 1.0f);
    PcfParams prm = makeParams(PCF_POISSON, 3, 1.0f);
    EXPECT_EQ(filterVisibility(map, vec2(0.5f), 0.5f, prm), 1.0f);
    // Occlude the half plane x < 32: a disk centred on the boundary is split.
    for (int j = 0; j < 64; ++j) {
        for (int i = 0; i < 32; ++i) map.setDepth(i, j, 0.1f);
    }
    for (float radius : {1.0f, 3.0f}) {
        prm.radius = radius;
        Trace tr = traceLookup(map, vec2(0.5f, 0.5f), 0.5f, 0.5f, prm);
        int lit = 0;
        for (int k = 0; k < 16; ++k) {
            vec2 p = vec2(32.0f) + PCF_POISSON_DISK[k] * radius;  // uv * size of the point
            int i = static_cast<int>(std::floor(p.x));
            EXPECT_EQ(tr.taps[k].texel.x, i);
            if (i >= 32) ++lit;
        }
        EXPECT_FLOAT_EQ(tr.visibility, lit / 16.0f);
    }
    // A half turn mirrors the disk: lit and shadowed points swap (no disk point has x = 0).
    prm.radius = 3.0f;
    float straight = filterVisibility(map, vec2(0.5f), 0.5f, prm);
    prm.rotation = PCF_ROTATIONS[8];
    EXPECT_FLOAT_EQ(filterVisibility(map, vec2(0.5f), 0.5f, prm), 1.0f - straight);
}

TEST(Pcf, PixelRotationComesFromTheTable) {
    std::set<int> used;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            vec2 r = pcfPixelRotation(ivec2(x, y));
            EXPECT_NEAR(glm::length(r), 1.0f, 1e-6f);
            for (int k = 0; k < 16; ++k) {
                if (r == PCF_ROTATIONS[k]) used.insert(k);
            }
        }
    }
    EXPECT_EQ(used.size(), 16u);  // the hash reaches every rotation
}

TEST(Pcf, ErrorFallsAsTheMapGrows) {
    // A straight shadow edge x = 0.3 + 0.1 y sampled by maps of growing size; the exact answer
    // at a receiver point is 1 when it is right of the edge. The mean error over a band of
    // lookups must fall for the filtered methods as texels shrink.
    auto meanError = [](int size, int method) {
        ShadowMap map(size, size);
        for (int j = 0; j < size; ++j) {
            for (int i = 0; i < size; ++i) {
                float u = (i + 0.5f) / size;
                float v = (j + 0.5f) / size;
                map.setDepth(i, j, u < 0.3f + 0.1f * v ? 0.2f : 0.9f);
            }
        }
        double err = 0.0;
        int count = 0;
        PcfParams prm = makeParams(method, 3);
        ShadowMap read = mapForMethod(map, prm);  // a moment method reads the map's moments
        for (int k = 0; k < 400; ++k) {
            for (int l = 0; l < 40; ++l) {
                vec2 uv(0.2f + 0.25f * k / 400.0f, 0.3f + 0.4f * l / 40.0f);
                float truth = uv.x < 0.3f + 0.1f * uv.y ? 0.0f : 1.0f;
                err += std::fabs(filterVisibility(read, uv, 0.5f, prm) - truth);
                ++count;
            }
        }
        return err / count;
    };
    for (const MethodInfo& m : allMethods()) {
        double e64 = meanError(64, m.id);
        double e256 = meanError(256, m.id);
        EXPECT_LT(e256, e64 * 0.6) << m.name;
    }
}

}  // namespace
}  // namespace pcf
