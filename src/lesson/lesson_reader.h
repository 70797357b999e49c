// lesson_reader.h: what reading a lesson file (lesson.cpp) is built from: its TOML values read
// with the lesson's problems, each naming the file and the line of the value at fault
// (InputError) and either thrown or, for `lesson check`, recorded while the reading goes on; and
// the readers of a step's own keys besides its settings (chart, chart_highlight, highlight,
// claims, keys, animate, compare, predict). Used by lesson.cpp only.
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "base/input_error.h"
#include "lesson/lesson.h"
#include "scene/scene.h"

namespace pcf::lesson_detail {

// The line of a value (1 at the least) and its TOML type's name, for problems.
int lineOf(const toml::node& node);
std::string typeName(const toml::node& node);
// A number as a problem quotes it ("0.25").
std::string formatValue(double v);

class LessonReader {
  public:
    // problems: when given, every problem is recorded there and the reading goes on past it
    // (`lesson check` reports them all); else the first is thrown.
    LessonReader(std::string source, std::vector<InputError>* problems)
        : mSource(std::move(source)), mProblems(problems) {}

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

    // The problem `problem` at the value's line.
    [[noreturn]] void fail(const toml::node& node, const std::string& problem) const;
    // A value of a type, or a problem naming `name` and the type found.
    std::string string(const toml::node& node, const std::string& name) const;
    int64_t integer(const toml::node& node, const std::string& name) const;
    double number(const toml::node& node, const std::string& name) const;  // finite
    // table[key], a string with more than white space in it; a key missing is blamed on `owner`.
    std::string requireText(const toml::table& table, std::string_view key, const std::string& what,
                            const toml::node& owner) const;
    // Characters as a reader counts them: UTF-8 code points (continuation bytes not counted).
    void checkLength(const toml::node& node, const std::string& what, const std::string& text,
                     size_t limit) const;
    // A TOML value as the parameter table's text reader takes it ("none", "3", "0.002", "true").
    static std::string valueText(const toml::node& v);

    // A step's own keys, read into `step` (`what`: "step 3", for problems).
    // chart, chart_highlight and highlight: what the step shows besides (or instead of) the
    // scene.
    void readChartKeys(const toml::table& table, const std::string& what, LessonStep& step) const;
    // claims = [...] and keys = [...]: strings, each claim parsed (lesson_claims.h), each key
    // one lesson_keys.h names.
    void readClaims(const toml::table& table, const std::string& what, LessonStep& step) const;
    // animate = { sweep = "sun", from = 90, to = 2, frames = 60, fps = 12, snap = false }.
    void readAnimation(const toml::table& table, const std::string& what, LessonStep& step) const;
    // compare = { key = [values, one per part], ... }: each value checked on the step's settings
    // (compare_spec.h: comparePart), a problem blamed on the compare table's line.
    void readCompare(const toml::table& table, const std::string& what, LessonStep& step) const;
    // predict = { ask = "...", choices = [...], answer = "{...}", tolerance = T } (StepPredict):
    // its texts' placeholders checked as the step's text's are (lesson_predict.h).
    void readPredict(const toml::table& table, const std::string& what, LessonStep& step) const;

  protected:
    std::string mSource;
    std::vector<InputError>* mProblems = nullptr;
    const Scene* mScene = nullptr;  // the lesson's, once read: points are checked against it

  private:
    // table[key] as a table, nullptr when absent; another type fails ("WHERE must be a table
    // (SHAPE)"), and so does a key of it not in `known`, naming them.
    const toml::table* optionalTable(const toml::table& table, const char* key,
                                     const std::string& where, const char* shape,
                                     std::initializer_list<std::string_view> known) const;
    void readChart(const toml::table& table, const std::string& what, LessonStep& step) const;
    void readHighlights(const toml::table& table, const std::string& what, LessonStep& step) const;
};

}  // namespace pcf::lesson_detail
