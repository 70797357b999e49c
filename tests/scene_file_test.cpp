// Scene files: every field read, every kind of bad input refused with `file:line: problem`.
#include "scene/scene_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "glm_expect.h"
#include "scene/presets.h"

namespace pcf {
namespace {

// Line numbers below are counted from the first line of each string.
constexpr const char* GOOD = R"([camera]
eye = [6.0, 5.0, 7]
target = [0.0, 0.5, 0.0]
up = [0.0, 2.0, 0.0]
fov = 35.5
near = 0.25
far = 40

[light]
type = "spot"
direction = [0.0, -2.0, 0.0]
position = [1.0, 6.0, -1.0]
cone = 30.0

[[object]]
type = "plane"
name = "ground"
centre = [0, 0, 0]
normal = [0, 3, 0]
size = [10, 8]
colour = [0.8, 0.7, 0.6]
receives_shadow = true
casts_shadow = false

[[object]]
type = "box"
name = "crate"
centre = [0, 0.5, 0]
half = [0.5, 0.25, 1.5]
rotate_y = 20.0

[[object]]
type = "sphere"
centre = [1, 2, 3]
radius = 0.5
receives_shadow = false
)";

TEST(SceneFile, GoodFileGivesEveryField) {
    Scene s = parseSceneString(GOOD, "good.toml");
    EXPECT_EQ(s.name, "good.toml");
    EXPECT_EQ(s.camera.eyeWs, glm::vec3(6, 5, 7));
    EXPECT_EQ(s.camera.targetWs, glm::vec3(0, 0.5f, 0));
    EXPECT_EQ(s.camera.upWs, glm::vec3(0, 1, 0));  // normalised
    EXPECT_FLOAT_EQ(s.camera.fovYDeg, 35.5f);
    EXPECT_FLOAT_EQ(s.camera.nearZ, 0.25f);
    EXPECT_FLOAT_EQ(s.camera.farZ, 40.0f);

    EXPECT_EQ(s.light.type, LightType::Spot);
    EXPECT_EQ(s.light.directionWs, glm::vec3(0, -1, 0));  // normalised
    EXPECT_EQ(s.light.positionWs, glm::vec3(1, 6, -1));
    EXPECT_FLOAT_EQ(s.light.coneDeg, 30.0f);

    ASSERT_EQ(s.objects.size(), 3u);
    const SceneObject& ground = s.objects[0];
    EXPECT_EQ(ground.name, "ground");
    EXPECT_EQ(ground.colour, glm::vec3(0.8f, 0.7f, 0.6f));
    EXPECT_FALSE(ground.castsShadow);
    EXPECT_TRUE(ground.receivesShadow);
    const Plane& plane = std::get<Plane>(ground.shape);
    EXPECT_EQ(plane.centreWs, glm::vec3(0));
    EXPECT_EQ(plane.normalWs, glm::vec3(0, 1, 0));
    EXPECT_VEC3_NEAR(plane.halfUWs, glm::vec3(5, 0, 0), 1e-6f);   // size[0] along x
    EXPECT_VEC3_NEAR(plane.halfVWs, glm::vec3(0, 0, -4), 1e-6f);  // size[1] along z

    const SceneObject& crate = s.objects[1];
    EXPECT_EQ(crate.name, "crate");
    EXPECT_EQ(crate.colour, glm::vec3(0.8f));  // default
    EXPECT_TRUE(crate.castsShadow);
    EXPECT_TRUE(crate.receivesShadow);
    const Box& box = std::get<Box>(crate.shape);
    EXPECT_EQ(box.centreWs, glm::vec3(0, 0.5f, 0));
    EXPECT_EQ(box.halfExtents, glm::vec3(0.5f, 0.25f, 1.5f));
    EXPECT_FLOAT_EQ(box.rotateYDeg, 20.0f);

    const SceneObject& ball = s.objects[2];
    EXPECT_EQ(ball.name, "sphere2");  // default: type + index
    EXPECT_FALSE(ball.receivesShadow);
    const Sphere& sphere = std::get<Sphere>(ball.shape);
    EXPECT_EQ(sphere.centreWs, glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(sphere.radius, 0.5f);
}

TEST(SceneFile, DefaultsAndFittedClipPlanes) {
    Scene s = parseSceneString(R"(
[camera]
eye = [0, 2, 8]
target = [0, 0, 0]
[light]
type = "directional"
direction = [1, -1, 0]
[[object]]
type = "sphere"
centre = [0, 0, 0]
radius = 1
)",
                               "defaults.toml");
    EXPECT_EQ(s.camera.upWs, glm::vec3(0, 1, 0));
    EXPECT_FLOAT_EQ(s.camera.fovYDeg, 40.0f);
    EXPECT_GT(s.camera.nearZ, 0.0f);
    EXPECT_GT(s.camera.farZ, 8.0f);
    EXPECT_LT(s.camera.nearZ, 8.25f - 1.0f);  // in front of the sphere
    EXPECT_EQ(s.light.type, LightType::Directional);
    EXPECT_VEC3_NEAR(s.light.directionWs, glm::normalize(glm::vec3(1, -1, 0)), 1e-7f);
    EXPECT_EQ(s.objects[0].name, "sphere0");
    EXPECT_TRUE(s.objects[0].castsShadow);
}

TEST(SceneFile, FormatRoundTrips) {
    Scene s = parseSceneString(GOOD, "good.toml");
    // A tilted plane with its own tangent, and a directional variant, too.
    s.objects.push_back({"wall",
                         *makePlane({1, 1, -2}, {0.3f, 0.1f, 0.9f}, {2, 3}, glm::vec3(0, 1, 0)),
                         glm::vec3(0.1f, 0.2f, 0.3f), false, false});
    for (LightType type : {LightType::Spot, LightType::Directional}) {
        s.light.type = type;
        s.light.radius = 0.125f;
        s.light.angularDiameterDeg = 0.53f;
        Scene back = parseSceneString(formatSceneToml(s), "formatted.toml");
        EXPECT_EQ(back.camera.eyeWs, s.camera.eyeWs);
        EXPECT_EQ(back.camera.targetWs, s.camera.targetWs);
        EXPECT_EQ(back.camera.upWs, s.camera.upWs);
        EXPECT_EQ(back.camera.fovYDeg, s.camera.fovYDeg);
        EXPECT_EQ(back.camera.nearZ, s.camera.nearZ);
        EXPECT_EQ(back.camera.farZ, s.camera.farZ);
        EXPECT_EQ(back.light.type, s.light.type);
        EXPECT_VEC3_NEAR(back.light.directionWs, s.light.directionWs, 1e-7f);
        if (type == LightType::Spot) {
            EXPECT_EQ(back.light.positionWs, s.light.positionWs);
            EXPECT_EQ(back.light.coneDeg, s.light.coneDeg);
            EXPECT_EQ(back.light.radius, 0.125f);  // a spot's size is its radius
            EXPECT_EQ(back.light.angularDiameterDeg, 0.0f);
        } else {
            EXPECT_EQ(back.light.angularDiameterDeg, 0.53f);  // a sun's, its angular diameter
            EXPECT_EQ(back.light.radius, 0.0f);
        }
        ASSERT_EQ(back.objects.size(), s.objects.size());
        for (size_t i = 0; i < s.objects.size(); ++i) {
            const SceneObject& a = s.objects[i];
            const SceneObject& b = back.objects[i];
            EXPECT_EQ(a.name, b.name);
            EXPECT_EQ(a.colour, b.colour);
            EXPECT_EQ(a.castsShadow, b.castsShadow);
            EXPECT_EQ(a.receivesShadow, b.receivesShadow);
            ASSERT_EQ(a.shape.index(), b.shape.index());
            if (const Plane* p = std::get_if<Plane>(&a.shape)) {
                const Plane& q = std::get<Plane>(b.shape);
                EXPECT_VEC3_NEAR(p->centreWs, q.centreWs, 0.0f);
                EXPECT_VEC3_NEAR(p->normalWs, q.normalWs, 1e-6f);
                EXPECT_VEC3_NEAR(p->halfUWs, q.halfUWs, 1e-6f);
                EXPECT_VEC3_NEAR(p->halfVWs, q.halfVWs, 1e-6f);
            } else if (const Box* bx = std::get_if<Box>(&a.shape)) {
                const Box& q = std::get<Box>(b.shape);
                EXPECT_EQ(bx->centreWs, q.centreWs);
                EXPECT_EQ(bx->halfExtents, q.halfExtents);
                EXPECT_EQ(bx->rotateYDeg, q.rotateYDeg);
            } else {
                const Sphere& p2 = std::get<Sphere>(a.shape);
                const Sphere& q = std::get<Sphere>(b.shape);
                EXPECT_EQ(p2.centreWs, q.centreWs);
                EXPECT_EQ(p2.radius, q.radius);
            }
        }
    }
}

TEST(SceneFile, TablesInsideALesson) {
    // A lesson keeps its own keys and nests the scene's tables; lines still point into the
    // lesson file.
    constexpr const char* LESSON = R"(title = "Acne"
step = 3

[scene.camera]
eye = [0, 2, 8]
target = [0, 0, 0]

[scene.light]
type = "directional"
direction = [1, -1, 0]

[[scene.object]]
type = "sphere"
centre = [0, 0, 0]
radius = -2
)";
    toml::table lesson = toml::parse(std::string_view(LESSON), std::string_view("lesson.toml"));
    try {
        parseSceneToml(*lesson["scene"].as_table(), "lesson.toml");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "lesson.toml:15: sphere radius must be positive, got -2");
        EXPECT_EQ(e.line(), 15);
        EXPECT_EQ(e.source(), "lesson.toml");
        EXPECT_EQ(e.problem(), "sphere radius must be positive, got -2");
    }
}

TEST(SceneFile, ReadsFilesAndReportsMissingOnes) {
    std::string path = testing::TempDir() + "pcfscope_scene_file_test.toml";
    {
        std::ofstream out(path);
        out << GOOD;
    }
    Scene s = parseSceneFile(path);
    EXPECT_EQ(s.name, path);
    EXPECT_EQ(s.objects.size(), 3u);
    std::remove(path.c_str());
    try {
        parseSceneFile(path);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": cannot open file");
    }
    EXPECT_THROW(parseSceneFile(testing::TempDir()), InputError);  // a directory
}

struct BadCase {
    const char* label;
    std::string text;
    int line;
    const char* problem;  // the message after `bad.toml:LINE: ` starts with this
};

const std::string CAMERA = "[camera]\neye = [6, 5, 7]\ntarget = [0, 0, 0]\n";  // lines 1-3
const std::string SUN = "[light]\ntype = \"directional\"\ndirection = [0, -1, 0]\n";
const std::string BALL = "[[object]]\ntype = \"sphere\"\ncentre = [0, 1, 0]\nradius = 0.5\n";

// Camera (3 lines) + light (3 lines) + the object text starting on line 7.
std::string withObject(const std::string& object) { return CAMERA + SUN + object; }

std::vector<BadCase> badCases() {
    return {
        {"syntax", CAMERA + "fov = = 40\n" + SUN + BALL, 4, ""},
        // toml++ notices the unclosed array where the next table starts.
        {"unclosed array", CAMERA + "fov = [1, 2\n" + SUN + BALL, 5, ""},
        {"duplicate key", CAMERA + "eye = [1, 1, 1]\n" + SUN + BALL, 4, ""},
        {"unknown type", withObject("[[object]]\ntype = \"cone\"\n"), 8,
         "unknown object type 'cone' (expected plane, box or sphere)"},
        {"missing radius", withObject("[[object]]\ntype = \"sphere\"\ncentre = [0, 1, 0]\n"), 7,
         "sphere is missing required key 'radius'"},
        {"missing type", withObject("[[object]]\ncentre = [0, 1, 0]\n"), 7,
         "object is missing required key 'type'"},
        {"radius string",
         withObject("[[object]]\ntype = \"sphere\"\ncentre = [0, 1, 0]\n"
                    "radius = \"big\"\n"),
         10, "sphere radius must be a number, got string"},
        {"short vector",
         withObject("[[object]]\ntype = \"sphere\"\ncentre = [0, 1]\n"
                    "radius = 1\n"),
         9, "sphere centre must be an array of 3 numbers, got 2"},
        {"vector of strings",
         withObject("[[object]]\ntype = \"sphere\"\ncentre = [0, \"1\", 0]\n"
                    "radius = 1\n"),
         9, "sphere centre[1] must be a number, got string"},
        {"type not a string", withObject("[[object]]\ntype = 3\n"), 8,
         "object type must be a string, got integer"},
        {"nan", withObject("[[object]]\ntype = \"sphere\"\ncentre = [0, 1, 0]\nradius = nan\n"), 10,
         "sphere radius must be finite, got nan"},
        {"inf", withObject("[[object]]\ntype = \"sphere\"\ncentre = [-inf, 1, 0]\nradius = 1\n"), 9,
         "sphere centre[0] must be finite, got -inf"},
        {"negative radius",
         withObject("[[object]]\ntype = \"sphere\"\ncentre = [0, 1, 0]\nradius = -1\n"), 10,
         "sphere radius must be positive, got -1"},
        {"zero radius",
         withObject("[[object]]\ntype = \"sphere\"\ncentre = [0, 1, 0]\nradius = 0\n"), 10,
         "sphere radius must be positive, got 0"},
        {"flat box",
         withObject("[[object]]\ntype = \"box\"\ncentre = [0, 1, 0]\n"
                    "half = [0.5, 0, 0.5]\n"),
         10, "box half must be positive, got [0.5, 0, 0.5]"},
        {"negative plane size",
         withObject("[[object]]\ntype = \"plane\"\ncentre = [0, 0, 0]\n"
                    "normal = [0, 1, 0]\nsize = [10, -4]\n"),
         11, "plane size must be positive, got [10, -4]"},
        {"zero normal",
         withObject("[[object]]\ntype = \"plane\"\ncentre = [0, 0, 0]\n"
                    "normal = [0, 0, 0]\nsize = [10, 4]\n"),
         10, "plane normal must not be zero-length"},
        {"tangent along normal",
         withObject("[[object]]\ntype = \"plane\"\ncentre = [0, 0, 0]\n"
                    "normal = [0, 1, 0]\nsize = [10, 4]\n"
                    "tangent = [0, -2, 0]\n"),
         12, "plane tangent must not be zero-length or parallel to the normal"},
        {"zero light direction",
         CAMERA + "[light]\ntype = \"directional\"\ndirection = [0, 0, 0]\n" + BALL, 6,
         "directional light direction must not be zero-length"},
        {"fov too wide", CAMERA + "fov = 179\n" + SUN + BALL, 4,
         "camera fov must be in (1, 179) degrees, got 179"},
        {"fov too narrow", CAMERA + "fov = 0.5\n" + SUN + BALL, 4,
         "camera fov must be in (1, 179) degrees, got 0.5"},
        {"eye at target", "[camera]\neye = [1, 2, 3]\n\ntarget = [1.0, 2, 3]\n" + SUN + BALL, 4,
         "camera eye and target must differ, both are [1, 2, 3]"},
        {"up along view",
         "[camera]\neye = [0, 5, 0]\ntarget = [0, 0, 0]\nup = [0, 1, 0]\n" + SUN + BALL, 4,
         "camera up must not be parallel to the view direction"},
        {"negative near", CAMERA + "near = -1\n" + SUN + BALL, 4,
         "camera near must be positive, got -1"},
        {"far before near", CAMERA + "near = 2\nfar = 1\n" + SUN + BALL, 5,
         "camera far must be greater than near (2), got 1"},
        {"empty scene", CAMERA + SUN, 1, "scene has no objects"},
        {"empty object array", "object = []\n" + CAMERA + SUN, 1, "scene has no objects"},
        {"object not tables", "\nobject = 5\n" + CAMERA + SUN, 2,
         "object must be an array of tables ([[object]]), got integer"},
        {"object array of numbers", "object = [1, 2]\n" + CAMERA + SUN, 1,
         "object must be an array of tables ([[object]]), got an array of other values"},
        {"missing camera", SUN + BALL, 1, "scene is missing the [camera] table"},
        {"camera not a table", "camera = 3\n" + SUN + BALL, 1,
         "camera must be a table ([camera]), got integer"},
        {"missing light", CAMERA + BALL, 1, "scene is missing the [light] table"},
        {"light without type", CAMERA + "[light]\ndirection = [0, -1, 0]\n" + BALL, 4,
         "light is missing required key 'type'"},
        {"unknown light", CAMERA + "[light]\ntype = \"point\"\n" + BALL, 5,
         "unknown light type 'point' (expected directional or spot)"},
        {"spot cone",
         CAMERA +
             "[light]\ntype = \"spot\"\ndirection = [0, -1, 0]\n"
             "position = [0, 5, 0]\ncone = 95\n" +
             BALL,
         8, "spot light cone must be in [0.01, 89] degrees, got 95"},
        // Printed as given, not rounded to the limit it exceeds ("got 89" read as a contradiction).
        {"spot cone a hair wide",
         CAMERA +
             "[light]\ntype = \"spot\"\ndirection = [0, -1, 0]\n"
             "position = [0, 5, 0]\ncone = 89.0000000001\n" +
             BALL,
         8, "spot light cone must be in [0.01, 89] degrees, got 89.0000000001"},
        // A cone too thin for float's tangent gave infinite light-space coordinates.
        {"spot cone too thin",
         CAMERA +
             "[light]\ntype = \"spot\"\ndirection = [0, -1, 0]\n"
             "position = [0, 5, 0]\ncone = 1e-45\n" +
             BALL,
         8, "spot light cone must be in [0.01, 89] degrees, got 1e-45"},
        {"spot without position",
         CAMERA + "[light]\ntype = \"spot\"\ndirection = [0, -1, 0]\ncone = 30\n" + BALL, 4,
         "spot light is missing required key 'position'"},
        {"cone on directional", CAMERA + SUN + "cone = 30\n" + BALL, 7,
         "directional light has unknown key 'cone'"},
        {"sun too wide", CAMERA + SUN + "angular_diameter = 12\n" + BALL, 7,
         "directional light angular_diameter must be in [0, 10] degrees, got 12"},
        {"negative sun", CAMERA + SUN + "angular_diameter = -0.5\n" + BALL, 7,
         "directional light angular_diameter must be in [0, 10] degrees, got -0.5"},
        {"sun a hair too wide", CAMERA + SUN + "angular_diameter = 10.000000000001\n" + BALL, 7,
         "directional light angular_diameter must be in [0, 10] degrees, got 10.000000000001"},
        {"radius on directional", CAMERA + SUN + "radius = 0.1\n" + BALL, 7,
         "directional light has unknown key 'radius'"},
        {"negative spot radius",
         CAMERA +
             "[light]\ntype = \"spot\"\ndirection = [0, -1, 0]\n"
             "position = [0, 5, 0]\ncone = 30\nradius = -1\n" +
             BALL,
         9, "spot light radius must be in [0, 100] world units, got -1"},
        {"misspelt key",
         withObject("[[object]]\ntype = \"sphere\"\ncentre = [0, 1, 0]\n"
                    "raduis = 1\n"),
         10, "sphere has unknown key 'raduis'"},
        {"american colour", withObject(BALL + "color = [1, 0, 0]\n"), 11,
         "sphere has unknown key 'color' (did you mean 'colour'?)"},
        {"colour range", withObject(BALL + "colour = [1.5, 0, 0]\n"), 11,
         "sphere colour must be in [0, 1], got [1.5, 0, 0]"},
        {"flag type", withObject(BALL + "casts_shadow = \"yes\"\n"), 11,
         "sphere casts_shadow must be true or false, got string"},
        {"duplicate name", withObject(BALL + "name = \"a\"\n" + BALL + "name = \"a\"\n"), 16,
         "object name 'a' is used twice (first at line 7)"},
    };
}

TEST(SceneFile, BadInputNamesFileAndLine) {
    for (const BadCase& c : badCases()) {
        SCOPED_TRACE(c.label);
        try {
            parseSceneString(c.text, "bad.toml");
            ADD_FAILURE() << "no error for: " << c.label;
        } catch (const InputError& e) {
            std::string what = e.what();
            std::string prefix = "bad.toml:" + std::to_string(c.line) + ": ";
            EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
            EXPECT_EQ(e.line(), c.line) << what;
            EXPECT_EQ(e.problem().rfind(c.problem, 0), 0u) << what;
            EXPECT_GT(e.problem().size(), 0u);
            if (std::getenv("PCFSCOPE_PRINT_ERRORS")) std::printf("%s\n", what.c_str());
        }
    }
}

TEST(SceneFile, InputErrorIsARuntimeError) {
    InputError e("box.toml", 7, "sphere radius must be positive, got -1");
    EXPECT_STREQ(e.what(), "box.toml:7: sphere radius must be positive, got -1");
    const std::runtime_error& base = e;
    EXPECT_STREQ(base.what(), e.what());
    EXPECT_STREQ(InputError("x.toml", 0, "cannot open file").what(), "x.toml: cannot open file");
    // One line always: a newline in the problem (or a file name) is written \n (oneLine).
    EXPECT_STREQ(InputError("x.toml", 2, "two\nlines").what(), "x.toml:2: two\\nlines");
    EXPECT_STREQ(InputError("a\tb.toml", 0, "x").what(), "a\\tb.toml: x");
}

}  // namespace
}  // namespace pcf

namespace pcf {
namespace {

std::string presetFileError(const std::string& text) {
    try {
        parseSceneString(text, "cards.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

// A scene file may be a preset with its numbers: [preset] name and gap set stacked-cards'
// gap; a number out of range, an unknown one, an unknown preset, or other scene tables beside
// it are refused with one line saying where.
TEST(SceneFile, APresetTableSetsThePresetsNumbers) {
    Scene scene = parseSceneString("[preset]\nname = \"stacked-cards\"\ngap = 0.3\n", "cards.toml");
    const double values[] = {0.3};
    Scene expected = *presetScene("stacked-cards", values);
    EXPECT_EQ(scene.name, "cards.toml");
    ASSERT_EQ(scene.objects.size(), expected.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        EXPECT_EQ(bounds(scene.objects[i].shape).minWs, bounds(expected.objects[i].shape).minWs);
        EXPECT_EQ(bounds(scene.objects[i].shape).maxWs, bounds(expected.objects[i].shape).maxWs);
    }
    // Without gap: the preset's default.
    Scene plain = parseSceneString("[preset]\nname = \"stacked-cards\"\n", "cards.toml");
    EXPECT_EQ(bounds(plain.objects.back().shape).minWs,
              bounds(presetScene("stacked-cards")->objects.back().shape).minWs);

    EXPECT_EQ(presetFileError("[preset]\nname = \"stacked-cards\"\ngap = 5\n"),
              "cards.toml:3: stacked-cards gap must be in [0.05, 2] world units, got 5");
    EXPECT_EQ(presetFileError("[preset]\nname = \"stacked-cards\"\ngap = \"wide\"\n"),
              "cards.toml:3: preset gap must be a number, got string");
    EXPECT_EQ(presetFileError("[preset]\nname = \"stacked-cards\"\n\nspace = 1\n"),
              "cards.toml:4: preset stacked-cards has no parameter 'space' (it takes gap)");
    EXPECT_EQ(presetFileError("[preset]\nname = \"pole\"\ngap = 1\n"),
              "cards.toml:3: preset pole has no parameter 'gap' (it takes none)");
    EXPECT_EQ(presetFileError("[preset]\nname = \"cards\"\n").substr(0, 41),
              "cards.toml:2: unknown preset 'cards' (kno");
    EXPECT_EQ(presetFileError("[preset]\ngap = 1\n"),
              "cards.toml:1: preset is missing required key 'name'");
    EXPECT_EQ(presetFileError("preset = 1\n"),
              "cards.toml:1: preset must be a table ([preset]), got integer");
    EXPECT_EQ(presetFileError("[preset]\nname = \"pole\"\n[light]\ntype = \"spot\"\n"),
              "cards.toml:3: a scene file with [preset] takes no light table (the preset has its "
              "own)");
}

}  // namespace
}  // namespace pcf
