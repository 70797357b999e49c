#include "app/exercise.h"

#include <memory>
#include <random>
#include <variant>
#include <vector>

#include "app/step_view.h"
#include "base/usage_error.h"
#include "kernel/methods.h"
#include "lesson/lesson_pick.h"
#include "render/scene_renderer.h"
#include "scene/camera.h"

namespace pcf {

namespace {

// The edge band is looked for on a grid of this many points across the view (16:9, inside a
// tenth of its edges, where every frame size shows it).
constexpr int BAND_COLUMNS = 96;
constexpr int BAND_ROWS = 54;
constexpr float BAND_VIEW = 0.9f;  // ndc
constexpr float BAND_EDGE = 0.1f;  // a visibility this near 0 or 1 asks little of the class

// A filter the lesson uses (a method with its kernel), with the first step's state that uses it.
struct FilterUse {
    LessonSettings settings;
};

std::vector<FilterUse> filtersOf(const Lesson& lesson) {
    std::vector<FilterUse> uses;
    for (const LessonStep& step : lesson.steps) {
        if (!step.chart.empty()) continue;
        const LessonSettings& s = step.settings;
        bool kernel = methodInfo(s.method).usesKernel;
        bool known = false;
        for (const FilterUse& u : uses) {
            known = known ||
                    (u.settings.method == s.method && (!kernel || u.settings.kernel == s.kernel));
        }
        if (known) continue;
        LessonSettings clean = s;
        clean.magnify = false;
        clean.heatmap = false;
        clean.point.reset();
        uses.push_back({clean});
    }
    return uses;
}

// A uniform index below n from the generator's next number (the standard's distributions are
// not the same on every library; this is, for a given seed).
size_t drawIndex(std::mt19937_64& rng, size_t n) { return static_cast<size_t>(rng() % n); }

// The points on the ground in view where the filter of `s` gives a visibility well between lit
// and shadowed (BAND_EDGE), on the map `renderer` renders for `s`.
std::vector<ScenePoint> edgeBand(const Scene& scene, const LessonSettings& s,
                                 SceneRenderer& renderer) {
    Scene lit = scene;
    lit.light = lessonLight(scene.light, s);
    renderer.setLight(lit.light);
    glm::mat4 fit = lessonShadowFit(lit, s, s.mapSize);
    renderer.setShadowClipFromWorld(fit);
    renderer.renderShadowPass(renderSettingsFor(s, {64, 64}));
    ShadowMap map = renderer.readShadowMap();
    std::vector<ScenePoint> band;
    for (int row = 0; row < BAND_ROWS; ++row) {
        for (int col = 0; col < BAND_COLUMNS; ++col) {
            glm::vec2 ndc{(2.0f * (col + 0.5f) / BAND_COLUMNS - 1.0f) * BAND_VIEW,
                          (2.0f * (row + 0.5f) / BAND_ROWS - 1.0f) * BAND_VIEW};
            std::optional<ScenePoint> p = pointAtNdc(lit, ndc, 16.0f / 9.0f, glm::vec2(0.0f));
            if (!p) continue;
            if (!std::holds_alternative<Plane>(lit.objects[static_cast<size_t>(p->object)].shape))
                continue;
            float v = tracePinned(map, lit, fit, s, *p).visibility;
            if (v > BAND_EDGE && v < 1.0f - BAND_EDGE) band.push_back(*p);
        }
    }
    return band;
}

// The filter's name as the question says it: "pcf-gather 3x3", "poisson R = 1", "box2x2".
std::string filterName(const LessonSettings& s) {
    const MethodInfo& info = methodInfo(s.method);
    std::string name(info.name);
    if (info.usesKernel) name += " " + std::to_string(s.kernel) + "x" + std::to_string(s.kernel);
    if (info.usesRadius) name += " R = " + formatNumber(s.radius);
    return name;
}

LessonStep exerciseItem(const FilterUse& use, const ScenePoint& point, int number) {
    LessonStep step;
    step.settings = use.settings;
    step.settings.point = point.posWs;
    std::string filter = filterName(step.settings);
    step.title = "Exercise " + std::to_string(number) + ": " + filter;
    step.text =
        "With ref = {ref}, a texel read is lit when ref <= its depth, and the visibility adds up "
        "the weights of the lit reads: {lit_count} of the {taps} reads pass, visibility = "
        "{visibility}.";
    StepPredict q;
    q.ask = "What visibility does " + filter +
            " give at the marked point? Compare each texel's depth with ref = {ref}, then add "
            "up the weights of the lit ones. To within 1/16.";
    q.answer = "{visibility}";
    q.tolerance = EXERCISE_TOLERANCE;
    step.predict = q;
    return step;
}

}  // namespace

Lesson makeExercise(const Lesson& lesson, int count, std::uint64_t seed) {
    if (count < 1 || count > MAX_EXERCISE_ITEMS) {
        throw UsageError("--count must be 1.." + std::to_string(MAX_EXERCISE_ITEMS) + ", got " +
                         std::to_string(count));
    }
    std::vector<FilterUse> uses = filtersOf(lesson);
    if (uses.empty()) {
        throw UsageError(lesson.sourcePath +
                         ": every step shows a chart; an exercise needs a scene");
    }
    Lesson out;
    out.name = lesson.name + "-exercise";
    out.title = "Exercises: " + lesson.title;
    out.sourcePath = lesson.sourcePath;
    out.scene = lesson.scene;
    SceneRenderer renderer(lesson.scene);
    std::vector<std::vector<ScenePoint>> bands(uses.size());
    std::mt19937_64 rng(seed);
    for (int k = 1; k <= count; ++k) {
        size_t u = drawIndex(rng, uses.size());
        if (bands[u].empty()) bands[u] = edgeBand(lesson.scene, uses[u].settings, renderer);
        if (bands[u].empty()) {
            throw UsageError(lesson.sourcePath + ": " + filterName(uses[u].settings) +
                             " gives no shadow edge in view, so no exercise point");
        }
        const ScenePoint& p = bands[u][drawIndex(rng, bands[u].size())];
        out.steps.push_back(exerciseItem(uses[u], p, k));
    }
    return out;
}

}  // namespace pcf
