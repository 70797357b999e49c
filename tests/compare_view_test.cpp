// The split view (app/compare_view.h) and the magnifier (app/magnifier.h): a compare spec is read
// from the command line and from a lesson and refused with one line when wrong; each part shows
// exactly what its setting alone shows at the same point (the same pixels, the same lookup), and
// the difference it states is the difference of those visibilities; under `animate --sweep sun`
// the parts' curves are the curves of three separate animations, one per bias mode, and the
// frames are the same bytes run to run with the right count; the magnifier keeps the point's
// lookup and makes its texel many pixels wide, measured from the GPU's own light-space lookups.
#include "app/compare_view.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "app/animation.h"
#include "app/magnifier.h"
#include "json_lite.h"
#include "render/gl_context.h"
#include "run_command.h"
#include "video_read.h"
#include "virtual_display.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

const std::string LESSON = std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/01-hard-shadows.toml";
// Open ground in lesson 1's view, in front of the box and away from its shadow while the sun
// sets: the acne under no bias is seen there.
constexpr glm::vec3 OPEN_GROUND{0.3f, 0.0f, 2.2f};

TEST(CompareSpec, ReadsKeysWithOneValuePerPartAndRefusesTheRest) {
    CompareSpec spec = parseCompareSpec("bias=none,constant,slope");
    ASSERT_EQ(spec.parts(), 3);
    LessonSettings base;
    base.method = PCF_NEAREST;
    EXPECT_EQ(comparePart(base, spec, 0).bias, BiasMode::None);
    EXPECT_EQ(comparePart(base, spec, 2).bias, BiasMode::Slope);
    EXPECT_EQ(comparePart(base, spec, 2).method, PCF_NEAREST) << "the rest is the base's";
    EXPECT_EQ(comparePartLabel(spec, 1), "bias constant");
    EXPECT_EQ(compareSpecText(spec), "bias=none,constant,slope");

    CompareSpec two = parseCompareSpec("method=nearest,tent kernel=1,5");
    LessonSettings tent = comparePart(base, two, 1);
    EXPECT_EQ(tent.method, PCF_TENT);
    EXPECT_EQ(tent.kernel, 5);
    EXPECT_EQ(comparePartLabel(two, 1), "method tent, kernel 5");
    // A method change alone keeps the kernel when the method takes it, else its smallest.
    base.kernel = 4;
    EXPECT_EQ(comparePart(base, parseCompareSpec("method=nearest,tent"), 1).kernel, 3);
    EXPECT_FLOAT_EQ(comparePart(base, parseCompareSpec("constant_bias=0.001,0.01"), 1).constantBias,
                    0.01f);

    for (const char* bad : {"bias=none", "bias=none,constant,slope,normal", "blur=1,2",
                            "bias=none,wobbly", "bias=none,constant method=tent,nearest,box2x2",
                            "kernel=3,99", "method=tent,nearest kernel=4,4", "bias none,slope",
                            "bias=none,,slope", "map_size=64,64 map_size=32,32", ""}) {
        EXPECT_THROW(
            {
                CompareSpec s = parseCompareSpec(bad);
                for (int i = 0; i < s.parts(); ++i) comparePart(base, s, i);
            },
            std::invalid_argument)
            << bad;
    }
}

TEST(CompareSpec, ALessonStepSaysItAsATableOfArraysCheckedAtItsLine) {
    const std::string head =
        "title = \"t\"\nscene = \"box-on-plane\"\n[[step]]\ntitle = \"s\"\n"
        "text = \"x\"\nmethod = \"nearest\"\n";
    Lesson lesson =
        parseLessonString(head +
                              "compare = { bias = [\"none\", \"constant\"], constant_bias = "
                              "[0.002, 0.004] }\n",
                          "ok.toml");
    const CompareSpec& spec = lesson.steps[0].compare;
    ASSERT_EQ(spec.parts(), 2);
    EXPECT_EQ(compareSpecText(spec), "bias=none,constant constant_bias=0.002,0.004");
    EXPECT_EQ(lesson.steps[0].compareLine, 7);
    for (const char* bad :
         {"compare = { bias = [\"none\"] }", "compare = { bias = \"none\" }",
          "compare = { method = [\"nearest\", \"tent\"], kernel = [4, 4] }", "compare = 3"}) {
        try {
            parseLessonString(head + bad + "\n", "bad.toml");
            ADD_FAILURE() << bad;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("bad.toml:7"), std::string::npos)
                << bad << ": " << e.what();
        }
    }
}

// A session showing lesson 1's first step at OPEN_GROUND (or its own point), as the scene alone.
void showStep(Session& s, glm::ivec2 sceneSize, bool openGround) {
    s.loadLesson(LESSON);
    s.setSceneOnly(true);
    s.setFrameSize(sceneSize);
    if (openGround) s.pinPoint(*seenPoint(s.scene(), OPEN_GROUND));
}

TEST(CompareView, EachPartIsWhatItsSettingAloneShowsAndTheDifferenceIsTheirs) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    const glm::ivec2 frame{640, 360};
    CompareView view(frame, false, parseCompareSpec("method=nearest,pcf-gather,tent"));
    Session main(view.partSceneSize(), false);
    showStep(main, view.partSceneSize(), false);  // the step's point, on the shadow's edge
    view.follow(main);
    view.compose();
    std::vector<uint8_t> frameBytes = view.readFrame();
    ASSERT_EQ(frameBytes.size(), size_t(frame.x) * frame.y * 4);
    glm::ivec2 part = view.partSceneSize();
    for (int i = 0; i < view.parts(); ++i) {
        Session alone(part, false);
        showStep(alone, part, false);
        alone.setSettings(comparePart(main.settings(), view.spec(), i));
        alone.compose();
        ASSERT_TRUE(alone.trace()) << i;
        ASSERT_TRUE(view.visibility(i)) << i;
        EXPECT_EQ(*view.visibility(i), alone.trace()->visibility) << i;
        EXPECT_EQ(alone.pixel(), view.part(i).pixel()) << i;
        // The part's pixels in the frame are the lone session's, byte for byte.
        std::vector<uint8_t> own = alone.readFrame();
        int x0 = static_cast<int>(view.partRect(i).x);
        int mismatched = 0;
        for (int y = 0; y < part.y; ++y) {
            for (int x = 0; x < part.x * 4; ++x) {
                mismatched += frameBytes[(size_t(y) * frame.x + x0) * 4 + x] !=
                              own[size_t(y) * part.x * 4 + x];
            }
        }
        EXPECT_EQ(mismatched, 0) << "part " << i;
        if (i > 0) {
            ASSERT_TRUE(view.difference(i));
            EXPECT_EQ(*view.difference(i), *view.visibility(i) - *view.visibility(0));
        }
    }
    // On the shadow's edge the three filters disagree: the differences are not zeros.
    EXPECT_NE(*view.visibility(0), *view.visibility(1));
    EXPECT_NE(view.json().find("\"label\":\"method tent\""), std::string::npos) << view.json();
}

// The split view answers as the lesson's frame does: the same status line along the bottom, its
// words the main view's and then what is compared, and the key list over everything while H
// (the main view's help) is on; the parts stay above the status line.
TEST(CompareView, HasTheLessonFramesStatusLineAndItsHelp) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    for (bool presentation : {false, true}) {
        const glm::ivec2 frame{1280, 720};
        Session main(frame, presentation);
        main.loadLesson(LESSON);
        CompareView view(frame, presentation, parseCompareSpec("bias=none,constant,slope"));
        const Rect single = inspectorLayout(frame, presentation).status;
        for (bool help : {false, true}) {
            SCOPED_TRACE(std::string(presentation ? "presentation" : "normal") +
                         (help ? ", help" : ""));
            main.setHelp(help);
            // The window's frame (help is the window's key) names H; a written one does not.
            main.setInteractive(help);
            view.follow(main);
            view.compose();
            EXPECT_EQ(view.status(), main.statusText() + "   compare bias=none,constant,slope");
            Rect statusPanel;
            std::string words;
            bool keysHint = false, helpShown = false;
            for (const LayoutBox& b : view.boxes()) {
                if (b.role == "status" && b.kind == BoxKind::Panel) statusPanel = b.rect;
                if (b.role == "status" && b.kind == BoxKind::Text) {
                    words = b.text;
                    EXPECT_TRUE(b.text == view.status() || b.shortened) << b.text;
                }
                keysHint |= b.role == "keys-hint";
                helpShown |= b.role == "help";
            }
            EXPECT_EQ(statusPanel, single) << "where the lesson's frame has it";
            EXPECT_TRUE(words.starts_with(main.statusText().substr(0, 20))) << words;
            EXPECT_EQ(keysHint, help) << "H: keys is the window's hint, not a written frame's";
            EXPECT_EQ(helpShown, help);
            for (int i = 0; i < view.parts(); ++i) {
                EXPECT_LE(view.partRect(i).bottom(), statusPanel.y) << "part " << i;
            }
            EXPECT_NE(view.json().find("\"status\":"), std::string::npos);
        }
    }
}

TEST(CompareView, SunSweepPartsAreThreeAnimationsOfOneBiasEach) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    const glm::ivec2 frame{640, 360};
    CompareSpec spec = parseCompareSpec("bias=none,constant,slope");
    AnimationOptions ao;
    ao.sweep = AnimationSweep::Sun;
    ao.frames = 5;
    CompareView view(frame, false, spec);
    view.setTraceBand(true);
    Session main(view.partSceneSize(), false);
    showStep(main, view.partSceneSize(), true);
    Animation split(main, ao, view);
    std::vector<std::vector<float>> drawn(3);
    for (int k = 0; k < ao.frames; ++k) {
        split.composeFrame(k);
        for (int i = 1; i < 3; ++i) {
            ASSERT_TRUE(view.difference(i));
            EXPECT_EQ(*view.difference(i), split.partCurve(i)[k] - split.partCurve(0)[k]);
        }
    }
    bool disagree = false;
    for (int i = 0; i < 3; ++i) {
        Session alone(view.partSceneSize(), false);
        showStep(alone, view.partSceneSize(), true);
        alone.setSettings(comparePart(alone.settings(), spec, i));
        AnimationOptions one = ao;
        one.compareMethod = -1;
        Animation single(alone, one);
        for (int k = 0; k < ao.frames; ++k) single.composeFrame(k);
        ASSERT_EQ(split.partCurve(i).size(), size_t(ao.frames));
        for (int k = 0; k < ao.frames; ++k) {
            EXPECT_EQ(split.partCurve(i)[k], single.curve()[k]) << "part " << i << " frame " << k;
            disagree = disagree || split.partCurve(i)[k] != split.partCurve(0)[k];
        }
    }
    EXPECT_TRUE(disagree) << "no bias and a bias differ somewhere as the sun sets (acne)";
    EXPECT_EQ(split.partCurve(1).front(), 1.0f) << "a constant bias: lit at noon";
}

TEST(AnimateCommand, ThreeBiasSunSetIsTheSameBytesRunToRunWithEveryFrame) {
    fs::path dir = testutil::makeTempDir("compare");
    std::string common =
        "animate 1 --sweep sun --frames 4 --size 640x360 --point 0.3,0,2.2 "
        "--compare bias=none,constant,slope ";
    for (const char* run : {"a", "b"}) {
        std::string d = (dir / run).string();
        testutil::CommandResult r =
            testutil::runPcfscope(common + "--png " + d + "/png -o " + d + "/sun.mp4");
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    for (int k = 1; k <= 4; ++k) {
        std::string name = "png/01-hard-shadows-step01-sun-000" + std::to_string(k) + ".png";
        ASSERT_TRUE(fs::exists(dir / "a" / name)) << name;
        EXPECT_EQ(testutil::readAll(dir / "a" / name), testutil::readAll(dir / "b" / name)) << name;
    }
    EXPECT_FALSE(fs::exists(dir / "a/png/01-hard-shadows-step01-sun-0005.png"));
    testutil::expectMp4(testutil::readVideo((dir / "a/sun.mp4").string()), 640, 360, 4);
    // Bad splits: one line, exit 2, nothing made.
    std::string out = (dir / "new").string();
    for (std::string args : {"--compare bias=none", "--compare blur=1,2",
                             "--compare bias=none,constant --size 320x180", "--point 0,5,0",
                             "--compare bias=none,wobbly"}) {
        testutil::CommandResult r =
            testutil::runPcfscope("animate 1 --frames 2 " + args + " -o " + out + "/x.mp4");
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << args << ": " << r.err;
        EXPECT_FALSE(fs::exists(out)) << args;
    }
    fs::remove_all(dir);
}

// The lines of `text` from the one holding `marker` through its command's last line (the lines
// that end in a backslash run on), the command joined into one line without "pcfscope ".
std::string guideCommandAfter(const std::string& text, const std::string& marker) {
    size_t at = text.find(marker);
    if (at == std::string::npos) return "";
    size_t start = text.find("\npcfscope ", at);
    if (start == std::string::npos) return "";
    std::string command;
    for (size_t line = start + 1;;) {
        size_t end = text.find('\n', line);
        std::string l = text.substr(line, end - line);
        bool more = !l.empty() && l.back() == '\\';
        if (more) l.pop_back();
        command += l;
        if (!more || end == std::string::npos) break;
        line = end + 1;
    }
    return command.substr(std::string("pcfscope ").size());
}

// The user guide's creep example, run exactly as the guide prints it: its words say "nearest
// and tent 3: a jump against a ramp". The split view's parts are nearest and tent 3 (before, the
// step's kernel 5 drew tent 5 under an acne the words never named); nearest's line goes from 0
// to 1 in one frame, tent 3's never moves by a twentieth between frames and climbs from 0.1 to
// 0.9 over some forty frames, as the paragraph under the example says.
TEST(AnimateCommand, TheUserGuidesCreepExampleShowsWhatItsWordsSay) {
    std::string guide = testutil::readAll(std::string(PCFSCOPE_SOURCE_DIR) + "/docs/user-guide.md");
    const std::string marker = "# one point's visibility under a creeping camera";
    size_t at = guide.find(marker);
    ASSERT_NE(at, std::string::npos);
    std::string words = guide.substr(at, guide.find('\n', at) - at);
    EXPECT_NE(words.find("nearest and tent 3: a jump against a ramp"), std::string::npos) << words;
    EXPECT_NE(guide.find("climbs from 0.1 to 0.9 over some forty frames"), std::string::npos);
    std::string command = guideCommandAfter(guide, marker);
    ASSERT_NE(command.find("-o creep.mp4"), std::string::npos) << command;
    fs::path dir = testutil::makeTempDir("creep");
    testutil::CommandResult r = testutil::runPcfscope(command, "cd " + dir.string() + " &&");
    ASSERT_EQ(r.exitCode, 0) << command << ": " << r.err;
    testutil::expectMp4(testutil::readVideo((dir / "creep.mp4").string()), 1280, 720, 72);
    // The same frames with their JSON, to read the parts' labels and lines.
    testutil::CommandResult png =
        testutil::runPcfscope(command + " --png frames -f", "cd " + dir.string() + " &&");
    ASSERT_EQ(png.exitCode, 0) << png.err;
    std::vector<float> nearest, tent;
    for (int k = 1; k <= 72; ++k) {
        char name[64];
        std::snprintf(name, sizeof name, "frames/13-shimmer-and-snapping-step03-camera-%04d.json",
                      k);
        jsonlite::Value frame = jsonlite::parse(testutil::readAll(dir / name));
        ASSERT_EQ(frame["parts"].size(), 2u);
        EXPECT_EQ(frame["parts"][size_t{0}]["label"].string.find("method nearest"), 0u);
        EXPECT_EQ(frame["parts"][size_t{1}]["label"].string, "method tent, kernel 3");
        nearest.push_back(static_cast<float>(frame["parts"][size_t{0}]["visibility"].number));
        tent.push_back(static_cast<float>(frame["parts"][size_t{1}]["visibility"].number));
    }
    int nearestChanges = 0, rising10 = -1, rising90 = -1;
    float tentJump = 0.0f;
    for (size_t k = 0; k < tent.size(); ++k) {
        EXPECT_TRUE(nearest[k] == 0.0f || nearest[k] == 1.0f) << k;
        if (k > 0) {
            nearestChanges += nearest[k] != nearest[k - 1];
            tentJump = std::max(tentJump, std::fabs(tent[k] - tent[k - 1]));
        }
        if (rising10 < 0 && tent[k] > 0.1f) rising10 = static_cast<int>(k);
        if (rising90 < 0 && tent[k] > 0.9f) rising90 = static_cast<int>(k);
    }
    EXPECT_EQ(nearest.front(), 0.0f);
    EXPECT_EQ(nearest.back(), 1.0f);
    EXPECT_EQ(nearestChanges, 1) << "one jump";
    EXPECT_LT(tentJump, 0.05f) << "a ramp";
    ASSERT_GE(rising10, 0);
    ASSERT_GE(rising90, 0);
    EXPECT_GE(rising90 - rising10, 35);
    EXPECT_LE(rising90 - rising10, 50);
    if (!HasFailure()) fs::remove_all(dir);
}

// The texel steps on screen at the session's pinned pixel, from the GPU's light-space lookups
// of pixels `d` apart (the trace's uv at each): the columns of d(pixel)/d(texel).
glm::vec2 measuredTexelPixels(Session& s, int d) {
    glm::ivec2 p = s.pixel();
    auto uvAt = [&](glm::ivec2 q) {
        s.setPixel(q);
        s.compose();
        EXPECT_TRUE(s.trace());
        return s.trace() ? s.trace()->uv * float(s.settings().mapSize) : glm::vec2(0.0f);
    };
    glm::vec2 at = uvAt(p);
    glm::vec2 du = (uvAt(p + glm::ivec2(d, 0)) - at) / float(d);  // texels per pixel right
    glm::vec2 dv = (uvAt(p + glm::ivec2(0, d)) - at) / float(d);  // texels per pixel down
    glm::mat2 pixelsPerTexel = glm::inverse(glm::mat2(du, dv));
    return {glm::length(pixelsPerTexel[0]), glm::length(pixelsPerTexel[1])};
}

TEST(Magnifier, KeepsThePointsLookupAndATexelIsManyPixelsWide) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    const glm::ivec2 size{640, 360};
    Session s(size, false);
    s.loadLesson(LESSON);
    s.setSceneOnly(true);
    s.compose();
    ASSERT_TRUE(s.trace());
    Trace wide = *s.trace();
    glm::vec3 point = s.point()->posWs;
    glm::vec2 widePx = measuredTexelPixels(s, 4);
    EXPECT_LT(std::min(widePx.x, widePx.y), 4.0f) << "the wide view: a texel is a few pixels";

    s.pinPoint(*seenPoint(s.scene(), point));
    Camera lessonCamera = s.scene().camera;
    magnifySession(s, lessonCamera);
    s.compose();
    ASSERT_TRUE(s.trace());
    EXPECT_EQ(s.point()->posWs, point);
    EXPECT_NEAR(s.trace()->uv.x, wide.uv.x, 1e-6f);
    EXPECT_NEAR(s.trace()->uv.y, wide.uv.y, 1e-6f);
    EXPECT_EQ(s.trace()->visibility, wide.visibility);
    float k = size.y / MAGNIFIER_TEXELS_ACROSS;  // 22.5 px
    glm::vec2 px = measuredTexelPixels(s, 2);
    EXPECT_GE(std::min(px.x, px.y), 0.95f * k) << px.x << " x " << px.y;
    EXPECT_LE(std::min(px.x, px.y), 1.5f * k) << "the close-up still shows a neighbourhood";
}

// A step with `magnify = true` is seen through the magnifier's close-up on its point: the same
// lookup as in the lesson's own view, a texel a sixteenth of the scene's height; a step that only
// slides the grid keeps that very camera (the pictures differ by the slide alone), and a step
// without `magnify` is seen through the lesson's camera again.
TEST(Magnifier, AStepsMagnifyKeyShowsTheCloseUp) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    fs::path dir = testutil::makeTempDir("magnifystep");
    std::string lesson = (dir / "magnify.toml").string();
    {
        std::ofstream f(lesson);
        f << "title = \"Magnify\"\nscene = \"box-on-plane\"\n[settings]\nmethod = \"nearest\"\n"
             "map_size = 256\ncull = \"front\"\npoint = [1.47568, 0, 0.03772]\n"
             "[[step]]\ntitle = \"Wide\"\ntext = \"x\"\n"
             "[[step]]\ntitle = \"Close\"\nmagnify = true\ntext = \"x\"\n"
             "[[step]]\ntitle = \"Slid\"\norigin_shift = 0.25\ntext = \"x\"\n"
             "[[step]]\ntitle = \"Wide again\"\nmagnify = false\norigin_shift = 0\ntext = \"x\"\n";
    }
    const glm::ivec2 size{640, 360};
    Session s(size, false);
    s.loadLesson(lesson);
    s.setSceneOnly(true);
    const Camera lessonCamera = s.scene().camera;
    s.compose();
    ASSERT_TRUE(s.trace());
    Trace wide = *s.trace();

    s.goToStep(1);
    s.compose();
    ASSERT_TRUE(s.trace());
    EXPECT_NE(s.scene().camera.eyeWs, lessonCamera.eyeWs);
    EXPECT_NEAR(s.trace()->uv.x, wide.uv.x, 1e-6f);
    EXPECT_NEAR(s.trace()->uv.y, wide.uv.y, 1e-6f);
    EXPECT_EQ(s.trace()->visibility, wide.visibility);
    const Camera close = s.scene().camera;
    float k = size.y / MAGNIFIER_TEXELS_ACROSS;  // 22.5 px
    glm::vec2 px = measuredTexelPixels(s, 2);
    EXPECT_GE(std::min(px.x, px.y), 0.95f * k) << px.x << " x " << px.y;
    EXPECT_LE(std::min(px.x, px.y), 1.5f * k) << px.x << " x " << px.y;

    s.goToStep(2);  // magnify inherited; only the grid slid
    s.compose();
    EXPECT_EQ(s.scene().camera.eyeWs, close.eyeWs);
    EXPECT_EQ(s.scene().camera.targetWs, close.targetWs);
    ASSERT_TRUE(s.trace());
    EXPECT_NEAR(s.trace()->uv.x * 256.0f, wide.uv.x * 256.0f + 0.25f, 1e-3f);

    s.goToStep(3);
    s.compose();
    EXPECT_EQ(s.scene().camera.eyeWs, lessonCamera.eyeWs);
    EXPECT_EQ(s.scene().camera.targetWs, lessonCamera.targetWs);
    ASSERT_TRUE(s.trace());
    EXPECT_NEAR(s.trace()->uv.x, wide.uv.x, 1e-6f);
    fs::remove_all(dir);
}

// A lesson step's own `compare` is exported beside its frame; a step without one is not; the
// JSON's differences are its parts' visibilities' differences. A bad --compare is one line,
// exit 2, and nothing is written.
TEST(ExportCompare, AStepsOwnCompareIsWrittenBesideItsFrame) {
    fs::path dir = testutil::makeTempDir("exportsplit");
    std::string lesson = (dir / "split.toml").string();
    {
        std::ofstream f(lesson);
        f << "title = \"Split\"\nscene = \"box-on-plane\"\n[settings]\nmethod = \"nearest\"\n"
             "map_size = 256\npoint = [1.3287, 0, 0.8441]\n"
             "[[step]]\ntitle = \"One\"\ntext = \"x\"\n"
             "[[step]]\ntitle = \"Two\"\ntext = \"y\"\n"
             "compare = { method = [\"nearest\", \"pcf-gather\", \"tent\"] }\n";
    }
    auto r =
        testutil::runPcfscope("export " + lesson + " --size 1024x768 -o " + (dir / "out").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out/split-step01-compare.png"));
    ASSERT_TRUE(fs::exists(dir / "out/split-step02-compare.png"));
    jsonlite::Value j = jsonlite::parse(testutil::readAll(dir / "out/split-step02-compare.json"));
    EXPECT_EQ(j["compare"].string, "method=nearest,pcf-gather,tent");
    const auto& parts = j["parts"].array;
    ASSERT_EQ(parts.size(), 3u);
    EXPECT_EQ(parts[2]["label"].string, "method tent");
    for (size_t i = 1; i < parts.size(); ++i) {
        EXPECT_NEAR(parts[i]["difference"].number,
                    parts[i]["visibility"].number - parts[0]["visibility"].number, 1e-6);
        EXPECT_EQ(parts[i]["visibility"].number, parts[i]["trace"]["visibility"].number);
    }
    std::string out = (dir / "bad").string();
    for (std::string args :
         {"--compare bias=none", "--compare \"method=nearest,tent kernel=3,4\" --steps 2",
          "--compare bias=none,slope --size 320x180"}) {
        auto bad = testutil::runPcfscope("export " + lesson + " " + args + " -o " + out);
        EXPECT_EQ(bad.exitCode, 2) << args << ": " << bad.err;
        EXPECT_EQ(testutil::lineCount(bad.err), 1) << args << ": " << bad.err;
        EXPECT_FALSE(fs::exists(out)) << args;
    }
    fs::remove_all(dir);
}

// The viewer's C and Z, replayed by --keys: the window shows exactly the frames `export
// --compare` and `export --magnify` write (the same code composes them), and Z again is the
// lesson's own frame.
TEST(ViewKeys, CIsTheSplitViewAndZTheMagnifierAsExportWritesThem) {
    testutil::VirtualDisplay x;
    ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
    fs::path dir = testutil::makeTempDir("viewsplit");
    std::string d = dir.string();
    auto view = [&](const std::string& keys, const std::string& shot) {
        testutil::CommandResult r =
            testutil::runPcfscope("view 1 --keys \"" + keys + "\" --screenshot " + d + "/" + shot,
                                  "DISPLAY=" + x.display());
        EXPECT_EQ(r.exitCode, 0) << keys << ": " << r.err;
    };
    view("c", "c.png");
    view("z", "z.png");
    view("z z", "zz.png");
    view("z right", "zr.png");  // the next step's point, found in the lesson's view, magnified
    auto split = testutil::runPcfscope(
        "export 1 --steps 1 --compare method=nearest,pcf-gather -o " + d + "/split");
    ASSERT_EQ(split.exitCode, 0) << split.err;
    auto magnified = testutil::runPcfscope("export 1 --steps 1-2 --magnify -o " + d + "/magnified");
    ASSERT_EQ(magnified.exitCode, 0) << magnified.err;
    auto plain = testutil::runPcfscope("export 1 --steps 1 -o " + d + "/plain");
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    const std::string stem = "/01-hard-shadows-step01";
    EXPECT_EQ(testutil::readAll(d + "/c.png"),
              testutil::readAll(d + "/split" + stem + "-compare.png"));
    EXPECT_EQ(testutil::readAll(d + "/z.png"), testutil::readAll(d + "/magnified" + stem + ".png"));
    EXPECT_NE(testutil::readAll(d + "/z.png"), testutil::readAll(d + "/plain" + stem + ".png"));
    EXPECT_EQ(testutil::readAll(d + "/zr.png"),
              testutil::readAll(d + "/magnified/01-hard-shadows-step02.png"));
    EXPECT_EQ(testutil::readAll(d + "/zz.png"), testutil::readAll(d + "/plain" + stem + ".png"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace pcf
