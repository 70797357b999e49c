// inspector_legend.cpp: the inspector's legend: a swatch and a word for every kind of mark a
// frame draws (LegendNeeds says which), drawn as the frame draws the mark.
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

namespace {

enum SwatchShape { SQUARE, DOT, RING, OUTLINE, BAR, TICK, CIRCLE, DISC, GRID, VLINE, STEM };

struct LegendEntry {
    Colour colour;
    std::string text;
    SwatchShape shape;
    Colour edge{0.0f};  // DISC: its edge (a pcss tap's disk colour)
};

// pcss's tap discs (inspector_pcss.cpp): the search's blockers or not, the filter's bits.
void pcssEntries(const LegendNeeds& need, std::vector<LegendEntry>& entries) {
    if (need.blockerTaps) {
        entries.push_back({SHADOWED_COLOUR, "blocker: depth < ref", DISC, SEARCH});
        entries.push_back({LIT_COLOUR, "not a blocker", DISC, SEARCH});
    }
    if (need.filterTaps) {
        entries.push_back({LIT_COLOUR, "lit: ref <= depth", DISC, ACCENT});
        entries.push_back({SHADOWED_COLOUR, "shadowed", DISC, ACCENT});
    }
    if (need.texelGrid) entries.push_back({PCSS_GRID, "grid: the map's texels", GRID});
}

// A moment method's figure (inspector_moment_page.cpp): its colours, as it draws them.
void momentEntries(const LegendNeeds& need, std::vector<LegendEntry>& entries) {
    if (need.momentBars) entries.push_back({MOMENT_BAR, "depth texels (weight)", SQUARE});
    if (need.meanLine) entries.push_back({ACCENT, "mean", VLINE});
    if (need.receiverLine) entries.push_back({POINT, "receiver t", VLINE});
    if (need.msmPoints) entries.push_back({GATHER, "reconstructed points", STEM});
    if (need.boundCurve) {
        entries.push_back(
            {LIT_COLOUR, need.negCurve ? "positive warp's bound" : "bound p_max(t)", BAR});
    }
    if (need.negCurve) entries.push_back({MOMENT_NEG_CURVE, "negative warp's bound", BAR});
    if (need.lbrCurve) entries.push_back({WEIGHT_BAR, "after LBR linstep", BAR});
    if (need.pcfMark) {
        std::string pcf(methodInfo(sameFootprintPcfMethod()).name);
        entries.push_back({PCF_MARK, pcf + " of the same texels", SQUARE});
    }
}

// One entry for every kind of mark this frame draws.
std::vector<LegendEntry> legendEntries(const InspectorModel& m, const LegendNeeds& need) {
    std::vector<LegendEntry> entries;
    if (need.cells && m.hidden.bits) {
        // A question on the bits: the cells say nothing of them until the reveal.
        entries.push_back({HIDDEN_BIT, "bit hidden (lit: ref <= depth)", SQUARE});
    } else if (need.cells) {
        entries.push_back({LIT_COLOUR, "lit: ref <= depth", SQUARE});
        entries.push_back({SHADOWED_COLOUR, "shadowed", SQUARE});
    }
    pcssEntries(need, entries);
    momentEntries(need, entries);
    if (need.padding) entries.push_back({PADDING, "not read", SQUARE});
    if (need.zeroWeight) {
        entries.push_back({glm::mix(LIT_COLOUR, PADDING, 0.55f), "read, weight 0", SQUARE});
    }
    if (need.clamped) entries.push_back({CLAMPED, "read clamped to the edge", OUTLINE});
    if (need.weightBar) entries.push_back({WEIGHT_BAR, "weight bar", BAR});
    if (need.point) entries.push_back({POINT, "lookup point", DOT});
    if (need.fraction) entries.push_back({POINT, "fx, fy: lookup point - base texel centre", BAR});
    if (need.hw8) entries.push_back({HW8_POINT, "8-bit position (1/256 texel)", OUTLINE});
    if (need.dots) entries.push_back({ACCENT, "each lookup", DOT});
    bool pcss = m.trace && methodInfo(m.trace->params.method).searchesBlockers;
    if (need.searchDisk) {
        entries.push_back(
            {SEARCH, need.blockerTaps ? "blocker search's disk" : "blocker search: taps, disk",
             CIRCLE});
    }
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
void planSwatch(Planner& pl, Rect sw, SwatchShape shape, Colour col, float lg, Colour edge) {
    pl.op([=](Canvas& c) {
        glm::vec2 cc = sw.centre();
        switch (shape) {
            case DISC:  // a pcss tap: its fill and its disk's colour round it
                c.circle(cc, lg * 0.45f, edge);
                c.circle(cc, lg * 0.45f - 2.0f, col);
                break;
            case GRID:  // two texels' edges
                c.strokeRect(sw, 1.0f, col);
                c.line({cc.x, sw.y}, {cc.x, sw.bottom()}, 1.0f, col);
                break;
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
            case VLINE:  // a line across a plot, as the moment figure's t and mean
                c.fillRect({cc.x - 1.5f, sw.y, 3.0f, sw.h}, col);
                break;
            case STEM:  // msm's point: a stem with a dot on it
                c.fillRect({cc.x - 1.0f, sw.y + sw.h * 0.3f, 2.0f, sw.h * 0.7f}, col);
                c.circle({cc.x, sw.y + sw.h * 0.3f}, lg * 0.18f, col);
                break;
            case TICK:  // a tick across a cell border, as in the cells
                c.fillRect({sw.x, sw.y + sw.h * 0.5f - 0.5f, sw.w, 1.0f}, TEXT_DIM);
                c.fillRect({cc.x - 1.5f, sw.y, 3.0f, sw.h}, col);
                break;
        }
    });
}

}  // namespace

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
        planSwatch(pl, sw, e.shape, e.colour, lg, e.edge);
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

}  // namespace pcf::inspector_detail
