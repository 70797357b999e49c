#include "app/lesson_step.h"

#include <algorithm>
#include <stdexcept>

#include "app/animation.h"
#include "app/predict.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "base/usage_error.h"
#include "charts/chart_facts.h"
#include "kernel/methods.h"
#include "lesson/lesson_claims.h"

namespace pcf {

namespace {

// One step's checks of checkLessonSteps.
void checkStep(const LessonStep& step, const std::string& path, int number,
               std::vector<InputError>& problems) {
    std::string which = "step " + std::to_string(number);
    auto problem = [&](int line, const std::string& what) {
        problems.emplace_back(path, line, which + what);
    };
    if (step.predict) {
        if (auto why = predictStepProblem(*step.predict)) problem(step.predict->line, " " + *why);
    }
    // A fact about a chart names one its chart's table knows (charts/chart_facts.h).
    for (const StepClaim& claim : step.claims) {
        std::string about = " claim \"" + claim.text + "\": ";
        // A claim about the frames reads the step's sweep (animation.h: stepFlickerCurves).
        if (isMotionClaim(claim) && !step.animate) {
            problem(claim.line, about + "the step does not move (it has no animate)");
        }
        std::string fact = chartFactOf(claim);
        if (fact.empty()) continue;
        if (step.chart.empty()) {
            problem(claim.line, about + "the step shows no chart");
            continue;
        }
        try {
            checkChartFactKnown(step.chart, fact);
        } catch (const std::invalid_argument& e) {
            problem(claim.line, about + e.what());
        }
    }
    if (step.chart.empty()) return;
    try {
        checkStepChart(step.chart);
    } catch (const InputError& e) {
        problem(step.chartLine, std::string(" chart: ") + e.what());
        return;
    }
    if (step.chartHighlight.empty()) return;
    try {
        checkStepChartHighlight(step.chart, step.chartHighlight);
    } catch (const std::invalid_argument& e) {
        problem(step.chartHighlightLine, std::string(" chart_highlight: ") + e.what());
    } catch (const InputError& e) {
        problem(step.chartLine, std::string(" chart: ") + e.what());
    }
}

}  // namespace

void checkLessonSteps(const Lesson& lesson, const std::string& path,
                      std::vector<InputError>& problems) {
    for (size_t i = 0; i < lesson.steps.size(); ++i) {
        checkStep(lesson.steps[i], path, static_cast<int>(i) + 1, problems);
    }
}

void requireSteps(const Lesson& lesson, const std::string& path) {
    if (lesson.steps.empty()) throw UsageError(path + ": the lesson has no steps");
}

Lesson loadLessonChecked(const std::string& path) {
    Lesson lesson = parseLessonFile(path);
    requireSteps(lesson, path);
    std::vector<InputError> problems;
    checkLessonSteps(lesson, path, problems);
    if (!problems.empty()) throw problems.front();
    return lesson;
}

std::vector<InputError> lessonProblems(const std::string& path, Lesson* read) {
    std::vector<InputError> problems;
    Lesson lesson = parseLessonString(readInputFile(path), path, problems);
    checkLessonSteps(lesson, path, problems);
    if (read) *read = std::move(lesson);
    std::stable_sort(problems.begin(), problems.end(),
                     [](const InputError& a, const InputError& b) { return a.line() < b.line(); });
    return problems;
}

StepChart stepChart(const LessonStep& step, bool presentation) {
    // The chart's smallest type: the frame's floors for numbers and labels (inspector.h:
    // typeSizes), so that the chart reads as well as the text beside it.
    InspectorLayout frame;
    frame.presentation = presentation;
    TypeSizes t = typeSizes(frame);
    // A projector's chart names only what the step talks about.
    return {step.chart, step.chartHighlight, std::max(t.numberFloor, t.labelFloor), presentation};
}

std::vector<uint8_t> drawStepChart(const LessonStep& step, glm::ivec2 size, bool presentation) {
    return drawStepChart(stepChart(step, presentation), size);
}

std::vector<LayoutBox> stepChartBoxes(const LessonStep& step, const InspectorLayout& layout) {
    std::vector<LayoutBox> out;
    if (step.chart.empty()) return out;
    glm::ivec2 size(layout.scene.size());
    for (const ChartTextBox& b : stepChartTexts(stepChart(step, layout.presentation), size)) {
        BoxKind kind =
            b.role == "chart-tick" || b.role == "chart-badge" ? BoxKind::Number
            : b.role == "chart-label" || b.role == "chart-legend" || b.role == "chart-key"
                ? BoxKind::Label
            : b.role == "chart-swatch" ? BoxKind::Mark
                                       : BoxKind::Text;
        Rect r{b.rect.x + layout.scene.x, b.rect.y + layout.scene.y, b.rect.w, b.rect.h};
        out.push_back({kind, r, "scene", b.role, b.fontPx, false, b.text});
    }
    return out;
}

Focus stepFocus(const LessonStep& step) {
    if (!step.chart.empty()) return Focus{.chart = true};
    if (step.focus) return *step.focus;
    // A heat map is drawn over the scene, and a nearest lookup's hard edge is seen there.
    if (step.settings.heatmap || methodInfo(step.settings.method).hard) {
        return Focus{.scene = true, .neighbourhood = true};
    }
    return Focus{.neighbourhood = true, .formula = true};
}

}  // namespace pcf
