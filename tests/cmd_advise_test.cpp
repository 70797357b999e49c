// `pcfscope advise`, run as a user runs it: a small search writes its four files and prints the
// [settings] table it chose; bad input and a budget nothing meets are refused in one line, exit
// 2, with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "image_read.h"
#include "json_lite.h"
#include "measure/advise_report.h"
#include "run_command.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

// Small and quick: a 160x90 frame, two cheap methods, two maps, few timing rounds.
const std::string BASE =
    "advise --scene box-on-plane --size 160x90 --kernels 3 --map-sizes 256,512 --repeats 2 "
    "--shimmer-frames 2 ";
const std::string SMALL = BASE + "--methods nearest,hw2x2,pcf-gather --biases none ";

class AdviseCommand : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("advise"); }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    // A refusal: exit 2, stderr's last line contains `words`, the lines before it (`progress`
    // of them) are the search's progress, and no output is left.
    void expectRefused(const std::string& args, const std::string& words, int progress = 0) {
        std::string out = path("refused");
        auto r = testutil::runPcfscope(args + " -o " + out);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
        ASSERT_FALSE(r.err.empty()) << args;
        size_t last = r.err.rfind('\n', r.err.size() - 2);
        std::string refusal = last == std::string::npos ? r.err : r.err.substr(last + 1);
        EXPECT_NE(refusal.find(words), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), progress + 1) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), ':'),
                  2 * progress + std::count(refusal.begin(), refusal.end(), ':'))
            << r.err;  // each progress line is "advise: N: SETTING"
        EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << args;
    }
    fs::path mDir;
};

TEST_F(AdviseCommand, WritesTheChoiceItsReasonsAndEveryMeasuredSetting) {
    std::string out = path("run");
    auto r = testutil::runPcfscope(SMALL + "--max-edge-rmse 0.1 --max-shimmer 0.5 -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* name : {"advise.csv", "advise.json", "settings.toml", "advise.png"}) {
        EXPECT_TRUE(fs::exists(fs::path(out) / name)) << name;
    }
    std::string toml = testutil::readAll(fs::path(out) / "settings.toml");
    // Printed as written, after the summary's comment lines.
    EXPECT_NE(r.out.find(toml), std::string::npos) << r.out;
    EXPECT_NE(toml.find("[settings]\nmethod = "), std::string::npos) << toml;
    jsonlite::Value json = jsonlite::parse(testutil::readAll(fs::path(out) / "advise.json"));
    const jsonlite::Value& choice = json["choice"];
    // The choice meets the budget as measured.
    EXPECT_LE(choice["metrics"]["edge_rmse"].number, 0.1);
    EXPECT_LE(choice["metrics"]["shimmer_p99"].number, 0.5);
    EXPECT_NE(toml.find("method = \"" + choice["method"].string + "\""), std::string::npos);
    EXPECT_NE(
        toml.find("map_size = " + std::to_string(static_cast<int>(choice["map_size"].number))),
        std::string::npos);
    // nearest, hw2x2 and pcf-gather 3 at two maps: 6 settings.
    EXPECT_EQ(json["grid_size"].number, 6);
    size_t measured = json["candidates"].size();
    EXPECT_EQ(json["measured"].number, static_cast<double>(measured));
    std::ifstream csv(fs::path(out) / "advise.csv");
    std::string line;
    ASSERT_TRUE(std::getline(csv, line));
    EXPECT_EQ(line, ADVISE_CSV_HEADER);
    size_t rows = 0;
    while (std::getline(csv, line)) ++rows;
    EXPECT_EQ(rows, measured);
    EXPECT_FALSE(json["binding"].string.empty());
    ImageSize png = readImageSize((fs::path(out) / "advise.png").string());
    EXPECT_EQ(png.width, 960);
    EXPECT_EQ(png.height, 540);
}

TEST_F(AdviseCommand, RefusesBadInputInOneLine) {
    expectRefused(SMALL, "advise needs a budget: --max-edge-rmse");
    expectRefused(BASE + "--max-edge-rmse 0.1 --methods nearest,blur", "unknown method 'blur'");
    expectRefused(SMALL + "--max-edge-rmse 2", "--max-edge-rmse");
    expectRefused(SMALL + "--max-edge-rmse 0.1 --max-acne -0.5", "--max-acne");
    expectRefused(SMALL + "--max-edge-rmse 0.1 --method tent", "--method does not apply");
    expectRefused(BASE + "--max-edge-rmse 0.1 --biases constant", "needs an amount");
    expectRefused(BASE + "--max-edge-rmse 0.1 --biases constant:x", "is not a number");
    expectRefused(BASE + "--max-edge-rmse 0.1 --biases constant:2", "--biases constant:2: ");
    expectRefused(SMALL + "--max-edge-rmse 0.1 --kernels 9", "--kernels");
    expectRefused("advise --max-edge-rmse 0.1", "needs --scene");
}

TEST_F(AdviseCommand, ABudgetNothingMeetsNamesTheClosestSetting) {
    // Every setting measured (3 filters at 2 maps): none met it.
    expectRefused(SMALL + "--max-edge-rmse 0.001",
                  "none of the 6 settings measured met the budget; the closest, ", 6);
}

}  // namespace
}  // namespace pcf
