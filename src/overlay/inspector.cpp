#include "overlay/inspector.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kernel/methods.h"

namespace pcf {

namespace {

// Colours (straight alpha). Presentation mode swaps in darker text and stronger lines.
constexpr Colour PANEL{0.10f, 0.11f, 0.14f, 1.0f};
constexpr Colour PANEL_LIGHT{0.16f, 0.17f, 0.21f, 1.0f};
constexpr Colour TEXT{0.92f, 0.93f, 0.95f, 1.0f};
constexpr Colour TEXT_DIM{0.62f, 0.65f, 0.72f, 1.0f};
constexpr Colour ACCENT{0.35f, 0.78f, 0.98f, 1.0f};
constexpr Colour POINT{0.95f, 0.20f, 0.45f, 1.0f};
constexpr Colour GATHER{0.30f, 0.90f, 0.50f, 1.0f};
constexpr Colour PADDING{0.30f, 0.31f, 0.35f, 1.0f};
constexpr Colour DARK_TEXT{0.08f, 0.08f, 0.10f, 1.0f};
constexpr Colour STATUS{0.03f, 0.03f, 0.04f, 1.0f};

std::string fixed(float v, int decimals) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, static_cast<double>(v));
    return buf;
}

float fontSize(const InspectorLayout& l, float base, bool presentation) {
    return std::round(base * l.scale * (presentation ? 1.35f : 1.0f));
}

const TapRecord* firstTapAt(const Trace& tr, glm::ivec2 texel) {
    for (const TapRecord& t : tr.taps) {
        if (t.texel == texel) return &t;
    }
    return nullptr;
}

// Texel-space position (uv * size: texel (i, j) spans [i, i+1)) of a uv, inside the view.
glm::vec2 viewPoint(const Neighbourhood& n, const Rect& area, glm::vec2 texelPos) {
    float cell = area.w / static_cast<float>(std::max(n.size.x, n.size.y));
    return {area.x + (texelPos.x - static_cast<float>(n.origin.x)) * cell,
            area.y + (texelPos.y - static_cast<float>(n.origin.y)) * cell};
}

void drawSceneOverlay(Canvas& c, const InspectorLayout& l, const InspectorModel& m) {
    glm::vec2 origin = l.scene.position();
    glm::vec2 centre = origin + glm::vec2(m.pixel) + 0.5f;
    float lineWidth = m.presentation ? 3.0f : 2.0f;
    c.pushClip(l.scene);
    // The texel grid of the shadow map where it lands on the receiver around the pixel: a pixel
    // is marked where its texel differs from its left or upper neighbour's. The footprint's
    // texels are tinted, so one texel visibly covers many pixels (perspective aliasing).
    glm::ivec2 region = m.lightSpaceSize;
    if (m.trace && m.lightSpace && region.x > 0 &&
        m.lightSpace->size() == static_cast<size_t>(region.x) * region.y * 4) {
        const std::vector<float>& ls = *m.lightSpace;
        glm::vec2 mapSize(m.trace->mapSize);
        int radius = gridRadius(m.sceneSize);
        auto texelAt = [&](int x, int y, glm::ivec2& out) {
            if (x < 0 || y < 0 || x >= m.sceneSize.x || y >= m.sceneSize.y) return false;
            glm::ivec2 r = glm::ivec2(x, y) - m.lightSpaceOrigin;
            if (r.x < 0 || r.y < 0 || r.x >= region.x || r.y >= region.y) return false;
            size_t k = (static_cast<size_t>(r.y) * region.x + r.x) * 4;
            if (ls[k + 3] != 1.0f) return false;
            out = glm::ivec2(glm::floor(glm::vec2(ls[k], ls[k + 1]) * mapSize));
            return true;
        };
        Neighbourhood n = neighbourhoodOf(*m.trace);
        // Per row, runs of pixels of one kind become one rect: a few hundred rects, not one
        // per pixel.
        enum Kind { NONE, FOOTPRINT_EDGE, EDGE, FOOTPRINT };
        const Colour colours[] = {Colour{0.0f}, Colour{0.1f, 0.9f, 1.0f, 0.95f},
                                  Colour{0.05f, 0.05f, 0.1f, 0.35f},
                                  Colour{0.2f, 0.85f, 1.0f, 0.18f}};
        for (int y = m.pixel.y - radius; y <= m.pixel.y + radius; ++y) {
            Kind runKind = NONE;
            int runStart = 0;
            for (int x = m.pixel.x - radius; x <= m.pixel.x + radius + 1; ++x) {
                Kind kind = NONE;
                glm::ivec2 t, left, up;
                if (x <= m.pixel.x + radius && texelAt(x, y, t)) {
                    bool inFootprint = t.x >= n.origin.x && t.y >= n.origin.y &&
                                       t.x < n.origin.x + n.size.x && t.y < n.origin.y + n.size.y;
                    bool edge = (texelAt(x - 1, y, left) && left != t) ||
                                (texelAt(x, y - 1, up) && up != t);
                    kind = edge ? (inFootprint ? FOOTPRINT_EDGE : EDGE)
                                : (inFootprint ? FOOTPRINT : NONE);
                }
                if (kind != runKind) {
                    if (runKind != NONE) {
                        c.fillRect({origin.x + runStart, origin.y + y,
                                    static_cast<float>(x - runStart), 1.0f},
                                   colours[runKind]);
                    }
                    runKind = kind;
                    runStart = x;
                }
            }
        }
    }
    c.ring(centre, 9.0f * l.scale, lineWidth, Colour{0, 0, 0, 0.8f});
    c.ring(centre, 9.0f * l.scale, lineWidth * 0.5f, POINT);
    c.fillRect({centre.x - 0.5f, centre.y - 0.5f, 1.0f, 1.0f}, POINT);
    c.popClip();
    std::string label = "pixel (" + std::to_string(m.pixel.x) + ", " + std::to_string(m.pixel.y) +
                        ")" + (m.trace ? "" : ": no shadow receiver here");
    float size = fontSize(l, 14, m.presentation);
    glm::vec2 at = centre + glm::vec2(14.0f, 10.0f) * l.scale;
    at.x = std::min(at.x, l.scene.right() - 260.0f * l.scale);
    at.y = std::min(at.y, l.scene.bottom() - size * 1.6f);
    Rect box = c.text(at, label, {FontFace::Sans, size, TEXT});
    c.fillRect(box.expanded(3), Colour{0, 0, 0, 0.55f});
    c.text(at, label, {FontFace::Sans, size, TEXT});
}

void drawNeighbourhood(Canvas& c, const InspectorLayout& l, const InspectorModel& m,
                       const Rect& area) {
    const Trace& tr = *m.trace;
    Neighbourhood n = neighbourhoodOf(tr);
    float cell = area.w / static_cast<float>(std::max(n.size.x, n.size.y));
    float line = m.presentation ? 3.0f : std::max(1.0f, std::round(l.scale));
    float maxWeight = 0.0f;
    for (float w : tr.weights.values) maxWeight = std::max(maxWeight, w);
    for (int j = 0; j < n.size.y; ++j) {
        for (int i = 0; i < n.size.x; ++i) {
            glm::ivec2 texel = n.origin + glm::ivec2(i, j);
            Rect r = texelCellRect(n, area, texel);
            const TapRecord* tap = firstTapAt(tr, texel);
            float weight = tr.weights.at(texel);
            bool inMap = texel.x >= 0 && texel.y >= 0 && texel.x < tr.mapSize.x &&
                         texel.y < tr.mapSize.y;
            Colour fill = !tap ? PADDING : tap->lit >= 0.5f ? LIT_COLOUR : SHADOWED_COLOUR;
            if (tap && weight == 0.0f) fill = glm::mix(fill, PADDING, 0.55f);
            c.fillRect(r, fill);
            // A tap whose texel lay outside the map, read clamped to the edge: an orange frame.
            bool clamped = std::any_of(tr.taps.begin(), tr.taps.end(), [&](const TapRecord& t) {
                return t.texel == texel && t.clamped;
            });
            if (clamped) c.strokeRect(r.expanded(-3.0f * line), line, Colour{1.0f, 0.6f, 0.1f, 1});
            // Weight as a bar along the cell's bottom edge, full width = the largest weight.
            if (tap && maxWeight > 0.0f && weight > 0.0f) {
                float h = std::max(3.0f, cell * 0.07f);
                c.fillRect({r.x, r.bottom() - h, r.w * weight / maxWeight, h},
                           Colour{0.95f, 0.35f, 0.25f, 0.9f});
            }
            Colour ink = tap && tap->lit >= 0.5f ? DARK_TEXT : TEXT;
            float big = std::min(cell * 0.30f, fontSize(l, 30, m.presentation));
            float small = std::min(cell * 0.16f, fontSize(l, 14, m.presentation));
            if (tap && cell >= 30.0f) {
                bool soft = tap->lit != 0.0f && tap->lit != 1.0f;  // the soft comparison
                bool ownRef = tap->ref != tr.ref && cell >= 64.0f;  // its ref goes below
                std::string bitText = soft ? fixed(tap->lit, 2) : tap->lit >= 0.5f ? "1" : "0";
                c.text({r.centre().x, r.y + cell * 0.30f}, bitText,
                       {FontFace::Mono, soft || ownRef ? big * 0.6f : big, ink, TextAlign::Center});
            }
            // The tap's own ref where the bias gave it one (receiver plane).
            if (tap && tap->ref != tr.ref && cell >= 64.0f && small >= 9.0f) {
                c.text({r.centre().x, r.y + cell * 0.50f}, "r " + fixed(tap->ref, 4),
                       {FontFace::Mono, small, ink, TextAlign::Center});
            }
            if (cell >= 64.0f && small >= 9.0f) {
                if (inMap) {
                    float depth = m.map ? m.map->depth(texel.x, texel.y)
                                        : (tap ? tap->depth : 0.0f);
                    c.text({r.centre().x, r.y + cell * 0.06f}, "d " + fixed(depth, 3),
                           {FontFace::Mono, small, ink, TextAlign::Center});
                }
                if (tap) {
                    c.text({r.centre().x, r.y + cell * 0.66f}, "w " + fixed(weight, 3),
                           {FontFace::Mono, small, ink, TextAlign::Center});
                }
            }
        }
    }
    // Grid lines and texel indices along the edges.
    for (int i = 0; i <= n.size.x; ++i) {
        float x = area.x + i * cell;
        c.line({x, area.y}, {x, area.y + n.size.y * cell}, line, Colour{0, 0, 0, 0.9f});
    }
    for (int j = 0; j <= n.size.y; ++j) {
        float y = area.y + j * cell;
        c.line({area.x, y}, {area.x + n.size.x * cell, y}, line, Colour{0, 0, 0, 0.9f});
    }
    float label = fontSize(l, 12, m.presentation);
    for (int i = 0; i < n.size.x; ++i) {
        c.text({area.x + (i + 0.5f) * cell, area.y - label * 1.4f},
               "i=" + std::to_string(n.origin.x + i),
               {FontFace::Mono, label, TEXT_DIM, TextAlign::Center});
    }
    for (int j = 0; j < n.size.y; ++j) {
        c.text({area.x - 4.0f * l.scale, area.y + (j + 0.5f) * cell - label * 0.6f},
               "j=" + std::to_string(n.origin.y + j),
               {FontFace::Mono, label, TEXT_DIM, TextAlign::Right});
    }

    // The fetches: hardware taps as rings, gathers as outlined 2x2 blocks, point reads and
    // bilinear lookups as small dots, all at the uv each instruction sampled.
    glm::vec2 size(tr.mapSize);
    for (size_t f = 0; f < tr.fetches.size(); ++f) {
        const FetchRecord& fr = tr.fetches[f];
        glm::vec2 at = viewPoint(n, area, fr.uv * size);
        if (fr.kind == PCF_FETCH_HW) {
            c.ring(at, std::max(5.0f, cell * 0.12f), line, Colour{0.1f, 0.1f, 0.1f, 0.9f});
            c.circle(at, std::max(2.0f, cell * 0.04f), ACCENT);
        } else if (fr.kind == PCF_FETCH_GATHER) {
            glm::ivec2 corner(glm::floor(fr.uv * size - 0.5f));
            Rect a = texelCellRect(n, area, corner);
            Rect b = texelCellRect(n, area, corner + glm::ivec2(1));
            Rect block{a.x, a.y, b.right() - a.x, b.bottom() - a.y};
            c.strokeRect(block.expanded(-2.0f * line), 2.0f * line, GATHER);
        } else if (tr.params.method == PCF_POISSON || tr.params.method == PCF_NAIVE ||
                   tr.params.method == PCF_HW) {
            c.circle(at, std::max(2.5f, cell * 0.035f), ACCENT);
        }
    }
    // The lookup point, its base texel centre and the fractions between them.
    glm::vec2 p = tr.uv * size;  // texel space with texel (i, j) spanning [i, i+1)
    glm::vec2 point = viewPoint(n, area, p);
    glm::vec2 baseCentre = viewPoint(n, area, glm::vec2(tr.pos.base) + 0.5f);
    if (tr.params.method == PCF_POISSON) {
        c.ring(point, tr.params.radius * cell, line, Colour{0.95f, 0.2f, 0.45f, 0.8f});
    }
    bool showFrac = tr.params.method != PCF_NEAREST && tr.params.method != PCF_POISSON;
    if (showFrac) {
        c.line(baseCentre, {point.x, baseCentre.y}, line * 1.5f, POINT);
        c.line({point.x, baseCentre.y}, point, line * 1.5f, POINT);
        c.circle(baseCentre, std::max(3.0f, cell * 0.04f), Colour{0.1f, 0.1f, 0.1f, 1.0f});
        float fs = fontSize(l, 15, m.presentation);
        std::string fx = "fx " + fixed(tr.pos.frac.x, 2);
        std::string fy = "fy " + fixed(tr.pos.frac.y, 2);
        glm::vec2 fxAt{(baseCentre.x + point.x) * 0.5f, baseCentre.y - fs * 1.5f};
        Rect bx = c.text(fxAt, fx, {FontFace::Mono, fs, POINT, TextAlign::Center});
        c.fillRect(bx.expanded(2), Colour{0, 0, 0, 0.7f});
        c.text(fxAt, fx, {FontFace::Mono, fs, Colour{1, 1, 1, 1}, TextAlign::Center});
        glm::vec2 fyAt{point.x + 6.0f * l.scale, (baseCentre.y + point.y) * 0.5f - fs * 0.6f};
        Rect by = c.text(fyAt, fy, {FontFace::Mono, fs, POINT});
        c.fillRect(by.expanded(2), Colour{0, 0, 0, 0.7f});
        c.text(fyAt, fy, {FontFace::Mono, fs, Colour{1, 1, 1, 1}});
    }
    c.circle(point, std::max(5.0f, cell * 0.07f), Colour{0, 0, 0, 0.9f});
    c.circle(point, std::max(3.5f, cell * 0.05f), POINT);
}

// The formula with its numbers, from the kernel's own step texts.
std::string formulaText(const Trace& tr) {
    std::string out;
    for (size_t k = 0; k < tr.steps.size(); ++k) {
        const TraceStep& s = tr.steps[k];
        bool last = k + 1 == tr.steps.size();
        if (last || s.title.find("Lerp") != std::string::npos) {
            if (!out.empty()) out += "\n";
            out += s.text;
        }
    }
    return out;
}

void drawInspectorPanel(Canvas& c, const InspectorLayout& l, const InspectorModel& m) {
    const Rect& p = l.inspector;
    float margin = std::round(18.0f * l.scale);
    float head = fontSize(l, 20, m.presentation);
    float y = p.y + margin;
    if (!m.trace) {
        c.text({p.x + margin, y}, "Inspector", {FontFace::Sans, head, TEXT});
        c.textBox({p.x + margin, y + head * 2.0f, p.w - 2 * margin, p.h},
                  "No shadow receiver under the picked pixel. Click a point on the ground or on "
                  "an object to see its shadow lookup.",
                  {FontFace::Sans, fontSize(l, 15, m.presentation), TEXT_DIM});
        return;
    }
    const Trace& tr = *m.trace;
    const MethodInfo& info = methodInfo(tr.params.method);
    std::string title = std::string(info.name);
    if (info.usesKernel) title += "  N = " + std::to_string(tr.params.kernel);
    if (info.usesRadius) title += "  R = " + formatNumber(tr.params.radius);
    c.text({p.x + margin, y}, title, {FontFace::Mono, head, ACCENT});
    std::string result = "visibility = " + formatNumber(tr.visibility);
    c.text({p.right() - margin, y}, result, {FontFace::Mono, head, TEXT, TextAlign::Right});
    y += head * 1.5f;
    std::string counts = std::to_string(tr.counts.texels) + " texel reads";
    if (tr.counts.gathers) counts += ", " + std::to_string(tr.counts.gathers) + " gathers";
    if (tr.counts.hwTaps) counts += ", " + std::to_string(tr.counts.hwTaps) + " hardware taps";
    counts += "   uv (" + fixed(tr.uv.x, 4) + ", " + fixed(tr.uv.y, 4) + ")  ref " +
              fixed(tr.ref, 4) + "  bias " + std::string(biasName(tr.bias.mode));
    float small = fontSize(l, 13, m.presentation);
    // One line under the title: large presentation type steps down until it fits.
    while (small > 8.0f && measureText(FontFace::Mono, small, counts).x > p.w - 2.0f * margin) {
        small = std::round(small * 0.92f);
    }
    c.text({p.x + margin, y}, counts, {FontFace::Mono, small, TEXT_DIM});

    Rect grid = neighbourhoodArea(l, tr, m.presentation);
    Neighbourhood n = neighbourhoodOf(tr);
    float cell = grid.w / static_cast<float>(std::max(n.size.x, n.size.y));
    c.pushClip(p);
    drawNeighbourhood(c, l, m, grid);
    c.popClip();
    y = grid.y + cell * static_cast<float>(n.size.y) + margin;

    // Legend.
    float lg = fontSize(l, 12, m.presentation);
    float x = p.x + margin;
    auto swatch = [&](const Colour& col, const std::string& text) {
        c.fillRect({x, y + 2.0f, lg, lg}, col);
        Rect r = c.text({x + lg * 1.4f, y}, text, {FontFace::Sans, lg, TEXT_DIM});
        x = r.right() + lg * 1.4f;
    };
    swatch(LIT_COLOUR, "lit: ref <= depth");
    swatch(SHADOWED_COLOUR, "shadowed");
    swatch(Colour{0.95f, 0.35f, 0.25f, 1.0f}, "weight bar");
    swatch(POINT, "lookup point");
    y += lg * 2.0f;

    // The formula, from the kernel's own explanation.
    Rect formula{p.x + margin, y, p.w - 2 * margin, p.bottom() - y - margin};
    c.pushClip(formula);
    c.textBox(formula, formulaText(tr), {FontFace::Mono, fontSize(l, 13, m.presentation), TEXT});
    c.popClip();
}

void drawThumbnail(Canvas& c, const InspectorLayout& l, const InspectorModel& m) {
    if (!m.map || m.map->width() <= 0) return;
    const ShadowMap& map = *m.map;
    Rect box = thumbnailRect(l, m.presentation);
    // The map's pixels are blitted in by the caller (thumbnailImage); here the frame around
    // them, the neighbourhood's box and the caption.
    c.strokeRect(box.expanded(2), 2.0f, Colour{0, 0, 0, 1});
    if (m.trace) {
        Neighbourhood n = neighbourhoodOf(*m.trace);
        float sx = box.w / static_cast<float>(map.width());
        float sy = box.h / static_cast<float>(map.height());
        Rect nb{box.x + n.origin.x * sx, box.y + n.origin.y * sy, n.size.x * sx, n.size.y * sy};
        nb = nb.expanded(std::max(0.0f, 3.0f - std::min(nb.w, nb.h) * 0.5f));
        c.strokeRect(nb, m.presentation ? 3.0f : 2.0f, POINT);
    }
    float fs = fontSize(l, 11, m.presentation);
    c.text({box.centre().x, box.bottom() + 4.0f},
           "shadow map " + std::to_string(map.width()) + " x " + std::to_string(map.height()),
           {FontFace::Sans, fs, TEXT_DIM, TextAlign::Center});
}

void drawStepsPanel(Canvas& c, const InspectorLayout& l, const InspectorModel& m) {
    const Rect& p = l.steps;
    float margin = std::round(14.0f * l.scale);
    float head = fontSize(l, 20, m.presentation);
    c.text({p.x + margin, p.y + margin}, m.title, {FontFace::Sans, head, TEXT});
    float top = p.y + margin + head * 1.6f;
    Rect thumb = thumbnailRect(l, m.presentation);
    // Step list on the left, the current step's text in the middle.
    float listW = std::round(p.w * 0.30f);
    float item = fontSize(l, 13, m.presentation);
    // Titles wrap inside the list's column (large type in presentation mode would cut them);
    // when the wrapped list would run out of the panel, each title keeps one line, elided.
    float textW = listW - 8.0f;
    std::vector<std::vector<std::string>> labels;
    float needed = 0.0f;
    for (size_t k = 0; k < m.stepTitles.size(); ++k) {
        labels.push_back(wrapText(FontFace::Sans, item,
                                  std::to_string(k + 1) + ". " + m.stepTitles[k], textW));
        needed += (static_cast<float>(labels.back().size()) * 1.2f + 0.3f) * item;
    }
    if (top + needed > p.bottom() - margin) {
        for (size_t k = 0; k < labels.size(); ++k) {
            labels[k] = {elideText(FontFace::Sans, item,
                                   std::to_string(k + 1) + ". " + m.stepTitles[k], textW)};
        }
    }
    float y = top;
    for (size_t k = 0; k < labels.size(); ++k) {
        bool current = static_cast<int>(k) == m.currentStep;
        float h = (static_cast<float>(labels[k].size()) * 1.2f + 0.25f) * item;
        Rect row{p.x + margin, y - 2.0f, listW, h};
        if (current) c.fillRect(row, Colour{0.35f, 0.78f, 0.98f, 0.25f});
        c.pushClip(row);
        for (size_t line = 0; line < labels[k].size(); ++line) {
            c.text({p.x + margin + 4.0f, y + static_cast<float>(line) * item * 1.2f},
                   labels[k][line], {FontFace::Sans, item, current ? TEXT : TEXT_DIM});
        }
        c.popClip();
        y += h + 0.05f * item;
    }
    Rect text{p.x + margin * 2.0f + listW, top, thumb.x - margin * 2.0f - (p.x + listW + margin),
              p.bottom() - top - margin};
    // Presentation type is larger; where a long step would not fit, step down towards the
    // normal size rather than cut the explanation off.
    float size = fontSize(l, 15, m.presentation);
    float smallest = fontSize(l, 15, false);
    while (size > smallest &&
           static_cast<float>(wrapText(FontFace::Sans, size, m.stepText, text.w).size()) *
                   fontMetrics(FontFace::Sans, size).lineHeight >
               text.h) {
        size = std::max(smallest, std::round(size * 0.92f));
    }
    c.pushClip(text);
    c.textBox(text, m.stepText, {FontFace::Sans, size, TEXT});
    c.popClip();
    (void)thumb;  // the thumbnail is drawn by drawInspectorTop, over the blitted map
}

void drawHelp(Canvas& c, const InspectorLayout& l, const InspectorModel& m) {
    float fs = fontSize(l, 16, m.presentation);
    const auto& keys = viewerKeys();
    float w = 620.0f * l.scale;
    float h = (static_cast<float>(keys.size()) + 3.0f) * fs * 1.5f;
    Rect box{(l.frameSize.x - w) * 0.5f, (l.frameSize.y - h) * 0.5f, w, h};
    c.fillRect(box, Colour{0.02f, 0.03f, 0.05f, 0.92f});
    c.strokeRect(box, 2.0f, ACCENT);
    float y = box.y + fs;
    c.text({box.x + fs, y}, "Keys", {FontFace::Sans, fs * 1.2f, ACCENT});
    y += fs * 2.0f;
    for (const auto& [key, what] : keys) {
        c.text({box.x + fs, y}, key, {FontFace::Mono, fs, TEXT});
        c.text({box.x + fs + 190.0f * l.scale, y}, what, {FontFace::Sans, fs, TEXT_DIM});
        y += fs * 1.5f;
    }
}

}  // namespace

Rect thumbnailRect(const InspectorLayout& l, bool presentation) {
    const Rect& p = l.steps;
    float margin = std::round(14.0f * l.scale);
    float top = p.y + margin + fontSize(l, 20, presentation) * 1.6f;
    float side = std::floor(std::min(p.h - (top - p.y) - margin * 2.0f, p.w * 0.22f));
    return {std::round(p.right() - margin - side), std::round(top), side, side};
}

std::vector<uint8_t> thumbnailImage(const ShadowMap& map, int side) {
    // Nearest texel per thumbnail pixel, depth as grey (near the light = dark). Rows top-down
    // with texel row 0 at the top, like the neighbourhood view.
    std::vector<uint8_t> rgba(static_cast<size_t>(side) * side * 4);
    for (int y = 0; y < side; ++y) {
        int j = std::min(map.height() - 1, y * map.height() / side);
        for (int x = 0; x < side; ++x) {
            int i = std::min(map.width() - 1, x * map.width() / side);
            float g = 0.15f + 0.8f * std::clamp(map.depth(i, j), 0.0f, 1.0f);
            uint8_t v = static_cast<uint8_t>(std::lround(g * 255.0f));
            size_t k = (static_cast<size_t>(y) * side + x) * 4;
            rgba[k] = v;
            rgba[k + 1] = v;
            rgba[k + 2] = static_cast<uint8_t>(std::min(255L, std::lround(g * 1.05f * 255.0f)));
            rgba[k + 3] = 255;
        }
    }
    return rgba;
}

InspectorLayout inspectorLayout(glm::ivec2 frameSize, bool presentation) {
    InspectorLayout l;
    l.frameSize = frameSize;
    float w = static_cast<float>(frameSize.x);
    float h = static_cast<float>(frameSize.y);
    l.scale = std::max(0.5f, std::min(w / 1600.0f, h / 900.0f));
    float statusH = std::round(28.0f * l.scale * (presentation ? 1.3f : 1.0f));
    float sceneW = std::round(w * 0.6f);
    float sceneH = std::round(sceneW * 9.0f / 16.0f);
    if (sceneH > h * 0.64f) {
        sceneH = std::round(h * 0.64f);
        sceneW = std::round(sceneH * 16.0f / 9.0f);
    }
    l.scene = {0.0f, 0.0f, sceneW, sceneH};
    l.status = {0.0f, h - statusH, w, statusH};
    l.steps = {0.0f, sceneH, sceneW, l.status.y - sceneH};
    l.inspector = {sceneW, 0.0f, w - sceneW, l.status.y};
    return l;
}

Rect neighbourhoodArea(const InspectorLayout& l, const Trace& tr, bool presentation) {
    // Below the panel's two header lines (see drawInspectorPanel), square, as large as fits
    // above the formula, in whole-pixel cells.
    const Rect& p = l.inspector;
    float margin = std::round(18.0f * l.scale);
    float y = p.y + margin + fontSize(l, 20, presentation) * 1.5f +
              fontSize(l, 13, presentation) * 2.6f;
    float labelRoom = std::round(44.0f * l.scale);
    float side = std::min(p.w - 2 * margin - labelRoom, p.h * 0.56f);
    Neighbourhood n = neighbourhoodOf(tr);
    int cells = std::max(n.size.x, n.size.y);
    float cell = std::floor(side / static_cast<float>(cells));
    return {std::round(p.x + margin + labelRoom), std::round(y), cell * cells, cell * cells};
}

Neighbourhood neighbourhoodOf(const Trace& tr) {
    glm::ivec2 lo = tr.pos.base;
    glm::ivec2 hi = tr.pos.base + glm::ivec2(1);
    if (!tr.weights.values.empty()) {
        lo = glm::min(lo, tr.weights.origin);
        hi = glm::max(hi, tr.weights.origin + tr.weights.size - glm::ivec2(1));
    }
    glm::ivec2 point(glm::floor(tr.uv * glm::vec2(tr.mapSize)));
    lo = glm::min(lo, point);
    hi = glm::max(hi, point);
    return {lo, hi - lo + glm::ivec2(1)};
}

Rect texelCellRect(const Neighbourhood& n, const Rect& area, glm::ivec2 texel) {
    float cell = area.w / static_cast<float>(std::max(n.size.x, n.size.y));
    return {area.x + static_cast<float>(texel.x - n.origin.x) * cell,
            area.y + static_cast<float>(texel.y - n.origin.y) * cell, cell, cell};
}

const std::vector<std::pair<std::string, std::string>>& viewerKeys() {
    static const std::vector<std::pair<std::string, std::string>> keys = {
        {"click", "pick a pixel"},
        {"Up / Down", "move the pixel one row"},
        {"Shift+arrows", "move the pixel one pixel"},
        {"Space, Right", "next step"},
        {"Left, Backspace", "previous step"},
        {"Home / End", "first / last step"},
        {"M / Shift+M", "next / previous method"},
        {"[ / ]", "smaller / larger kernel"},
        {"- / +", "smaller / larger shadow map"},
        {"B", "next bias mode"},
        {"Q", "texture unit: exact / hw8"},
        {"L / Shift+L", "next / previous lesson"},
        {"E", "export this frame (PNG + JSON)"},
        {"P", "presentation mode"},
        {"H", "this help"},
        {"F", "fullscreen"},
        {"Esc", "quit"},
    };
    return keys;
}

void drawInspector(Canvas& c, const InspectorLayout& l, const InspectorModel& m) {
    if (m.showScene) drawSceneOverlay(c, l, m);
    drawStepsPanel(c, l, m);
    drawInspectorPanel(c, l, m);
    float fs = fontSize(l, 14, m.presentation);
    c.text({l.status.x + 10.0f * l.scale, l.status.y + (l.status.h - fs * 1.2f) * 0.5f},
           m.status, {FontFace::Mono, fs, TEXT});
    c.text({l.status.right() - 10.0f * l.scale, l.status.y + (l.status.h - fs * 1.2f) * 0.5f},
           "H: keys", {FontFace::Sans, fs, TEXT_DIM, TextAlign::Right});
}

void clearInspectorPanels(GLuint framebuffer, const InspectorLayout& l) {
    // Scissored clears: on llvmpipe a clear is a memset, while a panel-sized quad would run the
    // overlay's fragment shader over a million pixels.
    auto clearRect = [&](const Rect& r, const Colour& colour) {
        int frameH = l.frameSize.y;
        glScissor(static_cast<GLint>(r.x), frameH - static_cast<GLint>(r.bottom()),
                  static_cast<GLsizei>(r.w), static_cast<GLsizei>(r.h));
        glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, &colour.x);
    };
    GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
    glEnable(GL_SCISSOR_TEST);
    clearRect(l.inspector, PANEL);
    clearRect(l.steps, PANEL_LIGHT);
    clearRect(l.status, STATUS);
    if (!scissor) glDisable(GL_SCISSOR_TEST);
}

void drawInspectorTop(Canvas& c, const InspectorLayout& l, const InspectorModel& m) {
    drawThumbnail(c, l, m);
    if (m.help) drawHelp(c, l, m);
}

}  // namespace pcf
