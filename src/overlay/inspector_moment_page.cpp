// inspector_moment_page.cpp: the inspector panel of a moment method (vsm, evsm2, evsm4, msm,
// msm-hausdorff). Its map holds averages, not depths, and no texel has a comparison bit, so
// instead of cells it shows the statistics the method works with, in the order it uses them:
// the footprint's depths as a histogram over depth with the receiver's t, the filtered moments
// with their mean and variance, then the bound drawn as a curve over depth (each warp's for
// evsm4, before and after the light-bleeding linstep) with t on it and the value read off it, or
// msm's reconstructed points over the histogram; and PCF of the same footprint beside it. The
// figure's numbers are MomentFigure's (inspector_moments.h): the trace's and the kernel's.
#include <algorithm>
#include <optional>

#include "kernel/methods.h"
#include "kernel/trace_explain.h"
#include "overlay/inspector_moments.h"
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

namespace {

constexpr Colour PLOT_BACK{0.14f, 0.15f, 0.19f, 1.0f};
constexpr Colour PLOT_AXIS{0.45f, 0.47f, 0.53f, 1.0f};

// Small moments and EVSM's large warped ones in four significant digits.
std::string g4(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", static_cast<double>(v));
    return buf;
}

bool isMsm(const Trace& tr) { return methodInfo(tr.params.method).reconstructs; }

// hideRef: a question hides the ref (HiddenNumbers::refs): t is named, not given.
std::string footprintCaption(const Trace& tr, const MomentFigure& f, bool hideRef) {
    if (!f.hasFootprint) return "The depths under the moments are not known for this lookup.";
    return "Footprint: the " + std::to_string(tr.depths.texels.size()) +
           " depth texels the moments average (the " + std::to_string(tr.params.kernel) + " x " +
           std::to_string(tr.params.kernel) + " " + std::string(weightsName(tr.params.weights)) +
           " blur, then the bilinear read); a bar is their weight, the line t" +
           (hideRef ? std::string() : " = " + fixed(f.receiver, 4)) + " the receiver.";
}

// The filtered moments and what they say, in the kernel's numbers (Trace::moments).
std::string numbersText(const Trace& tr) {
    const PcfMomentEstimate& e = tr.moments;
    const MethodInfo& info = methodInfo(tr.params.method);
    std::string s = "m = (" + g4(e.moments.x) + ", " + g4(e.moments.y);
    if (texelKindInfo(tr.map.texels).channels == 4) {
        s += ", " + g4(e.moments.z) + ", " + g4(e.moments.w);
    }
    s += ")";
    if (info.reconstructs) s += " after moment bias " + g4(tr.params.momentBias);
    // evsm's mean and variance are of the positive warp's w+, not of the depth.
    std::string of = info.warps > 0 ? " of w+" : "";
    s += "\nmean" + of + " " + g4(e.mean) + "  variance" + of + " " + g4(e.variance);
    if (info.warps > 0) {
        int bits = texelKindInfo(tr.map.texels).bits;
        s += "\nexponents used: c+ " + g4(tr.params.evsmExponents.x);
        if (info.warps == 2) s += ", c- " + g4(tr.params.evsmExponents.y);
        s += " (" + std::string(momentFormatName(bits)) + " holds up to " +
             g4(evsmExponentLimit(bits)) + ")";
    }
    return s;
}

std::string boundCaption(const Trace& tr) {
    std::string s =
        "Chebyshev: p_max(t) = var / (var + (t - mean)^2), 1 for t <= mean, over the receiver's "
        "depth t";
    if (methodInfo(tr.params.method).warps > 0) s += " (each warp's moments; the smaller taken)";
    return s + ".";
}

std::string pcfLine(const Trace& tr, const MomentFigure& f) {
    if (!f.hasFootprint) return "";
    return std::string(methodInfo(tr.depths.pcfMethod).name) + ", the same " +
           std::to_string(tr.depths.texels.size()) + " texels at ref " + fixed(tr.ref, 4) + ": " +
           formatNumber(f.pcfVisibility);
}

// What the bound, or msm's reconstruction, gives, and PCF of the same footprint under it.
std::string resultText(const Trace& tr, const MomentFigure& f) {
    std::string s;
    if (isMsm(tr)) {
        s = "Reconstructed:";
        for (glm::vec2 p : f.points) s += " z " + g4(p.x) + " w " + g4(p.y) + ";";
        s += " the weight below t is the shadow.";
    } else {
        bool two = methodInfo(tr.params.method).warps == 2;
        for (const MomentFigure::Curve& c : f.curves) {
            if (c.afterLbr) continue;
            s += std::string(s.empty() ? "p_max(t) = " : ", ") + formatNumber(c.atReceiver);
            if (two) s += c.warp < 0 ? " (negative warp)" : " (positive warp)";
        }
        if (tr.params.lbr > 0.0f) {
            s += "; linstep(" + formatNumber(tr.params.lbr) +
                 ", 1, p) = " + formatNumber(f.curves.back().atReceiver);
        }
    }
    s += "\n" + std::string(methodInfo(tr.params.method).name) +
         ": visibility = " + formatNumber(tr.visibility);
    std::string pcf = pcfLine(tr, f);
    if (!pcf.empty()) s += "\n" + pcf;
    return s;
}

// ---- The plots. ----

struct Axis {
    Rect r;
    float lo = 0.0f, hi = 1.0f;
    float x(float depth) const { return r.x + (depth - lo) / (hi - lo) * r.w; }
    float y(float v, float top) const { return r.bottom() - std::clamp(v / top, 0.0f, 1.0f) * r.h; }
};

constexpr Colour HIST_BAR = MOMENT_BAR;
constexpr Colour MEAN_LINE = ACCENT;
constexpr Colour MSM_STEM = GATHER;

Colour curveColour(const MomentFigure::Curve& c) {
    if (c.afterLbr) return WEIGHT_BAR;
    return c.warp < 0 ? MOMENT_NEG_CURVE : LIT_COLOUR;
}

// The depth axis's ends under a plot, as labels. Returns the y under them.
float planAxisLabels(Planner& pl, const Axis& a, const TypeSizes& t) {
    TextStyle st{FontFace::Mono, t.label, TEXT_DIM};
    float y = a.r.bottom() + 2.0f;
    pl.text({a.r.x, y}, fixed(a.lo, 3), st, BoxKind::Label, "inspector", "moment-axis");
    st.align = TextAlign::Right;
    pl.text({a.r.right(), y}, fixed(a.hi, 3), st, BoxKind::Label, "inspector", "moment-axis");
    // The axis's name between its ends, where they leave it room.
    std::string ends = fixed(a.lo, 3) + "  depth  " + fixed(a.hi, 3);
    if (measureText(FontFace::Mono, t.label, ends).x * 1.5f <= a.r.w) {
        st.align = TextAlign::Center;
        pl.text({a.r.centre().x, y}, "depth", st, BoxKind::Label, "inspector", "moment-axis");
    }
    return y + lineHeightOf(t.label);
}

// The receiver's t as a vertical line across a plot.
void planReceiverLine(Planner& pl, const Axis& a, float t, float width) {
    float x = std::round(a.x(t));
    Rect r = a.r;
    pl.op([=](Canvas& c) { c.line({x, r.y}, {x, r.bottom()}, width, POINT); });
}

// The histogram of the footprint's depths (bar height: their weight), msm's points as stems
// over it on the same weight scale, the mean and the receiver's t.
void planHistogram(Planner& pl, const InspectorLayout& l, const Trace& tr, const MomentFigure& f,
                   const Axis& a, LegendNeeds& need) {
    float top = 0.0f;
    for (const MomentFigure::Bin& b : f.bins) top = std::max(top, b.weight);
    for (glm::vec2 p : f.points) top = std::max(top, p.y);
    top = std::max(top * 1.1f, 1e-6f);  // the tallest bar short of the plot's top edge
    pl.fill(a.r, PLOT_BACK);
    pl.box(BoxKind::Mark, a.r, "inspector", "moment-histogram");
    for (const MomentFigure::Bin& b : f.bins) {
        if (b.texels == 0) continue;
        Rect bar{a.x(b.lo) + 1.0f, a.y(b.weight, top), std::max(1.0f, a.x(b.hi) - a.x(b.lo) - 2.0f),
                 a.r.bottom() - a.y(b.weight, top)};
        pl.fill(bar, HIST_BAR);
        need.momentBars = true;
    }
    float w = lineOf(l);
    Rect clip = a.r;
    if (methodInfo(tr.params.method).warps == 0) {
        float mx = std::round(a.x(tr.moments.mean));
        pl.op([=](Canvas& c) {
            c.pushClip(clip);
            c.line({mx, clip.y}, {mx, clip.bottom()}, std::max(1.0f, w - 1.0f), MEAN_LINE);
            c.popClip();
        });
        need.meanLine = true;
    }
    // t under msm's points: the receiver's own point (z_f) stands on it.
    planReceiverLine(pl, a, f.receiver, w);
    need.receiverLine = true;
    for (glm::vec2 p : f.points) {
        if (!(p.x >= a.lo && p.x <= a.hi)) continue;
        glm::vec2 foot{a.x(p.x), a.r.bottom()};
        glm::vec2 head{foot.x, a.y(p.y, top)};
        float dot = std::max(3.0f, w + 1.0f);
        pl.op([=](Canvas& c) {
            c.line(foot, head, w, MSM_STEM);
            c.circle(head, dot, MSM_STEM);
        });
        need.msmPoints = true;
    }
}

// A value at the receiver's t: a curve's (a dot in its colour) or PCF's of the same footprint
// (a square), with its label.
struct ValueAtT {
    float v = 0.0f;
    Colour colour;
    std::string label;
    bool pcf = false;
};

// The values read off the plot at t: a label beside each mark, right of the line where it
// fits, each under the one above when they would meet (highest first).
void planReadouts(Planner& pl, const TypeSizes& t, const Axis& a, float x,
                  std::vector<ValueAtT> values) {
    std::stable_sort(values.begin(), values.end(),
                     [](const ValueAtT& p, const ValueAtT& q) { return p.v > q.v; });
    TextStyle st{FontFace::Mono, t.label, TEXT};
    float lh = lineHeightOf(t.label);
    float below = a.r.y;
    for (const ValueAtT& value : values) {
        float tw = measureText(st.face, st.pixelSize, value.label).x;
        float y = std::clamp(a.y(value.v, 1.0f) - lh, a.r.y, a.r.bottom() - lh);
        if (y < below) y = below;
        if (y + lh > a.r.bottom()) continue;  // no room left in the plot: the words give it
        bool right = x + 8.0f + tw <= a.r.right() - 2.0f;
        float lx = right ? x + 8.0f : x - 8.0f - tw;
        Rect plate{std::round(lx) - 2.0f, std::round(y), tw + 4.0f, lh};
        pl.fill(plate, Colour{PLOT_BACK.r, PLOT_BACK.g, PLOT_BACK.b, 0.85f});
        st.colour = value.colour;
        pl.text({lx, y}, value.label, st, BoxKind::Label, "inspector", "moment-value");
        below = y + lh;
    }
}

// The marks at t: a dot on each curve, a square at PCF's value.
void planValueMarks(Planner& pl, const InspectorLayout& l, const Axis& a, float x,
                    const std::vector<ValueAtT>& values) {
    float dot = std::max(4.0f, lineOf(l) + 2.0f);
    for (const ValueAtT& value : values) {
        glm::vec2 at{x, a.y(value.v, 1.0f)};
        Colour c = value.colour;
        bool square = value.pcf;
        pl.op([=](Canvas& cv) {
            if (square) {
                cv.fillRect({at.x - dot - 1.5f, at.y - dot - 1.5f, 2 * dot + 3, 2 * dot + 3},
                            Colour{0, 0, 0, 0.9f});
                cv.fillRect({at.x - dot, at.y - dot, 2 * dot, 2 * dot}, c);
            } else {
                cv.circle(at, dot + 1.5f, Colour{0, 0, 0, 0.9f});
                cv.circle(at, dot, c);
            }
        });
    }
}

// One plot of the bound over depth: its curve(s), t with a dot on each and the value read off
// it, and (`pcf`) a square at PCF's visibility of the same footprint (unless the step hides
// the result); 0 and 1 on its left.
void planCurvePlot(Planner& pl, const InspectorLayout& l, const TypeSizes& t, const Axis& a,
                   float receiver, const std::vector<const MomentFigure::Curve*>& curves,
                   std::optional<float> pcf, bool hideValue, LegendNeeds& need) {
    pl.fill(a.r, PLOT_BACK);
    pl.box(BoxKind::Mark, a.r, "inspector", "moment-curve");
    float w = lineOf(l);
    Rect clip = a.r;
    std::vector<ValueAtT> values;
    for (const MomentFigure::Curve* c : curves) {
        std::vector<glm::vec2> px;
        for (glm::vec2 p : c->points) px.push_back({a.x(p.x), a.y(p.y, 1.0f)});
        Colour col = curveColour(*c);
        pl.op([=](Canvas& cv) {
            cv.pushClip(clip);
            for (size_t k = 1; k < px.size(); ++k) cv.line(px[k - 1], px[k], w, col);
            cv.popClip();
        });
        (c->afterLbr ? need.lbrCurve : c->warp < 0 ? need.negCurve : need.boundCurve) = true;
        values.push_back({c->atReceiver, col, formatNumber(c->atReceiver), false});
    }
    planReceiverLine(pl, a, receiver, w);
    need.receiverLine = true;
    float x = std::round(a.x(receiver));
    if (!hideValue) {
        if (pcf) {
            values.push_back({*pcf, PCF_MARK, "pcf " + formatNumber(*pcf), true});
            need.pcfMark = true;
        }
        planValueMarks(pl, l, a, x, values);
        planReadouts(pl, t, a, x, values);
    }
    TextStyle st{FontFace::Mono, t.label, TEXT_DIM, TextAlign::Right};
    pl.text({a.r.x - 4.0f, a.r.y}, "1", st, BoxKind::Label, "inspector", "moment-axis");
    pl.text({a.r.x - 4.0f, a.r.bottom() - lineHeightOf(t.label)}, "0", st, BoxKind::Label,
            "inspector", "moment-axis");
}

// ---- The page. ----

// The marks the figure draws, for the legend (the page's part of them: need).
LegendNeeds figureNeeds(const Trace& tr, const MomentFigure& f, bool sceneTint) {
    LegendNeeds n;
    n.cells = n.point = false;
    n.footprint = sceneTint;
    n.momentBars = f.hasFootprint;
    n.meanLine = methodInfo(tr.params.method).warps == 0;
    n.msmPoints = !f.points.empty();
    n.receiverLine = true;
    n.pcfMark = f.hasFootprint && !f.curves.empty();
    for (const MomentFigure::Curve& c : f.curves) {
        (c.afterLbr ? n.lbrCurve : c.warp < 0 ? n.negCurve : n.boundCurve) = true;
    }
    return n;
}

constexpr const char* MASKED = "(the numbers are hidden until the answer is revealed)";

// The panel's texts for the figure, fitted to its width, and the room they and the plots need.
struct MomentTexts {
    FittedText caption, numbers, bound, result;
    float axisRow = 0.0f, gap = 0.0f, indent = 0.0f, subcaption = 0.0f;
};

MomentTexts momentTexts(const InspectorModel& m, const TypeSizes& t, const MomentFigure& f,
                        float width) {
    const Trace& tr = *m.trace;
    MomentTexts x;
    bool hidden = m.hidden.any();
    auto sans = [&](const std::string& s) {
        return fitText(s, FontFace::Sans, t.label, t.labelFloor, width, 1e6f);
    };
    auto mono = [&](const std::string& s) {
        return fitText(s, FontFace::Mono, t.number, t.numberFloor, width, 1e6f);
    };
    x.caption = sans(footprintCaption(tr, f, m.hidden.refs));
    x.numbers = hidden ? sans(MASKED) : mono(numbersText(tr));
    if (!isMsm(tr)) x.bound = sans(boundCaption(tr));
    x.result = hidden ? sans(MASKED) : mono(resultText(tr, f));
    x.axisRow = lineHeightOf(t.label) + 2.0f;
    x.gap = std::round(t.label * 0.4f);
    x.indent = measureText(FontFace::Mono, t.label, "1").x + 8.0f;
    x.subcaption = methodInfo(tr.params.method).warps == 2 ? lineHeightOf(t.label) : 0.0f;
    return x;
}

float heightOf(const FittedText& f) { return static_cast<float>(f.lines.size()) * f.lineHeight; }

// Places a fitted block at y (its whole height); returns the y under it and a gap.
float placeBlock(Planner& pl, const FittedText& f, float x, float y, float width, FontFace face,
                 const std::string& role, float gap) {
    if (f.lines.empty()) return y;
    float h = heightOf(f);
    placeFitted(pl, f, {x, y, width, h}, 0, face, TEXT, "inspector", role, "");
    return y + h + gap;
}

// The curves' plots in `box`: one, or evsm4's two warps side by side, each under a label that
// names its exponent and says which bound was taken. LBR's curve goes with the bound it cuts.
void planCurves(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t,
                const MomentFigure& f, const Axis& whole, float subcaption, LegendNeeds& need) {
    std::vector<std::vector<const MomentFigure::Curve*>> plots;
    for (const MomentFigure::Curve& c : f.curves) {
        if (c.afterLbr) continue;
        plots.push_back({&c});
    }
    for (const MomentFigure::Curve& c : f.curves) {
        if (!c.afterLbr) continue;
        for (auto& p : plots) {
            if (p.front()->taken) p.push_back(&c);
        }
    }
    float gapX = plots.size() > 1 ? whole.r.x - l.inspector.x : 0.0f;
    float w = (whole.r.w - gapX * static_cast<float>(plots.size() - 1)) /
              static_cast<float>(plots.size());
    for (size_t k = 0; k < plots.size(); ++k) {
        Axis a = whole;
        a.r.x = std::round(whole.r.x + static_cast<float>(k) * (w + gapX));
        a.r.w = std::floor(w);
        if (subcaption > 0.0f) {
            const MomentFigure::Curve& c = *plots[k].front();
            std::string s = std::string(c.warp < 0 ? "negative" : "positive") + " warp, c " +
                            formatNumber(c.exponent) + (c.taken ? ": taken" : "");
            s = elideText(FontFace::Sans, t.label, s, a.r.w);
            pl.text({a.r.x, a.r.y - subcaption}, s,
                    {FontFace::Sans, t.label, c.taken ? TEXT : TEXT_DIM}, BoxKind::Text,
                    "inspector", "moment-warp");
        }
        // PCF of the same footprint on the plot whose bound gave the visibility.
        std::optional<float> pcf;
        if (f.hasFootprint && plots[k].front()->taken) pcf = f.pcfVisibility;
        planCurvePlot(pl, l, t, a, f.receiver, plots[k], pcf, m.hidden.any(), need);
        planAxisLabels(pl, a, t);
    }
}

}  // namespace

bool momentFigures(const Trace& tr) { return readsMoments(tr.params.method); }

namespace {

// The heights the parts take: part 0 (the histogram and the moments), part 1 (the bound and
// the result), less their plots; the plots' smallest height.
struct MomentRoom {
    float fixed0 = 0.0f, fixed1 = 0.0f, minPlot = 0.0f;
    bool curves = false;
};

MomentRoom momentRoom(const MomentTexts& x, const TypeSizes& t, bool curves) {
    MomentRoom r;
    r.curves = curves;
    r.minPlot = 4.0f * lineHeightOf(t.number);
    r.fixed0 = heightOf(x.caption) + x.gap + x.axisRow + x.gap + heightOf(x.numbers) + x.gap;
    r.fixed1 = (curves ? heightOf(x.bound) + x.gap + x.subcaption + x.axisRow + x.gap : 0.0f) +
               heightOf(x.result) + x.gap;
    return r;
}

// Page `part` of `parts` (1: everything on it) from top to bottom.
void planMomentPart(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                    const TypeSizes& t, const MomentFigure& f, const MomentTexts& x,
                    const MomentRoom& room, int parts, int part, float top, float bottom) {
    const Trace& tr = *m.trace;
    float margin = inspectorMargin(l);
    float x0 = l.inspector.x + margin;
    float width = l.inspector.w - 2.0f * margin;
    LegendNeeds all = figureNeeds(tr, f, pl.plan.footprintShown);
    LegendNeeds need = all;
    need.momentBars = need.meanLine = need.msmPoints = false;
    need.boundCurve = need.negCurve = need.lbrCurve = need.receiverLine = need.pcfMark = false;
    FramePlan scratch;
    Planner sp{scratch};
    float legendH = planLegend(sp, l, m, all, t, margin, 0.0f);
    bool first = parts == 1 || part == 0;
    bool second = parts == 1 || part == 1;
    float fixedH = (first ? room.fixed0 : 0.0f) + (second ? room.fixed1 : 0.0f);
    float plotsRoom = bottom - top - legendH - fixedH;
    bool twoPlots = first && second && room.curves;
    float histH = twoPlots ? std::round(plotsRoom * 0.45f) : std::round(plotsRoom);
    histH = std::min(histH, std::round(l.inspector.h * (room.curves ? 0.3f : 0.45f)));
    float curveH = std::min(std::round(plotsRoom - (twoPlots ? histH : 0.0f)),
                            std::round(l.inspector.h * 0.32f));
    Axis axis{{x0 + x.indent, 0.0f, width - x.indent, 0.0f}, f.axisLo, f.axisHi};
    float y = top;
    if (first) {
        y = placeBlock(pl, x.caption, x0, y, width, FontFace::Sans, "moment-caption", x.gap);
        Axis h = axis;
        h.r.y = y;
        h.r.h = histH;
        planHistogram(pl, l, tr, f, h, need);
        y = planAxisLabels(pl, h, t) + x.gap;
        y = placeBlock(pl, x.numbers, x0, y, width,
                       m.hidden.any() ? FontFace::Sans : FontFace::Mono,
                       m.hidden.any() ? "masked" : "moment-numbers", x.gap);
        for (size_t k = 0; k < tr.fetches.size(); ++k) {
            pl.plan.drawnFetches.push_back(static_cast<int>(k));
        }
        for (const FootprintTexel& ft : tr.depths.texels) pl.plan.drawnTexels.push_back(ft.texel);
    }
    if (second) {
        if (room.curves) {
            y = placeBlock(pl, x.bound, x0, y, width, FontFace::Sans, "moment-caption", x.gap);
            Axis c = axis;
            c.r.y = y + x.subcaption;
            c.r.h = curveH;
            planCurves(pl, l, m, t, f, c, x.subcaption, need);
            y = c.r.bottom() + x.axisRow + x.gap;
        }
        bool masked = m.hidden.any();
        y = placeBlock(pl, x.result, x0, y, width, masked ? FontFace::Sans : FontFace::Mono,
                       masked ? "masked" : "formula", x.gap);
        pl.plan.formulaWhole = !masked;
    }
    planLegend(pl, l, m, need, t, margin, std::max(y, bottom - legendH));
}

}  // namespace

void planMomentInspector(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                         const TypeSizes& t) {
    const Trace& tr = *m.trace;
    float margin = inspectorMargin(l);
    float width = l.inspector.w - 2.0f * margin;
    Header header = headerOf(tr, t, width);
    planHeader(pl, l, header, t, margin, tr, m.hidden);
    float top = l.inspector.y + margin + header.height + t.label * 0.5f;
    float bottom = l.inspector.bottom() - margin;
    // Bins about a label's size wide; the figure's numbers for this width.
    float indent = measureText(FontFace::Mono, t.label, "1").x + 8.0f;
    int bins =
        std::clamp(static_cast<int>((width - indent) / std::max(6.0f, t.label * 0.7f)), 8, 40);
    MomentFigure f = momentFigure(tr, bins);
    MomentTexts x = momentTexts(m, t, f, width);
    MomentRoom room = momentRoom(x, t, !f.curves.empty());
    FramePlan scratch;
    Planner sp{scratch};
    float legendH =
        planLegend(sp, l, m, figureNeeds(tr, f, pl.plan.footprintShown), t, margin, 0.0f);
    float plots = (room.curves ? 2.0f : 1.0f) * room.minPlot;
    bool onePage = bottom - top - legendH - room.fixed0 - room.fixed1 >= plots;
    int parts = onePage ? 1 : 2;
    pl.plan.textPages = std::max(pl.plan.textPages, parts);
    pl.plan.inspectorParts = parts;
    int part = std::clamp(m.textPage, 0, parts - 1);
    float noteH = part + 1 < parts ? lineHeightOf(t.label) + t.label * 0.5f : 0.0f;
    planMomentPart(pl, l, m, t, f, x, room, parts, part, top, bottom - noteH);
    pl.plan.moments = f;
    if (part + 1 < parts) {
        planNextPageNote(pl, l, m, t, margin, bottom - noteH + t.label * 0.5f,
                         room.curves ? "the bound over depth" : "the reconstruction's numbers");
    }
}

}  // namespace pcf::inspector_detail
