// The teaching frames as a user gets them: `pcfscope export` (headless), `pcfscope view` with
// replayed keys under Xvfb, and the main job without a display.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "image_read.h"
#include "json_lite.h"
#include "kernel/methods.h"
#include "kernel/trace_explain.h"
#include "lesson/lesson.h"
#include "overlay/inspector.h"
#include "run_command.h"
#include "virtual_display.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;
using testutil::runPcfscope;

// A lesson of our own, so the test knows what each step shows.
constexpr const char* TEST_LESSON = R"(title = "Test lesson"
scene = "box-on-plane"
[settings]
map_size = 128
cull = "front"
point = [0.9398, 0.0, 0.3514]
[[step]]
title = "Nearest"
text = "texel {base.x},{base.y}: visibility = {visibility}"
method = "nearest"
[[step]]
title = "Bilinear"
text = "fx = {frac.x}, fy = {frac.y}, visibility = {visibility}"
method = "bilinear2x2"
point = [0.4370, 0.7305, 0.3479]  # on the box shadow's edge: lit and shadowed texels
[[step]]
title = "Gather"
text = "{texels} texels, {gathers} gathers, visibility = {visibility}"
method = "pcf-gather"
)";

class ExportTest : public ::testing::Test {
  protected:
    void SetUp() override {
        mDir = testutil::makeTempDir("export");
        std::ofstream(mDir / "test.toml") << TEST_LESSON;
    }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    fs::path mDir;
};

std::string readFile(const std::string& p) { return testutil::readAll(p); }

TEST_F(ExportTest, WritesAFrameAndATracePerStep) {
    auto r =
        runPcfscope("export " + path("test.toml") + " -o " + path("frames") + " --size 1280x720",
                    "env -u DISPLAY");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (int s = 1; s <= 3; ++s) {
        std::string stem = path("frames/test-step0" + std::to_string(s));
        ImageSize size = readImageSize(stem + ".png");
        EXPECT_EQ(size.width, 1280);
        EXPECT_EQ(size.height, 720);
        jsonlite::Value j = jsonlite::parse(readFile(stem + ".json"));
        EXPECT_EQ(j["step"].number, s);
        ASSERT_EQ(j["trace"].kind, jsonlite::Value::OBJECT) << "step " << s << " has no receiver";
        const jsonlite::Value& tr = j["trace"];
        // The step text shows the kernel's own numbers.
        float visibility = static_cast<float>(tr["visibility"].number);
        EXPECT_NE(j["text"].string.find("visibility = " + formatNumber(visibility)),
                  std::string::npos)
            << j["text"].string;
        double sum = 0.0;
        for (const jsonlite::Value& t : tr["taps"].array) {
            sum += t["weight"].number * t["lit"].number;
        }
        EXPECT_NEAR(sum, visibility, 1e-5);
        // The sidecar lists the frame's layout: the four panels, then what was drawn in them.
        const jsonlite::Value& layout = j["layout"];
        ASSERT_EQ(layout.kind, jsonlite::Value::ARRAY);
        int panels = 0, numbers = 0, stepText = 0;
        for (const jsonlite::Value& b : layout.array) {
            panels += b["kind"].string == "panel";
            numbers += b["kind"].string == "number";
            if (b["role"].string == "step-text") {
                ++stepText;
                EXPECT_GE(b["font_px"].number, 12.0);
                EXPECT_EQ(b["rect"].array.size(), 4u);
            }
        }
        EXPECT_EQ(panels, 4);
        EXPECT_GT(numbers, 4);  // at least a bit per cell and the visibility
        EXPECT_EQ(stepText, 1);
        // Its focus (nearest: the scene and the texel; a filter: the neighbourhood and the
        // formula), and every texel and fetch the trace read among those drawn.
        EXPECT_EQ(j["focus"].string, s == 1 ? "scene+neighbourhood" : "neighbourhood+formula");
        std::set<std::pair<double, double>> drawn;
        for (const jsonlite::Value& d : j["drawn"]["texels"].array) {
            drawn.insert({d[0].number, d[1].number});
        }
        ASSERT_FALSE(j["read"]["texels"].array.empty());
        for (const jsonlite::Value& rt : j["read"]["texels"].array) {
            EXPECT_TRUE(drawn.count({rt[0].number, rt[1].number})) << "step " << s;
        }
        EXPECT_EQ(j["drawn"]["fetches"].array.size(), j["read"]["fetches"].array.size());
        EXPECT_EQ(j["read"]["fetches"].array.size(), tr["fetch_list"].array.size());
    }
    jsonlite::Value gather = jsonlite::parse(readFile(path("frames/test-step03.json")));
    EXPECT_EQ(gather["trace"]["method"].string, "pcf-gather");
    EXPECT_NE(gather["text"].string.find("16 texels, 4 gathers"), std::string::npos);
    EXPECT_NE(r.err.find("frames/s"), std::string::npos) << r.err;
}

// The neighbourhood's cells are tinted by their comparison bit: look at the exported pixels of
// each tap's cell and find the lit or the shadowed colour there.
TEST_F(ExportTest, CellsAreTintedByTheirBits) {
    auto r = runPcfscope(
        "export " + path("test.toml") + " -o " + path("frames") + " --size 1600x900 --steps 2",
        "env -u DISPLAY");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    jsonlite::Value j = jsonlite::parse(readFile(path("frames/test-step02.json")));
    std::vector<unsigned char> px = readImageBytes(path("frames/test-step02.png"), 4);
    // The cells where the sidecar says the frame drew them.
    const jsonlite::Value& t = j["trace"];
    const jsonlite::Value& cells = j["drawn"]["cells"];
    ASSERT_EQ(cells.kind, jsonlite::Value::OBJECT);
    Neighbourhood n{
        {static_cast<int>(cells["origin"][0].number), static_cast<int>(cells["origin"][1].number)},
        {static_cast<int>(cells["size"][0].number), static_cast<int>(cells["size"][1].number)}};
    EXPECT_EQ(n.size, glm::ivec2(2, 2));
    EXPECT_EQ(j["focus"].string, "neighbourhood+formula");
    Rect area{
        static_cast<float>(cells["rect"][0].number), static_cast<float>(cells["rect"][1].number),
        static_cast<float>(cells["rect"][2].number), static_cast<float>(cells["rect"][3].number)};
    int litCells = 0;
    int shadowedCells = 0;
    for (const jsonlite::Value& tap : t["taps"].array) {
        glm::ivec2 texel(static_cast<int>(tap["texel"][0].number),
                         static_cast<int>(tap["texel"][1].number));
        Rect cell = texelCellRect(n, area, texel);
        // A few pixels in from the cell's top-left corner: past the grid line, before the text.
        size_t k = (static_cast<size_t>(cell.y + 4) * 1600 + static_cast<size_t>(cell.x + 4)) * 4;
        bool lit = tap["lit"].number == 1;
        Colour expect = lit ? LIT_COLOUR : SHADOWED_COLOUR;
        EXPECT_NEAR(px[k], expect.r * 255.0f, 1.0f) << "texel " << texel.x << "," << texel.y;
        EXPECT_NEAR(px[k + 1], expect.g * 255.0f, 1.0f) << "texel " << texel.x << "," << texel.y;
        EXPECT_NEAR(px[k + 2], expect.b * 255.0f, 1.0f) << "texel " << texel.x << "," << texel.y;
        (lit ? litCells : shadowedCells) += 1;
    }
    EXPECT_EQ(litCells + shadowedCells, 4);
    // The picked pixel of this step sits on the shadow's edge: both kinds of cell are there.
    EXPECT_GT(litCells, 0);
    EXPECT_GT(shadowedCells, 0);
}

// A chart step shows the bench chart where the scene goes; the next step shows the scene again.
TEST_F(ExportTest, ChartStepsShowTheChartInTheScenesPlace) {
    auto r = runPcfscope("export 11-speed-and-accuracy -o " + path("chart") +
                         " --size 1600x900 --steps 3-4");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<unsigned char> chart =
        readImageBytes(path("chart/11-speed-and-accuracy-step03.png"), 4);
    std::vector<unsigned char> scene =
        readImageBytes(path("chart/11-speed-and-accuracy-step04.png"), 4);
    // The chart's page is white at the scene's top-left corner; the scene there is sky.
    auto at = [](const std::vector<unsigned char>& px, int x, int y) {
        size_t k = (static_cast<size_t>(y) * 1600 + x) * 4;
        return glm::ivec3(px[k], px[k + 1], px[k + 2]);
    };
    EXPECT_EQ(at(chart, 4, 4), glm::ivec3(255, 255, 255));
    EXPECT_NE(at(scene, 4, 4), glm::ivec3(255, 255, 255));
    // The inspector still traces the pixel on both.
    jsonlite::Value j = jsonlite::parse(readFile(path("chart/11-speed-and-accuracy-step03.json")));
    EXPECT_EQ(j["trace"].kind, jsonlite::Value::OBJECT);
}

// `render --lesson L --step S` of a chart step writes the chart, as export shows it, at --size;
// the step's chart_highlight rings its dots in orange; a scene step still writes the scene.
TEST_F(ExportTest, RenderOfAChartStepWritesTheChart) {
    auto r = runPcfscope("render --lesson 11 --step 2 --size 960x540 -o " + path("chart.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("the chart of lesson step 2"), std::string::npos) << r.err;
    auto s = runPcfscope("render --lesson 11 --step 4 --size 960x540 -o " + path("scene.png"));
    ASSERT_EQ(s.exitCode, 0) << s.err;
    std::vector<unsigned char> chart = readImageBytes(path("chart.png"), 4);
    std::vector<unsigned char> scene = readImageBytes(path("scene.png"), 4);
    ASSERT_EQ(chart.size(), 960u * 540u * 4u);
    auto at = [](const std::vector<unsigned char>& px, int x, int y) {
        size_t k = (static_cast<size_t>(y) * 960 + x) * 4;
        return glm::ivec3(px[k], px[k + 1], px[k + 2]);
    };
    EXPECT_EQ(at(chart, 4, 4), glm::ivec3(255, 255, 255));
    EXPECT_NE(at(scene, 4, 4), glm::ivec3(255, 255, 255));
    // The highlight's orange (255, 140, 0) is on the chart: the Pareto front's dots.
    int orange = 0;
    for (size_t k = 0; k < chart.size(); k += 4) {
        orange += chart[k] >= 250 && chart[k + 1] >= 130 && chart[k + 1] <= 150 &&
                  chart[k + 2] <= 10;  // not box2x2's dots (242, 143, 43)
    }
    EXPECT_GT(orange, 50);
}

// Every lesson that ships exports headless, a frame and a trace per step, each step's pixel on a
// receiver (its numbers come from a trace, not from nowhere).
TEST_F(ExportTest, EveryLessonExportsHeadless) {
    int lessons = 0;
    for (const auto& entry : fs::directory_iterator(PCFSCOPE_SOURCE_DIR "/lessons")) {
        if (entry.path().extension() != ".toml") continue;
        ++lessons;
        Lesson lesson = parseLessonFile(entry.path().string());
        std::string dir = path("all/" + lesson.name);
        auto r = runPcfscope("export " + entry.path().string() + " -o " + dir + " --size 1280x720",
                             "env -u DISPLAY -u WAYLAND_DISPLAY");
        ASSERT_EQ(r.exitCode, 0) << lesson.name << ": " << r.err;
        for (size_t s = 1; s <= lesson.steps.size(); ++s) {
            char step[16];
            std::snprintf(step, sizeof step, "-step%02zu", s);
            std::string stem = dir + "/" + lesson.name + step;
            EXPECT_EQ(readImageSize(stem + ".png").width, 1280) << stem;
            jsonlite::Value j = jsonlite::parse(readFile(stem + ".json"));
            EXPECT_EQ(j["trace"].kind, jsonlite::Value::OBJECT) << stem << ": no receiver";
            EXPECT_EQ(j["text"].string.find('{'), std::string::npos) << stem << ": unfilled";
            // The text as drawn: code spans without their backticks (lessons 11, 13-15 have them).
            EXPECT_EQ(j["text"].string.find('`'), std::string::npos) << stem << ": backticks";
        }
    }
    EXPECT_GE(lessons, 10);
}

TEST_F(ExportTest, SameBytesOnEveryRun) {
    auto a = runPcfscope("export " + path("test.toml") + " -o " + path("a") + " --size 800x450");
    auto b = runPcfscope("export " + path("test.toml") + " -o " + path("b") + " --size 800x450");
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    for (int s = 1; s <= 3; ++s) {
        std::string name = "/test-" + std::to_string(s);
        EXPECT_EQ(readFile(path("a") + name + ".png"), readFile(path("b") + name + ".png")) << s;
        EXPECT_EQ(readFile(path("a") + name + ".json"), readFile(path("b") + name + ".json")) << s;
    }
}

TEST_F(ExportTest, RefusesToOverwriteAndBadInputExitsTwo) {
    ASSERT_EQ(
        runPcfscope("export " + path("test.toml") + " -o " + path("f") + " --steps 1").exitCode, 0);
    auto again = runPcfscope("export " + path("test.toml") + " -o " + path("f") + " --steps 1");
    EXPECT_EQ(again.exitCode, 2);
    EXPECT_NE(again.err.find("already exists"), std::string::npos) << again.err;

    std::ofstream(mDir / "bad.toml") << "title = \"x\"\nscene = \"box-on-plane\"\n[[step]]\n"
                                        "title = \"a\"\ntext = \"{frac.q}\"\n";
    auto bad = runPcfscope("export " + path("bad.toml") + " -o " + path("g"));
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_EQ(testutil::lineCount(bad.err), 1) << bad.err;
    EXPECT_NE(bad.err.find("bad.toml:5:"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(path("g")));

    auto steps = runPcfscope("export " + path("test.toml") + " -o " + path("h") + " --steps 2-9");
    EXPECT_EQ(steps.exitCode, 2);
    EXPECT_NE(steps.err.find("--steps"), std::string::npos) << steps.err;
    EXPECT_FALSE(fs::exists(path("h")));

    auto unknown = runPcfscope("export no-such-lesson");
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_NE(unknown.err.find("unknown lesson"), std::string::npos) << unknown.err;
}

// A chart's bench.csv is read when the lesson is loaded, so a broken one is reported at the
// lesson's line (and the CSV's) before any frame is made, by export and by view alike.
TEST_F(ExportTest, BrokenChartIsReportedAtItsLessonLine) {
    std::ofstream(mDir / "chart.toml") << "title = \"x\"\nscene = \"box-on-plane\"\n[[step]]\n"
                                          "title = \"a\"\ntext = \"b\"\nchart = \"bad.csv\"\n";
    std::ofstream(mDir / "bad.csv")
        << "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,edge_rmse,"
           "edge_max_err,timer\npcf-gather,3,1024,fast\n";
    // view checks the lesson before it opens a window (so no real display is needed here).
    std::vector<testutil::CommandResult> runs = {
        runPcfscope("export " + path("chart.toml") + " -o " + path("c")),
        runPcfscope("view " + path("chart.toml"), "DISPLAY=:pcfscope-none"),
    };
    for (const testutil::CommandResult& r : runs) {
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find("chart.toml:6: step 1 chart:"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("bad.csv:2: expected 11 fields"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(fs::exists(path("c")));
}

TEST_F(ExportTest, ViewWithoutADisplaySaysSoAndPointsToExport) {
    auto r = runPcfscope("view " + path("test.toml"), "env -u DISPLAY -u WAYLAND_DISPLAY");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("display"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("pcfscope export"), std::string::npos) << r.err;
}

TEST_F(ExportTest, MainJobWithoutADisplayExportsLessonOne) {
    auto r = runPcfscope("", "cd " + mDir.string() + " && env -u DISPLAY -u WAYLAND_DISPLAY");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("exported"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(mDir / "pcfscope-frames"));
    int pngs = 0;
    for (const auto& e : fs::recursive_directory_iterator(mDir / "pcfscope-frames")) {
        pngs += e.path().extension() == ".png";
    }
    EXPECT_GE(pngs, 3);
    // A second run goes to a new folder instead of overwriting the first.
    auto again = runPcfscope("", "cd " + mDir.string() + " && env -u DISPLAY -u WAYLAND_DISPLAY");
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_NE(again.out.find("-2/"), std::string::npos) << again.out;
}

TEST_F(ExportTest, ViewKeysScreenshotIsTheExportedFrame) {
    testutil::VirtualDisplay x;
    ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
    auto shot = runPcfscope(
        "view " + path("test.toml") + " --keys \"right right\" --screenshot " + path("shot.png"),
        "DISPLAY=" + x.display());
    ASSERT_EQ(shot.exitCode, 0) << shot.err;
    auto r = runPcfscope("export " + path("test.toml") + " -o " + path("frames") + " --steps 3");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(readFile(path("shot.png")), readFile(path("frames/test-step03.png")));
    // Keys change the state: M moves pcf-gather to pcf-hw, and the frame changes with it.
    auto other = runPcfscope(
        "view " + path("test.toml") + " --keys \"end m\" --screenshot " + path("shot-m.png"),
        "DISPLAY=" + x.display());
    ASSERT_EQ(other.exitCode, 0) << other.err;
    EXPECT_NE(readFile(path("shot-m.png")), readFile(path("frames/test-step03.png")));
    // Keys that change the state the words were written for: the numbers follow the live
    // state and the text says it was written for another one (the E key's JSON holds it; 5.1
    // asks first, R shows the answer and the words).
    auto wider = runPcfscope("view 5 --keys \"right_bracket r e\" --screenshot " + path("n4.png"),
                             "cd " + mDir.string() + " && DISPLAY=" + x.display());
    ASSERT_EQ(wider.exitCode, 0) << wider.err;
    jsonlite::Value step =
        jsonlite::parse(readFile(path("pcfscope-frames/05-gather-weights-step01-reveal.json")));
    EXPECT_NE(step["text"].string.find("(Written for pcf-gather N=3"), std::string::npos)
        << step["text"].string;
    EXPECT_NE(step["text"].string.find("now pcf-gather N=4"), std::string::npos);
    EXPECT_NE(step["text"].string.find("against 64 reads in 16 lookups"), std::string::npos)
        << step["text"].string;
    // A kernel change under a method that has none changes nothing the words talk about.
    auto same = runPcfscope("view 8 --keys \"right_bracket e\" --screenshot " + path("n8.png"),
                            "cd " + mDir.string() + " && DISPLAY=" + x.display());
    ASSERT_EQ(same.exitCode, 0) << same.err;
    jsonlite::Value acne =
        jsonlite::parse(readFile(path("pcfscope-frames/08-acne-and-bias-step01.json")));
    EXPECT_EQ(acne["text"].string.find("(Written for"), std::string::npos) << acne["text"].string;
    auto badKey =
        runPcfscope("view " + path("test.toml") + " --keys \"warp\" --screenshot " + path("x.png"),
                    "DISPLAY=" + x.display());
    EXPECT_EQ(badKey.exitCode, 2);
    EXPECT_NE(badKey.err.find("unknown key 'warp'"), std::string::npos) << badKey.err;
}

}  // namespace
}  // namespace pcf
