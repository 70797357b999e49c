#include "kernel/shadow_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <string_view>

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

// Each texel kind says what its texels hold: the depths a fixed-point format clamps the ref for
// (16, 24), float depths, and moments in 2 or 4 channels of half or single floats; each by its
// own name, which reads back.
TEST(ShadowMap, EveryTexelKindHasItsOwnNameAndItsChannels) {
    std::set<std::string_view> names;
    for (TexelKind k : allTexelKinds()) {
        const TexelKindInfo& info = texelKindInfo(k);
        EXPECT_TRUE(names.insert(info.name).second) << info.name;
        EXPECT_EQ(texelKindFromName(info.name), k) << info.name;
        EXPECT_EQ(info.channels == 1, info.depth) << info.name;
        EXPECT_TRUE(info.channels == 1 || info.channels == 2 || info.channels == 4) << info.name;
        EXPECT_TRUE(!info.fixedPoint || info.depth) << info.name;
    }
    EXPECT_EQ(texelKindInfo(TexelKind::D16).bits, 16);
    EXPECT_TRUE(texelKindInfo(TexelKind::D24).fixedPoint);
    EXPECT_FALSE(texelKindInfo(TexelKind::D32F).fixedPoint);
    EXPECT_EQ(texelKindInfo(TexelKind::Moments4F16).channels, 4);
    EXPECT_EQ(texelKindInfo(TexelKind::Moments2F32).bits, 32);
    EXPECT_EQ(texelKindFromName("32"), TexelKind::D32F);
    EXPECT_FALSE(texelKindFromName("8").has_value());
}

// Every value of the enum is in allTexelKinds() (the list the names, the command line and the
// parity test read): texelKindInfo's switch names every kind (no `default:`) and throws past the
// last, so walking the values until it throws visits each kind once.
TEST(ShadowMap, EveryTexelKindIsListed) {
    std::span<const TexelKind> listed = allTexelKinds();
    int k = 0;
    for (;; ++k) {
        TexelKind kind = static_cast<TexelKind>(k);
        try {
            texelKindInfo(kind);
        } catch (const std::out_of_range&) {
            break;
        }
        EXPECT_NE(std::find(listed.begin(), listed.end(), kind), listed.end()) << k;
    }
    EXPECT_EQ(static_cast<size_t>(k), listed.size());
}

// A map made from depths is one layer of 32F depths, fitted by nothing (identity, orthographic,
// texel size unknown); its spec can say otherwise only where the texels stored fit it.
TEST(ShadowMap, ItsSpecSaysWhatItHolds) {
    ShadowMap map(4, 2, 0.5f);
    EXPECT_EQ(map.spec().size, glm::ivec2(4, 2));
    EXPECT_EQ(map.spec().texels, TexelKind::D32F);
    ASSERT_EQ(map.layers(), 1);
    EXPECT_EQ(map.spec().layers[0].shadowClipFromWorld, glm::mat4(1.0f));
    EXPECT_EQ(map.spec().layers[0].depthRange, glm::vec2(0.0f));
    EXPECT_FALSE(map.isFixedPoint());

    map.setTexelKind(TexelKind::D24);
    EXPECT_EQ(map.fixedPointBits(), 24);
    // Two channels a texel need twice the values; two layers too.
    EXPECT_THROW(map.setTexelKind(TexelKind::Moments2F32), std::invalid_argument);
    MapSpec two = map.spec();
    two.layers.push_back(MapSpec::unfittedLayer());
    EXPECT_THROW(map.setSpec(two), std::invalid_argument);
    MapSpec none = map.spec();
    none.layers.clear();
    EXPECT_EQ(checkMapSpec(none).value(), "a map has 1 to 4 layers, not 0");

    // Moments: channels interleaved, depth() reads a texel's first.
    MapSpec moments{glm::ivec2(2, 1),
                    TexelKind::Moments2F32,
                    {MapSpec::unfittedLayer()},
                    glm::vec2(0.0f),
                    std::nullopt};
    ShadowMap m(moments, {0.25f, 0.0625f, 0.5f, 0.25f});
    EXPECT_EQ(m.depth(1, 0), 0.5f);
    // Layers one after the other: layerTexels finds each.
    MapSpec layered{glm::ivec2(2, 1),
                    TexelKind::D32F,
                    {MapSpec::unfittedLayer(), MapSpec::unfittedLayer()},
                    glm::vec2(0.0f),
                    std::nullopt};
    ShadowMap l(layered, {0.1f, 0.2f, 0.3f, 0.4f});
    EXPECT_EQ(l.layerTexels(1)[0], 0.3f);
    EXPECT_THROW(l.layerTexels(2), std::out_of_range);
}

// Two specs are equal when size, texel kind and every layer's fit are.
TEST(ShadowMap, SpecsCompareByValue) {
    MapSpec a{
        glm::ivec2(8), TexelKind::D16, {MapSpec::unfittedLayer()}, glm::vec2(0.0f), std::nullopt};
    MapSpec b = a;
    EXPECT_EQ(a, b);
    // A cascaded map's depth bounds are part of its value (render.json, verify).
    MapSpec bounded = a;
    bounded.visibleDepths = glm::vec2(4.0f, 95.0f);
    EXPECT_NE(bounded, a);
    b.layers[0].texelWs = 0.5f;
    EXPECT_NE(a, b);
    b = a;
    b.layers[0].shadowClipFromWorld[3][0] = 0.25f;
    EXPECT_NE(a, b);
    b = a;
    b.texels = TexelKind::D24;
    EXPECT_NE(a, b);
}

}  // namespace
}  // namespace pcf
