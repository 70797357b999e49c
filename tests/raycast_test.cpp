// Exact ray casting: hand-computed hits and misses for each primitive, shadow rays, and the
// analytic shadow of a sphere (an ellipse) against occluded().
#include "scene/raycast.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "glm_expect.h"

namespace pcf {
namespace {

const Sphere UNIT_SPHERE{glm::vec3(0.0f), 1.0f};

TEST(RaySphere, HeadOnHitsTheNearSide) {
    auto hit = intersect(UNIT_SPHERE, Ray{{0, 0, -5}, {0, 0, 1}});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4.0f);
    EXPECT_VEC3_NEAR(hit->posWs, glm::vec3(0, 0, -1), 1e-6f);
    EXPECT_VEC3_NEAR(hit->normalWs, glm::vec3(0, 0, -1), 1e-6f);
    EXPECT_TRUE(hit->frontFace);
    EXPECT_EQ(hit->object, -1);
}

TEST(RaySphere, OffCentreHitMatchesPythagoras) {
    // x = 0.6 meets the unit sphere at z = -sqrt(1 - 0.36) = -0.8, so t = 5 - 0.8.
    auto hit = intersect(UNIT_SPHERE, Ray{{0.6f, 0, -5}, {0, 0, 1}});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.2f, 1e-6f);
    EXPECT_VEC3_NEAR(hit->posWs, glm::vec3(0.6f, 0, -0.8f), 1e-6f);
    EXPECT_VEC3_NEAR(hit->normalWs, glm::vec3(0.6f, 0, -0.8f), 1e-6f);
}

TEST(RaySphere, MissesJustOutsideAndBehind) {
    EXPECT_FALSE(intersect(UNIT_SPHERE, Ray{{1.001f, 0, -5}, {0, 0, 1}}));
    EXPECT_FALSE(intersect(UNIT_SPHERE, Ray{{0, 0, 5}, {0, 0, 1}}));  // sphere behind the origin
    EXPECT_FALSE(intersect(UNIT_SPHERE, Ray{{0, 0, -5}, {0, 0, 1}}, 0.0f, 3.9f));  // past tMax
}

TEST(RaySphere, GrazingRayTouchesAtOnePoint) {
    auto hit = intersect(UNIT_SPHERE, Ray{{1, 0, -5}, {0, 0, 1}});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 5.0f);
    EXPECT_VEC3_NEAR(hit->posWs, glm::vec3(1, 0, 0), 1e-6f);
    EXPECT_VEC3_NEAR(hit->normalWs, glm::vec3(1, 0, 0), 1e-6f);
}

TEST(RaySphere, FromInsideHitsTheFarSideFromBehind) {
    Sphere s{{1, 2, 3}, 2.0f};
    auto hit = intersect(s, Ray{{1, 2, 3}, {0, 1, 0}});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2.0f);
    EXPECT_VEC3_NEAR(hit->posWs, glm::vec3(1, 4, 3), 1e-6f);
    EXPECT_VEC3_NEAR(hit->normalWs, glm::vec3(0, 1, 0), 1e-6f);
    EXPECT_FALSE(hit->frontFace);
}

TEST(RaySphere, NonUnitDirectionMeasuresTInItsLength) {
    auto hit = intersect(UNIT_SPHERE, Ray{{0, 0, -5}, {0, 0, 2}});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2.0f);
}

TEST(RaySphere, FarOriginStaysPrecise) {
    // 10^4 units away the naive b^2 - ac loses digits; the stable form and the snap keep the
    // point on the sphere.
    auto hit = intersect(UNIT_SPHERE, Ray{{0.6f, 0, -1e4f}, {0, 0, 1}});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->posWs.z, -0.8f, 1e-6f);
    EXPECT_NEAR(glm::length(hit->posWs), 1.0f, 1e-6f);
}

const Box UNIT_BOX{{0, 0.5f, 0}, {0.5f, 0.5f, 0.5f}, 0.0f};

TEST(RayBox, HitsTheFaceItMeetsFirst) {
    auto side = intersect(UNIT_BOX, Ray{{-3, 0.5f, 0}, {1, 0, 0}});
    ASSERT_TRUE(side);
    EXPECT_FLOAT_EQ(side->t, 2.5f);
    EXPECT_VEC3_NEAR(side->posWs, glm::vec3(-0.5f, 0.5f, 0), 1e-6f);
    EXPECT_VEC3_NEAR(side->normalWs, glm::vec3(-1, 0, 0), 1e-6f);
    EXPECT_TRUE(side->frontFace);

    auto top = intersect(UNIT_BOX, Ray{{0.2f, 3, 0.1f}, {0, -1, 0}});
    ASSERT_TRUE(top);
    EXPECT_FLOAT_EQ(top->t, 2.0f);
    EXPECT_VEC3_NEAR(top->posWs, glm::vec3(0.2f, 1, 0.1f), 1e-6f);
    EXPECT_VEC3_NEAR(top->normalWs, glm::vec3(0, 1, 0), 1e-6f);

    // Diagonal: from (1.9, 2.5, 0) along (-1, -1, 0) / sqrt(2) meets the top y = 1 at x = 0.4.
    auto diag = intersect(UNIT_BOX, Ray{{1.9f, 2.5f, 0}, glm::normalize(glm::vec3(-1, -1, 0))});
    ASSERT_TRUE(diag);
    EXPECT_VEC3_NEAR(diag->posWs, glm::vec3(0.4f, 1, 0), 1e-6f);
    EXPECT_NEAR(diag->t, 1.5f * std::numbers::sqrt2_v<float>, 1e-5f);
}

TEST(RayBox, Misses) {
    EXPECT_FALSE(intersect(UNIT_BOX, Ray{{-3, 1.2f, 0}, {1, 0, 0}}));   // above
    EXPECT_FALSE(intersect(UNIT_BOX, Ray{{-3, 0.5f, 0}, {-1, 0, 0}}));  // pointing away
    EXPECT_FALSE(intersect(UNIT_BOX, Ray{{-3, 0.5f, 0.6f}, {1, 0, 0}}));
    // Inside the x slab for t in [-0.5, 0.5], the z slab for t in [0.55, 1.55]: passes beside
    // the corner (0.5, -0.5) without touching.
    EXPECT_FALSE(intersect(UNIT_BOX, Ray{{0, 0.5f, -1.05f}, {1, 0, 1}}));
}

TEST(RayBox, GrazingAlongAFaceCountsAsTouching) {
    // In the plane of the top face: the boundary belongs to the slab.
    auto hit = intersect(UNIT_BOX, Ray{{-3, 1.0f, 0}, {1, 0, 0}});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2.5f);
    EXPECT_FALSE(intersect(UNIT_BOX, Ray{{-3, 1.0001f, 0}, {1, 0, 0}}));
}

TEST(RayBox, FromInsideHitsTheExitFace) {
    auto hit = intersect(UNIT_BOX, Ray{{0, 0.5f, 0}, {0, 0, 1}});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 0.5f);
    EXPECT_VEC3_NEAR(hit->normalWs, glm::vec3(0, 0, 1), 1e-6f);
    EXPECT_FALSE(hit->frontFace);
}

TEST(RayBox, RotatedBoxIsHitInItsOwnFrame) {
    // Turned 45 degrees about Y, a corner points along -x at x = -sqrt(2)/2. At z = 0.2 the
    // ray meets the face with outward normal (-1, 0, 1) / sqrt(2), whose plane is
    // -x + z = sqrt(2) * 0.5, so x = 0.2 - sqrt(2) / 2.
    Box box{{0, 0.5f, 0}, {0.5f, 0.5f, 0.5f}, 45.0f};
    auto hit = intersect(box, Ray{{-3, 0.5f, 0.2f}, {1, 0, 0}});
    ASSERT_TRUE(hit);
    float x = 0.2f - 0.5f * std::numbers::sqrt2_v<float>;
    EXPECT_NEAR(hit->t, 3.0f + x, 1e-6f);
    EXPECT_VEC3_NEAR(hit->posWs, glm::vec3(x, 0.5f, 0.2f), 1e-6f);
    EXPECT_VEC3_NEAR(hit->normalWs, glm::normalize(glm::vec3(-1, 0, 1)), 1e-6f);
    // The unrotated box would have been hit at x = -0.5; a ray at z = 0.6 misses it but meets
    // the rotated one (its corner reaches out to |z| = 0.707 at x = 0).
    EXPECT_TRUE(intersect(box, Ray{{0, 3, 0.6f}, {0, -1, 0}}));
    EXPECT_FALSE(intersect(UNIT_BOX, Ray{{0, 3, 0.6f}, {0, -1, 0}}));
}

TEST(RayPlane, FiniteRectangle) {
    // Ground plane 4 along x, 2 along z.
    Plane ground = *makePlane({0, 0, 0}, {0, 1, 0}, {4, 2});
    auto hit = intersect(ground, Ray{{1, 5, 0.5f}, {0, -1, 0}});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 5.0f);
    EXPECT_VEC3_NEAR(hit->posWs, glm::vec3(1, 0, 0.5f), 1e-6f);
    EXPECT_VEC3_NEAR(hit->normalWs, glm::vec3(0, 1, 0), 1e-6f);
    EXPECT_TRUE(hit->frontFace);

    EXPECT_FALSE(intersect(ground, Ray{{2.1f, 5, 0}, {0, -1, 0}}));  // beyond x = 2
    EXPECT_FALSE(intersect(ground, Ray{{1, 5, 1.1f}, {0, -1, 0}}));  // beyond z = 1
    EXPECT_FALSE(intersect(ground, Ray{{1, 5, 0}, {0, 1, 0}}));      // pointing away
}

TEST(RayPlane, FromBehindEdgeOnAndAtTheEdge) {
    Plane ground = *makePlane({0, 0, 0}, {0, 1, 0}, {4, 2});
    auto below = intersect(ground, Ray{{1, -3, 0}, {0, 1, 0}});
    ASSERT_TRUE(below);
    EXPECT_FLOAT_EQ(below->t, 3.0f);
    EXPECT_VEC3_NEAR(below->normalWs, glm::vec3(0, 1, 0), 1e-6f);  // the plane's own normal
    EXPECT_FALSE(below->frontFace);
    // In the plane itself: edge-on, no area, no hit.
    EXPECT_FALSE(intersect(ground, Ray{{-5, 0, 0}, {1, 0, 0}}));
    // 45 degrees down from (0, 2, 0) lands exactly on the edge x = 2: inside (inclusive).
    auto edge = intersect(ground, Ray{{0, 2, 0}, glm::normalize(glm::vec3(1, -1, 0))});
    ASSERT_TRUE(edge);
    EXPECT_NEAR(edge->t, 2.0f * std::numbers::sqrt2_v<float>, 1e-6f);
    EXPECT_VEC3_NEAR(edge->posWs, glm::vec3(2, 0, 0), 1e-6f);
}

TEST(RayPlane, TiltedWall) {
    // Normal +Z: U = +X (size[0] = 2), V = cross(Z, X) = +Y (size[1] = 4).
    Plane wall = *makePlane({0, 1, 0}, {0, 0, 1}, {2, 4});
    EXPECT_TRUE(intersect(wall, Ray{{0.9f, 2.9f, 5}, {0, 0, -1}}));
    EXPECT_FALSE(intersect(wall, Ray{{1.1f, 1, 5}, {0, 0, -1}}));
    EXPECT_FALSE(intersect(wall, Ray{{0, 3.1f, 5}, {0, 0, -1}}));
}

Scene boxOnGround(glm::vec3 lightDirection) {
    Scene scene;
    scene.light.type = LightType::Directional;
    scene.light.directionWs = glm::normalize(lightDirection);
    scene.objects.push_back({"ground", *makePlane({0, 0, 0}, {0, 1, 0}, {10, 10})});
    scene.objects.push_back({"box", UNIT_BOX});
    return scene;
}

TEST(SceneIntersect, NearestObjectWins) {
    Scene scene = boxOnGround({0, -1, 0});
    auto onBox = intersect(scene, Ray{{0.1f, 5, 0.1f}, {0, -1, 0}});
    ASSERT_TRUE(onBox);
    EXPECT_EQ(onBox->object, 1);
    EXPECT_FLOAT_EQ(onBox->t, 4.0f);
    auto onGround = intersect(scene, Ray{{3, 5, 3}, {0, -1, 0}});
    ASSERT_TRUE(onGround);
    EXPECT_EQ(onGround->object, 0);
    EXPECT_FLOAT_EQ(onGround->t, 5.0f);
    EXPECT_FALSE(intersect(scene, Ray{{3, 5, 3}, {0, 1, 0}}));
}

TEST(Occluded, GroundUnderTheBoxIsInShadow) {
    // Light travelling (1, -2, 0.5): from ground point (0.8, 0, 0.3) back toward the light the
    // ray passes (0.4, 0.8, 0.1), inside the box; from (1.2, 0, 0.3) it stays at x >= 0.7.
    Scene scene = boxOnGround({1, -2, 0.5f});
    glm::vec3 toLight = -scene.light.directionWs;
    float inf = RAY_T_MAX;
    EXPECT_TRUE(occluded(scene, {0.8f, 0, 0.3f}, toLight, inf));
    EXPECT_TRUE(occluded(scene, {0.8f, 0, 0.3f}, toLight, inf, 0));  // skipping the ground
    EXPECT_FALSE(occluded(scene, {1.2f, 0, 0.3f}, toLight, inf));
    EXPECT_FALSE(occluded(scene, {4, 0, -4}, toLight, inf));
    // The box is the only blocker: skipped, or not a caster, nothing blocks.
    EXPECT_FALSE(occluded(scene, {0.8f, 0, 0.3f}, toLight, inf, 1));
    scene.objects[1].castsShadow = false;
    EXPECT_FALSE(occluded(scene, {0.8f, 0, 0.3f}, toLight, inf));
}

TEST(Occluded, StopsAtMaxT) {
    // A light between the point and the box (a spot at distance 0.3) is not blocked.
    Scene scene = boxOnGround({0, -1, 0});
    glm::vec3 p(0.8f, 0, 0.3f);
    glm::vec3 toLight = glm::normalize(glm::vec3(-1, 2, -0.5f));
    EXPECT_TRUE(occluded(scene, p, toLight, 5.0f));
    EXPECT_FALSE(occluded(scene, p, toLight, 0.3f));
}

TEST(Occluded, ShadowRayEpsilonScalesWithPosition) {
    EXPECT_FLOAT_EQ(shadowRayTMin({0.5f, -0.2f, 0.9f}, {0, 1, 0}), SHADOW_RAY_EPSILON);
    EXPECT_FLOAT_EQ(shadowRayTMin({0, -200, 50}, {0, 1, 0}), 200 * SHADOW_RAY_EPSILON);
    EXPECT_FLOAT_EQ(shadowRayTMin({0, 0, 0}, {0, 2, 0}), 0.5f * SHADOW_RAY_EPSILON);
}

TEST(Occluded, SphereShadowIsTheProjectedEllipse) {
    // The sphere's shadow under a directional light is the cylinder of radius r about the line
    // C + s d cut by the ground y = 0: centred where that line meets the ground,
    //   P0 = C - (C.y / d.y) d,
    // with semi-axes a = r / cos(theta) along the light's horizontal direction h and b = r
    // across it (theta = angle between d and the vertical, cos(theta) = -d.y for unit d).
    Scene scene;
    scene.light.directionWs = glm::normalize(glm::vec3(0.6f, -1.0f, 0.3f));
    scene.objects.push_back({"ground", *makePlane({0, 0, 0}, {0, 1, 0}, {20, 20})});
    Sphere ball{{0.3f, 1.5f, -0.2f}, 0.5f};
    scene.objects.push_back({"ball", ball});

    glm::dvec3 d(scene.light.directionWs);
    glm::dvec3 c(ball.centreWs);
    glm::dvec3 p0 = c - (c.y / d.y) * d;
    glm::dvec3 h = glm::normalize(glm::dvec3(d.x, 0, d.z));
    glm::dvec3 across = glm::cross(h, glm::dvec3(0, 1, 0));
    double a = ball.radius / -d.y;
    double b = ball.radius;
    EXPECT_GT(a, 1.2 * b);  // a real ellipse, not a circle

    glm::vec3 toLight = -scene.light.directionWs;
    int inside = 0;
    int outside = 0;
    for (int k = 0; k < 72; ++k) {
        double phi = 2.0 * std::numbers::pi * k / 72;
        glm::dvec3 q = a * std::cos(phi) * h + b * std::sin(phi) * across;
        glm::vec3 in(p0 + 0.98 * q);
        glm::vec3 out(p0 + 1.02 * q);
        ASSERT_NEAR(in.y, 0.0f, 1e-6f);
        if (occluded(scene, in, toLight, RAY_T_MAX, 0)) ++inside;
        if (!occluded(scene, out, toLight, RAY_T_MAX, 0)) ++outside;
    }
    EXPECT_EQ(inside, 72);
    EXPECT_EQ(outside, 72);
    EXPECT_TRUE(occluded(scene, glm::vec3(p0), toLight, RAY_T_MAX));
}

TEST(LitByLight, CameraHitsInAndOutOfTheShadow) {
    Scene scene = boxOnGround({1, -2, 0.5f});
    auto shadowed = intersect(scene, Ray{{0.8f, 5, 0.3f}, {0, -1, 0}});
    ASSERT_TRUE(shadowed);
    EXPECT_EQ(shadowed->object, 0);
    EXPECT_FALSE(litByLight(scene, *shadowed));
    auto lit = intersect(scene, Ray{{1.2f, 5, 0.3f}, {0, -1, 0}});
    ASSERT_TRUE(lit);
    EXPECT_TRUE(litByLight(scene, *lit));
    // A receiver that does not receive is lit wherever it faces the light.
    scene.objects[0].receivesShadow = false;
    EXPECT_TRUE(litByLight(scene, *shadowed));
}

TEST(LitByLight, SidesFacingAwayAreDark) {
    Scene scene = boxOnGround({1, -2, 0.5f});
    // The box's +x face faces the light's direction of travel: its own shadow side.
    auto away = intersect(scene, Ray{{3, 0.5f, 0}, {-1, 0, 0}});
    ASSERT_TRUE(away);
    EXPECT_EQ(away->object, 1);
    EXPECT_FALSE(litByLight(scene, *away));
    auto facing = intersect(scene, Ray{{-3, 0.5f, 0}, {1, 0, 0}});
    ASSERT_TRUE(facing);
    EXPECT_TRUE(litByLight(scene, *facing));
    // The ground seen from below faces away from a light above.
    auto below = intersect(scene, Ray{{3, -2, 3}, {0, 1, 0}});
    ASSERT_TRUE(below);
    EXPECT_FALSE(litByLight(scene, *below));
}

TEST(LitByLight, GrazingLightHasNoSelfShadowOnThePlane) {
    // 89.5 degrees from the normal: a shadow ray barely leaves the ground, yet skipping the
    // surface it starts on keeps every open ground point lit, with no acne.
    Scene scene;
    double theta = glm::radians(89.5);
    scene.light.directionWs = glm::vec3(std::sin(theta), -std::cos(theta), 0.0);
    scene.objects.push_back({"ground", *makePlane({0, 0, 0}, {0, 1, 0}, {20, 20})});
    int lit = 0;
    for (int i = 0; i < 100; ++i) {
        Ray ray{{-5.0f + 0.1f * i, 3, 0.15f * i - 7}, glm::normalize(glm::vec3(0.1f, -1, 0.05f))};
        auto hit = intersect(scene, ray);
        ASSERT_TRUE(hit);
        lit += litByLight(scene, *hit) ? 1 : 0;
    }
    EXPECT_EQ(lit, 100);
}

TEST(LitByLight, SpotConeLimitsTheLight) {
    Scene scene;
    scene.light.type = LightType::Spot;
    scene.light.positionWs = {0, 4, 0};
    scene.light.directionWs = {0, -1, 0};
    scene.light.coneDeg = 30.0f;
    scene.objects.push_back({"ground", *makePlane({0, 0, 0}, {0, 1, 0}, {20, 20})});
    // tan(30) * 4 = 2.309: the cone's footprint on the ground.
    auto in = intersect(scene, Ray{{2.2f, 1, 0}, {0, -1, 0}});
    auto out = intersect(scene, Ray{{2.4f, 1, 0}, {0, -1, 0}});
    ASSERT_TRUE(in && out);
    EXPECT_TRUE(litByLight(scene, *in));
    EXPECT_FALSE(litByLight(scene, *out));
}

}  // namespace
}  // namespace pcf
