#include "charts/speed_chart_labels.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "charts/chart_axes.h"
#include "charts/speed_chart.h"
#include "draw/text_layout.h"
#include "kernel/methods.h"

namespace pcf {

namespace {

float overlapArea(const Rect& a, const Rect& b) {
    Rect o = a.intersect(b);
    return o.w * o.h;
}

// Area of r outside `inside`.
float outsideArea(const Rect& r, const Rect& inside) { return r.w * r.h - overlapArea(r, inside); }

// The distance from a box to a point (0 inside it), pixels.
float boxDistance(const Rect& box, glm::vec2 p) {
    return glm::length(glm::clamp(p, box.position(), box.position() + box.size()) - p);
}

// A name's box, or a badge's disc (the largest disc in its square box).
struct Spot {
    Rect box;
    bool disc = false;
};

// The distance from a spot to a point (0 inside it), pixels.
float spotDistance(const Spot& s, glm::vec2 p) {
    if (!s.disc) return boxDistance(s.box, p);
    return std::max(0.0f, glm::length(s.box.centre() - p) - 0.5f * s.box.w);
}

// 24 directions round a dot, 15 degrees apart, starting to the right.
constexpr int DIRECTIONS = 24;
glm::vec2 direction(int i) {
    float a = static_cast<float>(i) * 6.2831853f / DIRECTIONS;
    return {std::cos(a), std::sin(a)};
}

// A uniform grid of cells over the chart, each listing the items (dots, error bars, placed
// names) whose boxes reach into it: a spot tried visits only the few items near it, not every
// dot and name, so placing n names takes time about linear in n, not quadratic. Items and
// queries outside the chart fall into its border cells.
class CellIndex {
  public:
    CellIndex(glm::vec2 size, float cell)
        : mCell(cell),
          mCols(std::max(1, static_cast<int>(std::ceil(size.x / cell)))),
          mRows(std::max(1, static_cast<int>(std::ceil(size.y / cell)))),
          mItems(static_cast<size_t>(mCols) * static_cast<size_t>(mRows)) {}

    void insert(size_t id, const Rect& r) {
        forCells(r, [&](size_t cell) { mItems[cell].push_back(id); });
    }
    void clear() {
        for (std::vector<size_t>& cell : mItems) cell.clear();
    }
    // The ids of the items whose cells r reaches, ascending, each once: every item whose box
    // overlaps r is among them.
    void query(const Rect& r, std::vector<size_t>& out) const {
        out.clear();
        forCells(r, [&](size_t cell) {
            out.insert(out.end(), mItems[cell].begin(), mItems[cell].end());
        });
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

    // Whether pred(id) holds for an item whose cells r reaches (items in several cells may be
    // asked more than once).
    template <typename Pred>
    bool any(const Rect& r, Pred pred) const {
        bool found = false;
        forCells(r, [&](size_t cell) {
            for (size_t id : mItems[cell]) {
                if (found) return;
                found = pred(id);
            }
        });
        return found;
    }

  private:
    // f(cell index) for every cell r reaches (floor is monotone, so two boxes that overlap reach
    // a common cell).
    template <typename F>
    void forCells(const Rect& r, F f) const {
        // The cell of coordinate t among n, clamped (NaN to the first).
        auto cellOf = [&](float t, int n) {
            float c = std::floor(t / mCell);
            if (!(c >= 0.0f)) return 0;
            return c >= static_cast<float>(n - 1) ? n - 1 : static_cast<int>(c);
        };
        int c0 = cellOf(r.x, mCols), c1 = std::max(c0, cellOf(r.right(), mCols));
        int r0 = cellOf(r.y, mRows), r1 = std::max(r0, cellOf(r.bottom(), mRows));
        for (int j = r0; j <= r1; ++j) {
            for (int i = c0; i <= c1; ++i) f(static_cast<size_t>(j * mCols + i));
        }
    }
    float mCell;
    int mCols, mRows;
    std::vector<std::vector<size_t>> mItems;
};

// The chart's marks a spot must keep off, computed once per placement.
class Placer {
  public:
    explicit Placer(SpeedChartLayout& layout)
        : L(layout),
          dotCells(layout.size, cellSize(layout)),
          barCells(layout.size, cellSize(layout)),
          placedCells(layout.size, cellSize(layout)) {
        for (size_t k = 0; k < L.points.size(); ++k) {
            marks.push_back(speedChartMarkRadius(L, k));
            bars.push_back(speedChartBarBox(L, k));
            dotCells.insert(k, {L.points[k].x, L.points[k].y, 0.0f, 0.0f});
            barCells.insert(k, bars.back());
            widestMark = std::max(widestMark, marks.back());
        }
    }

    // What a spot for row k does wrong, 0 when nothing: it leaves the plot, lies on a placed
    // name or badge, an error bar (a bar through a name strikes it out), a dot or its rings (its
    // own too, with CHART_MARK_CLEARANCE; a badge may lie on its own dot's rings), or is not
    // nearer its own dot than any other by a dot radius (dots whose discs overlap excepted: no
    // spot names one of them and not the other). Only the items near the spot can add to it
    // (each term below is 0 farther out), and they are added in row order, so the sum is the
    // same float as over every row.
    float fault(size_t k, const Spot& s) const {
        constexpr float HARD = 1000.0f;
        float f = HARD * outsideArea(s.box, L.plot);
        placedCells.query(s.box, near);
        for (size_t i : near) f += HARD * overlapArea(s.box, placed[i]);
        glm::vec2 p = L.points[k];
        float own = spotDistance(s, p);
        // A dot counts within its keep distance (at most the widest mark's) or within own plus
        // a dot radius; a pixel more for rounding.
        float reach = std::max(widestMark + CHART_MARK_CLEARANCE, own + L.dotRadius) + 1.0f;
        nearRows(s.box, reach);
        for (size_t j : near) {
            f += HARD * overlapArea(s.box, bars[j]);
            float d = spotDistance(s, L.points[j]);
            float keep = (j == k && s.disc ? L.dotRadius : marks[j]) + CHART_MARK_CLEARANCE;
            if (d < keep) f += HARD * (keep - d);
            if (j == k || glm::length(L.points[j] - p) < 2.0f * L.dotRadius) continue;
            // (By a dot radius at least: a name about as near two dots reads as either's.)
            if (d <= own + L.dotRadius) f += HARD * (1.0f + own + L.dotRadius - d);
        }
        return f;
    }

    // Whether fault(k, s) is 0, without summing: every term of fault is >= 0, so it is 0 when
    // none is positive, and the first positive one ends the test (in a crowded chart most spots
    // tried meet a dot at once).
    bool clean(size_t k, const Spot& s) const {
        if (outsideArea(s.box, L.plot) > 0.0f) return false;
        glm::vec2 p = L.points[k];
        float own = spotDistance(s, p);
        float reach = std::max(widestMark + CHART_MARK_CLEARANCE, own + L.dotRadius) + 1.0f;
        bool nearDot = dotCells.any(s.box.expanded(reach), [&](size_t j) {
            float d = spotDistance(s, L.points[j]);
            float keep = (j == k && s.disc ? L.dotRadius : marks[j]) + CHART_MARK_CLEARANCE;
            if (d < keep) return true;
            if (j == k || glm::length(L.points[j] - p) < 2.0f * L.dotRadius) return false;
            return d <= own + L.dotRadius;
        });
        if (nearDot) return false;
        auto overlaps = [&](const std::vector<Rect>& boxes) {
            return [&](size_t i) { return overlapArea(s.box, boxes[i]) > 0.0f; };
        };
        return !placedCells.any(s.box, overlaps(placed)) && !barCells.any(s.box, overlaps(bars));
    }

    // The nearest clean spot for a name of size t round row k's dot whose nearest point lies
    // at most `reach` from the dot's centre: rings from the dot's outer ring outwards, a few
    // pixels apart, each in 24 directions with the box's side or corner nearest the dot at the
    // ring; the first ring with a clean spot gives its nearest one.
    std::optional<Rect> nameSpot(size_t k, glm::vec2 t, float reach) const {
        glm::vec2 p = L.points[k];
        float step = std::max(2.0f, 0.5f * L.dotRadius);
        for (float r = marks[k] + CHART_MARK_CLEARANCE; r <= reach + 1e-3f; r += step) {
            std::optional<Rect> best;
            float bestD = 1e30f;
            for (int i = 0; i < DIRECTIONS; ++i) {
                glm::vec2 d = direction(i);
                glm::vec2 at = p + r * d;
                float x = d.x > 0.38f ? at.x : d.x < -0.38f ? at.x - t.x : at.x - 0.5f * t.x;
                float y = d.y > 0.38f ? at.y : d.y < -0.38f ? at.y - t.y : at.y - 0.5f * t.y;
                Rect box{std::round(x), std::round(y), t.x, t.y};
                float own = boxDistance(box, p);
                if (own > reach || own >= bestD || !clean(k, {box, false})) continue;
                best = box;
                bestD = own;
            }
            if (best) return best;
        }
        return std::nullopt;
    }

    // What a badge centred on row k's dot does wrong, 0 when nothing: it leaves the plot, lies
    // on a placed name or badge, or covers another dot's centre (the badge is drawn over the
    // dots: each other dot must still show where it is), but for a dot whose disc overlaps this
    // one's, which overlapping dots hide already.
    float onDotFault(size_t k, const Rect& box) const {
        constexpr float HARD = 1000.0f;
        float f = HARD * outsideArea(box, L.plot);
        placedCells.query(box, near);
        for (size_t i : near) f += HARD * overlapArea(box, placed[i]);
        float keep = L.badgeRadius + CHART_MARK_CLEARANCE;
        glm::vec2 p = L.points[k];
        dotCells.query(
            {p.x - keep - 1.0f, p.y - keep - 1.0f, 2.0f * keep + 2.0f, 2.0f * keep + 2.0f}, near);
        for (size_t j : near) {
            float d = glm::length(L.points[j] - p);
            if (j != k && d >= 2.0f * L.dotRadius && d < keep) f += HARD * (keep - d);
        }
        return f;
    }

    Rect onDotBox(size_t k) const {
        glm::vec2 p = glm::round(L.points[k]);
        float radius = L.badgeRadius;
        return {p.x - radius, p.y - radius, 2.0f * radius, 2.0f * radius};
    }

    // Row k's badge: a disc touching the dot's outer ring where a clean spot does, else one
    // touching the dot itself (on its rings), else the nearest clean one up to
    // speedChartBadgeGap beyond the ring; none clean, the badge centred on the dot, and where
    // even that is not clean, the spot of least fault. Returns whether it is on the dot.
    bool placeBadge(size_t k) {
        Rect box = badgeSpot(k);
        bool onDot = !clean(k, {box, true});
        if (onDot) {
            Rect there = onDotBox(k);
            if (onDotFault(k, there) <= 0.0f || onDotFault(k, there) < fault(k, {box, true})) {
                box = there;
            } else {
                onDot = false;
            }
        }
        L.badgeBoxes[k] = box;
        L.badgeOnDot[k] = onDot;
        addPlaced(box);
        return onDot;
    }

    Rect badgeSpot(size_t k) const {
        glm::vec2 p = L.points[k];
        float radius = L.badgeRadius;
        std::vector<float> centres{marks[k] + CHART_MARK_CLEARANCE,
                                   L.dotRadius + CHART_MARK_CLEARANCE};
        for (float gap = CHART_MARK_CLEARANCE + std::max(1.0f, 0.5f * L.dotRadius);
             gap <= speedChartBadgeGap(L) + 1e-3f; gap += std::max(1.0f, 0.5f * L.dotRadius)) {
            centres.push_back(marks[k] + gap);
        }
        Rect best;
        float bestFault = 1e30f;
        for (float from : centres) {
            for (int i = 0; i < DIRECTIONS; ++i) {
                glm::vec2 c = p + (from + radius) * direction(i);
                Rect box{std::round(c.x - radius), std::round(c.y - radius), 2.0f * radius,
                         2.0f * radius};
                float f = fault(k, {box, true});
                if (f < bestFault) {
                    best = box;
                    bestFault = f;
                }
            }
            if (bestFault <= 0.0f) break;
        }
        return best;
    }

    // Names mustName's rows in `order` (a badge where no clean spot is within reach), then, but
    // with keptLabelsOnly, any other row where a clean spot lies right beside its dot. Returns
    // the badges given.
    int place(const std::vector<size_t>& order, bool keptLabelsOnly) {
        size_t n = L.points.size();
        L.labels.assign(n, Rect{});
        L.labelShown.assign(n, false);
        L.badge.assign(n, 0);
        L.badgeBoxes.assign(n, Rect{});
        L.badgeOnDot.assign(n, false);
        placed.clear();
        placedCells.clear();
        int badges = 0;
        std::vector<bool> must(n, false);
        for (size_t k : order) {
            must[k] = true;
            glm::vec2 t = measureText(FontFace::Sans, L.labelPx, L.labelTexts[k]);
            if (std::optional<Rect> box = nameSpot(k, t, speedChartNameReach(L))) {
                L.labels[k] = *box;
                L.labelShown[k] = true;
                addPlaced(*box);
            } else {
                placeBadge(k);
                L.badge[k] = ++badges;  // numbered by time once placed
            }
        }
        if (keptLabelsOnly) return badges;
        for (size_t k = 0; k < n; ++k) {
            if (must[k]) continue;
            glm::vec2 t = measureText(FontFace::Sans, L.labelPx, L.labelTexts[k]);
            float reach = marks[k] + CHART_MARK_CLEARANCE + L.dotRadius;
            if (std::optional<Rect> box = nameSpot(k, t, reach)) {
                L.labels[k] = *box;
                L.labelShown[k] = true;
                addPlaced(*box);
            }
        }
        return badges;
    }

  private:
    SpeedChartLayout& L;
    std::vector<float> marks;  // per row: speedChartMarkRadius
    std::vector<Rect> bars;    // per row: speedChartBarBox
    std::vector<Rect> placed;  // the names and badges placed so far
    float widestMark = 0.0f;
    CellIndex dotCells, barCells, placedCells;   // rows by dot and by bar; placed by box
    mutable std::vector<size_t> near, nearBars;  // a query's answer, reused

    static float cellSize(const SpeedChartLayout& layout) {
        return std::max(8.0f, 4.0f * layout.dotRadius);
    }
    void addPlaced(const Rect& box) {
        placedCells.insert(placed.size(), box);
        placed.push_back(box);
    }
    // Into `near`: the rows whose dot lies within `reach` of box or whose bar overlaps it,
    // ascending.
    void nearRows(const Rect& box, float reach) const {
        dotCells.query(box.expanded(reach), near);
        barCells.query(box, nearBars);
        size_t dots = near.size();
        near.insert(near.end(), nearBars.begin(), nearBars.end());
        std::inplace_merge(near.begin(), near.begin() + static_cast<long>(dots), near.end());
        near.erase(std::unique(near.begin(), near.end()), near.end());
    }
};

// Numbers the badges 1, 2, ... in the order of their dots' times (left to right), so that the
// key reads in the chart's order.
void numberBadges(SpeedChartLayout& L) {
    std::vector<size_t> rows;
    for (size_t k = 0; k < L.badge.size(); ++k) {
        if (L.badge[k] > 0) rows.push_back(k);
    }
    std::stable_sort(rows.begin(), rows.end(),
                     [&](size_t a, size_t b) { return L.points[a].x < L.points[b].x; });
    for (size_t i = 0; i < rows.size(); ++i) L.badge[rows[i]] = static_cast<int>(i) + 1;
    L.keyRows = rows;
}

}  // namespace

float speedChartNameReach(const SpeedChartLayout& L) { return 8.0f * L.dotRadius; }

float speedChartBadgeGap(const SpeedChartLayout& L) {
    return std::max(2.0f * L.dotRadius, L.badgeRadius);
}

void placeSpeedChartLabels(SpeedChartLayout& L, bool keptLabelsOnly) {
    Placer placer(L);
    int badges = placer.place(L.mustName, keptLabelsOnly);
    if (badges > 0) {
        // A crowd's few clean spots go to whoever comes first: once more with the badged first.
        std::vector<size_t> retry;
        for (size_t k : L.mustName) {
            if (L.badge[k] > 0) retry.push_back(k);
        }
        for (size_t k : L.mustName) {
            if (L.badge[k] == 0) retry.push_back(k);
        }
        std::vector<Rect> labels = L.labels, badgeBoxes = L.badgeBoxes;
        std::vector<bool> shown = L.labelShown, onDot = L.badgeOnDot;
        std::vector<int> badge = L.badge;
        if (placer.place(retry, keptLabelsOnly) >= badges) {
            L.labels = std::move(labels);
            L.labelShown = std::move(shown);
            L.badge = std::move(badge);
            L.badgeBoxes = std::move(badgeBoxes);
            L.badgeOnDot = std::move(onDot);
        }
    }
    numberBadges(L);
}

std::optional<ChartLeader> speedChartLeader(const SpeedChartLayout& L, size_t row) {
    if (!L.labelShown[row]) return std::nullopt;
    const Rect& box = L.labels[row];
    glm::vec2 p = L.points[row];
    glm::vec2 nearest = glm::clamp(p, box.position(), box.position() + box.size());
    float mark = speedChartMarkRadius(L, row);
    float d = glm::length(nearest - p);
    if (d <= mark + L.dotRadius) return std::nullopt;
    return ChartLeader{p + (nearest - p) * (mark / d), nearest};
}

ChartTextBox& addChartTextBox(std::vector<ChartTextBox>& out, glm::vec2 pos, TextAlign align,
                              float px, const std::string& role, const std::string& words) {
    glm::vec2 size = measureText(FontFace::Sans, px, words);
    float x = pos.x;
    if (align == TextAlign::Center) x -= size.x * 0.5f;
    if (align == TextAlign::Right) x -= size.x;
    out.push_back({{std::round(x), std::round(pos.y), size.x, size.y}, px, role, words});
    return out.back();
}

void speedChartNameBoxes(const SpeedChartLayout& L, std::vector<ChartTextBox>& out) {
    for (size_t k = 0; k < L.labels.size(); ++k) {
        if (L.labelShown[k]) {
            out.push_back({L.labels[k], L.labelPx, "chart-label", L.labelTexts[k]});
            out.back().row = static_cast<int>(k);
        }
        if (L.badge[k] > 0) {
            out.push_back({L.badgeBoxes[k], L.labelPx, "chart-badge", std::to_string(L.badge[k])});
            out.back().row = static_cast<int>(k);
        }
    }
    float keyLineH = fontMetrics(FontFace::Sans, L.legendPx).lineHeight;
    for (size_t i = 0; i < L.keyRows.size(); ++i) {
        int row = static_cast<int>(L.keyRows[i]);
        out.push_back({L.keyBadges[i], L.labelPx, "chart-badge", std::to_string(i + 1)});
        out.back().row = row;
        float x = std::round(L.keyBadges[i].right() + speedChartLegendGap(L));
        addChartTextBox(out, {x, L.keyBadges[i].centre().y - 0.5f * keyLineH}, TextAlign::Left,
                        L.legendPx, "chart-key", L.labelTexts[L.keyRows[i]])
            .row = row;
    }
}

std::vector<ChartTextBox> speedChartTextBoxes(const SpeedChartLayout& L,
                                              const SpeedChartText& text) {
    std::vector<ChartTextBox> out;
    float s = L.scale;
    auto add = [&](glm::vec2 pos, TextAlign align, float px, const std::string& role,
                   const std::string& words) -> ChartTextBox& {
        return addChartTextBox(out, pos, align, px, role, words);
    };
    float pad = std::round(12.0f * s);
    float titleH = fontMetrics(FontFace::Sans, L.titlePx).lineHeight;
    float subH = fontMetrics(FontFace::Sans, L.subtitlePx).lineHeight;
    add({pad, pad * 0.6f}, TextAlign::Left, L.titlePx, "chart-title", text.title);
    add({pad, std::round(pad * 0.6f) + titleH}, TextAlign::Left, L.subtitlePx, "chart-subtitle",
        text.subtitle);
    // The y axis's name above it (the canvas draws no rotated text).
    add({L.plot.x, std::round(pad * 0.6f) + titleH + L.subtitleLines * subH + 4.0f * s},
        TextAlign::Left, L.axisPx, "chart-axis", text.yLabel);
    for (const ChartTick& t : L.xTicks) {
        if (t.text.empty()) continue;
        add({std::round(t.pixel) + 0.5f, L.plot.bottom() + 5.0f * s}, TextAlign::Center, L.tickPx,
            "chart-tick", t.text);
    }
    float tickH = fontMetrics(FontFace::Sans, L.tickPx).lineHeight;
    for (const ChartTick& t : L.yTicks) {
        add({L.plot.x - 6.0f * s, std::round(t.pixel) + 0.5f - tickH / 2}, TextAlign::Right,
            L.tickPx, "chart-tick", t.text);
    }
    add({L.plot.centre().x, L.plot.bottom() + 8.0f * s + tickH}, TextAlign::Center, L.axisPx,
        "chart-axis", text.xLabel);
    speedChartNameBoxes(L, out);
    float lineH = fontMetrics(FontFace::Sans, L.legendPx).lineHeight;
    for (size_t k = 0; k < L.legendSwatches.size(); ++k) {
        bool method = k < L.legendMethods.size();
        float y = L.legendSwatches[k].centre().y - 0.5f * lineH;  // the line its mark centres
        std::string name = method ? std::string(methodInfo(L.legendMethods[k]).name)
                           : k == L.legendMethods.size() ? FRONT_LEGEND
                                                         : HIGHLIGHT_LEGEND;
        add({L.legendTextX, y}, TextAlign::Left, L.legendPx, "chart-legend", name).method =
            method ? L.legendMethods[k] : -1;
        out.push_back({L.legendSwatches[k], 0.0f, "chart-swatch", name});
        out.back().method = method ? L.legendMethods[k] : -1;
    }
    return out;
}

}  // namespace pcf
