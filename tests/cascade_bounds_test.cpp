// --cascade-bounds depth on the GPU (kernel/cascades.h, render/scene_renderer.h visibleDepths):
// the depth prepass measures the view depths of the receivers the frame shows, the cascades split
// [n, f] tightened to them, cascade 0's texels shrink, and every receiver pixel of the frame still
// reads a cascade. Runs on llvmpipe through EGL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "kernel/cascades.h"
#include "kernel/shading.h"
#include "render/gl_context.h"
#include "render/scene_renderer.h"
#include "scene/cascade_fit.h"
#include "scene/presets.h"

namespace pcf {
namespace {

class CascadeBounds : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> CascadeBounds::sContext;

// Zhang, Sun, Xu and Lau, "Parallel-Split Shadow Maps for Large-scale Virtual Environments"
// (2006): C_i = lambda n (f/n)^(i/N) + (1 - lambda)(n + (f - n) i/N), written out as the paper
// gives it.
double practicalSplit(double n, double f, int i, int count, double lambda) {
    double t = static_cast<double>(i) / count;
    return lambda * n * std::pow(f / n, t) + (1.0 - lambda) * (n + (f - n) * t);
}

// 4 cascades, practical lambda 0.5, ending at a shadow distance of 400: four times as far as the
// long-ground preset's camera sees (its far plane is 100).
RenderSettings farShadowDistance(int bounds) {
    RenderSettings s;
    s.cascades = 4;
    s.cascadeSplit = CASCADE_SPLIT_PRACTICAL;
    s.cascadeLambda = 0.5f;
    s.shadowDistance = 400.0f;
    s.cascadeBounds = bounds;
    s.mapSize = 512;
    s.frameSize = {320, 180};
    s.writePositions = true;
    return s;
}

// What the frame the renderer drew shows: each receiver pixel's view depth along the camera
// (pcfViewDepth of the world position the camera pass wrote) and how many pixels of it `map`'s
// cascades leave past the last (cascadeOfPoint, the camera pass's choice on the CPU).
struct FrameReceivers {
    float lo = std::numeric_limits<float>::infinity();
    float hi = 0.0f;
    int receivers = 0;
    int pastLast = 0;
};

FrameReceivers frameReceivers(const SceneRenderer& renderer, const MapSpec& map) {
    std::vector<float> ls = renderer.readLightSpace();
    std::vector<float> pos = renderer.readPositions();
    const Camera& camera = renderer.scene().camera;
    FrameReceivers f;
    for (size_t k = 0; k < ls.size() / 4; ++k) {
        if (ls[4 * k + 3] != 1.0f) continue;
        glm::vec3 p(pos[4 * k], pos[4 * k + 1], pos[4 * k + 2]);
        float d = pcfViewDepth(p, camera.eyeWs, cameraViewDirWs(camera));
        f.lo = std::min(f.lo, d);
        f.hi = std::max(f.hi, d);
        ++f.receivers;
        if (cascadeOfPoint(map, camera, p) >= static_cast<int>(map.layers.size())) ++f.pastLast;
    }
    return f;
}

// The long-ground preset, as it is (the camera looks along the ground) or with the camera
// looking down at the ground a few units ahead (the farthest receiver it sees is near).
Scene longGround(bool lookDown) {
    Scene scene = *presetScene("long-ground");
    if (lookDown) scene.camera.targetWs = scene.camera.eyeWs + glm::vec3(0.0f, -1.6f, -2.5f);
    return scene;
}

TEST_F(CascadeBounds, DepthBoundsSplitTheVisibleReceiversAndEveryPixelReadsACascade) {
    for (bool lookDown : {false, true}) {
        std::string what = lookDown ? "looking down" : "looking along the ground";
        Scene scene = longGround(lookDown);
        SceneRenderer renderer(scene);
        RenderSettings fixed = farShadowDistance(CASCADE_BOUNDS_FIXED);
        renderer.render(fixed);
        float fixedTexel0 = renderer.mapSpec().layers.front().texelWs;
        EXPECT_FALSE(renderer.mapSpec().visibleDepths.has_value()) << what;

        RenderSettings depth = farShadowDistance(CASCADE_BOUNDS_DEPTH);
        renderer.render(depth);
        MapSpec map = renderer.mapSpec();
        ASSERT_TRUE(map.visibleDepths.has_value()) << what;
        ASSERT_EQ(map.layers.size(), 4u) << what;
        // The prepass measured the receivers the camera pass drew (read from its positions).
        FrameReceivers frame = frameReceivers(renderer, map);
        ASSERT_GT(frame.receivers, 20000) << what;
        EXPECT_NEAR(map.visibleDepths->x, frame.lo, 1e-5f * frame.lo) << what;
        EXPECT_NEAR(map.visibleDepths->y, frame.hi, 1e-5f * frame.hi) << what;
        EXPECT_GT(frame.lo, scene.camera.nearZ * 10.0f) << what;  // the ground starts ahead
        EXPECT_LT(frame.hi, 101.0f) << what;                      // and ends within 100
        // The splits lie within [dmin, dmax], widened by the margin, and follow the formula
        // over the span they cover.
        double n = map.layers.front().viewDepth.x, f = map.layers.back().viewDepth.y;
        EXPECT_GE(n, frame.lo * (1.0 - 2.0 * CASCADE_BOUNDS_MARGIN)) << what;
        EXPECT_LE(n, frame.lo) << what;
        EXPECT_GE(f, frame.hi) << what;
        EXPECT_LE(f, frame.hi * (1.0 + 2.0 * CASCADE_BOUNDS_MARGIN)) << what;
        for (int i = 0; i < 4; ++i) {
            EXPECT_NEAR(map.layers[static_cast<size_t>(i)].viewDepth.y,
                        practicalSplit(n, f, i + 1, 4, 0.5), 1e-5 * f)
                << what << " cascade " << i;
        }
        // render.json's account: [n, f] as the settings name them beside what was measured.
        EXPECT_EQ(map.cascadeDepths, glm::vec2(scene.camera.nearZ, 400.0f)) << what;
        // Cascade 0's texels are smaller than over the fixed [n, f].
        float depthTexel0 = map.layers.front().texelWs;
        std::printf("%s: visible [%.4f, %.4f]; cascade 0 texel %.5f (depth) vs %.5f (fixed)\n",
                    what.c_str(), static_cast<double>(frame.lo), static_cast<double>(frame.hi),
                    static_cast<double>(depthTexel0), static_cast<double>(fixedTexel0));
        EXPECT_LT(depthTexel0, 0.8f * fixedTexel0) << what;
        // Every receiver pixel reads a cascade.
        EXPECT_EQ(frame.pastLast, 0) << what;

        // The same frame with the bounds tightened by a deliberate error (the far one by twice
        // the margin): its deepest receivers fall past the last cascade.
        glm::vec2 tooTight(
            map.visibleDepths->x,
            map.visibleDepths->y * static_cast<float>(1.0 - 2.0 * CASCADE_BOUNDS_MARGIN));
        MapSpec wrong = map;
        wrong.layers = cascadeLayers(scene, depth, frameAspect(depth.frameSize), tooTight);
        EXPECT_GT(frameReceivers(renderer, wrong).pastLast, 0) << what;
    }
}

// The prepass measures the frame the camera pass draws; a lesson's cascades are fitted to a
// camera at one frame shape for every size, which it cannot measure: refused, not fitted fixed.
TEST_F(CascadeBounds, ACascadeCameraOtherThanTheFramesIsRefused) {
    Scene scene = longGround(false);
    SceneRenderer renderer(scene);
    RenderSettings s = farShadowDistance(CASCADE_BOUNDS_DEPTH);
    s.cascadeAspect = 16.0f / 9.0f;
    EXPECT_THROW(renderer.render(s), std::invalid_argument);
    s.cascadeAspect = 0.0f;
    renderer.setCascadeCamera(scene.camera);
    EXPECT_THROW(renderer.render(s), std::invalid_argument);
}

}  // namespace
}  // namespace pcf
