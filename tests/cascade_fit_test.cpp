// scene/cascade_fit.h: each cascade's light box fitted to its slice of the camera frustum, box
// or sphere, snapped or not; and the map's value with one layer per cascade.
#include "scene/cascade_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "kernel/cascades.h"
#include "kernel/shading.h"
#include "scene/light.h"
#include "scene/shadow_fit.h"

namespace pcf {
namespace {

constexpr int MAP_SIZE = 1024;
constexpr float ASPECT = 16.0f / 9.0f;

// A ground 120 units across with a post on it, a low sun, and a camera near the ground.
Scene groundScene() {
    Scene scene;
    scene.name = "test ground";
    scene.light.directionWs = glm::normalize(glm::vec3(0.5f, -1.0f, 0.3f));
    scene.objects.push_back({"ground", *makePlane(glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                                                  glm::vec2(120.0f, 120.0f))});
    scene.objects.push_back(
        {"post", Box{glm::vec3(3.0f, 1.0f, -6.0f), glm::vec3(0.2f, 1.0f, 0.2f)}});
    scene.camera.eyeWs = glm::vec3(0.0f, 2.0f, 0.0f);
    scene.camera.targetWs = glm::vec3(0.0f, 1.0f, -10.0f);
    scene.camera.nearZ = 0.1f;
    scene.camera.farZ = 200.0f;
    return scene;
}

ShadowSettings cascaded(int fit, bool snap) {
    ShadowSettings s;
    s.cascades = 4;
    s.cascadeSplit = CASCADE_SPLIT_PRACTICAL;
    s.cascadeLambda = 0.5f;
    s.shadowDistance = 100.0f;
    s.cascadeFit = fit;
    s.cascadeSnap = snap;
    s.mapSize = MAP_SIZE;
    return s;
}

// The camera at `step` of a path that turns all the way round while it walks and nods.
Camera turningCamera(int step) {
    Camera c = groundScene().camera;
    float yaw = glm::radians(static_cast<float>(step) * 7.3f);
    float pitch = glm::radians(-10.0f + 8.0f * std::sin(static_cast<float>(step) * 0.4f));
    c.eyeWs = glm::vec3(0.05f * static_cast<float>(step), 2.0f, -0.03f * static_cast<float>(step));
    glm::vec3 forward(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                      -std::cos(yaw) * std::cos(pitch));
    c.targetWs = c.eyeWs + forward;
    return c;
}

constexpr int PATH_STEPS = 60;

TEST(CascadeFit, TheRangesRunBackToBackFromTheNearPlaneToTheShadowDistance) {
    Scene scene = groundScene();
    std::vector<CascadeRange> r = cascadeRanges(scene.camera, cascaded(CASCADE_FIT_BOX, false));
    ASSERT_EQ(r.size(), 4u);
    EXPECT_EQ(r[0].nearZ, 0.1f);
    EXPECT_NEAR(r[0].farZ, 12.8187f, 1e-3f);
    for (size_t i = 1; i < r.size(); ++i) EXPECT_EQ(r[i].nearZ, r[i - 1].farZ);
    EXPECT_EQ(r[3].farZ, 100.0f);
    // No shadow distance: the camera's far plane.
    ShadowSettings s = cascaded(CASCADE_FIT_BOX, false);
    s.shadowDistance = 0.0f;
    EXPECT_EQ(cascadeRanges(scene.camera, s).back().farZ, 200.0f);
}

// Every corner of a cascade's slice lands inside its map (uv in [0,1], depth in [0,1]), for both
// fits, snapped or not, along the whole path.
TEST(CascadeFit, EveryCascadeSeesItsWholeSlice) {
    Scene scene = groundScene();
    for (int fit : {CASCADE_FIT_BOX, CASCADE_FIT_SPHERE}) {
        for (bool snap : {false, true}) {
            for (int step = 0; step < PATH_STEPS; step += 7) {
                scene.camera = turningCamera(step);
                ShadowSettings s = cascaded(fit, snap);
                for (const CascadeRange& r : cascadeRanges(scene.camera, s)) {
                    glm::mat4 m = cascadeClipFromWorld(scene, ASPECT, r, fit, snap, MAP_SIZE);
                    for (glm::vec3 c : frustumSliceWs(scene.camera, ASPECT, r)) {
                        // Only the part above the ground's depth range matters for depth: the
                        // slice reaches below the ground, the light box need not.
                        ShadowCoord sc = shadowCoord(m, c);
                        EXPECT_GE(sc.uvSm.x, -1e-5f) << fit << snap << step;
                        EXPECT_LE(sc.uvSm.x, 1.0f + 1e-5f) << fit << snap << step;
                        EXPECT_GE(sc.uvSm.y, -1e-5f) << fit << snap << step;
                        EXPECT_LE(sc.uvSm.y, 1.0f + 1e-5f) << fit << snap << step;
                    }
                    for (int k = 0; k < 8; ++k) {
                        float d = shadowCoord(m, sceneBounds(scene).cornerWs(k)).depth;
                        EXPECT_GT(d, 0.0f);
                        EXPECT_LT(d, 1.0f);
                    }
                }
            }
        }
    }
}

// The bounding sphere of a slice: every corner within its radius of its centre, and some corner
// within 1/16 of it (the rounding up).
TEST(CascadeFit, TheSliceSphereHoldsEveryCornerTightly) {
    Scene scene = groundScene();
    glm::mat4 viewFromWorldM = viewFromWorld(scene.camera);
    for (const CascadeRange& r : cascadeRanges(scene.camera, cascaded(CASCADE_FIT_SPHERE, false))) {
        SliceSphere sphere = sliceSphere(scene.camera, ASPECT, r);
        EXPECT_GE(sphere.depth, r.nearZ);
        EXPECT_LE(sphere.depth, r.farZ);
        EXPECT_EQ(sphere.radius * 16.0, std::floor(sphere.radius * 16.0));
        double farthest = 0.0;
        for (glm::vec3 c : frustumSliceWs(scene.camera, ASPECT, r)) {
            glm::vec3 v(viewFromWorldM * glm::vec4(c, 1.0f));
            double d = glm::length(glm::dvec3(v) - glm::dvec3(0.0, 0.0, -sphere.depth));
            EXPECT_LE(d, sphere.radius + 1e-4);
            farthest = std::max(farthest, d);
        }
        EXPECT_GT(farthest, sphere.radius - 1.0 / 16.0 - 1e-4);
    }
}

struct PathTexels {
    std::vector<float> lo, hi;  // per cascade, the texel size's extremes along the path
};

PathTexels texelsAlongPath(int fit, bool snap) {
    Scene scene = groundScene();
    PathTexels t{std::vector<float>(4, 1e30f), std::vector<float>(4, 0.0f)};
    for (int step = 0; step < PATH_STEPS; ++step) {
        scene.camera = turningCamera(step);
        std::vector<PcfMapLayer> layers = cascadeLayers(scene, cascaded(fit, snap), ASPECT);
        for (size_t i = 0; i < layers.size(); ++i) {
            t.lo[i] = std::min(t.lo[i], layers[i].texelWs);
            t.hi[i] = std::max(t.hi[i], layers[i].texelWs);
        }
    }
    return t;
}

// The stability numbers: along a turning camera path the sphere fit's texel size is
// constant (the same float at every step, beyond the 1e-4 relative: its scale is made
// from the sphere's radius alone), and the box fit's swings by at least 1.2x.
TEST(CascadeStability, TheSphereFitsTexelIsConstantAndTheBoxFitsIsNot) {
    PathTexels sphere = texelsAlongPath(CASCADE_FIT_SPHERE, true);
    PathTexels box = texelsAlongPath(CASCADE_FIT_BOX, true);
    for (int i = 0; i < 4; ++i) {
        EXPECT_GT(sphere.lo[i], 0.0f);
        EXPECT_EQ(sphere.hi[i], sphere.lo[i]) << i;
        EXPECT_GE(box.hi[i] / box.lo[i], 1.2f) << i;
        // The sphere's square holds the slice's light-space box at every turn: never finer.
        EXPECT_GE(sphere.lo[i], box.hi[i] * (1.0f - 1e-5f)) << i;
        std::printf(
            "cascade %d: box texel %.5f .. %.5f (x%.3f), sphere %.5f (area x%.2f .. x%.2f of "
            "box)\n",
            i, static_cast<double>(box.lo[i]), static_cast<double>(box.hi[i]),
            static_cast<double>(box.hi[i] / box.lo[i]), static_cast<double>(sphere.lo[i]),
            static_cast<double>(sphere.lo[i] * sphere.lo[i] / (box.hi[i] * box.hi[i])),
            static_cast<double>(sphere.lo[i] * sphere.lo[i] / (box.lo[i] * box.lo[i])));
    }
}

// With snapping, the world origin projects onto a texel corner in every cascade at every step:
// the map's texel grid is fixed to the world and only slides by whole texels.
TEST(CascadeStability, SnappingPutsTheOriginOnWholeTexels) {
    Scene scene = groundScene();
    double worst = 0.0, worstUnsnapped = 0.0;
    for (int step = 0; step < PATH_STEPS; ++step) {
        scene.camera = turningCamera(step);
        for (bool snap : {true, false}) {
            for (const PcfMapLayer& layer :
                 cascadeLayers(scene, cascaded(CASCADE_FIT_SPHERE, snap), ASPECT)) {
                glm::vec4 o = layer.shadowClipFromWorld * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
                for (int a = 0; a < 2; ++a) {
                    double texels = static_cast<double>(o[a] / o.w) * MAP_SIZE / 2.0;
                    double frac = std::fabs(texels - std::round(texels));
                    (snap ? worst : worstUnsnapped) = std::max(snap ? worst : worstUnsnapped, frac);
                }
            }
        }
    }
    EXPECT_LT(worst, 1e-4);
    EXPECT_GT(worstUnsnapped, 0.1);  // unsnapped, the origin lands anywhere in a texel
}

TEST(CascadeFit, TheMapHasOneLayerPerCascadeWithItsViewDepths) {
    Scene scene = groundScene();
    ShadowSettings s = cascaded(CASCADE_FIT_SPHERE, true);
    MapSpec spec = shadowMapSpec(scene, s, shadowClipFromWorld(scene), ASPECT);
    ASSERT_EQ(spec.layers.size(), 4u);
    EXPECT_FALSE(checkMapSpec(spec).has_value());
    std::vector<CascadeRange> r = cascadeRanges(scene.camera, s);
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(spec.layers[i].viewDepth, vec2(r[i].nearZ, r[i].farZ));
        EXPECT_EQ(spec.layers[i].depthRange, vec2(0.0f));  // orthographic
        if (i > 0) {
            EXPECT_GT(spec.layers[i].texelWs, spec.layers[i - 1].texelWs);
        }
    }
    // One cascade: the map over the whole scene, as before cascades.
    s.cascades = 1;
    MapSpec one = shadowMapSpec(scene, s, shadowClipFromWorld(scene), ASPECT);
    ASSERT_EQ(one.layers.size(), 1u);
    EXPECT_EQ(one.layers[0].shadowClipFromWorld, shadowClipFromWorld(scene));
    EXPECT_EQ(one.layers[0].viewDepth, vec2(0.0f));
}

// Normal offset is K texels of the cascade read (its layer's texelWs): the same point moves as
// many of its own cascade's texels across the map in every cascade, K sin^2(theta) (the normal's
// d = K texelWs sin(theta), of which sin(theta) lies across the light), so a far cascade's
// coarser texels move it further in the world; its depth moves by d cos(theta) of a depth range
// every cascade shares, so in proportion to the texel's world size.
TEST(CascadeFit, NormalOffsetIsTexelsOfTheCascadeRead) {
    Scene scene = groundScene();
    ShadowSettings s = cascaded(CASCADE_FIT_SPHERE, true);
    MapSpec spec = shadowMapSpec(scene, s, shadowClipFromWorld(scene), ASPECT);
    glm::vec3 p(1.0f, 0.0f, -8.0f), n(0.0f, 1.0f, 0.0f);
    float cosTheta = glm::dot(n, -glm::normalize(scene.light.directionWs));
    float sin2 = 1.0f - cosTheta * cosTheta;
    const float k = 2.0f;
    std::vector<float> depthShift;
    for (const PcfMapLayer& layer : spec.layers) {
        PcfReceiverLookup at =
            pcfReceiverLookup(layer.shadowClipFromWorld, p, n, cosTheta, PCF_BIAS_CONSTANT, 0.0f,
                              0.0f, 0.0f, k, layer.texelWs, true);
        PcfReceiverLookup moved =
            pcfReceiverLookup(layer.shadowClipFromWorld, p, n, cosTheta, PCF_BIAS_NORMAL, 0.0f,
                              0.0f, 0.0f, k, layer.texelWs, true);
        float texelsMoved = glm::length(glm::vec2(moved.u - at.u, moved.v - at.v)) * MAP_SIZE;
        EXPECT_NEAR(texelsMoved, k * sin2, 2e-3f);
        depthShift.push_back(std::fabs(moved.z - at.z));
    }
    for (size_t i = 1; i < spec.layers.size(); ++i) {
        float texelRatio = spec.layers[i].texelWs / spec.layers[0].texelWs;
        EXPECT_NEAR(depthShift[i] / depthShift[0], texelRatio, 1e-2f * texelRatio) << i;
    }
}

TEST(CascadeFit, CascadesAreRefusedForASpotAndAShadowDistanceBeforeTheNearPlane) {
    Scene scene = groundScene();
    ShadowSettings s = cascaded(CASCADE_FIT_BOX, false);
    EXPECT_FALSE(cascadeProblem(scene, s).has_value());
    s.shadowDistance = 0.05f;
    ASSERT_TRUE(cascadeProblem(scene, s).has_value());
    EXPECT_EQ(cascadeProblem(scene, s)->text(),
              "shadow_distance 0.05 must lie beyond the camera's near plane 0.1");
    EXPECT_THROW(shadowMapSpec(scene, s, shadowClipFromWorld(scene), ASPECT),
                 std::invalid_argument);
    s.shadowDistance = 100.0f;
    scene.light.type = LightType::Spot;
    ASSERT_TRUE(cascadeProblem(scene, s).has_value());
    EXPECT_EQ(cascadeProblem(scene, s)->text(),
              "cascades 4 are for a directional light; the scene's light is a spot");
    scene.light.type = LightType::Directional;
    s.method = PCF_PCSS;
    ASSERT_TRUE(cascadeProblem(scene, s).has_value());
    EXPECT_EQ(cascadeProblem(scene, s)->text(),
              "cascades 4 do not work with pcss (one penumbra scale per map)");
}

}  // namespace
}  // namespace pcf
