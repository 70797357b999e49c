// Cascaded maps on the GPU equal the CPU kernel (docs/architecture.md, "One kernel for the CPU
// and the GPU"): the depth pass draws each cascade into its layer of an array texture, the camera
// pass picks a layer per receiver by its view depth, and the CPU, given the GPU's own targets
// (the receiver's world position, u, v, ref and receiver plane), picks the same layer and gives
// the same visibility, for every method, both fits, and the bias modes whose size is a texel's.
// Runs on llvmpipe through EGL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "kernel/cascades.h"
#include "kernel/methods.h"
#include "kernel/pcf.h"
#include "kernel/shading.h"
#include "render/gl_context.h"
#include "render/scene_renderer.h"
#include "scene/cascade_fit.h"

namespace pcf {
namespace {

constexpr float PARITY_TOLERANCE = 1e-5f;

class CascadeParity : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> CascadeParity::sContext;

// A ground 100 units long with a post every 8 units along it, a low sun from the side, and the
// camera near the ground looking along it: every cascade has posts' shadows to agree about.
Scene postsAlongGround() {
    Scene scene;
    scene.name = "posts along the ground";
    scene.light.directionWs = glm::normalize(glm::vec3(0.8f, -1.0f, 0.2f));
    scene.objects.push_back(
        {"ground", *makePlane(glm::vec3(0.0f, 0.0f, -48.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                              glm::vec2(24.0f, 104.0f))});
    for (int k = 0; k < 12; ++k) {
        float z = -2.0f - 8.0f * static_cast<float>(k);
        scene.objects.push_back({"post" + std::to_string(k),
                                 Box{glm::vec3(-1.5f, 1.0f, z), glm::vec3(0.25f, 1.0f, 0.25f)}});
    }
    scene.camera.eyeWs = glm::vec3(0.5f, 1.6f, 4.0f);
    scene.camera.targetWs = glm::vec3(-0.5f, 0.2f, -20.0f);
    fitCameraPlanes(scene.camera, sceneBounds(scene));
    return scene;
}

struct CascadeAgreement {
    float worst = 0.0f;
    int receivers = 0;
    int shadowed = 0;
    int beyond = 0;  // receivers past the last cascade (lit, on both sides)
    std::vector<int> perLayer = std::vector<int>(MAX_CASCADES, 0);
};

// One frame's GPU targets, read back (scene_renderer.h): what the CPU is held to, per pixel k.
struct FrameTargets {
    ShadowMap map;
    std::vector<float> lightSpace, receiver, nextReceiver, positions, normals, visibility;
    bool isReceiver(size_t k) const { return lightSpace[4 * k + 3] == 1.0f; }
    glm::vec2 uv(size_t k) const { return {lightSpace[4 * k], lightSpace[4 * k + 1]}; }
    float ref(size_t k) const { return lightSpace[4 * k + 2]; }
    glm::vec2 dzduv(size_t k) const { return {receiver[4 * k], receiver[4 * k + 1]}; }
    glm::vec2 nextDzduv(size_t k) const { return {nextReceiver[4 * k], nextReceiver[4 * k + 1]}; }
    glm::vec3 position(size_t k) const {
        return {positions[4 * k], positions[4 * k + 1], positions[4 * k + 2]};
    }
    glm::vec3 normal(size_t k) const {
        return {normals[4 * k], normals[4 * k + 1], normals[4 * k + 2]};
    }
    float cosTheta(size_t k) const { return normals[4 * k + 3]; }
};

// Renders `s` with every target and reads them back.
FrameTargets renderTargets(SceneRenderer& renderer, RenderSettings s) {
    s.writePositions = true;
    renderer.render(s);
    return {renderer.readShadowMap(),    renderer.readLightSpace(), renderer.readReceiver(),
            renderer.readNextReceiver(), renderer.readPositions(),  renderer.readNormals(),
            renderer.readVisibility()};
}

// Renders `s` and runs the CPU kernel on the GPU's own targets, each receiver on the layer the
// CPU picks for its world position.
CascadeAgreement renderAndCompare(SceneRenderer& renderer, const Scene& scene, RenderSettings s) {
    FrameTargets t = renderTargets(renderer, s);
    CascadeAgreement a;
    for (size_t k = 0; k < t.visibility.size(); ++k) {
        if (!t.isReceiver(k)) continue;
        ++a.receivers;
        int layer = cascadeOfPoint(t.map.spec(), scene.camera, t.position(k));
        float cpu = 1.0f;
        if (layer < t.map.layers()) {
            ++a.perLayer[static_cast<size_t>(layer)];
            cpu = filterLayerVisibility(t.map, layer, t.uv(k), t.ref(k), renderer.pcfParams(s),
                                        s.kernelBias(t.dzduv(k)));
        } else {
            ++a.beyond;
        }
        a.shadowed += t.visibility[k] < 0.5f ? 1 : 0;
        a.worst = std::max(a.worst, std::fabs(cpu - t.visibility[k]));
    }
    return a;
}

RenderSettings cascaded(int method, int kernel, int fit, bool snap) {
    RenderSettings s;
    s.method = method;
    s.kernel = kernel;
    s.cascades = 4;
    s.cascadeSplit = CASCADE_SPLIT_PRACTICAL;
    s.cascadeLambda = 0.7f;
    s.shadowDistance = 60.0f;
    s.cascadeFit = fit;
    s.cascadeSnap = snap;
    s.mapSize = 256;
    s.frameSize = {240, 136};
    return s;
}

void expectAgreement(const CascadeAgreement& a, const RenderSettings& s, const std::string& what) {
    EXPECT_LE(a.worst, PARITY_TOLERANCE) << what;
    EXPECT_GT(a.receivers, s.frameSize.x * s.frameSize.y / 4) << what;
    EXPECT_GT(a.shadowed, 100) << what;  // there are shadows to agree about
    for (int layer = 0; layer < s.cascades; ++layer) {
        EXPECT_GT(a.perLayer[static_cast<size_t>(layer)], 200) << what << " layer " << layer;
    }
    EXPECT_GT(a.beyond, 50) << what;  // the ground runs past the shadow distance
}

TEST_F(CascadeParity, EveryMethodOnEveryCascadeMatchesTheCpuKernel) {
    Scene scene = postsAlongGround();
    SceneRenderer renderer(scene);
    float worst = 0.0f;
    for (const MethodInfo& m : allMethods()) {
        // Refused with cascades (cascadeProblem): pcss, and the methods that read a moments map.
        if (m.searchesBlockers || !texelKindInfo(mapTexelKind(m.id, TexelKind::D32F, 32)).depth) {
            continue;
        }
        int kernel = m.kernelSizes.empty() ? 3 : m.kernelSizes.front();
        for (int fit : {CASCADE_FIT_BOX, CASCADE_FIT_SPHERE}) {
            RenderSettings s = cascaded(m.id, kernel, fit, fit == CASCADE_FIT_SPHERE);
            CascadeAgreement a = renderAndCompare(renderer, scene, s);
            expectAgreement(a, s, std::string(m.name) + " fit " + std::string(cascadeFitName(fit)));
            worst = std::max(worst, a.worst);
        }
    }
    std::printf("cascade parity, every method, box and sphere: max |GPU - CPU| = %g\n",
                static_cast<double>(worst));
}

// Normal offset moves each receiver by texels of its own cascade (the layer's texelWs), and the
// receiver plane is the chosen layer's: both agree with the CPU per cascade.
TEST_F(CascadeParity, TexelSizedBiasesScalePerCascade) {
    Scene scene = postsAlongGround();
    SceneRenderer renderer(scene);
    for (BiasMode mode : {BiasMode::Normal, BiasMode::ReceiverPlane, BiasMode::Slope}) {
        for (int method : {PCF_GATHER, PCF_NAIVE, PCF_HW2X2}) {
            RenderSettings s = cascaded(method, 3, CASCADE_FIT_SPHERE, true);
            s.bias = mode;
            s.normalOffset = 1.5f;
            CascadeAgreement a = renderAndCompare(renderer, scene, s);
            expectAgreement(
                a, s, std::string(biasModeName(mode)) + " " + std::string(methodInfo(method).name));
        }
    }
    // The layers' texel sizes grow from cascade to cascade, so the same K texels of normal
    // offset move a far receiver further than a near one.
    RenderSettings s = cascaded(PCF_GATHER, 3, CASCADE_FIT_SPHERE, true);
    renderer.render(s);
    const MapSpec& map = renderer.mapSpec();
    ASSERT_EQ(map.layers.size(), 4u);
    for (size_t k = 1; k < 4; ++k) EXPECT_GT(map.layers[k].texelWs, map.layers[k - 1].texelWs);
}

// The next cascade's lookup in the blend band cannot be read back from the GPU (its targets hold
// the first lookup's u, v and ref), so the CPU recomputes it from the GPU's world position; the
// GPU's matrix product may round u, v by about 1e-7 otherwise than the CPU's, which a hardware
// tap (a texel's bits lerped by the position) turns into up to mapSize * 1e-7 of visibility.
constexpr float RECOMPUTED_LOOKUP_SLACK = 3e-5f;

struct BlendAgreement {
    float worst = 0.0f;            // beyond PARITY_TOLERANCE + weight * RECOMPUTED_LOOKUP_SLACK
    float worstOutside = 0.0f;     // receivers outside the band: |GPU - CPU|
    float worstRecomputed = 0.0f;  // cascadeVisibilityAt, every lookup from the world position
    int inBand = 0;                // receivers the band blends (weight in (0, 1])
    int seamVisible = 0;           // of those, the ones whose two cascades disagree by over 0.01
};

// A blended frame: the CPU looks each receiver up in its cascade (the GPU's own u, v, ref and
// receiver plane, as renderAndCompare) and, in the band, in the next (cascadeVisibilityAt, from
// the GPU's world position, normal and receiver plane in the next cascade), and mixes them by
// the shared weight.
BlendAgreement renderBlendedAndCompare(SceneRenderer& renderer, const Scene& scene,
                                       RenderSettings s) {
    FrameTargets t = renderTargets(renderer, s);
    BlendAgreement a;
    for (size_t k = 0; k < t.visibility.size(); ++k) {
        if (!t.isReceiver(k)) continue;
        CascadeLookup c =
            cascadeVisibilityAt(t.map, scene.camera, s, renderer.pcfParams(s), t.position(k),
                                t.normal(k), t.cosTheta(k), t.dzduv(k), t.nextDzduv(k));
        float cpu = 1.0f;
        if (c.layer < t.map.layers()) {
            float own = filterLayerVisibility(t.map, c.layer, t.uv(k), t.ref(k),
                                              renderer.pcfParams(s), s.kernelBias(t.dzduv(k)));
            cpu = pcfCascadeBlend(own, c.nextVisibility, c.weight);
        }
        float diff = std::fabs(cpu - t.visibility[k]);
        if (c.weight > 0.0f) {
            ++a.inBand;
            a.seamVisible += std::fabs(c.visibility - c.nextVisibility) > 0.01f ? 1 : 0;
            a.worst = std::max(a.worst, diff - c.weight * RECOMPUTED_LOOKUP_SLACK);
        } else {
            a.worstOutside = std::max(a.worstOutside, diff);
            a.worst = std::max(a.worst, diff);
        }
        a.worstRecomputed = std::max(a.worstRecomputed, std::fabs(c.blended - t.visibility[k]));
    }
    return a;
}

// With a blend band the GPU filters the next cascade too where the band says so, and mixes the
// two by the shared weight: the CPU gives the same, for every method and bias mode (receiver-plane
// bias filters the next cascade with the receiver's plane there, the GPU's own derivative, which
// the next receiver target holds).
TEST_F(CascadeParity, BlendedCascadesMatchTheCpuKernel) {
    Scene scene = postsAlongGround();
    SceneRenderer renderer(scene);
    float worst = 0.0f, worstOutside = 0.0f, worstRecomputed = 0.0f;
    int seamVisible = 0;
    for (int method : {PCF_GATHER, PCF_NAIVE, PCF_HW2X2, PCF_TENT, PCF_POISSON, PCF_NEAREST}) {
        for (BiasMode mode :
             {BiasMode::Constant, BiasMode::Normal, BiasMode::Slope, BiasMode::ReceiverPlane}) {
            RenderSettings s = cascaded(method, 3, CASCADE_FIT_SPHERE, true);
            s.bias = mode;
            s.cascadeBlend = 0.3f;
            BlendAgreement a = renderBlendedAndCompare(renderer, scene, s);
            std::string what =
                std::string(methodInfo(method).name) + " " + std::string(biasModeName(mode));
            EXPECT_LE(a.worst, PARITY_TOLERANCE) << what;
            EXPECT_LE(a.worstOutside, PARITY_TOLERANCE) << what;
            EXPECT_LE(a.worstRecomputed, PARITY_TOLERANCE + RECOMPUTED_LOOKUP_SLACK) << what;
            EXPECT_GT(a.inBand, 1000) << what;  // a band at every split but the last
            worst = std::max(worst, a.worst);
            worstOutside = std::max(worstOutside, a.worstOutside);
            worstRecomputed = std::max(worstRecomputed, a.worstRecomputed);
            seamVisible += a.seamVisible;
        }
    }
    // The band changes the picture: in it the two cascades disagree.
    EXPECT_GT(seamVisible, 200);
    std::printf(
        "cascade parity, blended: outside the band max |GPU - CPU| = %g; in it %g beyond the "
        "recomputed lookup's slack; all recomputed %g; %d band receivers the blend changes\n",
        static_cast<double>(worstOutside), static_cast<double>(worst),
        static_cast<double>(worstRecomputed), seamVisible);
}

// Without a band no receiver reads a second cascade, and the frame is the unblended one.
TEST_F(CascadeParity, NoBandBlendsNothing) {
    Scene scene = postsAlongGround();
    SceneRenderer renderer(scene);
    RenderSettings s = cascaded(PCF_GATHER, 3, CASCADE_FIT_BOX, false);
    BlendAgreement a = renderBlendedAndCompare(renderer, scene, s);
    EXPECT_EQ(a.inBand, 0);
    EXPECT_LE(a.worstOutside, PARITY_TOLERANCE);
}

}  // namespace
}  // namespace pcf
