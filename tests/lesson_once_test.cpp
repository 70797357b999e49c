// lesson_once_test.cpp: a command reads, parses and checks its lesson once and hands the Lesson
// on (lesson/lesson.h: lessonParseCount). `export` and `view` parsed it again from its path to
// render it, every part of a split view once more, and `lesson check` twice.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "lesson/lesson.h"
#include "run_command.h"
#include "virtual_display.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

// Lesson 8's step 3 has a `compare` of three parts, which export writes as a split view too.
const std::string LESSON = std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/08-acne-and-bias.toml";

// The viewer's display, started before main: a command run in this process blocks SIGTERM in every
// thread (app/output_files.h, installInterruptCleanup), and an Xvfb forked after that would inherit
// the mask and never stop.
const testutil::VirtualDisplay DISPLAY_FOR_VIEWER;

// pcfscope's command line run in this process; its exit code.
int runHere(std::vector<std::string> args) {
    args.insert(args.begin(), "pcfscope");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    return runCommandLine(static_cast<int>(args.size()), argv.data());
}

TEST(LessonOnce, ExportParsesItsLessonOnceSplitViewIncluded) {
    fs::path dir = testutil::makeTempDir("lesson-once-export");
    long before = lessonParseCount();
    ASSERT_EQ(runHere({"export", LESSON, "-o", (dir / "out").string(), "--size", "640x360",
                       "--steps", "3"}),
              0);
    EXPECT_EQ(lessonParseCount() - before, 1);
    EXPECT_TRUE(fs::exists(dir / "out/08-acne-and-bias-step03.png"));
    EXPECT_TRUE(fs::exists(dir / "out/08-acne-and-bias-step03-compare.png"));
    fs::remove_all(dir);
}

// `lesson check` reports every problem of the file, then checks the claims of the lesson it read.
TEST(LessonOnce, LessonCheckParsesItsLessonOnce) {
    long before = lessonParseCount();
    ASSERT_EQ(runHere({"lesson", "check",
                       std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/01-hard-shadows.toml"}),
              0);
    EXPECT_EQ(lessonParseCount() - before, 1);
}

TEST(LessonOnce, TheViewerParsesItsLessonOnce) {
    const testutil::VirtualDisplay& x = DISPLAY_FOR_VIEWER;
    ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
    ASSERT_EQ(setenv("DISPLAY", x.display().c_str(), 1), 0);
    fs::path dir = testutil::makeTempDir("lesson-once-view");
    long before = lessonParseCount();
    ASSERT_EQ(runHere({"view", LESSON, "--keys", "right right c", "--screenshot",
                       (dir / "shot.png").string()}),
              0);
    EXPECT_EQ(lessonParseCount() - before, 1);
    EXPECT_TRUE(fs::exists(dir / "shot.png"));
    fs::remove_all(dir);
}

// N opens an exercise drawn from the lesson and N again goes back to the lesson's step: the lesson
// it goes back to is the one the viewer read (it was read again from its path).
TEST(LessonOnce, LeavingAnExerciseDoesNotReadTheLessonAgain) {
    const testutil::VirtualDisplay& x = DISPLAY_FOR_VIEWER;
    ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
    ASSERT_EQ(setenv("DISPLAY", x.display().c_str(), 1), 0);
    fs::path dir = testutil::makeTempDir("lesson-once-exercise");
    long before = lessonParseCount();
    ASSERT_EQ(runHere({"view", std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/05-gather-weights.toml",
                       "--keys", "right n n right", "--screenshot", (dir / "shot.png").string()}),
              0);
    EXPECT_EQ(lessonParseCount() - before, 1);
    EXPECT_TRUE(fs::exists(dir / "shot.png"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace pcf
