// lesson_pick.h: a lesson's scene point is seen where it is, lands on the centre of the pixel
// derived for every frame size once the camera is jittered, and is looked up with the camera
// pass's own formulas. (tests/lesson_pixels_test.cpp renders it: the GPU shows that lookup.)
#include "lesson/lesson_pick.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "json_lite.h"
#include "render/scene_renderer.h"
#include "run_command.h"
#include "scene/presets.h"
#include "virtual_display.h"

namespace pcf {
namespace {

Scene boxOnPlane() { return *presetScene("box-on-plane"); }

TEST(LessonPick, APointOnTheGroundIsSeenAHiddenOrFloatingOneIsNot) {
    Scene scene = boxOnPlane();
    std::optional<ScenePoint> p = seenPoint(scene, {1.4486f, 0.0f, -0.0163f});
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->posWs.y, 0.0f, 1e-6f);
    EXPECT_NEAR(p->normalWs.y, 1.0f, 1e-6f);
    EXPECT_FALSE(seenPoint(scene, {1.4486f, 0.5f, -0.0163f}));  // in the air
    // The ground behind the box, seen from the camera: the box is in the way.
    std::optional<ScenePoint> centre = pointAtNdc(scene, {0.0f, 0.0f}, 1.0f, {0.0f, 0.0f});
    ASSERT_TRUE(centre);
    ASSERT_GT(centre->posWs.y, 1e-3f);  // the box, in the middle of the view
    glm::vec3 eye = scene.camera.eyeWs;
    glm::vec3 dir = glm::normalize(centre->posWs - eye);
    EXPECT_FALSE(seenPoint(scene, eye + (-eye.y / dir.y) * dir));
}

TEST(LessonPick, TheJitteredCameraPutsThePointOnItsPixelsCentreAtEverySize) {
    Scene scene = boxOnPlane();
    glm::vec3 point(1.4486f, 0.0f, -0.0163f);
    for (glm::ivec2 size : {glm::ivec2(617, 347), glm::ivec2(960, 540), glm::ivec2(512, 288),
                            glm::ivec2(1152, 648), glm::ivec2(803, 452)}) {
        FramePick pick = framePick(scene.camera, point, size);
        ASSERT_TRUE(pick.inFrame);
        // Less than half a pixel of shift.
        EXPECT_LE(std::fabs(pick.jitterNdc.x) * size.x / 2.0f, 0.5f + 1e-4f);
        EXPECT_LE(std::fabs(pick.jitterNdc.y) * size.y / 2.0f, 0.5f + 1e-4f);
        float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
        glm::vec4 clip = jitterClip(clipFromWorld(scene.camera, aspect), pick.jitterNdc) *
                         glm::vec4(point, 1.0f);
        glm::vec2 window = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(size);
        glm::ivec2 gl(pick.pixel.x, size.y - 1 - pick.pixel.y);
        EXPECT_NEAR(window.x, gl.x + 0.5f, 2e-3f) << size.x;
        EXPECT_NEAR(window.y, gl.y + 0.5f, 2e-3f) << size.x;
        // A click on that pixel of the jittered frame pins the same point again.
        std::optional<ScenePoint> clicked =
            pointAtNdc(scene, pixelCentreNdc(gl, size), aspect, pick.jitterNdc);
        ASSERT_TRUE(clicked);
        EXPECT_LT(glm::length(clicked->posWs - point), 1e-4f);
    }
}

TEST(LessonPick, TheLookupIsTheCameraPassFormulaAndIndependentOfTheFrame) {
    Scene scene = boxOnPlane();
    ScenePoint p = *seenPoint(scene, {1.4486f, 0.0f, -0.0163f});
    LessonSettings s;
    s.bias = BiasMode::Constant;
    s.constantBias = 0.002f;
    glm::mat4 fit = shadowClipFromWorld(scene);
    PinnedLookup at = pinnedLookup(scene, fit, s, p);
    glm::vec4 clip = fit * glm::vec4(p.posWs, 1.0f);
    EXPECT_NEAR(at.uv.x, clip.x / clip.w * 0.5f + 0.5f, 1e-7f);
    EXPECT_NEAR(at.uv.y, clip.y / clip.w * 0.5f + 0.5f, 1e-7f);
    EXPECT_NEAR(at.z0, clip.z / clip.w * 0.5f + 0.5f, 1e-7f);
    EXPECT_FLOAT_EQ(at.ref, at.z0 - 0.002f);
    // A directional light's map is an affine image of the ground: dz/duv reproduces the depth
    // of another ground point from this one's.
    glm::vec3 q = p.posWs + glm::vec3(0.3f, 0.0f, -0.2f);
    glm::vec4 cq = fit * glm::vec4(q, 1.0f);
    glm::vec3 d = glm::vec3(cq) / cq.w * 0.5f + 0.5f - glm::vec3(at.uv, at.z0);
    EXPECT_NEAR(d.z, at.dzduv.x * d.x + at.dzduv.y * d.y, 1e-5f);
    // The light comes down at acos(n . toLight) from the ground's normal.
    glm::vec3 toLight = -glm::normalize(scene.light.directionWs);
    EXPECT_NEAR(lightAngleDeg(scene, p), glm::degrees(std::acos(toLight.y)), 1e-3f);
}

// `pcfscope pick` prints what a click in the viewer prints, for the same frame pixel of the same
// step at the same size: the line, byte for byte. Pinned by a lesson's `point`, that point traces
// the lookup the click traced (to the six decimals printed).
TEST(PickCommand, PrintsTheViewersClickAndItsPointTracesTheClicksLookup) {
    testutil::VirtualDisplay display;
    ASSERT_FALSE(display.display().empty()) << "Xvfb did not start";
    std::filesystem::path dir = testutil::makeTempDir("pick");
    testutil::CommandResult picked = testutil::runPcfscope("pick 3 --step 1 --pixel 300,200");
    ASSERT_EQ(picked.exitCode, 0) << picked.err;
    testutil::CommandResult viewed = testutil::runPcfscope(
        "view 3 --keys click:300,200 --screenshot " + (dir / "view.png").string(),
        "DISPLAY=" + display.display());
    ASSERT_EQ(viewed.exitCode, 0) << viewed.err;
    EXPECT_NE(viewed.out.find(picked.out), std::string::npos) << viewed.out << picked.out;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(picked.out, m, std::regex("point = \\[[^\\]]+\\]")))
        << picked.out;
    // Lesson 3 with its first step's point the one printed, against the click on that step.
    std::ifstream in(PCFSCOPE_SOURCE_DIR "/lessons/03-bilinear-lerp.toml");
    std::string lesson((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    size_t at = lesson.find("point = [0.9847, 0, -0.3699]");
    ASSERT_NE(at, std::string::npos);
    lesson.replace(at, std::string("point = [0.9847, 0, -0.3699]").size(), m.str());
    std::ofstream((dir / "picked.toml").string()) << lesson;
    std::string common = " --steps 1-1 --size 1600x900 -o ";
    testutil::CommandResult a = testutil::runPcfscope("export " + (dir / "picked.toml").string() +
                                                      common + (dir / "a").string());
    testutil::CommandResult b =
        testutil::runPcfscope("export 3 --keys click:300,200" + common + (dir / "b").string());
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    auto trace = [&](const char* sub, const char* stem) {
        std::ifstream f(dir / sub / (std::string(stem) + "-step01.json"));
        std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
        return jsonlite::parse(text)["trace"];
    };
    jsonlite::Value ta = trace("a", "picked"), tb = trace("b", "03-bilinear-lerp");
    for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(ta["uv"][k].number, tb["uv"][k].number, 2e-6);
        EXPECT_NEAR(ta["frac"][k].number, tb["frac"][k].number, 2e-3);
    }
    EXPECT_NEAR(ta["ref"].number, tb["ref"].number, 2e-6);
    EXPECT_NEAR(ta["visibility"].number, tb["visibility"].number, 2e-3);
    ASSERT_EQ(ta["taps"].size(), tb["taps"].size());
    for (size_t k = 0; k < ta["taps"].size(); ++k) {
        EXPECT_EQ(ta["taps"][k]["texel"][0].number, tb["taps"][k]["texel"][0].number);
        EXPECT_EQ(ta["taps"][k]["texel"][1].number, tb["taps"][k]["texel"][1].number);
        EXPECT_EQ(ta["taps"][k]["lit"].number, tb["taps"][k]["lit"].number);
    }
    // The click pinned another point than the lesson's own: the traces compared are the click's.
    EXPECT_EQ(picked.out.find("0.984700"), std::string::npos) << picked.out;
    if (!HasFailure()) std::filesystem::remove_all(dir);
}

// A pixel off the scene, off the frame, or on a chart step: one line, exit 2.
TEST(PickCommand, RefusesAPixelItCannotPick) {
    testutil::CommandResult r = testutil::runPcfscope("pick 3 --step 1 --pixel 900,200");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("is not on the scene (step 1's scene spans x"), std::string::npos)
        << r.err;
    r = testutil::runPcfscope("pick 3 --step 1 --pixel 5000,200");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("is outside the 1600x900 frame"), std::string::npos) << r.err;
    r = testutil::runPcfscope("pick 11 --step 1 --pixel 300,200");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("shows a chart"), std::string::npos) << r.err;
    r = testutil::runPcfscope("pick 3 --step 9 --pixel 300,200");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
}

}  // namespace
}  // namespace pcf
