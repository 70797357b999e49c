// bench.csv read back: what a lesson's chart is drawn from.
#include "measure/bench_report.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "base/input_error.h"
#include "kernel/methods.h"

namespace pcf {
namespace {

std::vector<BenchRow> sampleRows() {
    BenchRow a;
    a.point = {PCF_GATHER, 3, 1024};
    a.gpuMs = 16.8375;
    a.cpuNsPerPixel = 70.41;
    a.texelReads = 16;
    a.error = {0.0225, 1.0, 0.2102, 0.99, 0, 0};
    a.timer = "glFinish+steady_clock";
    a.point.weights = PCF_WEIGHTS_GAUSSIAN;
    a.point.sigma = 1.25f;
    a.acne = {0.125, 0.03125, 4096};
    a.leak = {0.0625, 0.015625, 512};
    a.shimmer.flickerMean = 0.0123456789;
    a.shimmer.flickerP99 = 0.375;
    a.shimmer.flickerShare = 0.02;
    a.shimmer.mean = 0.000246913578;
    a.gpuCpuMs = 21.25;
    a.lookupCpuMs = 9.5;
    a.gpuCpuMsIqr = 0.75;
    a.lookupCpuMsIqr = 0.25;
    a.glRenderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    a.contact.edgeRmse = 0.0625;
    a.contact.edgePixels = 37;
    a.contactDistance = 1.5;
    a.truth = "area (a sun disk of 2 degrees)";
    BenchRow b = a;
    b.point = {PCF_NEAREST, 0, 256};
    b.acne = {};
    b.shimmer.flickerP99 = 1.0;
    b.gpuMs = 11.5;
    b.texelReads = 1;
    return {a, b};
}

TEST(BenchReport, CsvReadsBackWhatWasWritten) {
    std::vector<BenchRow> rows = sampleRows();
    std::vector<BenchRow> back = parseBenchCsv(benchCsv(rows), "bench.csv");
    ASSERT_EQ(back.size(), 2u);
    for (size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(back[k].point, rows[k].point);
        EXPECT_NEAR(back[k].gpuMs, rows[k].gpuMs, 1e-4);
        EXPECT_NEAR(back[k].cpuNsPerPixel, rows[k].cpuNsPerPixel, 1e-2);
        EXPECT_EQ(back[k].texelReads, rows[k].texelReads);
        EXPECT_DOUBLE_EQ(back[k].error.edgeRmse, rows[k].error.edgeRmse);
        EXPECT_EQ(back[k].timer, rows[k].timer);
        // The error split, the weighting and the shimmer: exact to 9 digits.
        EXPECT_EQ(back[k].point.weights, rows[k].point.weights);
        EXPECT_EQ(back[k].point.sigma, rows[k].point.sigma);
        EXPECT_EQ(back[k].acne.share, rows[k].acne.share);
        EXPECT_EQ(back[k].acne.mean, rows[k].acne.mean);
        EXPECT_EQ(back[k].acne.count, rows[k].acne.count);
        EXPECT_EQ(back[k].leak.share, rows[k].leak.share);
        EXPECT_EQ(back[k].leak.mean, rows[k].leak.mean);
        EXPECT_EQ(back[k].leak.count, rows[k].leak.count);
        EXPECT_NEAR(back[k].shimmer.flickerMean, rows[k].shimmer.flickerMean, 1e-12);
        EXPECT_EQ(back[k].shimmer.flickerP99, rows[k].shimmer.flickerP99);
        EXPECT_NEAR(back[k].shimmer.flickerShare, rows[k].shimmer.flickerShare, 1e-12);
        EXPECT_NEAR(back[k].shimmer.mean, rows[k].shimmer.mean, 1e-15);
        EXPECT_NEAR(back[k].gpuCpuMs, rows[k].gpuCpuMs, 1e-4);
        EXPECT_NEAR(back[k].lookupCpuMs, rows[k].lookupCpuMs, 1e-4);
        EXPECT_NEAR(back[k].gpuCpuMsIqr, rows[k].gpuCpuMsIqr, 1e-4);
        EXPECT_NEAR(back[k].lookupCpuMsIqr, rows[k].lookupCpuMsIqr, 1e-4);
        // The renderer, its comma written ';' (the files carry no quoting).
        EXPECT_EQ(back[k].glRenderer, "llvmpipe (LLVM 15.0.6; 256 bits)");
        EXPECT_EQ(back[k].contact.edgeRmse, rows[k].contact.edgeRmse);
        EXPECT_EQ(back[k].contact.edgePixels, rows[k].contact.edgePixels);
        // The truth and the contact distance: what a lesson's chart says it measured.
        EXPECT_EQ(back[k].truth, rows[k].truth);
        EXPECT_EQ(benchTruthKind(back[k]), "area");
        EXPECT_EQ(back[k].contactDistance, 1.5);
    }
    // The columns by name: the weighting's name, and the gaussian's sigma.
    std::string csv = benchCsv(rows);
    EXPECT_NE(
        csv.find(",gaussian,1.25,0.125,0.03125,4096,0.0625,0.015625,512,0.0123456789,0.375,"
                 "0.02,0.000246913578,21.2500,9.5000,llvmpipe (LLVM 15.0.6; 256 bits),0.0625,37,"
                 "area (a sun disk of 2 degrees),1.5,0.7500,0.2500\n"),
        std::string::npos)
        << csv;
}

// A file from before the truth column reads with the truth unknown and no contact distance.
TEST(BenchReport, CsvBeforeTheTruthColumnReadsWithoutIt) {
    std::string csv = benchCsv(sampleRows());
    std::string v6(BENCH_CSV_HEADER_V6);
    std::string old = v6 + "\n";
    size_t line = csv.find('\n') + 1;
    for (size_t end; (end = csv.find('\n', line)) != std::string::npos; line = end + 1) {
        std::string row = csv.substr(line, end - line);
        // Drop the last four fields (the truth, the contact distance and the CPU spreads).
        for (int k = 0; k < 4; ++k) row = row.substr(0, row.rfind(','));
        old += row + "\n";
    }
    std::vector<BenchRow> back = parseBenchCsv(old, "old.csv");
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[0].truth, "");
    EXPECT_EQ(benchTruthKind(back[0]), "");
    EXPECT_EQ(back[0].contactDistance, 0.0);
    EXPECT_EQ(back[0].contact.edgePixels, 37);
}

TEST(BenchReport, TheShippedCsvParses) {
    std::string path = PCFSCOPE_SOURCE_DIR "/lessons/figures/bench.csv";
    FILE* f = std::fopen(path.c_str(), "rb");
    ASSERT_NE(f, nullptr);
    std::string text;
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
    std::fclose(f);
    std::vector<BenchRow> rows = parseBenchCsv(text, path);
    EXPECT_GE(rows.size(), 60u);  // every method, N = 3, 5, 7, four map sizes
    // The error split, the shimmer and the renderer are there (the current header or the one
    // before the truth column, BENCH_CSV_HEADER_V6: a hard-truth run), and say what they must:
    // lesson 11's words on llvmpipe read the renderer.
    EXPECT_TRUE(text.starts_with(std::string(BENCH_CSV_HEADER) + "\n"));
    for (const BenchRow& r : rows) {
        std::string name = pointName(r.point) + " map " + std::to_string(r.point.mapSize);
        EXPECT_NE(r.glRenderer.find("llvmpipe"), std::string::npos) << name;
        EXPECT_GT(r.acne.count, 0) << name;
        // (pcss at the 256 and 512 maps has no clean umbra pixel to count: its leak is 0 of 0
        // pixels, which bench.md prints as "-", BenchReport.AnEmptyMaskIsNoMeasurement.)
        if (r.point.method != PCF_PCSS || r.point.mapSize >= 1024) {
            EXPECT_GT(r.leak.count, 0) << name;
        }
        EXPECT_GT(r.shimmer.flickerShare, 0.0) << name;
        if (r.point.method == PCF_NEAREST) {
            EXPECT_EQ(r.shimmer.flickerP99, 1.0) << name;
        }
    }
}

// Every committed bench CSV (the lessons' charts) is the current header, carries its CPU times'
// spreads, and within each method (at one map size and weighting) the time grows with the
// kernel by both clocks, wall and process CPU, for both passes: a student reading a chart must not
// see a wider kernel cost less (issue 32: 17.4's wall clock put gather 7x7 at 8.5 ms and 3x3 at
// 11.6).
TEST(BenchReport, EveryShippedCsvsTimesRiseWithTheKernel) {
    int files = 0, pairs = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(PCFSCOPE_SOURCE_DIR "/lessons/figures")) {
        std::string path = entry.path().string();
        if (!path.ends_with("bench.csv")) continue;
        ++files;
        std::ifstream in(path, std::ios::binary);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_TRUE(text.starts_with(std::string(BENCH_CSV_HEADER) + "\n")) << path;
        std::vector<BenchRow> rows = parseBenchCsv(text, path);
        for (const BenchRow& a : rows) {
            EXPECT_TRUE(benchTimesByCpu(a)) << path << " " << pointName(a.point);
            EXPECT_GT(a.gpuCpuMsIqr, 0.0) << path << " " << pointName(a.point);
            for (const BenchRow& b : rows) {
                BenchPoint same = b.point;
                same.kernel = a.point.kernel;
                if (same != a.point || b.point.kernel <= a.point.kernel) continue;
                ++pairs;
                std::string what = path + ": " + pointName(a.point) + " against " +
                                   pointName(b.point) + " map " + std::to_string(a.point.mapSize);
                EXPECT_LT(a.gpuMs, b.gpuMs) << what << ", scene wall";
                EXPECT_LT(a.gpuCpuMs, b.gpuCpuMs) << what << ", scene CPU";
                EXPECT_LT(a.lookupMs, b.lookupMs) << what << ", lookup wall";
                EXPECT_LT(a.lookupCpuMs, b.lookupCpuMs) << what << ", lookup CPU";
            }
        }
    }
    EXPECT_GE(files, 3);
    EXPECT_GE(pairs, 40);
}

TEST(BenchReport, AnEmptyMaskIsNoMeasurement) {
    // Row b's acne mask is empty (acne = {}): its acne column reads "-", not 0.00 %; row a's
    // shares are percentages of their masks.
    std::vector<BenchRow> rows = sampleRows();
    BenchSetup setup;
    std::string md = benchMarkdown(rows, setup);
    EXPECT_NE(md.find("| 12.50 | 6.25 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| - | 6.25 |"), std::string::npos) << md;
    EXPECT_EQ(md.find("| 0.00 | 6.25 |"), std::string::npos) << md;
}

TEST(BenchReport, BadCsvNamesTheLine) {
    std::string header = std::string(BENCH_CSV_HEADER_V2) + "\n";
    auto message = [](const std::string& text) {
        try {
            parseBenchCsv(text, "b.csv");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("method,kernel\n"),
              "b.csv:1: not a bench.csv header: expected '" + std::string(BENCH_CSV_HEADER) + "'");
    EXPECT_EQ(message(header + "nearest,0,256\n"), "b.csv:2: expected 15 fields, got 3");
    EXPECT_EQ(message(header + "blur,0,256,1,1,1,0,0,0,0,t,0,1,0,0\n"),
              "b.csv:2: unknown method 'blur'");
    EXPECT_EQ(message(header + "nearest,0,256,x,1,1,0,0,0,0,t,0,1,0,0\n"),
              "b.csv:2: field 4 'x' is not a number");
    EXPECT_EQ(message(header + "nearest,0,256,nan,1,1,0,0,0,0,t,0,1,0,0\n"),
              "b.csv:2: field 4 'nan' is not a number");
    EXPECT_EQ(message(header + "nearest,0,256,1,1,1,0,0,0,0,t,0,1,0,2\n"),
              "b.csv:2: field 15 '2' is not 0 or 1");
    // The header before the CPU times: its 27 fields, a weighting it knows.
    std::string v3 = std::string(BENCH_CSV_HEADER_V3) + "\n";
    const std::string head = "nearest,0,256,1,1,1,0,0,0,0,t,0,1,0,0,";
    EXPECT_EQ(message(v3 + head + "box,0,0,0,10,0,0,10,0,0,0,0\n").substr(0, 8), "no error");
    EXPECT_EQ(message(v3 + head + "sharp,0,0,0,10,0,0,10,0,0,0,0\n"),
              "b.csv:2: unknown weights 'sharp'");
    EXPECT_EQ(message(v3 + head + "box,0,0,0,1.5,0,0,10,0,0,0,0\n"),
              "b.csv:2: field 20 '1.5' is not a whole number");
    EXPECT_EQ(message(v3 + "nearest,0,256,1,1,1,0,0,0,0,t,0,1,0,0\n"),
              "b.csv:2: expected 27 fields, got 15");
    // The header before the renderer: 29 fields, the last two the passes' CPU time.
    std::string v4 = std::string(BENCH_CSV_HEADER_V4) + "\n";
    const std::string row27 = head + "box,0,0,0,10,0,0,10,0,0,0,0";
    EXPECT_EQ(message(v4 + row27 + "\n"), "b.csv:2: expected 29 fields, got 27");
    std::vector<BenchRow> cpu = parseBenchCsv(v4 + row27 + ",12.5,4.25\n", "b.csv");
    ASSERT_EQ(cpu.size(), 1u);
    EXPECT_EQ(cpu[0].gpuCpuMs, 12.5);
    EXPECT_EQ(cpu[0].lookupCpuMs, 4.25);
    EXPECT_EQ(parseBenchCsv(v3 + row27 + "\n", "b.csv")[0].gpuCpuMs, 0.0);
    EXPECT_EQ(cpu[0].glRenderer, "");  // not recorded before the current header
    // The header before the contact columns: 30 fields, the last the renderer.
    std::string v5 = std::string(BENCH_CSV_HEADER_V5) + "\n";
    EXPECT_EQ(message(v5 + row27 + ",12.5,4.25\n"), "b.csv:2: expected 30 fields, got 29");
    std::vector<BenchRow> named =
        parseBenchCsv(v5 + row27 + ",12.5,4.25,NVIDIA H200/PCIe/SSE2\n", "b.csv");
    ASSERT_EQ(named.size(), 1u);
    EXPECT_EQ(named[0].glRenderer, "NVIDIA H200/PCIe/SSE2");
    EXPECT_EQ(named[0].contact.edgePixels, 0);
    // The header before the truth: 32 fields, the last two the edge error near the contacts.
    std::string v6 = std::string(BENCH_CSV_HEADER_V6) + "\n";
    const std::string row30 = row27 + ",12.5,4.25,llvmpipe";
    EXPECT_EQ(message(v6 + row30 + "\n"), "b.csv:2: expected 32 fields, got 30");
    std::vector<BenchRow> contact = parseBenchCsv(v6 + row30 + ",0.125,640\n", "b.csv");
    ASSERT_EQ(contact.size(), 1u);
    EXPECT_EQ(contact[0].contact.edgeRmse, 0.125);
    EXPECT_EQ(contact[0].contact.edgePixels, 640);
    EXPECT_EQ(contact[0].truth, "");
    EXPECT_EQ(message(v6 + row30 + ",0.125,6.5\n"),
              "b.csv:2: field 32 '6.5' is not a whole number");
    // The header before the CPU spreads: 34 fields, the last two the truth and the contact
    // distance.
    std::string v7 = std::string(BENCH_CSV_HEADER_V7) + "\n";
    const std::string row32 = row30 + ",0.125,640";
    EXPECT_EQ(message(v7 + row32 + "\n"), "b.csv:2: expected 34 fields, got 32");
    std::vector<BenchRow> truth =
        parseBenchCsv(v7 + row32 + ",area (a sun disk of 2 degrees),1.5\n", "b.csv");
    ASSERT_EQ(truth.size(), 1u);
    EXPECT_EQ(truth[0].truth, "area (a sun disk of 2 degrees)");
    EXPECT_EQ(truth[0].contactDistance, 1.5);
    EXPECT_EQ(message(v7 + row32 + ",hard,near\n"), "b.csv:2: field 34 'near' is not a number");
    EXPECT_EQ(truth[0].gpuCpuMsIqr, 0.0);  // no spread recorded before the current header
    // The current header: 36 fields, the last two the CPU times' interquartile ranges.
    std::string v8 = std::string(BENCH_CSV_HEADER) + "\n";
    const std::string row34 = row32 + ",area (a sun disk of 2 degrees),1.5";
    EXPECT_EQ(message(v8 + row34 + "\n"), "b.csv:2: expected 36 fields, got 34");
    std::vector<BenchRow> spread = parseBenchCsv(v8 + row34 + ",0.75,0.25\n", "b.csv");
    ASSERT_EQ(spread.size(), 1u);
    EXPECT_EQ(spread[0].gpuCpuMsIqr, 0.75);
    EXPECT_EQ(spread[0].lookupCpuMsIqr, 0.25);
    EXPECT_EQ(message(v8 + row34 + ",0.75,-1\n"),
              "b.csv:2: field 36 '-1' is negative; it is a measure, 0 or more");
    // The eleven columns from before the timing spreads still read, with no spread.
    std::string v1 = std::string(BENCH_CSV_HEADER_V1) + "\n";
    EXPECT_EQ(message(v1 + "nearest,0,256,1,1,1,0,0,0,0,t,0,1,0,0\n"),
              "b.csv:2: expected 11 fields, got 15");
    std::vector<BenchRow> old = parseBenchCsv(v1 + "nearest,0,256,1.5,1,1,0,0,0,0,t\n", "b.csv");
    ASSERT_EQ(old.size(), 1u);
    EXPECT_EQ(old[0].gpuMs, 1.5);
    EXPECT_EQ(old[0].gpuMsIqr, 0.0);
    EXPECT_FALSE(old[0].noisy);
    EXPECT_EQ(message(""), "b.csv:1: empty file: expected a bench.csv header");
    // Found by the chart_csv fuzz target: a kernel of 6.7e122 was cast to int (undefined
    // behaviour). Counts and sizes must be whole numbers an int holds.
    EXPECT_EQ(message(header + "pcf-naive,6.66667e+122,256,1,1,1,0,0,0,0,t,0,1,0,0\n"),
              "b.csv:2: field 2 '6.66667e+122' is not a whole number");
    EXPECT_EQ(message(header + "nearest,0,1e10,1,1,1,0,0,0,0,t,0,1,0,0\n"),
              "b.csv:2: field 3 '1e10' is not a whole number");
    EXPECT_EQ(message(header + "nearest,0,256,1,1,2.5,0,0,0,0,t,0,1,0,0\n"),
              "b.csv:2: field 6 '2.5' is not a whole number");
}

}  // namespace
}  // namespace pcf
