// inspector_predict.cpp: a question in the step panel (a predict step before its reveal, an
// exercise item): the question, its choices and what was typed; after the reveal, the answer
// above the step's words. And the roles a frame with hidden numbers does not draw.
#include "overlay/inspector_plan.h"

namespace pcf {

std::vector<std::string> hiddenRoles(const HiddenNumbers& hidden) {
    std::vector<std::string> roles;
    if (hidden.visibility) roles.push_back("visibility");
    if (hidden.bits) roles.push_back("cell-bit");
    if (hidden.weights) roles.insert(roles.end(), {"cell-weight", "weight-bar"});
    if (hidden.fraction) roles.insert(roles.end(), {"fx", "fy", "fx-hw8", "fy-hw8"});
    if (hidden.refs) roles.push_back("cell-ref");
    if (hidden.depths) roles.push_back("cell-depth");
    // The formula holds every number of the lookup: any hidden one hides it.
    if (hidden.any()) roles.push_back("formula");
    return roles;
}

namespace inspector_detail {

namespace {

// The choices, lettered ("A  0.25"), flowed left to right and onto more lines where the area is
// narrow: each one's top-left from the top of the list, and the list's height.
struct ChoiceFlow {
    std::vector<std::string> labels;
    std::vector<glm::vec2> at;
    float height = 0.0f;
};

ChoiceFlow flowChoices(const PredictPanel& p, const TypeSizes& t, float width) {
    ChoiceFlow f;
    if (p.choices.empty()) return f;
    float lh = lineHeightOf(t.body);
    float gap = t.body * 2.0f;
    float x = 0.0f, y = t.body * 0.6f;
    for (size_t k = 0; k < p.choices.size(); ++k) {
        std::string label = std::string(1, static_cast<char>('A' + k)) + "  " + p.choices[k];
        label = elideText(FontFace::Mono, t.body, label, width);
        float w = measureText(FontFace::Mono, t.body, label).x;
        if (x > 0.0f && x + w > width) {
            x = 0.0f;
            y += lh;
        }
        f.labels.push_back(label);
        f.at.push_back({x, y});
        x += w + gap;
    }
    f.height = y + lh;
    return f;
}

void planChoices(Planner& pl, const ChoiceFlow& f, const TypeSizes& t, glm::vec2 origin) {
    for (size_t k = 0; k < f.labels.size(); ++k) {
        pl.text(origin + f.at[k], f.labels[k], {FontFace::Mono, t.body, TEXT}, BoxKind::Text,
                "steps", "predict-choice");
    }
}

// The lines at the bottom of the area, bottom up: the hint (how to answer and reveal) and what
// was typed. Returns the top of what they take.
float planQuestionFoot(Planner& pl, const PredictPanel& p, const TypeSizes& t, const Rect& area) {
    const std::string panel = "steps";
    float y = area.bottom();
    float hintPx = std::max(t.labelFloor, t.label);
    if (!p.hint.empty()) {
        y -= lineHeightOf(hintPx);
        std::string hint = elideText(FontFace::Sans, hintPx, p.hint, area.w);
        pl.text({area.x, y}, hint, {FontFace::Sans, hintPx, TEXT_DIM}, BoxKind::Text, panel,
                "predict-hint", hint != p.hint);
    }
    if (!p.typed.empty()) {
        y -= lineHeightOf(t.body);
        std::string typed = elideText(FontFace::Mono, t.body, "your answer: " + p.typed, area.w);
        pl.text({area.x, y}, typed, {FontFace::Mono, t.body, ACCENT}, BoxKind::Text, panel,
                "predict-typed");
    }
    return y - t.body * 0.4f;
}

}  // namespace

void planPredict(Planner& pl, const InspectorModel& m, const TypeSizes& t, const Rect& area) {
    const PredictPanel& p = m.predict;
    const std::string panel = "steps";
    if (p.revealed) {
        // The answer on every page of the words, so that each page reads alone; the two share
        // one type size, stepped down together towards the floor before the words page.
        FittedText a, f;
        Rect rest = area;
        for (float size = t.body;; size = stepDown(size, t.bodyFloor)) {
            a = fitText(p.answer, FontFace::Sans, size, size, area.w, area.h * 0.4f);
            float used = static_cast<float>(a.lines.size()) * a.lineHeight + size * 0.3f;
            rest = {area.x, area.y + used, area.w, std::max(0.0f, area.h - used)};
            f = fitText(m.stepText, FontFace::Sans, size, size, rest.w, rest.h);
            if (f.pages == 1 || size <= t.bodyFloor) break;
        }
        placeFitted(pl, a, area, 0, FontFace::Sans, ACCENT, panel, "predict-answer", "");
        pl.plan.textPages = f.pages;
        placeFitted(pl, f, rest, m.textPage, FontFace::Sans, TEXT, panel, "step-text", pageKeys(m));
        return;
    }
    // The question, with its choices right under it, above the foot.
    float foot = planQuestionFoot(pl, p, t, area);
    ChoiceFlow choices = flowChoices(p, t, area.w);
    Rect ask{area.x, area.y, area.w, std::max(0.0f, foot - area.y - choices.height)};
    FittedText f = fitText(p.ask, FontFace::Sans, t.body, t.bodyFloor, ask.w, ask.h);
    pl.plan.textPages = f.pages;
    float used = placeFitted(pl, f, ask, m.textPage, FontFace::Sans, TEXT, panel, "predict-ask",
                             pageKeys(m));
    planChoices(pl, choices, t, {area.x, area.y + (f.pages > 1 ? ask.h : used)});
}

}  // namespace inspector_detail

}  // namespace pcf
