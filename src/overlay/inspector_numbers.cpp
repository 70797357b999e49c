// inspector_numbers.cpp: the inspector panel's words and numbers: the header (method,
// visibility, fetch counts, uv, ref, bias), the notes on what the cells leave out, the legend of
// the marks drawn, and the formula with its numbers from the kernel's own explanation.
#include "kernel/methods.h"
#include "kernel/trace_explain.h"
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

// The header's title line and the counts under it are this far apart.
constexpr float HEADER_GAP_PX = 4.0f;

namespace {

// The header's counts: fetch counts (a moment method's one bilinear read of its moments), then uv,
// ref and bias; each hidden number a "?" (a count hidden keeps the plural, which would give a 1
// away).
std::string countsText(const Trace& tr, const HiddenNumbers& hidden) {
    auto plural = [&](int n, const char* one, const char* many) {
        if (hidden.counts) return std::string(HIDDEN_NUMBER) + " " + many;
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    // A moment method reads its filtered moments map once, bilinearly (its map pass is the
    // moments pass, kernel/methods.h): its texels hold moments, not depths to compare.
    std::string counts =
        readsMoments(tr.params.method)
            ? plural(static_cast<int>(tr.fetches.size()), "bilinear read", "bilinear reads") +
                  " of the filtered moments (" + plural(tr.counts.texels, "texel", "texels") + ")"
            : plural(tr.counts.texels, "texel read", "texel reads");
    if (tr.counts.gathers) counts += ", " + plural(tr.counts.gathers, "gather", "gathers");
    if (tr.counts.hwTaps)
        counts += ", " + plural(tr.counts.hwTaps, "hardware tap", "hardware taps");
    counts += "\nuv (" + fixed(tr.uv.x, 4) + ", " + fixed(tr.uv.y, 4) + ")  ref " +
              (hidden.refs ? std::string(HIDDEN_NUMBER) : fixed(tr.ref, 4)) + "  bias " +
              std::string(biasName(tr.bias.modeId()));
    std::string cascade = cascadeHeaderText(tr);
    if (!cascade.empty()) counts += "\n" + cascade;
    std::string blend = cascadeBlendText(tr, hidden);
    if (!blend.empty()) counts += "\n" + blend;
    return counts;
}

// The counts on one line when it holds them, else wrapped (and each line wrapped again).
std::vector<std::string> countsLines(const std::string& counts, const TypeSizes& t, float width) {
    std::string oneLine = counts;
    std::replace(oneLine.begin(), oneLine.end(), '\n', ' ');
    oneLine.insert(oneLine.find(" uv ("), "  ");
    if (size_t c = oneLine.find(" cascade "); c != std::string::npos) oneLine.insert(c, "  ");
    if (measureText(FontFace::Mono, t.number, oneLine).x <= width) return {oneLine};
    return wrapText(FontFace::Mono, t.number, counts, width);
}

}  // namespace

Header headerOf(const Trace& tr, const TypeSizes& t, float width) {
    Header h;
    const MethodInfo& info = methodInfo(tr.params.method);
    h.title = std::string(info.name);
    if (info.usesKernel) h.title += "  N = " + std::to_string(tr.params.kernel);
    if (info.usesRadius) h.title += "  R = " + formatNumber(tr.params.radius);
    h.result = "visibility = " + formatNumber(tr.visibility);
    float tw = measureText(FontFace::Mono, t.head, h.title).x;
    float rw = measureText(FontFace::Mono, t.head, h.result).x;
    h.resultOnOwnLine = tw + rw + t.head > width;
    h.counts = countsLines(countsText(tr, {}), t, width);
    float headLh = lineHeightOf(t.head);
    h.height = headLh * (h.resultOnOwnLine ? 2.0f : 1.0f) + HEADER_GAP_PX +
               lineHeightOf(t.number) * static_cast<float>(h.counts.size());
    return h;
}

float inspectorMargin(const InspectorLayout& l) {
    return std::max(8.0f, std::round(18.0f * l.scale));
}

namespace {

std::string formulaText(const Trace& tr, const HiddenNumbers& hidden) {
    // Every number of the lookup is in it: a question shows none of it.
    if (hidden.any()) return "(the formula is hidden until the answer is revealed)";
    std::string out;
    std::vector<TraceStep> steps = explainTrace(tr);
    for (size_t k = 0; k < steps.size(); ++k) {
        const TraceStep& s = steps[k];
        bool last = k + 1 == steps.size();
        if (last || s.kind == TraceStepKind::Lerp) {
            if (!out.empty()) out += "\n";
            out += s.text;
        }
    }
    return out;
}

}  // namespace

void planHeader(Planner& pl, const InspectorLayout& l, const Header& h, const TypeSizes& t,
                float margin, const Trace& tr, const HiddenNumbers& hidden) {
    const Rect& p = l.inspector;
    const std::string panel = "inspector";
    float y = p.y + margin;
    pl.text({p.x + margin, y}, h.title, {FontFace::Mono, t.head, ACCENT}, BoxKind::Text, panel,
            "method");
    std::string result =
        hidden.visibility ? "visibility = " + std::string(HIDDEN_NUMBER) : h.result;
    std::string role = hidden.visibility ? "masked" : "visibility";
    if (h.resultOnOwnLine) {
        y += lineHeightOf(t.head);
        pl.text({p.x + margin, y}, result, {FontFace::Mono, t.head, TEXT}, BoxKind::Number, panel,
                role);
    } else {
        pl.text({p.right() - margin, y}, result, {FontFace::Mono, t.head, TEXT, TextAlign::Right},
                BoxKind::Number, panel, role);
    }
    y += lineHeightOf(t.head) + HEADER_GAP_PX;
    std::vector<std::string> counts = h.counts;
    if (hidden.counts || hidden.refs) {
        counts = countsLines(countsText(tr, hidden), t, p.w - 2 * margin);
    }
    for (const std::string& c : counts) {
        pl.text({p.x + margin, y}, c, {FontFace::Mono, t.number, TEXT_DIM}, BoxKind::Number, panel,
                "counts");
        y += lineHeightOf(t.number);
    }
}

namespace {

// What the cells leave out, said in words, from `y` down; returns the new y.
float planNotes(Planner& pl, const InspectorLayout& l, int hidden, const TypeSizes& t, float margin,
                float y) {
    const Rect& p = l.inspector;
    float width = p.w - 2 * margin;
    std::vector<std::string> notes;
    if (hidden > 0) {
        notes.push_back("numbers of " + std::to_string(hidden) +
                        (hidden == 1 ? " cell" : " cells") + " left out: no room at this size");
    }
    for (const std::string& note : notes) {
        FittedText f =
            fitText(note, FontFace::Sans, t.label, t.labelFloor, width, 3 * lineHeightOf(t.label));
        y += placeFitted(pl, f, {p.x + margin, y, width, 3 * lineHeightOf(t.label)}, 0,
                         FontFace::Sans, TEXT_DIM, "inspector", "view-note", "");
    }
    return y;
}

// The formula with its numbers, from the kernel's own explanation, fitted into `box` at the
// numbers' size down to their floor; `page` of it when it pages.
FittedText fitFormula(const InspectorModel& m, const TypeSizes& t, const Rect& box) {
    return fitText(formulaText(*m.trace, m.hidden), FontFace::Mono, t.number, t.numberFloor, box.w,
                   box.h);
}

void placeFormula(Planner& pl, const InspectorModel& m, const FittedText& f, const Rect& box,
                  int page) {
    placeFitted(pl, f, box, page, FontFace::Mono, m.hidden.any() ? TEXT_DIM : TEXT, "inspector",
                m.hidden.any() ? "masked" : "formula", "");
    pl.plan.formulaWhole = f.pages == 1 && !m.hidden.any();
}

}  // namespace

void planNextPageNote(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                      const TypeSizes& t, float margin, float y, const std::string& what) {
    if (m.singleFrame) return;  // a video's frame: no page follows it
    const Rect& p = l.inspector;
    float lh = lineHeightOf(t.label);
    std::string keys = pageKeys(m);
    std::string note = what + ": next page" + (keys.empty() ? "" : " (" + keys + ")");
    std::string shown = elideText(FontFace::Sans, t.label, note, p.w - 2 * margin);
    pl.text({p.x + margin, std::min(y, p.bottom() - margin - lh)}, shown,
            {FontFace::Sans, t.label, ACCENT}, BoxKind::Text, "inspector", "more", shown != note);
}

namespace {

// The panel without a trace: its heading and what to do.
void planNoTrace(Planner& pl, const Rect& p, const TypeSizes& t, float margin) {
    float width = p.w - 2 * margin;
    float y = p.y + margin;
    pl.text({p.x + margin, y}, "Inspector", {FontFace::Sans, t.head, TEXT}, BoxKind::Text,
            "inspector", "heading");
    y += lineHeightOf(t.head) * 1.5f;
    FittedText f = fitText(
        "No shadow receiver under the picked pixel. Click a point on the "
        "ground or on an object to see its shadow lookup.",
        FontFace::Sans, t.body, t.bodyFloor, width, p.bottom() - margin - y);
    placeFitted(pl, f, {p.x + margin, y, width, p.bottom() - margin - y}, 0, FontFace::Sans,
                TEXT_DIM, "inspector", "no-trace", "");
}

// The cells' plan (planned before the page was known: inspectorPanel) becomes the frame's.
void takeCellsPlan(Planner& pl, FramePlan& cells) {
    for (auto& op : cells.base) pl.op(std::move(op));
    pl.plan.boxes.insert(pl.plan.boxes.end(), cells.boxes.begin(), cells.boxes.end());
    pl.plan.drawnTexels = cells.drawnTexels;
    pl.plan.drawnFetches = cells.drawnFetches;
    pl.plan.numberedTexels = cells.numberedTexels;
    pl.plan.diskRadii = cells.diskRadii;
    pl.plan.rings = cells.rings;
}

// The first part: the cells, with the formula under them when it fits there, and the line that
// says what follows (the texel table, `table`, or the formula).
void planCellsPart(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                   const TypeSizes& t, InspectorPanel& panel, bool table) {
    const Rect& p = l.inspector;
    float margin = inspectorMargin(l);
    float width = p.w - 2 * margin;
    takeCellsPlan(pl, panel.cells);
    Rect under{p.x + margin, panel.cellsBottom, width, p.bottom() - margin - panel.cellsBottom};
    // The room inspectorPanel kept for the line that points to the texel table.
    if (table) under.h -= t.label * 0.5f + lineHeightOf(t.label);
    float noteY = panel.cellsBottom;
    if (panel.together) {
        placeFormula(pl, m, fitFormula(m, t, under), under, 0);
        noteY = pl.plan.boxes.back().rect.bottom() + t.label * 0.5f;
    }
    // Where the rest is; under a formula only where there is room left for the line (a
    // question's hidden formula has no page of its own).
    bool room = noteY + lineHeightOf(t.label) <= p.bottom() - margin;
    if (table && room) {
        planNextPageNote(pl, l, m, t, margin, noteY, "every texel's numbers");
    } else if (!panel.together && !m.hidden.any()) {
        planNextPageNote(pl, l, m, t, margin, noteY, "the formula, every term");
    }
}

// The texel table's paging, the formula following it (on pages of its own, `formulaPages`, or
// under the table's last lines) when it is not under the cells.
TablePaging tablePaging(const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t,
                        const InspectorPanel& panel, float top, int formulaPages) {
    if (panel.tableTexels.empty()) return {};
    const Rect& p = l.inspector;
    float margin = inspectorMargin(l);
    FormulaAfter after;
    if (!panel.together && !m.hidden.any()) {
        after.pages = formulaPages;
        after.fitsFrom = [&](float y) {
            Rect below{p.x + margin, y, p.w - 2 * margin, p.bottom() - margin - y};
            return below.h >= lineHeightOf(t.numberFloor) && fitFormula(m, t, below).pages == 1;
        };
    }
    return texelTablePaging(l, m, t, panel.tableTexels, panel.cells.bitTexels, top, after);
}

}  // namespace

void planInspector(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                   const TypeSizes& t) {
    const Rect& p = l.inspector;
    float margin = inspectorMargin(l);
    if (!m.trace) {
        planNoTrace(pl, p, t, margin);
        return;
    }
    const Trace& tr = *m.trace;
    // pcss: its figures, page by page, instead of its disks' hundreds of small cells.
    if (pcssFigures(tr)) return planPcssInspector(pl, l, m, t);
    // The moment methods: the statistics their moments hold, not taps (no texel has a bit).
    if (momentFigures(tr)) return planMomentInspector(pl, l, m, t);
    InspectorPanel panel = inspectorPanel(l, m, t, pl.onTop, pl.plan.footprintShown);
    const PanelLayout& layout = panel.layout;
    planHeader(pl, l, layout.header, t, margin, tr, m.hidden);
    float width = p.w - 2 * margin;
    float formulaTop = p.y + margin + layout.header.height + t.label * 0.5f;
    Rect alone{p.x + margin, formulaTop, width, p.bottom() - margin - formulaTop};
    FittedText formulaAlone = fitFormula(m, t, alone);
    // The parts: the cells (with the formula when it fits under them), the texel table's pages
    // when some cells could not hold their numbers (the formula under its last lines when it
    // fits there whole), the formula's pages when it did not fit.
    const std::vector<glm::ivec2>& table = panel.tableTexels;
    TablePaging paging = tablePaging(l, m, t, panel, formulaTop, formulaAlone.pages);
    int tableParts = table.empty() ? 0 : paging.pages();
    // A question's formula is hidden (app/predict.h): no page of its own for the line saying so.
    bool formulaHidden = m.hidden.any();
    int formulaParts =
        panel.together || paging.formulaBelow || formulaHidden ? 0 : formulaAlone.pages;
    int parts = 1 + tableParts + formulaParts;
    pl.plan.textPages = std::max(pl.plan.textPages, parts);
    pl.plan.inspectorParts = parts;
    int part = std::min(std::max(0, m.textPage), parts - 1);
    if (part == 0) return planCellsPart(pl, l, m, t, panel, tableParts > 0);
    if (part <= tableParts) {
        float end = planTexelTable(pl, l, m, t, table, formulaTop, paging, part - 1);
        if (part == tableParts && paging.formulaBelow) {
            Rect below{p.x + margin, paging.formulaTop, width,
                       p.bottom() - margin - paging.formulaTop};
            placeFormula(pl, m, fitFormula(m, t, below), below, 0);
            return;
        }
        if (part < parts - 1) {
            planNextPageNote(pl, l, m, t, margin, end + t.label * 0.5f,
                             part < tableParts ? "more texels" : "the formula, every term");
        }
        return;
    }
    int formulaPage = part - tableParts - 1;
    placeFormula(pl, m, formulaAlone, alone, formulaPage);
    if (formulaPage < formulaAlone.pages - 1) {
        float end = pl.plan.boxes.back().rect.bottom() + t.label * 0.5f;
        planNextPageNote(pl, l, m, t, margin, end, "the rest of the formula");
    }
}

InspectorPanel inspectorPanel(const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t,
                              bool onTop, bool sceneTint) {
    const Rect& p = l.inspector;
    const Trace& tr = *m.trace;
    float margin = inspectorMargin(l);
    InspectorPanel out;
    // The cells' page in a scratch plan: where the legend ends says whether the formula fits
    // under it whole. When it does not, the cells are planned again with the formula's room
    // (it goes on a page of its own).
    int hidden = 0;
    auto planCellsPage = [&](const PanelLayout& pan) {
        out.layout = pan;
        out.cells = FramePlan{};
        Planner cp{out.cells, onTop};
        LegendNeeds need;
        need.footprint = sceneTint;
        hidden = 0;
        planCells(cp, l, m, pan.grid, t, need, hidden);
        float y = planNotes(cp, l, hidden, t, margin, pan.grid.bottom + 2.0f);
        out.cellsBottom = planLegend(cp, l, m, need, t, margin, y + 4.0f);
    };
    float width = p.w - 2 * margin;
    auto formulaFits = [&]() {
        Rect under{p.x + margin, out.cellsBottom, width, p.bottom() - margin - out.cellsBottom};
        // Cells that could not hold their numbers send them to a table on the next page: the
        // line that says so (planNextPageNote) needs its room under the formula, or page 1
        // would give no sign that there is more.
        if (!texelsWithoutNumbers(tr, out.cells).empty()) {
            under.h -= t.label * 0.5f + lineHeightOf(t.label);
        }
        return under.h >= lineHeightOf(t.numberFloor) && fitFormula(m, t, under).pages == 1;
    };
    auto finish = [&]() {
        out.tableTexels = texelsWithoutNumbers(tr, out.cells);
        return out;
    };
    float legendH = BELOW_APART_LINES * lineHeightOf(t.label);
    if (cellsAlone(m.focus)) {
        // The step is about the cells: they keep the room the formula would take.
        planCellsPage(panelLayout(l, tr, t, m.highlightFetch, legendH));
        out.together = false;
        return finish();
    }
    planCellsPage(panelLayout(l, tr, t, m.highlightFetch));
    out.together = formulaFits();
    if (out.together) return finish();
    // Cells a little smaller, the formula's own height kept under them, as long as every cell
    // keeps its numbers (a 2 x 2 has room to spare).
    FittedText whole = fitFormula(m, t, {0, 0, width, 1e6f});
    float formulaH = static_cast<float>(whole.lines.size()) * whole.lineHeight;
    planCellsPage(panelLayout(l, tr, t, m.highlightFetch, formulaH + legendH));
    out.together = hidden == 0 && formulaFits();
    if (!out.together) planCellsPage(panelLayout(l, tr, t, m.highlightFetch, legendH));
    return finish();
}

}  // namespace pcf::inspector_detail
