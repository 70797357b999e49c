// `pcfscope bench`, run as a user runs it: --quick writes the CSV, the table, the chart and the
// difference images; bad input is refused before anything is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "image_read.h"
#include "kernel/methods.h"
#include "measure/bench_report.h"
#include "run_command.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

class BenchCommand : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("bench"); }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    fs::path mDir;
};

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string f; std::getline(s, f, ',');) fields.push_back(f);
    return fields;
}

TEST_F(BenchCommand, QuickWritesTheFilesWithOneRowPerPoint) {
    std::string out = path("quick");
    auto r = testutil::runPcfscope("bench --quick -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // Every method, N = 3 for the four that take a kernel, maps 128 and 256.
    const int points = static_cast<int>(allMethods().size()) * 2;
    EXPECT_NE(r.err.find("bench: 12/" + std::to_string(points) + " "), std::string::npos)
        << r.err;  // progress

    std::ifstream csv(out + "/bench.csv");
    std::string line;
    ASSERT_TRUE(std::getline(csv, line));
    EXPECT_EQ(line, BENCH_CSV_HEADER);
    EXPECT_EQ(line,
              "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,"
              "edge_rmse,edge_max_err,timer,gpu_ms_iqr,lookup_ms,lookup_ms_iqr,noisy,weights,sigma,"
              "acne_share,acne_darkening,acne_pixels,leak_share,leak_mean,leak_pixels,"
              "shimmer_mean,shimmer_p99,flicker_share,change_mean,gpu_cpu_ms,lookup_cpu_ms,"
              "gl_renderer,contact_edge_rmse,contact_edge_pixels,truth,contact_distance,"
              "gpu_cpu_ms_iqr,lookup_cpu_ms_iqr");
    std::set<std::string> methods;
    int rows = 0;
    while (std::getline(csv, line)) {
        ++rows;
        std::vector<std::string> f = splitCsvLine(line);
        ASSERT_EQ(f.size(), 36u) << line;
        EXPECT_EQ(f[32], "hard (the light's centre)") << line;  // truth
        EXPECT_EQ(f[33], "0") << line;                          // contact_distance: not measured
        // The CPU times' spreads: the IQR of the repeats, never negative, below the median.
        for (auto [iqr, median] : {std::pair{34, 27}, std::pair{35, 28}}) {
            EXPECT_GE(std::stod(f[iqr]), 0.0) << line;
            EXPECT_LT(std::stod(f[iqr]), std::stod(f[median])) << line;
        }
        methods.insert(f[0]);
        std::optional<int> method = methodFromName(f[0]);
        ASSERT_TRUE(method.has_value()) << line;
        bool kernelMethod = methodInfo(*method).usesKernel;
        EXPECT_EQ(f[1], kernelMethod ? "3" : "0") << line;
        EXPECT_TRUE(f[2] == "128" || f[2] == "256") << line;
        EXPECT_GT(std::stod(f[3]), 0.0) << line;  // gpu_ms
        EXPECT_GT(std::stod(f[4]), 0.0) << line;  // cpu_ns_per_pixel
        EXPECT_GE(std::stoi(f[5]), 1) << line;    // texel_reads
        for (int k = 6; k <= 9; ++k) {
            double e = std::stod(f[k]);
            EXPECT_GE(e, 0.0) << line;
            EXPECT_LE(e, 1.0) << line;
        }
        EXPECT_GT(std::stod(f[8]), 0.0) << line;  // an edge band exists, and PCF misses it
        EXPECT_TRUE(f[10] == "glFinish+steady_clock" || f[10] == "GL_TIME_ELAPSED") << line;
        EXPECT_GE(std::stod(f[11]), 0.0) << line;  // gpu_ms_iqr
        EXPECT_GT(std::stod(f[12]), 0.0) << line;  // lookup_ms
        EXPECT_GE(std::stod(f[13]), 0.0) << line;  // lookup_ms_iqr
        // gpu_cpu_ms, lookup_cpu_ms: the passes' CPU time where the CPU renders, else 0
        bool cpuRenders = f[10] == "glFinish+steady_clock";
        EXPECT_EQ(std::stod(f[27]) > 0.0, cpuRenders) << line;
        EXPECT_EQ(std::stod(f[28]) > 0.0, cpuRenders) << line;
        // noisy exactly when an IQR is above 10 % of its median (to the CSV's 4 decimals)
        EXPECT_TRUE(f[14] == "0" || f[14] == "1") << line;
        bool noisy = std::stod(f[11]) > 0.1 * std::stod(f[3]) + 1e-4 ||
                     std::stod(f[13]) > 0.1 * std::stod(f[12]) + 1e-4;
        if (noisy) {
            EXPECT_EQ(f[14], "1") << line;
        }
        EXPECT_EQ(f[15], "box") << line;  // weights
        EXPECT_EQ(f[16], "0") << line;    // sigma: not gaussian
        // Shares and shimmer are in [0,1]; the clean masks hold pixels of both kinds (the
        // ground around the box's shadow is lit, the shadow's core is umbra).
        for (int k : {17, 18, 20, 21, 23, 24, 25, 26}) {
            EXPECT_GE(std::stod(f[k]), 0.0) << k << ": " << line;
            EXPECT_LE(std::stod(f[k]), 1.0) << k << ": " << line;
        }
        EXPECT_GT(std::stoi(f[19]), 1000) << line;  // clean lit pixels
        // Clean umbra pixels: none for pcss, whose blocker search may reach 32.5 texels, farther
        // than any point of the box's shadow on a 128 or 256 map lies from its edge.
        if (f[0] == "pcss") {
            EXPECT_EQ(std::stoi(f[22]), 0) << line;
        } else {
            EXPECT_GT(std::stoi(f[22]), 100) << line;
        }
        // The darkening is at most the share darker than 0.99 plus 1 % of the rest.
        EXPECT_LE(std::stod(f[18]), std::stod(f[17]) + 0.01) << line;
        // Some pixel flickers as the grid slides, and nearest jumps all the way (0 <-> 1).
        EXPECT_GT(std::stod(f[25]), 0.0) << line;
        // The renderer it was timed on (GL_RENDERER, commas written ';'): the charts read it.
        EXPECT_EQ(f[29].find(','), std::string::npos) << line;
        EXPECT_FALSE(f[29].empty()) << line;
        EXPECT_GT(std::stod(f[24]), 0.0) << line;
        if (f[0] == "nearest") {
            EXPECT_EQ(f[24], "1") << line;
        }
        if (f[0] == "pcf-gather") {
            EXPECT_LT(std::stod(f[24]), 0.5) << line;
        }
    }
    EXPECT_EQ(rows, points);
    EXPECT_EQ(methods.size(), allMethods().size());

    std::string md = testutil::readAll(out + "/bench.md");
    EXPECT_NE(md.find("Measured on `"), std::string::npos) << md;
    EXPECT_NE(md.find("| pcf-gather"), std::string::npos) << md;
    EXPECT_EQ(r.out, md);  // the table on stdout too

    // The timing rounds are reported, and the truth's bound.
    EXPECT_NE(r.err.find("bench: timing round 5/5"), std::string::npos) << r.err;
    EXPECT_NE(md.find("largest per-pixel bound"), std::string::npos) << md;
    // The chart: the frame's size but at least 960x540, unless --chart-size says otherwise.
    for (const char* name : {"/speed_vs_accuracy.png", "/speed_vs_stability.png"}) {
        ImageSize chart = readImageSize(out + name);
        EXPECT_EQ(chart.width, 960) << name;
        EXPECT_EQ(chart.height, 540) << name;
    }
    int diffs = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(out + "/diff")) {
        ++diffs;
        ImageSize d = readImageSize(e.path().string());
        EXPECT_EQ(d.width, 320) << e.path();
        EXPECT_EQ(d.height, 180) << e.path();
    }
    EXPECT_EQ(diffs, points);
    EXPECT_TRUE(fs::exists(out + "/diff/pcf-gather-n3-map256.png"));
    EXPECT_TRUE(fs::exists(out + "/diff/nearest-map128.png"));
    // Nothing else: no staging folder left behind.
    int entries = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(out)) {
        (void)e;
        ++entries;
    }
    EXPECT_EQ(entries, 5);
}

TEST_F(BenchCommand, ChosenMethodsKernelsMapsAndChartSize) {
    std::string out = path("chosen");
    auto r = testutil::runPcfscope(
        "bench --quick --methods tent,nearest --kernels 3,5 "
        "--map-sizes 64,96,128 --chart-size 640x400 -o " +
        out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string csv = testutil::readAll(out + "/bench.csv");
    EXPECT_EQ(testutil::lineCount(csv), 1 + (2 + 1) * 3) << csv;
    EXPECT_NE(csv.find("\ntent,5,96,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nnearest,0,64,"), std::string::npos) << csv;
    ImageSize chart = readImageSize(out + "/speed_vs_accuracy.png");
    EXPECT_EQ(chart.width, 640);
    EXPECT_EQ(chart.height, 400);
}

// Without --quick the defaults are N = 3, 5 on a 1024 map (a minute on 2 cores); --full sweeps
// N = 3, 5, 7 over maps 256..2048, and options given explicitly still win over either.
TEST_F(BenchCommand, DefaultsAreNThreeAndFiveOnA1024MapAndFullSweepsEverything) {
    const std::string tiny = " --size 64x36 --repeats 1 --shimmer-frames 0 -o ";
    auto plain = testutil::runPcfscope("bench --methods tent,nearest" + tiny + path("plain"));
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    std::string csv = testutil::readAll(path("plain") + "/bench.csv");
    EXPECT_EQ(testutil::lineCount(csv), 1 + 3) << csv;
    EXPECT_NE(csv.find("\ntent,3,1024,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\ntent,5,1024,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nnearest,0,1024,"), std::string::npos) << csv;

    auto maps = testutil::runPcfscope("bench --full --methods nearest" + tiny + path("maps"));
    ASSERT_EQ(maps.exitCode, 0) << maps.err;
    csv = testutil::readAll(path("maps") + "/bench.csv");
    EXPECT_EQ(testutil::lineCount(csv), 1 + 4) << csv;
    for (const char* size : {"256", "512", "1024", "2048"}) {
        EXPECT_NE(csv.find("\nnearest,0," + std::string(size) + ","), std::string::npos) << csv;
    }
    auto kernels =
        testutil::runPcfscope("bench --full --methods tent --map-sizes 64" + tiny + path("n"));
    ASSERT_EQ(kernels.exitCode, 0) << kernels.err;
    csv = testutil::readAll(path("n") + "/bench.csv");
    EXPECT_EQ(testutil::lineCount(csv), 1 + 3) << csv;
    EXPECT_NE(csv.find("\ntent,7,64,"), std::string::npos) << csv;
}

// --weights takes a list: pcf-naive and pcf-gather run once per weighting, every other method
// with the box; the CSV names the weighting and the gaussian's sigma.
TEST_F(BenchCommand, WeightsListSweepsTheWeightedMethods) {
    std::string out = path("weights");
    auto r = testutil::runPcfscope(
        "bench --quick --methods pcf-gather,nearest --weights box,gaussian --sigma 1.5 "
        "--map-sizes 128 --repeats 1 --shimmer-frames 0 -o " +
        out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<BenchRow> rows = parseBenchCsv(testutil::readAll(out + "/bench.csv"), "bench.csv");
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0].point.weights, 0);  // box
    EXPECT_EQ(rows[0].point.sigma, 0.0f);
    EXPECT_EQ(rows[1].point.method, rows[0].point.method);
    EXPECT_EQ(rows[1].point.weights, 2);  // gaussian
    EXPECT_FLOAT_EQ(rows[1].point.sigma, 1.5f);
    EXPECT_EQ(rows[2].point.weights, 0);  // nearest: the box only
    // A different filter: a different error (the Gaussian is wider than the 3x3 box).
    EXPECT_NE(rows[0].error.edgeRmse, rows[1].error.edgeRmse);
    EXPECT_TRUE(fs::exists(out + "/diff/pcf-gather-n3-gaussian-map128.png"));
    EXPECT_TRUE(fs::exists(out + "/diff/pcf-gather-n3-map128.png"));
    EXPECT_NE(r.out.find("| pcf-gather gaussian 1.5"), std::string::npos) << r.out;
    // No shimmer frames: the shimmer columns are 0.
    EXPECT_EQ(rows[0].shimmer.flickerP99, 0.0);
}

// --reference times each run's textbook pass in the same rounds and writes reference.csv: one
// row per run, in bench.csv's order, with both passes' medians and their ratio.
TEST_F(BenchCommand, ReferenceWritesBothPassesPerRun) {
    std::string out = path("reference");
    auto r = testutil::runPcfscope(
        "bench --quick --methods nearest,pcf-gather --map-sizes 128 --repeats 3 "
        "--shimmer-frames 0 --reference -o " +
        out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string csv = testutil::readAll(out + "/reference.csv");
    std::stringstream lines(csv);
    std::string header, nearest, gather, extra;
    std::getline(lines, header);
    std::getline(lines, nearest);
    std::getline(lines, gather);
    EXPECT_FALSE(std::getline(lines, extra)) << csv;
    EXPECT_EQ(header,
              "method,kernel,map_size,lookup_ms,lookup_iqr_ms,reference_ms,reference_iqr_ms,"
              "ratio,lookup_cpu_ms,reference_cpu_ms");
    for (const std::string& line : {nearest, gather}) {
        std::vector<std::string> f = splitCsvLine(line);
        ASSERT_EQ(f.size(), 10u) << line;
        double lookup = std::stod(f[3]);
        double reference = std::stod(f[5]);
        EXPECT_GT(lookup, 0.0) << line;
        EXPECT_GT(reference, 0.0) << line;
        EXPECT_NEAR(std::stod(f[7]), lookup / reference, 0.002 + 1e-3 * lookup / reference) << line;
    }
    EXPECT_EQ(splitCsvLine(nearest)[0], "nearest");
    EXPECT_EQ(splitCsvLine(gather)[0], "pcf-gather");
    EXPECT_EQ(splitCsvLine(gather)[1], "3");
    // Without the flag, no reference.csv.
    std::string plain = path("plain");
    auto p = testutil::runPcfscope(
        "bench --quick --methods nearest --map-sizes 128 --repeats 1 --shimmer-frames 0 -o " +
        plain);
    ASSERT_EQ(p.exitCode, 0) << p.err;
    EXPECT_FALSE(fs::exists(plain + "/reference.csv"));
}

// --truth area: the truth integrates over the scene light's disk (post-in-sun: 2 degrees), the
// report and the chart say so, and pcss, whose penumbra follows the blocker, is nearer that truth
// at the edges than a fixed 3 x 3 kernel, which draws the hard shadow's narrow penumbra.
TEST_F(BenchCommand, AreaTruthMeasuresAgainstTheLightsDisk) {
    std::string out = path("area");
    auto r = testutil::runPcfscope(
        "bench --quick --scene post-in-sun --truth area --methods pcf-gather,pcss --kernels 7 "
        "--map-sizes 256 --size 192x108 --contact 1 -o " +
        out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("ground truth area (a sun disk of 2 degrees)"), std::string::npos)
        << r.err;
    std::string md = testutil::readAll(out + "/bench.md");
    EXPECT_NE(md.find("ground truth, area (a sun disk of 2 degrees)"), std::string::npos) << md;
    std::string csv = testutil::readAll(out + "/bench.csv");
    std::istringstream lines(csv);
    std::string line;
    std::getline(lines, line);
    std::vector<std::string> header = splitCsvLine(line);
    size_t rmse = std::find(header.begin(), header.end(), "edge_rmse") - header.begin();
    size_t near = std::find(header.begin(), header.end(), "contact_edge_rmse") - header.begin();
    size_t nearPixels =
        std::find(header.begin(), header.end(), "contact_edge_pixels") - header.begin();
    size_t truth = std::find(header.begin(), header.end(), "truth") - header.begin();
    size_t distance = std::find(header.begin(), header.end(), "contact_distance") - header.begin();
    ASSERT_LT(rmse, header.size()) << line;
    ASSERT_LT(nearPixels, header.size()) << line;
    ASSERT_LT(distance, header.size()) << line;
    std::map<std::string, double> edge, contact;
    while (std::getline(lines, line)) {
        std::vector<std::string> cells = splitCsvLine(line);
        ASSERT_EQ(cells.size(), header.size()) << line;
        edge[cells[0]] = std::stod(cells[rmse]);
        contact[cells[0]] = std::stod(cells[near]);
        // The edge band within 1 unit of the post's foot: part of the band, not all of it.
        EXPECT_GT(std::stoi(cells[nearPixels]), 20) << line;
        // Each row says which truth and which distance (a lesson's chart reads them).
        EXPECT_EQ(cells[truth], "area (a sun disk of 2 degrees)") << line;
        EXPECT_EQ(cells[distance], "1") << line;
    }
    ASSERT_EQ(edge.size(), 2u) << csv;
    EXPECT_LT(edge["pcss"], edge["pcf-gather"]) << csv;
    // Near the contact the true penumbra is narrow and pcss narrows its kernel with it, while a
    // wide fixed kernel (7 texels, 0.3 units on this map) stays wide: measured 0.058 against
    // 0.128 (and 0.047 against 0.090 over the whole edge band).
    EXPECT_LT(contact["pcss"], contact["pcf-gather"]) << csv;
    EXPECT_GT(contact["pcss"], 0.0) << csv;
    EXPECT_TRUE(fs::exists(out + "/speed_vs_contact.png"));
    EXPECT_NE(r.err.find("speed_vs_stability.png, speed_vs_contact.png}"), std::string::npos)
        << r.err;  // the last line names every file written
}

// --truth area under a spot light: its disk of the scene's radius (light_visibility.h), which
// the CSV's truth column names; a spot without a radius has no disk, one line.
TEST_F(BenchCommand, AreaTruthOfASpotLightsDisk) {
    const std::string head =
        "[camera]\neye = [2.5, 3.0, 3.5]\ntarget = [0.3, 0.3, 0.0]\nfov = 40.0\n"
        "[light]\ntype = \"spot\"\ndirection = [0.0, -1.0, 0.0]\nposition = [0.0, 4.0, 0.0]\n"
        "cone = 50.0\n";
    const std::string objects =
        "[[object]]\ntype = \"plane\"\nname = \"ground\"\ncentre = [0.0, 0.0, 0.0]\n"
        "normal = [0.0, 1.0, 0.0]\nsize = [8.0, 8.0]\n"
        "[[object]]\ntype = \"box\"\nname = \"post\"\ncentre = [0.4, 0.75, 0.0]\n"
        "half = [0.15, 0.75, 0.15]\n";
    std::ofstream(path("point.toml")) << head << objects;
    auto refused = testutil::runPcfscope("bench --quick --truth area --scene-file " +
                                         path("point.toml") + " -o " + path("refused"));
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_EQ(testutil::lineCount(refused.err), 1) << refused.err;
    EXPECT_NE(refused.err.find("has a spot light without a radius"), std::string::npos)
        << refused.err;
    EXPECT_FALSE(fs::exists(path("refused")));

    std::ofstream(path("disk.toml")) << head << "radius = 0.4\n" << objects;
    std::string out = path("disk");
    auto r = testutil::runPcfscope(
        "bench --quick --truth area --methods pcf-gather --kernels 3 "
        "--map-sizes 256 --size 96x54 --scene-file " +
        path("disk.toml") + " -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<BenchRow> rows =
        parseBenchCsv(testutil::readAll(out + "/bench.csv"), out + "/bench.csv");
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].truth, "area (a spot disk of radius 0.4)");
    EXPECT_GT(rows[0].error.edgeRmse, 0.0);
}

TEST_F(BenchCommand, BadInputExitsTwoWithOneLineAndWritesNothing) {
    struct Case {
        std::string args;
        std::string expect;
    };
    std::vector<Case> cases = {
        {"--methods nearest,blur", "unknown method 'blur'"},
        {"--kernels 3,9", "--kernels 9 is out of range"},
        {"--kernels 3,x", "--kernels"},
        {"--kernels 3,,5", "--kernels"},
        {"--map-sizes 3", "--map-sizes 3 is out of range"},
        {"--contact -1", "--contact must be a distance in world units"},
        {"--map-sizes 5000", "--map-sizes 5000"},
        {"--methods tent --kernels 4", "tent takes --kernels 3, 5 or 7"},
        {"--size 0x10", "--size"},
        {"--chart-size 20x20", "--chart-size"},
        {"--scene no-such", "unknown scene 'no-such'"},
        {"--scene pole --scene-file x.toml", "give one of --scene, --scene-file"},
        {"--method nearest", "--method does not apply to bench"},
        {"--shimmer-frames 40", "--shimmer-frames 40 is out of range"},
        {"--weights box,sharp", "unknown --weights 'sharp'"},
        {"--methods nearest --weights gaussian", "pcf-naive and pcf-gather only"},
        {"--weights gaussian --sigma -1", "--sigma must be in [0.05, 16] texels, got -1"},
        {"--methods hw2x2 --bias soft", "soft"},
        {"--spp 0", "--spp 0"},
        {"--repeats 0", "--repeats"},
        {"--timing wall", "--timing"},
        {"--cull sideways", "--cull"},
        {"--reference --bias receiver-plane", "--reference times the methods' plain"},
        {"--reference --depth-format 24", "--depth-format 32f"},
        {"--full", "--quick and --full exclude each other"},
        {"--truth soft", "unknown --truth 'soft'"},
    };
    for (const Case& c : cases) {
        auto r = testutil::runPcfscope("bench --quick " + c.args + " -o " + path("out"));
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_FALSE(fs::exists(path("out"))) << c.args;
    }
    // -o naming a file, not a directory.
    { std::ofstream(path("file")) << "x"; }
    auto notDir = testutil::runPcfscope("bench --quick -o " + path("file"));
    EXPECT_EQ(notDir.exitCode, 2);
    EXPECT_NE(notDir.err.find("not a directory"), std::string::npos) << notDir.err;
}

// Error is charted over the edge band; a frame without a shadow edge has none, and a row of
// perfect zeros would be a lie. The run is refused, after the truth that shows it, with nothing
// written.
TEST_F(BenchCommand, RefusesAFrameWithoutAShadowEdge) {
    std::ofstream(path("plane.toml"))
        << "[camera]\neye = [0.0, 3.0, -6.0]\ntarget = [0.0, 0.0, 0.0]\nfov = 45.0\n"
           "[light]\ntype = \"directional\"\ndirection = [0.3, -1.0, 0.2]\n"
           "[[object]]\ntype = \"plane\"\nname = \"ground\"\ncentre = [0.0, 0.0, 0.0]\n"
           "normal = [0.0, 1.0, 0.0]\nsize = [8.0, 8.0]\n";
    auto r = testutil::runPcfscope("bench --quick --methods nearest --scene-file " +
                                   path("plane.toml") + " -o " + path("out"));
    EXPECT_EQ(r.exitCode, 2) << r.err;
    // The refusal is the only line: no progress before it (the truth is checked first).
    EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("pcfscope: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("no shadow edge"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("out")));
}

// --replot draws an existing bench.csv's charts and measures nothing: the two PNGs at the chart
// size and nothing else (no CSV, table or difference images, no sweep's progress); options that
// choose what is measured, a CSV that is not there, --contact for a CSV without contact columns
// and charts already there are refused with one line and nothing written.
TEST_F(BenchCommand, ReplotDrawsACsvsChartsAndMeasuresNothing) {
    const std::string csv = PCFSCOPE_SOURCE_DIR "/lessons/figures/bench.csv";
    std::string out = path("replot");
    auto r = testutil::runPcfscope("bench --replot " + csv + " --chart-size 960x540 -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("bench: drew "), std::string::npos) << r.err;
    std::set<std::string> written;
    for (const fs::directory_entry& e : fs::directory_iterator(out)) {
        written.insert(e.path().filename().string());
    }
    EXPECT_EQ(written, (std::set<std::string>{"speed_vs_accuracy.png", "speed_vs_stability.png"}));
    for (const std::string& name : written) {
        ImageSize chart = readImageSize(out + "/" + name);
        EXPECT_EQ(chart.width, 960) << name;
        EXPECT_EQ(chart.height, 540) << name;
    }
    auto again = testutil::runPcfscope("bench --replot " + csv + " -o " + out);
    EXPECT_EQ(again.exitCode, 2) << again.err;
    EXPECT_NE(again.err.find("already exists"), std::string::npos) << again.err;
    EXPECT_EQ(testutil::runPcfscope("bench --replot " + csv + " -f -o " + out).exitCode, 0);

    struct Case {
        std::string args;
        std::string expect;
    };
    std::vector<Case> cases = {
        {"--replot " + path("none.csv"), "none.csv"},
        {"--replot " + csv + " --methods nearest", "--methods does not apply to --replot"},
        {"--replot " + csv + " --quick", "--quick does not apply to --replot"},
        {"--replot " + csv + " --contact 0.5", "has no contact columns"},
        {"--replot " + csv + " --timing wall", "--timing"},
    };
    for (const Case& c : cases) {
        auto bad = testutil::runPcfscope("bench " + c.args + " -o " + path("out"));
        EXPECT_EQ(bad.exitCode, 2) << c.args << "\n" << bad.err;
        EXPECT_EQ(testutil::lineCount(bad.err), 1) << c.args << "\n" << bad.err;
        EXPECT_NE(bad.err.find(c.expect), std::string::npos) << c.args << "\n" << bad.err;
        EXPECT_FALSE(fs::exists(path("out"))) << c.args;
    }
}

TEST_F(BenchCommand, RefusesToOverwriteWithoutForce) {
    std::string out = path("again");
    fs::create_directories(out);
    { std::ofstream(out + "/bench.csv") << "old"; }
    auto r = testutil::runPcfscope("bench --quick --methods nearest -o " + out);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(testutil::lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("bench.csv already exists"), std::string::npos) << r.err;
    EXPECT_EQ(testutil::readAll(out + "/bench.csv"), "old");
    int entries = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(out)) {
        (void)e;
        ++entries;
    }
    EXPECT_EQ(entries, 1);  // nothing written beside it

    auto forced = testutil::runPcfscope("bench --quick --methods nearest -f -o " + out);
    ASSERT_EQ(forced.exitCode, 0) << forced.err;
    EXPECT_EQ(testutil::readAll(out + "/bench.csv").rfind(BENCH_CSV_HEADER, 0), 0u);
    // The difference images count as output files too.
    for (const char* name :
         {"bench.csv", "bench.md", "speed_vs_accuracy.png", "speed_vs_stability.png"}) {
        fs::remove(out + "/" + name);
    }
    auto diffOnly = testutil::runPcfscope("bench --quick --methods nearest -o " + out);
    EXPECT_EQ(diffOnly.exitCode, 2);
    EXPECT_NE(diffOnly.err.find("nearest-map128.png already exists"), std::string::npos)
        << diffOnly.err;
    EXPECT_FALSE(fs::exists(out + "/bench.csv"));
}

}  // namespace
}  // namespace pcf
