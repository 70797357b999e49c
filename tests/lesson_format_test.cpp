// The lesson format: parsing, inheritance across steps, and one-line errors at the right line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "base/input_error.h"
#include "charts/speed_chart.h"
#include "kernel/pcf.h"
#include "lesson/lesson.h"
#include "measure/bench_report.h"
#include "scene/presets.h"

namespace pcf {
namespace {

const char* GOOD = R"(title = "The bilinear lerp"
scene = "box-on-plane"

[settings]
method = "bilinear2x2"
map_size = 256
point = [0.9794, 0, -0.4338]

[[step]]
title = "Four bits"
text = """
Visibility {visibility}."""

[[step]]
title = "One hardware tap"
text = "The same: {visibility}."
method = "hw2x2"
bias = "none"

[[step]]
title = "Bigger map"
text = "Map {map_size}."
map_size = 1024
point = [1.5, 0, 0.25]
depth_format = "16"
cull = "front"
constant_bias = 0.01
kernel = 5
radius = 2.5
rotate = true
)";

TEST(LessonFormat, ParsesStepsThatInheritTheStateBeforeThem) {
    Lesson lesson = parseLessonString(GOOD, "lessons/03-bilinear.toml");
    EXPECT_EQ(lesson.name, "03-bilinear");
    EXPECT_EQ(lesson.title, "The bilinear lerp");
    EXPECT_EQ(lesson.sourcePath, "lessons/03-bilinear.toml");
    EXPECT_EQ(lesson.scene.name, "box-on-plane");
    EXPECT_EQ(lesson.scene.objects.size(), 2u);
    ASSERT_EQ(lesson.steps.size(), 3u);

    const LessonStep& s0 = lesson.steps[0];
    EXPECT_EQ(s0.title, "Four bits");
    EXPECT_EQ(s0.text, "Visibility {visibility}.");
    EXPECT_EQ(s0.line, 9);
    EXPECT_EQ(s0.settings.method, PCF_BILINEAR2X2);
    EXPECT_EQ(s0.settings.mapSize, 256);
    EXPECT_EQ(s0.settings.point, glm::vec3(0.9794f, 0.0f, -0.4338f));
    // Everything [settings] leaves out keeps RenderSettings' defaults.
    EXPECT_EQ(s0.settings.kernel, 3);
    EXPECT_EQ(s0.settings.radius, 1.0f);
    EXPECT_FALSE(s0.settings.rotate);
    EXPECT_EQ(s0.settings.bias, BiasMode::Constant);
    EXPECT_EQ(s0.settings.constantBias, 0.002f);
    EXPECT_EQ(s0.settings.cull, CullMode::Back);
    EXPECT_EQ(s0.settings.depthFormat, TexelKind::D32F);

    const LessonStep& s1 = lesson.steps[1];
    EXPECT_EQ(s1.line, 14);
    EXPECT_EQ(s1.settings.method, PCF_HW2X2);
    EXPECT_EQ(s1.settings.bias, BiasMode::None);
    EXPECT_EQ(s1.settings.mapSize, 256);  // inherited from [settings]
    EXPECT_EQ(s1.settings.point, glm::vec3(0.9794f, 0.0f, -0.4338f));

    const LessonStep& s2 = lesson.steps[2];
    EXPECT_EQ(s2.settings.method, PCF_HW2X2);  // inherited from step 2
    EXPECT_EQ(s2.settings.bias, BiasMode::None);
    EXPECT_EQ(s2.settings.mapSize, 1024);
    EXPECT_EQ(s2.settings.point, glm::vec3(1.5f, 0.0f, 0.25f));
    EXPECT_EQ(s2.settings.depthFormat, TexelKind::D16);
    EXPECT_EQ(s2.settings.cull, CullMode::Front);
    EXPECT_EQ(s2.settings.constantBias, 0.01f);
    EXPECT_EQ(s2.settings.kernel, 5);
    EXPECT_EQ(s2.settings.radius, 2.5f);
    EXPECT_TRUE(s2.settings.rotate);
}

TEST(LessonFormat, DepthBiasIsZeroWithoutConstantBias) {
    LessonSettings s;
    s.constantBias = 0.005f;
    EXPECT_EQ(s.baseBias(), 0.005f);
    s.bias = BiasMode::None;
    EXPECT_EQ(s.baseBias(), 0.0f);
}

TEST(LessonFormat, PcfParamsRotateTheDiskWithTheTexelLookedUp) {
    LessonSettings s;
    s.method = PCF_POISSON;
    s.radius = 2.0f;
    PcfParams plain = s.pcfParams({0.3f, 0.7f}, 256);
    EXPECT_EQ(plain.method, PCF_POISSON);
    EXPECT_EQ(plain.radius, 2.0f);
    EXPECT_EQ(plain.rotation, vec2(1.0f, 0.0f));
    s.rotate = true;
    // uv (0.3, 0.7) of a 256 map falls in texel (76, 179); every uv in that texel turns alike.
    EXPECT_EQ(s.pcfParams({0.3f, 0.7f}, 256).rotation, pcfPixelRotation(ivec2(76, 179)));
    EXPECT_EQ(s.pcfParams({76.9f / 256.0f, 179.1f / 256.0f}, 256).rotation,
              pcfPixelRotation(ivec2(76, 179)));
}

TEST(LessonFormat, EmbeddedSceneTables) {
    const char* text = R"(title = "Close up"
[camera]
eye = [0.0, 2.0, 3.0]
target = [0.0, 0.0, 0.0]
[light]
type = "directional"
direction = [0.3, -1.0, 0.2]
[[object]]
type = "plane"
centre = [0, 0, 0]
normal = [0, 1, 0]
size = [4, 4]
[[object]]
type = "sphere"
centre = [0, 1, 0]
radius = 0.3
[[step]]
title = "t"
text = "x"
)";
    Lesson lesson = parseLessonString(text, "close.toml");
    EXPECT_EQ(lesson.scene.objects.size(), 2u);
    EXPECT_EQ(lesson.scene.camera.eyeWs, glm::vec3(0.0f, 2.0f, 3.0f));
    EXPECT_EQ(lesson.steps.size(), 1u);
    // A step with no settings has the defaults.
    EXPECT_EQ(lesson.steps[0].settings, LessonSettings{});
}

TEST(LessonFormat, ReadsAFileAndNamesItByItsStem) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() / "pcfscope_lesson_test";
    std::filesystem::create_directories(dir);
    std::filesystem::path file = dir / "07-poisson.toml";
    {
        std::ofstream out(file);
        out << GOOD;
    }
    Lesson lesson = parseLessonFile(file.string());
    EXPECT_EQ(lesson.name, "07-poisson");
    EXPECT_EQ(lesson.sourcePath, file.string());
    EXPECT_EQ(lesson.steps.size(), 3u);
    std::filesystem::remove_all(dir);
}

// The error for `text`, which must be an InputError.
std::string errorOf(const std::string& text, const std::string& source = "bad.toml") {
    try {
        parseLessonString(text, source);
    } catch (const InputError& e) {
        EXPECT_EQ(e.source(), source);
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
        return "";
    }
    ADD_FAILURE() << "parsed without error:\n" << text;
    return "";
}

// A good lesson header and one step, then `extra` appended to the step (line 5 on).
std::string withStep(const std::string& extra) {
    return "title = \"T\"\n"            // 1
           "scene = \"pole\"\n"         // 2
           "[[step]]\n"                 // 3
           "title = \"S\"\n"            // 4
           "text = \"{visibility}\"\n"  // 5
           + extra;                     // 6..
}

TEST(LessonFormat, MissingFileAndDirectoryAreOneLine) {
    try {
        parseLessonFile("/nonexistent/lesson.toml");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/lesson.toml: cannot open file");
    }
    EXPECT_THROW(parseLessonFile(std::filesystem::temp_directory_path().string()), InputError);
}

TEST(LessonFormat, TomlSyntaxErrorsNameTheirLine) {
    std::string e = errorOf(withStep("kernel = = 3\n"));
    EXPECT_EQ(e.rfind("bad.toml:6: ", 0), 0u) << e;
}

TEST(LessonFormat, UnknownKeysAreRefusedAtTheirLine) {
    std::string e = errorOf(withStep("kernal = 3\n"));
    EXPECT_EQ(e, "bad.toml:6: step 1 has unknown key 'kernal' (did you mean 'kernel'?)");
    e = errorOf(
        "title = \"T\"\nscene = \"pole\"\n\n[settings]\nmethod = \"nearest\"\n"
        "mapsize = 64\n[[step]]\ntitle = \"S\"\ntext = \"x\"\n");
    EXPECT_EQ(e, "bad.toml:6: settings has unknown key 'mapsize' (did you mean 'map_size'?)");
    e = errorOf("title = \"T\"\nmethod = \"nearest\"\nscene = \"pole\"\n");
    EXPECT_EQ(e.rfind("bad.toml:2: lesson has unknown key 'method'", 0), 0u) << e;
}

TEST(LessonFormat, WrongTypesAreRefused) {
    EXPECT_EQ(errorOf(withStep("kernel = 3.0\n")),
              "bad.toml:6: step 1 kernel must be an integer, got floating-point");
    EXPECT_EQ(errorOf(withStep("rotate = \"yes\"\n")),
              "bad.toml:6: step 1 rotate must be true or false, got string");
    EXPECT_EQ(errorOf(withStep("method = 2\n")),
              "bad.toml:6: step 1 method must be a string, got integer");
    EXPECT_EQ(errorOf(withStep("radius = \"1\"\n")),
              "bad.toml:6: step 1 radius must be a number, got string");
    std::string e = errorOf(withStep("depth_format = 16\n"));
    EXPECT_EQ(e.rfind("bad.toml:6: step 1 depth_format must be a string", 0), 0u) << e;
    e = errorOf(withStep("point = [1.1, \"0\", 0.3]\n"));
    EXPECT_EQ(e, "bad.toml:6: step 1 point[1] must be a number, got string");
    e = errorOf(withStep("point = [1, 2]\n"));
    EXPECT_EQ(e.rfind("bad.toml:6: step 1 point must be [x, y, z]", 0), 0u) << e;
    e = errorOf("title = 3\nscene = \"pole\"\n[[step]]\ntitle = \"S\"\ntext = \"x\"\n");
    EXPECT_EQ(e, "bad.toml:1: lesson title must be a string, got integer");
    e = errorOf(
        "title = \"T\"\nscene = \"pole\"\nsettings = 3\n[[step]]\ntitle = \"S\"\n"
        "text = \"x\"\n");
    EXPECT_EQ(e.rfind("bad.toml:3: settings must be a table", 0), 0u) << e;
}

TEST(LessonFormat, UnknownNamesAreRefused) {
    std::string e = errorOf(withStep("method = \"bilinear\"\n"));
    EXPECT_EQ(e.rfind("bad.toml:6: unknown method 'bilinear' (known: nearest, box2x2,", 0), 0u)
        << e;
    EXPECT_EQ(errorOf(withStep("bias = \"sloped\"\n")),
              "bad.toml:6: unknown bias mode 'sloped' (known: none, constant, slope, normal, "
              "receiver-plane, soft, interpolated)");
    // A mode the step's method cannot take is blamed on the line that set the mode.
    e = errorOf(withStep("method = \"tent\"\nbias = \"soft\"\n"));
    EXPECT_EQ(e.rfind("bad.toml:7: step 1: bias soft compares", 0), 0u) << e;
    e = errorOf(withStep("slope_max = 3\n"));
    EXPECT_EQ(e, "bad.toml:6: step 1 slope_max must be in [0, 1] light depth units, got 3");
    EXPECT_EQ(errorOf(withStep("cull = \"both\"\n")),
              "bad.toml:6: unknown cull mode 'both' (known: back, front, none)");
    EXPECT_EQ(errorOf(withStep("depth_format = \"32\"\n")),
              "bad.toml:6: unknown depth format '32' (known: 16, 24, 32f)");
    e = errorOf("title = \"T\"\nscene = \"poles\"\n[[step]]\ntitle = \"S\"\ntext = \"x\"\n");
    EXPECT_EQ(e,
              "bad.toml:2: unknown scene preset 'poles' (known: box-on-plane, "
              "sphere-over-plane, pole, post-in-sun, post-under-spot, grazing, stairs, "
              "stacked-cards, long-ground)");
}

TEST(LessonFormat, ValuesOutOfRangeAreRefused) {
    EXPECT_EQ(errorOf(withStep("kernel = 9\n")), "bad.toml:6: step 1 kernel must be 1..8, got 9");
    EXPECT_EQ(errorOf(withStep("kernel = 0\n")), "bad.toml:6: step 1 kernel must be 1..8, got 0");
    EXPECT_EQ(errorOf(withStep("map_size = 3\n")),
              "bad.toml:6: step 1 map_size must be 4..4096, got 3");
    EXPECT_EQ(errorOf(withStep("map_size = 8192\n")),
              "bad.toml:6: step 1 map_size must be 4..4096, got 8192");
    EXPECT_EQ(errorOf(withStep("radius = 0\n")),
              "bad.toml:6: step 1 radius must be in (0, 64] texels, got 0");
    EXPECT_EQ(errorOf(withStep("constant_bias = 2\n")),
              "bad.toml:6: step 1 constant_bias must be in [-1, 1] light depth units, got 2");
    EXPECT_EQ(errorOf(withStep("constant_bias = nan\n")),
              "bad.toml:6: step 1 constant_bias must be finite, got nan");
    // The light's size: the parameter table's range, its value as written, and each size for
    // its own kind of light (the pole scene's is directional), also in a compare.
    EXPECT_EQ(errorOf(withStep("light_size = 10.000001\n")),
              "bad.toml:6: step 1 light_size must be in [0, 10] degrees, got 10.000001");
    EXPECT_EQ(errorOf(withStep("light_radius = 0.5\n")),
              "bad.toml:6: step 1: light_radius (a spot light's radius) does not apply to a "
              "directional light, whose size is its angular diameter");
    EXPECT_EQ(errorOf(withStep("compare = { light_size = [\"2\", \"11\"] }\n")),
              "bad.toml:6: step 1 compare: light_size must be in [0, 10] degrees, got 11");
    EXPECT_EQ(errorOf(withStep("compare = { light_radius = [\"0\", \"1\"] }\n")),
              "bad.toml:6: step 1 compare: light_radius (a spot light's radius) does not apply "
              "to a directional light, whose size is its angular diameter");
    // A point must lie on a surface the camera sees: the pole scene's ground does, the air
    // above it does not.
    EXPECT_NO_THROW(parseLessonString(withStep("point = [1.1, 0, 0.3]\n"), "ok.toml"));
    std::string e = errorOf(withStep("point = [1.1,\n  3, 0.3]\n"));
    EXPECT_EQ(
        e.rfind("bad.toml:6: step 1 point [1.1, 3, 0.3] is not on a surface the camera sees", 0),
        0u)
        << e;
    // A screen pixel is refused with what to write instead.
    e = errorOf(withStep("pixel = [10, 20]\n"));
    EXPECT_EQ(e.rfind("bad.toml:6: step 1 pixel: a lesson pins a scene point", 0), 0u) << e;
}

TEST(LessonFormat, TentKernelIsBlamedOnTheKeySetLast) {
    // The step names the method; the kernel 4 came from [settings] two lines up.
    std::string text =
        "title = \"T\"\nscene = \"pole\"\n[settings]\nkernel = 4\n[[step]]\ntitle = \"S\"\n"
        "text = \"x\"\nmethod = \"tent\"\n";
    EXPECT_EQ(errorOf(text), "bad.toml:8: step 1: tent takes kernel 3, 5 or 7, not 4");
    // A later step changes only the kernel: now the kernel is the culprit.
    text = withStep("method = \"tent\"\n[[step]]\ntitle = \"S2\"\ntext = \"y\"\nkernel = 6\n");
    EXPECT_EQ(errorOf(text), "bad.toml:10: step 2: tent takes kernel 3, 5 or 7, not 6");
}

TEST(LessonFormat, StepsNeedTitleAndText) {
    EXPECT_EQ(errorOf("title = \"T\"\nscene = \"pole\"\n[[step]]\ntitle = \"S\"\n"),
              "bad.toml:3: step 1 has no text");
    EXPECT_EQ(errorOf(withStep("[[step]]\ntext = \"x\"\n")), "bad.toml:6: step 2 has no title");
    EXPECT_EQ(errorOf(withStep("[[step]]\ntitle = \"x\"\ntext = \"  \"\n")),
              "bad.toml:8: step 2 text must not be empty");
    EXPECT_EQ(errorOf("scene = \"pole\"\n[[step]]\ntitle = \"S\"\ntext = \"x\"\n"),
              "bad.toml:1: lesson has no title");
}

TEST(LessonFormat, ALessonNeedsStepsAndAScene) {
    EXPECT_EQ(errorOf("title = \"T\"\nscene = \"pole\"\n"),
              "bad.toml:1: lesson has no steps: add at least one [[step]] table");
    EXPECT_EQ(errorOf("title = \"T\"\nscene = \"pole\"\nstep = []\n"),
              "bad.toml:3: lesson has no steps: add at least one [[step]] table");
    std::string e = errorOf("title = \"T\"\nscene = \"pole\"\nstep = 3\n");
    EXPECT_EQ(e.rfind("bad.toml:3: step must be an array of tables", 0), 0u) << e;
    e = errorOf("title = \"T\"\n[[step]]\ntitle = \"S\"\ntext = \"x\"\n");
    EXPECT_EQ(e.rfind("bad.toml:1: lesson has no scene", 0), 0u) << e;
    e = errorOf("title = \"T\"\nscene = \"pole\"\n[light]\ntype = \"directional\"\n");
    EXPECT_EQ(
        e.rfind("bad.toml:2: lesson gives both scene = \"pole\" and scene tables ([light]", 0), 0u)
        << e;
}

TEST(LessonFormat, ACameraBesideAPresetViewsThePresetFromThere) {
    Lesson lesson = parseLessonString(
        "title = \"T\"\nscene = \"grazing\"\n[camera]\neye = [0.5, 1.0, 3.0]\n"
        "target = [0.9, 0.0, 1.4]\nfov = 30.0\n[[step]]\ntitle = \"S\"\ntext = \"x\"\n",
        "close.toml");
    std::optional<Scene> preset = presetScene("grazing");
    ASSERT_TRUE(preset);
    EXPECT_EQ(lesson.scene.objects.size(), preset->objects.size());
    EXPECT_EQ(lesson.scene.light.directionWs, preset->light.directionWs);
    EXPECT_EQ(lesson.scene.camera.eyeWs, glm::vec3(0.5f, 1.0f, 3.0f));
    EXPECT_EQ(lesson.scene.camera.targetWs, glm::vec3(0.9f, 0.0f, 1.4f));
    EXPECT_EQ(lesson.scene.camera.fovYDeg, 30.0f);
    EXPECT_NE(lesson.scene.camera.eyeWs, preset->camera.eyeWs);
    // Its planes are fitted to the preset's scene, as a preset's own camera's are.
    EXPECT_GT(lesson.scene.camera.nearZ, 0.0f);
    EXPECT_GT(lesson.scene.camera.farZ, lesson.scene.camera.nearZ);
    // A bad camera beside a preset names its line.
    std::string e = errorOf("title = \"T\"\nscene = \"grazing\"\n[camera]\neye = [0, 1, 3]\n");
    EXPECT_EQ(e.rfind("bad.toml:3: ", 0), 0u) << e;
    EXPECT_NE(e.find("target"), std::string::npos) << e;
}

TEST(LessonFormat, EmbeddedSceneErrorsKeepTheLessonsLines) {
    std::string text = R"(title = "T"
[camera]
eye = [0.0, 2.0, 3.0]
target = [0.0, 0.0, 0.0]
[light]
type = "directional"
direction = [0.3, -1.0, 0.2]
[[object]]
type = "sphere"
centre = [0, 1, 0]
radius = -1
[[step]]
title = "S"
text = "x"
)";
    EXPECT_EQ(errorOf(text, "close.toml"), "close.toml:11: sphere radius must be positive, got -1");
}

TEST(LessonFormat, UnknownPlaceholdersNameTheLineOfTheText) {
    std::string text =
        "title = \"T\"\n"                // 1
        "scene = \"pole\"\n"             // 2
        "[[step]]\n"                     // 3
        "title = \"S\"\n"                // 4
        "text = \"\"\"\n"                // 5
        "The fraction is {frac.x},\n"    // 6
        "and the result {visiblity}.\n"  // 7
        "\"\"\"\n";                      // 8
    // The nearest known name, and where the names are listed: the authoring guide, not the code.
    EXPECT_EQ(errorOf(text),
              "bad.toml:7: step 1 text: unknown placeholder {visiblity} (did you mean "
              "{visibility}?) (the names: docs/lesson-authoring.md#placeholders; write {{ for a "
              "literal brace)");
    // Without a newline after the opening quotes, and with escaped newlines on one line.
    text =
        "title = \"T\"\nscene = \"pole\"\n[[step]]\ntitle = \"S\"\n"
        "text = \"\"\"ok {z}\n{zz}\"\"\"\n";
    EXPECT_EQ(errorOf(text).rfind("bad.toml:6: step 1 text: unknown placeholder {zz}", 0), 0u);
    text =
        "title = \"T\"\nscene = \"pole\"\n[[step]]\ntitle = \"S\"\n"
        "text = \"a\\nb\\n{zz}\"\n";
    EXPECT_EQ(errorOf(text).rfind("bad.toml:5: step 1 text: unknown placeholder {zz}", 0), 0u);
    // An unmatched brace.
    text = withStep("[[step]]\ntitle = \"S2\"\ntext = \"\"\"\nfine\nset {0, 1\n\"\"\"\n");
    std::string e = errorOf(text);
    EXPECT_EQ(e.rfind("bad.toml:10: step 2 text: a { with no closing }", 0), 0u) << e;
}

// The line of a text's character where a line-ending backslash joins file lines without a
// newline in the text, and where escapes are longer in the file than in the text.
TEST(LessonFormat, ATextsCharactersAreFoundOnTheirFileLines) {
    std::string text =
        "title = \"T\"\n"         // 1
        "scene = \"pole\"\n"      // 2
        "[[step]]\n"              // 3
        "title = \"S\"\n"         // 4
        "text = \"\"\"\n"         // 5
        "One \\u00e9 line, \\\n"  // 6: an escape, then a joined line
        "   two {zz} \\\n"        // 7
        "\n"                      // 8
        "   three, \\t {yy}\n"    // 9
        "four {xx}\"\"\"\n";      // 10
    std::vector<InputError> problems;
    parseLessonString(text, "bad.toml", problems);
    ASSERT_EQ(problems.size(), 3u);
    EXPECT_EQ(problems[0].line(), 7);
    EXPECT_EQ(problems[1].line(), 9);
    EXPECT_EQ(problems[2].line(), 10);
    Lesson ok = parseLessonString(
        "title = \"T\"\nscene = \"pole\"\n[[step]]\ntitle = \"S\"\ntext = \"\"\"\n"
        "a \\\n  b\nc\"\"\"\n",
        "ok.toml");
    const LessonStep& step = ok.steps[0];
    ASSERT_EQ(step.text, "a b\nc");
    EXPECT_EQ(stepTextLine(step, 0), 6);  // a
    EXPECT_EQ(stepTextLine(step, 2), 7);  // b, after the joined line
    EXPECT_EQ(stepTextLine(step, 4), 8);  // c
}

// Reading on: every problem of a file, each at its line, in file order; the first is the one
// a one-line reader (view, export) throws.
TEST(LessonFormat, EveryProblemOfAFileIsFoundInOneReading) {
    std::string text =
        "title = \"T\"\n"               // 1
        "scene = \"pole\"\n"            // 2
        "[settings]\n"                  // 3
        "kernal = 3\n"                  // 4: unknown key
        "[[step]]\n"                    // 5
        "title = \"S\"\n"               // 6
        "text = \"{frac.z}\"\n"         // 7: unknown placeholder
        "claims = [\"{taps} is 1\"]\n"  // 8: a claim with no comparison
        "[[step]]\n"                    // 9
        "title = \"S2\"\n"              // 10
        "map_size = 3\n"                // 11: out of range
        "text = \"{a} and {b}\"\n";     // 12: two unknown placeholders
    std::vector<InputError> problems;
    parseLessonString(text, "bad.toml", problems);
    std::vector<int> lines;
    for (const InputError& e : problems) lines.push_back(e.line());
    EXPECT_EQ(lines, (std::vector<int>{4, 7, 8, 11, 12, 12})) << problems.front().what();
    EXPECT_EQ(errorOf(text).rfind("bad.toml:4: settings has unknown key 'kernal'", 0), 0u);
    // A file TOML cannot read is one problem.
    problems.clear();
    parseLessonString("title = \"T\nscene", "bad.toml", problems);
    EXPECT_EQ(problems.size(), 1u);
}

TEST(LessonFormat, TapIndicesMustExistForTheStepsMethod) {
    // bilinear2x2 reads 4 texels: tap[3] exists, tap[4] does not.
    std::string ok = withStep(
        "method = \"bilinear2x2\"\n[[step]]\ntitle = \"S2\"\n"
        "text = \"{tap[3].depth}\"\n");
    EXPECT_NO_THROW(parseLessonString(ok, "ok.toml"));
    std::string e =
        errorOf(withStep("method = \"bilinear2x2\"\n[[step]]\ntitle = \"S2\"\n"
                         "text = \"{tap[4].depth}\"\n"));
    EXPECT_EQ(e.rfind("bad.toml:9: step 2 text: tap[4] is past the 4 reads", 0), 0u) << e;
    // pcf-naive 3x3: 36 reads in 9 lookups.
    EXPECT_NO_THROW(parseLessonString(withStep("method = \"pcf-naive\"\n[[step]]\ntitle = \"S\"\n"
                                               "text = \"{tap[35].lit} {fetch[8].value}\"\n"),
                                      "ok.toml"));
    e =
        errorOf(withStep("method = \"pcf-naive\"\n[[step]]\ntitle = \"S\"\n"
                         "text = \"{fetch[9].value}\"\n"));
    EXPECT_EQ(e.rfind("bad.toml:9: step 2 text: fetch[9] is past the 9 fetch instructions", 0), 0u)
        << e;
}

}  // namespace
}  // namespace pcf

namespace pcf {
namespace {

// A step may show a bench chart, from a bench.csv beside the lesson; a missing one is named.
TEST(LessonFormat, ChartStepsNameTheirCsvAndAMissingOneFails) {
    Lesson lesson = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/11-speed-and-accuracy.toml");
    ASSERT_GE(lesson.steps.size(), 4u);
    EXPECT_EQ(std::filesystem::path(lesson.steps[0].chart).filename(), "bench.csv");
    EXPECT_TRUE(std::filesystem::exists(lesson.steps[0].chart));
    EXPECT_TRUE(lesson.steps[3].chart.empty());  // not inherited
    const char* missing = R"(title = "x"
scene = "box-on-plane"
[[step]]
title = "a"
text = "b"
chart = "nowhere/bench.csv"
)";
    try {
        parseLessonString(missing, "/tmp/m.toml");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/tmp/m.toml:6: step 1 chart 'nowhere/bench.csv' "
                                              "not found",
                                              0),
                  0u)
            << e.what();
    }
}

}  // namespace
}  // namespace pcf

namespace pcf {
namespace {

// `grid` starts a step with the texel grid off; `highlight` names the fetch its text is about
// (not inherited); both are checked like every other key.
TEST(LessonFormatLayoutKeys, GridAndHighlight) {
    std::string text = std::string(GOOD) + R"(
[[step]]
title = "Grid off, first fetch"
text = "Fetch one."
grid = false
highlight = 1

[[step]]
title = "Next"
text = "Still off."
)";
    Lesson lesson = parseLessonString(text, "keys.toml");
    ASSERT_EQ(lesson.steps.size(), 5u);
    EXPECT_TRUE(lesson.steps[0].settings.grid);
    EXPECT_EQ(lesson.steps[0].highlightFetch, 0);
    EXPECT_FALSE(lesson.steps[3].settings.grid);
    EXPECT_EQ(lesson.steps[3].highlightFetch, 1);
    EXPECT_FALSE(lesson.steps[4].settings.grid);   // settings are inherited
    EXPECT_EQ(lesson.steps[4].highlightFetch, 0);  // the highlight is not
    std::string bad =
        std::string(GOOD) + "\n[[step]]\ntitle = \"x\"\ntext = \"y\"\nhighlight = 0\n";
    EXPECT_NE(errorOf(bad).find("highlight must be a fetch number"), std::string::npos)
        << errorOf(bad);
    std::string badGrid = std::string(GOOD) + "\n[[step]]\ntitle = \"x\"\ntext = \"y\"\ngrid = 1\n";
    EXPECT_NE(errorOf(badGrid).find("grid must be true or false"), std::string::npos)
        << errorOf(badGrid);
}

// `chart_highlight` names bench-chart dots: it needs a bench chart, and it is not inherited.
TEST(LessonFormatLayoutKeys, ChartHighlightNeedsABenchChart) {
    std::string noChart = std::string(GOOD) +
                          "\n[[step]]\ntitle = \"x\"\ntext = \"y\"\nchart_highlight = \"front\"\n";
    EXPECT_NE(errorOf(noChart).find("chart_highlight needs a bench chart"), std::string::npos)
        << errorOf(noChart);
    Lesson lesson = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/11-speed-and-accuracy.toml");
    ASSERT_GE(lesson.steps.size(), 3u);
    EXPECT_EQ(lesson.steps[1].chartHighlight, "front");
    for (const LessonStep& step : lesson.steps) {
        if (step.chart.empty()) {
            EXPECT_TRUE(step.chartHighlight.empty());
        }
    }
}

// The selectors: "front" is the chart's Pareto front, a first word takes every map size, a
// full label one dot; a selector that names no dot is refused.
TEST(LessonFormatLayoutKeys, ChartHighlightSelectsDotsByLabel) {
    std::ifstream in(PCFSCOPE_SOURCE_DIR "/lessons/figures/bench.csv");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<BenchRow> rows = parseBenchCsv(text, "bench.csv");
    std::vector<size_t> gather3 = chartRowsMatching(rows, "gather3");
    ASSERT_EQ(gather3.size(), 4u);  // maps 256 .. 2048
    for (size_t k : gather3) {
        EXPECT_EQ(rows[k].point.method, PCF_GATHER);
        EXPECT_EQ(rows[k].point.kernel, 3);
    }
    std::vector<size_t> one = chartRowsMatching(rows, " gather3 256 ,tent5 1024");
    ASSERT_EQ(one.size(), 2u);
    EXPECT_EQ(chartLabel(rows[one[0]].point), "gather3 256");
    EXPECT_EQ(chartLabel(rows[one[1]].point), "tent5 1024");
    std::vector<size_t> front = benchParetoFront(rows);
    std::sort(front.begin(), front.end());  // the front is fastest first; the matches row order
    EXPECT_EQ(chartRowsMatching(rows, "front"), front);
    EXPECT_THROW(chartRowsMatching(rows, "gather3, gather9"), std::invalid_argument);
    EXPECT_THROW(chartRowsMatching(rows, "gather"), std::invalid_argument);  // not a whole word
}

}  // namespace
}  // namespace pcf
