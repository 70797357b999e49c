// Animation and `pcfscope animate`: frames that are the same bytes run to run, videos FFmpeg
// reads back with the right size and frame count, and the flicker trace's curve being exactly
// what `stability` measures: the flicker of the pinned point's curve, computed through the
// animation's path (Session frames), equals the stability sweep's light_pinned_flicker.
#include "app/animation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "app/session.h"
#include "json_lite.h"
#include "measure/failure_measures.h"
#include "measure/stability.h"
#include "render/gl_context.h"
#include "run_command.h"
#include "video_read.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

const std::string LESSON =
    std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/13-shimmer-and-snapping.toml";

// The stability row of `metric` for one method, or -1.
double rowValue(const StabilityResult& r, int method, const std::string& metric) {
    for (const StabilityRow& row : r.rows) {
        if (row.method == method && row.metric == metric) return row.y;
    }
    return -1.0;
}

TEST(Animation, FlickerTraceIsTheStabilityCurveOfThePinnedPoint) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    const glm::ivec2 size{320, 180};
    Session session(size, false);
    session.loadLesson(LESSON);
    // Step 7 (index 6): nearest, seen through the lesson's own camera (steps 2, 4 and 5 are
    // magnified, which would put the pixel on another point).
    session.goToStep(6);
    session.setSceneOnly(true);
    // A ground pixel by the box's shadow edge that the creeping grid flips.
    session.setPixel({181, 90});
    const LessonSettings base = session.settings();
    ASSERT_EQ(base.method, PCF_NEAREST);

    StabilityOptions o;
    o.sweeps = {Sweep::Shimmer};
    o.methods = {{PCF_NEAREST, 0}, {PCF_GATHER, 3}};
    o.biases = {base.bias};
    o.base = renderSettingsFor(base, size);
    o.frameSize = size;
    o.mapSize = base.mapSize;
    o.truthSpp = 1;
    o.cameraFrames = 1;
    o.pinnedPixel = session.pixel();
    o.pinnedJitter = session.jitter();  // the camera that shows the pinned point at that pixel
    StabilityContext sc;
    sc.scene = &session.scene();
    StabilityResult stability = runStability(sc, o);

    for (bool snap : {false, true}) {
        session.goToStep(6);
        session.setPixel(*o.pinnedPixel);
        AnimationOptions ao;
        ao.sweep = AnimationSweep::Light;
        ao.frames = o.shimmerFrames;
        ao.snap = snap;
        ao.compareMethod = PCF_GATHER;
        ao.compareKernel = 3;
        Animation animation(session, ao);
        for (int k = 0; k < ao.frames; ++k) animation.composeFrame(k);
        ASSERT_EQ(animation.curve().size(), static_cast<size_t>(ao.frames));
        for (float v : animation.curve()) ASSERT_GE(v, 0.0f) << "the point is on a receiver";
        std::string metric = snap ? "snapped_pinned_flicker" : "light_pinned_flicker";
        double nearest = rowValue(stability, PCF_NEAREST, metric);
        double gather = rowValue(stability, PCF_GATHER, metric);
        ASSERT_GE(nearest, 0.0) << metric;
        EXPECT_NEAR(curveFlicker(animation.curve()), nearest, 1e-4) << metric;
        EXPECT_NEAR(curveFlicker(animation.compareCurve()), gather, 1e-4) << metric;
        // And the curves themselves, frame by frame.
        std::string curveMetric = snap ? "snapped_pinned_visibility" : "light_pinned_visibility";
        int compared = 0;
        for (const StabilityRow& row : stability.rows) {
            if (row.metric != curveMetric) continue;
            ++compared;
            const std::vector<float>& curve =
                row.method == PCF_NEAREST ? animation.curve() : animation.compareCurve();
            size_t t = static_cast<size_t>(row.x);
            ASSERT_LT(t, curve.size());
            EXPECT_NEAR(curve[t], row.y, 1e-4)
                << curveMetric << " " << row.method << " frame " << t;
        }
        EXPECT_EQ(compared, 2 * ao.frames) << "both methods' curves, every frame";
        if (!snap) {
            // The point does flicker under the creeping grid: the comparison is not of zeros.
            EXPECT_GT(nearest, 0.01);
            EXPECT_GT(gather, 0.0);
        }
    }
}

// What `lesson check` reads for a `flickers` claim: the step's flicker trace, from the frames its
// sweep composes. The point belongs to the scene, so the curves are the same at every frame size;
// lesson 13's last step rings a point on the stair-stepped edge: nearest jumps 0 <-> 1 there,
// pcf-gather 3x3 creeps.
TEST(Animation, AStepsFlickerCurvesAreTheSameAtEverySize) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    Lesson lesson = parseLessonFile(LESSON);
    const int step = static_cast<int>(lesson.steps.size()) - 1;
    const LessonSettings& s = lesson.steps[static_cast<size_t>(step)].settings;
    FlickerCurves small = stepFlickerCurves(lesson, step, s, {320, 180});
    FlickerCurves large = stepFlickerCurves(lesson, step, s, {960, 540});
    ASSERT_EQ(small.main.size(), 64u);
    EXPECT_EQ(small.main, large.main);
    EXPECT_EQ(small.compare, large.compare);
    auto largestJump = [](const std::vector<float>& curve) {
        float most = 0.0f;
        for (size_t k = 1; k < curve.size(); ++k) {
            most = std::max(most, std::fabs(curve[k] - curve[k - 1]));
        }
        return most;
    };
    EXPECT_EQ(largestJump(small.main), 1.0f);
    EXPECT_GT(largestJump(small.compare), 0.0f);
    EXPECT_LT(largestJump(small.compare), 0.5f);
    // A step that does not move has no curves.
    EXPECT_TRUE(stepFlickerCurves(lesson, 0, lesson.steps[0].settings).main.empty());
}

TEST(AnimateCommand, FramesAreTheSameBytesRunToRunAndVideosReadBack) {
    fs::path dir = testutil::makeTempDir("animate");
    std::string common = "animate 13 --step 2 --sweep light --frames 3 --size 320x180 ";
    for (const char* run : {"a", "b"}) {
        std::string d = (dir / run).string();
        testutil::CommandResult r = testutil::runPcfscope(common + "--png " + d + "/png -o " + d +
                                                          "/clip.mp4 -o " + d + "/clip.gif");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.err.find("3/3"), std::string::npos) << "a progress bar: " << r.err;
    }
    for (int k = 1; k <= 3; ++k) {
        std::string name =
            "png/13-shimmer-and-snapping-step02-light-000" + std::to_string(k) + ".png";
        ASSERT_TRUE(fs::exists(dir / "a" / name)) << name;
        EXPECT_EQ(testutil::readAll(dir / "a" / name), testutil::readAll(dir / "b" / name)) << name;
    }
    EXPECT_NE(testutil::readAll(dir / "a/png/13-shimmer-and-snapping-step02-light-0001.png"),
              testutil::readAll(dir / "a/png/13-shimmer-and-snapping-step02-light-0003.png"))
        << "the frames move";
    testutil::expectMp4(testutil::readVideo((dir / "a/clip.mp4").string()), 320, 180, 3);
    testutil::expectGif(testutil::readVideo((dir / "a/clip.gif").string()), 320, 180, 3);
    // Encoded on the writers' own threads, the videos are still the same bytes run to run.
    for (const char* clip : {"clip.mp4", "clip.gif"}) {
        EXPECT_EQ(testutil::readAll(dir / "a" / clip), testutil::readAll(dir / "b" / clip)) << clip;
    }
    // No scratch folder is left beside the videos.
    for (const auto& e : fs::directory_iterator(dir / "a")) {
        EXPECT_EQ(e.path().filename().string().rfind(".pcfscope-", 0), std::string::npos)
            << e.path();
    }
    fs::remove_all(dir);
}

// A JSON number as `pcfscope trace` reads it back into the same float.
std::string floatText(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

// `animate --png DIR` writes beside each frame's PNG its JSON, as `export` writes a still's: the
// trace, the layout with the words drawn, the settings and the frame's motion. Its trace is the
// one `pcfscope trace` gives on that frame's map at that frame's lookup: a bias sweep keeps the
// map (the constant bias is the camera pass's), which `render --raw` writes for the step.
TEST(AnimateCommand, EachPngHasItsFramesJsonWhoseTraceIsTracesAtThatLookup) {
    fs::path dir = testutil::makeTempDir("animate-json");
    std::string d = dir.string();
    testutil::CommandResult r = testutil::runPcfscope(
        "animate 14 --step 3 --sweep bias --frames 3 --size 640x360 --png " + d + "/png");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    testutil::CommandResult raw = testutil::runPcfscope("render --lesson 14 --step 3 --raw " + d +
                                                        "/raw -o " + d + "/still.png");
    ASSERT_EQ(raw.exitCode, 0) << raw.err;
    AnimationOptions sweep;
    sweep.sweep = AnimationSweep::Bias;
    sweep.frames = 3;
    for (int k = 1; k <= 3; ++k) {
        std::string stem = d + "/png/14-bias-trade-off-step03-bias-000" + std::to_string(k);
        ASSERT_TRUE(fs::exists(stem + ".png")) << stem;
        ASSERT_TRUE(fs::exists(stem + ".json")) << stem;
        jsonlite::Value frame = jsonlite::parse(testutil::readAll(stem + ".json"));
        EXPECT_EQ(frame["motion"]["sweep"].string, "bias");
        EXPECT_EQ(frame["motion"]["frame"].number, k);
        double bias = frame["settings"]["constant_bias"].number;
        EXPECT_NEAR(bias, animationSweepValue(sweep, k - 1), 1e-6 * bias) << k;
        // The words drawn, as drawn: the step-text box knows them.
        bool words = false;
        for (const jsonlite::Value& box : frame["layout"].array) {
            words |=
                box["role"].string == "step-text" && box.has("text") && !box["text"].string.empty();
        }
        EXPECT_TRUE(words) << k;
        const jsonlite::Value& t = frame["trace"];
        testutil::CommandResult traced = testutil::runPcfscope(
            "trace --map " + d + "/raw/shadowmap.exr --uv " + floatText(t["uv"][size_t{0}].number) +
            "," + floatText(t["uv"][size_t{1}].number) + " --z " + floatText(t["z"].number) +
            " --method pcf-gather --kernel 3 --bias constant --constant-bias " + floatText(bias) +
            " --json");
        ASSERT_EQ(traced.exitCode, 0) << traced.err;
        jsonlite::Value want = jsonlite::parse(traced.out);
        EXPECT_EQ(t["ref"].number, want["ref"].number) << k;
        EXPECT_EQ(t["visibility"].number, want["visibility"].number) << k;
        ASSERT_EQ(t["taps"].size(), want["taps"].size()) << k;
        for (size_t i = 0; i < t["taps"].size(); ++i) {
            for (const char* field : {"depth", "ref", "lit", "weight"}) {
                EXPECT_EQ(t["taps"][i][field].number, want["taps"][i][field].number)
                    << "frame " << k << " tap " << i << " " << field;
            }
            for (size_t c : {0u, 1u}) {
                EXPECT_EQ(t["taps"][i]["texel"][c].number, want["taps"][i]["texel"][c].number);
            }
        }
    }
    if (!HasFailure()) fs::remove_all(dir);
}

TEST(AnimateCommand, CtrlCLeavesNoHalfVideoNorScratchFolder) {
    fs::path dir = testutil::makeTempDir("animate");
    fs::path out = dir / "out";
    // Interrupted once the first PNG is written: the videos are then half encoded.
    std::string script =
        "cd " + dir.string() + " && (" + PCFSCOPE_EXE +
        " animate 13 --step 3 --frames 400 --size 320x180 -o out/v.mp4 -o out/v.gif "
        "--png out/png 2>err.txt >/dev/null & pid=$!; "
        "for i in $(seq 600); do ls out/png/*.png >/dev/null 2>&1 && break; "
        "sleep 0.05; done; kill -INT $pid; wait $pid; echo $? >rc.txt)";
    ASSERT_EQ(std::system(script.c_str()), 0);
    EXPECT_EQ(testutil::readAll(dir / "rc.txt"), "130\n") << testutil::readAll(dir / "err.txt");
    EXPECT_FALSE(fs::exists(out)) << "the folder it made, with everything in it, is taken back";
    fs::remove_all(dir);
}

TEST(AnimateCommand, BadInputIsOneLineAndLeavesNothing) {
    fs::path dir = testutil::makeTempDir("animate");
    std::string out = (dir / "new").string();
    for (std::string args :
         {"--sweep wobble", "--size 321x180", "--compare tent --compare-kernel 4", "--frames 1"}) {
        testutil::CommandResult r =
            testutil::runPcfscope("animate 13 --step 3 " + args + " -o " + out + "/x.mp4");
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << args << ": " << r.err;
        EXPECT_FALSE(fs::exists(out)) << args;
    }
    // An existing file is not overwritten unasked.
    fs::create_directories(out);
    {
        std::ofstream keep(out + "/x.gif");
        keep << "mine";
    }
    testutil::CommandResult r =
        testutil::runPcfscope("animate 13 --step 3 --frames 2 --size 320x180 -o " + out + "/x.gif");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(testutil::readAll(out + "/x.gif"), "mine");
    fs::remove_all(dir);
}

// The turn sweep (lesson 22): the camera turns about the vertical through the pinned point, which
// keeps its pixel while the view turns; a cascaded map is fitted again on every frame, so a box
// fit's texel changes with the turn and a sphere fit's does not; restore() puts the lesson's
// camera back.
TEST(Animation, TheTurnSweepTurnsTheCameraAboutThePinnedPoint) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    const std::string lesson =
        std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/22-cascades-that-do-not-shimmer.toml";
    struct Seen {
        glm::ivec2 pixel;
        glm::vec3 point, eye;
        float texel;
    };
    auto play = [&](int step) {
        Session session({640, 360}, false);
        session.loadLesson(lesson);
        session.goToStep(step);
        const Camera before = session.scene().camera;
        AnimationOptions ao =
            stepAnimationOptions(session.lesson().steps[static_cast<size_t>(step)]);
        EXPECT_EQ(ao.sweep, AnimationSweep::Turn);
        ao.frames = 3;
        Animation animation(session, ao);
        std::vector<Seen> seen;
        for (int k = 0; k < ao.frames; ++k) {
            animation.composeFrame(k);
            seen.push_back({session.pixel(), session.point()->posWs, session.scene().camera.eyeWs,
                            session.shadowMap().spec().layers[0].texelWs});
        }
        animation.restore();
        EXPECT_EQ(session.scene().camera.eyeWs, before.eyeWs);
        return seen;
    };
    std::vector<Seen> box = play(1);  // the box fit, turning 0 to 45 degrees
    ASSERT_EQ(box.size(), 3u);
    glm::vec2 axis(box[0].point.x, box[0].point.z);
    for (const Seen& f : box) {
        EXPECT_EQ(f.pixel, box[0].pixel);
        EXPECT_EQ(f.point, box[0].point);
        // The eye keeps its height and its distance from the point's vertical.
        EXPECT_NEAR(f.eye.y, box[0].eye.y, 1e-4f);
        EXPECT_NEAR(glm::distance(glm::vec2(f.eye.x, f.eye.z), axis),
                    glm::distance(glm::vec2(box[0].eye.x, box[0].eye.z), axis), 1e-3f);
    }
    EXPECT_GT(glm::distance(box[2].eye, box[0].eye), 1.0f);
    EXPECT_GT(std::fabs(box[2].texel / box[0].texel - 1.0f), 0.01f) << "a box refitted";
    std::vector<Seen> sphere = play(5);  // the sphere fit, snapped
    for (const Seen& f : sphere) EXPECT_NEAR(f.texel / sphere[0].texel, 1.0f, 1e-4f);
}

}  // namespace
}  // namespace pcf
