// The rendered shadow falls where the analytic scene says it does, for every preset, and the
// render command behaves as a user expects.
#include "render/scene_renderer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>

#include "image_read.h"
#include "json_lite.h"
#include "kernel/methods.h"
#include "kernel/trace.h"
#include "render/gl_context.h"
#include "render/image_io.h"
#include "run_command.h"
#include "scene/camera.h"
#include "scene/light.h"
#include "scene/presets.h"
#include "scene/raycast.h"
#include "scene/shadow_fit.h"

namespace pcf {
namespace {

class SceneRendererTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> SceneRendererTest::sContext;

struct ShadowAgreement {
    int receivers = 0;    // receiver pixels away from any true shadow edge
    int shadowed = 0;     // of those, truly in shadow
    int missed = 0;       // truly in shadow, rendered lit (visibility > 0.5)
    int falseShadow = 0;  // truly lit, rendered shadowed (visibility < 0.5)
    int darkened = 0;     // truly lit, rendered below 0.99 (any acne, partial included)
};

// The exact answer per pixel: the camera ray through the pixel centre meets the analytic
// surface, and a shadow ray from there tells lit or not (scene/raycast.h). Pixels within `band`
// pixels of a change in that answer are left out (the filter blurs there on purpose).
ShadowAgreement compareWithRayCast(const Scene& scene, const SceneRenderer& r, int band) {
    glm::ivec2 size = r.frameSize();
    std::vector<float> ls = r.readLightSpace();
    std::vector<float> vis = r.readVisibility();
    float aspect = static_cast<float>(size.x) / size.y;
    std::vector<int> truth(static_cast<size_t>(size.x) * size.y, -1);  // -1 no receiver
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            size_t k = static_cast<size_t>(y) * size.x + x;
            if (ls[4 * k + 3] != 1.0f) continue;
            // Readback rows are top-down; pixelCentreNdc counts GL rows from the bottom.
            Ray ray = cameraRay(scene.camera, pixelCentreNdc({x, size.y - 1 - y}, size), aspect);
            std::optional<Hit> hit = intersect(scene, ray);
            if (!hit) continue;
            // Surfaces edge-on to the light or turned away from it are dark by shading, not by
            // a shadow: leave them out.
            glm::vec3 n = hit->frontFace ? hit->normalWs : -hit->normalWs;
            if (glm::dot(n, towardLight(scene.light, hit->posWs).dirWs) < 0.05f) continue;
            truth[k] = litByLight(scene, *hit) ? 0 : 1;
        }
    }
    ShadowAgreement a;
    for (int y = band; y < size.y - band; ++y) {
        for (int x = band; x < size.x - band; ++x) {
            size_t k = static_cast<size_t>(y) * size.x + x;
            if (truth[k] < 0) continue;
            bool uniform = true;
            for (int dy = -band; dy <= band && uniform; ++dy) {
                for (int dx = -band; dx <= band; ++dx) {
                    int t = truth[static_cast<size_t>(y + dy) * size.x + x + dx];
                    if (t != truth[k]) {
                        uniform = false;
                        break;
                    }
                }
            }
            if (!uniform) continue;
            ++a.receivers;
            if (truth[k] == 1) {
                ++a.shadowed;
                if (vis[k] > 0.5f) ++a.missed;
            } else {
                if (vis[k] < 0.5f) ++a.falseShadow;
                if (vis[k] < 0.99f) ++a.darkened;
            }
        }
    }
    return a;
}

TEST_F(SceneRendererTest, EveryPresetShadowsWhereTheRayCastSays) {
    for (std::string_view name : presetNames()) {
        Scene scene = *presetScene(name);
        SceneRenderer renderer(scene);
        RenderSettings s;
        s.frameSize = {640, 360};
        s.mapSize = 1024;
        renderer.render(s);
        ShadowAgreement a = compareWithRayCast(scene, renderer, 2);
        EXPECT_GT(a.receivers, 640 * 360 / 5) << name;
        EXPECT_GT(a.shadowed, a.receivers / 200) << name;  // a real shadow, the pole's is thin
        EXPECT_LE(a.missed, a.shadowed / 100) << name;
        EXPECT_LE(a.falseShadow, a.receivers / 100) << name;
    }
}

// Slope-scaled bias (glPolygonOffset in the shadow pass) cures the acne of a grazing light that
// no bias at all leaves on the lit ground.
TEST_F(SceneRendererTest, PolygonOffsetCuresGrazingAcne) {
    Scene scene = *presetScene("grazing");
    SceneRenderer renderer(scene);
    RenderSettings s;
    s.frameSize = {480, 270};
    s.mapSize = 512;
    s.bias = BiasMode::None;
    renderer.render(s);
    ShadowAgreement acne = compareWithRayCast(scene, renderer, 2);
    s.polygonOffset = {2.0f, 4.0f};
    renderer.render(s);
    ShadowAgreement cured = compareWithRayCast(scene, renderer, 2);
    EXPECT_GT(acne.falseShadow, acne.receivers / 20) << "no bias should show acne";
    EXPECT_LT(cured.falseShadow, acne.falseShadow / 10);
    EXPECT_LE(cured.missed, cured.shadowed / 50);  // the real shadow is still there
}

// On grazing with pcf-gather 5x5 and a small constant, the constant alone leaves acne; the
// receiver plane (per gather), the slope-scaled and the normal-offset biases cure nearly all of
// it, and the real shadow stays. (The soft comparison does not: it only ramps the test's edge.)
TEST_F(SceneRendererTest, BiasModesCureTheAcneASmallConstantLeaves) {
    Scene scene = *presetScene("grazing");
    SceneRenderer renderer(scene);
    RenderSettings s;
    s.frameSize = {480, 270};
    s.mapSize = 512;
    s.method = PCF_GATHER;
    s.kernel = 5;
    s.constantBias = 0.002f;
    std::map<BiasMode, ShadowAgreement> got;
    for (BiasMode mode : {BiasMode::None, BiasMode::Constant, BiasMode::Slope, BiasMode::Normal,
                          BiasMode::ReceiverPlane, BiasMode::Soft}) {
        s.bias = mode;
        renderer.render(s);
        got[mode] = compareWithRayCast(scene, renderer, 3);
        std::printf("grazing pcf-gather 5x5 map 512, bias %s: darkened %d of %d, missed %d of %d\n",
                    std::string(biasModeName(mode)).c_str(), got[mode].darkened,
                    got[mode].receivers, got[mode].missed, got[mode].shadowed);
    }
    const ShadowAgreement& constant = got[BiasMode::Constant];
    EXPECT_GT(constant.darkened, constant.receivers / 50) << "the constant alone leaves acne";
    EXPECT_GE(got[BiasMode::None].darkened, constant.darkened);
    for (BiasMode mode : {BiasMode::Slope, BiasMode::Normal, BiasMode::ReceiverPlane}) {
        EXPECT_LT(got[mode].darkened, constant.darkened / 10) << biasModeName(mode);
        EXPECT_LE(got[mode].missed, got[mode].shadowed / 50) << biasModeName(mode);
    }
}

// The receiver target holds the plane the shader derived: on the flat ground of grazing, dz/du
// and dz/dv equal the analytic ones (three ground points projected into the map).
TEST_F(SceneRendererTest, ReceiverTargetHoldsTheGroundsPlaneInTheMap) {
    Scene scene = *presetScene("grazing");
    SceneRenderer renderer(scene);
    RenderSettings s;
    s.frameSize = {320, 180};
    s.writePositions = true;
    s.bias = BiasMode::ReceiverPlane;
    renderer.render(s);
    glm::mat4 m = renderer.shadowClipFromWorld();
    ShadowCoord a = shadowCoord(m, {0.0f, 0.0f, 0.0f});
    ShadowCoord b = shadowCoord(m, {1.0f, 0.0f, 0.0f});
    ShadowCoord c = shadowCoord(m, {0.0f, 0.0f, 1.0f});
    // z = z0 + g . (uv - uv0) through the three points: solve the 2x2 system for g.
    glm::mat2 duv(b.uvSm - a.uvSm, c.uvSm - a.uvSm);  // columns
    glm::vec2 dz(b.depth - a.depth, c.depth - a.depth);
    glm::vec2 g = glm::inverse(glm::transpose(duv)) * dz;
    std::vector<float> rc = renderer.readReceiver();
    std::vector<float> pos = renderer.readPositions();
    int ground = 0;
    int close = 0;
    for (size_t k = 0; k < rc.size() / 4; ++k) {
        if (rc[4 * k + 3] != 1.0f || std::fabs(pos[4 * k + 1]) > 1e-4f) continue;
        ++ground;
        glm::vec2 got(rc[4 * k], rc[4 * k + 1]);
        if (glm::length(got - g) <= 0.01f * glm::length(g)) ++close;
    }
    EXPECT_GT(ground, 320 * 180 / 3);
    EXPECT_GT(close, ground * 98 / 100) << "analytic dz/duv " << g.x << ", " << g.y;
}

// The position target holds each pixel's world point: projected back with the camera, it lands
// in that pixel.
TEST_F(SceneRendererTest, PositionsProjectBackToTheirPixels) {
    Scene scene = *presetScene("sphere-over-plane");
    SceneRenderer renderer(scene);
    RenderSettings s;
    s.frameSize = {320, 180};
    s.writePositions = true;
    renderer.render(s);
    std::vector<float> pos = renderer.readPositions();
    glm::mat4 clip = renderer.clipFromWorld();
    int drawn = 0;
    for (int y = 0; y < 180; y += 7) {
        for (int x = 0; x < 320; x += 7) {
            size_t k = (static_cast<size_t>(y) * 320 + x) * 4;
            if (pos[k + 3] != 1.0f) continue;
            ++drawn;
            glm::vec4 c = clip * glm::vec4(pos[k], pos[k + 1], pos[k + 2], 1.0f);
            glm::vec2 ndc = glm::vec2(c) / c.w;
            glm::vec2 px((ndc.x * 0.5f + 0.5f) * 320.0f, (0.5f - ndc.y * 0.5f) * 180.0f);
            EXPECT_NEAR(px.x, x + 0.5f, 0.01f);
            EXPECT_NEAR(px.y, y + 0.5f, 0.01f);
        }
    }
    EXPECT_GT(drawn, 500);
}

// Each depth format renders the same shadow (to the precision of the format).
TEST_F(SceneRendererTest, DepthFormatsAgree) {
    Scene scene = *presetScene("box-on-plane");
    SceneRenderer renderer(scene);
    RenderSettings s;
    s.frameSize = {320, 180};
    s.mapSize = 512;
    std::vector<float> reference;
    for (TexelKind f : {TexelKind::D32F, TexelKind::D24, TexelKind::D16}) {
        s.depthFormat = f;
        renderer.render(s);
        // The format is applied: a 16-bit map holds only k / 65535, a float map other depths.
        int offGrid = 0;
        ShadowMap map = renderer.readShadowMap();
        for (float d : map.depths()) {
            float k = d * 65535.0f;
            offGrid += std::fabs(k - std::round(k)) > 0.01f;
        }
        if (f == TexelKind::D16) {
            EXPECT_EQ(offGrid, 0);
        }
        if (f == TexelKind::D32F) {
            EXPECT_GT(offGrid, 0);
        }
        std::vector<float> vis = renderer.readVisibility();
        if (reference.empty()) {
            reference = vis;
            continue;
        }
        int differ = 0;
        for (size_t k = 0; k < vis.size(); ++k) differ += std::fabs(vis[k] - reference[k]) > 0.5f;
        EXPECT_LT(differ, static_cast<int>(vis.size()) / 500) << depthFormatName(f);
    }
}

// The depth pass makes the map as a value: its size and texel kind are the settings', its one
// layer the fit it was drawn with (a spot's perspective depth range with it), and the map read
// back carries the same value.
TEST_F(SceneRendererTest, TheDepthPassSaysWhatTheMapHolds) {
    for (const char* preset : {"box-on-plane", "post-under-spot"}) {
        Scene scene = *presetScene(preset);
        SceneRenderer renderer(scene);
        RenderSettings s;
        s.frameSize = {64, 36};
        s.mapSize = 96;
        s.depthFormat = TexelKind::D24;
        glm::mat4 fit = shiftShadowOrigin(shadowClipFromWorld(scene), glm::vec2(0.25f), 96, false);
        renderer.setShadowClipFromWorld(fit);
        renderer.render(s);
        const MapSpec& map = renderer.mapSpec();
        EXPECT_EQ(map.size, glm::ivec2(96));
        EXPECT_EQ(map.texels, TexelKind::D24);
        ASSERT_EQ(map.layers.size(), 1u);
        EXPECT_EQ(map.layers[0].shadowClipFromWorld, fit) << preset;
        EXPECT_EQ(map.layers[0].texelWs, shadowTexelWs(scene, 96)) << preset;
        bool spot = scene.light.type == LightType::Spot;
        EXPECT_EQ(map.layers[0].depthRange.x > 0.0f, spot) << preset;
        if (spot) {
            EXPECT_GT(map.layers[0].depthRange.y, map.layers[0].depthRange.x);
        }
        ShadowMap read = renderer.readShadowMap();
        EXPECT_EQ(read.spec(), map) << preset;
        EXPECT_EQ(read.fixedPointBits(), 24);
        // A trace of it carries the value whole.
        EXPECT_EQ(traceLookup(read, glm::vec2(0.5f), 0.5f, 0.5f, s.pcfParams()).map, map);
    }
}

class RenderCommand : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("render"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    std::filesystem::path mDir;
};

TEST_F(RenderCommand, WritesThePngAndRefusesToOverwriteIt) {
    auto r = testutil::runPcfscope(
        "render --scene box-on-plane --method pcf-gather --size 160x90 -o " + path("shadow.png"),
        "env -u DISPLAY");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ImageSize size = readImageSize(path("shadow.png"));
    EXPECT_EQ(size.width, 160);
    EXPECT_EQ(size.height, 90);
    auto again =
        testutil::runPcfscope("render --scene box-on-plane --size 160x90 -o " + path("shadow.png"));
    EXPECT_EQ(again.exitCode, 2);
    EXPECT_NE(again.err.find("already exists"), std::string::npos) << again.err;
    auto forced = testutil::runPcfscope("render --scene box-on-plane --size 160x90 -f -o " +
                                        path("shadow.png"));
    EXPECT_EQ(forced.exitCode, 0) << forced.err;
}

TEST_F(RenderCommand, BadInputExitsTwoWithOneLineAndWritesNothing) {
    struct Case {
        std::string args;
        std::string expect;
    };
    std::vector<Case> cases = {
        {"--scene no-such-scene", "unknown scene 'no-such-scene'"},
        {"--scene box-on-plane --size 0x10", "--size"},
        {"--scene box-on-plane --size 12", "--size"},
        {"--scene box-on-plane --size 99999x10", "--size"},
        {"--scene box-on-plane --method blur", "unknown method 'blur'"},
        {"--scene box-on-plane --method tent --kernel 2", "tent takes"},
        {"--scene box-on-plane --map-size 3", "--map-size must be 4..4096, got 3"},
        {"--scene box-on-plane --map-size 5000", "--map-size must be 4..4096, got 5000"},
        {"--scene box-on-plane --bias fancy", "unknown bias mode"},
        {"--scene box-on-plane --depth-format 8", "--depth-format"},
        {"--scene-file " + path("missing.toml"), "missing.toml"},
        {"", "needs --scene"},
    };
    for (const Case& c : cases) {
        auto r = testutil::runPcfscope("render " + c.args + " -o " + path("out.png") + " --raw " +
                                       path("raw"));
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(path("out.png"))) << c.args;
        EXPECT_FALSE(std::filesystem::exists(path("raw"))) << c.args;
    }
}

// --raw writes the map, the light-space target and the visibility; `trace --map` on that map at
// a pixel's (u, v, ref) gives that pixel's visibility: the inspector and the picture agree.
TEST_F(RenderCommand, RawFilesFeedTraceAndAgreeWithThePicture) {
    auto r = testutil::runPcfscope(
        "render --scene sphere-over-plane --method tent --kernel 5 "
        "--map-size 256 --size 200x120 --raw " +
        path("raw"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ShadowMap map = readDepthImage(path("raw/shadowmap.exr"));
    EXPECT_EQ(map.size(), glm::ivec2(256, 256));
    std::vector<float> ls = readImageFloats(path("raw/lightspace.exr"), 4);
    std::vector<float> vis = readImageFloats(path("raw/visibility.exr"), 1);
    ASSERT_EQ(ls.size(), 200u * 120u * 4u);
    ASSERT_EQ(vis.size(), 200u * 120u);
    // Pick pixels in shadow, in light and in the penumbra.
    std::vector<size_t> picks;
    for (size_t k = 0; k < vis.size() && picks.size() < 9; k += 7) {
        if (ls[4 * k + 3] != 1.0f) continue;
        bool penumbra = vis[k] > 0.05f && vis[k] < 0.95f;
        if (penumbra || picks.size() < 3 || (vis[k] == 0.0f && picks.size() < 6))
            picks.push_back(k);
    }
    ASSERT_GE(picks.size(), 6u);
    int penumbra = 0;
    for (size_t k : picks) {
        char args[256];
        // The light-space target holds ref (after the render's bias): trace it with no bias.
        std::snprintf(args, sizeof args, "--uv %.9g,%.9g --z %.9g", ls[4 * k], ls[4 * k + 1],
                      ls[4 * k + 2]);
        auto t = testutil::runPcfscope("trace --map " + path("raw/shadowmap.exr") + " " + args +
                                       " --method tent --kernel 5 --json");
        ASSERT_EQ(t.exitCode, 0) << t.err;
        jsonlite::Value j = jsonlite::parse(t.out);
        EXPECT_NEAR(j["visibility"].number, vis[k], 1e-5) << args;
        penumbra += vis[k] > 0.05f && vis[k] < 0.95f;
    }
    EXPECT_GE(penumbra, 1);
}

}  // namespace
}  // namespace pcf
