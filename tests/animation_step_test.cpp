// A lesson step that is an animation (`animate = {...}`, lesson.h: StepAnimation): export writes
// it as an MP4 beside the still with the step's frames and the frame size, the same bytes run to
// run; a bad `animate` is one line at its line; the viewer's frame keys show the sweep's frames.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include "app/animation.h"
#include "json_lite.h"
#include "render/gl_context.h"
#include "run_command.h"
#include "video_read.h"
#include "virtual_display.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

class AnimationStep : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("animation-step"); }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }
    // A still step, then a step whose constant bias grows over the frames (`animate` is the
    // step's table's last line, line 12).
    std::string write(const std::string& animate, const std::string& name = "anim.toml") {
        std::string path = (mDir / name).string();
        std::ofstream(path) << "title = \"Anim\"\n"                 // 1
                               "scene = \"box-on-plane\"\n"         // 2
                               "[settings]\n"                       // 3
                               "method = \"nearest\"\n"             // 4
                               "map_size = 128\n"                   // 5
                               "[[step]]\n"                         // 6
                               "title = \"Still\"\n"                // 7
                               "text = \"v {visibility}\"\n"        // 8
                               "[[step]]\n"                         // 9
                               "title = \"Moving\"\n"               // 10
                               "text = \"bias {constant_bias}\"\n"  // 11
                            << "animate = " << animate << "\n";     // 12
        return path;
    }
    fs::path mDir;
};

constexpr const char* BIAS_SWEEP =
    "{ sweep = \"bias\", from = 0.001, to = 0.1, frames = 5, fps = 10 }";

TEST_F(AnimationStep, ExportWritesAnMp4OfTheStepsFramesTheSameBytesRunToRun) {
    std::string lesson = write(BIAS_SWEEP);
    for (const char* out : {"a", "b"}) {
        testutil::CommandResult r = testutil::runPcfscope(
            "export " + lesson + " -o " + (mDir / out).string() + " --size 320x180");
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    EXPECT_FALSE(fs::exists(mDir / "a/anim-step01.mp4")) << "a still step has no video";
    EXPECT_TRUE(fs::exists(mDir / "a/anim-step02.png"));
    testutil::expectMp4(testutil::readVideo((mDir / "a/anim-step02.mp4").string()), 320, 180, 5);
    EXPECT_EQ(testutil::readAll(mDir / "a/anim-step02.mp4"),
              testutil::readAll(mDir / "b/anim-step02.mp4"));
    // An odd size cannot be an MP4: refused before anything is written.
    testutil::CommandResult odd = testutil::runPcfscope(
        "export " + lesson + " -o " + (mDir / "odd").string() + " --size 321x180");
    EXPECT_EQ(odd.exitCode, 2);
    EXPECT_EQ(testutil::lineCount(odd.err), 1) << odd.err;
    EXPECT_FALSE(fs::exists(mDir / "odd"));
}

TEST_F(AnimationStep, BadAnimateIsOneLineAtItsLine) {
    struct Bad {
        std::string animate, says;
    };
    for (const Bad& bad : {Bad{"{ sweep = \"moon\" }", "sweep 'moon' is not one of"},
                           Bad{"{ sweep = \"light\", from = 2 }", "has no from / to"},
                           Bad{"{ sweep = \"sun\", to = 0 }", "must be in [1, 90]"},
                           Bad{"{ sweep = \"sun\", frames = 1 }", "frames must be"},
                           Bad{"{ sweep = \"sun\", speed = 2 }", "unknown key 'speed'"},
                           Bad{"\"sun\"", "animate must be a table"}}) {
        std::string lesson = write(bad.animate);
        testutil::CommandResult r = testutil::runPcfscope("lesson check " + lesson);
        EXPECT_EQ(r.exitCode, 2) << bad.animate;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find("anim.toml:12:"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(bad.says), std::string::npos) << r.err;
    }
}

// The viewer shows frame k after k presses of `.` (`,` goes back; a settings key starts again
// from frame 0): the bias sweep's frame is its constant bias, which the E key's JSON holds.
TEST_F(AnimationStep, TheViewersFrameKeysShowTheSweepsFrames) {
    std::string lesson = write(BIAS_SWEEP);
    testutil::VirtualDisplay x;
    ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
    AnimationOptions o;
    o.sweep = AnimationSweep::Bias;
    o.frames = 5;
    o.from = 0.001;
    o.to = 0.1;
    struct Case {
        std::string keys;
        int frame;
    };
    for (const Case& c : {Case{"right period period e", 2}, Case{"right period period comma e", 1},
                          Case{"right period period v e", 0}}) {
        fs::remove_all(mDir / "pcfscope-frames");
        testutil::CommandResult r =
            testutil::runPcfscope("view " + lesson + " --keys \"" + c.keys + "\" --screenshot " +
                                      (mDir / "shot.png").string() + " -f",
                                  "cd " + mDir.string() + " && DISPLAY=" + x.display());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        jsonlite::Value step =
            jsonlite::parse(testutil::readAll(mDir / "pcfscope-frames/anim-step02.json"));
        // The JSON rounds to two digits; the frames' values are 0.001, 0.0032, 0.01.
        double want = animationSweepValue(o, c.frame);
        EXPECT_NEAR(step["settings"]["constant_bias"].number, want, 0.02 * want) << c.keys;
    }
}

// One composed animation frame: a `trace` panel off the scene, steps and inspector, above the
// status line, its title and two labels whole inside it; the step's words unshortened, no
// "more" mark in the step panel.
void expectTraceAndWordsWhole(const Session& session, int k) {
    std::map<std::string, Rect> panels;
    for (const LayoutBox& b : session.boxes()) {
        if (b.kind == BoxKind::Panel) panels[b.panel] = b.rect;
    }
    ASSERT_TRUE(panels.count("trace")) << "frame " << k;
    const Rect& trace = panels["trace"];
    EXPECT_TRUE(trace.intersect(panels["scene"]).empty());
    EXPECT_TRUE(trace.intersect(panels["steps"]).empty());
    EXPECT_TRUE(trace.intersect(panels["inspector"]).empty());
    EXPECT_LE(trace.bottom(), panels["status"].y);
    int titles = 0, labels = 0;
    for (const LayoutBox& b : session.boxes()) {
        if (b.role == "step-text" || (b.panel == "steps" && b.role == "more")) {
            EXPECT_FALSE(b.shortened || b.role == "more") << "frame " << k;
        }
        if (b.panel != "trace" || b.kind == BoxKind::Panel) continue;
        titles += b.role == "trace-title";
        labels += b.role == "trace-label";
        EXPECT_FALSE(b.shortened) << b.text;
        EXPECT_TRUE(b.rect.x >= trace.x && b.rect.right() <= trace.right() + 0.5f &&
                    b.rect.y >= trace.y && b.rect.bottom() <= trace.bottom() + 0.5f)
            << b.text << " runs out of the panel";
    }
    EXPECT_EQ(titles, 1);
    EXPECT_EQ(labels, 2) << "the method on screen and its comparison";
}

// The lessons' animation steps as their MP4s show them (`export 8 --steps 7`, the viewer playing
// them), at the projector sizes and the handout's: the flicker trace has a room of its own, off
// the scene (whose acne or stairs the frames show) and off the step's words, with its title and
// both labels whole; the words are whole on the first page, since a video never shows a second.
TEST(AnimationFrames, LessonAnimationsShowTheSceneTheTraceAndTheWordsWhole) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    struct Frame {
        glm::ivec2 size;
        bool presentation;
    };
    struct Moving {
        const char* name;
        int step;  // 0-based
    };
    // Lesson 22's last: the camera turning with a cascaded map.
    for (Moving m : {Moving{"08-acne-and-bias", 6}, Moving{"13-shimmer-and-snapping", 6},
                     Moving{"22-cascades-that-do-not-shimmer", 5}}) {
        const std::string lesson =
            std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/" + m.name + ".toml";
        for (Frame f :
             {Frame{{1280, 720}, true}, Frame{{1024, 768}, true}, Frame{{1600, 900}, false}}) {
            SCOPED_TRACE(std::string(m.name) + " step " + std::to_string(m.step + 1) + " at " +
                         std::to_string(f.size.x) + "x" + std::to_string(f.size.y) +
                         (f.presentation ? " presentation" : ""));
            Session session(f.size, f.presentation);
            session.loadLesson(lesson);
            session.goToStep(m.step);
            const LessonStep& step = session.lesson().steps[static_cast<size_t>(m.step)];
            ASSERT_TRUE(step.animate);
            AnimationOptions ao = stepAnimationOptions(step);
            Animation animation(session, ao);
            for (int k : {0, ao.frames - 1}) {
                animation.composeFrame(k);
                expectTraceAndWordsWhole(session, k);
            }
        }
    }
}

}  // namespace
}  // namespace pcf
