// lesson_reader.cpp: a lesson file's TOML values and a step's own keys (lesson_reader.h).
#include "lesson/lesson_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "kernel/methods.h"
#include "kernel/shadow_map.h"
#include "kernel/trace.h"
#include "lesson/lesson_claims.h"
#include "lesson/lesson_keys.h"
#include "lesson/lesson_predict.h"
#include "scene/light.h"

namespace pcf::lesson_detail {

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

void LessonReader::checkLength(const toml::node& node, const std::string& what,
                               const std::string& text, size_t limit) const {
    size_t chars = 0;
    for (char c : text) chars += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1 : 0;
    if (chars > limit) {
        fail(node, what + " is " + std::to_string(chars) + " characters; the limit is " +
                       std::to_string(limit));
    }
}

void LessonReader::fail(const toml::node& node, const std::string& problem) const {
    throw InputError(mSource, lineOf(node), problem);
}

std::string LessonReader::requireText(const toml::table& table, std::string_view key,
                                      const std::string& what, const toml::node& owner) const {
    const toml::node* node = table.get(key);
    if (!node) fail(owner, what + " has no " + std::string(key));
    const auto* s = node->as_string();
    if (!s)
        fail(*node, what + " " + std::string(key) + " must be a string, got " + typeName(*node));
    std::string value = s->get();
    if (value.find_first_not_of(" \t\r\n") == std::string::npos) {
        fail(*node, what + " " + std::string(key) + " must not be empty");
    }
    return value;
}

std::string LessonReader::string(const toml::node& node, const std::string& name) const {
    const auto* s = node.as_string();
    if (!s) fail(node, name + " must be a string, got " + typeName(node));
    return s->get();
}

int64_t LessonReader::integer(const toml::node& node, const std::string& name) const {
    const auto* i = node.as_integer();
    if (!i) fail(node, name + " must be an integer, got " + typeName(node));
    return i->get();
}

double LessonReader::number(const toml::node& node, const std::string& name) const {
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

std::string LessonReader::valueText(const toml::node& v) {
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

const toml::table* LessonReader::optionalTable(
    const toml::table& table, const char* key, const std::string& where, const char* shape,
    std::initializer_list<std::string_view> known) const {
    const toml::node* node = table.get(key);
    if (!node) return nullptr;
    const toml::table* t = node->as_table();
    if (!t) fail(*node, where + " must be a table (" + shape + ")");
    std::string names;
    for (std::string_view k : known) names += (names.empty() ? "" : ", ") + std::string(k);
    for (auto&& [k, value] : *t) {
        if (std::find(known.begin(), known.end(), k.str()) != known.end()) continue;
        fail(value,
             where + " has unknown key '" + std::string(k.str()) + "' (known: " + names + ")");
    }
    return t;
}

void LessonReader::readChartKeys(const toml::table& table, const std::string& what,
                                 LessonStep& step) const {
    attempt([&] { readChart(table, what, step); });
    attempt([&] { readHighlights(table, what, step); });
}

void LessonReader::readChart(const toml::table& table, const std::string& what,
                             LessonStep& step) const {
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

void LessonReader::readHighlights(const toml::table& table, const std::string& what,
                                  LessonStep& step) const {
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

void LessonReader::readClaims(const toml::table& table, const std::string& what,
                              LessonStep& step) const {
    auto strings = [&](const char* key) {
        std::vector<std::pair<std::string, const toml::node*>> out;
        const toml::node* node = table.get(key);
        if (!node) return out;
        const toml::array* array = node->as_array();
        if (!array) fail(*node, what + " " + key + " must be an array of strings");
        for (const toml::node& e : *array) {
            const auto* s = e.as_string();
            if (!s) fail(e, what + " " + key + " must be an array of strings, got " + typeName(e));
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

void LessonReader::readAnimation(const toml::table& table, const std::string& what,
                                 LessonStep& step) const {
    std::string where = what + " animate";
    const toml::table* a = optionalTable(table, "animate", where, "{ sweep = \"sun\", ... }",
                                         {"sweep", "from", "to", "frames", "fps", "snap"});
    if (!a) return;
    const toml::node* node = table.get("animate");
    StepAnimation anim;
    anim.line = lineOf(*node);
    std::string sweep = requireText(*a, "sweep", where, *a);
    std::optional<AnimationSweep> known = animationSweepFromName(sweep);
    if (!known) {
        fail(*node,
             where + " sweep '" + sweep + "' is not one of: " + std::string(ANIMATION_SWEEP_NAMES));
    }
    anim.sweep = *known;
    if (!step.chart.empty()) fail(*node, where + ": a chart step cannot move");
    auto integer = [&](const char* key, int lo, int hi, int& out) {
        const toml::node* n = a->get(key);
        if (!n) return;
        const auto* v = n->as_integer();
        if (!v || v->get() < lo || v->get() > hi) {
            fail(*n, where + " " + key + " must be a whole number in " + std::to_string(lo) + ".." +
                         std::to_string(hi));
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

void LessonReader::readCompare(const toml::table& table, const std::string& what,
                               LessonStep& step) const {
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

void LessonReader::readPredict(const toml::table& table, const std::string& what,
                               LessonStep& step) const {
    std::string where = what + " predict";
    const toml::table* p =
        optionalTable(table, "predict", where, "{ ask = \"...\", answer = \"{...}\" }",
                      {"ask", "choices", "answer", "tolerance"});
    if (!p) return;
    const toml::node* node = table.get("predict");
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
    Trace trace =
        traceLookup(probe, vec2(0.5f), 0.5f, 0.5f,
                    makeParams(step.settings.method, step.settings.kernel, step.settings.radius));
    if (auto problem = predictProblem(
            predict, p->get("tolerance") != nullptr, static_cast<int>(trace.taps.size()),
            static_cast<int>(trace.fetches.size()), step.compare.parts())) {
        fail(*node, where + ": " + *problem);
    }
    step.predict = std::move(predict);
}

}  // namespace pcf::lesson_detail
