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

int lineOf(const toml::node& node) {
    return std::max(1, static_cast<int>(node.source().begin.line));
}

std::string typeName(const toml::node& node) {
    std::ostringstream s;
    s << node.type();
    return s.str();
}

std::string formatValue(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

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

class LessonParser {
  public:
    // problems: when given, every problem is recorded there and the reading goes on past it
    // (`lesson check` reports them all); else the first is thrown.
    LessonParser(std::string_view text, std::string source,
                 std::vector<InputError>* problems = nullptr)
        : mText(text), mSource(std::move(source)), mProblems(problems) {
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

    // Runs one check: without a problem list its problem is thrown; with one, recorded, and the
    // reading goes on. Returns whether it passed.
    template <class F>
    bool attempt(F&& check) const {
        if (!mProblems) {
            check();
            return true;
        }
        try {
            check();
            return true;
        } catch (const InputError& e) {
            mProblems->push_back(e);
            return false;
        }
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

    // predict = { ask = "...", choices = [...], answer = "{...}", tolerance = T } (StepPredict):
    // its texts' placeholders checked as the step's text's are (lesson_predict.h).
    void readPredict(const toml::table& table, const std::string& what, LessonStep& step) const {
        const toml::node* node = table.get("predict");
        if (!node) return;
        const toml::table* p = node->as_table();
        std::string where = what + " predict";
        if (!p) fail(*node, where + " must be a table ({ ask = \"...\", answer = \"{...}\" })");
        for (auto&& [key, value] : *p) {
            std::string_view k = key.str();
            if (k == "ask" || k == "choices" || k == "answer" || k == "tolerance") continue;
            fail(value, where + " has unknown key '" + std::string(k) +
                            "' (known: ask, choices, answer, tolerance)");
        }
        StepPredict predict;
        predict.line = lineOf(*node);
        predict.ask = requireText(*p, "ask", where, *p);
        predict.answer = requireText(*p, "answer", where, *p);
        if (const toml::node* c = p->get("choices")) {
            const toml::array* array = c->as_array();
            if (!array) fail(*c, where + " choices must be an array of strings");
            for (const toml::node& e : *array) {
                const auto* v = e.as_string();
                if (!v) fail(e, where + " choices must be strings, got " + typeName(e));
                predict.choices.push_back(v->get());
            }
        }
        if (const toml::node* t = p->get("tolerance")) {
            predict.tolerance = number(*t, where + " tolerance");
        }
        ShadowMap probe(16, 16, 1.0f);
        Trace trace = traceLookup(
            probe, vec2(0.5f), 0.5f, 0.5f,
            makeParams(step.settings.method, step.settings.kernel, step.settings.radius));
        if (auto problem = predictProblem(
                predict, p->get("tolerance") != nullptr, static_cast<int>(trace.taps.size()),
                static_cast<int>(trace.fetches.size()), step.compare.parts())) {
            fail(*node, where + ": " + *problem);
        }
        step.predict = std::move(predict);
    }

    // chart, chart_highlight and highlight: what the step shows besides (or instead of) the
    // scene.
    void readChartKeys(const toml::table& table, const std::string& what, LessonStep& step) const {
        attempt([&] { readChart(table, what, step); });
        attempt([&] { readHighlights(table, what, step); });
    }

    void readChart(const toml::table& table, const std::string& what, LessonStep& step) const {
        if (table.get("chart")) {
            std::string chart = requireText(table, "chart", what, table);
            // "figures/stability.csv#shimmer": which of a stability.csv's charts to show.
            size_t hash = chart.find('#');
            std::string view = hash == std::string::npos ? "" : chart.substr(hash);
            std::filesystem::path p =
                std::filesystem::path(mSource).parent_path() / chart.substr(0, hash);
            // What is there, said as it is: a FIFO or a folder is not "not found".
            std::error_code ec;
            std::filesystem::file_status status = std::filesystem::status(p, ec);
            if (!std::filesystem::is_regular_file(status)) {
                std::string why = !std::filesystem::exists(status) ? "not found"
                                  : std::filesystem::is_directory(status)
                                      ? "is a directory"
                                      : "is not a regular file (a FIFO, device or socket)";
                fail(*table.get("chart"),
                     what + " chart '" + chart + "' " + why + " (looked at " + p.string() + ")");
            }
            step.chart = p.string() + view;
            step.chartLine = lineOf(*table.get("chart"));
        }
    }

    void readHighlights(const toml::table& table, const std::string& what, LessonStep& step) const {
        if (const toml::node* h = table.get("chart_highlight")) {
            // That the chart is a bench chart (not a stability chart, "PATH#NAME") is checked
            // with the file (charts/step_chart.h: checkStepChartHighlight).
            if (step.chart.empty()) {
                fail(*h, what + " chart_highlight needs a bench chart (chart = \"....csv\")");
            }
            step.chartHighlight = requireText(table, "chart_highlight", what, table);
            step.chartHighlightLine = lineOf(*h);
        }
        if (const toml::node* h = table.get("highlight")) {
            const auto* v = h->as_integer();
            if (!v || v->get() < 1 || v->get() > 64) {
                fail(*h, what +
                             " highlight must be a fetch number 1..64 (the instruction the "
                             "text talks about), got " +
                             typeName(*h));
            }
            step.highlightFetch = static_cast<int>(v->get());
        }
    }

    // claims = [...] and keys = [...]: strings, each claim parsed (lesson_claims.h), each key
    // one lesson_keys.h names.
    void readClaims(const toml::table& table, const std::string& what, LessonStep& step) const {
        auto strings = [&](const char* key) {
            std::vector<std::pair<std::string, const toml::node*>> out;
            const toml::node* node = table.get(key);
            if (!node) return out;
            const toml::array* array = node->as_array();
            if (!array) fail(*node, what + " " + key + " must be an array of strings");
            for (const toml::node& e : *array) {
                const auto* s = e.as_string();
                if (!s)
                    fail(e, what + " " + key + " must be an array of strings, got " + typeName(e));
                out.emplace_back(s->get(), &e);
            }
            return out;
        };
        std::vector<std::pair<std::string, const toml::node*>> claims, keys;
        attempt([&] { claims = strings("claims"); });
        attempt([&] { keys = strings("keys"); });
        for (const auto& [text, node] : claims) {
            attempt([&] {
                StepClaim claim{text, lineOf(*node), nullptr};
                try {
                    claim.parsed = parseClaim(text);
                } catch (const std::invalid_argument& e) {
                    fail(*node, what + " claim \"" + text + "\": " + e.what());
                }
                step.claims.push_back(std::move(claim));
            });
        }
        for (const auto& [key, node] : keys) {
            attempt([&] {
                const std::vector<std::string>& known = settingKeyNames();
                if (std::find(known.begin(), known.end(), key) == known.end()) {
                    std::string names;
                    for (const std::string& k : known) names += (names.empty() ? "" : ", ") + k;
                    fail(*node, what + " keys: unknown key '" + key + "' (known: " + names + ")");
                }
                step.keys.push_back(key);
                step.keysLine = lineOf(*node);
            });
        }
    }

    // animate = { sweep = "sun", from = 90, to = 2, frames = 60, fps = 12, snap = false }.
    void readAnimation(const toml::table& table, const std::string& what, LessonStep& step) const {
        const toml::node* node = table.get("animate");
        if (!node) return;
        const toml::table* a = node->as_table();
        if (!a) fail(*node, what + " animate must be a table ({ sweep = \"sun\", ... })");
        std::string where = what + " animate";
        for (auto&& [key, value] : *a) {
            std::string_view k = key.str();
            if (k == "sweep" || k == "from" || k == "to" || k == "frames" || k == "fps" ||
                k == "snap") {
                continue;
            }
            fail(value, where + " has unknown key '" + std::string(k) +
                            "' (known: sweep, from, to, frames, fps, snap)");
        }
        StepAnimation anim;
        anim.line = lineOf(*node);
        std::string sweep = requireText(*a, "sweep", where, *a);
        std::optional<AnimationSweep> known = animationSweepFromName(sweep);
        if (!known) {
            fail(*node, where + " sweep '" + sweep +
                            "' is not one of: " + std::string(ANIMATION_SWEEP_NAMES));
        }
        anim.sweep = *known;
        if (!step.chart.empty()) fail(*node, where + ": a chart step cannot move");
        auto integer = [&](const char* key, int lo, int hi, int& out) {
            const toml::node* n = a->get(key);
            if (!n) return;
            const auto* v = n->as_integer();
            if (!v || v->get() < lo || v->get() > hi) {
                fail(*n, where + " " + key + " must be a whole number in " + std::to_string(lo) +
                             ".." + std::to_string(hi));
            }
            out = static_cast<int>(v->get());
        };
        integer("frames", 2, MAX_ANIMATION_FRAMES, anim.frames);
        integer("fps", 1, 60, anim.fps);
        for (const char* key : {"from", "to"}) {
            if (const toml::node* n = a->get(key)) {
                double v = number(*n, where + " " + key);
                if (auto why = animationEndProblem(anim.sweep, v)) fail(*node, where + *why);
                (key[0] == 'f' ? anim.from : anim.to) = v;
            }
        }
        if (const toml::node* n = a->get("snap")) {
            const auto* b = n->as_boolean();
            if (!b) fail(*n, where + " snap must be true or false, got " + typeName(*n));
            anim.snap = b->get();
        }
        step.animate = anim;
    }

    // compare = { key = [values, one per part], ... }: each value checked on the step's settings
    // (compare_spec.h: comparePart), a problem blamed on the compare table's line.
    void readCompare(const toml::table& table, const std::string& what, LessonStep& step) const {
        const toml::node* node = table.get("compare");
        if (!node) return;
        const toml::table* keys = node->as_table();
        if (!keys || keys->empty()) {
            fail(*node, what +
                            " compare must be a table of arrays, e.g. compare = { bias = "
                            "[\"none\", \"constant\", \"slope\"] }");
        }
        try {
            for (auto&& [key, values] : *keys) {
                const toml::array* array = values.as_array();
                if (!array)
                    fail(values, what + " compare " + std::string(key.str()) +
                                     " must be an array, one value per part");
                std::vector<std::string> texts;
                for (const toml::node& v : *array) texts.push_back(valueText(v));
                addCompareKey(step.compare, std::string(key.str()), std::move(texts));
            }
            for (int part = 0; part < step.compare.parts(); ++part) {
                LessonSettings s = comparePart(step.settings, step.compare, part);
                if (std::optional<ParamProblem> why =
                        mScene ? lightSizeProblem(mScene->light, s) : std::nullopt) {
                    fail(*node, what + " compare: " + why->text());
                }
                if (s.cascades > 1) {
                    fail(*node, what + " compare: cascades " + std::to_string(s.cascades) +
                                    ": a split view compares maps of one layer");
                }
            }
        } catch (const std::invalid_argument& e) {
            fail(*node, what + " " + e.what());
        }
        step.compareLine = lineOf(*node);
    }

    // A TOML value as the parameter table's text reader takes it ("none", "3", "0.002", "true").
    static std::string valueText(const toml::node& v) {
        if (const auto* s = v.as_string()) return s->get();
        if (const auto* b = v.as_boolean()) return b->get() ? "true" : "false";
        if (const auto* i = v.as_integer()) return std::to_string(i->get());
        if (const auto* f = v.as_floating_point()) {
            std::ostringstream s;
            s.precision(9);
            s << f->get();
            return s.str();
        }
        return "(" + typeName(v) + ")";
    }

  private:
    // Characters as a reader counts them: UTF-8 code points (continuation bytes not counted).
    void checkLength(const toml::node& node, const std::string& what, const std::string& text,
                     size_t limit) const {
        size_t chars = 0;
        for (char c : text) chars += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1 : 0;
        if (chars > limit) {
            fail(node, what + " is " + std::to_string(chars) + " characters; the limit is " +
                           std::to_string(limit));
        }
    }

    [[noreturn]] void fail(const toml::node& node, const std::string& problem) const {
        throw InputError(mSource, lineOf(node), problem);
    }

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

    std::string requireText(const toml::table& table, std::string_view key, const std::string& what,
                            const toml::node& owner) const {
        const toml::node* node = table.get(key);
        if (!node) fail(owner, what + " has no " + std::string(key));
        const auto* s = node->as_string();
        if (!s)
            fail(*node,
                 what + " " + std::string(key) + " must be a string, got " + typeName(*node));
        std::string value = s->get();
        if (value.find_first_not_of(" \t\r\n") == std::string::npos) {
            fail(*node, what + " " + std::string(key) + " must not be empty");
        }
        return value;
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

    std::string string(const toml::node& node, const std::string& name) const {
        const auto* s = node.as_string();
        if (!s) fail(node, name + " must be a string, got " + typeName(node));
        return s->get();
    }

    int64_t integer(const toml::node& node, const std::string& name) const {
        const auto* i = node.as_integer();
        if (!i) fail(node, name + " must be an integer, got " + typeName(node));
        return i->get();
    }

    double number(const toml::node& node, const std::string& name) const {
        double v = 0.0;
        if (const auto* i = node.as_integer()) {
            v = static_cast<double>(i->get());
        } else if (const auto* f = node.as_floating_point()) {
            v = f->get();
        } else {
            fail(node, name + " must be a number, got " + typeName(node));
        }
        if (!std::isfinite(v)) fail(node, name + " must be finite, got " + formatValue(v));
        return v;
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
    std::string mSource;
    std::vector<InputError>* mProblems = nullptr;
    const Scene* mScene = nullptr;  // the lesson's, once read: points are checked against it
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
