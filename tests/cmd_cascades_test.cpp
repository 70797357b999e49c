// `pcfscope render --cascades N`: a directional light's map in N cascades, and render.json's
// account of them under "map" (camera_near, shadow_distance, and per cascade its view depths and
// texel size), which follows Zhang et al.'s practical split for the n, f and lambda it reports.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "image_read.h"
#include "kernel/trace_json.h"
#include "run_command.h"

namespace {

using pcf::Json;

class CascadesCommand : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("cascades"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    // A ground 120 units long, posts along it, the camera near the ground with near = 0.1.
    std::string writeScene() const {
        std::string scene = path("ground.toml");
        std::ofstream f(scene);
        f << "[camera]\neye = [0.0, 1.5, 5.0]\ntarget = [0.0, 0.5, -20.0]\nfov = 45.0\n"
             "near = 0.1\nfar = 150.0\n\n[light]\ntype = \"directional\"\n"
             "direction = [0.7, -1.0, 0.3]\n\n[[object]]\ntype = \"plane\"\nname = \"ground\"\n"
             "centre = [0.0, 0.0, -55.0]\nnormal = [0.0, 1.0, 0.0]\nsize = [30.0, 120.0]\n";
        for (int k = 0; k < 6; ++k) {
            f << "\n[[object]]\ntype = \"box\"\nname = \"post" << k << "\"\ncentre = [-2.0, 1.0, "
              << -4.0 - 15.0 * k << "]\nhalf = [0.3, 1.0, 0.3]\n";
        }
        return scene;
    }
    Json renderJson(const std::string& options) {
        std::string raw = path("raw");
        std::filesystem::remove_all(raw);
        testutil::CommandResult r =
            testutil::runPcfscope("render --scene-file " + writeScene() +
                                  " --size 320x180 --map-size 128 " + options + " --raw " + raw);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return Json::parse(testutil::readAll(raw + "/render.json"));
    }
    std::filesystem::path mDir;
};

// C_i = lambda n (f/n)^(i/N) + (1 - lambda)(n + (f - n) i/N): Zhang, Sun, Xu and Lau,
// "Parallel-Split Shadow Maps for Large-scale Virtual Environments" (2006), written out here as
// the paper gives it.
double practicalSplit(double n, double f, int i, int count, double lambda) {
    double t = static_cast<double>(i) / count;
    return lambda * n * std::pow(f / n, t) + (1.0 - lambda) * (n + (f - n) * t);
}

TEST_F(CascadesCommand, RenderJsonListsTheIssuesSplits) {
    Json j = renderJson("--cascades 4 --cascade-lambda 0.5 --shadow-distance 100");
    const Json& map = j["map"];
    EXPECT_EQ(j["cascades"], 4);
    ASSERT_EQ(map["layers"].size(), 4u);
    EXPECT_NEAR(map["camera_near"].get<double>(), 0.1, 1e-6);
    EXPECT_NEAR(map["shadow_distance"].get<double>(), 100.0, 1e-6);
    const Json& c = map["cascades"];
    ASSERT_EQ(c.size(), 4u);
    double want[] = {12.8187, 26.6061, 46.4039, 100.0};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(c[i]["index"], i);
        EXPECT_NEAR(c[i]["far"].get<double>(), want[i], 1e-3) << i;
        EXPECT_EQ(c[i]["near"], i == 0 ? map["camera_near"] : c[i - 1]["far"]) << i;
        // Each farther cascade covers more of the world with the same texels.
        if (i > 0) {
            EXPECT_GT(c[i]["texel_world"].get<double>(), c[i - 1]["texel_world"].get<double>());
        }
        // Measured on the frame: the receivers that read this cascade, its texels per pixel (the
        // farthest cascade holds a few rows under the horizon, where most neighbours are more
        // than 32 texels apart and are not measured).
        EXPECT_GT(c[i]["pixels_measured"].get<int>(), i < 3 ? 200 : 0) << i;
        double median = c[i]["texels_per_pixel_median"].get<double>();
        EXPECT_GT(median, 0.0) << i;
        EXPECT_GE(c[i]["texels_per_pixel_max"].get<double>(), median) << i;
        // Lloyd's per-direction measure, the larger singular value s1 of each pixel's Jacobian:
        // s1 >= sqrt(s1 s2) = sqrt(area ratio) at every pixel, so at every quantile too.
        double svMedian = c[i]["texels_per_pixel_sv_median"].get<double>();
        double svMax = c[i]["texels_per_pixel_sv_max"].get<double>();
        EXPECT_GE(svMedian, std::sqrt(median) * (1.0 - 1e-6)) << i;
        EXPECT_GE(svMax, svMedian) << i;
        EXPECT_GE(svMax, std::sqrt(c[i]["texels_per_pixel_max"].get<double>()) * (1.0 - 1e-6)) << i;
        std::printf(
            "cascade %d: far %.4f, texel_world %.5f, texels per pixel median %.4f max %.4f\n", i,
            c[i]["far"].get<double>(), c[i]["texel_world"].get<double>(), median,
            c[i]["texels_per_pixel_max"].get<double>());
    }
}

// For any n, f and lambda it reports, render.json's splits are the formula's.
TEST_F(CascadesCommand, RenderJsonsSplitsFollowTheFormulaForWhatItReports) {
    for (const char* options :
         {"--cascades 3 --cascade-lambda 0.8 --shadow-distance 60",
          "--cascades 4 --cascade-split log --shadow-distance 90",
          "--cascades 2 --cascade-split uniform --cascade-fit sphere --cascade-snap",
          "--cascades 4 --cascade-lambda 0.25"}) {
        Json j = renderJson(options);
        const Json& map = j["map"];
        double n = map["camera_near"].get<double>();
        double f = map["shadow_distance"].get<double>();
        std::string split = j["cascade_split"].get<std::string>();
        double lambda = split == "log"       ? 1.0
                        : split == "uniform" ? 0.0
                                             : j["cascade_lambda"].get<double>();
        int count = j["cascades"].get<int>();
        ASSERT_EQ(map["cascades"].size(), static_cast<size_t>(count)) << options;
        for (int i = 0; i < count; ++i) {
            double far = map["cascades"][i]["far"].get<double>();
            EXPECT_NEAR(far, practicalSplit(n, f, i + 1, count, lambda), 1e-5 * f)
                << options << " cascade " << i;
        }
    }
    // No --shadow-distance: the camera's far plane.
    EXPECT_NEAR(renderJson("--cascades 2")["map"]["shadow_distance"].get<double>(), 150.0, 1e-4);
}

TEST_F(CascadesCommand, RefusesASpotLightPcssAndADistanceBeforeTheNearPlane) {
    struct Case {
        std::string args, message;
    };
    for (const Case& c :
         {Case{"--scene post-under-spot --cascades 2",
               "pcfscope: --cascades 2 are for a directional light; the scene's light is a spot"},
          Case{"--scene box-on-plane --cascades 3 --method pcss",
               "pcfscope: --cascades 3 do not work with pcss (one penumbra scale per map)"},
          Case{"--scene-file " + writeScene() + " --cascades 2 --shadow-distance 0.05",
               "pcfscope: --shadow-distance 0.05 must lie beyond the camera's near plane 0.1"},
          Case{"--scene box-on-plane --cascades 2 --method vsm",
               "pcfscope: --cascades 2 do not work with vsm (a moments map has one layer)"},
          Case{"--scene box-on-plane --cascades 5", "pcfscope: --cascades must be 1..4, got 5"}}) {
        testutil::CommandResult r =
            testutil::runPcfscope("render " + c.args + " --size 64x36 -o " + path("x.png"));
        EXPECT_EQ(r.exitCode, 2) << c.args;
        EXPECT_EQ(r.err, c.message + "\n") << c.args;
        EXPECT_FALSE(std::filesystem::exists(path("x.png"))) << c.args;
    }
}

// --cascade-blend B reaches the frame and render.json, and a band outside [0, 1] is refused. The
// band changes the picture where the two cascades on either side of a split differ (a post's
// shadow edge), and only there: the frames with and without it differ, but in few pixels.
TEST_F(CascadesCommand, TheBlendBandIsASettingOfTheFrame) {
    Json j = renderJson("--cascades 4 --shadow-distance 60 --cascade-blend 0.25");
    EXPECT_NEAR(j["cascade_blend"].get<double>(), 0.25, 1e-7);
    std::vector<std::vector<unsigned char>> frames;
    for (const char* blend : {"0", "0.3"}) {
        std::string png = path(std::string("blend") + blend + ".png");
        testutil::CommandResult r = testutil::runPcfscope(
            "render --scene-file " + writeScene() +
            " --size 160x90 --map-size 64 --cascades 4 --shadow-distance 60 --shading visibility "
            "--cascade-blend " +
            blend + " -o " + png);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        frames.push_back(readImageBytes(png, 4));
    }
    ASSERT_EQ(frames[0].size(), frames[1].size());
    int differ = 0;
    for (size_t k = 0; k < frames[0].size(); k += 4) differ += frames[0][k] != frames[1][k];
    EXPECT_GT(differ, 5);
    EXPECT_LT(differ, 160 * 90 / 4);
    testutil::CommandResult bad = testutil::runPcfscope(
        "render --scene box-on-plane --cascades 2 --cascade-blend 1.5 --size 64x36 -o " +
        path("bad.png"));
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_EQ(bad.err, "pcfscope: --cascade-blend must be in [0, 1], got 1.5\n");
    EXPECT_FALSE(std::filesystem::exists(path("bad.png")));
}

// `verify` on a blended render --raw folder: a pixel in a band holds the mix of two cascades'
// lookups, which verify bounds by the same mix of their envelopes; every pixel inside, with a
// method of hardware taps (tent) and one of nearest texels (poisson).
TEST_F(CascadesCommand, VerifyHoldsABlendedFolderToTheMixOfTwoCascades) {
    for (const char* method : {"tent --kernel 5", "poisson --radius 2 --rotate"}) {
        std::string raw = path("blended");
        std::filesystem::remove_all(raw);
        testutil::CommandResult r = testutil::runPcfscope(
            std::string("render --scene long-ground --cascades 4 --map-size 256 --size 320x180 "
                        "--bias normal --cascade-blend 0.3 --method ") +
            method + " --raw " + raw);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        testutil::CommandResult v = testutil::runPcfscope("verify " + raw);
        EXPECT_EQ(v.exitCode, 0) << method << v.out << v.err;
        EXPECT_NE(v.out.find("(100.0000 %)"), std::string::npos) << method << v.out;
    }
}

// --cascade-bounds depth: render.json says what the cascades split ([n, f] as the settings name
// it) and what it was tightened to (depth_min, depth_max: the frame's receivers' view depths);
// `verify` passes on the folder and fails once render.json's bounds are altered.
TEST_F(CascadesCommand, VerifyHoldsDepthBoundsToTheFramesReceivers) {
    std::string raw = path("bounds");
    testutil::CommandResult r = testutil::runPcfscope(
        "render --scene long-ground --cascades 4 --shadow-distance 400 --cascade-bounds depth "
        "--map-size 256 --size 320x180 --raw " +
        raw);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Json j = Json::parse(testutil::readAll(raw + "/render.json"));
    EXPECT_EQ(j["cascade_bounds"], "depth");
    const Json& map = j["map"];
    EXPECT_NEAR(map["camera_near"].get<double>(), 0.1, 1e-6);
    EXPECT_NEAR(map["shadow_distance"].get<double>(), 400.0, 1e-4);
    double lo = map["depth_min"].get<double>(), hi = map["depth_max"].get<double>();
    EXPECT_GT(lo, 1.0);    // the ground starts ahead of the camera
    EXPECT_LT(hi, 101.0);  // and ends within its far plane
    EXPECT_LE(map["cascades"][0]["near"].get<double>(), lo);
    EXPECT_GE(map["cascades"][3]["far"].get<double>(), hi);
    EXPECT_LT(map["cascades"][3]["far"].get<double>(), 101.0);
    testutil::CommandResult v = testutil::runPcfscope("verify " + raw);
    EXPECT_EQ(v.exitCode, 0) << v.out << v.err;
    EXPECT_NE(v.out.find("0 receiver pixels nearer than the shadow distance past the last"),
              std::string::npos)
        << v.out;

    // trace --raw reads the same cascades: a pixel on the ground near the bottom of the frame
    // is in cascade 0, which begins at the tightened near end, not at the camera's near plane.
    testutil::CommandResult t =
        testutil::runPcfscope("trace --raw " + raw + " --pixel 160,170 --json");
    ASSERT_EQ(t.exitCode, 0) << t.err;
    Json traced = Json::parse(t.out);
    EXPECT_EQ(traced["cascade"]["index"], 0);
    EXPECT_EQ(traced["cascade"]["near"], map["cascades"][0]["near"]);
    EXPECT_GT(traced["cascade"]["near"].get<double>(), 1.0);

    // Altered: a depth_max the receivers do not reach, then a depth_min with the far end left.
    for (const char* key : {"depth_max", "depth_min"}) {
        Json tampered = j;
        tampered["map"][key] = tampered["map"][key].get<double>() * 0.95;
        std::ofstream(raw + "/render.json") << tampered.dump();
        testutil::CommandResult bad = testutil::runPcfscope("verify " + raw);
        EXPECT_EQ(bad.exitCode, 2) << key << bad.out;
        EXPECT_NE(bad.err.find("render.json does not describe these images"), std::string::npos)
            << key << bad.err;
    }
    // Altered consistently (depth_max and the receivers' bounds agree, the splits do not): the
    // last cascade's far end moved in.
    Json split = j;
    split["map"]["cascades"][3]["far"] = hi * 0.9;
    split["map"]["layers"][3]["view_depth"][1] = hi * 0.9;
    std::ofstream(raw + "/render.json") << split.dump();
    testutil::CommandResult moved = testutil::runPcfscope("verify " + raw);
    EXPECT_EQ(moved.exitCode, 2) << moved.out;
    EXPECT_NE(moved.err.find("cascade 3 covers"), std::string::npos) << moved.err;
}

// A lesson fits its cascades once for every frame size, which bounds measured on a frame cannot
// give: --cascade-bounds depth with --lesson is refused in one line, as is the key in a lesson.
TEST_F(CascadesCommand, DepthBoundsAreRefusedForALesson) {
    testutil::CommandResult r = testutil::runPcfscope(
        "render --lesson 21 --step 2 --cascade-bounds depth --size 160x90 -o " + path("l.png"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--cascade-bounds depth is not for a lesson"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(path("l.png")));

    // The key in a lesson's step: blamed on its line.
    std::string text = testutil::readAll(std::string(PCFSCOPE_SOURCE_DIR) +
                                         "/lessons/21-cascades-and-splits.toml");
    std::string after = "cascade_lambda = 0.5\n";
    size_t at = text.find(after);
    ASSERT_NE(at, std::string::npos);
    text.insert(at + after.size(), "cascade_bounds = \"depth\"\n");
    int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n')) + 1;
    std::string lesson = path("depth-bounds.toml");
    std::ofstream(lesson) << text;
    testutil::CommandResult check = testutil::runPcfscope("lesson check " + lesson);
    EXPECT_EQ(check.exitCode, 2) << check.out;
    EXPECT_NE(check.err.find("depth-bounds.toml:" + std::to_string(line) + ":"), std::string::npos)
        << check.err;
    EXPECT_NE(check.err.find("cascade_bounds depth is not for a lesson"), std::string::npos)
        << check.err;
}

// --shading cascades tints each pixel by the cascade it reads: with four cascades over the
// ground running away from the camera, each of the four tints covers part of the frame, the
// nearest (red) at the bottom, and the ground past the shadow distance stays untinted (grey).
TEST_F(CascadesCommand, CascadeShadingShowsEachCascadesColour) {
    std::string png = path("tinted.png");
    testutil::CommandResult r = testutil::runPcfscope(
        "render --scene-file " + writeScene() +
        " --size 160x90 --map-size 128 --cascades 4 --shadow-distance 60 --shading cascades -o " +
        png);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<unsigned char> rgba = readImageBytes(png, 4);
    ASSERT_EQ(rgba.size(), 160u * 90u * 4u);
    int red = 0, green = 0, blue = 0, yellow = 0, grey = 0, redBottom = 0;
    for (size_t k = 0; k < rgba.size() / 4; ++k) {
        int cr = rgba[4 * k], cg = rgba[4 * k + 1], cb = rgba[4 * k + 2];
        bool isRed = cr > cg + 40 && cr > cb + 40 && cg < cb + 20;
        red += isRed ? 1 : 0;
        redBottom += isRed && k / 160 >= 60 ? 1 : 0;  // rows top-down: the bottom third
        green += cg > cr + 40 && cg > cb + 40 ? 1 : 0;
        blue += cb > cr + 30 && cb > cg + 20 ? 1 : 0;
        yellow += cr > cb + 60 && cg > cb + 60 ? 1 : 0;
        grey += std::abs(cr - cg) < 8 && std::abs(cg - cb) < 8 && cr > 60 ? 1 : 0;
    }
    EXPECT_GT(red, 200);
    EXPECT_GT(redBottom, red / 2);
    EXPECT_GT(green, 100);
    EXPECT_GT(blue, 50);
    EXPECT_GT(yellow, 20);
    EXPECT_GT(grey, 20);  // the ground past 60 units
}

}  // namespace
