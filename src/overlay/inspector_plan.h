// inspector_plan.h: the parts the inspector's source files share (internal to src/overlay; the
// public interface is inspector.h). A frame is planned, panel by panel, into boxes and draw
// commands (FramePlan) by these functions, one file each:
//   inspector.cpp               the frame's panels (inspectorLayout), type sizes, planFrame, JSON
//   inspector_text.cpp          text blocks that fit: wrap, smaller type to a floor, then pages
//   inspector_scene.cpp         the scene: the picked pixel, its label, the texel grid
//   inspector_neighbourhood.cpp the magnified cells: their one layout (panelLayout) and drawing
//   inspector_cell_numbers.cpp  the numbers in each cell, placed clear of the marks
//   inspector_numbers.cpp       the inspector's header, notes, legend and formula
//   inspector_steps.cpp         the step panel, the map thumbnail, the status line
//   inspector_keys.cpp          the key table and the help overlay drawn from it
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "draw/text_layout.h"
#include "kernel/trace_explain.h"
#include "overlay/inspector.h"

namespace pcf::inspector_detail {

// Colours (straight alpha).
constexpr Colour PANEL{0.10f, 0.11f, 0.14f, 1.0f};
constexpr Colour PANEL_LIGHT{0.16f, 0.17f, 0.21f, 1.0f};
constexpr Colour TEXT{0.92f, 0.93f, 0.95f, 1.0f};
constexpr Colour TEXT_DIM{0.66f, 0.69f, 0.76f, 1.0f};
constexpr Colour MONO_TEXT{0.80f, 0.92f, 1.0f, 1.0f};
constexpr Colour ACCENT{0.35f, 0.78f, 0.98f, 1.0f};
constexpr Colour POINT{0.95f, 0.20f, 0.45f, 1.0f};
constexpr Colour GATHER{0.30f, 0.90f, 0.50f, 1.0f};
constexpr Colour HW_RING{0.10f, 0.10f, 0.10f, 0.95f};
constexpr Colour PADDING{0.30f, 0.31f, 0.35f, 1.0f};
constexpr Colour CLAMPED{1.0f, 0.6f, 0.1f, 1.0f};  // a texel read clamped to the edge
constexpr Colour DARK_TEXT{0.08f, 0.08f, 0.10f, 1.0f};
constexpr Colour STATUS{0.03f, 0.03f, 0.04f, 1.0f};
constexpr Colour WEIGHT_BAR{0.95f, 0.35f, 0.25f, 0.9f};
constexpr Colour HIGHLIGHT{1.0f, 0.62f, 0.10f, 1.0f};
constexpr Colour FOOTPRINT_TINT{0.2f, 0.85f, 1.0f, 0.18f};
constexpr Colour SEARCH{0.80f, 0.58f, 1.0f, 1.0f};       // pcss: the blocker search's taps and disk
constexpr Colour PCSS_GRID{0.45f, 0.47f, 0.53f, 1.0f};   // pcss's figures: the faint texel grid
constexpr Colour HIDDEN_BIT{0.42f, 0.36f, 0.52f, 1.0f};  // a cell whose bit a question hides
constexpr Colour MOMENT_BAR{0.55f, 0.64f, 0.80f, 1.0f};  // the moment figure's histogram bars
constexpr Colour MOMENT_NEG_CURVE{0.62f, 0.88f, 0.42f, 1.0f};  // evsm4's negative warp's bound
constexpr Colour PCF_MARK{0.95f, 0.95f, 0.98f, 1.0f};  // pcf-naive of the moments' footprint

// A texel narrower than this on screen makes the grid's lines a moire that reads as acne: the
// grid is hidden then (the tint of the texels read stays). Lesson 8's acne stripes, one texel
// apart, measure 3.95 px across at 1024x768 presentation: their grid shows.
constexpr float GRID_MIN_TEXEL_PX = 3.5f;

inline std::string fixed(float v, int decimals) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, static_cast<double>(v));
    return buf;
}

// A weight in five characters: three decimals, or, for a weight above 0 that would print as
// 0.000 (a 7x7 tent's outer texels), its first digit and power of ten ("3e-04"): a texel that
// counts never reads as one that does not.
inline std::string weightText(float w) {
    if (w <= 0.0f || w >= 0.0005f) return fixed(w, 3);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0e", static_cast<double>(w));
    return buf;
}

inline float lineHeightOf(float size) {
    return std::max(fontMetrics(FontFace::Sans, size).lineHeight,
                    fontMetrics(FontFace::Mono, size).lineHeight);
}

// The next smaller size on the way down to a floor.
inline float stepDown(float size, float floor) {
    float next = std::round(size * 0.92f);
    if (next >= size) next = size - 1.0f;
    return std::max(floor, next);
}

inline bool overlaps(const Rect& a, const Rect& b) { return !a.intersect(b).empty(); }

inline bool inside(const Rect& inner, const Rect& outer) {
    return inner.x >= outer.x - 0.01f && inner.y >= outer.y - 0.01f &&
           inner.right() <= outer.right() + 0.01f && inner.bottom() <= outer.bottom() + 0.01f;
}

// Records boxes and the draw commands that go with them.
// The keys that turn a page, as the "more" marks say them in the window (on an animation step
// Space plays it); a written frame names none.
inline std::string pageKeys(const InspectorModel& m) {
    if (!m.interactive) return "";
    return m.plays ? "Right" : "Space/Right";
}

struct Planner {
    FramePlan& plan;
    bool onTop = false;

    void op(std::function<void(Canvas&)> f) {
        (onTop ? plan.top : plan.base).push_back(std::move(f));
    }
    void box(BoxKind kind, const Rect& r, const std::string& panel, const std::string& role,
             float font = 0.0f, bool shortened = false) {
        plan.boxes.push_back({kind, r, panel, role, font, shortened, {}});
    }
    void fill(const Rect& r, const Colour& c) {
        op([=](Canvas& cv) { cv.fillRect(r, c); });
    }
    // Text at a whole-pixel position; returns its measured box (what Canvas::text will cover).
    Rect measure(glm::vec2 pos, const std::string& s, const TextStyle& st) const {
        glm::vec2 size = measureText(st.face, st.pixelSize, s);
        float x = std::round(pos.x);
        if (st.align == TextAlign::Center) x = std::round(pos.x - size.x * 0.5f);
        if (st.align == TextAlign::Right) x = std::round(pos.x - size.x);
        return {x, std::round(pos.y), size.x, size.y};
    }
    Rect text(glm::vec2 pos, const std::string& s, const TextStyle& st, BoxKind kind,
              const std::string& panel, const std::string& role, bool shortened = false) {
        Rect r = measure(pos, s, st);
        TextStyle left = st;
        left.align = TextAlign::Left;
        glm::vec2 at = r.position();
        op([=](Canvas& cv) { cv.text(at, s, left); });
        box(kind, r, panel, role, st.pixelSize, shortened);
        plan.boxes.back().text = s;
        return r;
    }
};

// ---- inspector_text.cpp: text blocks that fit. ----

struct FitLine {
    std::string text;
    bool mono = false;  // a preformatted line: monospace, spaces kept, never rewrapped
    SpanLine spans;     // a prose line's pieces: prose and `code spans` (monospace); text is
                        // their concatenation, without the backticks
    int para = -1;      // prose: the source line (up to a hard line break) it was wrapped from
};

struct FittedText {
    float size = 0.0f;
    float lineHeight = 0.0f;
    std::vector<FitLine> lines;
    // The first line of each page (pageStarts[0] = 0), and where the last page ends: a page holds
    // lines [pageStarts[k], pageStarts[k + 1]) or, the last, [pageStarts.back(), pageEnd).
    std::vector<int> pageStarts{0};
    int pages = 1;
    bool stepped = false;  // drawn below its starting size
};

// Wraps `text` into `width`, stepping the type down from `start` towards `floor` until it fits
// `height`; what still does not fit is paged. markLine: each page keeps its last line for the
// "more" mark (false: the mark goes elsewhere, MarkPlace).
FittedText fitText(std::string_view text, FontFace face, float start, float floor, float width,
                   float height, bool markLine = true);
// Where a paged block's "more" mark goes instead of its area's last line: right-aligned in
// `row`, at `size` (the step header's line in presentation mode).
struct MarkPlace {
    Rect row;
    float size = 0.0f;
};
// The "more" mark of page `page`: "more Space/Right (1/3)", the last page's "(3/3)".
std::string moreMarkText(const FittedText& f, int page, const std::string& moreHint);
// Draws page `page` of a fitted block at the top-left of `area`, with the "more" mark on the
// last line of the area (or at `mark`) when there are more pages. Returns the height used.
float placeFitted(Planner& pl, const FittedText& f, const Rect& area, int page, FontFace face,
                  const Colour& colour, const std::string& panel, const std::string& role,
                  const std::string& moreHint, const std::optional<MarkPlace>& mark = std::nullopt);

// ---- inspector_neighbourhood.cpp: the inspector panel's one layout and the cells. ----

// The inspector's header: method, visibility, fetch counts, uv/ref/bias (wrapped to the panel).
struct Header {
    std::string title;
    std::string result;
    std::vector<std::string> counts;  // wrapped
    bool resultOnOwnLine = false;
    float height = 0.0f;
};

// The cell geometry the inspector uses for a trace.
struct Grid {
    Neighbourhood full;
    Neighbourhood view;
    Rect area;  // the cells
    float cell = 0.0f;
    float number = 0.0f;  // the cells' number size
    float bit = 0.0f;
    float pad = 0.0f;  // inset of the numbers from the cell's edge (gather outlines live there)
    float bar = 0.0f;  // weight bar height
    Rect laneTop, laneLeft, laneRight, laneBottom;
    float bottom = 0.0f;  // below the bottom lane (and the sub-texel inset)
    // hw8 (the texture unit keeps 8 fractional bits): the fx and fy labels add the 8-bit
    // fraction k/256 on a second line, and the sub-texel inset, right of the fy lane, magnifies
    // the 1/256 steps around the lookup point. Empty when the trace is not hw8.
    bool hw8 = false;
    Rect inset;
    Rect insetCaption;  // the lane above the inset
};

// Texel index labels go on every `step`-th cell: the smallest of 1, 2, 5, 10, 20, 50, 100 whose
// run of cells is at least `need` pixels long.
inline int indexLabelStep(float cell, float need) {
    for (int step : {1, 2, 5, 10, 20, 50}) {
        if (static_cast<float>(step) * cell >= need) return step;
    }
    return 100;
}

// True when the lookup's hardware taps or gathers ran with 8 fractional bits (issue 10).
inline bool hw8Lookup(const Trace& tr) {
    return tr.usesTextureUnit && tr.params.precision == PCF_PRECISION_HW8;
}
// The 8-bit fraction as the labels print it, "k/256" with k = fracHw8 * 256 (0..255).
std::string hw8Steps(float fracHw8);

// Everything the inspector panel places for a trace, computed once: the plan, neighbourhoodView
// and neighbourhoodArea all read it. The view is always the whole neighbourhood (the highlight
// argument is kept for callers; it no longer moves a window).
struct PanelLayout {
    float margin = 0.0f;  // inside the panel, all round
    float width = 0.0f;   // the panel's width less the margins
    Header header;
    Grid grid;
};
float inspectorMargin(const InspectorLayout& l);
// reserve: the height kept under the cells for the notes, the legend and the formula; < 0: a
// share of the panel (inspectorPanel picks it: the formula's own height, or none of it when the
// formula goes on a page of its own).
PanelLayout panelLayout(const InspectorLayout& l, const Trace& tr, const TypeSizes& t,
                        int highlight = -1, float reserve = -1.0f);
// The notes and the legend under the cells, in label lines, when the formula is not there.
constexpr float BELOW_APART_LINES = 7.0f;

// The inspector panel's cells as the frame draws them: planned (into `cells`, a scratch plan)
// with the formula under them when it fits there whole (`together`), else with the formula's
// room, the formula then on a page of its own. cellsBottom: under the notes and the legend.
struct InspectorPanel {
    PanelLayout layout;
    FramePlan cells;
    float cellsBottom = 0.0f;
    bool together = true;
    // The read texels whose cells could not hold all their numbers: the texel table lists them
    // on the page(s) after the cells (inspector_table.cpp).
    std::vector<glm::ivec2> tableTexels;
};
// sceneTint: the scene shows the texels read (planTexelGrid), so the legend names them.
InspectorPanel inspectorPanel(const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t,
                              bool onTop = false, bool sceneTint = false);

// The line width of the inspector's strokes.
inline float lineOf(const InspectorLayout& l) {
    return l.presentation ? 3.0f : std::max(1.0f, std::round(l.scale));
}

// Which kinds of mark the cells drew (the legend names only those).
struct LegendNeeds {
    bool cells = true;  // the cells' fills (lit, shadowed); pcss's figures have none
    bool point = true;  // the lookup point (pcss's penumbra figure has none)
    bool highlight = false, weightBar = false, dots = false, rings = false, gathers = false,
         fraction = false, baseCentre = false, padding = false;
    bool zeroWeight = false;  // a texel read whose weight is 0 (its fill paled towards grey)
    bool footprint = false;   // the texels read, tinted on the scene
    bool clamped = false;     // a texel read clamped to the edge (any finite uv)
    bool hw8 = false;         // the 8-bit position (the sub-texel inset)
    bool movedMark = false;   // a point mark moved beside its cell's numbers, with a tick
    bool disk = false;        // the Poisson disk's circle
    bool searchDisk = false;  // pcss: the blocker search's disk and taps
    // pcss's figures (inspector_pcss.cpp): the search's taps as discs, blocker or not; the
    // filter's taps, lit or shadowed; the faint texel grid under them.
    bool blockerTaps = false, filterTaps = false, texelGrid = false;
    // A moment method's figure (inspector_moment_page.cpp): the footprint's histogram, its mean,
    // the receiver's t, the bound's curves (evsm4's negative warp's, after the LBR linstep), and
    // msm's reconstructed points.
    bool momentBars = false, meanLine = false, receiverLine = false, boundCurve = false,
         negCurve = false, lbrCurve = false, msmPoints = false;
    bool pcfMark = false;  // PCF of the same footprint at t, on the bound's plot
};

// The legend: a swatch and a word for every kind of mark this frame draws, flowing onto more
// lines when the panel is narrow (inspector_legend.cpp). From `y` down; returns the new y.
float planLegend(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                 const LegendNeeds& need, const TypeSizes& t, float margin, float y);
// The inspector's header (method, visibility, counts, uv, ref, bias) at the panel's top, with
// the numbers `hidden` drawn as "?" (the room is the one the numbers take, so a question's cells
// sit where its answer's do).
void planHeader(Planner& pl, const InspectorLayout& l, const Header& h, const TypeSizes& t,
                float margin, const Trace& tr, const HiddenNumbers& hidden);
// A line at the panel's bottom saying where the rest of the inspector is (the next page).
// `y`: the top of the room left under the rest.
void planNextPageNote(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                      const TypeSizes& t, float margin, float y, const std::string& what);

// ---- inspector_pcss.cpp: pcss's pages (Fernando, "Percentage-Closer Soft Shadows", 2005). ----
// A pcss trace (its blocker search ran) is shown as figures readable from a room instead of
// its disks' hundreds of small cells: the search's 16 taps on its disk, each a disc marked
// blocker or not with its depth; the penumbra's width by similar triangles with the trace's
// numbers; the filter's 16 taps, lit or shadowed, with their depths, and the visibility.
bool pcssFigures(const Trace& tr);
// The inspector panel of a pcss trace: the header, then the page of its figures the model's
// textPage asks for (the frame's pages grow to hold them all).
void planPcssInspector(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                       const TypeSizes& t);
// The penumbra's page (inspector_pcss_penumbra.cpp): the similar triangles drawn with the
// trace's distances, and the words that give w with its numbers, between top and bottom.
void planPenumbraPage(Planner& pl, const InspectorLayout& l, const Trace& tr, const TypeSizes& t,
                      float top, float bottom);

// ---- inspector_moment_page.cpp: the moment methods' page (vsm, evsm2, evsm4, msm, ...). ----
// Their map holds averages and no texel a bit: the panel shows the statistics instead of cells,
// the footprint's depths as a histogram, the moments, the bound over depth or msm's points, and
// PCF of the same footprint (inspector_moments.h has the numbers; FramePlan::moments, what
// was drawn).
bool momentFigures(const Trace& tr);
void planMomentInspector(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                         const TypeSizes& t);

// ---- inspector_disks.cpp: the disks poisson's and pcss's points lie on. ----
// The rings planDisks draws round the lookup point, radii in texels (0: none): pcss's blocker
// search, and poisson's disk or pcss's filter disk. The cells reach round them (gridOf).
struct DiskRings {
    float search = 0.0f;
    float filter = 0.0f;
};
DiskRings diskRings(const Trace& tr);
struct CellMarks;
// Rings round the lookup point (`point`, pixels; `cell` pixels per texel) clipped to `area`:
// poisson's disk, or pcss's search disk and (when it found a blocker) its filter disk. Each
// ring's stroke goes into `marks` as small squares along it, which the cells' numbers keep
// clear of (7.1's ring crossed them), and into the plan's rings.
void planDisks(Planner& pl, const Trace& tr, const Rect& area, glm::vec2 point, float cell,
               float width, LegendNeeds& legend, CellMarks& marks);

// The cells, their numbers, the fetch marks and the fx/fy brackets; counts the cells whose
// numbers the marks left no room for.
void planCells(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const Grid& g,
               const TypeSizes& t, LegendNeeds& legend, int& hiddenCells);

// The comparison bit's type size for a number size.
float bitFor(float number);
// The first read of `texel` in the trace's read order; null when none reads it.
const TapRecord* firstTapAt(const Trace& tr, glm::ivec2 texel);
// Numbers keep this far from any mark, pixels.
constexpr float MARK_CLEARANCE_PX = 2.0f;

// Marks go first: they sit where the math puts them, and the numbers then find room beside them.
// Their rects (clipped to the cells) are what the numbers avoid; their draw calls run after the
// numbers', so that a mark is never hidden under a number's cell.
// A point mark (a lookup dot, a hardware tap's ring, the lookup point) whose cell cannot hold its
// numbers around it moves into a lane at that cell's edge (see planCellNumbers); it keeps its
// true position in one axis and a tick in the cell's border band gives the other.
struct PointMark {
    glm::vec2 at;       // where it is drawn
    glm::vec2 trueAt;   // where the math puts it
    float half = 0.0f;  // its box: a square of this half side round `at`
    std::string role;
    Colour tickColour;
    std::function<void(Canvas&, glm::vec2)> draw;
    // Never moved: a disk's points and the lookup point at its centre (poisson, pcss) are the
    // figure itself; a point moved off them no longer lies on its ring (7.1's lookup point sat
    // 30 px off its ring's centre). The numbers find room around them instead.
    bool fixed = false;
    Rect rect() const { return {at.x - half, at.y - half, 2 * half, 2 * half}; }
};

struct CellMarks {
    std::vector<Rect> rects;  // fixed marks: weight bars, gather outlines, ticks
    std::vector<PointMark> points;
    std::vector<std::function<void(Canvas&)>> ops;
    void add(Planner& pl, const Rect& area, const Rect& r, const std::string& role) {
        Rect clipped = r.intersect(area);
        if (clipped.empty()) return;
        rects.push_back(clipped);
        pl.box(BoxKind::Mark, clipped, "inspector", role);
    }
    // Every mark's rect, the point marks where they are now, clipped to the cells.
    std::vector<Rect> all(const Rect& area) const {
        std::vector<Rect> out = rects;
        for (const PointMark& p : points) {
            Rect c = p.rect().intersect(area);
            if (!c.empty()) out.push_back(c);
        }
        return out;
    }
};

// ---- inspector_cell_numbers.cpp: each cell's number block, placed clear of the marks. ----

// Numbers: each cell's block (bit, own ref, depth, weight) goes where no mark is; a smaller
// block, or none, where the whole does not fit (smaller type first, not below numberFloor).
// Moves point marks into lanes where that gives a cell its numbers. Returns the cells left
// without numbers.
int planCellNumbers(Planner& pl, const InspectorModel& m, const Grid& g, CellMarks& cm,
                    float numberFloor);

// ---- inspector_table.cpp: the texel table. ----

// The read texels (each once, row by row) whose numbers `cells` did not draw whole.
std::vector<glm::ivec2> texelsWithoutNumbers(const Trace& tr, const FramePlan& cells);
// The formula as it follows the texel table (it goes on pages after it unless it fits under the
// table's last lines): its pages on its own (0: it is with the cells, not after the table), and
// whether it fits whole in the panel from a y down.
struct FormulaAfter {
    int pages = 0;
    std::function<bool(float top)> fitsFrom;
};
// How the texel table is paged: in rows (one per texel, with bit, own ref, depth, depth - ref
// and w) or in grids (each number of every texel laid out as the cells sit, the bits left to
// the cells), whichever makes fewer parts; the first row or grid of each page; whether the
// formula goes whole under the last page's lines, and where.
struct TablePaging {
    bool grids = false;
    std::vector<size_t> starts{0};
    bool formulaBelow = false;
    float formulaTop = 0.0f;
    int parts = 1;  // the table's pages, and the formula's after them unless formulaBelow
    int pages() const { return static_cast<int>(starts.size()); }
};
// The texel table: the texels of `texels` with the numbers their cells show at a size where they
// fit, under a title (wrapped, never cut; it gives the ref when every read compares with the
// same one, and the ref column or grid goes), in the inspector panel from `top` down.
// texelTablePaging: how it pages (bitTexels: the texels whose cells show their bit);
// planTexelTable: page `page` of it (it lists the texels it draws whole in numberedTexels);
// returns the y under its last line.
TablePaging texelTablePaging(const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t,
                             const std::vector<glm::ivec2>& texels,
                             const std::vector<glm::ivec2>& bitTexels, float top,
                             const FormulaAfter& formula);
float planTexelTable(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                     const TypeSizes& t, const std::vector<glm::ivec2>& texels, float top,
                     const TablePaging& paging, int page);

// ---- inspector_subtexel.cpp: the hw8 inset. ----

// The 1/256-texel lattice around a hardware tap's or gather's position (the highlighted fetch's,
// else the one nearest the lookup point), magnified in g.inset: the float position,
// the 8-bit one it rounds to and the square of positions that round there. Nothing unless g.hw8.
void planSubtexelInset(Planner& pl, const InspectorLayout& l, const Trace& tr, const Grid& g,
                       const TypeSizes& t, int highlight);
// The colour of the 8-bit position (inset, fx/fy labels, legend).
constexpr Colour HW8_POINT{0.72f, 1.0f, 0.28f, 1.0f};

// ---- One function per panel (the files named at the top). ----

Header headerOf(const Trace& tr, const TypeSizes& t, float width);
// The header's line on the cascade a cascaded map's lookup read (inspector_cascade.cpp): its
// index of the count, view depths, texel size and measured density; empty with one map.
std::string cascadeHeaderText(const Trace& tr);
// In a cascaded map's blend band (Trace::cascadeBlend), the line under it: the cascade read's
// visibility and the next cascade's side by side, the next one's weight and the result shown;
// "" outside the band or with one map.
std::string cascadeBlendText(const Trace& tr, const HiddenNumbers& hidden);
void planScene(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t);
void planInspector(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                   const TypeSizes& t);
void planSteps(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t);
void planThumbnail(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                   const TypeSizes& t);
void planStatus(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t);
void planHelp(Planner& pl, const InspectorLayout& l, const TypeSizes& t);
// inspector_predict.cpp: the step panel's text area `area` for a question (m.predict): the
// question with its choices and what was typed, or, revealed, the answer above the step's words.
void planPredict(Planner& pl, const InspectorModel& m, const TypeSizes& t, const Rect& area);
// A number the frame hides (HiddenNumbers): "?" after its prefix ("w ?").
inline std::string hiddenOr(bool hidden, const std::string& prefix, const std::string& shown) {
    return prefix + (hidden ? std::string(HIDDEN_NUMBER) : shown);
}

// The step panel's margin and the top of what sits under the lesson title (the step text and
// the thumbnail): one definition for inspectorLayout and planSteps.
float stepsMargin(const InspectorLayout& l);
float stepsBodyTop(const InspectorLayout& l, const TypeSizes& t);

}  // namespace pcf::inspector_detail
