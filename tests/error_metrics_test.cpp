// Error metrics, difference images, the Pareto front, the bench's CSV and table, and the chart's
// layout and drawing, on small hand-made inputs whose answers are known.
#include "measure/error_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <sstream>

#include "charts/chart_axes.h"
#include "charts/speed_chart.h"
#include "charts/step_chart.h"
#include "kernel/methods.h"
#include "measure/bench_report.h"
#include "measure/difference_image.h"
#include "measure/pareto.h"
#include "render/gl_context.h"
#include "speed_chart_checks.h"

namespace pcf {
namespace {

// A W x H truth, every pixel a light-facing receiver, visibility 1, except what the test sets.
GroundTruth flatTruth(int w, int h) {
    GroundTruth t;
    t.size = {w, h};
    t.spp = 4;
    t.visibility.assign(t.pixelCount(), 1.0f);
    t.receiver.assign(t.pixelCount(), 1);
    t.facesLight.assign(t.pixelCount(), 1);
    return t;
}

TEST(ErrorMetrics, ComparesOnlyLightFacingReceiversTheRendererDrew) {
    GroundTruth t = flatTruth(4, 1);
    t.receiver[1] = 0;    // background or a non-receiver
    t.facesLight[2] = 0;  // turned away from the light: dark by shading
    t.visibility[2] = 0.0f;
    std::vector<uint8_t> rendered = {1, 1, 1, 0};  // the mesh left pixel 3 to another object
    ErrorRegions r = errorRegions(t, rendered);
    EXPECT_EQ(r.compared, (std::vector<uint8_t>{1, 0, 0, 0}));
    EXPECT_EQ(r.comparedCount, 1);
    // A raw PCF result of 1 on the face turned away is no error: that pixel is not compared.
    ErrorStats s = measureError(t, r, std::vector<float>{0.5f, 0.0f, 1.0f, 0.0f});
    EXPECT_EQ(s.pixels, 1);
    EXPECT_DOUBLE_EQ(s.rmse, 0.5);
    EXPECT_DOUBLE_EQ(s.maxErr, 0.5);
}

TEST(ErrorMetrics, RmseAndMaxOverAllAndOverTheEdgeBand) {
    // One row of 12: shadow (0) on the left, a penumbra pixel at 5, lit (1) on the right.
    GroundTruth t = flatTruth(12, 1);
    for (int x = 0; x < 5; ++x) t.visibility[x] = 0.0f;
    t.visibility[5] = 0.5f;
    ErrorRegions r = errorRegions(t);
    // The band: pixel 5 dilated by 2 -> 3..7.
    std::vector<uint8_t> band(12, 0);
    for (int x = 3; x <= 7; ++x) band[x] = 1;
    EXPECT_EQ(r.edge, band);
    EXPECT_EQ(r.edgeCount, 5);

    std::vector<float> v = t.visibility;
    v[0] = 0.3f;  // outside the band
    v[4] = 0.2f;  // inside
    v[6] = 0.6f;  // inside: e = -0.4
    ErrorStats s = measureError(t, r, v);
    EXPECT_EQ(s.pixels, 12);
    EXPECT_EQ(s.edgePixels, 5);
    EXPECT_NEAR(s.rmse, std::sqrt((0.09 + 0.04 + 0.16) / 12.0), 1e-7);
    EXPECT_NEAR(s.maxErr, 0.4, 1e-7);
    EXPECT_NEAR(s.edgeRmse, std::sqrt((0.04 + 0.16) / 5.0), 1e-7);
    EXPECT_NEAR(s.edgeMaxErr, 0.4, 1e-7);
}

TEST(ErrorMetrics, EdgeBandIsAFiveByFiveSquareAroundEachCrossedPixel) {
    GroundTruth t = flatTruth(9, 9);
    t.visibility[t.index(4, 4)] = 0.25f;
    ErrorRegions r = errorRegions(t);
    EXPECT_EQ(r.edgeCount, 25);
    for (int y = 0; y < 9; ++y) {
        for (int x = 0; x < 9; ++x) {
            bool in = std::abs(x - 4) <= 2 && std::abs(y - 4) <= 2;
            EXPECT_EQ(r.edge[t.index(x, y)], in ? 1 : 0) << x << ", " << y;
        }
    }
    // A truth with no partial pixel has no band, and its edge errors are 0.
    ErrorRegions none = errorRegions(flatTruth(5, 5));
    EXPECT_EQ(none.edgeCount, 0);
    ErrorStats s = measureError(flatTruth(5, 5), none, std::vector<float>(25, 0.0f));
    EXPECT_DOUBLE_EQ(s.edgeRmse, 0.0);
    EXPECT_DOUBLE_EQ(s.rmse, 1.0);
}

TEST(ErrorMetrics, RefusesImagesOfAnotherSize) {
    GroundTruth t = flatTruth(4, 4);
    ErrorRegions r = errorRegions(t);
    EXPECT_THROW(measureError(t, r, std::vector<float>(15, 1.0f)), std::invalid_argument);
    EXPECT_THROW(errorRegions(t, std::vector<uint8_t>(3, 1)), std::invalid_argument);
}

TEST(DifferenceImage, BlueNegativeWhiteZeroRedPositive) {
    EXPECT_EQ(signedErrorColour(0.0f), glm::u8vec4(255, 255, 255, 255));
    EXPECT_EQ(signedErrorColour(1.0f), glm::u8vec4(255, 0, 0, 255));
    EXPECT_EQ(signedErrorColour(-1.0f), glm::u8vec4(0, 0, 255, 255));
    EXPECT_EQ(signedErrorColour(0.5f), glm::u8vec4(255, 128, 128, 255));
    EXPECT_EQ(signedErrorColour(-3.0f), glm::u8vec4(0, 0, 255, 255));  // clamped
    EXPECT_EQ(signedErrorColour(0.25f, 0.5f), glm::u8vec4(255, 128, 128, 255));

    GroundTruth t = flatTruth(3, 1);
    t.receiver[2] = 0;
    ErrorRegions r = errorRegions(t);
    std::vector<uint8_t> img = differenceImage(t, r, std::vector<float>{0.0f, 1.0f, 0.0f});
    ASSERT_EQ(img.size(), 12u);
    EXPECT_EQ(glm::u8vec4(img[0], img[1], img[2], img[3]), glm::u8vec4(0, 0, 255, 255));
    EXPECT_EQ(glm::u8vec4(img[4], img[5], img[6], img[7]), glm::u8vec4(255, 255, 255, 255));
    EXPECT_EQ(glm::u8vec4(img[8], img[9], img[10], img[11]), DIFFERENCE_BACKGROUND);
}

TEST(Pareto, KeepsExactlyThePointsNothingBeatsOnBothCounts) {
    std::vector<glm::dvec2> pts = {
        {1.0, 0.9},  // 0: fastest
        {2.0, 0.5},  // 1: front
        {2.0, 0.7},  // 2: same time as 1, worse
        {3.0, 0.5},  // 3: slower than 1, same error: dominated
        {4.0, 0.2},  // 4: front
        {5.0, 0.3},  // 5: dominated by 4
        {4.0, 0.2},  // 6: a tie with 4: both stay
        {8.0, 0.1},  // 7: most accurate
    };
    EXPECT_EQ(paretoFront(pts), (std::vector<size_t>{0, 1, 4, 6, 7}));
    EXPECT_TRUE(paretoFront(std::vector<glm::dvec2>{}).empty());
    // With a tolerance, an error better by a hair does not put a slower point on the front.
    std::vector<glm::dvec2> hair = {{1.0, 0.5}, {2.0, 0.5 - 1e-9}, {3.0, 0.4}, {3.0, 0.4 + 1e-9}};
    EXPECT_EQ(paretoFront(hair), (std::vector<size_t>{0, 1, 2}));
    EXPECT_EQ(paretoFront(hair, 1e-6), (std::vector<size_t>{0, 2, 3}));
}

std::vector<BenchRow> sampleRows() {
    std::vector<BenchRow> rows;
    auto add = [&](int method, int kernel, int map, double ms, double edge) {
        BenchRow r;
        r.point = {method, kernel, map};
        r.gpuMs = ms;
        r.cpuNsPerPixel = 12.345;
        r.texelReads = fetchCounts(method, kernel > 0 ? kernel : 3).texels;
        r.error.rmse = edge / 10;
        r.error.maxErr = 1.0;
        r.error.edgeRmse = edge;
        r.error.edgeMaxErr = 0.75;
        r.timer = "glFinish+steady_clock";
        r.gpuMsIqr = ms / 20;  // 5 %
        r.lookupMs = ms / 2;
        r.lookupMsIqr = ms / 4;  // 50 %: noisy
        r.noisy = method == PCF_POISSON;
        if (r.noisy) r.gpuMsIqr = ms / 4;  // the scene time too: a wide bar on either chart
        r.glRenderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
        rows.push_back(r);
    };
    add(PCF_NEAREST, 0, 256, 2.0, 0.5);
    add(PCF_GATHER, 3, 256, 7.5, 0.3);
    add(PCF_NAIVE, 3, 256, 18.0, 0.3);
    add(PCF_TENT, 5, 1024, 11.0, 0.12345678912);
    add(PCF_POISSON, 0, 1024, 130.0, 0.2);
    return rows;
}

TEST(BenchReport, CsvHasTheDocumentedColumnsAndOneLinePerRow) {
    std::vector<BenchRow> rows = sampleRows();
    std::string csv = benchCsv(rows);
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line,
              "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,"
              "edge_rmse,edge_max_err,timer,gpu_ms_iqr,lookup_ms,lookup_ms_iqr,noisy,weights,sigma,"
              "acne_share,acne_darkening,acne_pixels,leak_share,leak_mean,leak_pixels,"
              "shimmer_mean,shimmer_p99,flicker_share,change_mean,gpu_cpu_ms,lookup_cpu_ms,"
              "gl_renderer,contact_edge_rmse,contact_edge_pixels,truth,contact_distance,"
              "gpu_cpu_ms_iqr,lookup_cpu_ms_iqr");
    std::getline(in, line);
    EXPECT_EQ(line,
              "nearest,0,256,2.0000,12.35,1,0.05,1,0.5,0.75,glFinish+steady_clock,0.1000,1.0000,"
              "0.5000,0,box,0,0,0,0,0,0,0,0,0,0,0,0.0000,0.0000,llvmpipe (LLVM 15.0.6; 256 bits),0,"
              "0,,0,0.0000,0.0000");
    int lines = 2;
    while (std::getline(in, line)) {
        ++lines;
        EXPECT_EQ(std::count(line.begin(), line.end(), ','), 35) << line;
    }
    EXPECT_EQ(lines, 1 + static_cast<int>(rows.size()));
    EXPECT_NE(csv.find("tent,5,1024,11.0000,12.35,36,0.0123456789,1,0.123456789,0.75,"),
              std::string::npos)
        << csv;
}

TEST(BenchReport, MarkdownNamesTheMachineAndTimerAndMarksTheFront) {
    std::vector<BenchRow> rows = sampleRows();
    BenchSetup setup;
    setup.sceneName = "box-on-plane";
    setup.glRenderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    setup.glVersion = "4.5";
    setup.frameSize = {1280, 720};
    setup.gpuRepeats = 5;
    std::string md = benchMarkdown(rows, setup);
    EXPECT_NE(md.find("llvmpipe (LLVM 15.0.6, 256 bits)"), std::string::npos);
    EXPECT_NE(md.find("glFinish+steady_clock"), std::string::npos);
    EXPECT_NE(md.find("| nearest * | - | 256 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| pcf-gather * | 3 | 256 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| pcf-naive | 3 | 256 |"), std::string::npos) << md;  // dominated
    EXPECT_NE(md.find("| tent * | 5 | 1024 |"), std::string::npos) << md;
    EXPECT_EQ(benchParetoFront(rows), (std::vector<size_t>{0, 1, 3}));
    // Both times and their IQRs are in the table; the noisy poisson row is marked.
    EXPECT_NE(md.find("| 2.000 | 0.100 | 1.000 | 0.500 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| poisson ! | - | 1024 |"), std::string::npos) << md;
    // Load above half the cores as the bench began: the machine was busy. The note comes
    // first, with both loads and the noisy share.
    setup.loadStart = 3.5;
    setup.loadEnd = 0.25;
    setup.cores = 2;
    EXPECT_TRUE(benchMachineBusy(setup));
    EXPECT_DOUBLE_EQ(noisyShare(rows), 0.2);
    md = benchMarkdown(rows, setup);
    size_t note = md.find("The machine was busy when the bench began.");
    ASSERT_NE(note, std::string::npos) << md;
    EXPECT_LT(note, md.find("Measured on"));
    EXPECT_NE(md.find("3.50 at the start and 0.25 at the end (which counts the bench's own "
                      "rasteriser threads), on 2 cores; 1 of 5 points (20 %)"),
              std::string::npos)
        << md;
    // A quiet start with the bench's own load at the end: not busy, but a noisy point still gets
    // its note, which then does not call the machine busy.
    setup.loadStart = 0.5;
    setup.loadEnd = 2.0;
    EXPECT_FALSE(benchMachineBusy(setup));
    EXPECT_TRUE(benchTimingNote(rows, setup));
    md = benchMarkdown(rows, setup);
    EXPECT_EQ(md.find("busy"), std::string::npos) << md;
    EXPECT_NE(md.find("**Noisy timings.** 1-minute load average 0.50 at the start and 2.00"),
              std::string::npos)
        << md;
    // Quiet: no noisy point, load below half the cores at the start: no note.
    for (BenchRow& r : rows) r.noisy = false;
    EXPECT_FALSE(benchTimingNote(rows, setup));
    EXPECT_EQ(benchMarkdown(rows, setup).find("Noisy timings"), std::string::npos);
}

TEST(SpeedChart, LayoutPutsTimeOnALogAxisAndErrorOnALinearOne) {
    std::vector<BenchRow> rows = sampleRows();
    SpeedChartLayout L = layoutSpeedChart(rows, {1280, 720});
    ASSERT_EQ(L.points.size(), rows.size());
    for (size_t k = 0; k < rows.size(); ++k) {
        EXPECT_TRUE(L.plot.contains(L.points[k])) << k;
        EXPECT_EQ(L.labelTexts[k], chartLabel(rows[k].point));  // noisy or not: no mark
        // The error bar spans the IQR around the median: median -/+ IQR / 2 on the log axis.
        EXPECT_LT(L.errorBars[k].x, L.points[k].x) << k;
        EXPECT_GT(L.errorBars[k].y, L.points[k].x) << k;
    }
    // Log x: equal ratios of time are equal distances (2 -> 18 ms is 9x, as 11 -> 99 would be).
    double pxPerDecade = (L.points[2].x - L.points[0].x) / std::log10(18.0 / 2.0);
    EXPECT_NEAR((L.points[4].x - L.points[3].x) / std::log10(130.0 / 11.0), pxPerDecade, 0.01);
    // Linear y from 0 at the bottom: error 0.3 sits 0.6 of the way to 0.5's height.
    float base = L.plot.bottom();
    EXPECT_NEAR((base - L.points[1].y) / (base - L.points[0].y), 0.6, 1e-4);
    EXPECT_DOUBLE_EQ(L.yLo, 0.0);
    // Ticks at 1, 2, 5 x 10^k inside the range: 2 .. 130 ms holds 2, 5, 10, 20, 50, 100.
    std::vector<std::string> texts;
    for (const ChartTick& t : L.xTicks) texts.push_back(t.text);
    for (const char* want : {"2", "5", "10", "20", "50", "100"}) {
        EXPECT_NE(std::find(texts.begin(), texts.end(), want), texts.end()) << want;
    }
    EXPECT_EQ(L.front, (std::vector<size_t>{0, 1, 3}));
    // log10(1.025 / 0.975) of a decade: the 5 % IQR of every sample row.
    double barPx = pxPerDecade * std::log10(1.025 / 0.975);
    EXPECT_NEAR(L.errorBars[0].y - L.errorBars[0].x, barPx, 0.01);
    // The lookup timing: half the time, so every dot sits log10(2) of a decade further left
    // relative to the slowest one, and the bars are the lookup's wider IQR.
    SpeedChartLayout lookup = layoutSpeedChart(rows, {1280, 720}, ChartTiming::Lookup);
    EXPECT_GT(lookup.errorBars[0].y - lookup.errorBars[0].x,
              5.0f * (L.errorBars[0].y - L.errorBars[0].x));
    EXPECT_EQ(chartMs(rows[2], ChartTiming::Lookup), 9.0);
    EXPECT_EQ(chartIqr(rows[2], ChartTiming::Scene), 18.0 / 20);
    EXPECT_EQ(chartLabel({PCF_GATHER, 3, 1024}), "gather3 1024");
    EXPECT_EQ(chartLabel({PCF_NEAREST, 0, 256}), "nearest 256");
    // Few points, room to spare: no two labels overlap and none covers a dot.
    for (size_t a = 0; a < L.labels.size(); ++a) {
        for (size_t b = a + 1; b < L.labels.size(); ++b) {
            EXPECT_TRUE(L.labels[a].intersect(L.labels[b]).empty()) << a << " " << b;
        }
        for (glm::vec2 p : L.points) EXPECT_FALSE(L.labels[a].contains(p)) << a;
    }
}

// The shipped chart's 72 dots in a lesson's scene panel (617 x 347 at 1280x720 presentation):
// the ringed dots (gather3 at every map size) are the ones the chart must name, each by a name
// beside it or, where none fits, a numbered badge with its name in the key; any other dot is
// named only where a clean spot lies right beside it, so fewer are on the small chart; the
// front's names give way to the ringed. Where nothing is ringed, the front's are named.
TEST(SpeedChart, ACrowdedChartNamesTheRingedDotsBesideThemOrByBadge) {
    std::ifstream in(PCFSCOPE_SOURCE_DIR "/lessons/figures/bench.csv");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<BenchRow> rows = parseBenchCsv(text, "bench.csv");
    ASSERT_GT(rows.size(), 40u);
    std::vector<size_t> gather3 = chartRowsMatching(rows, "gather3");
    ASSERT_EQ(gather3.size(), 4u);
    std::map<int, size_t> shownAt;
    for (glm::ivec2 size : {glm::ivec2(617, 347), glm::ivec2(1280, 720)}) {
        // (The small chart with a projector's 18 px type, as a lesson frame draws it.)
        SpeedChartLayout L =
            layoutSpeedChart(rows, size, ChartTiming::Scene, ChartAccuracy::EdgeRmse, gather3,
                             size.x == 617 ? 18.0f : 8.0f);
        EXPECT_EQ(L.mustName, gather3) << size.x;
        for (size_t k : gather3) {
            EXPECT_TRUE(L.labelShown[k] || L.badge[k] > 0) << size.x << ": gather3 " << k;
        }
        // Each name and badge beside its own dot, off the bars; each dot's time near a tick.
        for (const std::string& f : speedChartLabelFaults(L)) ADD_FAILURE() << size.x << ": " << f;
        for (const std::string& f : speedChartTickFaults(L)) ADD_FAILURE() << size.x << ": " << f;
        shownAt[size.x] =
            static_cast<size_t>(std::count(L.labelShown.begin(), L.labelShown.end(), true));
    }
    EXPECT_LT(shownAt[617], shownAt[1280]) << "room decides how many of the rest are named";
    EXPECT_LT(shownAt[617], rows.size()) << "a crowded chart drops names";
    SpeedChartLayout plain = layoutSpeedChart(rows, {1280, 720});
    EXPECT_EQ(plain.mustName, plain.front);
    for (const std::string& f : speedChartLabelFaults(plain)) ADD_FAILURE() << f;
}

// A crowd too dense for names: 8 ringed runs in a line, each a few dot diameters from the next,
// named at a projector's 18 px. Every one gets a name beside it or a badge touching it, none on
// another dot, and the key lists the badges in the order of their dots' times, each with its
// dot's name.
TEST(SpeedChart, ACrowdTooDenseForNamesGetsNumberedBadgesAndAKey) {
    std::vector<BenchRow> rows;
    for (int i = 0; i < 8; ++i) {  // a line of dots up and to the right, ~30 px apart
        BenchRow r;
        r.point.method = PCF_GATHER;
        r.point.kernel = 3;
        r.point.mapSize = 64 * (i + 1);
        r.gpuMs = 10.0 * std::pow(1.25, i);
        r.error.edgeRmse = 0.1 + 0.03 * i;
        rows.push_back(r);
    }
    std::vector<size_t> all(rows.size());
    for (size_t k = 0; k < all.size(); ++k) all[k] = k;
    SpeedChartLayout L = layoutSpeedChart(rows, {617, 347}, ChartTiming::Scene,
                                          ChartAccuracy::EdgeRmse, all, 18.0f, true);
    for (const std::string& f : speedChartLabelFaults(L)) ADD_FAILURE() << f;
    ASSERT_GE(L.keyRows.size(), 2u) << "a crowd this dense has badges";
    for (size_t i = 1; i < L.keyRows.size(); ++i) {
        EXPECT_LE(L.points[L.keyRows[i - 1]].x, L.points[L.keyRows[i]].x) << "key in time order";
    }
    std::vector<ChartTextBox> boxes = speedChartTextBoxes(L, SpeedChartText{});
    for (size_t i = 0; i < L.keyRows.size(); ++i) {
        size_t row = L.keyRows[i];
        int numbers = 0, keyNames = 0;
        for (const ChartTextBox& b : boxes) {
            if (b.row != static_cast<int>(row)) continue;
            numbers += b.role == "chart-badge" && b.text == std::to_string(i + 1);
            keyNames += b.role == "chart-key" && b.text == L.labelTexts[row];
            EXPECT_NE(b.role, "chart-label") << "a badged dot has no name by it: " << row;
        }
        EXPECT_EQ(numbers, 2) << "the badge by the dot and in the key: " << row;
        EXPECT_EQ(keyNames, 1) << row;
        // The badge touches the dot's outer ring, or lies just beyond it.
        float gap = glm::length(L.badgeBoxes[row].centre() - L.points[row]) - L.badgeRadius -
                    speedChartMarkRadius(L, row);
        EXPECT_LE(gap, speedChartBadgeGap(L) + 1.0f) << row;
        EXPECT_GT(L.keyBadges[i].y, L.plot.bottom()) << "the key under the x axis: " << i;
        EXPECT_LE(L.keyBadges[i].bottom(), static_cast<float>(L.size.y)) << i;
    }
}

// Every dot is solid and named without a mark; the subtitle says what the bars through the dots
// are, wrapped to the chart's width; a chart whose times have no spread draws no bar and says
// nothing of bars. The legend states the front's rule.
TEST(SpeedChart, SubtitleSaysWhatTheBarsAre) {
    std::vector<BenchRow> rows = sampleRows();  // poisson 1024 is noisy
    EXPECT_EQ(spreadNote(),
              "bars: IQR of the repeated times, centred on the median; the front's line joins "
              "only dots whose bars are apart");
    SpeedChartText text;
    text.subtitle = "rendered on llvmpipe";
    auto unwrapped = [](std::string t) {
        std::replace(t.begin(), t.end(), '\n', ' ');
        return t;
    };
    SpeedChartLayout all = layoutSpeedChart(rows, {1280, 720});
    ASSERT_TRUE(all.labelShown[4]);
    EXPECT_EQ(all.labelTexts[4], "poisson 1024");
    // The bars' words on a line of their own.
    EXPECT_EQ(speedChartTextFor(rows, text, {1280, 720}).subtitle,
              "rendered on llvmpipe\n" + spreadNote());
    // Narrow: the same words, wrapped to lines that fit the chart.
    glm::ivec2 narrow{480, 270};  // a lesson frame's chart, at its 18 px type
    SpeedChartText big = text;
    big.minFontPx = 18.0f;
    SpeedChartText fitted = speedChartTextFor(rows, big, narrow);
    EXPECT_EQ(unwrapped(fitted.subtitle), "rendered on llvmpipe " + spreadNote());
    EXPECT_GT(subtitleLineCount(fitted.subtitle), 1);
    SpeedChartLayout small =
        layoutSpeedChart(rows, narrow, ChartTiming::Scene, ChartAccuracy::EdgeRmse, {}, 18.0f,
                         false, subtitleLineCount(fitted.subtitle));
    int frontLegends = 0;
    for (const ChartTextBox& b : speedChartTextBoxes(small, fitted)) {
        EXPECT_LE(b.rect.right(), narrow.x) << b.text;
        if (b.role == "chart-legend" && b.method == -1) {
            EXPECT_EQ(b.text, FRONT_LEGEND);
            ++frontLegends;
        }
    }
    EXPECT_EQ(frontLegends, 1);
    // No spread in the scene times: no bar, no note; the lookup times have theirs (50 %).
    std::vector<BenchRow> exact = rows;
    for (BenchRow& r : exact) r.gpuMsIqr = 0.0;
    EXPECT_EQ(speedChartTextFor(exact, text, {1280, 720}).subtitle, "rendered on llvmpipe");
    EXPECT_EQ(unwrapped(speedChartTextFor(exact, text, {1280, 720}, ChartTiming::Lookup).subtitle),
              "rendered on llvmpipe " + spreadNote());
}

// On a CPU rasteriser with CPU times recorded, the chart, the front and bench.md go by the
// process CPU time (issue 32: 17.4's wall clock put pcf-gather 7x7 left of 3x3 while its CPU time
// rose with the kernel); on a GPU, or without CPU times, by the wall clock or the GPU's timer. The
// CPU times' IQRs go through the CSV and back.
TEST(SpeedChart, ACpuRasterisersTimesAreItsCpuTime) {
    std::vector<BenchRow> rows(2);
    for (int k = 0; k < 2; ++k) {
        BenchRow& r = rows[k];
        r.point = {PCF_GATHER, k == 0 ? 3 : 7, 512};
        r.timer = "glFinish+steady_clock";
        r.glRenderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
        r.error.edgeRmse = k == 0 ? 0.15 : 0.10;
    }
    // The wall clock backwards (11.6 ms for 3x3, 8.5 for 7x7), the CPU time rising.
    rows[0].gpuMs = 11.6, rows[0].gpuMsIqr = 0.5, rows[0].gpuCpuMs = 6.3, rows[0].gpuCpuMsIqr = 0.2;
    rows[1].gpuMs = 8.5, rows[1].gpuMsIqr = 5.7, rows[1].gpuCpuMs = 9.2, rows[1].gpuCpuMsIqr = 0.4;
    rows[0].lookupMs = 8.0, rows[0].lookupCpuMs = 5.4, rows[0].lookupCpuMsIqr = 0.3;
    rows[1].lookupMs = 18.4, rows[1].lookupCpuMs = 11.3, rows[1].lookupCpuMsIqr = 0.6;
    EXPECT_TRUE(benchTimesByCpu(rows[0]));
    EXPECT_DOUBLE_EQ(chartMs(rows[0], ChartTiming::Scene), 6.3);
    EXPECT_DOUBLE_EQ(chartIqr(rows[1], ChartTiming::Scene), 0.4);
    EXPECT_DOUBLE_EQ(chartMs(rows[1], ChartTiming::Lookup), 11.3);
    EXPECT_DOUBLE_EQ(chartIqr(rows[0], ChartTiming::Lookup), 0.3);
    EXPECT_EQ(speedChartXLabel(rows, ChartTiming::Scene),
              "camera pass, process CPU time, ms (log scale)");
    // By CPU time 3x3 is the cheaper and 7x7 the more accurate: both on the front, 3x3 first,
    // and their bars (6.1-6.5 and 9.0-9.4 ms) apart: joined.
    SpeedChartLayout L = layoutSpeedChart(rows, {1280, 720});
    EXPECT_EQ(L.front, (std::vector<size_t>{0, 1}));
    EXPECT_LT(L.points[0].x, L.points[1].x);
    EXPECT_EQ(L.frontJoined, (std::vector<bool>{false, true}));
    EXPECT_FALSE(benchSpreadsOverlap(rows[0], rows[1], false));
    // Read back from the CSV, the same.
    std::vector<BenchRow> back = parseBenchCsv(benchCsv(rows), "cpu.csv");
    ASSERT_EQ(back.size(), 2u);
    EXPECT_DOUBLE_EQ(back[1].gpuCpuMsIqr, 0.4);
    EXPECT_DOUBLE_EQ(back[0].lookupCpuMsIqr, 0.3);
    EXPECT_DOUBLE_EQ(chartMs(back[1], ChartTiming::Scene), 9.2);
    // A GPU's rows go by their own timer, and so does a CPU rasteriser's file without CPU times.
    std::vector<BenchRow> gpu = rows;
    for (BenchRow& r : gpu) r.glRenderer = "NVIDIA H200/PCIe/SSE2";
    EXPECT_FALSE(benchTimesByCpu(gpu[0]));
    EXPECT_DOUBLE_EQ(chartMs(gpu[0], ChartTiming::Scene), 11.6);
    EXPECT_EQ(speedChartXLabel(gpu, ChartTiming::Scene), "camera pass, time, ms (log scale)");
    EXPECT_EQ(layoutSpeedChart(gpu, {1280, 720}).front, (std::vector<size_t>{1}));
    std::vector<BenchRow> old = rows;
    for (BenchRow& r : old) r.gpuCpuMs = r.lookupCpuMs = 0.0;
    EXPECT_DOUBLE_EQ(chartMs(old[0], ChartTiming::Scene), 11.6);
    BenchSetup setup;
    EXPECT_NE(benchMarkdown(rows, setup).find("Pareto front of scene process CPU time"),
              std::string::npos);
    EXPECT_NE(benchMarkdown(rows, setup).find("| 6.300 | 0.200 | 5.400 | 0.300 |"),
              std::string::npos)
        << benchMarkdown(rows, setup);
}

// A step of the front is a line only where the two dots' bars are apart: the line says the next
// dot costs more, which overlapping bars do not support (issue 32). The dots stay on the front,
// ringed.
TEST(SpeedChart, TheFrontsLineJoinsOnlyDotsWhoseBarsAreApart) {
    std::string csv = std::string(BENCH_CSV_HEADER_V2) + "\n";
    // method,kernel,map,gpu_ms,cpu_ns,reads,rmse,max,edge_rmse,edge_max,timer,iqr,lookup,iqr,noisy
    csv += "nearest,0,256,2,1,1,0,1,0.5,1,t,0.2,1,0.05,0\n";     // 1.9 to 2.1 ms
    csv += "hw2x2,0,256,2.3,1,1,0,1,0.4,1,t,0.6,1,0.05,0\n";     // 2.0 to 2.6: overlaps nearest
    csv += "pcf-gather,3,256,5,1,16,0,1,0.3,1,t,0.2,2,0.1,0\n";  // 4.9 to 5.1: apart
    csv += "tent,3,256,5.05,1,16,0,1,0.25,1,t,0.02,2,0.1,0\n";   // 5.04 to 5.06: inside gather's
    std::vector<BenchRow> rows = parseBenchCsv(csv, "front.csv");
    SpeedChartLayout L = layoutSpeedChart(rows, {1280, 720});
    EXPECT_EQ(L.front, (std::vector<size_t>{0, 1, 2, 3}));
    EXPECT_EQ(L.frontJoined, (std::vector<bool>{false, false, true, false}));
    EXPECT_TRUE(benchSpreadsOverlap(rows[0], rows[1], false));
    EXPECT_FALSE(benchSpreadsOverlap(rows[1], rows[2], false));
    EXPECT_TRUE(benchSpreadsOverlap(rows[2], rows[3], false));
}

// The front is the Pareto front of the medians over every dot: a noisy dot (a wide bar) that no
// dot beats on both median time and error is on it, in the chart, the table and a lesson's
// "front" highlight alike. Read from a CSV, as a lesson's chart is.
TEST(SpeedChart, TheFrontIsOfTheMediansOfEveryDot) {
    std::string csv = std::string(BENCH_CSV_HEADER_V2) + "\n";
    // method,kernel,map,gpu_ms,cpu_ns,reads,rmse,max,edge_rmse,edge_max,timer,iqr,lookup,iqr,noisy
    csv += "nearest,0,256,2,1,1,0,1,0.5,1,t,0.1,1,0.05,0\n";     // 0: beaten by 1 on both
    csv += "hw2x2,0,256,1,1,1,0,1,0.4,1,t,1.9,1,0.05,1\n";       // 1: noisy, 1 +- 0.95 ms
    csv += "pcf-gather,3,256,5,1,16,0,1,0.3,1,t,0.2,2,0.1,0\n";  // 2
    csv += "pcf-naive,3,256,8,1,36,0,1,0.2,1,t,4,4,0.2,1\n";     // 3: noisy
    csv += "tent,5,1024,20,1,36,0,1,0.1,1,t,1,10,0.5,0\n";       // 4: most accurate
    std::vector<BenchRow> rows = parseBenchCsv(csv, "noisy.csv");
    ASSERT_EQ(rows.size(), 5u);
    const std::vector<size_t> front{1, 2, 3, 4};
    EXPECT_EQ(benchParetoFront(rows), front);
    SpeedChartLayout L = layoutSpeedChart(rows, {1280, 720});
    EXPECT_EQ(L.front, front);
    EXPECT_EQ(L.labelTexts[1], "hw2x2 256");
    EXPECT_EQ(chartRowsMatching(rows, "front"), front);
    // The bar is as wide as the IQR, centred on the median: hw2x2's runs 0.05 to 1.95 ms, its
    // dot at 1 ms between (on the log axis, so not halfway in pixels).
    EXPECT_LT(L.errorBars[1].x, L.points[1].x);
    EXPECT_GT(L.errorBars[1].y, L.points[1].x);
    auto pixelOf = [&](double ms) {
        return L.plot.x +
               static_cast<float>((std::log10(ms) - L.xLogLo) / (L.xLogHi - L.xLogLo)) * L.plot.w;
    };
    EXPECT_NEAR(L.errorBars[1].y, pixelOf(1.95), 0.5f);
    EXPECT_NEAR(L.errorBars[1].x, pixelOf(0.1), 0.5f);  // the low end kept at a tenth of the median
    EXPECT_NEAR(L.errorBars[2].x, pixelOf(4.9), 0.5f);
    EXPECT_NEAR(L.errorBars[2].y, pixelOf(5.1), 0.5f);
    // The lookup times: nearest ties hw2x2's 1 ms and is less accurate: the same front.
    EXPECT_EQ(benchParetoFront(rows, true), front);
    BenchSetup setup;
    setup.glRenderer = "llvmpipe";
    std::string md = benchMarkdown(rows, setup);
    EXPECT_NE(md.find("| hw2x2 * ! |"), std::string::npos) << md;
    EXPECT_NE(md.find("| nearest | - |"), std::string::npos) << md;
    EXPECT_NE(md.find("| tent * | 5 |"), std::string::npos) << md;
}

// A lesson's orange rings (chart_highlight) mark the dots its words name, not a front: the legend
// says so, with an orange ring of its own, whenever they are drawn, and only then (16.6 ringed
// pcss, off the front, and nothing on the chart said what the ring meant).
TEST(SpeedChart, TheLegendNamesTheOrangeRings) {
    std::string csv = std::string(BENCH_CSV_HEADER_V2) + "\n";
    csv += "nearest,0,256,2,1,1,0,1,0.5,1,t,0.1,1,0.05,0\n";
    csv += "pcf-gather,3,256,5,1,16,0,1,0.3,1,t,0.2,2,0.1,0\n";
    csv += "tent,5,1024,20,1,36,0,1,0.1,1,t,1,10,0.5,0\n";
    std::vector<BenchRow> rows = parseBenchCsv(csv, "ringed.csv");
    ASSERT_EQ(rows.size(), 3u);
    auto entries = [&](const SpeedChartLayout& L) {
        int named = 0;
        std::vector<ChartTextBox> boxes = speedChartTextBoxes(L, SpeedChartText{});
        for (const ChartTextBox& b : boxes) {
            if (b.role != "chart-legend" || b.text != HIGHLIGHT_LEGEND) continue;
            ++named;
            // Its swatch on its line, clear of the words and inside the legend.
            for (const ChartTextBox& w : boxes) {
                if (w.role == "chart-swatch" && w.text == HIGHLIGHT_LEGEND) {
                    EXPECT_TRUE(w.rect.intersect(b.rect).empty());
                    EXPECT_TRUE(L.legend.contains(w.rect.centre()));
                    EXPECT_NEAR(w.rect.centre().y, b.rect.centre().y, 0.5f * b.rect.h);
                }
            }
        }
        return named;
    };
    const std::vector<size_t> ringed{0, 1};
    for (glm::ivec2 size : {glm::ivec2(1280, 720), glm::ivec2(480, 270)}) {
        EXPECT_EQ(entries(layoutSpeedChart(rows, size)), 0);
        SpeedChartLayout L =
            layoutSpeedChart(rows, size, ChartTiming::Scene, ChartAccuracy::EdgeRmse, ringed);
        EXPECT_EQ(entries(L), 1);
        EXPECT_LE(L.legend.bottom(), static_cast<float>(size.y));
    }
}

// A chart drawn from a CSV names the renderer the CSV records (a lesson's chart, from the
// shipped bench.csv: llvmpipe, with what carries over to a GPU), in its layout list; a CSV from
// before the renderer column says it was not recorded, and no renderer is made up.
TEST(SpeedChart, AChartFromACsvNamesItsRenderer) {
    auto subtitleOf = [](const std::string& chart, glm::ivec2 size) {
        std::string subtitle;
        for (const ChartTextBox& b : stepChartTexts(StepChart{chart, "", 18.0f, true}, size)) {
            if (b.role != "chart-subtitle") continue;
            subtitle += b.text;
            EXPECT_LE(b.rect.right(), size.x) << b.text;
        }
        // Read as one text: where a line wraps is the layout's business.
        std::replace(subtitle.begin(), subtitle.end(), '\n', ' ');
        return subtitle;
    };
    std::string shipped = PCFSCOPE_SOURCE_DIR "/lessons/figures/bench.csv";
    for (glm::ivec2 size : {glm::ivec2(617, 347), glm::ivec2(1280, 720)}) {
        std::string subtitle = subtitleOf(shipped, size);
        EXPECT_NE(subtitle.find("rendered on llvmpipe (LLVM 15.0.6; 256 bits)"), std::string::npos)
            << subtitle;
        EXPECT_NE(subtitle.find(LLVMPIPE_NOTE), std::string::npos) << subtitle;
    }
    EXPECT_EQ(LLVMPIPE_NOTE, "llvmpipe: a CPU rasteriser; a GPU's times, and their ratios, differ");
    std::string old = (std::filesystem::temp_directory_path() / "pcfscope-v4-bench.csv").string();
    {
        std::ofstream f(old);
        f << BENCH_CSV_HEADER_V4 << "\n"
          << "nearest,0,256,1,1,1,0,0,0,0,t,0,1,0,0,box,0,0,0,10,0,0,10,0,0,0,0,0,0\n";
    }
    std::string subtitle = subtitleOf(old, {1280, 720});
    std::filesystem::remove(old);
    EXPECT_NE(subtitle.find(RENDERER_UNKNOWN), std::string::npos) << subtitle;
    EXPECT_EQ(subtitle.find("rendered on"), std::string::npos) << subtitle;
}

TEST(SpeedChart, DrawsTheRequestedSizeWithEachMethodsColour) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    std::vector<BenchRow> rows = sampleRows();
    glm::ivec2 size{1280, 720};
    SpeedChartText text;
    text.title = "Speed against accuracy: test";
    text.subtitle = context->renderer();
    text.minFontPx = 24.0f;  // dots 6 px
    std::vector<uint8_t> rgba = drawSpeedChart(rows, size, text);
    ASSERT_EQ(rgba.size(), static_cast<size_t>(size.x) * size.y * 4);
    // Laid out as drawSpeedChart lays it out: with the subtitle's lines once wrapped.
    int subtitleLines = subtitleLineCount(speedChartTextFor(rows, text, size).subtitle);
    SpeedChartLayout L = layoutSpeedChart(rows, size, ChartTiming::Scene, ChartAccuracy::EdgeRmse,
                                          {}, text.minFontPx, false, subtitleLines);
    // Each dot is solid: 2 px below its centre (off the bar through it) is its method's colour,
    // the noisy poisson dot's too.
    for (size_t k = 0; k < rows.size(); ++k) {
        glm::ivec2 p(L.points[k]);
        size_t at = ((static_cast<size_t>(p.y) + 2) * size.x + p.x) * 4;
        glm::vec4 want = methodColour(rows[k].point.method) * 255.0f;
        EXPECT_NEAR(rgba[at + 0], want.r, 2.0) << k;
        EXPECT_NEAR(rgba[at + 1], want.g, 2.0) << k;
        EXPECT_NEAR(rgba[at + 2], want.b, 2.0) << k;
    }
    // The corner is the white background; the picture is not all one colour.
    EXPECT_EQ(glm::u8vec4(rgba[0], rgba[1], rgba[2], rgba[3]), glm::u8vec4(255, 255, 255, 255));
    size_t dark = 0;
    for (size_t k = 0; k < rgba.size(); k += 4) dark += rgba[k] < 100 && rgba[k + 1] < 100;
    EXPECT_GT(dark, 500u);  // text, axes, the front
}

// The chart `bench` writes, from the repository's own default run (lessons/figures/bench.csv):
// at the default 1280x720 every text is at least 14 px, inside the chart, and none overlaps
// another; the subtitle says the renderer and, for llvmpipe, what carries over.
TEST(SpeedChart, StandAloneTextIsAtLeast14PxWithoutOverlap) {
    std::ifstream in(std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/figures/bench.csv");
    std::string csv((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<BenchRow> rows = parseBenchCsv(csv, "bench.csv");
    ASSERT_GT(rows.size(), 10u);
    SpeedChartText text;
    text.title = "Speed against accuracy: box-on-plane, 1280x720";
    text.subtitle = chartRendererLine("llvmpipe (LLVM 15.0.6, 256 bits)") +
                    "\nmedian of 9 round-robin samples, glFinish+steady_clock; bars: IQR";
    text.minFontPx = STANDALONE_CHART_MIN_PX;
    const glm::ivec2 size{1280, 720};
    text = speedChartTextFor(rows, text, size);  // as drawSpeedChart draws it
    SpeedChartLayout L =
        layoutSpeedChart(rows, size, ChartTiming::Scene, ChartAccuracy::EdgeRmse, {},
                         text.minFontPx, false, subtitleLineCount(text.subtitle));
    std::vector<ChartTextBox> boxes = speedChartTextBoxes(L, text);
    std::string subtitle;
    int swatches = 0;
    for (const ChartTextBox& b : boxes) {
        // A legend's mark has no type (the pairs below keep it off every text, its own words too).
        if (b.role == "chart-swatch") {
            ++swatches;
            continue;
        }
        EXPECT_GE(b.fontPx, STANDALONE_CHART_MIN_PX) << b.role << " '" << b.text << "'";
        EXPECT_GE(b.rect.x, 0.0f) << b.text;
        EXPECT_LE(b.rect.right(), size.x) << b.text;
        EXPECT_LE(b.rect.bottom(), size.y) << b.text;
        if (b.role == "chart-subtitle") subtitle = b.text;
    }
    EXPECT_NE(subtitle.find(LLVMPIPE_NOTE), std::string::npos) << subtitle;
    EXPECT_EQ(swatches, static_cast<int>(L.legendMethods.size()) + 1);  // and the front's
    for (const std::string& f : speedChartLabelFaults(L)) ADD_FAILURE() << f;
    for (const std::string& f : speedChartTickFaults(L)) ADD_FAILURE() << f;
    for (size_t i = 0; i < boxes.size(); ++i) {
        for (size_t j = i + 1; j < boxes.size(); ++j) {
            // (Two legend marks with their clearances may touch: a column of marks.)
            if (boxes[i].role == "chart-swatch" && boxes[j].role == "chart-swatch") continue;
            EXPECT_TRUE(boxes[i].rect.intersect(boxes[j].rect).empty())
                << "'" << boxes[i].text << "' overlaps '" << boxes[j].text << "'";
        }
    }
}

}  // namespace
}  // namespace pcf
