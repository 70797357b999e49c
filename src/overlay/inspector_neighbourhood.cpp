// inspector_neighbourhood.cpp: the magnified texel neighbourhood: where its cells go (the
// inspector panel's one layout, panelLayout) and what each cell shows (fill, weight bar, the
// fetches' marks, the lookup point, the fx and fy brackets); the numbers in the cells (bit,
// depth, weight) are inspector_cell_numbers.cpp's.
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

namespace {

// The neighbourhood's proportions, named once. Sizes scale with the numbers' type size or the
// cell; the _PX ones are pixels at any size.
constexpr float BIT_PER_NUMBER = 1.5f;         // the comparison bit's type size / the numbers'
constexpr float BAR_MIN_PX = 3.0f;             // the weight bar's height: at least this,
constexpr float BAR_PER_NUMBER = 0.25f;        // else this share of the numbers' size
constexpr float OUTLINE_EXTRA_PX = 1.0f;       // a gather outline is the line width plus this
constexpr float PAD_GAP_PX = 2.0f;             // numbers keep this far inside the gather outline
constexpr float MARK_ROOM = 1.08f;             // a cell is this much larger than its number block
constexpr float INDEX_GAP_PX = 8.0f;           // the "j=" lane: the widest label plus this
constexpr float INDEX_LANE_PAD_PX = 12.0f;     // the "i=" lane: a label line plus this
constexpr float FRACTION_LANE_PAD_PX = 16.0f;  // the fy lane: "fy 0.00" plus this
constexpr float MIN_GRID_SIDE_PX = 40.0f;      // the cells' square, however small the panel
constexpr float BELOW_MIN_LINES = 4.0f;        // room kept under the cells for the legend and the
constexpr float BELOW_MIN_SHARE = 0.22f;  // formula: these many lines, or this share of the panel
constexpr float GROWN_PER_CELL = 0.12f;   // big cells: numbers up to this share of the cell,
constexpr float GROWN_MAX_PER_NUMBER = 1.8f;  // and at most this times the frame's number size
constexpr float INDEX_TOP_GAP_PX = 4.0f;      // "i=" labels below the lane's top
constexpr float INDEX_RIGHT_GAP_PX = 6.0f;    // "j=" labels left of the cells
constexpr float DOT_MIN_PX = 3.0f, DOT_PER_CELL = 0.04f;      // a lookup's dot radius
constexpr float RING_MIN_PX = 5.0f, RING_PER_CELL = 0.07f;    // a hardware tap's ring radius
constexpr float RING_CORE_MIN_PX = 2.0f, RING_CORE = 0.4f;    // the dot inside the ring
constexpr float POINT_MIN_PX = 4.0f, POINT_PER_CELL = 0.05f;  // the lookup point's radius
constexpr float POINT_OUTLINE_PX = 1.5f;                      // its dark outline
constexpr float HIGHLIGHT_EXTRA_PX = 2.0f;  // the highlighted fetch's mark grows by this
constexpr float BRACKET_MIN_PX = 2.0f;      // the fx/fy brackets' line width, at least
constexpr float BRACKET_GAP_PX = 4.0f;      // the fx bracket below the cells
constexpr float FY_BRACKET_GAP_PX = 5.0f;   // the fy bracket right of the cells
constexpr float BRACKET_TICK_PX = 6.0f;     // the brackets' end ticks
constexpr float FX_LABEL_GAP_PX = 1.0f;     // "fx" under its bracket
constexpr float FY_LABEL_GAP_PX = 3.0f;     // "fy" right of its bracket
constexpr float INSET_SHARE = 0.3f;         // hw8: the inset's side, this share of the width
constexpr float INSET_GAP_PX = 6.0f;        // between the fy lane and the inset

// The weight bar's height for a number size.
float barFor(float number) { return std::max(BAR_MIN_PX, number * BAR_PER_NUMBER); }

// The side of a cell for a number size: room for the block and, beside it, for the marks a cell
// may hold. `pad`: the cell's border band.
float cellFor(float number, float pad) {
    float bit = bitFor(number);
    float blockW = measureText(FontFace::Mono, number, "d 0.000").x;
    float blockH = lineHeightOf(bit) + 2.0f * lineHeightOf(number);
    float bar = barFor(number);
    return std::max(blockW + 2.0f * pad, blockH + bar + 2.0f * pad) * MARK_ROOM;
}

// The lanes around the cells: the "j=" labels' width, the "i=" lane's height, the fy lane's
// width, the bottom lane's height, the inset column's width (0 without hw8).
struct Lanes {
    float labelW, laneH, fyW, laneBottomH, insetW;
};

Lanes lanesOf(const Grid& g, const TypeSizes& t, float width) {
    Lanes ln;
    int lastRow = std::max(std::abs(g.full.origin.y), std::abs(g.full.origin.y + g.full.size.y));
    // (Room for the axes' caption too, which bare index labels bring: planGridLines.)
    ln.labelW = std::max(measureText(FontFace::Mono, t.label, "j=-" + std::to_string(lastRow)).x,
                         measureText(FontFace::Mono, t.label, "j↓ i→").x) +
                INDEX_GAP_PX;
    ln.laneH = lineHeightOf(t.label) + INDEX_LANE_PAD_PX;
    ln.fyW = measureText(FontFace::Mono, t.label, "fy 0.00").x + FRACTION_LANE_PAD_PX;
    // hw8: the fractions get four decimals and their 8-bit step on a second line (the bottom
    // lane one line taller), and a column right of the fy lane holds the sub-texel inset.
    ln.laneBottomH = ln.laneH;
    ln.insetW = 0.0f;
    if (g.hw8) {
        ln.fyW = std::max(measureText(FontFace::Mono, t.label, "fy 0.0000").x,
                          measureText(FontFace::Mono, t.label, "255/256").x) +
                 FRACTION_LANE_PAD_PX;
        ln.laneBottomH += lineHeightOf(t.label);
        ln.insetW = std::round((width - ln.labelW - ln.fyW) * INSET_SHARE) + INSET_GAP_PX;
    }
    return ln;
}

// The cells', the lanes' and the inset's rectangles, once the view and the cell size are known.
void placeGrid(Grid& g, const Rect& p, const Lanes& ln, float margin, float top, float side) {
    float gridW = g.cell * g.view.size.x;
    float gridH = g.cell * g.view.size.y;
    float x0 = std::round(p.x + margin + ln.labelW);
    float y0 = std::round(top + ln.laneH);
    g.area = {x0, y0, gridW, gridH};
    g.laneTop = {x0, y0 - ln.laneH, gridW, ln.laneH};
    g.laneLeft = {p.x + margin, y0, ln.labelW, gridH};
    g.laneRight = {x0 + gridW, y0, ln.fyW, gridH};
    g.laneBottom = {x0, y0 + gridH, gridW, ln.laneBottomH};
    g.bottom = y0 + gridH + ln.laneBottomH;
    if (g.hw8) {
        // Square, level with the cells, within the height the cells may take; the caption in
        // the lane above it.
        float insetSide = std::floor(std::min(ln.insetW - INSET_GAP_PX, side));
        float ix = std::round(g.laneRight.right() + INSET_GAP_PX);
        g.inset = {ix, y0, insetSide, insetSide};
        g.insetCaption = {ix, g.laneTop.y, insetSide, ln.laneH};
        g.bottom = std::max(g.bottom, g.inset.bottom() + INSET_GAP_PX);
    }
}

// The cells under the header: their size, the window of the neighbourhood they show, the lanes
// around them. `top`: the header's bottom.
Grid gridOf(const InspectorLayout& l, const Trace& tr, const TypeSizes& t, float margin,
            float width, float top, float reserve) {
    Grid g;
    const Rect& p = l.inspector;
    g.full = neighbourhoodOf(tr);
    // poisson's and pcss's rings are drawn whole: the cells reach round the largest (texel i
    // spans p in [i - 0.5, i + 0.5)).
    DiskRings rings = diskRings(tr);
    if (float ring = std::max(rings.search, rings.filter); ring > 0.0f) {
        glm::ivec2 lo(glm::floor(tr.pos.p - glm::vec2(ring) + 0.5f));
        glm::ivec2 hi(glm::floor(tr.pos.p + glm::vec2(ring) + 0.5f));
        lo = glm::min(lo, g.full.origin);
        hi = glm::max(hi, g.full.origin + g.full.size - glm::ivec2(1));
        g.full = {lo, hi - lo + glm::ivec2(1)};
    }
    float line = lineOf(l);
    // The cell's border band: the gather outline (inset `line`, `line + 1` wide), then 2 px.
    g.pad = 2.0f * line + (OUTLINE_EXTRA_PX + PAD_GAP_PX);
    g.hw8 = hw8Lookup(tr);
    Lanes ln = lanesOf(g, t, width);
    // The grid takes at most this share of the panel's height: the legend and the formula need
    // the rest.
    float below = reserve >= 0.0f
                      ? reserve
                      : std::max(BELOW_MIN_LINES * lineHeightOf(t.number), BELOW_MIN_SHARE * p.h);
    float maxH = p.bottom() - margin - top - ln.laneH - ln.laneBottomH - below;
    float side = std::max(MIN_GRID_SIDE_PX, std::min(width - ln.labelW - ln.fyW - ln.insetW, maxH));
    int cellsFull = std::max(g.full.size.x, g.full.size.y);
    // The whole neighbourhood, always (a step's words talk about every texel it reads), at the
    // largest number size that fits, down to the floor. Smaller cells than that keep their bit
    // and fill and drop the numbers they have no room for (planCell); the formula, on its own
    // page when need be, lists every term.
    float number = t.number;
    while (cellFor(number, g.pad) * cellsFull > side && number > t.numberFloor) {
        number = stepDown(number, t.numberFloor);
    }
    g.number = number;
    g.bit = bitFor(number);
    g.bar = barFor(number);
    g.view = g.full;
    int viewCells = std::max(g.view.size.x, g.view.size.y);
    g.cell = std::floor(side / static_cast<float>(viewCells));
    // Big cells (few texels) get bigger numbers, as long as the block still fits beside marks.
    float grown =
        std::min(std::round(g.cell * GROWN_PER_CELL), std::round(t.number * GROWN_MAX_PER_NUMBER));
    while (grown > g.number && cellFor(grown, g.pad) > g.cell) grown -= 1.0f;
    if (grown > g.number) {
        g.number = grown;
        g.bit = bitFor(grown);
        g.bar = barFor(grown);
    }
    placeGrid(g, p, ln, margin, top, side);
    return g;
}

glm::vec2 viewPoint(const Grid& g, glm::vec2 texelPos) {
    return {g.area.x + (texelPos.x - static_cast<float>(g.view.origin.x)) * g.cell,
            g.area.y + (texelPos.y - static_cast<float>(g.view.origin.y)) * g.cell};
}

}  // namespace

float bitFor(float number) { return std::round(number * BIT_PER_NUMBER); }

const TapRecord* firstTapAt(const Trace& tr, glm::ivec2 texel) {
    for (const TapRecord& tp : tr.taps) {
        if (tp.texel == texel) return &tp;
    }
    return nullptr;
}

PanelLayout panelLayout(const InspectorLayout& l, const Trace& tr, const TypeSizes& t, int,
                        float reserve) {
    PanelLayout pl;
    const Rect& p = l.inspector;
    pl.margin = inspectorMargin(l);
    pl.width = p.w - 2 * pl.margin;
    pl.header = headerOf(tr, t, pl.width);
    float top = p.y + pl.margin + pl.header.height + t.label * 0.5f;
    pl.grid = gridOf(l, tr, t, pl.margin, pl.width, top, reserve);
    return pl;
}

namespace {

// Each cell's fill (its bit's colour), the clamped frame and the weight bar.
void planCellFills(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const Grid& g,
                   CellMarks& marks, LegendNeeds& legend) {
    const Trace& tr = *m.trace;
    float line = lineOf(l);
    float maxWeight = 0.0f;
    for (float w : tr.weights.values) maxWeight = std::max(maxWeight, w);
    for (int j = 0; j < g.view.size.y; ++j) {
        for (int i = 0; i < g.view.size.x; ++i) {
            glm::ivec2 texel = g.view.origin + glm::ivec2(i, j);
            Rect r = texelCellRect(g.view, g.area, texel);
            const TapRecord* tap = firstTapAt(tr, texel);
            float weight = tr.weights.at(texel);
            Colour fill = !tap ? PADDING : tap->lit >= 0.5f ? LIT_COLOUR : SHADOWED_COLOUR;
            if (tap && m.hidden.bits) fill = HIDDEN_BIT;
            if (tap && weight == 0.0f && !m.hidden.weights) fill = glm::mix(fill, PADDING, 0.55f);
            if (!tap) legend.padding = true;
            if (tap && weight == 0.0f) legend.zeroWeight = true;
            pl.fill(r, fill);
            // A tap whose texel lay outside the map, read clamped to the edge: an orange frame
            // in the cell's border band, where no number goes.
            bool clamped = std::any_of(tr.taps.begin(), tr.taps.end(), [&](const TapRecord& tp) {
                return tp.texel == texel && tp.clamped;
            });
            if (clamped) {
                legend.clamped = true;
                Rect frame = r.expanded(-line);
                pl.op([frame, line](Canvas& c) { c.strokeRect(frame, line, CLAMPED); });
            }
            if (tap && maxWeight > 0.0f && weight > 0.0f && !m.hidden.weights) {
                float band = 2.0f * line + OUTLINE_EXTRA_PX;
                Rect bar{r.x + band, r.bottom() - g.bar - band,
                         (r.w - 2 * band) * weight / maxWeight, g.bar};
                pl.fill(bar, WEIGHT_BAR);
                marks.add(pl, g.area, bar, "weight-bar");
                legend.weightBar = true;
            }
        }
    }
}

// The cell borders (the numbers stay g.pad inside them) and the texel indices in the lanes
// above and to the left.
void planGridLines(Planner& pl, const InspectorLayout& l, const Grid& g, const TypeSizes& t) {
    const std::string panel = "inspector";
    float line = lineOf(l);
    Rect area = g.area;
    std::vector<std::pair<glm::vec2, glm::vec2>> lines;
    for (int i = 0; i <= g.view.size.x; ++i) {
        float x = area.x + i * g.cell;
        lines.push_back({{x, area.y}, {x, area.bottom()}});
    }
    for (int j = 0; j <= g.view.size.y; ++j) {
        float y = area.y + j * g.cell;
        lines.push_back({{area.x, y}, {area.right(), y}});
    }
    pl.op([lines, line](Canvas& c) {
        for (const auto& [a, b] : lines) c.line(a, b, line, Colour{0, 0, 0, 0.9f});
    });
    // Column labels as wide as the cells allow: "i=117", else "117" on every cell, else on the
    // texels whose index is a multiple of the smallest step that gives a label its room (a
    // 33-texel pcss disk at 1280x720 has 11 px cells). Row labels likewise by line height, and
    // named the same way as the columns: "j=135" beside "i=117", else bare numbers on both and
    // the axes named once, in the corner above the row labels and left of the column labels
    // ("j↓ i→": the row index grows downwards, the column index to the right).
    int last = g.view.origin.x + g.view.size.x - 1;
    float labelW = measureText(FontFace::Mono, t.label, std::to_string(last)).x + INDEX_GAP_PX;
    bool prefix =
        measureText(FontFace::Mono, t.label, "i=" + std::to_string(last)).x + INDEX_GAP_PX <=
        g.cell;
    int every = prefix ? 1 : indexLabelStep(g.cell, labelW);
    float labelTop = g.laneTop.y + INDEX_TOP_GAP_PX;
    for (int i = 0; i < g.view.size.x; ++i) {
        if ((g.view.origin.x + i) % every != 0) continue;
        pl.text({area.x + (i + 0.5f) * g.cell, labelTop},
                (prefix ? "i=" : "") + std::to_string(g.view.origin.x + i),
                {FontFace::Mono, t.label, TEXT_DIM, TextAlign::Center}, BoxKind::Label, panel,
                "texel-index");
    }
    int everyRow = indexLabelStep(g.cell, lineHeightOf(t.label));
    for (int j = 0; j < g.view.size.y; ++j) {
        if ((g.view.origin.y + j) % everyRow != 0) continue;
        pl.text({g.laneLeft.right() - INDEX_RIGHT_GAP_PX,
                 area.y + (j + 0.5f) * g.cell - lineHeightOf(t.label) * 0.5f},
                (prefix ? "j=" : "") + std::to_string(g.view.origin.y + j),
                {FontFace::Mono, t.label, TEXT_DIM, TextAlign::Right}, BoxKind::Label, panel,
                "texel-index");
    }
    if (!prefix) {
        pl.text({g.laneLeft.right() - INDEX_RIGHT_GAP_PX, labelTop}, "j↓ i→",
                {FontFace::Mono, t.label, TEXT_DIM, TextAlign::Right}, BoxKind::Label, panel,
                "texel-axes");
    }
}

// A gather's 2 x 2 block as an outline in the border band of its cells, clipped to the view;
// the highlight is its colour, not a wider outline: the cells' numbers keep the band inside the
// outline (g.pad) that every gather leaves them. Drawn when its whole 2 x 2 is in the cells.
void planGatherOutline(Planner& pl, const Grid& g, float line, glm::vec2 uvTexels, int fi,
                       bool highlit, CellMarks& marks) {
    glm::ivec2 corner(glm::floor(uvTexels - 0.5f));
    Rect a = texelCellRect(g.view, g.area, corner);
    Rect b = texelCellRect(g.view, g.area, corner + glm::ivec2(1));
    Rect block = Rect{a.x, a.y, b.right() - a.x, b.bottom() - a.y}.expanded(-line);
    float w = line + OUTLINE_EXTRA_PX;
    Colour gatherColour = highlit ? HIGHLIGHT : GATHER;
    Rect edges[] = {{block.x, block.y, block.w, w},
                    {block.x, block.bottom() - w, block.w, w},
                    {block.x, block.y, w, block.h},
                    {block.right() - w, block.y, w, block.h}};
    for (const Rect& e : edges) {
        Rect ce = e.intersect(g.area);
        if (ce.empty()) continue;
        marks.ops.push_back([=](Canvas& c) { c.fillRect(ce, gatherColour); });
        marks.add(pl, g.area, ce, "gather-outline");
    }
    if (inside(block, g.area)) pl.plan.drawnFetches.push_back(fi);
}

// Point reads and lookups without a mark of their own (nearest, box2x2, bilinear2x2) are drawn
// when the cells of the texels they read are.
bool texelsInView(const Grid& g, const FetchRecord& fr, glm::vec2 size) {
    glm::vec2 q = fr.uv * size - (fr.kind == PCF_FETCH_POINT ? 0.0f : 0.5f);
    glm::ivec2 lo(glm::floor(q));
    glm::ivec2 hi = lo + (fr.kind == PCF_FETCH_POINT ? 0 : 1);
    glm::ivec2 end = g.view.origin + g.view.size;
    return glm::all(glm::greaterThanEqual(lo, g.view.origin)) && glm::all(glm::lessThan(hi, end));
}

// The fetches: gathers as outlines in the cells' border band, hardware taps as small rings,
// lookups and point reads as dots, each at the uv the instruction sampled; then the lookup point.
// The base texel's centre is not marked in the cell (its bit sits there): the fx and fy
// brackets in the lanes start at its column and row.
void planFetchMarks(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const Grid& g,
                    CellMarks& marks, LegendNeeds& legend) {
    const Trace& tr = *m.trace;
    const MethodInfo& info = methodInfo(tr.params.method);
    float line = lineOf(l);
    glm::vec2 size(tr.map.size);
    Rect area = g.area;
    float dotR = std::max(DOT_MIN_PX, std::round(g.cell * DOT_PER_CELL));
    // poisson's and pcss's points lie on a disk round the lookup point: they stay put.
    DiskRings disk = diskRings(tr);
    bool onDisk = disk.filter > 0.0f || disk.search > 0.0f;
    for (size_t fi = 0; fi < tr.fetches.size(); ++fi) {
        const FetchRecord& fr = tr.fetches[fi];
        glm::vec2 at = viewPoint(g, fr.uv * size);
        bool highlit = static_cast<int>(fi) == m.highlightFetch;
        if (highlit) legend.highlight = true;
        if (fr.kind == PCF_FETCH_GATHER) {
            planGatherOutline(pl, g, line, fr.uv * size, static_cast<int>(fi), highlit, marks);
            legend.gathers = true;
        } else if (fr.kind == PCF_FETCH_HW) {
            float rr = std::max(RING_MIN_PX, std::round(g.cell * RING_PER_CELL));
            if (!area.contains(at)) continue;
            pl.plan.drawnFetches.push_back(static_cast<int>(fi));
            marks.points.push_back(
                {at, at, rr + line, "hw-tap", HW_RING, [=](Canvas& c, glm::vec2 p) {
                     c.ring(p, rr, highlit ? line + HIGHLIGHT_EXTRA_PX : line,
                            highlit ? HIGHLIGHT : HW_RING);
                     c.circle(p, std::max(RING_CORE_MIN_PX, rr * RING_CORE), ACCENT);
                 }});
            legend.rings = true;
        } else if (info.hasDisk || info.overlappingLookups) {
            if (!area.contains(at)) continue;
            pl.plan.drawnFetches.push_back(static_cast<int>(fi));
            float mr = highlit ? dotR * 2.0f + 2.0f : dotR + 1.0f;  // the highlight's halo too
            // pcss: its first 16 reads are the blocker search's (weight 0), then the filter's.
            bool search = info.searchesBlockers && fi < PCF_PCSS_TAPS;
            Colour dot = search ? SEARCH : ACCENT;
            marks.points.push_back({at, at, mr, "lookup", dot, [=](Canvas& c, glm::vec2 p) {
                                        if (highlit) c.circle(p, dotR * 2.0f + 1.0f, HIGHLIGHT);
                                        c.circle(p, dotR, dot);
                                    }});
            marks.points.back().fixed = onDisk;
            (search ? legend.searchDisk : legend.dots) = true;
        } else if (texelsInView(g, fr, size)) {
            pl.plan.drawnFetches.push_back(static_cast<int>(fi));
        }
    }
    glm::vec2 point = viewPoint(g, tr.uv * size);
    planDisks(pl, tr, area, point, g.cell, std::max(1.0f, line - 1.0f), legend, marks);
    float pr = std::max(POINT_MIN_PX, std::round(g.cell * POINT_PER_CELL));
    if (area.contains(point)) {
        marks.points.push_back(
            {point, point, pr + 2, "lookup-point", POINT, [=](Canvas& c, glm::vec2 p) {
                 c.circle(p, pr + POINT_OUTLINE_PX, Colour{0, 0, 0, 0.9f});
                 c.circle(p, pr, POINT);
             }});
        marks.points.back().fixed = onDisk;
    }
}

// The point marks where planCellNumbers left them. One moved into a lane keeps its true
// position along that lane; a tick of its colour across the cell's border band (where no number
// goes, and the neighbour's) marks its true position in the other axis: on the left or right
// edge, whichever is nearer the mark, for its height; on the top or bottom edge for its column.
void planPointMarks(Planner& pl, const InspectorLayout& l, const Grid& g, CellMarks& cm,
                    LegendNeeds& legend) {
    float line = lineOf(l);
    float tw = std::max(BRACKET_MIN_PX, line) + 1.0f;
    for (const PointMark& p : cm.points) {
        glm::ivec2 at(glm::floor((p.trueAt - glm::vec2(g.area.x, g.area.y)) / g.cell));
        Rect r = texelCellRect(g.view, g.area, g.view.origin + at);
        // Across the cell's border line, one band deep on either side.
        float band = g.pad;
        std::vector<Rect> ticks;
        // (A mark moved by no more than the numbers' clearance needs no tick.)
        if (std::abs(p.at.y - p.trueAt.y) > MARK_CLEARANCE_PX) {
            float ex = p.at.x - r.x < r.right() - p.at.x ? r.x : r.right();
            ticks.push_back({ex - band, p.trueAt.y - tw * 0.5f, 2 * band, tw});
        }
        if (std::abs(p.at.x - p.trueAt.x) > MARK_CLEARANCE_PX) {
            float ey = p.at.y - r.y < r.bottom() - p.at.y ? r.y : r.bottom();
            ticks.push_back({p.trueAt.x - tw * 0.5f, ey - band, tw, 2 * band});
        }
        for (const Rect& t : ticks) {
            Rect ct = t.intersect(g.area);
            if (ct.empty()) continue;
            Colour c = p.tickColour;
            cm.ops.push_back([ct, c](Canvas& cv) { cv.fillRect(ct, c); });
            cm.add(pl, g.area, ct, p.role + "-tick");
            legend.movedMark = true;
        }
        auto draw = p.draw;
        glm::vec2 where = p.at;
        cm.ops.push_back([draw, where](Canvas& c) { draw(c, where); });
        cm.add(pl, g.area, p.rect(), p.role);
    }
}

// fx and fy in the lanes under and beside the cells: a bracket from the base texel's centre
// to the lookup point, with its value.
void planFractions(Planner& pl, const InspectorLayout& l, const Trace& tr, const Grid& g,
                   const TypeSizes& t, bool hidden) {
    const std::string panel = "inspector";
    glm::vec2 size(tr.map.size);
    Rect area = g.area;
    float line = lineOf(l);
    glm::vec2 point = viewPoint(g, tr.uv * size);
    glm::vec2 baseCentre = viewPoint(g, glm::vec2(tr.pos.base) + 0.5f);
    float x0 = std::clamp(baseCentre.x, area.x, area.right());
    float x1 = std::clamp(point.x, area.x, area.right());
    float y0 = std::clamp(baseCentre.y, area.y, area.bottom());
    float y1 = std::clamp(point.y, area.y, area.bottom());
    float lw = std::max(BRACKET_MIN_PX, line);
    float ly = g.laneBottom.y + BRACKET_GAP_PX;
    float lx = g.laneRight.x + FY_BRACKET_GAP_PX;
    float tick = BRACKET_TICK_PX;
    Rect hb{std::min(x0, x1) - lw, ly, std::abs(x1 - x0) + 2 * lw, tick};
    Rect vb{lx, std::min(y0, y1) - lw, tick, std::abs(y1 - y0) + 2 * lw};
    pl.op([=](Canvas& c) {
        c.line({x0, ly + tick * 0.5f}, {x1, ly + tick * 0.5f}, lw, POINT);
        c.line({x0, ly}, {x0, ly + tick}, lw, POINT);
        c.line({x1, ly}, {x1, ly + tick}, lw, POINT);
        c.line({lx + tick * 0.5f, y0}, {lx + tick * 0.5f, y1}, lw, POINT);
        c.line({lx, y0}, {lx + tick, y0}, lw, POINT);
        c.line({lx, y1}, {lx + tick, y1}, lw, POINT);
    });
    pl.box(BoxKind::Mark, hb, panel, "fx-bracket");
    pl.box(BoxKind::Mark, vb, panel, "fy-bracket");
    // With hw8 the float fraction gets four decimals, and under it the 8-bit one, k/256, that
    // the texture unit lerps with (the trace's fracHw8).
    int decimals = g.hw8 ? 4 : 2;
    std::string fx = hiddenOr(hidden, "fx ", fixed(tr.pos.frac.x, decimals));
    std::string fy = hiddenOr(hidden, "fy ", fixed(tr.pos.frac.y, decimals));
    std::string fxRole = hidden ? "masked" : "fx", fyRole = hidden ? "masked" : "fy";
    TextStyle fst{FontFace::Mono, t.label, POINT, TextAlign::Left};
    TextStyle qst{FontFace::Mono, t.label, HW8_POINT, TextAlign::Left};
    Rect fxs = pl.measure({0, 0}, fx, fst);
    float rows = g.hw8 ? 2.0f : 1.0f;
    float fxX =
        std::clamp((x0 + x1) * 0.5f - fxs.w * 0.5f, g.laneBottom.x, g.laneBottom.right() - fxs.w);
    Rect fxBox =
        pl.text({fxX, ly + tick + FX_LABEL_GAP_PX}, fx, fst, BoxKind::Label, panel, fxRole);
    float fyY = std::clamp((y0 + y1) * 0.5f - fxs.h * rows * 0.5f, g.laneRight.y,
                           g.laneRight.bottom() - fxs.h * rows);
    Rect fyBox =
        pl.text({lx + tick + FY_LABEL_GAP_PX, fyY}, fy, fst, BoxKind::Label, panel, fyRole);
    if (g.hw8 && !hidden) {
        pl.text({fxBox.x, fxBox.bottom()}, hw8Steps(tr.fracHw8.x), qst, BoxKind::Label, panel,
                "fx-hw8");
        pl.text({fyBox.x, fyBox.bottom()}, hw8Steps(tr.fracHw8.y), qst, BoxKind::Label, panel,
                "fy-hw8");
    }
}

}  // namespace

void planCells(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const Grid& g,
               const TypeSizes& t, LegendNeeds& legend, int& hiddenCells) {
    const Trace& tr = *m.trace;
    CellMarks marks;
    planCellFills(pl, l, m, g, marks, legend);
    for (int j = 0; j < g.view.size.y; ++j) {
        for (int i = 0; i < g.view.size.x; ++i) {
            pl.plan.drawnTexels.push_back(g.view.origin + glm::ivec2(i, j));
        }
    }
    planGridLines(pl, l, g, t);
    planFetchMarks(pl, l, m, g, marks, legend);
    hiddenCells += planCellNumbers(pl, m, g, marks, t.numberFloor);
    planPointMarks(pl, l, g, marks, legend);
    for (auto& f : marks.ops) pl.op(std::move(f));
    if (!methodInfo(tr.params.method).nearestTexels) {
        legend.fraction = true;
        planFractions(pl, l, tr, g, t, m.hidden.fraction);
    }
    planSubtexelInset(pl, l, tr, g, t, m.highlightFetch);
    legend.hw8 = g.hw8;
}

}  // namespace pcf::inspector_detail
