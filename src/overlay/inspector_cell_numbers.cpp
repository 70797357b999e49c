// inspector_cell_numbers.cpp: the numbers in each magnified cell (its bit, own ref, depth and
// weight), placed clear of the marks the cell holds: in smaller type, with fewer numbers, or with
// the cell's point marks moved into lanes at its edge, where the whole block does not fit.
#include <initializer_list>

#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

namespace {

// One line of a cell's number block.
struct Item {
    std::string text;
    float size;
    std::string role;
    bool hidden = false;  // drawn as "?" (HiddenNumbers), its box's role "masked"
};
using Placed = std::vector<std::pair<Rect, const Item*>>;

// A cell's whole block: bit (or a soft comparison's fraction), own ref, depth, weight.
std::vector<Item> cellItems(const InspectorModel& m, const Grid& g, glm::ivec2 texel,
                            const TapRecord* tap, bool inMap) {
    const Trace& tr = *m.trace;
    const HiddenNumbers& hide = m.hidden;
    std::vector<Item> all;
    // The bit; a soft comparison's fraction (bias soft) in its place.
    bool soft = tap && tap->lit != 0.0f && tap->lit != 1.0f;
    if (tap) {
        std::string bit = soft ? fixed(tap->lit, 2) : tap->lit >= 0.5f ? "1" : "0";
        all.push_back({hiddenOr(hide.bits, "", bit), g.bit, "cell-bit", hide.bits});
    }
    // The tap's own ref where the bias gave it one (receiver plane), under its bit.
    bool ownRef = tap && tap->ref != tr.ref;
    if (ownRef) {
        all.push_back(
            {hiddenOr(hide.refs, "r ", fixed(tap->ref, 4)), g.number, "cell-ref", hide.refs});
    }
    if (inMap) {
        float depth = m.map ? m.map->depth(texel.x, texel.y) : (tap ? tap->depth : 0.0f);
        // Bits hidden: the depth to ref's four decimals, so that the comparison can be made.
        int decimals = hide.bits ? 4 : 3;
        all.push_back({hiddenOr(hide.depths, "d ", fixed(depth, decimals)), g.number, "cell-depth",
                       hide.depths});
    }
    if (tap) {
        all.push_back({hiddenOr(hide.weights, "w ", weightText(tr.weights.at(texel))), g.number,
                       "cell-weight", hide.weights});
    }
    return all;
}

// The items of `all` but those in the roles named.
std::vector<Item> itemsWithout(const std::vector<Item>& all,
                               std::initializer_list<const char*> roles) {
    std::vector<Item> out;
    for (const Item& it : all) {
        if (std::none_of(roles.begin(), roles.end(), [&](const char* r) { return it.role == r; }))
            out.push_back(it);
    }
    return out;
}

// The blocks to try, most first: variants from whole to nothing (all; without the own ref;
// without depth; the bit and weight; the bit alone), each at the cell's number size, then a few
// steps smaller down to the floor: a cell crowded by marks keeps its depth in smaller type
// before it drops it, and its bit always: the comparison is what the cell is for (12.3's
// receiver-plane cells at 1024x768 showed their weights alone, the own ref too wide to fit).
// What a cell leaves out goes to the texel table.
std::vector<std::vector<Item>> numberCandidates(const std::vector<Item>& all, bool tap,
                                                bool hasDepth, const Grid& g, float numberFloor) {
    std::vector<std::vector<Item>> variants{all};
    bool ownRef =
        std::any_of(all.begin(), all.end(), [](const Item& it) { return it.role == "cell-ref"; });
    if (tap && hasDepth && ownRef) variants.push_back(itemsWithout(all, {"cell-ref"}));
    if (tap && hasDepth) variants.push_back(itemsWithout(all, {"cell-depth"}));
    if (tap && ownRef) variants.push_back(itemsWithout(all, {"cell-depth", "cell-ref"}));
    if (tap) variants.push_back({all.front()});
    variants.push_back({});
    std::vector<std::vector<Item>> candidates;
    for (const std::vector<Item>& items : variants) {
        float size = g.number;
        for (int step = 0; step < 4; ++step) {
            std::vector<Item> scaled = items;
            for (Item& it : scaled) it.size = it.size == g.bit ? bitFor(size) : size;
            candidates.push_back(scaled);
            float next = stepDown(size, numberFloor);
            if (items.empty() || next >= size) break;
            size = next;
        }
        // Last, the bit at the numbers' size (half a line less to find room for).
        if (!items.empty() && items.front().role == "cell-bit") {
            std::vector<Item> flat = candidates.back();
            flat.front().size = flat.size() > 1 ? flat.back().size : numberFloor;
            candidates.push_back(flat);
        }
    }
    return candidates;
}

// The lines of a candidate, placed in `inner` clear of `cellMarks`: the block in one piece at
// the first free spot, else its lines in order, top to bottom, each at the first height below
// the last where it clears every mark (the lookup point in the middle of a cell then sits
// between the bit and the depth, not on them). Empty: no room.
Placed fitItems(const std::vector<Item>& items, const std::vector<Rect>& cellMarks,
                const Rect& inner) {
    Placed out;
    auto clear = [&](const Rect& b) {
        return std::none_of(cellMarks.begin(), cellMarks.end(),
                            [&](const Rect& mk) { return overlaps(mk, b); });
    };
    float bw = 0, bh = 0;
    for (const Item& it : items) {
        bw = std::max(bw, measureText(FontFace::Mono, it.size, it.text).x);
        bh += lineHeightOf(it.size);
    }
    if (bw > inner.w || bh > inner.h) return out;
    float cx = inner.x + (inner.w - bw) * 0.5f, cy = inner.y + (inner.h - bh) * 0.5f;
    float rx = inner.right() - bw, by = inner.bottom() - bh;
    const glm::vec2 spots[] = {{cx, cy},      {cx, inner.y}, {cx, by},
                               {inner.x, cy}, {rx, cy},      {inner.x, inner.y},
                               {rx, inner.y}, {inner.x, by}, {rx, by}};
    for (glm::vec2 s : spots) {
        Rect blk{std::round(s.x), std::round(s.y), bw, bh};
        if (!clear(blk)) continue;
        float y = blk.y;
        for (const Item& it : items) {
            out.push_back({{blk.x, y, bw, lineHeightOf(it.size)}, &it});
            y += lineHeightOf(it.size);
        }
        return out;
    }
    float y = inner.y, below = bh;
    for (const Item& it : items) {
        float w = measureText(FontFace::Mono, it.size, it.text).x;
        float h = lineHeightOf(it.size);
        below -= h;
        const float xs[] = {inner.x + (inner.w - w) * 0.5f, inner.x, inner.right() - w};
        bool found = false;
        for (; y + h + below <= inner.bottom() + 0.01f && !found; y += 1.0f) {
            for (float x : xs) {
                Rect ln{std::round(x), std::round(y), w, h};
                if (clear(ln)) {
                    out.push_back({ln, &it});
                    found = true;
                    break;
                }
            }
            if (found) break;
        }
        if (!found) return Placed{};
        y += h;
    }
    return out;
}

// Lanes: which edges a moved mark hugs (x: -1 left, 1 right, 0 kept; y likewise); the bottom one
// just above the weight bar. {0, 0}: where the math puts it.
const glm::ivec2 MARK_LANES[] = {{0, 0},   {0, -1}, {-1, 0}, {1, 0}, {0, 1},
                                 {-1, -1}, {1, -1}, {-1, 1}, {1, 1}};

// Where a point mark of cell `r` goes in `lane`; `barTop`: the weight bar's top.
glm::vec2 laneAt(const PointMark& pm, glm::ivec2 lane, const Rect& r, float barTop) {
    glm::vec2 at = pm.trueAt;
    if (lane == glm::ivec2(0)) return at;
    for (int ax = 0; ax < 2; ++ax) {
        float lo = (ax == 0 ? r.x : r.y) + pm.half;
        float hi = (ax == 0 ? r.right() : barTop) - pm.half;
        if (lane[ax] < 0) at[ax] = lo;
        if (lane[ax] > 0) at[ax] = hi;
        at[ax] = std::clamp(at[ax], lo, std::max(lo, hi));
    }
    return at;
}

// The ways to place a cell's `owned` point marks: each its own lane (two marks or fewer), else
// all in one; nearest first, so that the marks move as little as they can (the first: none
// moves).
std::vector<std::vector<glm::ivec2>> laneWays(const CellMarks& cm, const std::vector<size_t>& owned,
                                              const Rect& r, float barTop) {
    std::vector<std::vector<glm::ivec2>> ways{{}};
    if (owned.size() <= 2) {
        for (size_t k = 0; k < owned.size(); ++k) {
            std::vector<std::vector<glm::ivec2>> next;
            for (const auto& w : ways) {
                for (glm::ivec2 lane : MARK_LANES) {
                    next.push_back(w);
                    next.back().push_back(lane);
                }
            }
            ways = std::move(next);
        }
    } else {
        ways.clear();
        for (glm::ivec2 lane : MARK_LANES) ways.emplace_back(owned.size(), lane);
    }
    auto travel = [&](const std::vector<glm::ivec2>& w) {
        float d = 0.0f;
        for (size_t k = 0; k < owned.size(); ++k) {
            const PointMark& pm = cm.points[owned[k]];
            d += glm::length(laneAt(pm, w[k], r, barTop) - pm.trueAt);
        }
        return d;
    };
    std::vector<float> travels;
    for (const auto& w : ways) travels.push_back(travel(w));
    std::vector<size_t> order(ways.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t x, size_t y) { return travels[x] < travels[y]; });
    std::vector<std::vector<glm::ivec2>> sorted;
    for (size_t k : order) sorted.push_back(ways[k]);
    return sorted;
}

// The point marks whose true position lies in `texel`'s cell and that may move (not fixed).
std::vector<size_t> ownedMarks(const CellMarks& cm, const Grid& g, glm::ivec2 texel) {
    std::vector<size_t> owned;
    for (size_t k = 0; k < cm.points.size(); ++k) {
        if (cm.points[k].fixed) continue;
        glm::ivec2 at(glm::floor((cm.points[k].trueAt - glm::vec2(g.area.x, g.area.y)) / g.cell));
        if (g.view.origin + at == texel) owned.push_back(k);
    }
    return owned;
}

// The marks that overlap cell `r`, grown by the clearance numbers keep from them.
std::vector<Rect> marksOver(const CellMarks& cm, const Grid& g, const Rect& r) {
    std::vector<Rect> near;
    for (const Rect& mk : cm.all(g.area)) {
        if (overlaps(mk, r)) near.push_back(mk.expanded(MARK_CLEARANCE_PX));
    }
    return near;
}

// One cell's room: where its numbers may go (inside the border band, above the weight bar) and
// the ways its own point marks may move into lanes, nearest first.
struct CellRoom {
    Rect r;      // the cell
    Rect inner;  // where its numbers may go
    float barTop = 0.0f;
    std::vector<size_t> owned;  // its point marks (indices into CellMarks::points)
    std::vector<std::vector<glm::ivec2>> ways;
};

CellRoom cellRoomOf(const CellMarks& cm, const Grid& g, glm::ivec2 texel) {
    CellRoom room;
    room.r = texelCellRect(g.view, g.area, texel);
    room.inner = room.r.expanded(-g.pad);
    room.inner.h -= g.bar + 1.0f;
    room.owned = ownedMarks(cm, g, texel);
    room.barTop = room.r.bottom() - (g.bar + g.pad);
    room.ways = laneWays(cm, room.owned, room.r, room.barTop);
    return room;
}

// Moves the cell's own point marks into the lanes of way `w` ({0, 0}: where the math puts it).
void moveOwnedMarks(CellMarks& cm, const CellRoom& room, const std::vector<glm::ivec2>& w) {
    for (size_t k = 0; k < room.owned.size(); ++k) {
        PointMark& pm = cm.points[room.owned[k]];
        pm.at = laneAt(pm, w[k], room.r, room.barTop);
    }
}

// One candidate tried with the cell's point marks in each way, nearest first (`inPlaceFirst`:
// the first try with every mark where the math puts it). The marks stay where the fitting try
// put them; empty: no way gives the candidate room.
Placed fitInSomeWay(const std::vector<Item>& items, CellMarks& cm, const Grid& g,
                    const CellRoom& room, bool inPlaceFirst) {
    for (size_t wi = 0; wi < room.ways.size(); ++wi) {
        moveOwnedMarks(cm, room,
                       inPlaceFirst && wi == 0
                           ? std::vector<glm::ivec2>(room.owned.size(), glm::ivec2(0))
                           : room.ways[wi]);
        Placed done = fitItems(items, marksOver(cm, g, room.r), room.inner);
        if (!done.empty()) return done;
    }
    return {};
}

// The candidates that keep the depth (where the cell has one), largest type first, each in
// every way of moving the marks: a cell's numbers keep the size of the others' rather than
// shrink for a mark that a lane has room for. Empty: none fits.
Placed fitKeepingDepth(const std::vector<std::vector<Item>>& candidates, bool hasDepth,
                       CellMarks& cm, const Grid& g, const CellRoom& room) {
    auto keepsDepth = [&](const std::vector<Item>& items) {
        return !hasDepth || std::any_of(items.begin(), items.end(),
                                        [](const Item& it) { return it.role == "cell-depth"; });
    };
    for (const std::vector<Item>& items : candidates) {
        if (items.empty() || !keepsDepth(items)) break;
        Placed done = fitInSomeWay(items, cm, g, room, false);
        if (!done.empty()) return done;
    }
    return {};
}

// The candidates down to the first empty one, without the depth: the marks where the math puts
// them first, then moved into the lanes, so that a cell keeps at least its bit (6.4 at 1280x720
// lost three bits to tap marks that a lane had room for). Where none fits, the marks go back
// where the math puts them. Empty: none fits.
Placed fitWithoutDepth(const std::vector<std::vector<Item>>& candidates, CellMarks& cm,
                       const Grid& g, const CellRoom& room) {
    for (const std::vector<Item>& items : candidates) {
        if (items.empty()) break;
        Placed done = fitInSomeWay(items, cm, g, room, true);
        if (!done.empty()) return done;
    }
    moveOwnedMarks(cm, room, std::vector<glm::ivec2>(room.owned.size(), glm::ivec2(0)));
    return {};
}

// One cell's numbers: the candidates that keep the depth (fitKeepingDepth), then those without
// it (fitWithoutDepth), drawn in the cell's ink; a texel whose whole block is drawn is listed as
// numbered. Returns whether the cell had numbers and shows none.
bool planCell(Planner& pl, const InspectorModel& m, const Grid& g, CellMarks& cm, float numberFloor,
              glm::ivec2 texel) {
    const Trace& tr = *m.trace;
    const TapRecord* tap = firstTapAt(tr, texel);
    bool inMap = texel.x >= 0 && texel.y >= 0 && texel.x < tr.map.size.x && texel.y < tr.map.size.y;
    std::vector<Item> all = cellItems(m, g, texel, tap, inMap);
    std::vector<std::vector<Item>> candidates =
        numberCandidates(all, tap != nullptr, inMap, g, numberFloor);
    CellRoom room = cellRoomOf(cm, g, texel);
    Placed done = fitKeepingDepth(candidates, inMap, cm, g, room);
    if (done.empty()) done = fitWithoutDepth(candidates, cm, g, room);
    if (tap && done.size() == all.size()) pl.plan.numberedTexels.push_back(texel);
    bool bit = std::any_of(done.begin(), done.end(),
                           [](const auto& d) { return d.second->role == "cell-bit"; });
    if (tap && bit) pl.plan.bitTexels.push_back(texel);
    Colour ink = tap && tap->lit >= 0.5f && !m.hidden.bits ? DARK_TEXT : TEXT;
    for (const auto& [box, it] : done) {
        pl.text({box.x + box.w * 0.5f, box.y}, it->text,
                {FontFace::Mono, it->size, ink, TextAlign::Center}, BoxKind::Number, "inspector",
                it->hidden ? "masked" : it->role);
    }
    // numberCandidates always ends with the empty block, so a cell none fits shows nothing.
    return done.empty() && !all.empty();
}

}  // namespace

int planCellNumbers(Planner& pl, const InspectorModel& m, const Grid& g, CellMarks& cm,
                    float numberFloor) {
    int hiddenCells = 0;
    for (int j = 0; j < g.view.size.y; ++j) {
        for (int i = 0; i < g.view.size.x; ++i) {
            if (planCell(pl, m, g, cm, numberFloor, g.view.origin + glm::ivec2(i, j)))
                ++hiddenCells;
        }
    }
    return hiddenCells;
}

}  // namespace pcf::inspector_detail
