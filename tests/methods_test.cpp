#include "kernel/methods.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "kernel/settings.h"
#include "kernel/trace.h"

namespace pcf {
namespace {

TEST(Methods, TheTenIdsOfTheDesignInOrder) {
    const char* ids[] = {"nearest",    "box2x2", "bilinear2x2", "hw2x2",   "pcf-naive",
                         "pcf-gather", "pcf-hw", "tent",        "poisson", "pcss"};
    ASSERT_EQ(allMethods().size(), 10u);
    for (int k = 0; k < 10; ++k) {
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
        EXPECT_NE(filterVisibility(map, uv, 0.5f, box), filterVisibility(map, uv, 0.5f, binomial))
            << m.name;
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
