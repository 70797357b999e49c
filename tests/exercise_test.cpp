// Exercises (app/exercise.h, `pcfscope exercise`, the viewer's N): the items are points of the
// lesson's shadow edges; the answer key's trace of each item is what `pcfscope trace` gives for
// the item's lookup on the item's map; the same seed writes the same files byte for byte, another
// seed other items; the worksheet holds no answer; the viewer scores a typed answer.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "json_lite.h"
#include "run_command.h"
#include "virtual_display.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;
using testutil::readAll;
using testutil::runPcfscope;

// Every file under `dir`, by its path relative to it, with its bytes.
std::map<std::string, std::string> filesUnder(const fs::path& dir) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = readAll(e.path());
    }
    return out;
}

class ExerciseTest : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("exercise"); }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }
    fs::path mDir;
};

TEST_F(ExerciseTest, TheSameSeedWritesTheSameFilesAndAnotherOtherItems) {
    for (const char* name : {"a", "b"}) {
        auto r = runPcfscope("exercise 5 --count 3 --seed 7 --size 1024x768 -o " +
                             (mDir / name).string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    std::map<std::string, std::string> a = filesUnder(mDir / "a"), b = filesUnder(mDir / "b");
    ASSERT_EQ(a.size(), b.size());
    for (const auto& [name, bytes] : a) {
        ASSERT_TRUE(b.count(name)) << name;
        EXPECT_TRUE(bytes == b[name]) << name << " differs between two runs with seed 7";
    }
    for (const char* name :
         {"worksheet/item01.png", "worksheet/item03.png", "answers/item02.png",
          "answers/item01-map.exr", "answers/answers.json", "worksheet.pdf", "answers.pdf"}) {
        EXPECT_TRUE(a.count(name)) << name;
    }
    // The worksheet gives nothing away: frames only, no sidecar with the trace.
    for (const auto& [name, bytes] : a) {
        if (name.starts_with("worksheet/")) {
            EXPECT_TRUE(name.ends_with(".png")) << name;
        }
    }
    auto r =
        runPcfscope("exercise 5 --count 3 --seed 8 --size 1024x768 -o " + (mDir / "c").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    jsonlite::Value seven = jsonlite::parse(a["answers/answers.json"]);
    jsonlite::Value eight = jsonlite::parse(readAll(mDir / "c/answers/answers.json"));
    int different = 0;
    for (size_t k = 0; k < 3; ++k) {
        different += seven["items"][k]["point"][0].number != eight["items"][k]["point"][0].number;
    }
    EXPECT_GT(different, 0) << "seeds 7 and 8 drew the same points";
}

TEST_F(ExerciseTest, TheAnswerKeyIsTraceAtEachItemsLookup) {
    auto r = runPcfscope("exercise 4 --count 4 --seed 3 -o " + (mDir / "e").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    fs::path answers = mDir / "e" / "answers";
    jsonlite::Value key = jsonlite::parse(readAll(answers / "answers.json"));
    ASSERT_EQ(key["items"].size(), 4u);
    for (size_t k = 0; k < 4; ++k) {
        const jsonlite::Value& item = key["items"][k];
        SCOPED_TRACE(item["title"].string);
        const jsonlite::Value& want = item["trace"];
        // An item on the edge band: between 0.1 and 0.9.
        EXPECT_GT(want["visibility"].number, 0.1);
        EXPECT_LT(want["visibility"].number, 0.9);
        EXPECT_NE(item["question"].string.find("To within 1/16"), std::string::npos);
        // The command the key gives, run from the answers folder.
        std::string command = item["lookup"]["command"].string;
        ASSERT_TRUE(command.starts_with("pcfscope trace --map "));
        auto t = runPcfscope(command.substr(9), "cd " + answers.string() + " &&");
        ASSERT_EQ(t.exitCode, 0) << command << ": " << t.err;
        jsonlite::Value got = jsonlite::parse(t.out);
        EXPECT_EQ(got["method"].string, want["method"].string);
        EXPECT_NEAR(got["visibility"].number, want["visibility"].number, 1e-6);
        EXPECT_NEAR(got["ref"].number, want["ref"].number, 1e-6);
        ASSERT_EQ(got["taps"].size(), want["taps"].size());
        for (size_t i = 0; i < got["taps"].size(); ++i) {
            EXPECT_EQ(got["taps"][i]["texel"][0].number, want["taps"][i]["texel"][0].number);
            EXPECT_EQ(got["taps"][i]["lit"].number, want["taps"][i]["lit"].number);
            EXPECT_NEAR(got["taps"][i]["weight"].number, want["taps"][i]["weight"].number, 1e-6);
        }
    }
}

TEST_F(ExerciseTest, BadCountsAreRefusedInOneLine) {
    auto r = runPcfscope("exercise 5 --count 0 -o " + (mDir / "x").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--count must be 1..32"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(mDir / "x"));
}

TEST_F(ExerciseTest, TheViewersExerciseModeScoresATypedAnswer) {
    testutil::VirtualDisplay x;
    ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
    // N: the exercise; "0.5" typed; Enter judges it and reveals the answer; E writes the frame.
    auto r = runPcfscope(
        "view 5 --keys \"n 0 . 5 enter e\" --screenshot " + (mDir / "shot.png").string(),
        "cd " + mDir.string() + " && DISPLAY=" + x.display());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    jsonlite::Value frame = jsonlite::parse(
        readAll(mDir / "pcfscope-frames/05-gather-weights-exercise-step01-reveal.json"));
    EXPECT_EQ(frame["predict"]["phase"].string, "reveal");
    double answer = std::stod(frame["predict"]["answer"].string);
    bool right = std::abs(0.5 - answer) <= 1.0 / 16.0;
    EXPECT_NE(frame["title"].string.find(right ? "(1 of 1 right)" : "(0 of 1 right)"),
              std::string::npos)
        << frame["title"].string << ", answer " << answer;
    EXPECT_NE(frame["predict"]["answer_line"].string.find("You said 0.5"), std::string::npos);
}

}  // namespace
}  // namespace pcf
