#include "analysis/speed_chart_labels.h"

#include <algorithm>
#include <cmath>

#include "draw/text_layout.h"

namespace pcf {

namespace {

float overlapArea(const Rect& a, const Rect& b) {
    Rect o = a.intersect(b);
    return o.w * o.h;
}

// Area of r outside `inside`.
float outsideArea(const Rect& r, const Rect& inside) { return r.w * r.h - overlapArea(r, inside); }

// The order labels are placed in: the front's first, then the kept rows', then the rest.
std::vector<size_t> labelOrder(const std::vector<size_t>& front,
                               const std::vector<bool>& needLabel) {
    std::vector<size_t> order = front;
    for (bool needed : {true, false}) {
        for (size_t k = 0; k < needLabel.size(); ++k) {
            bool onFront = std::find(front.begin(), front.end(), k) != front.end();
            if (!onFront && needLabel[k] == needed) order.push_back(k);
        }
    }
    return order;
}

// The distance from a box to a point (0 inside it), pixels.
float boxDistance(const Rect& box, glm::vec2 p) {
    return glm::length(glm::clamp(p, box.position(), box.position() + box.size()) - p);
}

// The distance from point c to the segment a-b, pixels.
float leaderDotDistance(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    glm::vec2 ab = b - a;
    float len2 = glm::dot(ab, ab);
    float t = len2 > 0.0f ? std::clamp(glm::dot(c - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(a + t * ab - c);
}

struct LabelSpot {
    Rect box;
    float fault = 1e30f;  // what the spot covers or misleads: 0 for a clean spot
};

// What a label at `box` for row k does wrong, 0 when nothing: it leaves the plot, covers a
// placed label, a dot or an error bar (a bar through a name strikes it out), or a reader could
// take it for another dot's: it is not nearer its own dot than any other, unless its leader
// crosses no other dot and no other dot lies next to it (within speedChartLeaderReach).
float labelFault(const SpeedChartLayout& L, size_t k, const Rect& box,
                 const std::vector<Rect>& placed) {
    constexpr float HARD = 1000.0f;
    glm::vec2 p = L.points[k];
    float fault = HARD * outsideArea(box, L.plot);
    for (const Rect& o : placed) fault += HARD * overlapArea(box, o);
    float own = boxDistance(box, p);
    glm::vec2 nearest = glm::clamp(p, box.position(), box.position() + box.size());
    bool leader = own > speedChartLeaderReach(L);
    bool nearestOwn = true, leaderClear = leader;
    for (size_t j = 0; j < L.points.size(); ++j) {
        fault += HARD * overlapArea(box, speedChartBarBox(L, j));
        if (j == k) continue;
        fault += HARD * overlapArea(box, speedChartDotBox(L, j));
        glm::vec2 q = L.points[j];
        // (Dots whose discs overlap have no nearer one: a label of either names both.)
        if (glm::length(q - p) < 2.0f * L.dotRadius) continue;
        float other = boxDistance(box, q);
        nearestOwn = nearestOwn && other > own;
        leaderClear = leaderClear && other > speedChartLeaderReach(L) &&
                      leaderDotDistance(p, nearest, q) >= L.dotRadius + 1.0f;
    }
    if (!nearestOwn && !leaderClear) fault += HARD;
    return fault;
}

// The spot for row k's label of size t: around its dot in 16 directions, nearest first; the
// first ring that has a clean spot (labelFault 0) gives its nearest one. A label the chart must
// show looks farther out (with a leader) and otherwise settles on the spot of least fault plus
// distance; any other stays within leader-free reach of its dot.
LabelSpot bestLabelSpot(const SpeedChartLayout& L, size_t k, glm::vec2 t, bool mustShow,
                        const std::vector<Rect>& placed) {
    glm::vec2 p = L.points[k];
    LabelSpot best;
    float bestCost = 1e30f;
    float step = L.dotRadius + 3.0f * L.scale;
    for (float ring : {1.0f, 1.5f, 2.1f, 2.8f, 3.6f, 4.6f, 5.8f, 7.2f, 9.0f, 11.5f, 14.5f, 18.0f}) {
        float r = step * ring;
        if (!mustShow && r > speedChartLeaderReach(L)) break;
        for (int i = 0; i < 16; ++i) {
            float a = static_cast<float>(i) * 0.39269908f;  // 22.5 degrees
            glm::vec2 d(std::cos(a), std::sin(a));
            glm::vec2 at = p + r * d;
            // The box's side (or corner) nearest the dot sits at `at`.
            float x = d.x > 0.38f ? at.x : d.x < -0.38f ? at.x - t.x : at.x - 0.5f * t.x;
            float y = d.y > 0.38f ? at.y : d.y < -0.38f ? at.y - t.y : at.y - 0.5f * t.y;
            Rect box{std::round(x), std::round(y), t.x, t.y};
            float fault = labelFault(L, k, box, placed);
            float cost = fault + boxDistance(box, p) / L.dotRadius;
            if (cost < bestCost) {
                bestCost = cost;
                best = {box, fault};
            }
        }
        if (best.fault < 0.5f) return best;  // a clean spot in this ring: none farther is nearer
    }
    if (!mustShow) return best;
    // A crowd left no clean spot within the rings: the nearest clean spot anywhere in the plot,
    // on a grid a few pixels fine (with its leader).
    float grid = std::max(3.0f, std::round(4.0f * L.scale));
    for (float y = L.plot.y; y + t.y <= L.plot.bottom(); y += grid) {
        for (float x = L.plot.x; x + t.x <= L.plot.right(); x += grid) {
            Rect box{std::round(x), std::round(y), t.x, t.y};
            float cost = boxDistance(box, p) / L.dotRadius;
            if (best.fault < 0.5f && cost >= bestCost) continue;
            float fault = labelFault(L, k, box, placed);
            if (fault + cost < bestCost) {
                bestCost = fault + cost;
                best = {box, fault};
            }
        }
    }
    return best;
}

// Greedy label placement in `order`; each at bestLabelSpot. A label that finds no clean spot is
// left out, unless the front or the caller needs it: a crowd of overlapping names reads as noise
// on a projector, and a name far from its dot is read as another dot's; the dot keeps its
// method's colour, which the legend names. Returns the needed labels that found no clean spot.
std::vector<size_t> placeLabelsInOrder(SpeedChartLayout& L, const std::vector<bool>& needLabel,
                                       bool keptLabelsOnly, const std::vector<size_t>& order) {
    L.labels.assign(L.points.size(), Rect{});
    L.labelShown.assign(L.points.size(), false);
    std::vector<Rect> placed;
    std::vector<size_t> faulty;
    for (size_t k : order) {
        if (keptLabelsOnly && !needLabel[k]) continue;
        glm::vec2 t = measureText(FontFace::Sans, L.labelPx, L.labelTexts[k]);
        bool needed = k < needLabel.size() && needLabel[k];
        LabelSpot spot = bestLabelSpot(L, k, t, needed, placed);
        if (spot.fault > 0.5f && !needed) continue;
        if (spot.fault > 0.5f) faulty.push_back(k);
        L.labels[k] = spot.box;
        L.labelShown[k] = true;
        placed.push_back(spot.box);
    }
    return faulty;
}

}  // namespace

float speedChartLeaderReach(const SpeedChartLayout& L) { return 2.5f * L.dotRadius; }

void placeSpeedChartLabels(SpeedChartLayout& L, const std::vector<bool>& needLabel,
                           bool keptLabelsOnly) {
    std::vector<size_t> order = labelOrder(L.front, needLabel);
    std::vector<size_t> faulty = placeLabelsInOrder(L, needLabel, keptLabelsOnly, order);
    if (faulty.empty()) return;
    std::vector<size_t> retry = faulty;
    for (size_t k : order) {
        if (std::find(faulty.begin(), faulty.end(), k) == faulty.end()) retry.push_back(k);
    }
    SpeedChartLayout first = L;
    if (placeLabelsInOrder(L, needLabel, keptLabelsOnly, retry).size() >= faulty.size()) {
        L = std::move(first);
    }
}

}  // namespace pcf
