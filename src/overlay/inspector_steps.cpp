// inspector_steps.cpp: the step panel (lesson title, step list, the step's text, paged), the
// shadow map's thumbnail in it, and the status line along the bottom.
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

float stepsMargin(const InspectorLayout& l) { return std::max(8.0f, std::round(14.0f * l.scale)); }

float stepsBodyTop(const InspectorLayout& l, const TypeSizes& t) {
    return l.steps.y + stepsMargin(l) * 0.7f + lineHeightOf(t.head) + t.head * 0.3f;
}

void planSteps(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t) {
    const Rect& p = l.steps;
    const std::string panel = "steps";
    float margin = stepsMargin(l);
    float width = p.w - 2 * margin;
    float y = p.y + margin * 0.7f;
    int n = static_cast<int>(m.stepTitles.size());
    Rect text;
    if (l.presentation) {
        // One header: where we are and what this step is about; the list would steal the room
        // the large text needs.
        std::string head = "Step " + std::to_string(m.currentStep + 1) + " of " +
                           std::to_string(n) + ": " +
                           (m.currentStep < n ? m.stepTitles[m.currentStep] : std::string());
        std::vector<std::string> lines = wrapText(FontFace::Sans, t.body, head, width);
        bool cut = lines.size() > 2;
        if (cut) {
            std::string rest;
            for (size_t k = 1; k < lines.size(); ++k) rest += (k > 1 ? " " : "") + lines[k];
            lines.resize(2);
            lines[1] = elideText(FontFace::Sans, t.body, rest, width);
        }
        for (const std::string& line : lines) {
            pl.text({p.x + margin, y}, line, {FontFace::Sans, t.body, ACCENT}, BoxKind::Text, panel,
                    "step-title", cut);
            y += lineHeightOf(t.body);
        }
        // The step list's neighbours of this step, one line at the numbers' size (18 px at
        // projector sizes): where the lesson came from, left, and where it goes, right.
        float listPx = std::max(t.numberFloor, t.label);
        int k = m.currentStep;
        std::string prev = k > 0 ? "< " + std::to_string(k) + ". " + m.stepTitles[k - 1] : "";
        std::string next =
            k + 1 < n ? std::to_string(k + 2) + ". " + m.stepTitles[k + 1] + " >" : "";
        float half = std::floor((width - listPx) / 2);
        for (bool right : {false, true}) {
            const std::string& item = right ? next : prev;
            if (item.empty()) continue;
            std::string shown = elideText(FontFace::Sans, listPx, item, half);
            pl.text({right ? p.right() - margin : p.x + margin, y}, shown,
                    {FontFace::Sans, listPx, TEXT_DIM, right ? TextAlign::Right : TextAlign::Left},
                    BoxKind::Text, panel, "step-list", shown != item);
        }
        if (n > 1) y += lineHeightOf(listPx);
        y += t.body * 0.4f;
        text = {p.x + margin, y, width, p.bottom() - margin * 0.7f - y};
    } else {
        // The lesson's title, one line.
        std::string title = elideText(FontFace::Sans, t.head, m.title, width);
        pl.text({p.x + margin, y}, title, {FontFace::Sans, t.head, TEXT}, BoxKind::Text, panel,
                "lesson-title", title != m.title);
        y += lineHeightOf(t.head) + t.head * 0.3f;
        float bottom = p.bottom() - margin * 0.7f;
        float thumbLeft = l.thumbnail.empty() ? p.right() - margin : l.thumbnail.x - margin;
        float listW = std::round(width * 0.28f);
        float itemLh = lineHeightOf(t.item);
        // Titles wrap in the list's column; when the wrapped list would run out of the panel,
        // each keeps one line (elided); when even that is too long, the list shows the steps
        // around the current one.
        std::vector<std::vector<std::string>> labels;
        float needed = 0.0f;
        for (int k = 0; k < n; ++k) {
            labels.push_back(wrapText(FontFace::Sans, t.item,
                                      std::to_string(k + 1) + ". " + m.stepTitles[k],
                                      listW - 8.0f));
            needed += static_cast<float>(labels.back().size()) * itemLh + 4.0f;
        }
        std::vector<bool> cut(static_cast<size_t>(n), false);
        if (y + needed > bottom) {
            for (int k = 0; k < n; ++k) {
                std::string full = std::to_string(k + 1) + ". " + m.stepTitles[k];
                labels[k] = {elideText(FontFace::Sans, t.item, full, listW - 8.0f)};
                cut[k] = labels[k][0] != full;
            }
        }
        int visible = std::max(1, static_cast<int>((bottom - y) / (itemLh + 4.0f)));
        int first = 0;
        if (n > visible && y + needed > bottom) {
            first = std::clamp(m.currentStep - visible / 2, 0, n - visible);
        }
        int last = std::min(n, first + visible);
        for (int k = first; k < last; ++k) {
            bool current = k == m.currentStep;
            float h = static_cast<float>(labels[k].size()) * itemLh + 2.0f;
            if (y + h > bottom + 0.5f) break;
            Rect row{p.x + margin, y - 1.0f, listW, h};
            if (current) pl.fill(row, Colour{0.35f, 0.78f, 0.98f, 0.25f});
            for (size_t li = 0; li < labels[k].size(); ++li) {
                bool more = (k == first && first > 0) || (k == last - 1 && last < n);
                pl.text({p.x + margin + 4.0f, y + static_cast<float>(li) * itemLh}, labels[k][li],
                        {FontFace::Sans, t.item, current ? TEXT : TEXT_DIM}, BoxKind::Text, panel,
                        "step-list", cut[k] || more);
            }
            y += h + 2.0f;
        }
        float top = stepsBodyTop(l, t);
        float tx = p.x + margin + listW + margin;
        text = {tx, top, thumbLeft - tx, bottom - top};
    }
    FittedText f = fitText(m.stepText, FontFace::Sans, t.body, t.bodyFloor, text.w, text.h);
    pl.plan.textPages = f.pages;
    placeFitted(pl, f, text, m.textPage, FontFace::Sans, TEXT, panel, "step-text", "Space/Right");
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
    std::string keys = "H: keys";
    float kw = measureText(FontFace::Sans, t.status, keys).x;
    float room = s.w - 3 * pad - kw;
    float size = t.status;
    while (size > t.labelFloor && measureText(FontFace::Mono, size, m.status).x > room) {
        size = stepDown(size, t.labelFloor);
    }
    std::string status = elideText(FontFace::Mono, size, m.status, room);
    float y = s.y + (s.h - lineHeightOf(size)) * 0.5f;
    pl.text({s.x + pad, y}, status, {FontFace::Mono, size, TEXT}, BoxKind::Text, "status", "status",
            status != m.status);
    float ky = s.y + (s.h - lineHeightOf(t.status)) * 0.5f;
    pl.text({s.right() - pad, ky}, keys, {FontFace::Sans, t.status, TEXT_DIM, TextAlign::Right},
            BoxKind::Text, "status", "keys-hint");
}

}  // namespace pcf::inspector_detail
