// cmd_lesson.cpp: `pcfscope lesson check FILE`: reports every problem of the file at its line;
// verifies every claim of a lesson's steps (lesson/lesson_claims.h), and the numbers and states
// its words type (lesson/lesson_words.h), on the step's own lookup, and after each key the step's
// words invite
// (`keys`); a claim about an animating step's frames (`flickers`) on the frames its sweep composes.
// The lookup belongs to a scene point (lesson/lesson_pick.h), so it is the same at every
// frame size and mode: the claims are checked once per state, and the point is checked to show in
// the scene view of every frame size a class is likely to see, normal and presentation.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/animation.h"
#include "app/cli_util.h"
#include "app/commands.h"
#include "app/session.h"
#include "app/step_view.h"
#include "base/input_file.h"
#include "charts/chart_facts.h"
#include "charts/speed_chart.h"
#include "charts/step_chart.h"
#include "lesson/lesson_claims.h"
#include "lesson/lesson_keys.h"
#include "lesson/lesson_pick.h"
#include "lesson/lesson_predict.h"
#include "lesson/lesson_words.h"
#include "measure/bench_report.h"
#include "render/gl_context.h"
#include "render/scene_renderer.h"

namespace pcf {

namespace {

// The frame sizes a lesson is checked at (lessons are shown at each, normal and presentation).
constexpr glm::ivec2 CHECKED_FRAMES[] = {{1024, 768}, {1280, 720}, {1600, 900}, {1920, 1080}};

// "7.15 +- 0.42 ms": a row's scene time as the chart draws it, the median and half the IQR.
std::string msWithSpread(const BenchRow& r) {
    char text[64];
    std::snprintf(text, sizeof text, "%.2f +- %.2f ms", chartMs(r, ChartTiming::Scene),
                  0.5 * chartIqr(r, ChartTiming::Scene));
    return text;
}

// A bench chart's order: whether a's metric is less than b's (time: the median scene pass, as
// the chart's x axis, refused where the two bars overlap; rmse: its y axis, the edge RMSE, or near
// the contacts on a "#contact" chart). Each label must pick one row. Any other chart claim is a
// fact of the chart's table (charts/chart_facts.h).
ClaimWorld chartWorld(const LessonStep& step) {
    ClaimWorld world;
    world.chartLess = [&step](const std::string& a, const std::string& b,
                              const std::string& metric) -> std::variant<bool, std::string> {
        StepChartRef ref = stepChartRef(step.chart);
        if (step.chart.empty() || !ref.bench) return std::string("the step shows no bench chart");
        std::vector<BenchRow> rows = parseBenchCsv(readInputFile(ref.path), ref.path);
        const BenchRow* picks[2] = {nullptr, nullptr};
        const std::string* labels[2] = {&a, &b};
        for (int k = 0; k < 2; ++k) {
            std::vector<size_t> picked;
            try {
                picked = chartRowsMatching(rows, *labels[k]);
            } catch (const std::invalid_argument& e) {
                return std::string(e.what());
            }
            if (picked.size() != 1) {
                return "'" + *labels[k] + "' names " + std::to_string(picked.size()) +
                       " dots of the chart, not one";
            }
            picks[k] = &rows[picked[0]];
        }
        if (metric != "time") {
            return chartAccuracy(*picks[0], ref.accuracy) < chartAccuracy(*picks[1], ref.accuracy);
        }
        // An order the bars do not support is not a fact of the chart (bench_report.h).
        if (benchSpreadsOverlap(*picks[0], *picks[1], false)) {
            return a + "'s and " + b + "'s time bars overlap (" + msWithSpread(*picks[0]) +
                   " and " + msWithSpread(*picks[1]) + "): no order to claim";
        }
        return chartMs(*picks[0], ChartTiming::Scene) < chartMs(*picks[1], ChartTiming::Scene);
    };
    world.chartFact = [&step](const std::string& fact, std::string* why) {
        if (step.chart.empty()) {
            *why = "the step shows no chart";
            return false;
        }
        try {
            ChartFactAnswer a = chartFactHolds(step.chart, fact);
            *why = a.why;
            return a.holds;
        } catch (const std::invalid_argument& e) {
            *why = e.what();
            return false;
        }
    };
    return world;
}

struct Checker {
    const Lesson& lesson;
    SceneRenderer& renderer;
    int failures = 0;
    int checked = 0;

    void failure(int line, const std::string& what) {
        std::printf("%s:%d: %s\n", lesson.sourcePath.c_str(), line, what.c_str());
        ++failures;
    }

    // The step's split view at the point (part[K].visibility), each part's map rendered as the
    // split view renders it; empty without `compare` or when the settings cannot take it.
    std::vector<float> partVisibilities(const LessonStep& step, const LessonSettings& s,
                                        const Scene& scene, const ScenePoint& point) {
        if (step.compare.empty()) return {};
        try {
            return comparePartVisibilities(renderer, scene, std::nullopt, s, step.compare, point);
        } catch (const std::invalid_argument&) {
            return {};
        }
    }

    // The step's claims on its lookup under settings s (after `key`, when not empty).
    void checkState(size_t index, const LessonStep& step, const LessonSettings& s,
                    const std::string& key, const ScenePoint& point) {
        // The sun as the keys (U, T) moved it (lesson_pick.h: lessonLight), as the viewer shows it.
        Scene scene = lesson.scene;
        scene.light = lessonLight(lesson.scene.light, s);
        renderer.setLight(scene.light);
        glm::mat4 fit = lessonShadowFit(scene, s, s.mapSize);
        renderer.setShadowClipFromWorld(fit);
        renderer.renderShadowPass(renderSettingsFor(s, {64, 64}));
        ShadowMap map = renderer.readShadowMap();
        Trace trace = tracePinned(map, scene, fit, s, point);
        StepContext ctx = makeStepContext(s, glm::ivec2(0), lightAngleDeg(scene, point));
        ctx.partVisibility = partVisibilities(step, s, scene, point);
        ClaimWorld world = chartWorld(step);
        world.onPlane = std::holds_alternative<Plane>(
            lesson.scene.objects[static_cast<size_t>(point.object)].shape);
        // `flickers`: the step's sweep played as the viewer plays it (loadLessonChecked refused
        // the claim on a step that does not move).
        world.flickerCurve = [&]() -> std::variant<std::vector<float>, std::string> {
            return stepFlickerCurves(lesson, static_cast<int>(index), s).main;
        };
        // The words typed where a placeholder or a claim belongs (lesson_words.h), read against
        // the step's own state (after a key its words are withheld where a claim fails).
        if (key.empty()) {
            for (const WordProblem& p : typedWordProblems(step.text, trace, ctx)) {
                failure(stepTextLine(step, p.offset),
                        "step " + std::to_string(index + 1) + " text: " + p.problem);
            }
        }
        // A predict step's answer is one of its choices (lesson_predict.h).
        if (step.predict && key.empty()) {
            ++checked;
            FilledPredict filled = fillPredict(*step.predict, trace, ctx);
            if (auto why = predictChoiceProblem(*step.predict, filled)) {
                failure(step.predict->line,
                        "step " + std::to_string(index + 1) + " predict: " + *why);
            }
        }
        for (const StepClaim& claim : step.claims) {
            ++checked;
            std::string why;
            if (claimHolds(claim, trace, ctx, world, &why)) continue;
            failure(claim.line, "step " + std::to_string(index + 1) + " claim \"" + claim.text +
                                    "\" fails" + (key.empty() ? "" : " after key " + key) + ": " +
                                    why);
        }
    }

    void checkStep(size_t index, const LessonStep& step) {
        std::optional<ScenePoint> point = stepPoint(lesson.scene, step.settings);
        if (!point) {
            failure(step.line,
                    "step " + std::to_string(index + 1) + ": its point is on no surface");
            return;
        }
        // The point shows in every frame: the pixel that holds it is in the scene view.
        for (glm::ivec2 frame : CHECKED_FRAMES) {
            for (bool presentation : {false, true}) {
                glm::ivec2 scene(inspectorLayout(frame, presentation).scene.size());
                if (framePick(lesson.scene.camera, point->posWs, scene).inFrame) continue;
                failure(step.line, "step " + std::to_string(index + 1) +
                                       ": its point is outside the scene view at " +
                                       std::to_string(frame.x) + "x" + std::to_string(frame.y) +
                                       (presentation ? " presentation" : ""));
            }
        }
        checkState(index, step, step.settings, "", *point);
        for (const std::string& key : step.keys) {
            if (std::optional<LessonSettings> s = settingsAfterKey(step.settings, key)) {
                checkState(index, step, *s, key, *point);
            }
        }
    }
};

struct LessonCheckOptions {
    std::string file;
    std::vector<std::string> pages;  // "1024x768P": a frame size, P for presentation
};

struct PageSize {
    glm::ivec2 size{0};
    bool presentation = false;
};

PageSize parsePageSize(const std::string& text) {
    bool p = !text.empty() && (text.back() == 'P' || text.back() == 'p');
    std::string size = p ? text.substr(0, text.size() - 1) : text;
    try {
        return {parseSize("--pages", size, {MIN_SESSION_SIZE}), p};
    } catch (const UsageError&) {
        throw UsageError("--pages takes WxH or WxHP (P: presentation), e.g. 1024x768P; got '" +
                         text + "'");
    }
}

// The frames each step makes at a size, as `export` writes them: its text's pages, or the
// inspector's parts (the cells, the texel table, the formula) where those are more.
void printPages(const Lesson& lesson, PageSize at) {
    Session session(at.size, at.presentation);
    session.setLesson(lesson);
    std::vector<int> pages;
    std::vector<std::string> parts;  // what makes them, where there are more than one
    for (int s = 0; s < session.stepCount(); ++s) {
        session.goToStep(s);
        session.compose();
        pages.push_back(session.textPages());
        FramePlan plan = planFrame(session.stepLayout(), session.model());
        parts.push_back(pages.back() == 1
                            ? ""
                            : " (text " + std::to_string(plan.stepTextPages) + ", inspector " +
                                  std::to_string(plan.inspectorParts) + ")");
    }
    int frames = 0;
    for (int p : pages) frames += p;
    std::printf("%s at %dx%d%s: %d frames for %zu steps\n", lesson.sourcePath.c_str(), at.size.x,
                at.size.y, at.presentation ? " presentation" : "", frames, pages.size());
    for (size_t s = 0; s < pages.size(); ++s) {
        std::printf("  step %zu: %d page%s  %s%s\n", s + 1, pages[s], pages[s] == 1 ? " " : "s",
                    lesson.steps[s].title.c_str(), parts[s].c_str());
    }
}

int runLessonCheck(const LessonCheckOptions& o) {
    std::vector<PageSize> pageSizes;
    for (const std::string& p : o.pages) pageSizes.push_back(parsePageSize(p));
    std::string path = resolveLesson(o.file);
    // Every problem of the file, each on its line, before anything is checked on its numbers.
    Lesson lesson;
    std::vector<InputError> problems = lessonProblems(path, &lesson);
    if (problems.size() > 1) {
        for (const InputError& e : problems) {
            std::fprintf(stderr, "pcfscope: %s\n", oneLine(e.what()).c_str());
        }
        return 2;
    }
    if (!problems.empty()) throw problems.front();
    requireSteps(lesson, path);
    std::unique_ptr<GlContext> context = createHeadlessContext();
    SceneRenderer renderer(lesson.scene);
    Checker checker{lesson, renderer};
    for (size_t i = 0; i < lesson.steps.size(); ++i) checker.checkStep(i, lesson.steps[i]);
    for (const PageSize& at : pageSizes) printPages(lesson, at);
    if (checker.failures > 0) return 1;
    std::printf("%s: %d claims hold over %zu steps\n", lesson.sourcePath.c_str(), checker.checked,
                lesson.steps.size());
    return 0;
}

}  // namespace

Command addLessonCommand(CLI::App& app) {
    auto o = std::make_shared<LessonCheckOptions>();
    CLI::App* lessonCmd = app.add_subcommand("lesson", "tools for lesson authors");
    lessonCmd->require_subcommand(1);
    CLI::App* check = lessonCmd->add_subcommand(
        "check",
        "verify every claim of a lesson's steps and the numbers its words type (exit 0: all "
        "hold; 1: one line per failure, file:line; 2: a bad file, one line per problem)");
    check->add_option("file", o->file, "a lesson: a .toml path, or a built-in lesson's number")
        ->required();
    check->add_option("--pages", o->pages,
                      "WxH or WxHP (P: presentation), e.g. 1024x768P: also print the frames "
                      "(pages) each step makes at that size; may be given more than once");
    return {lessonCmd, [o] { return runLessonCheck(*o); }};
}

}  // namespace pcf
