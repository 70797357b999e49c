// An advise folder shown as a lesson step's chart (charts/step_chart.h, "DIR/advise.csv"): a
// folder that lacks advise.json is refused in one line at the chart's line, from `lesson check`
// and `export`; a claim false for the committed figures fails at its line. These run pcfscope,
// which opens a GL context for `export`, so they are not in CI's sanitized list.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "advise_written.h"
#include "run_command.h"

namespace pcf {
namespace {

using advise_test::Written;
using advise_test::written;

class AdviseStepChart : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("advise-step"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    // A one-step lesson charting `folder`/advise.csv; the chart line is line 6.
    std::string lesson(const std::filesystem::path& folder, const std::string& claims = "") {
        std::string path = (mDir / "advise.toml").string();
        std::ofstream(path) << "title = \"Advice\"\n"                 // 1
                               "scene = \"box-on-plane\"\n"           // 2
                               "[[step]]\n"                           // 3
                               "title = \"The chart\"\n"              // 4
                               "text = \"The settings measured.\"\n"  // 5
                               "chart = \""
                            << (folder / "advise.csv").string() << "\"\n"  // 6
                            << claims;                                     // 7..
        return path;
    }
    std::filesystem::path mDir;
};

// A folder without its advise.json, or one whose CSV is not advise's, is a bad lesson: one line
// at the chart's line, exit 2, from `lesson check` and from `export`.
TEST_F(AdviseStepChart, ABadFolderIsRefusedAtTheChartsLine) {
    Written w = written();
    std::filesystem::path folder = mDir / "run";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "advise.csv") << w.csv;
    std::string path = lesson(folder);
    std::string out = (mDir / "out-advise").string();
    for (std::string command :
         {std::string("lesson check "), "export -o " + out + " --size 640x360 "}) {
        testutil::CommandResult r = testutil::runPcfscope(command + path);
        EXPECT_EQ(r.exitCode, 2) << command << r.out << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(path + ":6:"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("advise.json"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(mDir / "out-advise"));
    std::ofstream(folder / "advise.json") << w.json;
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
}

// A claim false for the committed figures fails at its line with what the chart shows (exit 1);
// one this chart's facts do not know is a bad file (exit 2).
TEST_F(AdviseStepChart, AFalseClaimAboutTheCommittedFiguresFailsAtItsLine) {
    std::filesystem::path figures = PCFSCOPE_SOURCE_DIR "/lessons/figures/box_advise";
    std::string path =
        lesson(figures,
               "claims = [\"chart: the choice is nearest map 256 bias none\",\n"  // 7
               "  \"chart: nearest map 256 bias none meets the budget\",\n"       // 8
               "  \"chart: the budget is edge 0.2\"]\n");                         // 9
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_EQ(testutil::lineCount(r.out), 3) << r.out;
    EXPECT_NE(r.out.find(path + ":7: step 1 claim \"chart: the choice is nearest map 256 bias "
                                "none\" fails: the choice is "),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(path + ":8: step 1 claim \"chart: nearest map 256 bias none meets the "
                                "budget\" fails: nearest map 256 bias none breaks edge"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(path + ":9: step 1 claim \"chart: the budget is edge 0.2\" fails: the "
                                "budget is edge 0.1, "),
              std::string::npos)
        << r.out;
    path = lesson(figures, "claims = [\"chart: the front is nearest 256\"]\n");
    r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(path + ":7: step 1 claim \"chart: the front is nearest 256\": unknown "
                                "chart fact"),
              std::string::npos)
        << r.err;
}

}  // namespace
}  // namespace pcf
