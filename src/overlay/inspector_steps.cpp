// inspector_steps.cpp: the step panel (lesson title, step list, the step's text, paged), the
// shadow map's thumbnail in it, and the status line along the bottom.
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

float stepsMargin(const InspectorLayout& l) { return std::max(8.0f, std::round(14.0f * l.scale)); }

float stepsBodyTop(const InspectorLayout& l, const TypeSizes& t) {
    return l.steps.y + stepsMargin(l) * 0.7f + lineHeightOf(t.head) + t.head * 0.3f;
}

namespace {

// Presentation: one header, where we are and what this step is about (the list would steal the
// room the large text needs), then the step list's neighbours of this step, one line at the
// numbers' size (18 px at projector sizes): where the lesson came from, left, and where it goes,
// right. When the step's text pages, its "more" mark takes the right of that line (the next
// thing Right shows is the text's next page) and the text keeps every line of its area.
struct StepHeader {
    std::vector<std::string> title;  // at most two lines, the second elided
    bool cut = false;
    float y = 0.0f;       // the title's top
    float listY = -1.0f;  // the neighbours' line (< 0: a lesson of one step has none)
    float listPx = 0.0f;
    // A revealed question's answer (app/predict.h) takes the neighbours' line where it fits
    // there (the words keep their room).
    bool answer = false;
    Rect text;  // what is left for the step's text
};

StepHeader stepHeaderOf(const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t) {
    const Rect& p = l.steps;
    float margin = stepsMargin(l);
    float width = p.w - 2 * margin;
    StepHeader h;
    h.y = p.y + margin * 0.7f;
    int n = static_cast<int>(m.stepTitles.size());
    std::string head = "Step " + std::to_string(m.currentStep + 1) + " of " + std::to_string(n) +
                       ": " + (m.currentStep < n ? m.stepTitles[m.currentStep] : std::string());
    h.title = wrapText(FontFace::Sans, t.body, head, width);
    h.cut = h.title.size() > 2;
    if (h.cut) {
        std::string rest;
        for (size_t k = 1; k < h.title.size(); ++k) rest += (k > 1 ? " " : "") + h.title[k];
        h.title.resize(2);
        h.title[1] = elideText(FontFace::Sans, t.body, rest, width);
    }
    float y = h.y + static_cast<float>(h.title.size()) * lineHeightOf(t.body);
    h.listPx = std::max(t.numberFloor, t.label);
    h.answer = m.predict.on && m.predict.revealed &&
               measureText(FontFace::Sans, t.body, m.predict.answer).x <= width;
    if (h.answer) {
        y += lineHeightOf(t.body);
    } else if (n > 1) {
        h.listY = y;
        y += lineHeightOf(h.listPx);
    }
    y += t.body * 0.4f;
    h.text = {p.x + margin, y, width, p.bottom() - margin * 0.7f - y};
    return h;
}

// The header as stepHeaderOf placed it; markWidth > 0: the text's "more" mark, that wide, takes
// the right of the neighbours' line. While more pages follow, Right turns the page, so the next
// step is not named there; on the last page it is, left of the mark.
void planStepHeader(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                    const TypeSizes& t, const StepHeader& h, float markWidth, bool lastPage) {
    const Rect& p = l.steps;
    const std::string panel = "steps";
    float margin = stepsMargin(l);
    float width = p.w - 2 * margin;
    float y = h.y;
    for (const std::string& line : h.title) {
        pl.text({p.x + margin, y}, line, {FontFace::Sans, t.body, ACCENT}, BoxKind::Text, panel,
                "step-title", h.cut);
        y += lineHeightOf(t.body);
    }
    if (h.answer) {
        pl.text({p.x + margin, y}, m.predict.answer, {FontFace::Sans, t.body, ACCENT},
                BoxKind::Text, panel, "predict-answer");
        return;
    }
    if (h.listY < 0.0f) return;
    int n = static_cast<int>(m.stepTitles.size());
    int k = m.currentStep;
    std::string prev = k > 0 ? "< " + std::to_string(k) + ". " + m.stepTitles[k - 1] : "";
    std::string next = k + 1 < n ? std::to_string(k + 2) + ". " + m.stepTitles[k + 1] + " >" : "";
    if (markWidth > 0.0f && !lastPage) next.clear();
    // The line's room beside the mark, shared by the items it names.
    float mark = markWidth > 0.0f ? markWidth + h.listPx : 0.0f;
    float room = width - mark;
    if (!prev.empty() && !next.empty()) room = std::floor((room - h.listPx) / 2);
    for (bool right : {false, true}) {
        const std::string& item = right ? next : prev;
        if (item.empty()) continue;
        std::string shown = elideText(FontFace::Sans, h.listPx, item, room);
        pl.text({right ? p.right() - margin - mark : p.x + margin, h.listY}, shown,
                {FontFace::Sans, h.listPx, TEXT_DIM, right ? TextAlign::Right : TextAlign::Left},
                BoxKind::Text, panel, "step-list", shown != item);
    }
}

// The step list's labels, "k. title": wrapped in the list's column of width listW, or each one
// line (elided) where the wrapped list would run from y past `bottom`.
struct StepLabels {
    std::vector<std::vector<std::string>> lines;  // per step
    std::vector<bool> cut;                        // per step: elided
    float needed = 0.0f;                          // the wrapped list's height
};

StepLabels stepListLabels(const InspectorModel& m, const TypeSizes& t, float listW, float y,
                          float bottom) {
    int n = static_cast<int>(m.stepTitles.size());
    float itemLh = lineHeightOf(t.item);
    StepLabels out;
    for (int k = 0; k < n; ++k) {
        out.lines.push_back(wrapText(FontFace::Sans, t.item,
                                     std::to_string(k + 1) + ". " + m.stepTitles[k], listW - 8.0f));
        out.needed += static_cast<float>(out.lines.back().size()) * itemLh + 4.0f;
    }
    out.cut.assign(static_cast<size_t>(n), false);
    if (y + out.needed > bottom) {
        for (int k = 0; k < n; ++k) {
            std::string full = std::to_string(k + 1) + ". " + m.stepTitles[k];
            out.lines[k] = {elideText(FontFace::Sans, t.item, full, listW - 8.0f)};
            out.cut[k] = out.lines[k][0] != full;
        }
    }
    return out;
}

// The normal layout: the lesson's title, then the step list on the left (the current step
// highlighted; when even one line a step is too long, the steps around the current one).
// Returns the rect left for the step's text, right of the list.
Rect planStepList(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                  const TypeSizes& t) {
    const Rect& p = l.steps;
    const std::string panel = "steps";
    float margin = stepsMargin(l);
    float width = p.w - 2 * margin;
    float y = p.y + margin * 0.7f;
    int n = static_cast<int>(m.stepTitles.size());
    std::string title = elideText(FontFace::Sans, t.head, m.title, width);
    pl.text({p.x + margin, y}, title, {FontFace::Sans, t.head, TEXT}, BoxKind::Text, panel,
            "lesson-title", title != m.title);
    y += lineHeightOf(t.head) + t.head * 0.3f;
    float bottom = p.bottom() - margin * 0.7f;
    float thumbLeft = l.thumbnail.empty() ? p.right() - margin : l.thumbnail.x - margin;
    float listW = std::round(width * 0.28f);
    float itemLh = lineHeightOf(t.item);
    StepLabels labels = stepListLabels(m, t, listW, y, bottom);
    bool overflow = y + labels.needed > bottom;
    int visible = std::max(1, static_cast<int>((bottom - y) / (itemLh + 4.0f)));
    int first = 0;
    if (n > visible && overflow) first = std::clamp(m.currentStep - visible / 2, 0, n - visible);
    int last = std::min(n, first + visible);
    for (int k = first; k < last; ++k) {
        bool current = k == m.currentStep;
        float h = static_cast<float>(labels.lines[k].size()) * itemLh + 2.0f;
        if (y + h > bottom + 0.5f) break;
        Rect row{p.x + margin, y - 1.0f, listW, h};
        if (current) pl.fill(row, Colour{0.35f, 0.78f, 0.98f, 0.25f});
        for (size_t li = 0; li < labels.lines[k].size(); ++li) {
            bool more = (k == first && first > 0) || (k == last - 1 && last < n);
            pl.text({p.x + margin + 4.0f, y + static_cast<float>(li) * itemLh}, labels.lines[k][li],
                    {FontFace::Sans, t.item, current ? TEXT : TEXT_DIM}, BoxKind::Text, panel,
                    "step-list", labels.cut[k] || more);
        }
        y += h + 2.0f;
    }
    float top = stepsBodyTop(l, t);
    float tx = p.x + margin + listW + margin;
    return {tx, top, thumbLeft - tx, bottom - top};
}

}  // namespace

void planSteps(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t) {
    const std::string panel = "steps";
    if (!l.presentation) {
        Rect text = planStepList(pl, l, m, t);
        if (m.predict.on) {
            planPredict(pl, m, t, text);
            pl.plan.stepTextPages = pl.plan.textPages;
            return;
        }
        FittedText f = fitText(m.stepText, FontFace::Sans, t.body, t.bodyFloor, text.w, text.h);
        pl.plan.textPages = pl.plan.stepTextPages = f.pages;
        placeFitted(pl, f, text, m.textPage, FontFace::Sans, TEXT, panel, "step-text", pageKeys(m));
        return;
    }
    StepHeader h = stepHeaderOf(l, m, t);
    // A question, or an answer the header could not hold, in the text's room (app/predict.h).
    if (m.predict.on && !h.answer) {
        planStepHeader(pl, l, m, t, h, 0.0f, true);
        planPredict(pl, m, t, h.text);
        pl.plan.stepTextPages = pl.plan.textPages;
        return;
    }
    bool headerMark = h.listY >= 0.0f;
    FittedText f =
        fitText(m.stepText, FontFace::Sans, t.body, t.bodyFloor, h.text.w, h.text.h, !headerMark);
    pl.plan.textPages = pl.plan.stepTextPages = f.pages;
    float markWidth = 0.0f;
    if (f.pages > 1 && headerMark) {
        markWidth =
            measureText(FontFace::Sans, h.listPx, moreMarkText(f, m.textPage, pageKeys(m))).x;
    }
    planStepHeader(pl, l, m, t, h, markWidth, m.textPage + 1 >= f.pages);
    std::optional<MarkPlace> mark;
    if (headerMark)
        mark = MarkPlace{{h.text.x, h.listY, h.text.w, lineHeightOf(h.listPx)}, h.listPx};
    placeFitted(pl, f, h.text, m.textPage, FontFace::Sans, TEXT, panel, "step-text", pageKeys(m),
                mark);
}

void planThumbnail(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                   const TypeSizes& t) {
    if (!m.map || m.map->width() <= 0 || l.thumbnail.empty()) return;
    const ShadowMap& map = *m.map;
    Rect box = l.thumbnail;
    pl.op([=](Canvas& c) { c.strokeRect(box.expanded(2), 2.0f, Colour{0, 0, 0, 1}); });
    if (m.trace) {
        Neighbourhood n = neighbourhoodOf(*m.trace);
        float sx = box.w / static_cast<float>(map.width());
        float sy = box.h / static_cast<float>(map.height());
        Rect nb{box.x + n.origin.x * sx, box.y + n.origin.y * sy, n.size.x * sx, n.size.y * sy};
        nb = nb.expanded(std::max(0.0f, 3.0f - std::min(nb.w, nb.h) * 0.5f));
        float w = l.presentation ? 3.0f : 2.0f;
        pl.op([=](Canvas& c) { c.strokeRect(nb, w, POINT); });
    }
    // The longest caption that is no wider than the thumbnail (the step text ends beside it).
    std::string dims = std::to_string(map.width()) + " x " + std::to_string(map.height());
    std::string caption = dims;
    for (std::string c : {"shadow map " + dims, "map " + dims}) {
        if (measureText(FontFace::Sans, t.label, c).x <= box.w) {
            caption = c;
            break;
        }
    }
    pl.text({box.centre().x, box.bottom() + 4.0f}, caption,
            {FontFace::Sans, t.label, TEXT_DIM, TextAlign::Center}, BoxKind::Label, "steps",
            "thumbnail-caption");
}

void planStatus(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                const TypeSizes& t) {
    const Rect& s = l.status;
    float pad = std::max(6.0f, 10.0f * l.scale);
    // The window's hint only: a written frame has no H to press.
    std::string keys = m.interactive ? "H: keys" : "";
    float kw = keys.empty() ? 0.0f : measureText(FontFace::Sans, t.status, keys).x;
    float room = s.w - 3 * pad - kw;
    float size = t.status;
    while (size > t.labelFloor && measureText(FontFace::Mono, size, m.status).x > room) {
        size = stepDown(size, t.labelFloor);
    }
    std::string status = elideText(FontFace::Mono, size, m.status, room);
    float y = s.y + (s.h - lineHeightOf(size)) * 0.5f;
    pl.text({s.x + pad, y}, status, {FontFace::Mono, size, TEXT}, BoxKind::Text, "status", "status",
            status != m.status);
    if (keys.empty()) return;
    float ky = s.y + (s.h - lineHeightOf(t.status)) * 0.5f;
    pl.text({s.right() - pad, ky}, keys, {FontFace::Sans, t.status, TEXT_DIM, TextAlign::Right},
            BoxKind::Text, "status", "keys-hint");
}

}  // namespace pcf::inspector_detail
