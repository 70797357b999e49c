#include "lesson/lesson.h"

#include <toml++/toml.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <variant>

#include "base/input_file.h"
#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/shadow_map.h"
#include "kernel/sigma_limits.h"
#include "kernel/trace.h"
#include "lesson/lesson_claims.h"
#include "lesson/lesson_keys.h"
#include "lesson/lesson_pick.h"
#include "lesson/lesson_predict.h"
#include "lesson/lesson_reader.h"
#include "lesson/lesson_text.h"
#include "lesson/lesson_text_lines.h"
#include "scene/cascade_view.h"
#include "scene/presets.h"
#include "scene/scene_file.h"

namespace pcf {

namespace {

// lessonParseCount's count.
std::atomic<long> gLessonParses{0};

// The keys a [settings] table and a [[step]] may set besides the parameter table's: the view's
// (`pixel` only to be refused with what to write instead).
constexpr std::string_view VIEW_KEYS[] = {"point",        "pixel", "grid",    "heatmap",
                                          "origin_shift", "snap",  "magnify", "freeze_cascades"};

bool isSettingKey(std::string_view key) {
    return findParam(key) != nullptr ||
           std::find(std::begin(VIEW_KEYS), std::end(VIEW_KEYS), key) != std::end(VIEW_KEYS);
}

// Where each setting got its current value, so that a problem found only once the state is
// complete (tent with kernel 4) is blamed on the line that made it.
struct SettingLines {
    int method = 0;
    int kernel = 0;
    int bias = 0;
};

using lesson_detail::formatValue;
using lesson_detail::lineOf;
using lesson_detail::typeName;

// The whole file: its root keys, scene, settings and steps, each step's state checked whole and
// its text's placeholders checked (the values and a step's own keys: lesson_reader.h).
class LessonParser : public lesson_detail::LessonReader {
  public:
    // problems: as LessonReader's.
    LessonParser(std::string_view text, std::string source,
                 std::vector<InputError>* problems = nullptr)
        : LessonReader(std::move(source), problems), mText(text) {
        size_t start = 0;
        while (start <= mText.size()) {
            size_t end = mText.find('\n', start);
            if (end == std::string_view::npos) end = mText.size();
            mLines.push_back(mText.substr(start, end - start));
            start = end + 1;
        }
    }

    Lesson parse() {
        ++gLessonParses;
        toml::table root;
        try {
            root = toml::parse(mText, mSource);
        } catch (const toml::parse_error& e) {
            throw InputError(mSource, std::max(1, static_cast<int>(e.source().begin.line)),
                             std::string(e.description()));
        }
        checkRootKeys(root);
        Lesson lesson;
        lesson.name = std::filesystem::path(mSource).stem().string();
        lesson.sourcePath = mSource;
        attempt([&] {
            lesson.title = requireText(root, "title", "lesson", root);
            checkLength(*root.get("title"), "lesson title", lesson.title, MAX_TITLE_CHARS);
        });
        lesson.scene = readScene(root);  // no scene: nothing more can be checked
        mScene = &lesson.scene;

        LessonSettings state;
        SettingLines lines;
        if (const toml::node* node = root.get("settings")) {
            if (const toml::table* settings = node->as_table()) {
                checkKeys(*settings, "settings", {});
                applySettings(*settings, "settings", state, lines);
            } else {
                attempt([&] {
                    fail(*node, "settings must be a table ([settings]), got " + typeName(*node));
                });
            }
        }

        const toml::array& steps = stepTables(root);
        for (size_t i = 0; i < steps.size(); ++i) {
            const toml::table& table = *steps.get(i)->as_table();
            std::string what = "step " + std::to_string(i + 1);
            checkKeys(table, what,
                      {"title", "text", "chart", "chart_highlight", "highlight", "claims", "keys",
                       "focus", "animate", "compare", "predict"});
            applySettings(table, what, state, lines);
            lesson.steps.push_back(readStep(table, what, state, lines));
            // The step's own focus, else the lesson's (lesson_focus.h).
            const toml::table& owner = table.get("focus") ? table : root;
            if (const toml::node* f = owner.get("focus")) {
                attempt([&] {
                    std::string name = requireText(owner, "focus", what, owner);
                    lesson.steps.back().focusLine = lineOf(*f);
                    lesson.steps.back().focus = parseFocus(name);
                    if (!lesson.steps.back().focus) {
                        fail(*f, what + " focus '" + name + "' is not one of: " + focusNames());
                    }
                });
            }
        }
        return lesson;
    }

    // The [[step]] tables: at least one, at most MAX_LESSON_STEPS, each a table.
    const toml::array& stepTables(const toml::table& root) const {
        const toml::node* stepsNode = root.get("step");
        const toml::array* steps = stepsNode ? stepsNode->as_array() : nullptr;
        if (!stepsNode || (steps && steps->empty())) {
            throw InputError(mSource, stepsNode ? lineOf(*stepsNode) : 1,
                             "lesson has no steps: add at least one [[step]] table");
        }
        if (!steps || !steps->is_array_of_tables()) {
            fail(*stepsNode,
                 "step must be an array of tables ([[step]]), got " +
                     (steps ? std::string("an array of other values") : typeName(*stepsNode)));
        }
        if (steps->size() > static_cast<size_t>(MAX_LESSON_STEPS)) {
            fail(*stepsNode, "lesson has " + std::to_string(steps->size()) +
                                 " steps; the limit is " + std::to_string(MAX_LESSON_STEPS));
        }
        return *steps;
    }

    // One step at the state its table left: its title and text, its chart keys, checked.
    LessonStep readStep(const toml::table& table, const std::string& what,
                        const LessonSettings& state, const SettingLines& lines) const {
        LessonStep step;
        step.line = lineOf(table);
        attempt([&] {
            step.title = requireText(table, "title", what, table);
            checkLength(*table.get("title"), what + " title", step.title, MAX_TITLE_CHARS);
        });
        bool text = attempt([&] {
            step.text = requireText(table, "text", what, table);
            checkLength(*table.get("text"), what + " text", step.text, MAX_STEP_TEXT_CHARS);
        });
        readChartKeys(table, what, step);
        readClaims(table, what, step);
        attempt([&] { readAnimation(table, what, step); });
        step.settings = state;
        attempt([&] { checkState(table, what, state, lines); });
        attempt([&] { readCompare(table, what, step); });  // before the text: its part[K]
        if (text) {
            const toml::node& node = *table.get("text");
            step.textLine = lineOf(node);
            step.textLineStarts = valueLineStarts(
                mLines, lineOf(node), static_cast<int>(node.source().begin.column), step.text);
            checkText(what, step);
        }
        attempt([&] { readPredict(table, what, step); });
        return step;
    }

  private:
    void checkRootKeys(const toml::table& root) const {
        for (auto&& [key, value] : root) {
            std::string_view k = key.str();
            if (k == "title" || k == "scene" || k == "settings" || k == "step" || k == "camera" ||
                k == "light" || k == "object" || k == "focus") {
                continue;
            }
            std::string problem = "lesson has unknown key '" + std::string(k) + "'";
            if (k == "steps") problem += " (steps are [[step]] tables)";
            if (k == "setting") problem += " (did you mean [settings]?)";
            if (k == "objects") problem += " (objects are [[object]] tables)";
            if (isSettingKey(k)) problem += " (put it in [settings] or in a [[step]])";
            attempt([&] {
                throw InputError(mSource, std::max(1, static_cast<int>(key.source().begin.line)),
                                 problem);
            });
        }
    }

    // Refuses keys that are neither settings nor in `extra`: a misspelt key (kernal) would
    // otherwise be silently ignored and the lesson would show another state than intended.
    void checkKeys(const toml::table& table, const std::string& what,
                   std::initializer_list<std::string_view> extra) const {
        for (auto&& [key, value] : table) {
            std::string_view k = key.str();
            bool known = isSettingKey(k);
            for (std::string_view e : extra) known = known || k == e;
            if (known) continue;
            std::string problem = what + " has unknown key '" + std::string(k) + "'";
            if (k == "kernal" || k == "kernel_size") problem += " (did you mean 'kernel'?)";
            if (k == "mapsize" || k == "map-size") problem += " (did you mean 'map_size'?)";
            if (k == "constant-bias" || k == "constantBias") {
                problem += " (did you mean 'constant_bias'?)";
            }
            if (k == "depth-format" || k == "depthFormat") {
                problem += " (did you mean 'depth_format'?)";
            }
            if (k == "body") problem += " (did you mean 'text'?)";
            attempt([&] {
                throw InputError(mSource, std::max(1, static_cast<int>(key.source().begin.line)),
                                 problem);
            });
        }
    }

    Scene readScene(const toml::table& root) const {
        bool hasTables =
            root.contains("camera") || root.contains("light") || root.contains("object");
        const toml::node* sceneNode = root.get("scene");
        if (sceneNode) {
            const auto* name = sceneNode->as_string();
            if (!name) {
                fail(*sceneNode, "scene must be a preset name (a string), got " +
                                     typeName(*sceneNode) +
                                     "; a lesson's own scene is given by top-level [camera], "
                                     "[light] and [[object]] tables");
            }
            // A [camera] alone beside a preset views the preset from there (lesson 8 looks
            // closer, so that its acne stripes are texels several pixels wide, not a moire).
            if (root.contains("light") || root.contains("object")) {
                fail(*sceneNode, "lesson gives both scene = \"" + name->get() +
                                     "\" and scene tables ([light], [[object]]): keep one");
            }
            std::optional<Scene> scene = presetScene(name->get());
            if (!scene) {
                fail(*sceneNode, "unknown scene preset '" + name->get() +
                                     "' (known: " + presetNameList() + ")");
            }
            if (const toml::node* camera = root.get("camera")) {
                const toml::table* table = camera->as_table();
                if (!table) fail(*camera, "camera must be a table, got " + typeName(*camera));
                scene->camera = parseCameraToml(*table, mSource, *scene);
            }
            return *scene;
        }
        if (!hasTables) {
            throw InputError(mSource, 1,
                             "lesson has no scene: add scene = \"box-on-plane\" (a preset) or "
                             "the [camera], [light] and [[object]] tables");
        }
        return parseSceneToml(root, mSource);
    }

    // Sets the state from every settings key of `table` (a [settings] table or a [[step]]).
    void applySettings(const toml::table& table, const std::string& what, LessonSettings& s,
                       SettingLines& lines) const {
        for (const ParamInfo& p : allParams()) {
            const toml::node* n = table.get(p.key);
            if (!n) continue;
            attempt([&] {
                std::visit([&](const auto& field) { readParam(*n, what, p, field, s); }, p.field);
            });
            if (p.key == "method") lines.method = lineOf(*n);
            // A weighting the method cannot take is blamed on the later of the two.
            if (p.key == "weights") lines.method = std::max(lines.method, lineOf(*n));
            if (p.key == "kernel") lines.kernel = lineOf(*n);
            if (p.key == "bias") lines.bias = lineOf(*n);
        }
        attempt([&] { applyMapKeys(table, what, s); });
        attempt([&] { applyViewKeys(table, what, s); });
    }

    // One parameter of the table, by its type: an integer, then a number, each in the table's
    // range (paramRangeProblem: the one range check of the command line, the compare values and
    // these files).
    void readParam(const toml::node& n, const std::string& what, const ParamInfo& p,
                   int ShadowSettings::*field, LessonSettings& s) const {
        int64_t v = integer(n, what + " " + std::string(p.key));
        if (auto why = paramRangeProblem(p, static_cast<double>(v), std::to_string(v))) {
            fail(n, what + " " + why->text());
        }
        s.*field = static_cast<int>(v);
    }

    void readParam(const toml::node& n, const std::string& what, const ParamInfo& p,
                   float ShadowSettings::*field, LessonSettings& s) const {
        double v = number(n, what + " " + std::string(p.key));
        if (auto why = paramRangeProblem(p, v)) fail(n, what + " " + why->text());
        s.*field = static_cast<float>(v);
    }

    void readParam(const toml::node& n, const std::string& what, const ParamInfo& p,
                   bool ShadowSettings::*field, LessonSettings& s) const {
        const auto* b = n.as_boolean();
        if (!b)
            fail(n, what + " " + std::string(p.key) + " must be true or false, got " + typeName(n));
        s.*field = b->get();
    }

    // A name, in its canonical spelling only (the command line also reads "32" for "32f").
    template <class T>
    void readParam(const toml::node& n, const std::string& what, const ParamInfo& p,
                   const NamedField<T>& named, LessonSettings& s) const {
        std::string text = string(n, what + " " + std::string(p.key));
        std::optional<T> v = named.fromName(text);
        if (!v || named.name(*v) != text) {
            fail(n, "unknown " + std::string(named.noun) + " '" + text +
                        "' (known: " + named.known() + ")");
        }
        s.*named.field = *v;
    }

    // The view's keys of the shadow map: its grid's origin (origin_shift, snap), the heat map of
    // its aliasing over the scene, and the magnifier's close-up on its texels.
    void applyMapKeys(const toml::table& table, const std::string& what, LessonSettings& s) const {
        auto name = [&](std::string_view key) { return what + " " + std::string(key); };
        for (auto [key, field] :
             {std::pair<const char*, bool*>{"heatmap", &s.heatmap},
              std::pair<const char*, bool*>{"snap", &s.snap},
              std::pair<const char*, bool*>{"magnify", &s.magnify},
              std::pair<const char*, bool*>{"freeze_cascades", &s.freezeCascades}}) {
            if (const toml::node* n = table.get(key)) {
                const auto* b = n->as_boolean();
                if (!b) fail(*n, name(key) + " must be true or false, got " + typeName(*n));
                *field = b->get();
            }
        }
        if (const toml::node* n = table.get("origin_shift")) {
            double shift = number(*n, name("origin_shift"));
            if (!(shift >= -64.0 && shift <= 64.0)) {
                fail(*n, what + " origin_shift must be in [-64, 64] texels");
            }
            s.originShift = static_cast<float>(shift);
        }
    }

    // What the view shows: the texel grid, the picked pixel.
    void applyViewKeys(const toml::table& table, const std::string& what, LessonSettings& s) const {
        auto name = [&](std::string_view key) { return what + " " + std::string(key); };
        if (const toml::node* n = table.get("grid")) {
            const auto* b = n->as_boolean();
            if (!b) fail(*n, name("grid") + " must be true or false, got " + typeName(*n));
            s.grid = b->get();
        }
        if (const toml::node* n = table.get("pixel")) {
            fail(*n, name("pixel") +
                         ": a lesson pins a scene point, not a screen pixel: write point = [x, y, "
                         "z] in world units (a click in `pcfscope view` prints the point)");
        }
        if (const toml::node* n = table.get("point")) s.point = readPoint(*n, name("point"));
    }

    // `point = [x, y, z]`: world units, on a surface the camera sees (lesson_pick.h).
    glm::vec3 readPoint(const toml::node& node, const std::string& name) const {
        const toml::array* array = node.as_array();
        if (!array || array->size() != 3) {
            fail(node,
                 name + " must be [x, y, z], three numbers (world units), got " +
                     (array ? "an array of " + std::to_string(array->size()) : typeName(node)));
        }
        glm::vec3 p;
        for (int k = 0; k < 3; ++k) {
            const toml::node& c = *array->get(static_cast<size_t>(k));
            double v = number(c, name + "[" + std::to_string(k) + "]");
            if (!(std::fabs(v) <= 1e6)) fail(c, name + " coordinates must be within +-1e6");
            p[k] = static_cast<float>(v);
        }
        if (!seenPoint(*mScene, p)) {
            fail(node, name + " [" + formatValue(p.x) + ", " + formatValue(p.y) + ", " +
                           formatValue(p.z) +
                           "] is not on a surface the camera sees (nothing there, or another "
                           "surface in front of it)");
        }
        return p;
    }

    // The checks that need the whole state: the kernel a method takes.
    void checkState(const toml::table& step, const std::string& what, const LessonSettings& s,
                    const SettingLines& lines) const {
        if (auto why = validateBias(static_cast<int>(s.bias), s.method)) {
            int line = std::max(lines.bias, lines.method);
            throw InputError(mSource, line > 0 ? line : lineOf(step), what + ": " + *why);
        }
        // light_size for a spot light, light_radius for a directional one: blamed on the key.
        if (std::optional<ParamProblem> why =
                mScene ? lightSizeProblem(mScene->light, s) : std::nullopt) {
            const toml::node* key = step.get(why->setting);
            throw InputError(mSource, lineOf(key ? *key : static_cast<const toml::node&>(step)),
                             what + ": " + why->text());
        }
        // Cascades where they work, frozen only where there are some (scene/cascade_view.h).
        if (auto why = mScene ? lessonCascadeProblem(*mScene, s, s.freezeCascades) : std::nullopt) {
            const toml::node* key = step.get(why->setting) ? step.get(why->setting) : &step;
            throw InputError(mSource, lineOf(*key), what + ": " + why->text());
        }
        std::optional<ParamProblem> problem = checkParams(s.ShadowSettings::pcfParams());
        if (!problem) return;
        std::string text = problem->text();  // the kernel's words are the lesson's keys
        int line = std::max(lines.method, lines.kernel);
        if (line <= 0) line = lineOf(step);
        throw InputError(mSource, line, what + ": " + text);
    }

    // Placeholders are checked now, not when shown: a typo must fail the lesson, not a class.
    void checkText(const std::string& what, const LessonStep& step) const {
        // The reads and fetch instructions this step's method issues, from the kernel itself.
        ShadowMap probe(16, 16, 1.0f);
        Trace trace = traceLookup(
            probe, vec2(0.5f), 0.5f, 0.5f,
            makeParams(step.settings.method, step.settings.kernel, step.settings.radius));
        for (const PlaceholderProblem& problem :
             placeholderProblems(step.text, static_cast<int>(trace.taps.size()),
                                 static_cast<int>(trace.fetches.size()), step.compare.parts(),
                                 trace.weights.size)) {
            attempt([&] {
                throw InputError(mSource, stepTextLine(step, problem.offset),
                                 what + " text: " + problem.problem);
            });
        }
        // A claim's placeholders index the same reads: past them is the same mistake.
        for (const StepClaim& claim : step.claims) {
            for (const std::string& inside : claimPlaceholders(claim)) {
                if (std::optional<PlaceholderProblem> problem =
                        checkPlaceholders("{" + inside + "}", static_cast<int>(trace.taps.size()),
                                          static_cast<int>(trace.fetches.size()),
                                          step.compare.parts(), trace.weights.size)) {
                    attempt([&] {
                        throw InputError(
                            mSource, claim.line,
                            what + " claim \"" + claim.text + "\": " + problem->problem);
                    });
                }
            }
        }
    }

    std::string_view mText;
    std::vector<std::string_view> mLines;
};

}  // namespace

int stepTextLine(const LessonStep& step, size_t offset) {
    auto after = std::upper_bound(step.textLineStarts.begin(), step.textLineStarts.end(), offset);
    return step.textLine + static_cast<int>(after - step.textLineStarts.begin());
}

PcfParams LessonSettings::pcfParams(glm::vec2 uv, int mapSizeTexels, float penumbraScale) const {
    vec2 rotation(1.0f, 0.0f);
    if (rotate) rotation = pcfTexelRotation(uv, ivec2(mapSizeTexels));
    return ShadowSettings::pcfParams(rotation, penumbraScale);
}

long lessonParseCount() { return gLessonParses.load(); }

Lesson parseLessonFile(const std::string& path) {
    return parseLessonString(readInputFile(path), path);
}

Lesson parseLessonString(std::string_view text, const std::string& sourceName) {
    return LessonParser(text, sourceName).parse();
}

Lesson parseLessonString(std::string_view text, const std::string& sourceName,
                         std::vector<InputError>& problems) {
    std::vector<InputError> found;
    Lesson lesson;
    try {
        lesson = LessonParser(text, sourceName, &found).parse();
    } catch (const InputError& e) {
        found.push_back(e);  // one that ends the reading (TOML syntax, no scene, no steps)
    }
    // In file order (a step's claims are read before its text).
    std::stable_sort(found.begin(), found.end(),
                     [](const InputError& a, const InputError& b) { return a.line() < b.line(); });
    problems.insert(problems.end(), found.begin(), found.end());
    return lesson;
}

}  // namespace pcf
