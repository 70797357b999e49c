#include "app/predict.h"

#include <algorithm>
#include <vector>

#include "lesson/lesson_predict.h"

namespace pcf {

namespace {

// A kind of number the frame shows, the placeholders that name it, and what asking for one of
// them hides.
struct AnswerKind {
    std::vector<std::string_view> names;
    HiddenNumbers shows;  // what a placeholder of this kind prints
    HiddenNumbers hides;  // what a question for it hides
};

const std::vector<AnswerKind>& answerKinds() {
    static const std::vector<AnswerKind> kinds = {
        // The result: the bits would give it by a weighted sum, so they go too.
        {{"visibility", "shadow", "1-visibility", "visibility_exact", "visibility_hw8",
          "part[K].visibility", "fetch[K].value"},
         {.visibility = true},
         {.visibility = true, .bits = true}},
        // How many reads pass: the bits, and the result, which counts them under equal weights.
        {{"lit_count", "shadowed_count", "tap[K].lit", "plane_changed", "lookup_shadowed_count"},
         {.bits = true},
         {.visibility = true, .bits = true}},
        {{"weight[I,J]", "tap[K].weight", "fetch[K].weight"}, {.weights = true}, {.weights = true}},
        // A fraction: the bilinear weights are its products, so they go with it.
        {{"frac.x", "frac.y", "1-frac.x", "1-frac.y", "in_texel.x", "in_texel.y", "g.x", "g.y",
          "1-g.x", "1-g.y", "tent.s", "tent.t", "frac_hw8.x", "frac_hw8.y", "steps_hw8.x"},
         {.fraction = true},
         {.weights = true, .fraction = true}},
        // A ref: z and the bias amount give it, so the status line's amount goes with it.
        {{"ref", "depth_bias", "z", "tap[K].ref", "tap[K].shift", "tap[K].margin",
          "tap[K].lookup_margin"},
         {.refs = true},
         {.refs = true}},
        {{"tap[K].depth"}, {.depths = true}, {.depths = true}},
        {{"taps", "texels", "gathers", "hw_taps", "fetches", "distinct"},
         {.counts = true},
         {.counts = true}},
    };
    return kinds;
}

const AnswerKind* kindOf(std::string_view name) {
    for (const AnswerKind& k : answerKinds()) {
        if (std::find(k.names.begin(), k.names.end(), name) != k.names.end()) return &k;
    }
    return nullptr;
}

bool overlap(const HiddenNumbers& a, const HiddenNumbers& b) {
    return (a.visibility && b.visibility) || (a.bits && b.bits) || (a.weights && b.weights) ||
           (a.fraction && b.fraction) || (a.refs && b.refs) || (a.depths && b.depths) ||
           (a.counts && b.counts);
}

}  // namespace

std::optional<HiddenNumbers> hiddenForAnswer(std::string_view name) {
    const AnswerKind* k = kindOf(name);
    if (!k) return std::nullopt;
    return k->hides;
}

std::optional<std::string> predictStepProblem(const StepPredict& p) {
    std::string name = predictAnswerName(p);
    std::optional<HiddenNumbers> hidden = hiddenForAnswer(name);
    if (!hidden) {
        return "predict answer " + p.answer +
               " is not a number the lookup computes for the question to hide (ask for a "
               "visibility, a bit count, a weight, a fraction, a ref or depth, or a fetch count)";
    }
    for (const std::string& used : placeholdersIn(p.ask)) {
        const AnswerKind* k = kindOf(used);
        if (k && overlap(k->shows, *hidden)) {
            return "predict ask prints {" + used + "}, which the question hides until the " +
                   "answer " + p.answer + " is revealed";
        }
    }
    return std::nullopt;
}

}  // namespace pcf
