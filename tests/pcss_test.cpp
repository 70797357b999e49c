// Percentage-closer soft shadows in the shared kernel (pcfPcss, pcf_kernel.h) and the light size
// it is given (scene/pcss.h): the blocker search's numbers, the penumbra that grows with the
// distance to the blocker (contact hardening), and the scale from the light and the map.
#include "scene/pcss.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "kernel/methods.h"
#include "kernel/pcf.h"
#include "kernel/trace.h"
#include "kernel/trace_explain.h"
#include "kernel/trace_json.h"
#include "random_map.h"
#include "scene/presets.h"

namespace pcf {
namespace {

PcfParams pcssParams(float penumbraScale, vec2 rotation = vec2(1.0f, 0.0f)) {
    PcfParams prm = makeParams(PCF_PCSS, 3, 1.0f, rotation);
    prm.penumbraScale = penumbraScale;
    return prm;
}

PcfPcssEstimate estimate(const ShadowMap& map, vec2 uv, float ref, float scale) {
    PcfParams prm = pcssParams(scale);
    return pcfPcssEstimate(plainMap(map, prm), uv, pcfPlainRef(ref, uv), scale, 0.0f, 0.0f,
                           prm.rotation);
}

// A 64 x 64 map lit at depth 1 but for an occluder at `depth` over columns i < 32.
ShadowMap halfOccluded(int size, float depth) {
    ShadowMap map(size, size, 1.0f);
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size / 2; ++i) map.setDepth(i, j, depth);
    }
    return map;
}

// A light of size 0 searches and filters over the smallest disk, radius 1 texel: where no
// search tap blocks, no filter tap can (the same taps, the same comparisons), so pcss is
// poisson with radius 1, bit for bit, rotated or not, under every per-tap bias but soft.
TEST(Pcss, ALightOfSizeZeroIsPoissonOfRadiusOne) {
    ShadowMap map = randomMap(37, 29, 5);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int partial = 0;
    for (int k = 0; k < 2000; ++k) {
        vec2 uv(unit(rng), unit(rng));
        float ref = unit(rng);
        vec2 rotation = PCF_ROTATIONS[k % 16];
        PcfBias bias{k % 2 == 0 ? PCF_BIAS_CONSTANT : PCF_BIAS_RECEIVER_PLANE,
                     vec2(unit(rng) - 0.5f, unit(rng) - 0.5f), 0.0f, PCF_DZDUV_UNCLAMPED};
        float pcss = filterVisibility(map, uv, ref, pcssParams(0.0f, rotation), bias);
        float poisson =
            filterVisibility(map, uv, ref, makeParams(PCF_POISSON, 3, 1.0f, rotation), bias);
        ASSERT_EQ(pcss, poisson) << "lookup " << k;
        if (pcss > 0.0f && pcss < 1.0f) ++partial;
    }
    EXPECT_GT(partial, 500);  // the random map puts most lookups on an edge
}

// Half the map occluded at depth 0.3, a receiver at 0.7 on the edge, S = 20 texels per depth
// unit: the search disk has radius 0.7 * 20 / 2 = 7 texels, and its 8 taps left of the edge
// (the disk's points with x < 0) are the blockers, all at 0.3. The penumbra is
// (0.7 - 0.3) * 20 = 8 texels, the filter's radius 4: again the 8 taps left of the edge are
// shadowed, visibility 1/2.
TEST(Pcss, TheBlockerSearchFindsTheOccludersAndTheirMeanDepth) {
    ShadowMap map = halfOccluded(64, 0.3f);
    vec2 uv(0.5f, 0.5f);  // on the edge: uv * size = 32
    PcfPcssEstimate e = estimate(map, uv, 0.7f, 20.0f);
    int left = 0;
    for (int k = 0; k < 16; ++k) left += PCF_POISSON_DISK[k].x < 0.0f ? 1 : 0;
    ASSERT_EQ(left, 8);
    EXPECT_FLOAT_EQ(e.searchRadius, 7.0f);
    EXPECT_EQ(e.blockers, left);
    EXPECT_FLOAT_EQ(e.blockerDepth, 0.3f);
    EXPECT_NEAR(e.penumbra, 8.0f, 1e-5f);
    EXPECT_NEAR(e.filterRadius, 4.0f, 1e-5f);
    EXPECT_FLOAT_EQ(filterVisibility(map, uv, 0.7f, pcssParams(20.0f)), 0.5f);

    // Far from the edge on the lit side no search tap reaches the occluder: fully lit, and the
    // estimate says why (no blockers, no penumbra).
    vec2 far((32.0f + 7.5f) / 64.0f, 0.5f);
    PcfPcssEstimate none = estimate(map, far, 0.7f, 20.0f);
    EXPECT_EQ(none.blockers, 0);
    EXPECT_EQ(none.penumbra, 0.0f);
    EXPECT_EQ(filterVisibility(map, far, 0.7f, pcssParams(20.0f)), 1.0f);
    // Deep in the shadow every tap blocks.
    EXPECT_EQ(estimate(map, vec2(8.0f / 64.0f, 0.5f), 0.7f, 20.0f).blockers, 16);
    EXPECT_EQ(filterVisibility(map, vec2(8.0f / 64.0f, 0.5f), 0.7f, pcssParams(20.0f)), 0.0f);
}

// The trace steps through the three stages with the kernel's numbers: the 16 search taps first
// (weight 0: they decide the width, not the visibility) with their blocker bits, then the
// penumbra from the mean blocker depth, then the filter's taps; --json carries the same.
TEST(Pcss, TheTraceStepsThroughSearchPenumbraAndFilter) {
    ShadowMap map = halfOccluded(64, 0.3f);
    Trace tr = traceLookup(map, vec2(0.5f, 0.5f), 0.7f, 0.7f, pcssParams(20.0f));
    ASSERT_EQ(tr.taps.size(), 32u);
    int blockers = 0;
    for (int k = 0; k < PCF_PCSS_TAPS; ++k) {
        EXPECT_EQ(tr.taps[k].weight, 0.0f) << k;
        blockers += tr.taps[k].lit == 0.0f ? 1 : 0;
    }
    EXPECT_EQ(blockers, 8);
    EXPECT_EQ(tr.pcss.blockers, 8);
    EXPECT_NEAR(tr.pcss.penumbra, 8.0f, 1e-5f);
    EXPECT_FLOAT_EQ(tr.visibility, 0.5f);
    EXPECT_FLOAT_EQ(weightedTapSum(tr), tr.visibility);
    std::vector<TraceStep> steps = explainTrace(tr);
    std::vector<TraceStepKind> kinds;
    for (const TraceStep& s : steps) kinds.push_back(s.kind);
    std::vector<TraceStepKind> tail = {TraceStepKind::BlockerSearch, TraceStepKind::PenumbraWidth,
                                       TraceStepKind::DiskPoints, TraceStepKind::Result};
    ASSERT_GE(kinds.size(), tail.size());
    EXPECT_TRUE(std::equal(tail.begin(), tail.end(), kinds.end() - 4));
    const std::string& width = steps[steps.size() - 3].text;
    EXPECT_NE(width.find("(0.7 - 0.3) * 20 = 8 texels"), std::string::npos) << width;
    EXPECT_NE(steps.back().text.find("8 lit / 16 = 0.5"), std::string::npos) << steps.back().text;
    Json j = traceJson(tr);
    EXPECT_EQ(j["pcss"]["blockers"], 8);
    EXPECT_NEAR(j["pcss"]["penumbra"].get<double>(), 8.0, 1e-5);
    EXPECT_NEAR(j["pcss"]["filter_radius"].get<double>(), 4.0, 1e-5);
    EXPECT_NEAR(j["pcss"]["search_radius"].get<double>(), 7.0, 1e-5);
    // Which search taps found a blocker: the disk's points left of the edge (x < 0), at 0.3;
    // the others read the lit side, 1.
    ASSERT_EQ(j["pcss"]["search"].size(), 16u);
    for (int k = 0; k < PCF_PCSS_TAPS; ++k) {
        const Json& s = j["pcss"]["search"][static_cast<size_t>(k)];
        bool left = PCF_POISSON_DISK[k].x < 0.0f;
        EXPECT_EQ(s["tap"].get<int>(), k);
        EXPECT_EQ(s["blocker"].get<bool>(), left) << k;
        EXPECT_NEAR(s["depth"].get<double>(), left ? 0.3 : 1.0, 1e-6) << k;
    }
    EXPECT_NEAR(j["pcss"]["blocker_depth"].get<double>(), 0.3, 1e-6);

    // No blocker: the search's taps only, all lit, and visibility 1 without a filter: their
    // mean, so they weigh 1/16 each.
    Trace lit = traceLookup(map, vec2(39.5f / 64.0f, 0.5f), 0.7f, 0.7f, pcssParams(20.0f));
    EXPECT_EQ(lit.taps.size(), 16u);
    EXPECT_EQ(lit.visibility, 1.0f);
    EXPECT_FLOAT_EQ(weightedTapSum(lit), 1.0f);
    std::vector<TraceStep> litSteps = explainTrace(lit);
    EXPECT_EQ(litSteps.back().kind, TraceStepKind::Result);
    EXPECT_EQ(litSteps[litSteps.size() - 2].kind, TraceStepKind::BlockerSearch);
}

// The width (texels) over which a scan across the edge is neither lit nor shadowed.
float partialWidth(const ShadowMap& map, float ref, const PcfParams& prm) {
    const float step = 0.125f;  // texels
    int partial = 0;
    for (float x = 0.0f; x < static_cast<float>(map.width()); x += step) {
        float v = filterVisibility(map, vec2(x / map.width(), 0.5f), ref, prm);
        if (v > 0.0f && v < 1.0f) ++partial;
    }
    return static_cast<float>(partial) * step;
}

// Contact hardening: the same receiver depth behind an occluder near it and one far from it.
// PCF's penumbra is one width whatever the distance; pcss's is (ref - d_blocker) * S, here 4
// and 24 texels, to within the disk's reach (its points reach 0.92 to 0.98 of the radius) and a
// texel of nearest reads.
TEST(Pcss, ThePenumbraGrowsWithTheDistanceToTheBlocker) {
    const float scale = 40.0f;
    const float ref = 0.8f;
    float widths[2];
    int k = 0;
    for (float blocker : {0.7f, 0.2f}) {
        ShadowMap map = halfOccluded(256, blocker);
        float expected = (ref - blocker) * scale;
        float width = partialWidth(map, ref, pcssParams(scale));
        EXPECT_GT(width, 0.85f * expected - 1.0f) << "blocker " << blocker;
        EXPECT_LT(width, 1.0f * expected + 1.0f) << "blocker " << blocker;
        // A fixed kernel does not care how far the blocker is.
        EXPECT_EQ(partialWidth(map, ref, makeParams(PCF_GATHER, 5)),
                  partialWidth(halfOccluded(256, 0.7f), ref, makeParams(PCF_GATHER, 5)));
        widths[k++] = width;
    }
    EXPECT_GT(widths[1], 4.0f * widths[0]);
}

// The scale against the map's own projection: a step of t world units along the light moves
// the depth by t * (dDepth/dt), a step across it moves the lookup by some texels; the penumbra
// of a disk of angular diameter theta is 2 tan(theta / 2) world units per world unit of
// distance, so S = 2 tan(theta / 2) * (texels per world unit across) / (depth per world unit).
// Texels per world unit across: the fewest over the directions across the light (the larger
// texel side, as shadowTexelWs measures the texel).
TEST(Pcss, TheScaleIsTheLightsAngleInTexelsPerDepthUnit) {
    Scene scene = *presetScene("box-on-plane");
    scene.light.angularDiameterDeg = 1.5f;
    glm::mat4 m = shadowClipFromWorld(scene);
    const int mapSize = 512;
    glm::vec3 p(0.3f, 0.2f, -0.4f);
    glm::vec3 dir = glm::normalize(scene.light.directionWs);
    float depthPerUnit = shadowCoord(m, p + dir).depth - shadowCoord(m, p).depth;
    glm::vec3 a = glm::normalize(glm::cross(dir, glm::vec3(0.0f, 0.0f, 1.0f)));
    glm::vec3 b = glm::cross(dir, a);
    float texelsPerUnit = 1e30f;
    for (int k = 0; k < 3600; ++k) {
        float t = glm::radians(0.1f * static_cast<float>(k));
        glm::vec3 e = std::cos(t) * a + std::sin(t) * b;
        glm::vec2 d = shadowCoord(m, p + e).uvSm - shadowCoord(m, p).uvSm;
        texelsPerUnit = std::min(texelsPerUnit, glm::length(d) * mapSize);
    }
    float expected = 2.0f * std::tan(glm::radians(1.5f) / 2.0f) * texelsPerUnit / depthPerUnit;
    EXPECT_NEAR(penumbraScale(scene.light, m, mapSize, 0.0f), expected, expected * 1e-4f);
    // The settings' size wins over the scene's; without either, the sun's.
    EXPECT_NEAR(penumbraScale(scene.light, m, mapSize, 3.0f),
                expected * std::tan(glm::radians(1.5f)) / std::tan(glm::radians(0.75f)),
                expected * 1e-4f);
    scene.light.angularDiameterDeg = 0.0f;
    EXPECT_FLOAT_EQ(penumbraScale(scene.light, m, mapSize, 0.0f),
                    penumbraScale(scene.light, m, mapSize, SUN_ANGULAR_DIAMETER_DEG));
    // Twice the texels, twice the scale; a widened depth range (light.h), twice the depth units.
    EXPECT_NEAR(penumbraScale(scene.light, m, 2 * mapSize, 1.5f),
                2.0f * penumbraScale(scene.light, m, mapSize, 1.5f), expected * 1e-4f);
    EXPECT_NEAR(penumbraScale(scene.light, widenShadowDepthRange(m, 2.0f), mapSize, 1.5f),
                2.0f * penumbraScale(scene.light, m, mapSize, 1.5f), expected * 1e-4f);
    // Only pcss gets a scale; a spot light on an orthographic map (not a perspective one) none.
    ShadowSettings s;
    s.method = PCF_GATHER;
    EXPECT_EQ(pcssPcfParams(scene.light, PcfMapLayer{m, pcssDepthRange(m), 0.0f}, s).penumbraScale,
              0.0f);
    s.method = PCF_PCSS;
    EXPECT_GT(pcssPcfParams(scene.light, PcfMapLayer{m, pcssDepthRange(m), 0.0f}, s).penumbraScale,
              0.0f);
    scene.light.type = LightType::Spot;
    EXPECT_EQ(pcssPcfParams(scene.light, PcfMapLayer{m, pcssDepthRange(m), 0.0f}, s).penumbraScale,
              0.0f);
}

// A spot map with near 1 and far 4 stores z = 4/3 * (1 - 1/d) at distance d: an occluder at
// d = 2 over the left half (z = 2/3), a receiver at d = 3 (z = 8/9) on the edge, S = 60. By
// Fernando's formulas in linear distance: the search radius S / 2 * (3 - 1) / (3 * 1) = 20
// texels, its 8 taps left of the edge block at mean distance 2, the penumbra
// S * (3 - 2) / (2 * 3) = 10 texels, the filter radius 5, visibility 1/2. (In stored depth the
// directional formula would give (8/9 - 2/3) * 60 = 13.3 texels.)
TEST(Pcss, ASpotMapsPenumbraFollowsTheLinearDistances) {
    ShadowMap map = halfOccluded(64, 2.0f / 3.0f);
    PcfParams prm = pcssParams(60.0f);
    prm.depthNear = 1.0f;
    prm.depthFar = 4.0f;
    vec2 uv(0.5f, 0.5f);
    PcfPcssEstimate e =
        pcfPcssEstimate(plainMap(map, prm), uv, pcfPlainRef(8.0f / 9.0f, uv), prm.penumbraScale,
                        prm.depthNear, prm.depthFar, prm.rotation);
    EXPECT_NEAR(e.searchRadius, 20.0f, 1e-4f);
    EXPECT_EQ(e.blockers, 8);
    EXPECT_NEAR(e.blockerDepth, 2.0f, 1e-5f);
    EXPECT_NEAR(e.penumbra, 10.0f, 1e-4f);
    EXPECT_NEAR(e.filterRadius, 5.0f, 1e-4f);
    EXPECT_EQ(filterVisibility(map, uv, 8.0f / 9.0f, prm), 0.5f);
    // The inspector's steps give the same numbers in the spot's terms; --json its near and far.
    Trace tr = traceLookup(map, uv, 8.0f / 9.0f, 8.0f / 9.0f, prm);
    std::vector<TraceStep> steps = explainTrace(tr);
    ASSERT_GE(steps.size(), 4u);
    const std::string& search = steps[steps.size() - 4].text;
    EXPECT_NE(search.find("near n = 1, far f = 4"), std::string::npos) << search;
    EXPECT_NE(search.find("d_receiver = 3."), std::string::npos) << search;
    EXPECT_NE(search.find("mean distance d_blocker = 16 / 8 = 2."), std::string::npos) << search;
    const std::string& width = steps[steps.size() - 3].text;
    EXPECT_NE(width.find("60 * (3 - 2) / (2 * 3) = 10 texels"), std::string::npos) << width;
    Json j = traceJson(tr);
    EXPECT_NEAR(j["pcss"]["depth_near"].get<double>(), 1.0, 1e-6);
    EXPECT_NEAR(j["pcss"]["depth_far"].get<double>(), 4.0, 1e-6);
    // A receiver on the far plane (z = 1, d = 4): S * (4 - 2) / (2 * 4) = 15 texels.
    EXPECT_NEAR(pcfPcssEstimate(plainMap(map, prm), uv, pcfPlainRef(1.0f, uv), 60.0f, 1.0f, 4.0f,
                                prm.rotation)
                    .penumbra,
                15.0f, 1e-4f);
}

// A spot of radius 0.25 looking down with a 90-degree cone (P00 = 1 / tan(45 degrees) = 1), near
// 1 and far 4, a 128 map: S = 0.25 * 1 * 128 = 32 texels times scene units, near and far read
// back from the matrix; a shifted texel grid changes neither, a widened depth range keeps near.
TEST(Pcss, ASpotsScaleAndDepthRangeComeFromItsMatrix) {
    Light spot;
    spot.type = LightType::Spot;
    spot.radius = 0.25f;
    glm::mat4 m = glm::perspectiveRH_NO(glm::radians(90.0f), 1.0f, 1.0f, 4.0f) *
                  glm::lookAtRH(glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0, 0, -1));
    EXPECT_NEAR(penumbraScale(spot, m, 128, 0.0f), 32.0f, 1e-4f);
    EXPECT_NEAR(penumbraScale(spot, m, 128, 3.0f), 32.0f, 1e-4f);  // degrees are the sun's
    glm::vec2 range = pcssDepthRange(m);
    EXPECT_NEAR(range.x, 1.0f, 1e-5f);
    EXPECT_NEAR(range.y, 4.0f, 1e-4f);
    glm::mat4 shifted = shiftShadowOrigin(m, glm::vec2(0.3f, -0.7f), 128, false);
    EXPECT_NEAR(penumbraScale(spot, shifted, 128, 0.0f), 32.0f, 1e-4f);
    EXPECT_NEAR(pcssDepthRange(shifted).y, 4.0f, 1e-4f);
    EXPECT_NEAR(pcssDepthRange(widenShadowDepthRange(m, 2.0f)).x, 1.0f, 1e-5f);
    EXPECT_EQ(pcssDepthRange(glm::orthoRH_NO(-1.0f, 1.0f, -1.0f, 1.0f, 1.0f, 4.0f)),
              glm::vec2(0.0f));
    ShadowSettings s;
    s.method = PCF_PCSS;
    s.mapSize = 128;
    PcfParams p = pcssPcfParams(spot, PcfMapLayer{m, pcssDepthRange(m), 0.0f}, s);
    EXPECT_NEAR(p.penumbraScale, 32.0f, 1e-4f);
    EXPECT_NEAR(p.depthNear, 1.0f, 1e-5f);
    s.method = PCF_POISSON;
    EXPECT_EQ(pcssPcfParams(spot, PcfMapLayer{m, pcssDepthRange(m), 0.0f}, s).depthNear, 0.0f);
}

}  // namespace
}  // namespace pcf
