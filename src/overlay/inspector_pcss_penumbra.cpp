// inspector_pcss_penumbra.cpp: pcss's penumbra page: the similar triangles of Fernando,
// "Percentage-Closer Soft Shadows" (NVIDIA, 2005), drawn with the step's own numbers. A light
// of width w_light, a blocker edge at distance d_b from it, a receiver at d_r: the rays from the
// light's two ends past the blocker's edge meet the receiver w apart, and by similar triangles
// w / (d_r - d_b) = w_light / d_b, so w = (d_r - d_b) * w_light / d_b.
#include "kernel/trace_explain.h"
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

namespace {

constexpr Colour BLOCKER_BAR{0.55f, 0.57f, 0.64f, 1.0f};
constexpr Colour LIGHT_BAR{1.0f, 0.93f, 0.55f, 1.0f};
constexpr Colour RAY{0.66f, 0.69f, 0.76f, 0.9f};

// The figure's heights: the light at yL, the blocker at yB, the receiver at yR, in proportion
// to the distances (d_b / d_r of the way down), the blocker kept a bar's width off both.
struct PenumbraGeometry {
    float yL, yB, yR;
    float xLight0, xLight1, xEdge;  // the light's ends, the blocker's edge
    float xLeft, xRight;            // the figure's extent (the blocker and receiver start at xLeft)
    float w0, w1;                   // the penumbra on the receiver: where the two rays meet it
};

PenumbraGeometry penumbraGeometry(const Rect& fig, float db, float dr) {
    PenumbraGeometry g;
    g.yL = fig.y;
    g.yR = fig.bottom();
    float share = dr > 0.0f ? std::clamp(db / dr, 0.08f, 0.95f) : 0.5f;
    g.yB = g.yL + (g.yR - g.yL) * share;
    g.xLeft = fig.x;
    g.xRight = fig.right();
    // Far side of the rays per unit of light width: (d_r - d_b) / d_b. The light's width is
    // chosen so that the figure holds the penumbra: light and penumbra share the width.
    float ratio = (g.yR - g.yB) / std::max(1.0f, g.yB - g.yL);
    float lightW = std::min(0.3f * fig.w, 0.7f * fig.w / std::max(1.0f, ratio + 1.0f));
    g.xEdge = fig.x + 0.55f * fig.w;
    g.xLight0 = g.xEdge - 0.5f * lightW;
    g.xLight1 = g.xEdge + 0.5f * lightW;
    // The ray from the light's left end passes the edge and lands right of it; from the right
    // end, left of it: similar triangles, in pixels.
    g.w1 = g.xEdge + (g.xEdge - g.xLight0) * ratio;
    g.w0 = g.xEdge - (g.xLight1 - g.xEdge) * ratio;
    return g;
}

// A label of the figure at `at` (its top left), as a text of the panel.
void figureLabel(Planner& pl, glm::vec2 at, const std::string& s, const TypeSizes& t,
                 TextAlign align, const std::string& role) {
    pl.text(at, s, {FontFace::Sans, t.number, TEXT, align}, BoxKind::Text, "inspector", role);
}

// The numbers the figure is drawn with: the distances and the width, as the trace has them.
struct PenumbraNumbers {
    float db = 0.0f, dr = 0.0f;  // light to blocker, light to receiver
    float w = 0.0f;              // the penumbra, texels
};

// The arrows d_b and d_r in two columns left of the figure (d_r outermost: their labels never
// meet however close d_b and d_r), each labelled with its name and value, one above the other.
void planDistanceArrows(Planner& pl, const Rect& box, const PenumbraGeometry& g, float column,
                        const PenumbraNumbers& n, const TypeSizes& t) {
    float lh = lineHeightOf(t.number);
    float xr = box.x + column, xb = box.x + 2.0f * column;
    pl.op([=](Canvas& c) {
        c.arrow({xr, g.yL}, {xr, g.yR}, 1.5f, TEXT_DIM);
        c.arrow({xb, g.yL}, {xb, g.yB}, 1.5f, TEXT_DIM);
        c.line({xb, g.yB}, {g.xLeft, g.yB}, 1.0f, RAY);
        c.line({xr, g.yR}, {g.xLeft, g.yR}, 1.0f, RAY);
    });
    auto label = [&](float x, float y0, float y1, const std::string& name, float value,
                     const std::string& role) {
        float y = std::clamp(0.5f * (y0 + y1) - lh, box.y + lh, box.bottom() - 2.0f * lh);
        figureLabel(pl, {x - 4.0f, y}, name, t, TextAlign::Right, role);
        figureLabel(pl, {x - 4.0f, y + lh}, formatNumber(value), t, TextAlign::Right,
                    role + "-value");
    };
    label(xr, g.yL, g.yR, "d_r", n.dr, "penumbra-dr");
    label(xb, g.yL, g.yB, "d_b", n.db, "penumbra-db");
}

// The side view: the light, the blocker's bar, the receiver's line, the two rays, the
// distances d_b and d_r as arrows on the left and w as a band on the receiver, named under it.
void planPenumbraFigure(Planner& pl, const Rect& box, const PenumbraNumbers& n,
                        const TypeSizes& t) {
    float lh = lineHeightOf(t.number);
    float column = std::max(measureText(FontFace::Sans, t.number, formatNumber(n.db)).x,
                            measureText(FontFace::Sans, t.number, formatNumber(n.dr)).x) +
                   8.0f;
    Rect fig{box.x + 2.0f * column + 12.0f, box.y + lh + 6.0f, box.w - 2.0f * column - 12.0f,
             box.h - 2.0f * lh - 16.0f};
    PenumbraGeometry g = penumbraGeometry(fig, n.db, n.dr);
    Rect light{g.xLight0, g.yL - 3.0f, g.xLight1 - g.xLight0, 6.0f};
    Rect blocker{g.xLeft, g.yB - 4.0f, g.xEdge - g.xLeft, 8.0f};
    Rect receiver{g.xLeft, g.yR - 1.0f, g.xRight - g.xLeft, 2.0f};
    Rect band{g.w0, g.yR - 2.0f, g.w1 - g.w0, 4.0f};
    pl.op([=](Canvas& c) {
        c.fillRect(light, LIGHT_BAR);
        c.fillRect(blocker, BLOCKER_BAR);
        c.fillRect(receiver, TEXT_DIM);
        c.line({g.xLight0, g.yL}, {g.w1, g.yR}, 1.5f, RAY);
        c.line({g.xLight1, g.yL}, {g.w0, g.yR}, 1.5f, RAY);
        c.fillRect(band, WEIGHT_BAR);
    });
    // The figure's parts as marks: centred on their lines, so that a check can measure the
    // triangles (band / (yR - yB) = light / (yB - yL)).
    pl.box(BoxKind::Mark, light, "inspector", "penumbra-light-bar");
    pl.box(BoxKind::Mark, blocker, "inspector", "penumbra-blocker");
    pl.box(BoxKind::Mark, receiver, "inspector", "penumbra-receiver");
    pl.box(BoxKind::Mark, band, "inspector", "penumbra-band");
    auto centred = [&](float x, float y, const std::string& s, const std::string& role) {
        float half = 0.5f * measureText(FontFace::Sans, t.number, s).x;
        figureLabel(pl, {std::clamp(x, box.x + half, box.right() - half), y}, s, t,
                    TextAlign::Center, role);
    };
    centred(0.5f * (g.xLight0 + g.xLight1), box.y, "light, w_light wide", "penumbra-light");
    centred(0.5f * (g.w0 + g.w1), g.yR + 6.0f, "w = " + formatNumber(n.w) + " texels",
            "penumbra-w");
    planDistanceArrows(pl, box, g, column, n, t);
}

// The words under the figure: what each mark is, the formula, and the trace's numbers in it.
std::string penumbraWords(const Trace& tr) {
    const PcfPcssEstimate& e = tr.pcss;
    float S = tr.params.penumbraScale;
    std::string s =
        "Similar triangles (Fernando, \"Percentage-Closer Soft Shadows\", 2005): the grey bar is "
        "the blockers' mean ";
    bool spot = tr.params.depthNear > 0.0f;
    float dr = spot ? pcfPcssLinearDepth(tr.ref, tr.params.depthNear, tr.params.depthFar) : tr.ref;
    if (spot) {
        s += "distance d_b = " + formatNumber(e.blockerDepth) +
             ", the line the receiver at d_r = " + formatNumber(dr) +
             ", distances from the spot, the red band the penumbra w = (d_r - d_b) * w_light / "
             "d_b. At the receiver the map turns it into texels with S = " +
             formatNumber(S) + ": w = S * (d_r - d_b) / (d_b * d_r) = " + formatNumber(S) + " * (" +
             formatNumber(dr) + " - " + formatNumber(e.blockerDepth) + ") / (" +
             formatNumber(e.blockerDepth) + " * " + formatNumber(dr) + ")";
    } else {
        s += "depth d_b = " + formatNumber(e.blockerDepth) +
             ", the line the receiver at d_r = ref = " + formatNumber(dr) +
             ", the red band the penumbra w = (d_r - d_b) * w_light / d_b. The sun is so far "
             "away that w_light / d_b is its angular size, S = " +
             formatNumber(S) + " texels per unit of depth: w = (" + formatNumber(dr) + " - " +
             formatNumber(e.blockerDepth) + ") * " + formatNumber(S);
    }
    s += " = " + formatNumber(e.penumbra) + " texels. The filter's points get half of it: scale " +
         formatNumber(e.filterRadius) + (e.filterRadius == 1.0f ? " texel" : " texels");
    bool clamped = std::abs(e.filterRadius - 0.5f * e.penumbra) > 1e-4f;
    if (clamped) {
        s += " (kept within [" + formatNumber(PCF_PCSS_MIN_RADIUS) + ", " +
             formatNumber(PCF_PCSS_MAX_RADIUS) + "])";
    }
    return s + ".";
}

}  // namespace

void planPenumbraPage(Planner& pl, const InspectorLayout& l, const Trace& tr, const TypeSizes& t,
                      float top, float bottom) {
    float margin = inspectorMargin(l);
    float width = l.inspector.w - 2 * margin;
    std::string words = penumbraWords(tr);
    FittedText f = fitText(words, FontFace::Sans, t.number, t.numberFloor, width, 1e6f);
    float wordsH = static_cast<float>(f.lines.size()) * f.lineHeight;
    float figH = std::min(bottom - top - wordsH - t.number, std::max(160.0f, 0.6f * width));
    figH = std::max(figH, 4.0f * lineHeightOf(t.number));
    bool spot = tr.params.depthNear > 0.0f;
    float dr = spot ? pcfPcssLinearDepth(tr.ref, tr.params.depthNear, tr.params.depthFar) : tr.ref;
    planPenumbraFigure(pl, {l.inspector.x + margin, top, width, figH},
                       {tr.pcss.blockerDepth, dr, tr.pcss.penumbra}, t);
    Rect area{l.inspector.x + margin, top + figH + t.number * 0.5f, width,
              bottom - (top + figH + t.number * 0.5f)};
    FittedText fitted =
        fitText(words, FontFace::Sans, t.number, t.numberFloor, area.w, std::max(area.h, 1.0f));
    placeFitted(pl, fitted, area, 0, FontFace::Sans, TEXT, "inspector", "penumbra-words", "");
}

}  // namespace pcf::inspector_detail
