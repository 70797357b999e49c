// Words true on every frame: a frame of an animation draws its step's words only where every
// claim of the step holds on that frame, and a caption for the motion in plain words elsewhere;
// no written frame or video carries a hint only the window can act on; `animate --png` writes
// each frame's JSON beside its PNG, whose trace is `pcfscope trace`'s at that frame's lookup.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "app/animation.h"
#include "app/session.h"
#include "json_lite.h"
#include "kernel/trace_explain.h"
#include "lesson/lesson_catalogue.h"
#include "lesson/lesson_claims.h"
#include "lesson/lesson_pick.h"
#include "overlay/inspector.h"
#include "render/gl_context.h"
#include "run_command.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

// The hints of the window's keys, which only its own frames may show.
const char* const WINDOW_HINTS[] = {"Space/Right", "(Right)",   "more Right",  "H: keys",
                                    "Step away",   "step away", "Space plays", ". and , show"};

// Every string of a JSON value (keys' values, arrays' items), depth first.
void stringsOf(const jsonlite::Value& v, std::vector<std::string>& out) {
    if (v.kind == jsonlite::Value::STRING) out.push_back(v.string);
    for (const jsonlite::Value& item : v.array) stringsOf(item, out);
    for (const auto& [key, item] : v.object) stringsOf(item, out);
}

void expectNoWindowHint(const std::string& json, const std::string& where) {
    std::vector<std::string> texts;
    stringsOf(jsonlite::parse(json), texts);
    for (const std::string& t : texts) {
        for (const char* hint : WINDOW_HINTS) {
            EXPECT_EQ(t.find(hint), std::string::npos) << where << ": \"" << hint << "\" in " << t;
        }
    }
}

// The verdict the frame's words must follow: every claim of the step (but a chart's) holds on the
// trace the session composed, with its light, fit and settings of this frame. A motion claim
// (`flickers`) speaks of the step's own sweep: held on its frames, not on another sweep's.
bool claimsHoldOnFrame(const Session& s) {
    const LessonStep& step = s.lesson().steps[static_cast<size_t>(s.step())];
    StepContext ctx =
        makeStepContext(s.settings(), s.pixel(), lightAngleDeg(s.scene(), *s.point()));
    ClaimWorld world;
    world.onPlane = std::holds_alternative<Plane>(
        s.scene().objects[static_cast<size_t>(s.point()->object)].shape);
    bool own = s.motion() && s.motion()->stepsOwn;
    for (const StepClaim& claim : step.claims) {
        if (isChartClaim(claim)) continue;
        if (isMotionClaim(claim) ? !own : !claimHolds(claim, *s.trace(), ctx, world)) return false;
    }
    return true;
}

// The words the frame drew in its step panel: the step-text boxes' text, in order.
std::string drawnStepWords(const jsonlite::Value& frame) {
    std::string words;
    for (const jsonlite::Value& box : frame["layout"].array) {
        if (box["role"].string != "step-text" || !box.has("text")) continue;
        words += box["text"].string;
    }
    return words;
}

// A composed frame of an animation against the verdict: the step's words (page 1 of them) where
// every claim holds, else the caption: what is swept and its value, what the ringed point does,
// why the words are not shown, in plain words (no placeholder, no claim).
void expectWordsFollowTheClaims(const Session& s, const std::string& what, int* captions) {
    const LessonStep& step = s.lesson().steps[static_cast<size_t>(s.step())];
    ASSERT_TRUE(s.trace()) << what;
    ASSERT_TRUE(s.motion()) << what;
    std::string json = s.stepJson();
    jsonlite::Value frame = jsonlite::parse(json);
    std::string drawn = drawnStepWords(frame);
    ASSERT_FALSE(drawn.empty()) << what;
    std::string firstLine = drawn.substr(0, drawn.find('\n'));
    StepContext ctx =
        makeStepContext(s.settings(), s.pixel(), lightAngleDeg(s.scene(), *s.point()));
    std::string stepWords = drawnStepText(fillText(step.text, *s.trace(), ctx));
    if (claimsHoldOnFrame(s)) {
        EXPECT_EQ(frame["words"].string, "step") << what;
        EXPECT_EQ(frame["text"].string, stepWords) << what;
        EXPECT_TRUE(stepWords.starts_with(firstLine)) << what << ": drew " << firstLine;
    } else {
        ++*captions;
        EXPECT_EQ(frame["words"].string, "caption") << what;
        EXPECT_EQ(stepWords.find(firstLine), std::string::npos) << what << ": " << firstLine;
        std::string caption = frame["text"].string;
        EXPECT_TRUE(caption.starts_with(frame["motion"]["words"].string)) << what << caption;
        EXPECT_NE(caption.find("visibility " + formatNumber(s.trace()->visibility)),
                  std::string::npos)
            << what << ": " << caption;
        EXPECT_NE(caption.find("This step's words are not shown on this frame"), std::string::npos)
            << what;
        EXPECT_EQ(caption.find('{'), std::string::npos) << what << ": claim syntax in " << caption;
    }
    expectNoWindowHint(json, what);
    // A video shows no second page, so no note points to one.
    for (const jsonlite::Value& box : frame["layout"].array) {
        if (box.has("text")) {
            EXPECT_EQ(box["text"].string.find("next page"), std::string::npos);
        }
    }
}

struct FrameSize {
    glm::ivec2 size;
    bool presentation;
};

// Every lesson video (each step with `animate`, as `export` writes it and the viewer plays it):
// on every frame at 1280x720 presentation (animate's default), on its first, middle and last at
// 1024x768 presentation and at the 1600x900 handout, the words follow the claims of that frame.
TEST(MotionWords, EveryLessonVideoDrawsItsWordsOnlyOnFramesWhereItsClaimsHold) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    int videos = 0, frames = 0, captions = 0;
    for (const std::string& path : builtInLessons()) {
        Lesson lesson = loadLessonChecked(path);
        for (size_t i = 0; i < lesson.steps.size(); ++i) {
            const LessonStep& step = lesson.steps[i];
            if (!step.animate) continue;
            ++videos;
            // Its claims are on the lookup alone: no split view's parts to read.
            ASSERT_TRUE(step.compare.empty()) << path << " step " << i + 1;
            for (FrameSize f : {FrameSize{{1280, 720}, true}, FrameSize{{1024, 768}, true},
                                FrameSize{{1600, 900}, false}}) {
                Session session(f.size, f.presentation);
                session.loadLesson(path);
                session.goToStep(static_cast<int>(i));
                AnimationOptions ao = stepAnimationOptions(step);
                Animation animation(session, ao);
                bool every = f.size.x == 1280;
                for (int k = 0; k < ao.frames; ++k) {
                    if (!every && k != 0 && k != ao.frames / 2 && k != ao.frames - 1) continue;
                    animation.composeFrame(k);
                    EXPECT_TRUE(session.motion()->stepsOwn);
                    expectWordsFollowTheClaims(session,
                                               lesson.name + " step " + std::to_string(i + 1) +
                                                   " frame " + std::to_string(k + 1) + " at " +
                                                   std::to_string(f.size.x),
                                               &captions);
                    ++frames;
                }
            }
        }
    }
    EXPECT_GE(videos, 2) << "lessons 8 and 13 play";
    EXPECT_GT(frames, 100);
}

// The README's first animation, `animate 13 --step 2 --sweep light`: step 2's words say the ring
// sits in a shadowed texel, which the creeping grid makes false on its frames. Each such frame
// draws the caption instead (before, frame 30 drew "gets 1 ... sits in a shadowed texel").
TEST(MotionWords, TheShimmerSweepOfAStillStepCaptionsTheFramesItsWordsDoNotFit) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    const std::string lesson =
        std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/13-shimmer-and-snapping.toml";
    Session session({1280, 720}, true);
    session.loadLesson(lesson);
    session.goToStep(1);
    AnimationOptions ao;
    ao.sweep = AnimationSweep::Light;
    ao.frames = 32;  // one whole texel of creep
    ao.compareMethod = PCF_GATHER;
    Animation animation(session, ao);
    int captions = 0;
    for (int k = 0; k < ao.frames; ++k) {
        animation.composeFrame(k);
        EXPECT_FALSE(session.motion()->stepsOwn);
        expectWordsFollowTheClaims(session, "frame " + std::to_string(k + 1), &captions);
    }
    EXPECT_GT(captions, 0) << "frame 30 shows the point lit, which the words deny";
    // Put back, the step's still says its words again.
    animation.restore();
    session.compose();
    EXPECT_EQ(session.stepWords().shown, WordsShown::Step);
}

// The window's frames tell how to play and page; the same step written (export, animate) never
// does: the hint list above is what the window draws, so its absence from the files means
// something.
TEST(MotionWords, OnlyTheWindowsFramesNameItsKeys) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    Session session({1024, 768}, true);
    session.loadLesson(std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/08-acne-and-bias.toml");
    session.goToStep(6);
    ASSERT_TRUE(session.lesson().steps[6].animate);
    session.setInteractive(true);
    session.compose();
    std::string window = session.stepJson();
    EXPECT_NE(window.find("Space plays"), std::string::npos);
    EXPECT_NE(window.find("H: keys"), std::string::npos);
    session.setInteractive(false);
    session.compose();
    expectNoWindowHint(session.stepJson(), "lesson 8 step 7 written");
}

// What `export` and `animate` write: every JSON of lessons 8 and 13 at 1024x768 presentation
// (their stills, pages and split views) and the frames of an animation and of a split view's,
// without a hint of the window's keys.
TEST(MotionWords, NoWrittenFrameOrVideoCarriesAWindowHint) {
    fs::path dir = testutil::makeTempDir("hints");
    for (const char* lesson : {"8", "13"}) {
        testutil::CommandResult r =
            testutil::runPcfscope(std::string("export ") + lesson +
                                  " --size 1024x768 --presentation -o " + (dir / lesson).string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    testutil::CommandResult a =
        testutil::runPcfscope("animate 8 --step 7 --frames 3 --png " + (dir / "a").string());
    ASSERT_EQ(a.exitCode, 0) << a.err;
    testutil::CommandResult s = testutil::runPcfscope(
        "animate 1 --sweep sun --point 0.3,0,2.2 --compare bias=none,constant,slope --frames 2 "
        "--size 640x360 --png " +
        (dir / "s").string());
    ASSERT_EQ(s.exitCode, 0) << s.err;
    int jsons = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        if (e.path().extension() != ".json") continue;
        ++jsons;
        expectNoWindowHint(testutil::readAll(e.path()), e.path().filename().string());
    }
    EXPECT_GE(jsons, 14 + 3 + 2);
    if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace pcf
