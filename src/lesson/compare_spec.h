// compare_spec.h: what a split view compares (issue 20, "side by side"): two or three parts, each
// the same step and pinned point with some parameters of the one parameter table
// (kernel/settings.h PARAMS) set otherwise. A lesson step says it as
//   compare = { bias = ["none", "constant", "slope"] }
// and `export --compare` / `animate --compare` as "bias=none,constant,slope"; several keys take
// one value per part each ("method=nearest,tent kernel=1,5"). Every other setting is the step's
// (or the live one the viewer's keys made), so the parts differ in exactly the named parameters.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pcf {

struct LessonSettings;  // lesson.h, which holds a step's CompareSpec

// A split view has 2 or 3 parts: a third of a 1280-pixel frame is the narrowest scene that still
// shows the pinned point's texels and a label.
constexpr int MIN_COMPARE_PARTS = 2;
constexpr int MAX_COMPARE_PARTS = 3;

struct CompareSpec {
    std::vector<std::string> keys;                 // parameter keys, in the order given
    std::vector<std::vector<std::string>> values;  // values[key][part], as written
    bool empty() const { return keys.empty(); }
    int parts() const { return keys.empty() ? 0 : static_cast<int>(values.front().size()); }
    bool operator==(const CompareSpec&) const = default;
};

// Adds one key with its values (one per part): throws std::invalid_argument when the key is not
// a parameter, is given twice, or the count is not 2..3 or differs from the other keys'.
void addCompareKey(CompareSpec& spec, const std::string& key, std::vector<std::string> values);

// "bias=none,constant,slope method=nearest,tent ...": keys separated by spaces, values by commas.
// Throws std::invalid_argument saying what is wrong.
CompareSpec parseCompareSpec(std::string_view text);
// The inverse: "bias=none,constant,slope".
std::string compareSpecText(const CompareSpec& spec);

// `base` with part `part`'s values set: names in their canonical spelling, numbers in their
// parameter's range; a method change keeps the kernel when the method takes it (fitKernel) unless
// kernel is itself compared. Throws std::invalid_argument naming the key and value, also when the
// combination is one the kernel refuses (tent with kernel 4, a bias mode the method cannot take).
LessonSettings comparePart(const LessonSettings& base, const CompareSpec& spec, int part);

// The part's label, its values in the table's words: "bias slope", "method tent, kernel 5".
std::string comparePartLabel(const CompareSpec& spec, int part);

}  // namespace pcf
