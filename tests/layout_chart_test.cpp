// A chart step's frame (inspector.h: planFrame, step_chart.h): on a projector the chart takes the
// inspector's room too and keeps its texts at the floors, its dots keep their names beside them,
// and a click on the chart picks no pixel of the hidden scene.
#include <gtest/gtest.h>

#include "layout_checks.h"

namespace pcf {
namespace {

using namespace testutil;

// A chart step on a projector: the chart takes the inspector's room too, every one of its texts
// (ticks, axis names, the dots' names, the legend; the stability charts' of lessons 13 and 14
// too) is at least 18 px (the presentation number floor; normal mode keeps the normal floors)
// and inside the chart, the dots the step rings are named, and no two texts lie on each other.
// (At 617 x 347, the scene panel's size, they were 8 px.)
TEST_F(Layout, ChartStepsInPresentationSetTheChartAtProjectorSize) {
    int chartSteps = 0, stabilitySteps = 0, adviseSteps = 0;
    std::vector<LessonStep> steps;
    for (const char* file :
         {"11-speed-and-accuracy", "13-shimmer-and-snapping", "14-bias-trade-off",
          "18-which-setting-a-scene-needs", "20-light-bleeding", "21-cascades-and-splits"}) {
        Lesson lesson =
            parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/" + std::string(file) + ".toml");
        for (const LessonStep& step : lesson.steps) steps.push_back(step);
    }
    for (const LessonStep& step : steps) {
        if (step.chart.empty()) continue;
        ++chartSteps;
        // A stability chart (lessons 13, 14: "stability.csv#view") has no dots to name; an
        // advise chart (lesson 18: "DIR/advise.csv") names its own marks.
        StepChartKind kind = stepChartRef(step.chart).kind;
        bool stability = kind == StepChartKind::Stability;
        stabilitySteps += stability;
        adviseSteps += kind == StepChartKind::Advise;
        for (glm::ivec2 size : {glm::ivec2{1280, 720}, glm::ivec2{1024, 768}}) {
            for (bool presentation : {true, false}) {
                std::string where = step.title + " at " + std::to_string(size.x) + "x" +
                                    std::to_string(size.y) + (presentation ? " presentation" : "");
                InspectorLayout l = chartStepLayout(inspectorLayout(size, presentation));
                const float floor = presentation ? 18.0f : 12.0f;
                if (presentation) {
                    EXPECT_EQ(l.scene.w, static_cast<float>(size.x)) << where;
                    EXPECT_GE(l.scene.h, 0.5f * size.y) << where;
                    EXPECT_TRUE(l.inspector.empty()) << where;
                }
                std::vector<LayoutBox> boxes = stepChartBoxes(step, l);
                std::map<std::string, int> roles;
                std::vector<const LayoutBox*> names;
                for (const LayoutBox& b : boxes) {
                    ++roles[b.role];
                    // (A legend's mark has no type; the pairs below keep it off every text.)
                    if (b.kind != BoxKind::Mark) {
                        EXPECT_GE(b.fontPx, floor)
                            << where << ": " << b.role << " '" << b.text << "'";
                    }
                    EXPECT_TRUE(inside(b.rect, l.scene)) << where << ": " << b.text;
                    if (b.role == "chart-label" || b.role == "chart-key") names.push_back(&b);
                }
                EXPECT_GE(roles["chart-tick"], 4) << where;
                // (The bar chart of lesson 13 names its groups instead of an x axis.)
                EXPECT_EQ(roles["chart-axis"], stability && roles["chart-label"] > 0 ? 1 : 2)
                    << where;
                EXPECT_GE(roles["chart-legend"], 3) << where;
                EXPECT_GE(roles["chart-swatch"], 3) << where;
                // No text of the chart on another (ticks, names, legend, titles), and no legend
                // mark on a text (the front's ring ran into "Pareto front" at 18 px type).
                for (size_t i = 0; i < boxes.size(); ++i) {
                    for (size_t j = i + 1; j < boxes.size(); ++j) {
                        // (Two legend marks with their clearances may touch: a column of marks.)
                        if (boxes[i].kind == BoxKind::Mark && boxes[j].kind == BoxKind::Mark) {
                            continue;
                        }
                        const Rect &a = boxes[i].rect, &b = boxes[j].rect;
                        EXPECT_TRUE(a.intersect(b).empty())
                            << where << ": '" << boxes[i].text << "' [" << a.x << " " << a.y << " "
                            << a.w << " " << a.h << "] on '" << boxes[j].text << "' [" << b.x << " "
                            << b.y << " " << b.w << " " << b.h << "]";
                    }
                }
                if (stability) {
                    EXPECT_GE(roles["chart-title"], 1) << where;
                } else if (presentation && kind == StepChartKind::Bench) {
                    // Every ringed dot is named, beside it or in the key (and, on a projector,
                    // only the ringed: a label for each of the ~80 dots would bury the plot).
                    std::vector<BenchRow> rows =
                        parseBenchCsv(readInputFile(step.chart), step.chart);
                    if (!step.chartHighlight.empty()) {
                        for (size_t k : chartRowsMatching(rows, step.chartHighlight)) {
                            std::string label = chartLabel(rows[k].point);
                            bool named = false;
                            for (const LayoutBox* b : names) named |= b->text.starts_with(label);
                            EXPECT_TRUE(named) << where << ": " << label;
                        }
                    }
                    EXPECT_LT(names.size(), 30u) << where;
                }
                for (size_t i = 0; i < names.size(); ++i) {
                    for (size_t j = i + 1; j < names.size(); ++j) {
                        EXPECT_TRUE(names[i]->rect.intersect(names[j]->rect).empty())
                            << where << ": '" << names[i]->text << "' on '" << names[j]->text
                            << "'";
                    }
                }
            }
        }
    }
    EXPECT_GE(chartSteps, 6);
    EXPECT_GE(stabilitySteps, 3);
    EXPECT_GE(adviseSteps, 3);
}

// A chart step's dots keep their names, at every size and mode: each drawn name or badge is nearer
// its own dot than any other, within reach of it, on no dot, ring, bar or other name, and every
// ringed dot has one (speedChartLabelFaults). Before badges, lesson 11 at 1024x768 presentation
// put "nearest 2048" beside the nearest-256 dot, 160 px from its own, and 11.3's four names far
// out on leaders across the plot; at 1280x720 presentation 11.2's "hw2x2 2048" sat by a nearest
// dot; in 16.5 to 17.5 the bars struck names through. Every dot's time has a labelled tick near
// it (17.4's four dots past "10" had none).
TEST_F(Layout, ChartStepsNameEachDotBesideItAndLabelItsTime) {
    int charts = 0, adviseCharts = 0, names = 0, badges = 0;
    for (const char* file : {"11-speed-and-accuracy", "16-contact-hardening",
                             "17-pcss-under-a-spot", "18-which-setting-a-scene-needs"}) {
        Lesson lesson =
            parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/" + std::string(file) + ".toml");
        for (const LessonStep& step : lesson.steps) {
            if (step.chart.empty()) continue;
            for (glm::ivec2 size : SIZES) {
                for (bool presentation : {true, false}) {
                    std::string where = step.title + " at " + std::to_string(size.x) + "x" +
                                        std::to_string(size.y) +
                                        (presentation ? " presentation" : "");
                    InspectorLayout l = chartStepLayout(inspectorLayout(size, presentation));
                    std::optional<SpeedChartLayout> chart = stepSpeedChartLayout(
                        stepChart(step, presentation), glm::ivec2(l.scene.size()));
                    if (!chart) continue;
                    // (An advise chart rings its choice itself, and names the front's dots.)
                    bool advise = stepChartRef(step.chart).kind == StepChartKind::Advise;
                    ++(advise ? adviseCharts : charts);
                    names += static_cast<int>(
                        std::count(chart->labelShown.begin(), chart->labelShown.end(), true));
                    badges += static_cast<int>(chart->keyRows.size());
                    // The dots the step rings are the ones it names.
                    if (!advise) {
                        std::vector<size_t> ringed = chartRowsMatching(
                            parseBenchCsv(readInputFile(stepChartRef(step.chart).path), step.chart),
                            step.chartHighlight);
                        EXPECT_EQ(chart->mustName, ringed) << where;
                    }
                    for (const std::string& f : speedChartLabelFaults(*chart)) {
                        ADD_FAILURE() << where << ": " << f;
                    }
                    for (const std::string& f : speedChartTickFaults(*chart)) {
                        ADD_FAILURE() << where << ": " << f;
                    }
                }
            }
        }
    }
    // The 8 bench chart steps (4 of lesson 11; 16.5, 16.6, 17.4, 17.5), each at 4 sizes, 2 modes.
    EXPECT_EQ(charts, 8 * 8);
    // Lesson 18's 3 advise chart steps, the speed chart under their marks.
    EXPECT_EQ(adviseCharts, 3 * 8);
    EXPECT_GE(names, charts);
    // Badges are for a crowd: lesson 11's 72 dots in a 1024x768 frame's chart.
    std::printf("layout: %d names and %d badges on the %d bench charts\n", names, badges, charts);
}

// A chart step shows its chart where the scene goes (in presentation mode over the inspector's
// room too): a click there picks no pixel of the hidden scene; on a scene step it does.
TEST_F(Layout, ClicksOnAChartPickNoScenePixel) {
    for (bool presentation : {true, false}) {
        Session session({1280, 720}, presentation);
        session.loadLesson(PCFSCOPE_SOURCE_DIR "/lessons/11-speed-and-accuracy.toml");
        int chartStep = -1, sceneStep = -1;
        for (int k = 0; k < session.stepCount(); ++k) {
            bool chart = !session.lesson().steps[static_cast<size_t>(k)].chart.empty();
            if (chart && chartStep < 0) chartStep = k;
            if (!chart && sceneStep < 0) sceneStep = k;
        }
        ASSERT_GE(chartStep, 0);
        ASSERT_GE(sceneStep, 0);
        session.goToStep(sceneStep);
        // Where the scene step draws its scene (an inset when its focus is the neighbourhood:
        // a click there picks the scene pixel under it, scaled back).
        Rect scene = session.stepLayout().scene;
        glm::vec2 at = scene.position() + glm::vec2(7.0f, 5.0f);
        glm::ivec2 picked(glm::floor(glm::vec2(7.0f, 5.0f) * session.layout().scene.w / scene.w));
        session.goToStep(chartStep);
        EXPECT_FALSE(session.sceneShown());
        glm::ivec2 before = session.pixel();
        ASSERT_NE(before, picked);
        EXPECT_FALSE(session.clickFrame(at));
        EXPECT_EQ(session.pixel(), before) << presentation;
        session.goToStep(sceneStep);
        EXPECT_TRUE(session.sceneShown());
        EXPECT_TRUE(session.clickFrame(at));
        EXPECT_EQ(session.pixel(), picked) << presentation;
        // Off the scene (the inspector's side): nothing.
        EXPECT_FALSE(session.clickFrame({scene.right() + 5.0f, scene.y + 5.0f}));
        EXPECT_EQ(session.pixel(), picked);
    }
}

// A step that names a panel of the bleed chart ("#bleed:lbr", lesson 20) gives it the whole
// plot: on a projector at 1024 x 768 its leak axis is at least three times as tall as in the
// four-panel chart, and has room for the 0.001 tick the step's words read the lines against (the
// four panels' axes drew only "1" and "<=0.0001").
TEST_F(Layout, ANamedBleedPanelGetsThePlotAndItsDecades) {
    Lesson lesson = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/20-light-bleeding.toml");
    const LessonStep* named = nullptr;
    for (const LessonStep& s : lesson.steps) {
        if (s.chart.ends_with("#bleed:lbr")) named = &s;
    }
    ASSERT_NE(named, nullptr);
    LessonStep all = *named;
    all.chart = all.chart.substr(0, all.chart.rfind('#')) + "#bleed";
    InspectorLayout l = chartStepLayout(inspectorLayout({1024, 768}, true));
    // The top panel's leak axis: from its "1" tick down to its floor's, and whether a tick of the
    // same column reads 0.001.
    auto axisOf = [&](const LessonStep& step) {
        std::vector<LayoutBox> ticks;
        for (const LayoutBox& b : stepChartBoxes(step, l)) {
            if (b.role == "chart-tick") ticks.push_back(b);
        }
        auto topmost = [&](const std::string& text) {
            const LayoutBox* best = nullptr;
            for (const LayoutBox& b : ticks) {
                if (b.text == text && (!best || b.rect.y < best->rect.y)) best = &b;
            }
            return best;
        };
        const LayoutBox* one = topmost("1");
        const LayoutBox* floor = topmost("<=0.0001");
        EXPECT_TRUE(one && floor) << step.chart;
        if (!one || !floor) return std::pair<float, bool>{0.0f, false};
        bool thousandth = false;
        for (const LayoutBox& b : ticks) {
            thousandth |= b.text == "0.001" &&
                          std::abs(b.rect.right() - one->rect.right()) < 1.0f &&
                          b.rect.y > one->rect.y && b.rect.y < floor->rect.y;
        }
        return std::pair<float, bool>{floor->rect.y - one->rect.y, thousandth};
    };
    auto [fourHeight, fourThousandth] = axisOf(all);
    auto [oneHeight, oneThousandth] = axisOf(*named);
    EXPECT_GT(fourHeight, 0.0f);
    EXPECT_GE(oneHeight, 3.0f * fourHeight) << fourHeight;
    EXPECT_FALSE(fourThousandth);
    EXPECT_TRUE(oneThousandth) << oneHeight;
}

}  // namespace
}  // namespace pcf
