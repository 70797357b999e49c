// The charts of `pcfscope stability` (stability_figures.h), read from their layout lists (the
// texts and where they go), not redrawn: each title states its population and metric and each
// subtitle the settings the rows were measured with (the renderer, and for llvmpipe what carries
// over); the shimmer bars all stand on the one edge population; coincident lines stay visible;
// the heat map carries its colour scale and map size; at the default chart size every text is
// at least 14 px and no two overlap.
#include "charts/stability_figures.h"

#include <gtest/gtest.h>

#include <cmath>

#include "charts/chart_axes.h"
#include "kernel/methods.h"
#include "measure/failure_measures.h"
#include "measure/stability_report.h"

namespace pcf {
namespace {

const std::string LLVMPIPE = "llvmpipe (LLVM 15.0.6, 256 bits)";
const glm::ivec2 CHART{1280, 720};  // `stability`'s default --chart-size

StabilitySetup setupOf(const std::string& renderer) {
    StabilitySetup s;
    s.sceneName = "box-on-plane";
    s.glRenderer = renderer;
    s.frameSize = {480, 270};
    s.mapSize = 512;
    s.truthSpp = 2;
    s.constantBias = 0.002;
    s.cull = "back";
    s.depthFormat = "32f";
    s.precisionElevation = 30;
    s.tradeoffElevation = 30;
    return s;
}

// Rows shaped like a default run's (its methods, biases and sweep points), with made-up values:
// pcf-gather 5x5's acne under "none" equals its "constant" line.
std::vector<StabilityRow> defaultShapedRows(const std::string& renderer) {
    StabilityOptions o;
    std::vector<StabilityRow> rows = stabilitySetupRows(setupOf(renderer));
    auto add = [&](const char* sweep, const StabilityMethod& m, BiasMode b, const char* xName,
                   double x, const std::string& metric, double y) {
        rows.push_back(
            {sweep, m.method, m.kernel, std::string(biasModeName(b)), xName, x, metric, y});
    };
    for (const StabilityMethod& m : o.methods) {
        for (BiasMode b : o.biases) {
            double k = static_cast<double>(b) + 1.0;
            bool twin = m.kernel == 5 && b == BiasMode::None;  // drawn as "constant"'s twin
            double kAcne = twin ? static_cast<double>(BiasMode::Constant) + 1.0 : k;
            for (float e : o.elevations) {
                add("acne", m, b, "elevation_deg", e, "false_shadow_rate",
                    std::min(1.0, kAcne * 0.1 * (90.0 - e) / 88.0));
            }
            for (const std::string& scene : o.leakScenes) {
                for (float bias : o.leakBiases) {
                    add("leak", m, b, "constant_bias", bias, scene + ":leak_width_texels",
                        k * std::log2(bias / 0.0004));
                    // Leak past 0.016: 2 % of the clean umbra at 0.032, 4 % at 0.064.
                    add("leak", m, b, "constant_bias", bias, scene + ":leak_rate",
                        bias > 0.02f ? bias * 0.625 : 0.0);
                }
            }
            // Acne at the trade-off's elevation: gone from 0.004 on (the wider filter: 0.008).
            for (float bias : o.leakBiases) {
                if (b != BiasMode::Constant) continue;
                float gone = m.kernel == 5 ? 0.006f : 0.003f;
                add("tradeoff", m, b, "constant_bias", bias, "false_shadow_rate",
                    bias < gone ? 0.9 : 0.0);
            }
            add("shimmer", m, b, "texel_step", 1.0 / 32, "light_flicker_p99", 0.9);
            add("shimmer", m, b, "texel_step", 1.0 / 32, "light_edge_mean", 0.004);
            add("shimmer", m, b, "texel_step", 1.0 / 32, "light_edge_peak_p99", 0.01 * k);
            add("shimmer", m, b, "texel_step", 1.0 / 32, "snapped_edge_peak_p99", 0.0);
            add("shimmer", m, b, "texel_step", 1.0 / 32, "light_edge_pixels", 2500);
            add("shimmer", m, b, "pixel_step", 1.0 / 6, "camera_edge_peak_p99", 0.02 * k);
            for (TexelKind f : o.depthFormats) {
                for (float r : o.depthRanges) {
                    add("precision", m, b, "depth_range", r,
                        "false_shadow_rate_d" + std::string(depthFormatName(f)),
                        std::min(1.0, 0.05 * k * std::log10(r)));
                }
            }
        }
    }
    for (int size : o.aliasingMapSizes) {
        rows.push_back({"aliasing", -1, 0, "-", "map_size", double(size), "pixels_per_texel_median",
                        1331.0 / size});
        rows.push_back({"aliasing", -1, 0, "-", "map_size", double(size), "pixels_per_texel_p99",
                        4070.0 / size});
    }
    return rows;
}

StabilityImage heatmap() {
    StabilityImage image{"aliasing_heatmap.png", {480, 270}, {}};
    image.rgba.assign(480 * 270 * 4, 200);
    return image;
}

std::string textOf(const std::vector<ChartTextBox>& boxes, const std::string& role) {
    std::string all;
    for (const ChartTextBox& b : boxes) {
        if (b.role == role) all += b.text + "\n";
    }
    return all;
}

struct NamedChart {
    std::string name;
    std::vector<ChartTextBox> boxes;
};

std::vector<NamedChart> allCharts(const std::vector<StabilityRow>& rows, float minPx) {
    const std::string source = "pcfscope stability";
    return {{"acne", lineChartTextBoxes(acneChartSpec(rows, source, minPx), CHART)},
            {"leak", lineChartTextBoxes(leakChartSpec(rows, source, minPx), CHART)},
            {"tradeoff", lineChartTextBoxes(tradeoffChartSpec(rows, source, minPx), CHART)},
            {"precision", lineChartTextBoxes(precisionChartSpec(rows, source, minPx), CHART)},
            {"shimmer", barChartTextBoxes(shimmerChartSpec(rows, source, minPx), CHART)},
            {"aliasing",
             imageChartTextBoxes(aliasingHeatmapSpec(heatmap(), rows, source, minPx), CHART)}};
}

TEST(StabilityFigures, TitlesStateThePopulationAndSubtitlesTheSettingsAndRenderer) {
    std::vector<StabilityRow> rows = defaultShapedRows(LLVMPIPE);
    std::vector<NamedChart> charts = allCharts(rows, STANDALONE_CHART_MIN_PX);
    // The population each title names.
    const char* populations[] = {"clean-lit receivers",
                                 "leaking pixels",
                                 "clean pixels",
                                 "clean-lit receivers",
                                 "the same 2500 pixels for every bar",
                                 "at each pixel, map 512^2"};
    for (size_t i = 0; i < charts.size(); ++i) {
        SCOPED_TRACE(charts[i].name);
        std::string title = textOf(charts[i].boxes, "chart-title");
        std::string subtitle = textOf(charts[i].boxes, "chart-subtitle");
        EXPECT_NE(title.find(populations[i]), std::string::npos) << title;
        EXPECT_NE(subtitle.find("480x270 frame, map 512^2"), std::string::npos) << subtitle;
        // The heat map depends on no bias, culling or depth format, and names none.
        bool biasSettings = subtitle.find("cull back, depth 32f") != std::string::npos;
        EXPECT_EQ(biasSettings, charts[i].name != "aliasing") << subtitle;
        EXPECT_NE(subtitle.find("rendered on llvmpipe (LLVM 15.0.6; 256 bits)"), std::string::npos)
            << subtitle;
        EXPECT_NE(subtitle.find(LLVMPIPE_NOTE), std::string::npos) << subtitle;
        // The leak and trade-off charts sweep the constant bias: their subtitles name no single
        // value of it.
        bool oneBias = subtitle.find("constant bias 0.002") != std::string::npos;
        bool swept = charts[i].name == "leak" || charts[i].name == "tradeoff";
        EXPECT_EQ(oneBias, !swept && charts[i].name != "aliasing") << subtitle;
    }
    // Panels name the kernel; the leak's title names the run length that counts.
    EXPECT_NE(textOf(charts[0].boxes, "chart-title").find("pcf-gather 5x5"), std::string::npos);
    EXPECT_NE(textOf(charts[1].boxes, "chart-title")
                  .find("runs of " + std::to_string(LEAK_MIN_RUN) + "+ leaking pixels"),
              std::string::npos);
    // On a GPU the note about llvmpipe goes.
    std::vector<StabilityRow> gpu = defaultShapedRows("NVIDIA H200/PCIe/SSE2");
    std::string subtitle =
        textOf(lineChartTextBoxes(acneChartSpec(gpu, "x", 14.0f), CHART), "chart-subtitle");
    EXPECT_NE(subtitle.find("rendered on NVIDIA H200/PCIe/SSE2"), std::string::npos) << subtitle;
    EXPECT_EQ(subtitle.find("llvmpipe"), std::string::npos) << subtitle;
    // Rows without setup (an older CSV): the subtitle is the source alone, claiming nothing.
    std::vector<StabilityRow> bare(rows.begin() + stabilitySetupRows(setupOf("")).size(),
                                   rows.end());
    EXPECT_EQ(acneChartSpec(bare, "measured by pcfscope stability").subtitle,
              "measured by pcfscope stability");
}

// The trade-off chart puts acne (at one elevation) and leak on one bias axis, and shades the
// biases where both stay under 1 %: "a good bias sits between the two curves" is what it shows.
TEST(StabilityFigures, TheTradeOffShadesTheBiasesBetweenAcneAndLeak) {
    std::vector<StabilityRow> rows = defaultShapedRows(LLVMPIPE);
    std::vector<TradeoffSeries> series = tradeoffSeries(rows);
    ASSERT_EQ(series.size(), 2u);  // nearest, pcf-gather 5x5
    EXPECT_EQ(series[1].name, "pcf-gather 5x5");
    // Swept biases 0.0005 .. 0.064: acne gone from 0.008 (5x5; nearest from 0.004), leak from
    // 0.032: the good biases run 0.008 .. 0.016 (nearest 0.004 .. 0.016).
    ASSERT_TRUE(series[1].good.has_value());
    EXPECT_NEAR(series[1].good->x, 0.008, 1e-6);
    EXPECT_NEAR(series[1].good->y, 0.016, 1e-6);
    ASSERT_TRUE(series[0].good.has_value());
    EXPECT_NEAR(series[0].good->x, 0.004, 1e-6);
    EXPECT_EQ(series[1].leakScenes, (std::vector<std::string>{"pole", "box-on-plane"}));
    LineChartSpec spec = tradeoffChartSpec(rows, "x", 14.0f);
    ASSERT_EQ(spec.panels.size(), 2u);
    for (size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(spec.panels[k].band, series[k].good);
        // One acne line (solid), one leak line per contact scene (dashed), on one axis.
        ASSERT_EQ(spec.panels[k].lines.size(), 3u);
        EXPECT_FALSE(spec.panels[k].lines[0].dashed);
        EXPECT_EQ(spec.panels[k].lines[0].label, "acne, light 30 deg");
        EXPECT_TRUE(spec.panels[k].lines[1].dashed);
        EXPECT_EQ(spec.panels[k].lines[2].label, "leak: box-on-plane");
        EXPECT_EQ(spec.panels[k].lines[1].points.size(), StabilityOptions{}.leakBiases.size());
    }
    std::string legend = textOf(lineChartTextBoxes(spec, CHART), "chart-legend");
    EXPECT_NE(legend.find("green: a good bias (both < 1%)"), std::string::npos) << legend;
    // Acne reaches 100 % where leak stays at a few percent: a log axis from 0.1 % (the zeros on
    // its floor) reads both, a grid line per decade, the 1 % onset among them. On a linear axis
    // to 100 % the leak lay flat on the floor.
    EXPECT_TRUE(spec.logY);
    EXPECT_DOUBLE_EQ(spec.yFloor, TRADEOFF_ONSET / 10.0);
    std::vector<float> tickY;  // the first panel's y ticks, bottom up
    std::vector<std::string> ticks;
    for (const ChartTextBox& b : lineChartTextBoxes(spec, CHART)) {
        if (b.role != "chart-tick" || b.text.find('%') == std::string::npos) continue;
        if (!tickY.empty() && b.rect.y > tickY.back()) break;  // the next panel's
        tickY.push_back(b.rect.y);
        ticks.push_back(b.text);
    }
    EXPECT_EQ(ticks, (std::vector<std::string>{"<=0.1%", "1%", "10%", "100%"}));
    ASSERT_EQ(tickY.size(), 4u);
    EXPECT_NEAR(tickY[0] - tickY[1], tickY[2] - tickY[3], 1.0f);  // decades evenly spaced
    // Acne that never goes: no good bias, no band.
    for (StabilityRow& r : rows) {
        if (r.sweep == "tradeoff" && r.kernel == 5) r.y = 0.5;
    }
    EXPECT_FALSE(tradeoffSeries(rows)[1].good.has_value());
    EXPECT_FALSE(tradeoffChartSpec(rows, "x").panels[1].band.has_value());
}

TEST(StabilityFigures, SetupRowsSurviveTheCsv) {
    std::vector<StabilityRow> rows = defaultShapedRows(LLVMPIPE);
    std::vector<StabilityRow> back = parseStabilityCsv(stabilityCsv(rows), "t.csv");
    std::optional<StabilitySetup> s = stabilitySetupOf(back);
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->glRenderer, "llvmpipe (LLVM 15.0.6; 256 bits)");
    EXPECT_EQ(s->sceneName, "box-on-plane");
    EXPECT_EQ(s->frameSize, glm::ivec2(480, 270));
    EXPECT_EQ(s->mapSize, 512);
    EXPECT_EQ(s->constantBias, 0.002);
    EXPECT_EQ(s->settings, "constant bias 0.002, cull back faces in the shadow pass, depth 32f");
}

TEST(StabilityFigures, EveryShimmerBarIsTheEdgePeakOfOnePopulation) {
    std::vector<StabilityRow> rows = defaultShapedRows(LLVMPIPE);
    BarChartSpec spec = shimmerChartSpec(rows, "x");
    StabilityOptions o;
    ASSERT_EQ(spec.groups.size(), o.methods.size() * o.biases.size());
    size_t g = 0;
    for (size_t mi = 0; mi < o.methods.size(); ++mi) {
        for (BiasMode b : o.biases) {
            std::string bias(biasModeName(b));
            double k = static_cast<double>(b) + 1.0;
            // The edge peaks (light, snapped, camera): never the per-pair flicker p99 (0.9),
            // whose population differs from pair to pair.
            EXPECT_DOUBLE_EQ(spec.groups[g].values[0], 0.01 * k) << spec.groups[g].label;
            EXPECT_DOUBLE_EQ(spec.groups[g].values[1], 0.0) << spec.groups[g].label;
            EXPECT_DOUBLE_EQ(spec.groups[g].values[2], 0.02 * k) << spec.groups[g].label;
            EXPECT_NE(spec.groups[g].label.find(bias), std::string::npos);
            ++g;
        }
    }
    EXPECT_NE(spec.yLabel.find("over the edge pixels"), std::string::npos) << spec.yLabel;
}

// A bar of height 0 (the snapped shimmer) would draw nothing while the legend names its series:
// each gets a "0" over its place on the axis, inside its own column; bars above 0 get none.
TEST(StabilityFigures, ZeroBarsAreMarkedZero) {
    BarChartSpec spec;
    spec.title = "t";
    spec.yLabel = "y";
    spec.series = {"a", "b", "c"};
    spec.groups = {{"one", {0.5, 0.0, 0.25}}, {"two", {0.0, 0.75, 0.0}}};
    spec.minFontPx = STANDALONE_CHART_MIN_PX;
    std::vector<ChartTextBox> boxes = barChartTextBoxes(spec, CHART);
    std::vector<const ChartTextBox*> zeros;
    float tickBottom = 0.0f;  // the lowest y tick's box: the axis runs along its middle
    for (const ChartTextBox& b : boxes) {
        if (b.role == "chart-value") zeros.push_back(&b);
        if (b.role == "chart-tick" && b.text == "0") tickBottom = b.rect.bottom();
    }
    ASSERT_EQ(zeros.size(), 3u);
    for (const ChartTextBox* z : zeros) {
        EXPECT_EQ(z->text, "0");
        EXPECT_GE(z->fontPx, STANDALONE_CHART_MIN_PX);
        EXPECT_LT(z->rect.bottom(), tickBottom) << "over the axis";
    }
    // Left to right: group one's second bar, group two's first and third.
    EXPECT_LT(zeros[0]->rect.right(), CHART.x / 2.0f);
    EXPECT_GT(zeros[1]->rect.x, zeros[0]->rect.right());
    EXPECT_GT(zeros[2]->rect.x, zeros[1]->rect.right());
}

TEST(StabilityFigures, CoincidentLinesAreOffsetAndNamed) {
    LineChartSpec spec = acneChartSpec(defaultShapedRows(LLVMPIPE), "x");
    const ChartPanel* gather = nullptr;
    for (const ChartPanel& p : spec.panels) {
        if (p.title == "pcf-gather 5x5") gather = &p;
    }
    ASSERT_NE(gather, nullptr);
    int offset = 0;
    for (const ChartLine& l : gather->lines) {
        if (l.offsetPx > 0.0f) {
            ++offset;
            EXPECT_EQ(l.label, "constant");
        }
    }
    EXPECT_EQ(offset, 1);
    std::string notes;
    for (const std::string& n : spec.notes) notes += n + "\n";
    EXPECT_NE(notes.find("pcf-gather 5x5: constant = none (drawn 4 px lower)"), std::string::npos)
        << notes;
    // nearest's lines all differ: nothing is moved there.
    for (const ChartLine& l : spec.panels.front().lines) EXPECT_EQ(l.offsetPx, 0.0f) << l.label;
}

TEST(StabilityFigures, TheHeatMapHasItsColourScaleAndMapSize) {
    std::vector<StabilityRow> rows = defaultShapedRows(LLVMPIPE);
    std::vector<ChartTextBox> boxes = imageChartTextBoxes(
        aliasingHeatmapSpec(heatmap(), rows, "x", STANDALONE_CHART_MIN_PX), CHART);
    std::string legend = textOf(boxes, "chart-legend");
    for (const char* entry : {"pixels per texel (log scale)", "1: a texel per pixel", "16 or more",
                              "1/16 or less", "not measured"}) {
        EXPECT_NE(legend.find(entry), std::string::npos) << entry << " in\n" << legend;
    }
    // The scale's ticks run top (16) to bottom (1/16), evenly.
    std::vector<float> tickY;
    for (const ChartTextBox& b : boxes) {
        if (b.role == "chart-legend" &&
            (b.text.find("16") != std::string::npos || b.text.find("1: ") == 0 || b.text == "4" ||
             b.text == "1/4")) {
            tickY.push_back(b.rect.y);
        }
    }
    ASSERT_EQ(tickY.size(), 5u) << legend;
    for (size_t i = 1; i < 5; ++i) EXPECT_GT(tickY[i], tickY[i - 1]);
    EXPECT_NEAR(tickY[2] - tickY[0], tickY[4] - tickY[2], 2.0f);
    std::string subtitle = textOf(boxes, "chart-subtitle");
    EXPECT_NE(subtitle.find("median 2.60, 99th percentile 7.95"), std::string::npos) << subtitle;
}

TEST(StabilityFigures, StandAloneTextIsAtLeast14PxAndNothingOverlaps) {
    for (const NamedChart& chart :
         allCharts(defaultShapedRows(LLVMPIPE), STANDALONE_CHART_MIN_PX)) {
        SCOPED_TRACE(chart.name);
        ASSERT_FALSE(chart.boxes.empty());
        for (const ChartTextBox& b : chart.boxes) {
            // (A legend's mark has no type; the pairs below keep it off every text.)
            if (b.role != "chart-swatch") {
                EXPECT_GE(b.fontPx, STANDALONE_CHART_MIN_PX) << b.role << " '" << b.text << "'";
            }
            EXPECT_GE(b.rect.x, 0.0f) << b.text;
            EXPECT_GE(b.rect.y, 0.0f) << b.text;
            EXPECT_LE(b.rect.right(), CHART.x) << b.text;
            EXPECT_LE(b.rect.bottom(), CHART.y) << b.text;
        }
        for (size_t i = 0; i < chart.boxes.size(); ++i) {
            for (size_t j = i + 1; j < chart.boxes.size(); ++j) {
                // (Two legend marks with their clearances may touch: a column of marks.)
                if (chart.boxes[i].role == "chart-swatch" &&
                    chart.boxes[j].role == "chart-swatch") {
                    continue;
                }
                const Rect& a = chart.boxes[i].rect;
                const Rect& b = chart.boxes[j].rect;
                bool apart =
                    a.right() <= b.x || b.right() <= a.x || a.bottom() <= b.y || b.bottom() <= a.y;
                EXPECT_TRUE(apart)
                    << "'" << chart.boxes[i].text << "' overlaps '" << chart.boxes[j].text << "'";
            }
        }
    }
}

}  // namespace
}  // namespace pcf
