// What pcfscope reads is bounded before it costs anything: lesson titles, texts and step counts,
// scene objects, chart rows, input file sizes, depth-image sides. Each limit is refused with one
// line that names it; FIFOs and other non-regular files are refused without blocking.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "app/cli_util.h"
#include "app/session.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "lesson/lesson.h"
#include "render/image_io.h"
#include "run_command.h"
#include "scene/scene_file.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

const std::string SCENE_HEAD =
    "[camera]\neye = [0, 2, 6]\ntarget = [0, 0, 0]\n"
    "[light]\ntype = \"directional\"\ndirection = [-0.4, -1, -0.3]\n";

std::string lessonWith(const std::string& title, int steps, const std::string& stepTitle,
                       const std::string& text) {
    std::string s = "title = \"" + title + "\"\nscene = \"box-on-plane\"\n";
    for (int k = 0; k < steps; ++k) {
        s += "[[step]]\ntitle = \"" + stepTitle + "\"\ntext = \"" + text + "\"\n";
    }
    return s;
}

// The message of the InputError that parsing `text` throws ("" when it parses).
std::string lessonError(const std::string& text) {
    try {
        parseLessonString(text, "limits.toml");
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
        return e.what();
    }
    return "";
}

TEST(InputLimits, LessonTitleAtTheLimitParsesOneMoreIsRefused) {
    EXPECT_EQ(lessonError(lessonWith(std::string(MAX_TITLE_CHARS, 'T'), 3, "s", "x")), "");
    EXPECT_EQ(lessonError(lessonWith(std::string(MAX_TITLE_CHARS + 1, 'T'), 3, "s", "x")),
              "limits.toml:1: lesson title is 121 characters; the limit is 120");
}

TEST(InputLimits, TitlesCountCharactersNotBytes) {
    // 120 two-byte letters: 240 bytes, 120 characters.
    std::string e;
    for (size_t k = 0; k < MAX_TITLE_CHARS; ++k) e += "\xc3\xa9";
    EXPECT_EQ(lessonError(lessonWith(e, 3, "s", "x")), "");
}

TEST(InputLimits, StepTitleAndTextLimitsNameTheStep) {
    std::string longTitle(MAX_TITLE_CHARS + 5, 's');
    EXPECT_EQ(lessonError(lessonWith("L", 2, longTitle, "x")),
              "limits.toml:4: step 1 title is 125 characters; the limit is 120");
    EXPECT_EQ(lessonError(lessonWith("L", 2, "s", std::string(MAX_STEP_TEXT_CHARS, 'x'))), "");
    EXPECT_EQ(lessonError(lessonWith("L", 2, "s", std::string(MAX_STEP_TEXT_CHARS + 1, 'x'))),
              "limits.toml:5: step 1 text is 4001 characters; the limit is 4000");
}

TEST(InputLimits, StepCount) {
    EXPECT_EQ(lessonError(lessonWith("L", MAX_LESSON_STEPS, "s", "x")), "");
    std::string e = lessonError(lessonWith("L", MAX_LESSON_STEPS + 1, "s", "x"));
    EXPECT_NE(e.find("lesson has 33 steps; the limit is 32"), std::string::npos) << e;
}

TEST(InputLimits, SceneObjects) {
    auto scene = [](size_t objects) {
        std::string s = SCENE_HEAD;
        for (size_t k = 0; k < objects; ++k) {
            s += "[[object]]\nname = \"s" + std::to_string(k) +
                 "\"\ntype = \"sphere\"\ncentre = [0, 1, 0]\nradius = 0.5\n";
        }
        return s;
    };
    EXPECT_NO_THROW(parseSceneString(scene(MAX_SCENE_OBJECTS), "objects.toml"));
    try {
        parseSceneString(scene(MAX_SCENE_OBJECTS + 1), "objects.toml");
        ADD_FAILURE() << "257 objects accepted";
    } catch (const InputError& e) {
        // The line of the first object past the limit: 6 lines of head, 5 per object.
        EXPECT_STREQ(e.what(), "objects.toml:1287: scene has 257 objects; the limit is 256");
    }
}

class InputFiles : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("limits"); }
    void TearDown() override { fs::remove_all(mDir); }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    fs::path mDir;
};

TEST_F(InputFiles, AFifoIsRefusedWithoutBlocking) {
    std::string fifo = path("lesson.toml");
    ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
    auto start = std::chrono::steady_clock::now();
    try {
        readInputFile(fifo);
        ADD_FAILURE() << "a FIFO was read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), fifo + ": not a regular file (a FIFO, device or socket)");
    }
    EXPECT_THROW(parseLessonFile(fifo), InputError);
    EXPECT_THROW(parseSceneFile(fifo), InputError);
    EXPECT_THROW(readDepthImage(fifo), ImageError);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    // A lesson's chart that is a FIFO is said to be one, not "not found".
    ASSERT_EQ(mkfifo(path("chart.csv").c_str(), 0644), 0);
    std::ofstream(path("chart.toml")) << "title = \"t\"\nscene = \"box-on-plane\"\n[[step]]\n"
                                         "title = \"s\"\nchart = \"chart.csv\"\ntext = \"x\"\n";
    try {
        parseLessonFile(path("chart.toml"));
        ADD_FAILURE() << "a FIFO chart was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path("chart.toml") + ":5: step 1 chart 'chart.csv' is not a regular file (a " +
                      "FIFO, device or socket) (looked at " + path("chart.csv") + ")");
    }
}

// A claim nested 60,000 deep (120 KB, well under the file limit) overflowed the claim parser's
// stack in every command that reads a lesson: now one line naming the claim's line, exit 2.
TEST_F(InputFiles, ADeeplyNestedClaimIsOneLineNotACrash) {
    for (const std::string& expr :
         {std::string(60000, '(') + "1" + std::string(60000, ')'), std::string(60000, '-') + "1"}) {
        std::string lesson = path("deep.toml");
        std::ofstream(lesson) << "title = \"t\"\nscene = \"box-on-plane\"\n[[step]]\n"
                                 "title = \"s\"\nclaims = [\"" +
                                     expr + " = 1\"]\ntext = \"x\"\n";
        for (const std::string& command :
             {std::string("lesson check "), "export --size 320x180 -o " + path("frames") + " "}) {
            testutil::CommandResult r = testutil::runPcfscope(command + lesson);
            EXPECT_EQ(r.exitCode, 2) << command;
            EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err.substr(0, 300);
            EXPECT_NE(r.err.find(lesson + ":5: step 1 claim"), std::string::npos)
                << r.err.substr(0, 300);
            EXPECT_NE(r.err.find("nested deeper than 256 levels"), std::string::npos);
        }
        EXPECT_FALSE(fs::exists(path("frames")));
    }
}

TEST_F(InputFiles, TooLargeFilesAreRefusedBeforeParsing) {
    std::string big = path("big.toml");
    {
        std::ofstream f(big);
        f << "# " << std::string(MAX_INPUT_FILE_BYTES, 'x') << "\n";
    }
    try {
        parseLessonFile(big);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  big + ": is 1048579 bytes; the limit for an input file is 1048576");
    }
    // A link to a lesson is a lesson.
    fs::create_symlink(PCFSCOPE_SOURCE_DIR "/lessons/01-hard-shadows.toml", path("link.toml"));
    EXPECT_EQ(parseLessonFile(path("link.toml")).steps.size(),
              parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/01-hard-shadows.toml").steps.size());
}

TEST_F(InputFiles, ChartRowsOverTheLimitAreRefusedAtLoad) {
    std::ifstream in(PCFSCOPE_SOURCE_DIR "/lessons/figures/bench.csv");
    std::string header, row;
    std::getline(in, header);
    std::getline(in, row);
    auto writeChart = [&](size_t rows) {
        std::ofstream f(path("bench.csv"));
        f << header << "\n";
        for (size_t k = 0; k < rows; ++k) f << row << "\n";
    };
    std::ofstream(path("chart.toml"))
        << "title = \"c\"\nscene = \"box-on-plane\"\n[[step]]\ntitle = \"t\"\ntext = \"x\"\n"
           "chart = \"bench.csv\"\n";
    writeChart(MAX_CHART_ROWS);
    EXPECT_NO_THROW(loadLessonChecked(path("chart.toml")));
    writeChart(MAX_CHART_ROWS + 1);
    try {
        loadLessonChecked(path("chart.toml"));
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("2001 rows; a chart shows at most 2000"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace pcf
