#include "analysis/speed_chart_labels.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "analysis/chart_axes.h"
#include "draw/text_layout.h"

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

// The chart's marks a spot must keep off, computed once per placement.
class Placer {
  public:
    explicit Placer(SpeedChartLayout& layout) : L(layout) {
        for (size_t k = 0; k < L.points.size(); ++k) {
            marks.push_back(speedChartMarkRadius(L, k));
            bars.push_back(speedChartBarBox(L, k));
        }
    }

    // What a spot for row k does wrong, 0 when nothing: it leaves the plot, lies on a placed
    // name or badge, an error bar (a bar through a name strikes it out), a dot or its rings (its
    // own too, with CHART_MARK_CLEARANCE; a badge may lie on its own dot's rings), or is not
    // nearer its own dot than any other by a dot radius (dots whose discs overlap excepted: no
    // spot names one of them and not the other).
    float fault(size_t k, const Spot& s) const {
        constexpr float HARD = 1000.0f;
        float f = HARD * outsideArea(s.box, L.plot);
        for (const Rect& o : placed) f += HARD * overlapArea(s.box, o);
        glm::vec2 p = L.points[k];
        float own = spotDistance(s, p);
        for (size_t j = 0; j < L.points.size(); ++j) {
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
                if (own > reach || own >= bestD || fault(k, {box, false}) > 0.0f) continue;
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
        for (const Rect& o : placed) f += HARD * overlapArea(box, o);
        for (size_t j = 0; j < L.points.size(); ++j) {
            float d = glm::length(L.points[j] - L.points[k]);
            float keep = L.badgeRadius + CHART_MARK_CLEARANCE;
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
        bool onDot = fault(k, {box, true}) > 0.0f;
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
        placed.push_back(box);
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
        int badges = 0;
        std::vector<bool> must(n, false);
        for (size_t k : order) {
            must[k] = true;
            glm::vec2 t = measureText(FontFace::Sans, L.labelPx, L.labelTexts[k]);
            if (std::optional<Rect> box = nameSpot(k, t, speedChartNameReach(L))) {
                L.labels[k] = *box;
                L.labelShown[k] = true;
                placed.push_back(*box);
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
                placed.push_back(*box);
            }
        }
        return badges;
    }

  private:
    SpeedChartLayout& L;
    std::vector<float> marks;  // per row: speedChartMarkRadius
    std::vector<Rect> bars;    // per row: speedChartBarBox
    std::vector<Rect> placed;  // the names and badges placed so far
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

}  // namespace pcf
