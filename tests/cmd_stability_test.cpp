// `pcfscope stability`, run as a user runs it: --quick writes the CSV with its documented
// columns, the table (also on stdout) and the charts; bad sweep parameters exit 2 with nothing
// written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "image_read.h"
#include "measure/stability_report.h"
#include "run_command.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

class StabilityCommand : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("stability"); }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    fs::path mDir;
};

TEST_F(StabilityCommand, QuickWritesEveryFile) {
    std::string out = path("quick");
    auto r = testutil::runPcfscope("stability --quick --chart-size 640x360 -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("stability: ["), std::string::npos) << r.err;  // progress

    std::ifstream csv(out + "/stability.csv");
    std::string line;
    ASSERT_TRUE(std::getline(csv, line));
    EXPECT_EQ(line, "sweep,method,kernel,bias,x_name,x,metric,y");
    std::set<std::string> sweeps;
    int rows = 0;
    while (std::getline(csv, line)) {
        ++rows;
        std::vector<std::string> f;
        std::stringstream s(line);
        for (std::string field; std::getline(s, field, ',');) f.push_back(field);
        ASSERT_EQ(f.size(), 8u) << line;
        sweeps.insert(f[0]);
        std::stod(f[5]);
        EXPECT_TRUE(std::isfinite(std::stod(f[7]))) << line;
    }
    EXPECT_GT(rows, 100);
    // The twelve sweeps, and the setup the charts state (stability_report.h: stabilitySetupRows).
    EXPECT_EQ(sweeps, (std::set<std::string>{"setup", "acne", "leak", "tradeoff", "shimmer",
                                             "precision", "aliasing", "pcss-thin", "pcss-overlap",
                                             "pcss-noise", "pcss-bias", "bleed", "cascades"}));
    std::string md = testutil::readAll(out + "/stability.md");
    EXPECT_NE(md.find("| pcf-gather N=3 | constant |"), std::string::npos) << md;
    EXPECT_EQ(r.out, md);
    for (const char* chart :
         {"stability_acne.png", "stability_leak.png", "stability_tradeoff.png",
          "stability_shimmer.png", "stability_precision.png", "aliasing_heatmap.png",
          "stability_pcss_thin.png", "stability_pcss_overlap.png", "stability_pcss_noise.png",
          "stability_pcss_bias.png", "stability_bleed.png", "stability_cascades.png"}) {
        ImageSize size = readImageSize(out + "/" + chart);
        EXPECT_EQ(size.width, 640) << chart;
        EXPECT_EQ(size.height, 360) << chart;
    }
    // No staging folder left behind.
    int entries = 0;
    for (const auto& e : fs::directory_iterator(out)) entries += e.is_regular_file() ? 1 : 100;
    EXPECT_EQ(entries, 16);  // the charts, the heat map, the three CSVs and the table
    EXPECT_EQ(testutil::readAll(out + "/stability_bleed.csv").substr(0, 20),
              "sweep,method,kernel,");
    EXPECT_EQ(testutil::readAll(out + "/stability_cascades.csv").substr(0, 20),
              "method,kernel,split,");

    // Written once: a second run without -f is refused and leaves the files alone.
    auto again = testutil::runPcfscope("stability --quick --sweep aliasing -o " + out);
    EXPECT_EQ(again.exitCode, 2);
    EXPECT_EQ(testutil::readAll(out + "/stability.md"), md);

    // --replot draws the run's charts again from its CSV alone, the same pixels, every chart but
    // the heat map (an image the CSV does not hold); nothing else is written.
    std::string redrawn = path("replot");
    auto replot = testutil::runPcfscope("stability --replot " + out +
                                        "/stability.csv --chart-size 640x360 -o " + redrawn);
    ASSERT_EQ(replot.exitCode, 0) << replot.err;
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(redrawn)) {
        names.insert(e.path().filename().string());
    }
    EXPECT_EQ(names,
              (std::set<std::string>{
                  "stability_acne.png", "stability_leak.png", "stability_tradeoff.png",
                  "stability_shimmer.png", "stability_precision.png", "stability_pcss_thin.png",
                  "stability_pcss_overlap.png", "stability_pcss_noise.png",
                  "stability_pcss_bias.png", "stability_bleed.png", "stability_cascades.png"}));
    for (const std::string& chart : names) {
        EXPECT_EQ(readImageBytes(redrawn + "/" + chart, 4), readImageBytes(out + "/" + chart, 4))
            << chart;
    }
    // Nothing it would overwrite without -f; a measuring option is refused, not ignored.
    auto twice =
        testutil::runPcfscope("stability --replot " + out + "/stability.csv -o " + redrawn);
    EXPECT_EQ(twice.exitCode, 2);
    EXPECT_NE(twice.err.find("already exists; pass --force"), std::string::npos) << twice.err;
    auto measuring = testutil::runPcfscope("stability --replot " + out +
                                           "/stability.csv --map-size 256 -o " + path("m"));
    EXPECT_EQ(measuring.exitCode, 2);
    EXPECT_EQ(measuring.err,
              "pcfscope: --map-size does not apply to --replot, which draws an existing "
              "stability.csv and measures nothing\n");
    EXPECT_FALSE(fs::exists(path("m")));
}

// --replot reads its CSV with every input check: one line naming the file and line, exit 2,
// nothing written.
TEST_F(StabilityCommand, ReplotRefusesABadCsv) {
    std::string csv = path("bad.csv");
    std::ofstream(csv) << "sweep,method,kernel,bias,x_name,x,metric,y\n"
                       << "acne,nearest,0,none,elevation_deg,ninety,false_shadow_rate,0.2\n";
    auto r = testutil::runPcfscope("stability --replot " + csv + " -o " + path("out"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("pcfscope: " + csv + ":2:", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(path("out")));
}

TEST_F(StabilityCommand, BadSweepParametersExit2WithNothingWritten) {
    const char* bad[] = {
        "--sweep acne,wobble",        "--sweep ''",
        "--methods nearest,blurry",   "--biases constant,huge",
        "--methods tent --kernels 4", "--size 8x8",
    };
    for (const char* args : bad) {
        std::string out = path("bad");
        auto r = testutil::runPcfscope(std::string("stability --quick ") + args + " -o " + out);
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << args << ": " << r.err;
        EXPECT_EQ(r.err.rfind("pcfscope: ", 0), 0u) << args << ": " << r.err;
        EXPECT_FALSE(fs::exists(out)) << args;
    }
    // The sweep's own checks name their setting as its flag (app/cli_util.h: cliWords).
    auto r = testutil::runPcfscope(
        "stability --quick --methods pcf-gather --biases interpolated -o " + path("bad"));
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("no method given combines with --biases: bias interpolated"),
              std::string::npos)
        << r.err;
}

}  // namespace
}  // namespace pcf
