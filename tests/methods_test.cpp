#include "kernel/methods.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "kernel/moments.h"
#include "kernel/settings.h"
#include "kernel/trace.h"

namespace pcf {
namespace {

TEST(Methods, TheFifteenIdsOfTheDesignInOrder) {
    const char* ids[] = {"nearest",    "box2x2", "bilinear2x2", "hw2x2",   "pcf-naive",
                         "pcf-gather", "pcf-hw", "tent",        "poisson", "pcss",
                         "vsm",        "evsm2",  "evsm4",       "msm",     "msm-hausdorff"};
    ASSERT_EQ(allMethods().size(), 15u);
    for (int k = 0; k < 15; ++k) {
        EXPECT_EQ(allMethods()[k].name, ids[k]);
        EXPECT_EQ(allMethods()[k].id, k);
        EXPECT_EQ(methodFromName(ids[k]), k);
    }
    EXPECT_FALSE(methodFromName("pcf").has_value());
    EXPECT_FALSE(methodFromName("").has_value());
}

TEST(Methods, EachEntryIsItsTypedIdWithItsOwnLabelAndColour) {
    std::set<std::string_view> labels;
    std::set<std::tuple<float, float, float>> colours;
    for (const MethodInfo& m : allMethods()) {
        EXPECT_EQ(static_cast<int>(methodOf(m.id)), m.id) << m.name;
        EXPECT_EQ(&methodInfo(m.id), &m) << m.name;
        EXPECT_TRUE(labels.insert(m.shortName).second) << m.shortName;
        EXPECT_TRUE(colours.insert({m.chartColour.r, m.chartColour.g, m.chartColour.b}).second)
            << m.name;
        EXPECT_EQ(m.usesKernel || m.kernelSizes.empty(), true) << m.name;
    }
    // No method stands in for an unknown one.
    EXPECT_THROW(methodInfo(PCF_METHOD_COUNT), std::out_of_range);
    EXPECT_THROW(fetchCounts(-1, 3), std::out_of_range);
}

// The table's `reads` is what the kernel issues: gathers, hardware taps or plain texel reads.
TEST(Methods, ReadsAreTheFetchesTheKernelIssues) {
    ShadowMap map(16, 16, 0.5f);
    for (const MethodInfo& m : allMethods()) {
        int n = fitKernel(m.id, 3);
        Trace tr = traceLookup(map, vec2(0.43f, 0.57f), 0.5f, 0.5f, makeParams(m.id, n));
        std::set<int> kinds;
        for (const FetchRecord& f : tr.fetches) kinds.insert(f.kind);
        MethodReads reads = kinds.count(PCF_FETCH_GATHER) ? MethodReads::Gathers
                            : kinds.count(PCF_FETCH_HW)   ? MethodReads::HwTaps
                                                          : MethodReads::Texels;
        EXPECT_EQ(m.reads, reads) << m.name;
        EXPECT_EQ(tr.usesTextureUnit, m.reads != MethodReads::Texels) << m.name;
    }
}

// takesWeights: binomial weights change what the method returns, and only those methods
// accept them.
TEST(Methods, WeightsChangeTheResultOfTheMethodsThatTakeThem) {
    ShadowMap map(16, 16, 0.5f);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x)
            map.setDepth(x, y, static_cast<float>((x * 7 + y * 3) % 5) * 0.25f);
    }
    for (const MethodInfo& m : allMethods()) {
        PcfParams box = makeParams(m.id, fitKernel(m.id, 3));
        PcfParams binomial = box;
        binomial.weights = PCF_WEIGHTS_BINOMIAL;
        EXPECT_EQ(checkParams(binomial).has_value(), !m.takesWeights) << m.name;
        if (!m.takesWeights) continue;
        vec2 uv(0.43f, 0.57f);
        // A moment method reads the moments its weights blurred (kernel/moments.h).
        auto read = [&](const PcfParams& p) {
            if (!readsMoments(m.id)) return map;
            return momentsMap(map, p, mapTexelKind(m.id, TexelKind::D32F));
        };
        // At some receiver depth behind part of the footprint (a moment method is 1 wherever
        // the receiver is before the mean; evsm2's warp exp(40 (2z - 1)) puts the mean of a
        // footprint holding a depth of 1 beyond every receiver but one at 1).
        bool differs = false;
        for (float ref : {0.5f, 0.7f, 0.9f, 1.0f}) {
            differs = differs || filterVisibility(read(box), uv, ref, box) !=
                                     filterVisibility(read(binomial), uv, ref, binomial);
        }
        EXPECT_TRUE(differs) << m.name;
    }
}

// A map with depths spread over [0, 1] (a fixed pattern): some taps lit, some not, anywhere.
ShadowMap patternMap(int n) {
    ShadowMap map(n, n);
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i)
            map.setDepth(i, j, static_cast<float>((i * 7 + j * 13) % 11) / 10.0f);
    }
    return map;
}

// Lookups spread over the map's middle (away from its edges), at irregular fractions.
std::vector<vec2> spreadLookups(int count) {
    std::vector<vec2> out;
    for (int k = 0; k < count; ++k) {
        out.push_back(vec2(0.3f + 0.4f * std::fmod(0.618034f * k, 1.0f),
                           0.3f + 0.4f * std::fmod(0.754878f * k + 0.1f, 1.0f)));
    }
    return out;
}

// The kernel's dispatch (pcf_filter.h pcfFilterRef) has a branch for every method of the table:
// none returns PCF_UNDISPATCHED, what an id without a branch gets (instead of another method's
// answer). tests/gpu_parity_test.cpp holds the GLSL to the same.
TEST(Methods, TheKernelsDispatchHasABranchForEveryMethod) {
    ShadowMap map = patternMap(32);
    for (const MethodInfo& m : allMethods()) {
        for (int weights : {PCF_WEIGHTS_BOX, PCF_WEIGHTS_BINOMIAL, PCF_WEIGHTS_GAUSSIAN}) {
            if (weights != PCF_WEIGHTS_BOX && !m.takesWeights) continue;
            PcfParams prm = makeParams(m.id, fitKernel(m.id, 3));
            prm.weights = weights;
            for (vec2 uv : spreadLookups(32)) {
                float v = filterVisibility(map, uv, 0.45f, prm);
                EXPECT_GE(v, 0.0f) << m.name;
                EXPECT_LE(v, 1.0f) << m.name;
            }
        }
    }
    PcfParams unknown = makeParams(PCF_METHOD_COUNT, 3);
    EXPECT_EQ(filterVisibility(map, vec2(0.5f), 0.45f, unknown), PCF_UNDISPATCHED);
}

// `hard`: one texel, one comparison, so only 0 or 1; every other method gives a value between
// on some lookup of a map whose depths vary texel by texel.
TEST(Methods, HardMethodsGiveOnlyZeroOrOne) {
    ShadowMap map = patternMap(32);
    for (const MethodInfo& m : allMethods()) {
        PcfParams prm = makeParams(m.id, fitKernel(m.id, 3), 2.0f);
        prm.penumbraScale = 8.0f;
        ShadowMap read = mapForMethod(map, prm);  // a moment method reads the map's moments
        bool between = false;
        for (vec2 uv : spreadLookups(64)) {
            // 1: evsm2's warped mean lies beyond every other receiver
            // (WeightsChangeTheResultOfTheMethodsThatTakeThem).
            for (float ref : {0.45f, 0.75f, 1.0f}) {
                float v = filterVisibility(read, uv, ref, prm);
                between = between || (v > 0.0f && v < 1.0f);
            }
        }
        EXPECT_EQ(!between, m.hard) << m.name;
    }
}

// `nearestTexels`: each texel read is the one its fetch's point falls in, floor(uv * size);
// the others read the 2x2 blocks around their points (box2x2, lookups, gathers, hardware taps).
TEST(Methods, NearestTexelMethodsReadTheTexelEachPointFallsIn) {
    ShadowMap map = patternMap(32);
    for (const MethodInfo& m : allMethods()) {
        PcfParams prm = makeParams(m.id, fitKernel(m.id, 3), 2.0f);
        prm.penumbraScale = 8.0f;
        Trace tr = traceLookup(map, vec2(0.43f, 0.57f), 0.45f, 0.45f, prm);
        bool underPoints = std::all_of(tr.taps.begin(), tr.taps.end(), [&](const TapRecord& t) {
            vec2 p = tr.fetches[static_cast<size_t>(t.fetch)].uv * 32.0f;
            return t.texel == pcfClampTexel(ivec2(glm::floor(p)), ivec2(32));
        });
        EXPECT_EQ(underPoints, m.nearestTexels) << m.name;
    }
}

// `hasDisk`: its first 16 reads sit at the Poisson set's points around the lookup, scaled (by
// the radius R; pcss's search by its search radius); no other method reads there.
TEST(Methods, DiskMethodsReadThePoissonPoints) {
    ShadowMap map = patternMap(64);
    vec2 uv(0.5f, 0.5f);
    for (const MethodInfo& m : allMethods()) {
        PcfParams prm = makeParams(m.id, fitKernel(m.id, 3), 2.0f);
        prm.penumbraScale = 8.0f;
        Trace tr = traceLookup(map, uv, 0.45f, 0.45f, prm);
        float scale = m.searchesBlockers ? tr.pcss.searchRadius : prm.radius;
        bool onDisk = tr.fetches.size() >= 16 && scale > 0.0f;
        for (size_t k = 0; onDisk && k < 16; ++k) {
            vec2 offset = (tr.fetches[k].uv - uv) * 64.0f / scale;
            onDisk = glm::length(offset - PCF_POISSON_DISK[k]) < 1e-4f;
        }
        EXPECT_EQ(onDisk, m.hasDisk) << m.name;
    }
}

// `searchesBlockers`: over an occluder the method finds blockers (the trace's pcss estimate,
// which the trace fills per method); no other method has a search.
TEST(Methods, BlockerSearchersFindTheBlocker) {
    ShadowMap map(32, 32, 0.9f);
    for (int j = 0; j < 32; ++j) {
        for (int i = 0; i < 16; ++i) map.setDepth(i, j, 0.2f);
    }
    for (const MethodInfo& m : allMethods()) {
        PcfParams prm = makeParams(m.id, fitKernel(m.id, 3));
        prm.penumbraScale = 8.0f;
        Trace tr = traceLookup(map, vec2(0.5f, 0.5f), 0.6f, 0.6f, prm);
        EXPECT_EQ(tr.pcss.blockers > 0, m.searchesBlockers) << m.name;
    }
}

// `overlappingLookups`: some texel is read by more than one of its lookups; a method with
// neither that nor a disk reads each texel once.
TEST(Methods, OverlappingLookupsReadATexelTwice) {
    ShadowMap map = patternMap(32);
    for (const MethodInfo& m : allMethods()) {
        if (m.hasDisk) continue;  // a disk's points may share a texel, by chance of the radius
        Trace tr = traceLookup(map, vec2(0.43f, 0.57f), 0.45f, 0.45f,
                               makeParams(m.id, fitKernel(m.id, 3)));
        std::set<std::pair<int, int>> texels;
        for (const TapRecord& t : tr.taps) texels.insert({t.texel.x, t.texel.y});
        EXPECT_EQ(texels.size() < tr.taps.size(), m.overlappingLookups) << m.name;
    }
}

// reachTexels is half the width of the block of texels a method reads (a disk: its radius
// plus half a texel, the stability sweeps' margin). At N = 3, 5 and 7 away from the edges.
TEST(Methods, ReachIsHalfTheFootprintsWidth) {
    ShadowMap map = patternMap(64);
    for (const MethodInfo& m : allMethods()) {
        if (m.hasDisk) {
            EXPECT_EQ(reachTexels(m.id, 3, 2.0f),
                      m.searchesBlockers ? PCF_PCSS_MAX_RADIUS + 0.5f : 2.5f)
                << m.name;
            continue;
        }
        // A moment method's taps are the moments map's 2x2 read; the depths behind them reach
        // (N + 1) / 2 texels through the moments pass's N x N blur, as pcf-naive's do.
        if (readsMoments(m.id)) {
            EXPECT_EQ(reachTexels(m.id, 3, 1.0f), reachTexels(PCF_NAIVE, 3, 1.0f)) << m.name;
            continue;
        }
        for (int n : {3, 5, 7}) {
            Trace tr = traceLookup(map, vec2(0.4321f, 0.5678f), 0.45f, 0.45f,
                                   makeParams(m.id, fitKernel(m.id, n)));
            int lo = 1 << 20, hi = -(1 << 20);
            for (const TapRecord& t : tr.taps) {
                lo = std::min(lo, t.texel.x);
                hi = std::max(hi, t.texel.x);
            }
            EXPECT_EQ(static_cast<float>(hi - lo + 1),
                      2.0f * reachTexels(m.id, fitKernel(m.id, n), 1.0f))
                << m.name << " N=" << n;
        }
    }
}

// The map a method reads comes from its map pass: the depth pass's map in the depth format
// asked for, or the moments pass's in the moment format (2 or 4 channels, whatever the depths).
TEST(Methods, EveryMethodReadsTheDepthMapInTheFormatAsked) {
    for (const MethodInfo& m : allMethods()) {
        for (TexelKind f : {TexelKind::D16, TexelKind::D24, TexelKind::D32F}) {
            if (m.mapPass == MapPass::Depth) {
                EXPECT_EQ(mapTexelKind(m.id, f), f) << m.name;
                continue;
            }
            int channels = m.mapPass == MapPass::Moments2 ? 2 : 4;
            EXPECT_EQ(texelKindInfo(mapTexelKind(m.id, f, 16)).channels, channels) << m.name;
            EXPECT_EQ(texelKindInfo(mapTexelKind(m.id, f, 16)).bits, 16) << m.name;
            EXPECT_EQ(texelKindInfo(mapTexelKind(m.id, f, 32)).bits, 32) << m.name;
        }
    }
}

TEST(Methods, FetchCountsOfTheDesignTable) {
    EXPECT_EQ(fetchCounts(PCF_NEAREST, 3), (FetchCounts{1, 0, 0}));
    EXPECT_EQ(fetchCounts(PCF_HW2X2, 3), (FetchCounts{4, 0, 1}));
    EXPECT_EQ(fetchCounts(PCF_NAIVE, 3), (FetchCounts{36, 0, 0}));
    EXPECT_EQ(fetchCounts(PCF_GATHER, 3), (FetchCounts{16, 4, 0}));
    EXPECT_EQ(fetchCounts(PCF_GATHER, 4), (FetchCounts{36, 9, 0}));  // ceil(5/2)^2 = 9
    EXPECT_EQ(fetchCounts(PCF_HW, 3), (FetchCounts{36, 0, 9}));
    EXPECT_EQ(fetchCounts(PCF_TENT, 5), (FetchCounts{36, 0, 9}));
    EXPECT_EQ(fetchCounts(PCF_TENT, 7), (FetchCounts{64, 0, 16}));
    EXPECT_EQ(fetchCounts(PCF_POISSON, 3), (FetchCounts{16, 0, 0}));
}

TEST(Methods, ValidationNamesTheProblem) {
    EXPECT_FALSE(validateParams(makeParams(PCF_NAIVE, 8)).has_value());
    EXPECT_EQ(validateParams(makeParams(PCF_NAIVE, 9)).value(), "kernel 9 is out of range (1..8)");
    EXPECT_EQ(validateParams(makeParams(PCF_GATHER, 0)).value(), "kernel 0 is out of range (1..8)");
    EXPECT_EQ(validateParams(makeParams(PCF_TENT, 4)).value(),
              "tent takes kernel 3, 5 or 7, not 4");
    // The setting is named once, so each caller can name it its own way.
    ParamProblem p = checkParams(makeParams(PCF_TENT, 4)).value();
    EXPECT_EQ(p.setting, "kernel");
    EXPECT_EQ(p.say("--kernel"), "tent takes --kernel 3, 5 or 7, not 4");
    EXPECT_FALSE(validateParams(makeParams(PCF_TENT, 7)).has_value());
    EXPECT_TRUE(validateParams(makeParams(PCF_POISSON, 3, 0.0f)).has_value());
    EXPECT_TRUE(validateParams(makeParams(PCF_POISSON, 3, NAN)).has_value());
    // Methods without a kernel ignore it.
    EXPECT_FALSE(validateParams(makeParams(PCF_NEAREST, 99)).has_value());
}

}  // namespace
}  // namespace pcf
