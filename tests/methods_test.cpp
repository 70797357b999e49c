#include "kernel/methods.h"

#include <gtest/gtest.h>

namespace pcf {
namespace {

TEST(Methods, TheNineIdsOfTheDesignInOrder) {
    const char* ids[] = {"nearest",    "box2x2", "bilinear2x2", "hw2x2",  "pcf-naive",
                         "pcf-gather", "pcf-hw", "tent",        "poisson"};
    ASSERT_EQ(allMethods().size(), 9u);
    for (int k = 0; k < 9; ++k) {
        EXPECT_EQ(allMethods()[k].name, ids[k]);
        EXPECT_EQ(allMethods()[k].id, k);
        EXPECT_EQ(methodFromName(ids[k]), k);
    }
    EXPECT_FALSE(methodFromName("pcf").has_value());
    EXPECT_FALSE(methodFromName("").has_value());
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
