#include "kernel/shadow_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace pcf {
namespace {

TEST(ShadowMap, RowZeroIsTheFirstRowStored) {
    ShadowMap map(3, 2, std::vector<float>{0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f});
    EXPECT_EQ(map.depth(0, 0), 0.1f);
    EXPECT_EQ(map.depth(2, 0), 0.3f);
    EXPECT_EQ(map.depth(0, 1), 0.4f);
    EXPECT_EQ(map.size(), glm::ivec2(3, 2));
}

TEST(ShadowMap, RejectsWrongSizes) {
    EXPECT_THROW(ShadowMap(0, 4), std::invalid_argument);
    EXPECT_THROW(ShadowMap(2, 2, std::vector<float>{0.1f}), std::invalid_argument);
}

TEST(ShadowMap, FindsTheFirstInvalidTexel) {
    ShadowMap map(4, 4, 0.5f);
    EXPECT_FALSE(map.findInvalidTexel().has_value());
    map.setDepth(2, 3, std::numeric_limits<float>::quiet_NaN());
    EXPECT_EQ(map.findInvalidTexel().value(), "texel (2, 3) is NaN");
    map.setDepth(1, 1, 1.5f);
    EXPECT_EQ(map.findInvalidTexel().value(), "texel (1, 1) has depth 1.5, outside [0, 1]");
    map.setDepth(0, 0, -std::numeric_limits<float>::infinity());
    EXPECT_EQ(map.findInvalidTexel().value(), "texel (0, 0) is infinite");
}

TEST(ShadowMap, ExampleHasItsOccluderCorner) {
    ShadowMap map = exampleShadowMap();
    EXPECT_EQ(map.size(), glm::ivec2(8, 8));
    EXPECT_FALSE(map.findInvalidTexel().has_value());
    EXPECT_LT(map.depth(4, 2), 0.5f);  // occluder
    EXPECT_GT(map.depth(3, 2), 0.5f);  // ground
    EXPECT_GT(map.depth(7, 1), 0.5f);  // ground, below the occluder's rows
}

}  // namespace
}  // namespace pcf
