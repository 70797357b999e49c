// The command line's input rules that hold for every command: errors stay on one line whatever
// the values hold (a newline is written \n), an empty value is refused, a FIFO is refused
// without blocking, and bench refuses what cannot work before it prints a progress line.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "exr_header.h"
#include "kernel/shadow_map.h"
#include "render/image_io.h"
#include "render/sanitizer_build.h"
#include "run_command.h"

namespace pcf {
namespace {

using testutil::runPcfscope;

class CliInputChecks : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("checks"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }

    // Runs in mDir (with a time limit: a blocked command fails instead of hanging the suite);
    // expects exit 2, one line on stderr holding `expect`, nothing on stdout, nothing written.
    void expectRefused(const std::string& args, const std::string& expect) {
        auto r = runPcfscope(args, "cd " + mDir.string() + " && timeout 60");
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << args << "\n" << r.err;
        EXPECT_NE(r.err.find(expect), std::string::npos) << args << "\n" << r.err;
        EXPECT_EQ(r.out, "") << args;
        std::vector<std::string> left;
        for (const auto& e : std::filesystem::directory_iterator(mDir)) {
            left.push_back(e.path().filename());
        }
        std::sort(left.begin(), left.end());
        EXPECT_EQ(left, mKeep) << args;
    }

    std::filesystem::path mDir;
    std::vector<std::string> mKeep;  // files the test made itself
};

TEST_F(CliInputChecks, NewlinesInValuesAreEscapedNotPrinted) {
    expectRefused("trace --example --method \"$(printf 'bogus\\nx')\"",
                  "unknown method 'bogus\\nx'");
    // OpenImageIO's message quotes the path: it is escaped too, and not cut at the newline.
    auto r = runPcfscope("trace --map \"$(printf 'no\\nsuch.exr')\" --uv 0.5,0.5 --z 0.5");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("pcfscope: no\\nsuch.exr: cannot read image (", 0), 0u) << r.err;
    EXPECT_EQ(r.err.substr(r.err.size() - 2), ")\n") << r.err;
    // A control character of another kind is written as \xNN.
    expectRefused("trace --example --method \"$(printf 'a\\033b')\"", "'a\\x1bb'");
}

TEST_F(CliInputChecks, EmptyValuesAreRefusedByEveryCommand) {
    const std::vector<std::string> cases = {
        "bench --methods ''",
        "bench --kernels ''",
        "bench --size ''",
        "render --scene pole --polygon-offset '' -o f.png",
        "render --scene pole --size '' -o f.png",
        "truth --scene pole --size '' -o t.exr",
        "export 1 -o ''",
        "export 1 --size ''",
        "export ''",
        "trace --example --method ''",
    };
    for (const std::string& args : cases) {
        // The option given empty: the last "--x ''" of the line ("-o" is "--out").
        size_t at = args.rfind(" ''");
        std::string option =
            args.substr(args.rfind(' ', at - 1) + 1, at - args.rfind(' ', at - 1) - 1);
        if (option == "-o") option = "--out";
        if (option == "export") option = "lesson";
        expectRefused(args, option + " needs a value; an empty one is refused");
    }
}

TEST_F(CliInputChecks, AFifoAsMapOrLessonIsRefusedNotWaitedOn) {
    ASSERT_EQ(mkfifo(path("map.exr").c_str(), 0644), 0);
    ASSERT_EQ(mkfifo(path("lesson.toml").c_str(), 0644), 0);
    ASSERT_EQ(mkfifo(path("scene.toml").c_str(), 0644), 0);
    mKeep = {"lesson.toml", "map.exr", "scene.toml"};  // sorted
    expectRefused("trace --map map.exr --uv 0.5,0.5 --z 0.5",
                  "map.exr: cannot read image (not a regular file)");
    expectRefused("export lesson.toml -o frames", "lesson.toml: not a regular file");
    expectRefused("render --scene-file scene.toml -o f.png", "scene.toml: not a regular file");
}

TEST_F(CliInputChecks, BenchRefusesOneSamplePerPixelBeforeAnyProgress) {
    // One sample per pixel makes a truth of only 0 and 1: no edge band to measure error over.
    expectRefused("bench --quick --spp 1 -o out", "--spp 1 is out of range (2..");
}

// Found by the depth_image fuzz target: a PNG cut inside a text chunk made libpng print its own
// line before ours. The refusal is still one line.
TEST_F(CliInputChecks, ABrokenPngMapIsOneLineToo) {
    // The corpus file's first byte is the fuzz target's choice of reader; the PNG follows.
    std::string png = testutil::readAll(PCFSCOPE_SOURCE_DIR
                                        "/tests/fuzz/corpus/depth_image/png-truncated-text.png");
    std::ofstream(mDir / "cut.png", std::ios::binary) << png.substr(1);
    mKeep = {"cut.png"};
#if PCFSCOPE_ASAN
    // Sanitizer builds let libpng's line through (image_io.cpp QuietStderr): ours is the last.
    auto r = runPcfscope("trace --map cut.png --uv 0.5,0.5 --z 0.5", "cd " + mDir.string() + " &&");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("\npcfscope: cut.png: cannot read image (Read error"), std::string::npos)
        << r.err;
#else
    expectRefused("trace --map cut.png --uv 0.5,0.5 --z 0.5",
                  "cut.png: cannot read image (Read error: hit end of file");
#endif
}

TEST_F(CliInputChecks, HugeDepthImageHeadersAreRefusedBeforeAllocating) {
    // A small EXR whose header claims 20000 x 20000 texels (1.6 GB as floats).
    writeDepthImage(path("huge.exr"), ShadowMap(16, 16, 0.5f));
    ASSERT_TRUE(testutil::makeExrClaimSize(path("huge.exr"), 20000));
    mKeep = {"huge.exr"};
    expectRefused("trace --map huge.exr --uv 0.5,0.5 --z 0.5",
                  "huge.exr: is 20000 x 20000 texels; a depth map is at most 16384 on a side");
}

// Every size option states its range in --help as its error does: "A up to B" (issue 24.13 found
// "16..8192 a side" in one command and "1x1 up to 8192x8192" in the others).
TEST_F(CliInputChecks, SizeRangesAreStatedOneWayInTheHelpAndTheError) {
    struct Case {
        std::string command, option, range;
    };
    const std::vector<Case> cases = {
        {"render --scene box-on-plane", "--size", "1x1 up to 8192x8192"},
        {"truth --scene box-on-plane", "--size", "1x1 up to 8192x8192"},
        {"bench --quick", "--size", "1x1 up to 8192x8192"},
        {"bench --quick", "--chart-size", "64x64 up to 8192x8192"},
        {"stability --quick", "--size", "16x16 up to 8192x8192"},
        {"stability --quick", "--chart-size", "64x64 up to 8192x8192"},
        {"export 3", "--size", "320x180 up to 8192x8192"},
        {"animate 13", "--size", "320x180 up to 8192x8192"},
        {"view 3", "--size", "320x180 up to 8192x8192"},
    };
    std::map<std::string, std::string> helps;  // per command, run once
    for (const Case& c : cases) {
        std::string sub = c.command.substr(0, c.command.find(' '));
        if (helps.count(sub) == 0) {
            auto help = runPcfscope(sub + " --help");
            ASSERT_EQ(help.exitCode, 0) << sub;
            helps[sub] = help.out;
        }
        const std::string& help = helps[sub];
        size_t at = help.find("  " + c.option + " ");
        ASSERT_NE(at, std::string::npos) << sub << " " << c.option;
        std::string line = help.substr(at, help.find('\n', at) - at);
        EXPECT_NE(line.find("WxH, " + c.range), std::string::npos) << sub << ": " << line;
        // One below the smallest side: refused, with the range the help gave.
        glm::ivec2 lo{0};
        ASSERT_EQ(std::sscanf(c.range.c_str(), "%dx%d", &lo.x, &lo.y), 2);
        std::string bad = std::to_string(lo.x - 1) + "x" + std::to_string(lo.y);
        std::string out = sub == "view" ? "" : " -o out";
        expectRefused(c.command + " " + c.option + " " + bad + out,
                      c.option + " " + bad + " is out of range (" + c.range + ")");
    }
}

// --light-size means one thing in every command: a directional light's angular diameter in
// degrees, in the parameter table's [0, 10], 0 the scene light's; a spot light's size is its
// radius, --light-radius. Values outside the range (nan and inf included) are refused by every
// command with the table's words and the value as typed; each size given for the other kind of
// light is refused, not ignored (render used to write it into render.json and ignore it).
TEST_F(CliInputChecks, LightSizeIsOneThingInEveryCommand) {
    const std::string range = "--light-size must be in [0, 10] degrees, got ";
    for (const std::string& command :
         {std::string("render --scene post-in-sun --method pcss --size 64x36 -o out.png"),
          std::string("truth --scene post-in-sun --size 16x9 -o out.exr"),
          std::string("bench --quick --scene post-in-sun --methods pcss -o out")}) {
        for (std::string bad : {"nan", "-1", "-inf", "inf", "11", "10.000000001"}) {
            expectRefused(command + " --light-size=" + bad, range + bad);
        }
        expectRefused(command + " --light-size 0x2", "--light-size must be a decimal number");
        expectRefused(command + " --light-radius 0.5",
                      "--light-radius (a spot light's radius) does not apply to a directional "
                      "light, whose size is its angular diameter");
    }
    for (const std::string& command :
         {std::string("render --scene post-under-spot --method pcss --size 64x36 -o out.png"),
          std::string("truth --scene post-under-spot --size 16x9 -o out.exr")}) {
        expectRefused(command + " --light-size 2",
                      "--light-size (a directional light's angular diameter) does not apply to a "
                      "spot light, whose size is its radius");
        expectRefused(command + " --light-radius 101",
                      "--light-radius must be in [0, 100] world units, got 101");
    }
    // stability's pcss sweeps choose their own lights: the option is not offered.
    expectRefused("stability --quick --light-size 2 -o out", "--light-size");
}

// A value below a range is printed as typed, never rounded into it: --bound 1e-300 is not "0".
TEST_F(CliInputChecks, OutOfRangeValuesArePrintedAsGiven) {
    expectRefused("truth --scene box-on-plane --bound 1e-300 -o t.exr",
                  "--bound 1e-300 is out of range [1e-06, 1]");
    expectRefused("render --scene box-on-plane --kernel 9 -o r.png",
                  "--kernel must be 1..8, got 9");
    expectRefused("render --scene box-on-plane --slope-max 1.0000001 -o r.png",
                  "--slope-max must be in [0, 1] light depth units, got 1.0000001");
    expectRefused("trace --example --z 1.0000001", "--z 1.0000001 is out of range [0, 1]");
}

// A size one step's compare cannot take names that step (the whole export was refused with only
// "a split view of 3 parts needs...").
TEST_F(CliInputChecks, ASizeRefusedForOneStepNamesIt) {
    expectRefused("export 8 --size 320x180 -o out",
                  "--size 320x180: step 3's compare (bias=none,constant,slope): a split view of 3 "
                  "parts needs a frame at least 484 pixels wide, got 320");
}

// Options that would change nothing are refused, not ignored: animate's --compare-kernel with a
// comparison that has no kernel, --snap with a sweep other than light's creeping grid, a chart
// step (no sweep moves a chart), and view's --bench-frames 0 (it opened the window).
TEST_F(CliInputChecks, OptionsThatWouldChangeNothingAreRefused) {
    const std::string animate = "animate 13 --step 3 --frames 2 --size 320x180 -o v.gif ";
    expectRefused(animate + "--compare nearest --compare-kernel 5",
                  "--compare-kernel is for a comparison method with a kernel; nearest has none");
    expectRefused(animate + "--compare none --compare-kernel 5",
                  "--compare-kernel is for a comparison method with a kernel; --compare none "
                  "draws no second curve");
    expectRefused(animate + "--sweep sun --snap",
                  "--snap is for --sweep light (it snaps the creeping texel grid), not sun");
    expectRefused("animate 11 --step 1 --frames 2 --size 320x180 -o v.gif",
                  "lesson step 1 shows a chart, which no sweep moves");
    expectRefused("view 3 --bench-frames 0", "--bench-frames 0 is out of range (1..10000)");
}

// What --replot reads back is what pcfscope writes: decimal numbers, never negative where they
// are measures or counts (hex and negative times were drawn), and rows its charts can draw
// (rows of metrics no chart reads made five empty charts and exit 0).
TEST_F(CliInputChecks, ReplotReadsOnlyWhatPcfscopeWrites) {
    std::string bench = testutil::readAll(PCFSCOPE_SOURCE_DIR "/lessons/figures/bench.csv");
    size_t row = bench.find('\n') + 1;
    size_t ms = bench.find(',', bench.find(',', bench.find(',', row) + 1) + 1) + 1;
    size_t msEnd = bench.find(',', ms);
    for (std::string bad : {"0x1p4", "-21.0463", " 21"}) {
        std::string csv = bench;
        csv.replace(ms, msEnd - ms, bad);
        std::ofstream(path("bench.csv")) << csv;
        mKeep = {"bench.csv"};
        expectRefused("bench --replot bench.csv -o out", "bench.csv:2: field 4 '" + bad + "'");
    }
    std::string stability = testutil::readAll(PCFSCOPE_SOURCE_DIR "/lessons/figures/stability.csv");
    std::string renamed;
    for (size_t at = 0, end; at < stability.size(); at = end + 1) {
        end = stability.find('\n', at);
        std::string line = stability.substr(at, end - at);
        // Every acne row's metric renamed to one no chart reads.
        if (line.rfind("acne,", 0) == 0) {
            size_t metric = line.rfind(',', line.rfind(',') - 1);
            line = line.substr(0, metric) + ",shadow_rate_v2" + line.substr(line.rfind(','));
        }
        renamed += line + "\n";
        if (end == std::string::npos) break;
    }
    std::ofstream(path("stability.csv")) << renamed;
    mKeep = {"bench.csv", "stability.csv"};
    expectRefused("stability --replot stability.csv -o out",
                  "stability.csv: the acne rows hold no metric its chart draws "
                  "(stability_acne.png would be empty)");
}

}  // namespace
}  // namespace pcf
