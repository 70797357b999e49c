// inspector_numbers.cpp: the inspector panel's words and numbers: the header (method,
// visibility, fetch counts, uv, ref, bias), the notes on what the cells leave out, the legend of
// the marks drawn, and the formula with its numbers from the kernel's own explanation.
#include "kernel/methods.h"
#include "kernel/trace_explain.h"
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

// The header's title line and the counts under it are this far apart.
constexpr float HEADER_GAP_PX = 4.0f;

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
    auto plural = [](int n, const char* one, const char* many) {
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    std::string counts = plural(tr.counts.texels, "texel read", "texel reads");
    if (tr.counts.gathers) counts += ", " + plural(tr.counts.gathers, "gather", "gathers");
    if (tr.counts.hwTaps)
        counts += ", " + plural(tr.counts.hwTaps, "hardware tap", "hardware taps");
    counts += "\nuv (" + fixed(tr.uv.x, 4) + ", " + fixed(tr.uv.y, 4) + ")  ref " +
              fixed(tr.ref, 4) + "  bias " + std::string(biasName(tr.bias.modeId()));
    // Two lines when one does not hold them, and each wraps again if need be.
    std::string oneLine = counts;
    std::replace(oneLine.begin(), oneLine.end(), '\n', ' ');
    oneLine.insert(oneLine.find(" uv ("), "  ");
    if (measureText(FontFace::Mono, t.number, oneLine).x <= width) {
        h.counts = {oneLine};
    } else {
        h.counts = wrapText(FontFace::Mono, t.number, counts, width);
    }
    float headLh = lineHeightOf(t.head);
    h.height = headLh * (h.resultOnOwnLine ? 2.0f : 1.0f) + HEADER_GAP_PX +
               lineHeightOf(t.number) * static_cast<float>(h.counts.size());
    return h;
}

float inspectorMargin(const InspectorLayout& l) {
    return std::max(8.0f, std::round(18.0f * l.scale));
}

namespace {

std::string formulaText(const Trace& tr) {
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

void planHeader(Planner& pl, const InspectorLayout& l, const Header& h, const TypeSizes& t,
                float margin) {
    const Rect& p = l.inspector;
    const std::string panel = "inspector";
    float y = p.y + margin;
    pl.text({p.x + margin, y}, h.title, {FontFace::Mono, t.head, ACCENT}, BoxKind::Text, panel,
            "method");
    if (h.resultOnOwnLine) {
        y += lineHeightOf(t.head);
        pl.text({p.x + margin, y}, h.result, {FontFace::Mono, t.head, TEXT}, BoxKind::Number, panel,
                "visibility");
    } else {
        pl.text({p.right() - margin, y}, h.result, {FontFace::Mono, t.head, TEXT, TextAlign::Right},
                BoxKind::Number, panel, "visibility");
    }
    y += lineHeightOf(t.head) + HEADER_GAP_PX;
    for (const std::string& c : h.counts) {
        pl.text({p.x + margin, y}, c, {FontFace::Mono, t.number, TEXT_DIM}, BoxKind::Number, panel,
                "counts");
        y += lineHeightOf(t.number);
    }
}

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

namespace {

enum SwatchShape { SQUARE, DOT, RING, OUTLINE, BAR, TICK, CIRCLE };

struct LegendEntry {
    Colour colour;
    std::string text;
    SwatchShape shape;
};

// One entry for every kind of mark this frame draws.
std::vector<LegendEntry> legendEntries(const InspectorModel& m, const LegendNeeds& need) {
    std::vector<LegendEntry> entries{{LIT_COLOUR, "lit: ref <= depth", SQUARE},
                                     {SHADOWED_COLOUR, "shadowed", SQUARE}};
    if (need.padding) entries.push_back({PADDING, "not read", SQUARE});
    if (need.clamped) entries.push_back({CLAMPED, "read clamped to the edge", OUTLINE});
    if (need.weightBar) entries.push_back({WEIGHT_BAR, "weight bar", BAR});
    entries.push_back({POINT, "lookup point", DOT});
    if (need.fraction) entries.push_back({POINT, "fx, fy: lookup point - base texel centre", BAR});
    if (need.hw8) entries.push_back({HW8_POINT, "8-bit position (1/256 texel)", OUTLINE});
    if (need.dots) entries.push_back({ACCENT, "each lookup", DOT});
    bool pcss = m.trace && methodInfo(m.trace->params.method).searchesBlockers;
    if (need.searchDisk) entries.push_back({SEARCH, "blocker search: taps, disk", CIRCLE});
    if (need.disk) {
        // The ring is the disk the points fill, wider than the scale they are given (planDisks).
        std::string reach = fixed(poissonSetReach(), 2);
        entries.push_back({ACCENT,
                           pcss ? "filter disk: " + reach + " x penumbra / 2"
                                : "the points' disk, radius " + reach + " R",
                           CIRCLE});
    }
    if (need.rings) entries.push_back({ACCENT, "hardware tap", RING});
    if (need.gathers) entries.push_back({GATHER, "one gather (2 x 2)", OUTLINE});
    if (need.highlight) entries.push_back({HIGHLIGHT, "the fetch the text talks about", OUTLINE});
    if (need.movedMark) entries.push_back({POINT, "tick: a moved mark's true place", TICK});
    if (need.footprint)
        entries.push_back({Colour{0.2f, 0.85f, 1.0f, 1.0f}, "texels read, on the scene", SQUARE});
    return entries;
}

// An entry's swatch in the square sw, its mark drawn as the frame draws it (lg: the type size).
void planSwatch(Planner& pl, Rect sw, SwatchShape shape, Colour col, float lg) {
    pl.op([=](Canvas& c) {
        glm::vec2 cc = sw.centre();
        switch (shape) {
            case DOT:
                c.circle(cc, lg * 0.35f + 1.5f, Colour{1, 1, 1, 0.9f});
                c.circle(cc, lg * 0.35f, col);
                break;
            case RING:
                c.ring(cc, lg * 0.38f, 2.0f, HW_RING);
                c.circle(cc, lg * 0.16f, col);
                break;
            case OUTLINE:
                c.strokeRect(sw, 3.0f, col);
                break;
            case CIRCLE:  // a thin circle, as the Poisson disk's
                c.ring(cc, lg * 0.45f, 1.5f, col);
                break;
            case BAR:
                c.fillRect({sw.x, sw.y + sw.h * 0.6f, sw.w, sw.h * 0.3f}, col);
                break;
            case SQUARE:
                c.fillRect(sw, col);
                break;
            case TICK:  // a tick across a cell border, as in the cells
                c.fillRect({sw.x, sw.y + sw.h * 0.5f - 0.5f, sw.w, 1.0f}, TEXT_DIM);
                c.fillRect({cc.x - 1.5f, sw.y, 3.0f, sw.h}, col);
                break;
        }
    });
}

}  // namespace

// The legend: a swatch and a word for every kind of mark this frame draws, flowing onto more
// lines when the panel is narrow. From `y` down; returns the new y.
float planLegend(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                 const LegendNeeds& need, const TypeSizes& t, float margin, float y) {
    const Rect& p = l.inspector;
    const std::string panel = "inspector";
    float lg = t.label;
    float lh = lineHeightOf(lg);
    float swatchW = lg * 1.4f;  // a swatch and the gap after it
    float x = p.x + margin;
    for (const LegendEntry& e : legendEntries(m, need)) {
        float tw = measureText(FontFace::Sans, lg, e.text).x;
        float w = swatchW + tw;
        if (x > p.x + margin && x + w > p.right() - margin) {
            x = p.x + margin;
            y += lh;
        }
        Rect sw{x, y + (lh - lg) * 0.5f, lg, lg};
        planSwatch(pl, sw, e.shape, e.colour, lg);
        pl.box(BoxKind::Mark, sw, panel, "legend-swatch");
        std::string text = e.text;
        if (tw > p.right() - margin - (x + swatchW)) {
            text = elideText(FontFace::Sans, lg, e.text, p.right() - margin - (x + swatchW));
        }
        pl.text({x + swatchW, y}, text, {FontFace::Sans, lg, TEXT_DIM}, BoxKind::Text, panel,
                "legend", text != e.text);
        x += w + swatchW;
    }
    return y + lh + lg * 0.6f;
}

// The formula with its numbers, from the kernel's own explanation, fitted into `box` at the
// numbers' size down to their floor; `page` of it when it pages.
FittedText fitFormula(const Trace& tr, const TypeSizes& t, const Rect& box) {
    return fitText(formulaText(tr), FontFace::Mono, t.number, t.numberFloor, box.w, box.h);
}

void placeFormula(Planner& pl, const FittedText& f, const Rect& box, int page) {
    placeFitted(pl, f, box, page, FontFace::Mono, TEXT, "inspector", "formula", "");
    pl.plan.formulaWhole = f.pages == 1;
}

// A line at the panel's bottom saying where the rest of the inspector is (the next page).
// `y`: the top of the room left under the rest.
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
    InspectorPanel panel = inspectorPanel(l, m, t, pl.onTop, pl.plan.footprintShown);
    const PanelLayout& layout = panel.layout;
    planHeader(pl, l, layout.header, t, margin);
    float width = p.w - 2 * margin;
    float formulaTop = p.y + margin + layout.header.height + t.label * 0.5f;
    Rect alone{p.x + margin, formulaTop, width, p.bottom() - margin - formulaTop};
    FittedText formulaAlone = fitFormula(tr, t, alone);
    // The parts: the cells (with the formula when it fits under them), the texel table's pages
    // when some cells could not hold their numbers, the formula's pages when it did not fit.
    const std::vector<glm::ivec2>& table = panel.tableTexels;
    int tableParts =
        table.empty() ? 0 : texelTablePages(l, m, t, table, formulaTop, !panel.together);
    int parts = 1 + tableParts + (panel.together ? 0 : formulaAlone.pages);
    pl.plan.textPages = std::max(pl.plan.textPages, parts);
    int part = std::min(std::max(0, m.textPage), parts - 1);
    if (part == 0) {
        takeCellsPlan(pl, panel.cells);
        Rect under{p.x + margin, panel.cellsBottom, width, p.bottom() - margin - panel.cellsBottom};
        // The room inspectorPanel kept for the line that points to the texel table.
        if (tableParts > 0) under.h -= t.label * 0.5f + lineHeightOf(t.label);
        float noteY = panel.cellsBottom;
        if (panel.together) {
            placeFormula(pl, fitFormula(tr, t, under), under, 0);
            noteY = pl.plan.boxes.back().rect.bottom() + t.label * 0.5f;
        }
        // Where the rest is; under a formula only where there is room left for the line.
        bool room = noteY + lineHeightOf(t.label) <= p.bottom() - margin;
        if (tableParts > 0 && room) {
            planNextPageNote(pl, l, m, t, margin, noteY, "every texel's numbers");
        } else if (!panel.together) {
            planNextPageNote(pl, l, m, t, margin, noteY, "the formula, every term");
        }
        return;
    }
    if (part <= tableParts) {
        float end = planTexelTable(pl, l, m, t, table, formulaTop, part - 1, !panel.together);
        if (part < parts - 1) {
            planNextPageNote(pl, l, m, t, margin, end + t.label * 0.5f,
                             part < tableParts ? "more texels" : "the formula, every term");
        }
        return;
    }
    int formulaPage = part - tableParts - 1;
    placeFormula(pl, formulaAlone, alone, formulaPage);
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
        return under.h >= lineHeightOf(t.numberFloor) && fitFormula(tr, t, under).pages == 1;
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
    FittedText whole = fitFormula(tr, t, {0, 0, width, 1e6f});
    float formulaH = static_cast<float>(whole.lines.size()) * whole.lineHeight;
    planCellsPage(panelLayout(l, tr, t, m.highlightFetch, formulaH + legendH));
    out.together = hidden == 0 && formulaFits();
    if (!out.together) planCellsPage(panelLayout(l, tr, t, m.highlightFetch, legendH));
    return finish();
}

}  // namespace pcf::inspector_detail
