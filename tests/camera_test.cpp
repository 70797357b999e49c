// The camera: GL matrices, and primary rays that land exactly where the rasterizer draws.
#include "scene/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "glm_expect.h"
#include "scene/raycast.h"
#include "scene/scene.h"

namespace pcf {
namespace {

constexpr float ASPECT = 16.0f / 9.0f;

Scene testScene() {
    Scene scene;
    scene.camera.eyeWs = {6, 5, 7};
    scene.camera.targetWs = {0, 0.5f, 0};
    scene.camera.fovYDeg = 40.0f;
    scene.objects.push_back({"ground", *makePlane({0, 0, 0}, {0, 1, 0}, {30, 30})});
    scene.objects.push_back({"box", Box{{0, 0.5f, 0}, {0.5f, 0.5f, 0.5f}, 20.0f}});
    scene.objects.push_back({"ball", Sphere{{1.5f, 0.6f, 1}, 0.6f}});
    fitCameraPlanes(scene.camera, sceneBounds(scene));
    return scene;
}

TEST(Camera, ViewMatrixPutsTheEyeAtTheOriginLookingDownMinusZ) {
    Camera cam = testScene().camera;
    glm::mat4 view = viewFromWorld(cam);
    EXPECT_VEC3_NEAR(glm::vec3(view * glm::vec4(cam.eyeWs, 1)), glm::vec3(0), 1e-5f);
    float dist = glm::length(cam.targetWs - cam.eyeWs);
    EXPECT_VEC3_NEAR(glm::vec3(view * glm::vec4(cam.targetWs, 1)), glm::vec3(0, 0, -dist), 1e-5f);
}

TEST(Camera, CentreRayGoesAlongTheViewDirection) {
    Camera cam = testScene().camera;
    Ray ray = cameraRay(cam, {0, 0}, ASPECT);
    EXPECT_VEC3_NEAR(ray.originWs, cam.eyeWs, 0.0f);
    EXPECT_VEC3_NEAR(ray.dirWs, glm::normalize(cam.targetWs - cam.eyeWs), 1e-6f);
    EXPECT_NEAR(glm::length(ray.dirWs), 1.0f, 1e-6f);
}

TEST(Camera, EdgeRaysSpanTheFieldOfView) {
    Camera cam = testScene().camera;
    glm::vec3 top = cameraRay(cam, {0, 1}, ASPECT).dirWs;
    glm::vec3 bottom = cameraRay(cam, {0, -1}, ASPECT).dirWs;
    EXPECT_NEAR(glm::degrees(std::acos(glm::dot(top, bottom))), 40.0f, 1e-3f);
    // Horizontally: 2 atan(aspect tan(fov / 2)).
    glm::vec3 left = cameraRay(cam, {-1, 0}, ASPECT).dirWs;
    glm::vec3 right = cameraRay(cam, {1, 0}, ASPECT).dirWs;
    float hfov = 2.0f * std::atan(ASPECT * std::tan(glm::radians(20.0f)));
    EXPECT_NEAR(std::acos(glm::dot(left, right)), hfov, 1e-5f);
    // y is up: the top ray points higher than the bottom one.
    EXPECT_GT(top.y, bottom.y);
}

TEST(Camera, HitPointsProjectBackToTheirNdc) {
    Scene scene = testScene();
    glm::mat4 clipFromWorldM = clipFromView(scene.camera, ASPECT) * viewFromWorld(scene.camera);
    EXPECT_EQ(clipFromWorldM, clipFromWorld(scene.camera, ASPECT));
    int hits = 0;
    for (int j = 0; j < 9; ++j) {
        for (int i = 0; i < 16; ++i) {
            glm::vec2 ndc = pixelCentreNdc({i, j}, {16, 9});
            auto hit = intersect(scene, cameraRay(scene.camera, ndc, ASPECT));
            if (!hit) continue;
            ++hits;
            glm::vec4 clip = clipFromWorldM * glm::vec4(hit->posWs, 1.0f);
            glm::vec3 back = glm::vec3(clip) / clip.w;
            EXPECT_NEAR(back.x, ndc.x, 1e-4f) << i << "," << j;
            EXPECT_NEAR(back.y, ndc.y, 1e-4f) << i << "," << j;
            // Inside the fitted depth range.
            EXPECT_GT(back.z, -1.0f);
            EXPECT_LT(back.z, 1.0f);
        }
    }
    EXPECT_GT(hits, 100);  // the ground fills most of the frame
}

TEST(Camera, PixelCentreNdc) {
    glm::vec2 a = pixelCentreNdc({0, 0}, {4, 2});
    EXPECT_FLOAT_EQ(a.x, -0.75f);
    EXPECT_FLOAT_EQ(a.y, -0.5f);
    glm::vec2 b = pixelCentreNdc({3, 1}, {4, 2});
    EXPECT_FLOAT_EQ(b.x, 0.75f);
    EXPECT_FLOAT_EQ(b.y, 0.5f);
}

TEST(Camera, ClipPlanesAreFittedAroundTheScene) {
    Scene scene = testScene();
    Aabb bounds = sceneBounds(scene);
    Camera& cam = scene.camera;
    EXPECT_GT(cam.nearZ, 0.0f);
    glm::vec3 forward = glm::normalize(cam.targetWs - cam.eyeWs);
    float nearest = 1e30f;
    float farthest = -1e30f;
    for (int k = 0; k < 8; ++k) {
        float d = glm::dot(bounds.cornerWs(k) - cam.eyeWs, forward);
        nearest = std::min(nearest, d);
        farthest = std::max(farthest, d);
    }
    EXPECT_LT(cam.farZ, 1.05f * farthest);
    EXPECT_GE(cam.farZ, farthest);
    EXPECT_LE(cam.nearZ, std::max(nearest, cam.farZ / 1000.0f));
    // Given planes are kept.
    Camera given = cam;
    given.nearZ = 0.5f;
    given.farZ = 80.0f;
    fitCameraPlanes(given, bounds);
    EXPECT_EQ(given.nearZ, 0.5f);
    EXPECT_EQ(given.farZ, 80.0f);
}

TEST(Camera, ProjectionNeedsClipPlanes) {
    Camera cam;
    EXPECT_THROW(clipFromView(cam, ASPECT), std::logic_error);
    cam.nearZ = 0.1f;
    cam.farZ = 10.0f;
    glm::mat4 p = clipFromView(cam, ASPECT);
    EXPECT_NEAR(p[1][1], 1.0f / std::tan(glm::radians(20.0f)), 1e-5f);
    EXPECT_NEAR(p[0][0], p[1][1] / ASPECT, 1e-5f);
    // GL convention: the near plane at ndc z = -1, the far at +1.
    glm::vec4 n = p * glm::vec4(0, 0, -0.1f, 1);
    glm::vec4 f = p * glm::vec4(0, 0, -10.0f, 1);
    EXPECT_NEAR(n.z / n.w, -1.0f, 1e-5f);
    EXPECT_NEAR(f.z / f.w, 1.0f, 1e-5f);
}

}  // namespace
}  // namespace pcf
