// Snapped cascades move by whole texels, and so their maps do, bit for bit (scene/cascade_fit.h
// snappedClip, shaders/depth_snapped.*): along the cascades sweep's turning path
// (measure/stability_cascades.h) every texel two steps share holds the same float, so that with
// the sphere fit no static receiver's filtered visibility changes. Runs on llvmpipe through EGL,
// at the sweep's full size (a 512 map, 480x270, 8 steps), where the fixed-function pass, which
// clips each triangle at the map's moving edges, changed a few edge texels per step. And the
// snapped pass, which writes its own depth, applies a polygon offset as the fixed-function one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "kernel/cascades.h"
#include "kernel/methods.h"
#include "measure/stability_cascades.h"
#include "render/gl_context.h"
#include "render/scene_renderer.h"

namespace pcf {
namespace {

class CascadeSnap : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> CascadeSnap::sContext;

StabilityOptions fullSizeOptions() {
    StabilityOptions o;  // the defaults: 480x270, a 512 map, 8 steps
    o.sweeps = {Sweep::Cascades};
    return o;
}

RenderSettings snappedSphere(float lambda) {
    StabilityOptions o = fullSizeOptions();
    RenderSettings s = o.base;
    s.method = PCF_GATHER;
    s.kernel = 5;
    s.bias = BiasMode::Normal;
    s.cascades = CASCADE_SWEEP_CASCADES;
    s.shadowDistance = CASCADE_SWEEP_DISTANCE;
    s.cascadeSplit = CASCADE_SPLIT_PRACTICAL;
    s.cascadeLambda = lambda;
    s.cascadeFit = CASCADE_FIT_SPHERE;
    s.cascadeSnap = true;
    s.mapSize = o.mapSize;
    s.frameSize = o.frameSize;
    return s;
}

// Where the world origin lands in a layer, in texels from the map's corner.
glm::dvec2 originTexels(const glm::mat4& clip, int size) {
    glm::vec4 o = clip * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    return (glm::dvec2(o.x, o.y) / static_cast<double>(o.w) + 1.0) * (size / 2.0);
}

// Texels of layer c of `b` that differ from the same world texel of `a` (moved by `offset`).
int changedTexels(const ShadowMap& a, const ShadowMap& b, int c, glm::ivec2 offset, int& shared) {
    int size = a.width(), changed = 0;
    const float* ta = a.layerTexels(c);
    const float* tb = b.layerTexels(c);
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            glm::ivec2 to = glm::ivec2(i, j) + offset;
            if (to.x < 0 || to.y < 0 || to.x >= size || to.y >= size) continue;
            ++shared;
            changed += ta[j * size + i] != tb[to.y * size + to.x] ? 1 : 0;
        }
    }
    return changed;
}

// At every step of the path each layer's world origin lies on a whole texel, its texel size and
// rows are the same floats, and its map is the last step's moved by the whole texels the origin
// moved: not one texel of the ones they share differs, not even by a float's last bit.
TEST_F(CascadeSnap, TheMapMovesByWholeTexelsBitForBit) {
    Scene scene = cascadeSweepScene();
    SceneRenderer renderer(scene);
    int steps = fullSizeOptions().cascadePathSteps;
    for (float lambda : {0.5f, 1.0f}) {
        RenderSettings s = snappedSphere(lambda);
        std::vector<ShadowMap> maps;
        for (int step = 0; step < steps; ++step) {
            renderer.setCamera(cascadePathCamera(scene.camera, step, steps));
            renderer.renderShadowPass(s);
            maps.push_back(renderer.readShadowMap());
        }
        for (int c = 0; c < CASCADE_SWEEP_CASCADES; ++c) {
            int changed = 0, shared = 0;
            for (int step = 1; step < steps; ++step) {
                const PcfMapLayer& was = maps[step - 1].spec().layers[c];
                const PcfMapLayer& now = maps[step].spec().layers[c];
                EXPECT_EQ(now.texelWs, was.texelWs) << "lambda " << lambda << " cascade " << c;
                glm::dvec2 from = originTexels(was.shadowClipFromWorld, s.mapSize);
                glm::dvec2 to = originTexels(now.shadowClipFromWorld, s.mapSize);
                EXPECT_EQ(from, glm::round(from));
                EXPECT_EQ(to, glm::round(to));
                glm::ivec2 offset(glm::round(to - from));
                changed += changedTexels(maps[step - 1], maps[step], c, offset, shared);
            }
            EXPECT_GT(shared, s.mapSize * s.mapSize);  // the steps share most of the map
            EXPECT_EQ(changed, 0) << "lambda " << lambda << " cascade " << c << ", of " << shared;
            std::printf("lambda %g cascade %d: %d of %d shared texels changed\n",
                        static_cast<double>(lambda), c, changed, shared);
        }
    }
}

// The sweep at its full size, on the log split, where the fixed-function pass made 1.3 % of
// cascade 3's static receivers flicker (pcf-gather 5x5), and where nearest flickered at one
// receiver of cascade 2 lying 1.5e-5 texel from a texel's edge until the lookup's clip
// coordinates were made exact (pcfLightClip): sphere and snap flicker in no cascade, for either.
TEST_F(CascadeSnap, SphereAndSnapNeverFlickerAtTheFullSize) {
    StabilityOptions o = fullSizeOptions();
    o.methods = {{PCF_GATHER, 5}, {PCF_NEAREST, 0}};
    o.cascadeLambdas = {1.0f};
    ASSERT_FALSE(validateStabilityOptions(o));
    std::vector<StabilityRow> rows;
    runCascadeSweep(o, {}, rows);
    int checked = 0;
    for (const CascadePoint& p : cascadePoints(rows)) {
        if (p.fit != "sphere" || !p.snap) continue;
        EXPECT_EQ(p.texelWorldMin, p.texelWorldMax) << "cascade " << p.cascade;
        EXPECT_EQ(p.flickerRate, 0.0)
            << p.method << " cascade " << p.cascade << " of " << p.staticReceivers;
        checked += p.staticReceivers > 100.0 ? 1 : 0;
        std::printf("cascade %d: flicker %g of %g receivers\n", p.cascade, p.flickerRate,
                    p.staticReceivers);
    }
    // the log split's cascades 2 and 3 hold the receivers on screen, for each method
    EXPECT_EQ(checked, 4);
}

}  // namespace
}  // namespace pcf

namespace pcf {
namespace {

// How far a polygon offset pushed layer c's depths back, against factor * m + units * r
// (GL 4.5, 14.6.5), m measured from the map without offset: the larger of a texel's depth steps to
// its right and upper neighbours, where those and the left and lower ones lie on one plane; r of
// a float depth is 2^(E - 23), E the exponent of the triangle's largest depth, so between the
// texel's own depth's and 1's. Counts the texels checked and those pushed by more than 5e-7
// outside that (where the offset lets another surface win the depth test, at a caster's edge).
struct OffsetCheck {
    int texels = 0;
    int off = 0;
};
OffsetCheck offsetAgainstSlope(const ShadowMap& plain, const ShadowMap& pushed, int c,
                               glm::vec2 offset) {
    OffsetCheck out;
    int size = plain.width();
    const float* d = plain.layerTexels(c);
    const float* e = pushed.layerTexels(c);
    for (int j = 1; j + 1 < size; ++j) {
        for (int i = 1; i + 1 < size; ++i) {
            auto at = [&](int x, int y) { return static_cast<double>(d[y * size + x]); };
            double dx = at(i + 1, j) - at(i, j), dy = at(i, j + 1) - at(i, j);
            bool plane = std::fabs(at(i, j) - at(i - 1, j) - dx) < 1e-6 &&
                         std::fabs(at(i, j) - at(i, j - 1) - dy) < 1e-6 && at(i + 1, j + 1) < 1.0;
            if (!plane) continue;
            int exponent = 0;
            std::frexp(at(i, j), &exponent);
            double slope = offset.x * std::max(std::fabs(dx), std::fabs(dy));
            double lo = slope + offset.y * std::ldexp(1.0, exponent - 24);
            double hi = slope + offset.y * std::ldexp(1.0, -24);
            double got = static_cast<double>(e[j * size + i]) - at(i, j);
            out.off += got < lo - 5e-7 || got > hi + 5e-7 ? 1 : 0;
            ++out.texels;
        }
    }
    return out;
}

// gl_FragDepth bypasses glPolygonOffset, so the snapped pass adds it itself: a slope-scaled offset
// and a constant one (64 units: 64 r is above the check's 5e-7) push the snapped map's depths back
// as the fixed-function pass pushes the free sphere's, by factor * m + units * r.
TEST_F(CascadeSnap, APolygonOffsetPushesTheSnappedMapBackAsTheFixedPassDoes) {
    Scene scene = cascadeSweepScene();
    SceneRenderer renderer(scene);
    for (bool snap : {true, false}) {
        RenderSettings s = snappedSphere(0.5f);
        s.cascadeSnap = snap;
        renderer.renderShadowPass(s);
        ShadowMap plain = renderer.readShadowMap();
        for (glm::vec2 offset : {glm::vec2(2.0f, 0.0f), glm::vec2(0.0f, 64.0f)}) {
            s.polygonOffset = offset;
            renderer.renderShadowPass(s);
            ShadowMap pushed = renderer.readShadowMap();
            for (int c = 0; c < CASCADE_SWEEP_CASCADES; ++c) {
                OffsetCheck check = offsetAgainstSlope(plain, pushed, c, offset);
                EXPECT_GT(check.texels, 50000) << snap << " cascade " << c;
                EXPECT_LE(check.off, check.texels / 1000) << snap << " cascade " << c;
                std::printf("%s, offset %g %g, cascade %d: %d of %d texels pushed otherwise\n",
                            snap ? "snapped" : "free", static_cast<double>(offset.x),
                            static_cast<double>(offset.y), c, check.off, check.texels);
            }
        }
    }
}

}  // namespace
}  // namespace pcf
