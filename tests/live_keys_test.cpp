// The live controls (app/live_keys.h, lesson/lesson_keys.h): every key reachable from --keys
// changes the session's state as the key table says, the status line lists what differs from the
// step, `export --keys` and `view --keys` (clicks included) agree, and `lesson check` presses the
// sun keys with the sun moved.
#include "app/live_keys.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "app/cli_util.h"
#include "app/session.h"
#include "app/step_words.h"
#include "json_lite.h"
#include "kernel/settings.h"
#include "lesson/lesson_keys.h"
#include "lesson/lesson_pick.h"
#include "render/gl_context.h"
#include "run_command.h"
#include "virtual_display.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

// pcf-gather with gaussian weights (so W and I act), a lit ground point of the box scene, whose
// sun is 50 degrees from the zenith (scene/presets.cpp): the light angle there is 50 degrees.
// `claims` and `keys` are the step's.
std::string lessonText(const std::string& claims, const std::string& keys) {
    return "title = \"Keys\"\n"
           "scene = \"box-on-plane\"\n"
           "[settings]\n"
           "method = \"pcf-gather\"\n"
           "weights = \"gaussian\"\n"
           "map_size = 256\n"
           "constant_bias = 0.002\n"
           "point = [-1.5, 0, 1.5]\n"
           "[[step]]\n"
           "title = \"One\"\n"
           "text = \"visibility {visibility}\"\n" +
           (claims.empty() ? "" : "claims = [" + claims + "]\n") +
           (keys.empty() ? "" : "keys = [" + keys + "]\n");
}

class LiveKeys : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    void SetUp() override { mDir = testutil::makeTempDir("live-keys"); }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }
    std::string write(const std::string& text, const std::string& name = "keys.toml") {
        std::string path = (mDir / name).string();
        std::ofstream(path) << text;
        return path;
    }
    // Presses one --keys token on the session, as `view` and `export` do.
    static void press(Session& session, const std::string& token) {
        std::vector<ScriptedInput> in = parseScriptedInput(token);
        ASSERT_EQ(in.size(), 1u);
        ASSERT_FALSE(in[0].click);
        ASSERT_TRUE(isLiveKey(in[0].key)) << token;
        ASSERT_TRUE(pressLiveKey(session, in[0].key)) << token;
    }
    static std::unique_ptr<GlContext> sContext;
    fs::path mDir;
};
std::unique_ptr<GlContext> LiveKeys::sContext;

// The sun's compass heading (degrees) of a light direction.
float headingDeg(const Light& light) {
    return glm::degrees(std::atan2(light.directionWs.z, light.directionWs.x));
}

TEST_F(LiveKeys, EveryNewKeyIsReachableFromKeysAndChangesWhatItSays) {
    Session session({640, 360}, false);
    session.loadLesson(write(lessonText("", "")));
    session.compose();
    const LessonSettings step = session.settings();
    ASSERT_TRUE(session.trace());
    const Trace before = *session.trace();
    const Light light = session.scene().light;

    press(session, "v");  // 0.002 -> the next step up
    EXPECT_EQ(session.settings().constantBias, 0.005f);
    press(session, "shift+v");
    EXPECT_EQ(session.settings(), step) << "V then Shift+V is the step again";

    press(session, "u");
    session.compose();
    EXPECT_NEAR(lightElevationDeg(session.scene().light),
                lightElevationDeg(light) + SUN_TILT_STEP_DEG, 1e-3);
    EXPECT_NEAR(headingDeg(session.scene().light), headingDeg(light), 1e-3);
    ASSERT_TRUE(session.trace());
    EXPECT_NE(session.trace()->uv, before.uv) << "the map is rendered from the moved sun";
    press(session, "shift+u");
    press(session, "t");
    session.compose();
    EXPECT_NEAR(std::remainder(headingDeg(light) - headingDeg(session.scene().light), 360.0f),
                SUN_TURN_STEP_DEG, 1e-3);
    EXPECT_NEAR(lightElevationDeg(session.scene().light), lightElevationDeg(light), 1e-3);
    press(session, "shift+t");
    session.compose();
    EXPECT_NEAR(glm::distance(session.scene().light.directionWs, light.directionWs), 0.0f, 1e-5f);

    press(session, "i");
    EXPECT_EQ(session.settings().sigma, 1.4f);
    press(session, "w");  // gaussian -> box
    EXPECT_EQ(session.settings().weights, PCF_WEIGHTS_BOX);
    press(session, "i");  // sigma means nothing to box weights: unchanged
    EXPECT_EQ(session.settings().sigma, 1.4f);
    press(session, "shift+w");
    EXPECT_EQ(session.settings().weights, PCF_WEIGHTS_GAUSSIAN);

    press(session, "k");
    EXPECT_EQ(session.settings().cull, CullMode::Front);
    press(session, "d");
    EXPECT_EQ(session.settings().depthFormat, TexelKind::D16);

    session.compose();
    std::vector<uint8_t> marked = session.readFrame();
    press(session, "x");
    EXPECT_FALSE(session.markers());
    session.compose();
    EXPECT_NE(session.readFrame(), marked);
    EXPECT_EQ(session.stepJson().find("picked-pixel"), std::string::npos) << "the ring is gone";
    press(session, "x");
    session.compose();
    EXPECT_EQ(session.readFrame(), marked);
}

// The status line names every setting the keys changed from the step's, and only those.
TEST_F(LiveKeys, TheStatusLineListsWhatDiffersFromTheStep) {
    Session session({960, 540}, false);
    session.loadLesson(write(lessonText("", "")));
    session.compose();
    EXPECT_EQ(session.model().status.find("keys:"), std::string::npos) << session.model().status;
    // The box scene's sun is 40.08 degrees up (scene/presets.cpp); Shift+U lowers it by 5.
    for (const char* key : {"v", "k", "shift+u", "t"}) press(session, key);
    session.compose();
    std::string status = session.model().status;
    for (const char* said :
         {"keys: constant_bias 0.005", "cull front", "sun 35.1 deg up", "sun turned 15 deg"}) {
        EXPECT_NE(status.find(said), std::string::npos) << said << " in " << status;
    }
    EXPECT_EQ(status.find("depth_format"), std::string::npos) << status;
    // Going back to the step gives the step's state, so nothing is listed.
    session.goToStep(0);
    EXPECT_EQ(session.model().status.find("keys:"), std::string::npos);
}

// A key that makes a claim of the step false withholds its words: the claim holds at the step's
// light angle (50 degrees) and 5 degrees steeper (U), not 5 degrees flatter (Shift+U).
TEST_F(LiveKeys, ASunKeyThatMakesAClaimFalseWithholdsTheWords) {
    Session session({960, 540}, false);
    session.loadLesson(write(lessonText("\"{light_angle} < 52\"", "")));
    session.compose();
    EXPECT_EQ(session.stepText().find("not shown"), std::string::npos) << session.stepText();
    press(session, "u");
    session.compose();
    EXPECT_EQ(session.stepText().find("not shown"), std::string::npos) << session.stepText();
    EXPECT_NE(session.stepText().find("now pcf-gather"), std::string::npos) << session.stepText();
    EXPECT_NE(session.stepText().find("sun +5 deg"), std::string::npos) << session.stepText();
    EXPECT_EQ(session.stepWords().shown, WordsShown::Noted);
    press(session, "shift+u");
    press(session, "shift+u");
    session.compose();
    // Withheld, and why in plain words: what the claim says, never its syntax.
    std::string text = session.stepText();
    EXPECT_EQ(session.stepWords().shown, WordsShown::Caption);
    EXPECT_NE(text.find("This step's words are not shown in this state: they say the light's "
                        "angle from the surface's normal is below 52, which is not so here."),
              std::string::npos)
        << text;
    EXPECT_EQ(text.find('{'), std::string::npos) << text;
    EXPECT_NE(text.find("the ringed point is"), std::string::npos) << text;
    // Only the window's frames tell how to get the words back.
    EXPECT_EQ(text.find("Step away and back"), std::string::npos) << text;
    session.setInteractive(true);
    EXPECT_NE(session.stepText().find("Step away and back to restore the step."),
              std::string::npos);
}

// Pure: the keys on settings (no GL). A method change drops weights the method cannot take.
TEST(LiveKeySettings, StepsStayOnTheirLaddersAndMethodsKeepValidWeights) {
    LessonSettings s;
    s.bias = BiasMode::None;
    s.constantBias = 0.003f;
    std::optional<LessonSettings> up = settingsAfterKey(s, "V");
    ASSERT_TRUE(up);
    EXPECT_EQ(up->bias, BiasMode::Constant) << "an amount needs a mode that subtracts it";
    EXPECT_EQ(up->constantBias, 0.005f);
    EXPECT_EQ(settingsAfterKey(s, "Shift+V")->constantBias, 0.002f);
    s.constantBias = BIAS_AMOUNT_STEPS[0];
    EXPECT_EQ(settingsAfterKey(s, "Shift+V")->constantBias, BIAS_AMOUNT_STEPS[0]);
    s.method = PCF_GATHER;
    s.weights = PCF_WEIGHTS_GAUSSIAN;
    for (int k = 0; k < PCF_METHOD_COUNT; ++k) {
        s = *settingsAfterKey(s, "M");
        EXPECT_FALSE(validateParams(s.ShadowSettings::pcfParams())) << methodInfo(s.method).name;
    }
    s.method = PCF_NEAREST;
    EXPECT_EQ(settingsAfterKey(s, "W")->weights, PCF_WEIGHTS_BOX) << "nearest takes no weights";
    s.sunTilt = 85.0f;
    EXPECT_EQ(settingsAfterKey(*settingsAfterKey(s, "U"), "U")->sunTilt, 90.0f);
    s.sunTurn = 180.0f;
    EXPECT_EQ(settingsAfterKey(s, "T")->sunTurn, -165.0f);
    // The sun never goes under the ground, whatever the tilt.
    LessonSettings low;
    low.sunTilt = -90.0f;
    EXPECT_NEAR(lightElevationDeg(lessonLight(Light{}, low)), MIN_SUN_ELEVATION_DEG, 1e-4);
    EXPECT_TRUE(changedSettings(low, low, Light{}).empty());
}

TEST(LiveKeyScript, ClicksAndBadTokens) {
    std::vector<ScriptedInput> in = parseScriptedInput("v click:120,80 shift+t");
    ASSERT_EQ(in.size(), 3u);
    ASSERT_TRUE(in[1].click);
    EXPECT_EQ(*in[1].click, glm::vec2(120.5f, 80.5f));
    EXPECT_EQ(settingKeyName(in[2].key), "Shift+T");
    EXPECT_THROW(parseScriptedInput("click:12"), UsageError);
    EXPECT_THROW(parseScriptedInput("click:a,b"), UsageError);
}

// `lesson check` presses a step's sun keys with the sun moved: at 50 degrees from the zenith the
// claim holds, 5 degrees lower (Shift+U) it does not, 5 higher (U) it does.
TEST_F(LiveKeys, LessonCheckMovesTheSunForTheSunKeys) {
    std::string holds = write(lessonText("\"{light_angle} < 52\"", "\"U\""), "holds.toml");
    testutil::CommandResult ok = testutil::runPcfscope("lesson check " + holds);
    EXPECT_EQ(ok.exitCode, 0) << ok.out << ok.err;
    std::string fails = write(lessonText("\"{light_angle} < 52\"", "\"U\", \"Shift+U\""));
    testutil::CommandResult bad = testutil::runPcfscope("lesson check " + fails);
    EXPECT_EQ(bad.exitCode, 1) << bad.out << bad.err;
    EXPECT_EQ(testutil::lineCount(bad.out), 1) << bad.out;
    EXPECT_NE(bad.out.find("after key Shift+U"), std::string::npos) << bad.out;
}

// `export --keys` and `view --keys` (a click and settings keys, then E) give the same step: the
// same settings, the same picked pixel, the same words. Keys that move between steps are refused
// by export.
TEST_F(LiveKeys, ExportAndViewApplyTheSameKeysAndClicks) {
    std::string lesson = write(lessonText("", ""));
    std::string keys = "v k click:300,200";
    testutil::CommandResult ex = testutil::runPcfscope(
        "export " + lesson + " -o " + (mDir / "out").string() + " --keys \"" + keys + "\"");
    ASSERT_EQ(ex.exitCode, 0) << ex.err;
    jsonlite::Value exported = jsonlite::parse(testutil::readAll(mDir / "out/keys-step01.json"));
    EXPECT_EQ(exported["settings"]["constant_bias"].number, 0.005);
    EXPECT_EQ(exported["settings"]["cull"].string, "front");
    // Every parameter of the table, the ones these keys left alone too.
    for (const ParamInfo& p : allParams()) {
        EXPECT_TRUE(exported["settings"].has(std::string(p.key))) << p.key;
    }
    EXPECT_EQ(static_cast<float>(exported["settings"]["slope_max"].number), DEFAULT_SLOPE_MAX);
    testutil::CommandResult plain =
        testutil::runPcfscope("export " + lesson + " -o " + (mDir / "plain").string());
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    jsonlite::Value unclicked = jsonlite::parse(testutil::readAll(mDir / "plain/keys-step01.json"));
    EXPECT_NE(exported["pixel"][size_t{0}].number, unclicked["pixel"][size_t{0}].number)
        << "the click picked another pixel";

    testutil::VirtualDisplay x;
    ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
    testutil::CommandResult view = testutil::runPcfscope(
        "view " + lesson + " --keys \"" + keys + " e\" --screenshot " + (mDir / "v.png").string(),
        "cd " + mDir.string() + " && DISPLAY=" + x.display());
    ASSERT_EQ(view.exitCode, 0) << view.err;
    jsonlite::Value viewed =
        jsonlite::parse(testutil::readAll(mDir / "pcfscope-frames/keys-step01.json"));
    EXPECT_EQ(viewed["settings"]["constant_bias"].number, 0.005);
    for (size_t k : {0u, 1u}) EXPECT_EQ(viewed["pixel"][k].number, exported["pixel"][k].number);
    EXPECT_EQ(viewed["text"].string, exported["text"].string);

    testutil::CommandResult right = testutil::runPcfscope(
        "export " + lesson + " -o " + (mDir / "r").string() + " --keys \"v right\"");
    EXPECT_EQ(right.exitCode, 2);
    EXPECT_EQ(testutil::lineCount(right.err), 1) << right.err;
    EXPECT_NE(right.err.find("'right'"), std::string::npos) << right.err;
    EXPECT_FALSE(fs::exists(mDir / "r"));
}

}  // namespace
}  // namespace pcf
