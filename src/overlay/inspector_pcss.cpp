// inspector_pcss.cpp: pcss's inspector pages (Fernando, "Percentage-Closer Soft Shadows", NVIDIA,
// 2005). Its disks span 30 to 80 texels, so as cells they were 1,764 or 6,400 squares of about
// 7 px, and nothing marked which of the 16 search taps found a blocker. Here each step of the
// method is a figure at the numbers' size (18 px at projector sizes): the blocker search's 16
// taps on its disk, each a disc marked blocker or not with its depth; the penumbra's width by
// similar triangles with the trace's numbers; the filter's 16 taps, lit or shadowed, with their
// depths, and the visibility they give. Every number is the trace's (the kernel's own).
#include "kernel/trace_explain.h"
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

namespace {

enum class PcssPart { Search, Penumbra, Filter };

// The parts in the order the step shows them: a step about the width (focus on the formula
// without the neighbourhood) starts with it. No blocker: the search alone (it says visibility 1).
std::vector<PcssPart> pcssParts(const Trace& tr, const Focus& focus) {
    if (tr.pcss.blockers == 0) return {PcssPart::Search};
    if (focus.formula && !focus.neighbourhood) {
        return {PcssPart::Penumbra, PcssPart::Filter, PcssPart::Search};
    }
    return {PcssPart::Search, PcssPart::Penumbra, PcssPart::Filter};
}

// One of the two tap disks: the trace's reads [first, first + count), their Poisson scale.
struct TapDisk {
    size_t first = 0, count = 0;
    float scale = 0.0f;  // texels: the points are the 16-point set times this
    Colour edge;         // SEARCH or ACCENT
    bool search = true;  // blocker or not; else lit or shadowed (the same test, other words)
};

// A ring's stroke crosses `r` (grown by half the stroke): sampled every 2 px.
bool ringCrosses(const FramePlan::Ring& ring, const Rect& r) {
    Rect grown = r.expanded(0.5f * ring.width + 1.0f);
    int n = std::max(32, static_cast<int>(std::ceil(6.2831853f * ring.radius / 2.0f)));
    for (int k = 0; k < n; ++k) {
        float a = 6.2831853f * static_cast<float>(k) / static_cast<float>(n);
        if (grown.contains(ring.centre + ring.radius * glm::vec2(std::cos(a), std::sin(a)))) {
            return true;
        }
    }
    return false;
}

// Where a label of `size` goes beside a mark of radius `mr` at `at`: the first of eight places
// round it (right, left, above, below, then the corners; near, then a line further) inside
// `bounds`, clear of `avoid` and of the rings. Nothing when none is.
std::optional<Rect> placeBeside(glm::vec2 at, float mr, glm::vec2 size, const Rect& bounds,
                                const std::vector<Rect>& avoid,
                                const std::vector<FramePlan::Ring>& rings) {
    const glm::vec2 dirs[] = {{1, 0}, {-1, 0}, {0, -1}, {0, 1}, {1, -1}, {-1, -1}, {1, 1}, {-1, 1}};
    for (float extra : {0.0f, 0.6f * size.y}) {
        float d = mr + 3.0f + extra;
        for (glm::vec2 dir : dirs) {
            glm::vec2 c = at + dir * (glm::vec2(d) + 0.5f * size);
            Rect r{std::round(c.x - 0.5f * size.x), std::round(c.y - 0.5f * size.y), size.x,
                   size.y};
            if (!inside(r, bounds)) continue;
            bool clear = std::none_of(avoid.begin(), avoid.end(),
                                      [&](const Rect& a) { return overlaps(a, r); }) &&
                         std::none_of(rings.begin(), rings.end(),
                                      [&](const FramePlan::Ring& g) { return ringCrosses(g, r); });
            if (clear) return r;
        }
    }
    return std::nullopt;
}

// The map's texel edges over the disk's square, faint, where a texel is 6 px or more: the
// nearest texel each tap reads is the square it falls in.
void planTexelGridUnder(Planner& pl, const Rect& sq, glm::vec2 centre, glm::vec2 lookup, float k,
                        LegendNeeds& need) {
    if (k < 6.0f) return;
    std::vector<std::pair<glm::vec2, glm::vec2>> lines;
    for (float i = std::ceil(lookup.x - (centre.x - sq.x) / k);; i += 1.0f) {
        float x = centre.x + (i - lookup.x) * k;
        if (x > sq.right()) break;
        lines.push_back({{x, sq.y}, {x, sq.bottom()}});
    }
    for (float j = std::ceil(lookup.y - (centre.y - sq.y) / k);; j += 1.0f) {
        float y = centre.y + (j - lookup.y) * k;
        if (y > sq.bottom()) break;
        lines.push_back({{sq.x, y}, {sq.right(), y}});
    }
    Colour c = PCSS_GRID;
    c.a = 0.45f;
    pl.op([lines, c](Canvas& cv) {
        for (const auto& [a, b] : lines) cv.line(a, b, 1.0f, c);
    });
    need.texelGrid = true;
}

// The disk's taps as discs (filled lit or shadowed, ringed in the disk's colour) at their
// points, each with its depth beside it; the lookup point at the centre.
void planTapMarks(Planner& pl, const InspectorModel& m, const TypeSizes& t, const TapDisk& d,
                  const Rect& sq, glm::vec2 centre, float k) {
    const Trace& tr = *m.trace;
    glm::vec2 size(tr.map.size);
    float mr = std::max(6.0f, std::round(t.number * 0.42f));
    std::vector<Rect> avoid;
    std::vector<glm::vec2> at;
    for (size_t q = d.first; q < d.first + d.count; ++q) {
        const TapRecord& tap = tr.taps[q];
        at.push_back(centre + (tr.fetches[static_cast<size_t>(tap.fetch)].uv - tr.uv) * size * k);
        avoid.push_back(Rect{at.back().x - mr, at.back().y - mr, 2 * mr, 2 * mr}.expanded(2.0f));
    }
    float pr = std::max(5.0f, std::round(t.number * 0.3f));
    avoid.push_back(Rect{centre.x - pr, centre.y - pr, 2 * pr, 2 * pr}.expanded(2.0f));
    std::vector<FramePlan::Ring> rings = pl.plan.rings;
    TextStyle st{FontFace::Mono, t.number, TEXT};
    for (size_t q = 0; q < at.size(); ++q) {
        const TapRecord& tap = tr.taps[d.first + q];
        glm::vec2 p = at[q];
        Colour fill = tap.lit >= 0.5f ? LIT_COLOUR : SHADOWED_COLOUR;
        bool highlit = tap.fetch == m.highlightFetch;
        pl.op([=](Canvas& c) {
            if (highlit) c.circle(p, mr + 4.0f, HIGHLIGHT);
            c.circle(p, mr, d.edge);
            c.circle(p, mr - 2.5f, fill);
        });
        pl.box(BoxKind::Mark, Rect{p.x - mr, p.y - mr, 2 * mr, 2 * mr}, "inspector",
               d.search ? "search-tap" : "filter-tap");
        pl.plan.drawnFetches.push_back(tap.fetch);
        std::string depth = fixed(tap.depth, 3);
        glm::vec2 ts = measureText(st.face, st.pixelSize, depth);
        std::optional<Rect> r = placeBeside(p, mr, ts, sq, avoid, rings);
        if (!r) continue;
        avoid.push_back(r->expanded(2.0f));
        // A depth set a line further out gets a short leader from its disc.
        glm::vec2 near = glm::clamp(p, r->position(), r->position() + r->size());
        if (glm::length(near - p) > mr + 6.0f) {
            glm::vec2 from = p + glm::normalize(near - p) * (mr + 1.0f);
            pl.op([=](Canvas& c) { c.line(from, near, 1.0f, TEXT_DIM); });
        }
        Rect plate = r->expanded(1.0f);
        pl.fill(plate, Colour{PANEL.r, PANEL.g, PANEL.b, 0.85f});
        pl.text(r->position(), depth, st, BoxKind::Number, "inspector",
                d.search ? "search-depth" : "filter-depth");
        pl.plan.numberedTexels.push_back(tap.texel);
    }
    pl.op([=](Canvas& c) {
        c.circle(centre, pr + 1.5f, Colour{0, 0, 0, 0.9f});
        c.circle(centre, pr, POINT);
    });
    pl.box(BoxKind::Mark, Rect{centre.x - pr, centre.y - pr, 2 * pr, 2 * pr}, "inspector",
           "pcss-point");
}

// One disk in the square at the top of `box`: the texel grid, the ring the points fill, the
// taps with their depths, the lookup point. Returns the square's bottom.
float planTapDisk(Planner& pl, const InspectorModel& m, const TypeSizes& t, const Rect& box,
                  const TapDisk& d, LegendNeeds& need) {
    const Trace& tr = *m.trace;
    float side = std::floor(std::min(box.w, box.h));
    Rect sq{std::round(box.x + 0.5f * (box.w - side)), box.y, side, side};
    glm::vec2 centre = sq.centre();
    // Room round the ring for the outer taps' discs and their depths.
    float pad = std::max(6.0f, std::round(t.number * 0.42f)) + 4.0f;
    float radius = std::max(8.0f, 0.5f * side - pad);
    float reach = d.scale * poissonSetReach();
    float k = radius / std::max(reach, 1e-3f);  // pixels per texel
    glm::vec2 lookup = tr.uv * glm::vec2(tr.map.size);
    planTexelGridUnder(pl, sq, centre, lookup, k, need);
    float width = 2.0f;
    pl.op([=](Canvas& c) { c.ring(centre, radius, width, d.edge); });
    pl.plan.rings.push_back({centre, radius, width, sq});
    pl.plan.diskRadii.push_back(reach);
    planTapMarks(pl, m, t, d, sq, centre, k);
    (d.search ? need.searchDisk : need.disk) = true;
    (d.search ? need.blockerTaps : need.filterTaps) = true;
    return sq.bottom();
}

// A paragraph in the panel from `y` down, fitted to `width` (Sans, at the numbers' size: it
// holds the figure's numbers). Returns the y under it.
float planWords(Planner& pl, const InspectorLayout& l, const TypeSizes& t, const std::string& text,
                float y, float maxH, const std::string& role) {
    float margin = inspectorMargin(l);
    Rect area{l.inspector.x + margin, y, l.inspector.w - 2 * margin, maxH};
    FittedText f = fitText(text, FontFace::Sans, t.number, t.numberFloor, area.w, area.h);
    return y + placeFitted(pl, f, area, 0, FontFace::Sans, TEXT, "inspector", role, "");
}

// The height a paragraph takes at the numbers' size in the panel's width.
float wordsHeight(const InspectorLayout& l, const TypeSizes& t, const std::string& text) {
    float width = l.inspector.w - 2 * inspectorMargin(l);
    FittedText f = fitText(text, FontFace::Sans, t.number, t.numberFloor, width, 1e6f);
    return static_cast<float>(f.lines.size()) * f.lineHeight;
}

// A spot's map stores perspective depth: pcss turns it into distances from the light.
bool spotLight(const Trace& tr) { return tr.params.depthNear > 0.0f; }

// "1 texel", "16.876 texels".
std::string inTexels(float n) { return formatNumber(n) + (n == 1.0f ? " texel" : " texels"); }

std::string searchCaption(const Trace& tr) {
    return "Blocker search: 16 taps on a disk of scale " + inTexels(tr.pcss.searchRadius) +
           " round the lookup point, each reading its nearest texel. A texel whose depth "
           "is below ref " +
           fixed(tr.ref, 4) + " blocks the light.";
}

std::string searchResult(const Trace& tr) {
    if (tr.pcss.blockers == 0) {
        return "No blocker: the point sees the whole light, visibility 1 without filtering.";
    }
    std::string what = spotLight(tr) ? "mean distance from the light (each depth turned into "
                                       "its distance first)"
                                     : "mean depth";
    return std::to_string(tr.pcss.blockers) + " of the 16 taps are blockers; their " + what +
           " is d_b = " + formatNumber(tr.pcss.blockerDepth) + ".";
}

// The legend at the bottom of the page, its height measured first in a scratch plan.
void planLegendAtBottom(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                        const LegendNeeds& need, const TypeSizes& t, float bottom) {
    FramePlan scratch;
    Planner sp{scratch};
    float margin = inspectorMargin(l);
    float h = planLegend(sp, l, m, need, t, margin, 0.0f);
    planLegend(pl, l, m, need, t, margin, bottom - h);
}

// The height the legend of `need` takes in the panel.
float legendHeight(const InspectorLayout& l, const InspectorModel& m, const LegendNeeds& need,
                   const TypeSizes& t) {
    FramePlan scratch;
    Planner sp{scratch};
    return planLegend(sp, l, m, need, t, inspectorMargin(l), 0.0f);
}

// The disk page: caption, the disk, the result under it, the legend at the bottom.
void planDiskPage(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                  const TypeSizes& t, float top, float bottom, const TapDisk& d,
                  const std::string& caption, const std::string& result, LegendNeeds need) {
    need.cells = false;
    LegendNeeds full = need;
    full.searchDisk = full.blockerTaps = d.search;
    full.disk = full.filterTaps = !d.search;
    full.texelGrid = true;
    float legendH = legendHeight(l, m, full, t);
    float y = planWords(pl, l, t, caption, top, bottom - top, "pcss-caption");
    float resultH = wordsHeight(l, t, result) + t.number * 0.5f;
    float margin = inspectorMargin(l);
    Rect box{l.inspector.x + margin, y + t.number * 0.4f, l.inspector.w - 2 * margin,
             bottom - legendH - resultH - y - t.number * 0.8f};
    y = planTapDisk(pl, m, t, box, d, need);
    planWords(pl, l, t, result, y + t.number * 0.4f, bottom - y, "pcss-result");
    planLegendAtBottom(pl, l, m, need, t, bottom);
}

}  // namespace

bool pcssFigures(const Trace& tr) {
    return tr.pcss.searchRadius > 0.0f && tr.taps.size() >= static_cast<size_t>(PCF_PCSS_TAPS) &&
           tr.fetches.size() == tr.taps.size();
}

namespace {

// Page `part` of the figures under the header (top: its bottom).
void planPcssPage(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                  const TypeSizes& t, float top, int part, bool sceneTint) {
    const Trace& tr = *m.trace;
    std::vector<PcssPart> parts = pcssParts(tr, m.focus);
    PcssPart which =
        parts[static_cast<size_t>(std::clamp(part, 0, static_cast<int>(parts.size()) - 1))];
    float margin = inspectorMargin(l);
    bool more = part + 1 < static_cast<int>(parts.size());
    float noteH = more ? lineHeightOf(t.label) + t.label * 0.5f : 0.0f;
    float bottom = l.inspector.bottom() - margin - noteH;
    LegendNeeds need;
    need.footprint = sceneTint;
    size_t n = static_cast<size_t>(PCF_PCSS_TAPS);
    if (which == PcssPart::Search) {
        planDiskPage(pl, l, m, t, top, bottom, {0, n, tr.pcss.searchRadius, SEARCH, true},
                     searchCaption(tr), searchResult(tr), need);
    } else if (which == PcssPart::Filter) {
        std::string caption =
            "Filter: 16 taps on a disk of scale " + inTexels(tr.pcss.filterRadius) +
            (std::abs(tr.pcss.filterRadius - 0.5f * tr.pcss.penumbra) > 1e-4f
                 ? " (half the penumbra, kept within [" + formatNumber(PCF_PCSS_MIN_RADIUS) + ", " +
                       formatNumber(PCF_PCSS_MAX_RADIUS) + "])"
                 : " (half the penumbra)") +
            ", each compared with ref " + fixed(tr.ref, 4) + " and weighing 1/16.";
        std::string result = explainTrace(tr).back().text;
        planDiskPage(pl, l, m, t, top, bottom,
                     {n, tr.taps.size() - n, tr.pcss.filterRadius, ACCENT, false}, caption, result,
                     need);
        pl.plan.formulaWhole = true;
    } else {
        // Its marks are named in its own labels and words; the legend names the scene's tint.
        need.cells = need.point = false;
        float legendH = need.footprint ? legendHeight(l, m, need, t) : 0.0f;
        planPenumbraPage(pl, l, tr, t, top, bottom - legendH);
        if (need.footprint) planLegendAtBottom(pl, l, m, need, t, bottom);
    }
    if (tr.pcss.blockers == 0) pl.plan.formulaWhole = true;
    if (more) {
        const char* next[] = {"the blocker search", "the penumbra's width", "the filter's taps"};
        planNextPageNote(pl, l, m, t, margin, bottom + t.label * 0.5f,
                         next[static_cast<int>(parts[static_cast<size_t>(part) + 1])]);
    }
}

}  // namespace

void planPcssInspector(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                       const TypeSizes& t) {
    const Trace& tr = *m.trace;
    float margin = inspectorMargin(l);
    Header header = headerOf(tr, t, l.inspector.w - 2 * margin);
    planHeader(pl, l, header, t, margin, tr, m.hidden);
    int parts = static_cast<int>(pcssParts(tr, m.focus).size());
    pl.plan.textPages = std::max(pl.plan.textPages, parts);
    float top = l.inspector.y + margin + header.height + t.label * 0.5f;
    planPcssPage(pl, l, m, t, top, std::clamp(m.textPage, 0, parts - 1), pl.plan.footprintShown);
}

}  // namespace pcf::inspector_detail
