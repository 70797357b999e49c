// `pcfscope lesson check FILE`: every claim of every shipped lesson holds (exit 0); a false claim
// is reported at its line (exit 1), also when it is false only after a key the step invites; a
// bad claim is a bad file (exit 2). The claims' own meaning is lesson_claims_test.cpp's.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "measure/bench_report.h"
#include "run_command.h"

namespace {

class LessonCheck : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("lesson-check"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    // A one-step lesson on the pole scene, its point the ground in the middle of the view.
    std::string write(const std::string& stepKeys) {
        std::string path = (mDir / "claims.toml").string();
        std::ofstream f(path);
        f << "title = \"Claims\"\n"                  // 1
             "scene = \"pole\"\n"                    // 2
             "[settings]\n"                          // 3
             "method = \"nearest\"\n"                // 4
             "map_size = 256\n"                      // 5
             "[[step]]\n"                            // 6
             "title = \"One read\"\n"                // 7
             "text = \"visibility {visibility}\"\n"  // 8
          << stepKeys;                               // 9..
        return path;
    }
    std::filesystem::path mDir;
};

TEST_F(LessonCheck, EveryShippedLessonHolds) {
    for (const auto& e : std::filesystem::directory_iterator(PCFSCOPE_SOURCE_DIR "/lessons")) {
        if (e.path().extension() != ".toml") continue;
        testutil::CommandResult r = testutil::runPcfscope("lesson check " + e.path().string());
        EXPECT_EQ(r.exitCode, 0) << e.path() << "\n" << r.out << r.err;
        EXPECT_NE(r.out.find("claims hold over"), std::string::npos) << r.out;
    }
}

// The worked example of docs/lesson-authoring.md (its first ```toml block) is a lesson whose
// claims hold: an author who copies it starts from something that passes.
TEST_F(LessonCheck, TheAuthoringGuidesWorkedExampleHolds) {
    std::ifstream doc(PCFSCOPE_SOURCE_DIR "/docs/lesson-authoring.md");
    ASSERT_TRUE(doc);
    std::string example;
    bool inside = false;
    for (std::string line; std::getline(doc, line);) {
        if (!inside && line == "```toml") {
            inside = true;
        } else if (inside && line == "```") {
            break;
        } else if (inside) {
            example += line + "\n";
        }
    }
    ASSERT_NE(example.find("claims"), std::string::npos) << "the example states claims";
    std::string path = (mDir / "example.toml").string();
    std::ofstream(path) << example;
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
}

TEST_F(LessonCheck, AFalseClaimFailsAtItsLine) {
    std::string path = write(
        "claims = [\"{taps} = 1\",\n"       // 9: holds
        "  \"{taps} = 2\",\n"               // 10: false
        "  \"{visibility} ~ 7 +- 0.5\"]\n"  // 11: false
    );
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_EQ(testutil::lineCount(r.out), 2) << r.out;
    EXPECT_NE(r.out.find(path + ":10: step 1 claim \"{taps} = 2\" fails: not 1 = 2"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(path + ":11: step 1 claim"), std::string::npos) << r.out;
}

TEST_F(LessonCheck, AClaimAKeyInvitedByTheStepBreaksFails) {
    // nearest reads 1 texel; the map doubled by "+" still 1, M moves to box2x2: 4 reads.
    std::string path = write("claims = [\"{taps} = 1\"]\nkeys = [\"+\", \"M\"]\n");
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_EQ(testutil::lineCount(r.out), 1) << r.out;
    EXPECT_NE(r.out.find(":9: step 1 claim \"{taps} = 1\" fails after key M"), std::string::npos)
        << r.out;
}

TEST_F(LessonCheck, ABadClaimIsABadFile) {
    std::string path = write("claims = [\"{taps} is 1\"]\n");
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(path + ":9: step 1 claim \"{taps} is 1\""), std::string::npos) << r.err;
    EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
    path = write("keys = [\"X\"]\n");
    r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(":9: step 1 keys: unknown key 'X'"), std::string::npos) << r.err;
}

// Every problem of a file, not only the first: two bad steps, both lines, one line each (exit 2).
TEST_F(LessonCheck, EveryProblemOfAFileIsReportedAtItsLine) {
    std::string path = write(
        "claims = [\"{taps} is 1\"]\n"  // 9: no comparison
        "[[step]]\n"                    // 10
        "title = \"Two\"\n"             // 11
        "text = \"{frac.z}\"\n"         // 12: unknown placeholder
    );
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_EQ(testutil::lineCount(r.err), 2) << r.err;
    EXPECT_NE(r.err.find(path + ":9: step 1 claim \"{taps} is 1\""), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(path + ":12: step 2 text: unknown placeholder {frac.z} (did you mean "
                                "{frac.x}?) (the names: docs/lesson-authoring.md#placeholders"),
              std::string::npos)
        << r.err;
    // The anchor it names is a heading of the authoring guide.
    std::ifstream guide(PCFSCOPE_SOURCE_DIR "/docs/lesson-authoring.md");
    std::string line;
    bool heading = false;
    while (std::getline(guide, line)) heading |= line == "## Placeholders";
    EXPECT_TRUE(heading);
}

// A number or a state typed where a placeholder or a claim belongs is refused at its line (after
// a line-ending backslash too), naming what to write: on the authoring guide's worked example's
// point, bilinear2x2 gives 1 - fx, a penumbra.
TEST_F(LessonCheck, TypedNumbersAndStatesOfTheStepAreRefusedAtTheirLine) {
    std::string path = (mDir / "typed.toml").string();
    std::ofstream(path) << "title = \"Typed\"\n"                                  // 1
                           "scene = \"box-on-plane\"\n"                           // 2
                           "[settings]\n"                                         // 3
                           "method = \"bilinear2x2\"\n"                           // 4
                           "map_size = 128\n"                                     // 5
                           "constant_bias = 0.02\n"                               // 6
                           "point = [0.9794, 0, -0.4338]\n"                       // 7
                           "[[step]]\n"                                           // 8
                           "title = \"One\"\n"                                    // 9
                           "claims = [\"penumbra\"]\n"                            // 10
                           "text = \"\"\"\n"                                      // 11
                           "The lookup lerps two bits, {visibility}. \\\n"        // 12
                           "Here the point is fully lit, visibility 1.\"\"\"\n";  // 13
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_EQ(testutil::lineCount(r.out), 2) << r.out;
    EXPECT_NE(r.out.find(path + ":13: step 1 text: \"fully lit\" is false here"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("list the claim \"penumbra\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(path + ":13: step 1 text: \"visibility 1\" is false here"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("(write {visibility})"), std::string::npos) << r.out;
}

// `flickers` reads the frames the step's sweep composes: on a step that does not move it is a bad
// file (exit 2, its line); where the line only creeps (pcf-gather: the sliding grid moves its
// weights 1/32 texel a frame) it fails at its line with the largest change (exit 1). Here nearest
// flickers (the middle of the view lies on the pole's stair-stepped edge), and lesson 13's last
// step does (EveryShippedLessonHolds).
TEST_F(LessonCheck, FlickersReadsTheStepsSweep) {
    std::string path = write("claims = [\"flickers\"]\n");
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(":9: step 1 claim \"flickers\": the step does not move"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
    const std::string sweep = "animate = { sweep = \"light\", frames = 8 }\n";
    path = write("claims = [\"flickers\"]\n" + sweep);
    r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    path = write("claims = [\"flickers\"]\nmethod = \"pcf-gather\"\n" + sweep);
    r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_EQ(testutil::lineCount(r.out), 1) << r.out;
    EXPECT_NE(r.out.find(":9: step 1 claim \"flickers\" fails: largest change between two frames "),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(" over 8 frames; flicker is a jump of 0.5 or more"), std::string::npos)
        << r.out;
}

// "the front is A, B" names the bench chart's Pareto front of the medians exactly, fastest first:
// every dot takes part, the noisy hw2x2 too (it beats nearest on both counts), and a dominated dot
// is left off.
TEST_F(LessonCheck, TheFrontIsTheChartsFrontExactly) {
    std::string csv = (mDir / "bench.csv").string();
    std::ofstream(csv) << pcf::BENCH_CSV_HEADER_V2 << "\n"
                       << "nearest,0,256,2,1,1,0,1,0.5,1,t,0.1,1,0.05,0\n"
                       << "pcf-gather,3,256,4,1,16,0,1,0.3,1,t,0.1,1,0.05,0\n"
                       << "pcf-naive,3,256,8,1,36,0,1,0.3,1,t,0.1,1,0.05,0\n"
                       << "hw2x2,0,256,1,1,1,0,1,0.4,1,t,0.5,1,0.05,1\n";
    std::string path = write(
        "claims = [\"chart: the front is hw2x2 256, gather3 256\",\n"  // 9
        "  \"chart: the front is nearest 256, gather3 256\"]\n"        // 10
        "chart = \"" +
        csv + "\"\n");
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_EQ(testutil::lineCount(r.out), 1) << r.out;
    EXPECT_NE(r.out.find(":10: step 1 claim \"chart: the front is nearest 256, gather3 256\" "
                         "fails: the front is hw2x2 256, gather3 256"),
              std::string::npos)
        << r.out;
}

// "A faster than B" holds only where the two dots' time bars are apart: where they overlap,
// another run of the bench could order them the other way, and the claim fails with both times
// and their spreads (issue 32).
TEST_F(LessonCheck, AnOrderAcrossOverlappingBarsIsNotAFact) {
    std::string csv = (mDir / "bench.csv").string();
    std::ofstream(csv) << pcf::BENCH_CSV_HEADER_V2 << "\n"
                       << "nearest,0,256,2,1,1,0,1,0.5,1,t,0.2,1,0.05,0\n"
                       << "pcf-gather,3,256,4,1,16,0,1,0.3,1,t,0.4,1,0.05,0\n"
                       << "pcf-naive,3,256,4.5,1,36,0,1,0.3,1,t,1,1,0.05,0\n";
    std::string path = write(
        "claims = [\"chart: nearest 256 faster than gather3 256\",\n"  // 9
        "  \"chart: gather3 256 faster than naive3 256\"]\n"           // 10
        "chart = \"" +
        csv + "\"\n");
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_EQ(testutil::lineCount(r.out), 1) << r.out;
    EXPECT_NE(r.out.find(":10: step 1 claim \"chart: gather3 256 faster than naive3 256\" fails: "
                         "gather3 256's and naive3 256's time bars overlap (4.00 +- 0.20 ms and "
                         "4.50 +- 0.50 ms): no order to claim"),
              std::string::npos)
        << r.out;
}

// A chart fact reads the CSV the step's chart draws: one the chart's table does not know, or on a
// step without a chart, is a bad file (exit 2, its line); a known one that the rows contradict
// fails at its line with the numbers (exit 1).
TEST_F(LessonCheck, ChartFactsReadTheChartsCsv) {
    std::string figures = PCFSCOPE_SOURCE_DIR "/lessons/figures/";
    std::string path = write("claims = [\"chart: measured on llvmpipe\"]\n");
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(":9: step 1 claim \"chart: measured on llvmpipe\": the step shows no "
                         "chart"),
              std::string::npos)
        << r.err;
    path = write("claims = [\"chart: acne looks bad\"]\nchart = \"" + figures +
                 "stability.csv#tradeoff\"\n");
    r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(":9: step 1 claim \"chart: acne looks bad\": unknown chart fact"),
              std::string::npos)
        << r.err;
    path = write(
        "claims = [\"chart: measured on NVIDIA\",\n"                       // 9
        "  \"chart: nearest: a good bias lies between acne and leak\",\n"  // 10
        "  \"chart: measured on llvmpipe\"]\n"                             // 11
        "chart = \"" +
        figures + "stability.csv#tradeoff\"\n");
    r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_NE(r.out.find(":9: step 1 claim \"chart: measured on NVIDIA\" fails: measured on "
                         "llvmpipe"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find(":11:"), std::string::npos) << r.out;
}

// A step names the panels of a stability chart it shows after a colon ("#bleed:lbr"): a name no
// panel has is a bad file at the chart's line (exit 2), listing the panels there are; a chart
// fact about a panel the step does not show fails at its claim's line (exit 1).
TEST_F(LessonCheck, ANamedChartPanelMustExistAndHoldTheFacts) {
    std::string csv = PCFSCOPE_SOURCE_DIR "/lessons/figures/bleed/stability.csv";
    std::string path = write("chart = \"" + csv + "#bleed:lbrx\"\n");
    testutil::CommandResult r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(":9: step 1 chart: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no panel 'lbrx' in the chart '#bleed' (its panels: lbr, "),
              std::string::npos)
        << r.err;
    for (const char* name : {"moment_format", "evsm_exponents", "moment_bias"}) {
        EXPECT_NE(r.err.find(name), std::string::npos) << name << ": " << r.err;
    }
    path = write(
        "claims = [\"chart: vsm 5x5: leak falls under 0.001 from lbr 0.3\",\n"   // 9
        "  \"chart: msm 5x5: leak falls under 0.001 from moment_bias 3e-5\"]\n"  // 10
        "chart = \"" +
        csv + "#bleed:lbr\"\n");
    r = testutil::runPcfscope("lesson check " + path);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_NE(r.out.find(":10: step 1 claim \"chart: msm 5x5: leak falls under 0.001 from "
                         "moment_bias 3e-5\" fails: the chart shows no 'moment_bias' panel (it "
                         "names lbr)"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find(":9:"), std::string::npos) << r.out;
}

}  // namespace
