// The shadow map's matrices: the directional light's orthographic frustum fitted tightly to the
// scene, the spot's perspective, shadow-map coordinates in GL's convention, and the direction
// to the light for shadow rays.
#include "scene/light.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "glm_expect.h"
#include "scene/raycast.h"
#include "scene/scene.h"

namespace pcf {
namespace {

Scene testScene(glm::vec3 lightDirection) {
    Scene scene;
    scene.light.type = LightType::Directional;
    scene.light.directionWs = glm::normalize(lightDirection);
    scene.objects.push_back({"ground", *makePlane({0.5f, 0, -1}, {0, 1, 0}, {10, 6})});
    scene.objects.push_back({"box", Box{{0, 0.5f, 0}, {0.5f, 0.5f, 0.5f}, 20.0f}});
    scene.objects.push_back({"ball", Sphere{{2, 1.5f, 1}, 0.5f}});
    return scene;
}

glm::vec3 ndcOf(const glm::mat4& clipFromWorld, glm::vec3 posWs) {
    glm::vec4 clip = clipFromWorld * glm::vec4(posWs, 1.0f);
    return glm::vec3(clip) / clip.w;
}

// The fit of every directional light: all 8 corners inside NDC, and for each of +-x, +-y, +-z
// the extreme corner exactly SHADOW_FIT_MARGIN of the diagonal inside the side, so no texel
// row or column is spent outside the scene's bounds.
void expectTightOrthoFit(const Scene& scene) {
    Aabb bounds = sceneBounds(scene);
    glm::mat4 proj = clipFromLight(scene);
    glm::mat4 m = proj * lightFromWorld(scene);
    EXPECT_EQ(m, shadowClipFromWorld(scene));
    glm::vec3 lo(2.0f);
    glm::vec3 hi(-2.0f);
    for (int k = 0; k < 8; ++k) {
        glm::vec3 ndc = ndcOf(m, bounds.cornerWs(k));
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    float margin = SHADOW_FIT_MARGIN * glm::length(bounds.extentWs());
    // Orthographic: ndc = (v - mid) * scale per axis, scale = proj[i][i] = 2 / width.
    for (int i = 0; i < 3; ++i) {
        float inset = margin * std::abs(proj[i][i]);
        EXPECT_GT(inset, 0.0f);
        EXPECT_LT(inset, 0.02f) << "axis " << i;  // ~1% of the range at most
        EXPECT_NEAR(hi[i], 1.0f - inset, 2e-5f) << "axis " << i;
        EXPECT_NEAR(lo[i], -1.0f + inset, 2e-5f) << "axis " << i;
    }
}

TEST(DirectionalLight, OrthoIsFittedTightlyToTheSceneBounds) {
    expectTightOrthoFit(testScene({-0.4f, -1.0f, -0.3f}));
    expectTightOrthoFit(testScene({1.0f, -0.2f, 0.0f}));  // grazing
    expectTightOrthoFit(testScene({0.0f, -1.0f, 0.0f}));  // straight down: another up vector
    expectTightOrthoFit(testScene({0.0f, 1.0f, 0.0f}));   // from below
}

TEST(DirectionalLight, ViewLooksAlongTheLight) {
    Scene scene = testScene({-0.4f, -1.0f, -0.3f});
    glm::mat4 view = lightFromWorld(scene);
    glm::vec3 dirLs = glm::vec3(view * glm::vec4(scene.light.directionWs, 0.0f));
    EXPECT_VEC3_NEAR(dirLs, glm::vec3(0, 0, -1), 1e-6f);
    // Orthographic: w stays 1.
    EXPECT_FLOAT_EQ((shadowClipFromWorld(scene) * glm::vec4(3, 2, 1, 1)).w, 1.0f);
}

TEST(DirectionalLight, PointsAlongALightRayShareUvAndDepthGrowsAwayFromTheLight) {
    // The ground point under the box and the point where its shadow ray meets the box: the
    // same texel, the blocker nearer the light. This is what makes the depth test work.
    Scene scene = testScene({1, -2, 0.5f});
    glm::mat4 m = shadowClipFromWorld(scene);
    glm::vec3 groundWs(0.8f, 0, 0.3f);
    auto blocker = intersect(scene, Ray{groundWs, -scene.light.directionWs}, 1e-3f);
    ASSERT_TRUE(blocker);
    EXPECT_EQ(blocker->object, 1);
    ShadowCoord g = shadowCoord(m, groundWs);
    ShadowCoord b = shadowCoord(m, blocker->posWs);
    EXPECT_NEAR(g.uvSm.x, b.uvSm.x, 1e-5f);
    EXPECT_NEAR(g.uvSm.y, b.uvSm.y, 1e-5f);
    EXPECT_LT(b.depth, g.depth);
    // Depth is linear along the light for an orthographic light: half way, half the change.
    ShadowCoord mid = shadowCoord(m, 0.5f * (groundWs + blocker->posWs));
    EXPECT_NEAR(mid.depth, 0.5f * (g.depth + b.depth), 1e-6f);
}

TEST(ShadowCoord, MatchesGlClipMath) {
    Scene scene = testScene({-0.4f, -1.0f, -0.3f});
    glm::mat4 m = shadowClipFromWorld(scene);
    for (glm::vec3 p : {glm::vec3(0.1f, 0.2f, 0.3f), glm::vec3(-4, 0, 1.5f), glm::vec3(2, 2, 1)}) {
        // glm::projectNO with the viewport (0, 0, 1, 1) is GL's window transform:
        // win.xy = ndc.xy * 0.5 + 0.5, win.z = ndc.z * 0.5 + 0.5.
        glm::vec3 win = glm::projectNO(p, glm::mat4(1.0f), m, glm::vec4(0, 0, 1, 1));
        ShadowCoord sc = shadowCoord(m, p);
        EXPECT_NEAR(sc.uvSm.x, win.x, 1e-6f);
        EXPECT_NEAR(sc.uvSm.y, win.y, 1e-6f);
        EXPECT_NEAR(sc.depth, win.z, 1e-6f);
        EXPECT_GE(sc.depth, 0.0f);
        EXPECT_LE(sc.depth, 1.0f);
    }
}

Light spotLight() {
    Light light;
    light.type = LightType::Spot;
    light.positionWs = {3, 4, 2};
    light.directionWs = glm::normalize(glm::vec3(0, 0.5f, 0) - light.positionWs);
    light.coneDeg = 35.0f;
    return light;
}

struct NearFar {
    float nearZ;
    float farZ;
};

// glm::perspectiveRH_NO: P[2][2] = -(f + n) / (f - n), P[3][2] = -2 f n / (f - n).
NearFar nearFarOf(const glm::mat4& p) {
    return {p[3][2] / (p[2][2] - 1.0f), p[3][2] / (p[2][2] + 1.0f)};
}

TEST(SpotLight, PerspectiveCoversTheConeAndIsFittedInDepth) {
    Scene scene = testScene({0, -1, 0});
    scene.light = spotLight();
    Aabb bounds = sceneBounds(scene);
    glm::mat4 view = lightFromWorld(scene);
    glm::mat4 proj = clipFromLight(scene);
    glm::mat4 m = proj * view;
    // fov = 2 * cone: proj[1][1] = 1 / tan(cone), square.
    EXPECT_NEAR(proj[1][1], 1.0f / std::tan(glm::radians(35.0f)), 1e-5f);
    EXPECT_NEAR(proj[0][0], proj[1][1], 1e-6f);

    // On the axis: the map's centre. On the cone, along the light's view x: the map's edge.
    glm::vec3 axis = scene.light.directionWs;
    glm::vec3 sideWs = glm::vec3(glm::inverse(view) * glm::vec4(1, 0, 0, 0));
    ShadowCoord centre = shadowCoord(m, scene.light.positionWs + 3.0f * axis);
    EXPECT_NEAR(centre.uvSm.x, 0.5f, 1e-5f);
    EXPECT_NEAR(centre.uvSm.y, 0.5f, 1e-5f);
    float cone = glm::radians(35.0f);
    glm::vec3 rim =
        scene.light.positionWs + 3.0f * (std::cos(cone) * axis + std::sin(cone) * sideWs);
    ShadowCoord edge = shadowCoord(m, rim);
    EXPECT_NEAR(edge.uvSm.x, 1.0f, 1e-5f);
    EXPECT_NEAR(edge.uvSm.y, 0.5f, 1e-5f);

    // Depth: every corner in front of the light lands in [0, 1], the farthest just inside 1.
    NearFar nf = nearFarOf(proj);
    float farthest = 0.0f;
    for (int k = 0; k < 8; ++k) {
        glm::vec3 c = bounds.cornerWs(k);
        float along = glm::dot(c - scene.light.positionWs, axis);
        farthest = std::max(farthest, along);
        if (along < nf.nearZ) continue;
        float depth = shadowCoord(m, c).depth;
        EXPECT_GE(depth, 0.0f);
        EXPECT_LE(depth, 1.0f);
    }
    float margin = SHADOW_FIT_MARGIN * glm::length(bounds.extentWs());
    EXPECT_NEAR(nf.farZ, farthest + margin, 1e-4f);
    EXPECT_GE(nf.nearZ, SPOT_MIN_NEAR);
    // Depth grows with distance along the axis, and matches GL's window transform.
    EXPECT_LT(shadowCoord(m, scene.light.positionWs + 2.0f * axis).depth,
              shadowCoord(m, scene.light.positionWs + 4.0f * axis).depth);
    glm::vec3 p(0.3f, 0.2f, -0.4f);
    glm::vec3 win = glm::projectNO(p, glm::mat4(1.0f), m, glm::vec4(0, 0, 1, 1));
    EXPECT_NEAR(shadowCoord(m, p).depth, win.z, 1e-6f);
}

TEST(SpotLight, NearIsTheNearestCornerOrClamped) {
    // Light well outside the scene: near = nearest corner depth minus the margin.
    Scene scene = testScene({0, -1, 0});
    scene.light.type = LightType::Spot;
    scene.light.positionWs = {0.5f, 20, -1};
    scene.light.directionWs = {0, -1, 0};
    scene.light.coneDeg = 20.0f;
    Aabb bounds = sceneBounds(scene);
    float margin = SHADOW_FIT_MARGIN * glm::length(bounds.extentWs());
    NearFar nf = nearFarOf(clipFromLight(scene));
    EXPECT_NEAR(nf.nearZ, 20.0f - bounds.maxWs.y - margin, 1e-3f);
    EXPECT_NEAR(nf.farZ, 20.0f - bounds.minWs.y + margin, 1e-3f);
    // Light inside the bounds: corners behind it would give near < 0; it is clamped.
    scene.light.positionWs = {0, 1, 0};
    EXPECT_NEAR(nearFarOf(clipFromLight(scene)).nearZ, SPOT_MIN_NEAR, 1e-5f);
}

TEST(TowardLight, DirectionalAndSpot) {
    Light sun;
    sun.directionWs = glm::normalize(glm::vec3(1, -2, 0.5f));
    LightSample s = towardLight(sun, {3, 0, 1});
    EXPECT_VEC3_NEAR(s.dirWs, -sun.directionWs, 1e-6f);
    EXPECT_TRUE(std::isinf(s.distance));
    EXPECT_TRUE(s.insideCone);

    Light spot;
    spot.type = LightType::Spot;
    spot.positionWs = {0, 4, 0};
    spot.directionWs = {0, -1, 0};
    spot.coneDeg = 30.0f;
    LightSample onAxis = towardLight(spot, {0, 1, 0});
    EXPECT_VEC3_NEAR(onAxis.dirWs, glm::vec3(0, 1, 0), 1e-6f);
    EXPECT_FLOAT_EQ(onAxis.distance, 3.0f);
    EXPECT_TRUE(onAxis.insideCone);
    // (3, 0, 4) from (0, 4, 0): distance 5, 53 degrees off the axis.
    LightSample off = towardLight(spot, {3, 0, 4});
    EXPECT_FLOAT_EQ(off.distance, std::sqrt(9.0f + 16.0f + 16.0f));
    EXPECT_VEC3_NEAR(off.dirWs, glm::normalize(glm::vec3(-3, 4, -4)), 1e-6f);
    EXPECT_FALSE(off.insideCone);
    // Just inside and just outside 30 degrees.
    float r29 = 4.0f * std::tan(glm::radians(29.9f));
    float r31 = 4.0f * std::tan(glm::radians(30.1f));
    EXPECT_TRUE(towardLight(spot, {r29, 0, 0}).insideCone);
    EXPECT_FALSE(towardLight(spot, {0, 0, r31}).insideCone);
    // Behind the spot.
    EXPECT_FALSE(towardLight(spot, {0, 5, 0}).insideCone);
}

TEST(LightElevation, KeepsTheHeadingAndSetsTheAngle) {
    glm::vec3 d = directionAtElevation(glm::vec3(1.1f, -1.0f, 0.45f), 30.0f);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::degrees(std::asin(-d.y)), 30.0f, 1e-4f);
    EXPECT_NEAR(d.z / d.x, 0.45f / 1.1f, 1e-5f);  // the same compass heading
    EXPECT_NEAR(directionAtElevation(glm::vec3(0, -1, 0), 90.0f).y, -1.0f, 1e-6f);
}

// Where a world point lands, in texels of a mapSize map.
glm::vec2 texelOf(const glm::mat4& m, glm::vec3 p, int mapSize) {
    return shadowCoord(m, p).uvSm * static_cast<float>(mapSize);
}

TEST(ShadowOrigin, ShiftMovesTheGridAndSnappingLeavesWholeTexels) {
    Light light;
    Aabb bounds{glm::vec3(-6, 0, -6), glm::vec3(6, 1, 6)};
    glm::mat4 m = clipFromLight(light, bounds) * lightFromWorld(light, bounds);
    const int n = 512;
    glm::vec3 p(1.3f, 0.0f, -2.7f), q(-4.1f, 0.5f, 3.3f);
    // A shift of (0.25, -0.5) texel moves every point by exactly that in the map.
    glm::mat4 shifted = shiftShadowOrigin(m, glm::vec2(0.25f, -0.5f), n, false);
    glm::vec2 d = texelOf(shifted, p, n) - texelOf(m, p, n);
    EXPECT_NEAR(d.x, 0.25f, 1e-3f);
    EXPECT_NEAR(d.y, -0.5f, 1e-3f);
    EXPECT_NEAR(shadowCoord(shifted, p).depth, shadowCoord(m, p).depth, 1e-7f);
    // Snapped, two fits a fraction of a texel apart differ by whole texels only (0 or 1), for
    // every point: the map's content moves, it does not change.
    for (float offset : {0.1f, 0.37f, 0.62f, 0.99f}) {
        glm::mat4 a = shiftShadowOrigin(m, glm::vec2(0.0f), n, true);
        glm::mat4 b = shiftShadowOrigin(m, glm::vec2(offset), n, true);
        for (glm::vec3 x : {p, q}) {
            glm::vec2 step = texelOf(b, x, n) - texelOf(a, x, n);
            EXPECT_NEAR(step.x, std::round(step.x), 1e-3f) << offset;
            EXPECT_NEAR(step.y, std::round(step.y), 1e-3f) << offset;
        }
        // The world origin sits on a texel corner.
        glm::vec2 o = texelOf(b, glm::vec3(0.0f), n);
        EXPECT_NEAR(o.x, std::round(o.x), 1e-3f);
        EXPECT_NEAR(o.y, std::round(o.y), 1e-3f);
    }
}

TEST(ShadowDepthRange, WideningDividesTheDepth) {
    Light light;
    Aabb bounds{glm::vec3(-1), glm::vec3(1)};
    glm::mat4 m = clipFromLight(light, bounds) * lightFromWorld(light, bounds);
    glm::mat4 wide = widenShadowDepthRange(m, 100.0f);
    for (glm::vec3 p : {glm::vec3(0.0f), glm::vec3(0.9f, -0.8f, 0.3f)}) {
        EXPECT_NEAR(shadowCoord(wide, p).depth, shadowCoord(m, p).depth / 100.0f, 1e-7f);
        glm::vec2 uv = shadowCoord(wide, p).uvSm - shadowCoord(m, p).uvSm;
        EXPECT_NEAR(glm::length(uv), 0.0f, 1e-7f);
    }
}

}  // namespace
}  // namespace pcf
