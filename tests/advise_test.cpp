// The advise search (measure/advise.h) over synthetic measurements with known numbers: the
// choice against every setting of the full grid (no setting whose whole cost spread is below the
// choice's meets the budget), the share of the grid measured, the timing tie rule, the binding
// sentence and the refusals. The search on a real scene: advise_gl_test.cpp.
#include "measure/advise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "kernel/settings.h"

namespace pcf {
namespace {

// A space of 9 filters, 4 map sizes and 4 biases.
AdviseSpace syntheticSpace() {
    AdviseSpace s;
    s.filters = {{PCF_NEAREST, 0}, {PCF_HW2X2, 0},  {PCF_GATHER, 3},
                 {PCF_GATHER, 5},  {PCF_GATHER, 7}, {PCF_TENT, 3},
                 {PCF_TENT, 5},    {PCF_TENT, 7},   {PCF_GATHER, 3, PCF_WEIGHTS_BINOMIAL}};
    s.mapSizes = {256, 512, 1024, 2048};
    s.biases = {{BiasMode::None, 0.0f},
                {BiasMode::Constant, 0.001f},
                {BiasMode::Constant, 0.004f},
                {BiasMode::Normal, 1.5f}};
    return s;
}

// Measures shaped like the real ones: the edge error halves with each map doubling and grows
// with the footprint, hard filters shimmer by a whole step at every size, the acne falls with
// the bias and the map size, the leak grows with the bias and the footprint, and the cost grows
// with the texel reads and a little with the map.
AdviseMetrics syntheticMetrics(const AdviseSetting& s) {
    AdviseMetrics m;
    int reads = adviseTexelReads(s.filter);
    double reach = s.filter.kernel > 0 ? s.filter.kernel : 1.0;
    double sizeFactor = 256.0 / s.mapSize;
    m.edgeRmse = 0.2 * sizeFactor * (0.6 + 0.1 * reach);
    m.shimmerP99 = methodInfo(s.filter.method).hard ? 1.0 : 0.6 / reach;
    double bias = s.bias.mode == BiasMode::None     ? 0.0
                  : s.bias.mode == BiasMode::Normal ? 0.003
                                                    : s.bias.amount;
    m.acneShare = std::max(0.0, 0.05 * sizeFactor - 20.0 * bias);
    m.leakTexels = 0.5 * reach + 100.0 * bias * (s.mapSize / 256.0);
    m.costMs = 0.5 + 0.1 * reads + 0.0001 * s.mapSize;
    m.costIqr = 0.02 * m.costMs;
    return m;
}

AdviseBudget syntheticBudget() {
    AdviseBudget b;
    b.maxEdgeRmse = 0.04;
    b.maxAcne = 0.001;
    b.maxLeakTexels = 3.0;
    b.maxShimmer = 0.25;
    return b;
}

struct Counted {
    int calls = 0;
    AdviseMeasure measure() {
        return [this](const AdviseSetting& s) {
            ++calls;
            return syntheticMetrics(s);
        };
    }
};

TEST(AdviseSearch, NoCheaperSettingOfTheFullGridMeetsTheBudget) {
    AdviseSpace space = syntheticSpace();
    AdviseBudget budget = syntheticBudget();
    Counted counted;
    AdviseResult r = searchAdvice(space, budget, counted.measure());
    ASSERT_TRUE(r.choice.has_value());
    const AdviseCandidate& choice = r.measured[*r.choice];
    EXPECT_TRUE(adviseBroken(budget, syntheticMetrics(choice.setting)).empty());
    int feasibleInGrid = 0;
    for (const AdviseSetting& s : adviseGrid(space)) {
        AdviseMetrics m = syntheticMetrics(s);
        if (!adviseBroken(budget, m).empty()) continue;
        ++feasibleInGrid;
        EXPECT_GE(m.costMs + m.costIqr / 2, choice.metrics.costMs - choice.metrics.costIqr / 2)
            << adviseSettingName(s) << " meets the budget and costs less than the choice "
            << adviseSettingName(choice.setting);
    }
    EXPECT_GT(feasibleInGrid, 1);  // a real choice, not the only way out
    EXPECT_EQ(r.gridSize, adviseGrid(space).size());
    EXPECT_EQ(counted.calls, static_cast<int>(r.measured.size()));
    EXPECT_LE(4 * r.measured.size(), r.gridSize)
        << r.measured.size() << " of " << r.gridSize << " measured";
}

TEST(AdviseSearch, TheGridLeavesOutBiasesAMethodCannotTake) {
    AdviseSpace space;
    space.filters = {{PCF_NEAREST, 0}, {PCF_HW2X2, 0}};
    space.mapSizes = {256};
    space.biases = {{BiasMode::None, 0.0f}, {BiasMode::Soft, 0.002f}};
    // soft needs the depths in the shader: hw2x2's comparison is the texture unit's.
    ASSERT_TRUE(validateBias(static_cast<int>(BiasMode::Soft), PCF_HW2X2).has_value());
    ASSERT_FALSE(validateBias(static_cast<int>(BiasMode::Soft), PCF_NEAREST).has_value());
    EXPECT_EQ(adviseGrid(space).size(), 3u);
}

// Two filters that both meet the budget at the smallest map, the costlier median with fewer
// reads: overlapping spreads choose by reads, apart ones by the median.
AdviseResult tieCase(double iqr) {
    AdviseSpace space;
    space.filters = {{PCF_GATHER, 3}, {PCF_HW2X2, 0}};
    space.mapSizes = {512};
    space.biases = {{BiasMode::None, 0.0f}};
    AdviseBudget budget;
    budget.maxEdgeRmse = 1.0;
    return searchAdvice(space, budget, [iqr](const AdviseSetting& s) {
        AdviseMetrics m;
        m.edgeRmse = 0.1;
        m.costMs = s.filter.method == PCF_GATHER ? 1.0 : 1.1;
        m.costIqr = iqr;
        return m;
    });
}

TEST(AdviseSearch, OverlappingSpreadsPickTheFewerReads) {
    ASSERT_LT(adviseTexelReads({PCF_HW2X2, 0}), adviseTexelReads({PCF_GATHER, 3}));
    AdviseResult tied = tieCase(0.3);
    ASSERT_TRUE(tied.choice && tied.runnerUp);
    EXPECT_EQ(tied.measured[*tied.choice].setting.filter.method, PCF_HW2X2);
    EXPECT_EQ(tied.measured[*tied.runnerUp].setting.filter.method, PCF_GATHER);
    std::string note = adviseTieNote(tied);
    EXPECT_NE(note.find("hw2x2"), std::string::npos) << note;
    EXPECT_NE(note.find("pcf-gather N=3"), std::string::npos) << note;

    EXPECT_NE(note.find("fewest texel reads (4)"), std::string::npos) << note;

    AdviseResult apart = tieCase(0.02);
    ASSERT_TRUE(apart.choice);
    EXPECT_EQ(apart.measured[*apart.choice].setting.filter.method, PCF_GATHER);
    EXPECT_TRUE(adviseTieNote(apart).empty());
}

TEST(AdviseSearch, OverlappingSpreadsWithEqualReadsPickTheLowerMedian) {
    ASSERT_EQ(adviseTexelReads({PCF_TENT, 3}), adviseTexelReads({PCF_GATHER, 3}));
    AdviseSpace space;
    space.filters = {{PCF_TENT, 3}, {PCF_GATHER, 3}};
    space.mapSizes = {512};
    space.biases = {{BiasMode::None, 0.0f}};
    AdviseBudget budget;
    budget.maxEdgeRmse = 1.0;
    AdviseResult r = searchAdvice(space, budget, [](const AdviseSetting& s) {
        AdviseMetrics m;
        m.costMs = s.filter.method == PCF_GATHER ? 1.0 : 1.1;
        m.costIqr = 0.3;
        return m;
    });
    ASSERT_TRUE(r.choice);
    EXPECT_EQ(r.measured[*r.choice].setting.filter.method, PCF_GATHER);
    std::string note = adviseTieNote(r);
    EXPECT_NE(note.find("none reads fewer texels"), std::string::npos) << note;
}

TEST(AdviseSearch, TheBindingSentenceNamesTheSmallerMapAndWhatItBroke) {
    AdviseSpace space;
    space.filters = {{PCF_GATHER, 3}};
    space.mapSizes = {256, 512, 1024};
    space.biases = {{BiasMode::None, 0.0f}};
    AdviseBudget budget;
    budget.maxEdgeRmse = 1.0;
    budget.maxLeakTexels = 2.0;
    AdviseResult r = searchAdvice(space, budget, [](const AdviseSetting& s) {
        AdviseMetrics m;
        m.leakTexels = s.mapSize == 256 ? 3.1 : 1.0;
        m.costMs = 1.0;
        return m;
    });
    ASSERT_TRUE(r.choice);
    EXPECT_EQ(r.measured[*r.choice].setting.mapSize, 512);
    EXPECT_EQ(r.measured.size(), 2u);  // 1024 is not needed
    EXPECT_EQ(adviseBinding(r, budget),
              "map 512 is needed for the leak budget; 256 leaks 3.1 texels (budget 2)");
}

TEST(AdviseSearch, AMeasureADoubledMapDidNotLowerEndsTheWalk) {
    // nearest jumps a whole step wherever it flickers, at any map size (syntheticMetrics): after
    // two sizes the walk knows a larger map will not mend it.
    AdviseSpace space;
    space.filters = {{PCF_NEAREST, 0}};
    space.mapSizes = {256, 512, 1024, 2048};
    space.biases = {{BiasMode::None, 0.0f}};
    AdviseBudget budget;
    budget.maxEdgeRmse = 1.0;
    budget.maxShimmer = 0.5;
    AdviseResult r = searchAdvice(space, budget, syntheticMetrics);
    EXPECT_FALSE(r.choice.has_value());
    ASSERT_EQ(r.measured.size(), 2u);
    EXPECT_EQ(r.measured[1].setting.mapSize, 512);
}

TEST(AdviseSearch, ACostlierFilterIsLeftAtItsSmallestMapWithItsLargerKernels) {
    // hw2x2 meets the budget at 256; pcf-gather N=3 at 256 already costs more (its spread wholly
    // above), so neither its larger maps nor N = 5, 7 are measured.
    AdviseSpace space;
    space.filters = {{PCF_HW2X2, 0}, {PCF_GATHER, 3}, {PCF_GATHER, 5}, {PCF_GATHER, 7}};
    space.mapSizes = {256, 512, 1024};
    space.biases = {{BiasMode::None, 0.0f}};
    AdviseBudget budget;
    budget.maxEdgeRmse = 1.0;
    AdviseResult r = searchAdvice(space, budget, syntheticMetrics);
    ASSERT_TRUE(r.choice.has_value());
    EXPECT_EQ(r.measured[*r.choice].setting.filter.method, PCF_HW2X2);
    ASSERT_EQ(r.measured.size(), 2u);
    EXPECT_EQ(r.measured[1].setting, (AdviseSetting{{PCF_GATHER, 3}, 256, {}}));
}

TEST(AdviseSearch, AnImpossibleBudgetHasNoChoiceButAClosestCandidate) {
    AdviseSpace space = syntheticSpace();
    AdviseBudget budget = syntheticBudget();
    budget.maxEdgeRmse = 0.001;  // below every setting's error
    AdviseResult r = searchAdvice(space, budget, syntheticMetrics);
    EXPECT_FALSE(r.choice.has_value());
    ASSERT_TRUE(r.closest.has_value());
    // The closest breaks no more constraints than any other measured.
    for (const AdviseCandidate& c : r.measured) {
        EXPECT_LE(r.measured[*r.closest].broken.size(), c.broken.size());
    }
    // A measure that no map size lowers stops the walk: far fewer than the grid.
    EXPECT_LE(4 * r.measured.size(), r.gridSize);
}

TEST(AdviseSearch, RefusesAnEmptySpaceAndABadBudget) {
    AdviseBudget budget = syntheticBudget();
    EXPECT_THROW(searchAdvice(AdviseSpace{}, budget, syntheticMetrics), std::invalid_argument);
    AdviseSpace descending = syntheticSpace();
    descending.mapSizes = {512, 256};
    EXPECT_THROW(searchAdvice(descending, budget, syntheticMetrics), std::invalid_argument);
    budget.maxLeakTexels = std::nan("");
    EXPECT_THROW(searchAdvice(syntheticSpace(), budget, syntheticMetrics), std::invalid_argument);
}

}  // namespace
}  // namespace pcf
