// inspector_scene.cpp: the scene panel's overlay: the picked pixel's ring and label, and the
// shadow map's texel grid projected onto the receiver around it (the texels read tinted: the
// distinct texels of the trace's taps, exactly those).
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

namespace {

// The shadow-map texel each scene pixel looks up, from the model's light-space buffer.
struct TexelLookup {
    const InspectorModel& m;
    glm::ivec2 region;
    glm::vec2 mapSize;

    // Whether pixel (x, y) has a texel (a receiver inside the buffer's region), and which.
    bool texelAt(int x, int y, glm::ivec2& out) const {
        if (x < 0 || y < 0 || x >= m.sceneSize.x || y >= m.sceneSize.y) return false;
        glm::ivec2 r = glm::ivec2(x, y) - m.lightSpaceOrigin;
        if (r.x < 0 || r.y < 0 || r.x >= region.x || r.y >= region.y) return false;
        const std::vector<float>& ls = *m.lightSpace;
        size_t k = (static_cast<size_t>(r.y) * region.x + r.x) * 4;
        if (ls[k + 3] != 1.0f) return false;
        out = glm::ivec2(glm::floor(glm::vec2(ls[k], ls[k + 1]) * mapSize));
        return true;
    }

    // How many screen pixels a texel spans along dir through the picked pixel: pixels per
    // texel change within `radius` of it.
    float spanAlong(glm::ivec2 dir, int radius) const {
        int valid = 0, changes = 0;
        glm::ivec2 prev{0}, cur{0};
        bool havePrev = false;
        for (int k = -radius; k <= radius; ++k) {
            glm::ivec2 q = m.pixel + dir * k;
            if (!texelAt(q.x, q.y, cur)) {
                havePrev = false;
                continue;
            }
            ++valid;
            if (havePrev && cur != prev) ++changes;
            prev = cur;
            havePrev = true;
        }
        return valid == 0 ? 0.0f : static_cast<float>(valid) / static_cast<float>(changes + 1);
    }
};

// Colour indices: colours[] in planTexelGrid.
enum PixelKind { PIXEL_NONE, PIXEL_FOOTPRINT_EDGE, PIXEL_EDGE, PIXEL_FOOTPRINT };

// The distinct texels the trace read (its taps'), in read order and sorted for look-ups: the
// texels the scene tints. A nearest lookup reads one, a Poisson disk 16 scattered ones, never
// the box around them.
struct ReadTexels {
    std::vector<glm::ivec2> inReadOrder;
    std::vector<glm::ivec2> sorted;

    static bool less(glm::ivec2 a, glm::ivec2 b) { return a.y != b.y ? a.y < b.y : a.x < b.x; }
    explicit ReadTexels(const Trace& tr) {
        for (const TapRecord& t : tr.taps) {
            if (std::find(inReadOrder.begin(), inReadOrder.end(), t.texel) == inReadOrder.end()) {
                inReadOrder.push_back(t.texel);
            }
        }
        sorted = inReadOrder;
        std::sort(sorted.begin(), sorted.end(), less);
    }
    bool has(glm::ivec2 tx) const {
        return std::binary_search(sorted.begin(), sorted.end(), tx, less);
    }
};

// The kind of each pixel of the box lo..hi (row-major), and the box of those with a kind.
struct KindGrid {
    std::vector<uint8_t> kinds;
    glm::ivec2 used0, used1;
    std::vector<glm::ivec2> tinted;  // the read texels that got a pixel, unordered
};

// Whether pixel p's four neighbours all look up texels that were read.
bool readAround(const TexelLookup& look, const ReadTexels& read, glm::ivec2 p) {
    const glm::ivec2 steps[] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    for (glm::ivec2 d : steps) {
        glm::ivec2 tx;
        if (!look.texelAt(p.x + d.x, p.y + d.y, tx) || !read.has(tx)) return false;
    }
    return true;
}

KindGrid kindsAround(const TexelLookup& look, const ReadTexels& read, glm::ivec2 lo, glm::ivec2 hi,
                     bool drawEdges) {
    glm::ivec2 size = hi - lo + 1;
    KindGrid g{
        std::vector<uint8_t>(static_cast<size_t>(size.x) * size.y, PIXEL_NONE), hi + 1, lo - 1, {}};
    for (int y = lo.y; y <= hi.y; ++y) {
        for (int x = lo.x; x <= hi.x; ++x) {
            glm::ivec2 tx, left, up;
            if (!look.texelAt(x, y, tx)) continue;
            bool isRead = read.has(tx);
            bool edge = drawEdges && ((look.texelAt(x - 1, y, left) && left != tx) ||
                                      (look.texelAt(x, y - 1, up) && up != tx));
            // The outline of the texels read is drawn at any texel size: where a texel spans two
            // or three pixels, the tint alone is a faint smudge under the pick's ring.
            if (isRead && !edge) edge = !readAround(look, read, {x, y});
            PixelKind kind = edge ? (isRead ? PIXEL_FOOTPRINT_EDGE : PIXEL_EDGE)
                                  : (isRead ? PIXEL_FOOTPRINT : PIXEL_NONE);
            if (kind == PIXEL_NONE) continue;
            if (isRead && std::find(g.tinted.begin(), g.tinted.end(), tx) == g.tinted.end()) {
                g.tinted.push_back(tx);
            }
            g.kinds[static_cast<size_t>(y - lo.y) * size.x + (x - lo.x)] =
                static_cast<uint8_t>(kind);
            g.used0 = glm::min(g.used0, glm::ivec2(x, y));
            g.used1 = glm::max(g.used1, glm::ivec2(x, y));
        }
    }
    return g;
}

// The texel grid's edges (where texels are large enough to see) and the tint of the texels read
// around the picked pixel.
void planTexelGrid(Planner& pl, const InspectorLayout& l, const InspectorModel& m) {
    glm::ivec2 region = m.lightSpaceSize;
    if (!(m.trace && m.lightSpace && region.x > 0 &&
          m.lightSpace->size() == static_cast<size_t>(region.x) * region.y * 4)) {
        return;
    }
    TexelLookup look{m, region, glm::vec2(m.trace->map.size)};
    int radius = gridRadius(m.sceneSize);
    // How many screen pixels a texel spans here: the smaller of the row's and the column's.
    float texelPx = std::min(look.spanAlong({1, 0}, radius), look.spanAlong({0, 1}, radius));
    bool drawEdges = m.grid && texelPx >= GRID_MIN_TEXEL_PX;
    pl.plan.gridShown = drawEdges;
    ReadTexels read(*m.trace);
    const Colour colours[] = {Colour{0.0f}, Colour{0.1f, 0.9f, 1.0f, 0.95f},
                              Colour{0.05f, 0.05f, 0.1f, 0.35f}, FOOTPRINT_TINT};
    // One picture over the box of pixels around the picked one that have a colour, each
    // pixel the colour of its kind, drawn as one quad: as thousands of 1-pixel-high runs of
    // rects it cost llvmpipe more per frame than the rest of the overlay (Canvas::image
    // blends each texel exactly as fillRect of that pixel did, so the frame's bytes are the
    // same). Without the grid only the few texels read are tinted: a small picture.
    glm::ivec2 lo = glm::max(m.pixel - radius, glm::ivec2(0));
    glm::ivec2 hi = glm::min(m.pixel + radius, m.sceneSize - 1);
    if (hi.x < lo.x || hi.y < lo.y) return;
    glm::ivec2 size = hi - lo + 1;
    KindGrid g = kindsAround(look, read, lo, hi, drawEdges);
    if (g.used1.x < g.used0.x || g.used1.y < g.used0.y) return;
    glm::ivec2 box = g.used1 - g.used0 + 1;
    std::vector<glm::vec4> pixels(static_cast<size_t>(box.x) * box.y);
    for (int y = 0; y < box.y; ++y) {
        for (int x = 0; x < box.x; ++x) {
            glm::ivec2 q = g.used0 - lo + glm::ivec2(x, y);
            pixels[static_cast<size_t>(y) * box.x + x] =
                colours[g.kinds[static_cast<size_t>(q.y) * size.x + q.x]];
        }
    }
    // The texels tinted, in read order: what the frame JSON lists as drawn.scene_texels.
    for (glm::ivec2 tx : read.inReadOrder) {
        if (std::find(g.tinted.begin(), g.tinted.end(), tx) != g.tinted.end()) {
            pl.plan.sceneTexels.push_back(tx);
        }
    }
    pl.plan.footprintShown = !pl.plan.sceneTexels.empty();
    auto image = std::make_shared<const CanvasImage>(box, std::move(pixels));
    glm::ivec2 at = glm::ivec2(glm::round(l.scene.position())) + g.used0;
    pl.op([image, at](Canvas& c) { c.image(at, image); });
}

// The label "pixel (x, y)" in the scene's corner farthest from the picked pixel, so that it
// never lies on what the step shows around the pixel (9.3's light gap hid under it when it sat
// beside the ring); the ring marks the pixel. Elided where it is wider than the scene.
void planPixelLabel(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                    const TypeSizes& t, glm::vec2 centre) {
    std::string label = "pixel (" + std::to_string(m.pixel.x) + ", " + std::to_string(m.pixel.y) +
                        ")" + (m.trace ? "" : ": no shadow receiver here");
    TextStyle st{FontFace::Sans, t.label, TEXT};
    Rect scenePad = l.scene.expanded(-6.0f);
    bool fits = pl.measure({0, 0}, label, st).w <= scenePad.w;
    std::string shown = fits ? label : elideText(FontFace::Sans, t.label, label, scenePad.w);
    Rect size = pl.measure({0, 0}, shown, st);
    bool right = centre.x < l.scene.centre().x;
    bool bottom = centre.y < l.scene.centre().y;
    glm::vec2 at{right ? scenePad.right() - size.w : scenePad.x,
                 bottom ? scenePad.bottom() - size.h : scenePad.y};
    Rect r = pl.measure(at, shown, st);
    pl.fill(r.expanded(3).intersect(l.scene), Colour{0, 0, 0, 0.6f});
    pl.text(at, shown, st, BoxKind::Label, "scene", "pixel-label", !fits);
}

}  // namespace

void planScene(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t) {
    if (!m.markers) return;  // X: the scene as rendered, nothing drawn over it
    glm::vec2 origin = l.scene.position();
    // An inset (focusLayout) draws the scene scaled: the pixel's place scales with it, and the
    // texel grid (one overlay pixel per scene pixel) is left to the full-size scene.
    float scale =
        l.sceneInset && m.sceneSize.x > 0 ? l.scene.w / static_cast<float>(m.sceneSize.x) : 1.0f;
    glm::vec2 centre = origin + (glm::vec2(m.pixel) + 0.5f) * scale;
    float lineWidth = l.presentation ? 3.0f : 2.0f;
    Rect scene = l.scene;
    if (!l.sceneInset) {
        pl.op([=](Canvas& c) { c.pushClip(scene); });
        planTexelGrid(pl, l, m);
        pl.op([](Canvas& c) { c.popClip(); });
    }
    // The ring and the label go on top, over what the session draws on the scene after the base
    // plan (the frozen cascades' boxes and split planes, session.cpp drawFrozenCascades).
    bool onTop = pl.onTop;
    pl.onTop = true;
    // Wide enough that what lies at the pixel (9.3's light gap at the pole's foot) shows inside.
    float ringR = std::max(11.0f, 14.0f * l.scale);
    pl.op([=](Canvas& c) {
        c.pushClip(scene);
        c.ring(centre, ringR, lineWidth, Colour{0, 0, 0, 0.8f});
        c.ring(centre, ringR, lineWidth * 0.5f, POINT);
        c.fillRect({centre.x - 0.5f, centre.y - 0.5f, 1.0f, 1.0f}, POINT);
        c.popClip();
    });
    Rect ring{centre.x - ringR - lineWidth, centre.y - ringR - lineWidth, 2 * (ringR + lineWidth),
              2 * (ringR + lineWidth)};
    pl.box(BoxKind::Mark, ring.intersect(l.scene), "scene", "picked-pixel");
    planPixelLabel(pl, l, m, t, centre);
    pl.onTop = onTop;
}

}  // namespace pcf::inspector_detail
