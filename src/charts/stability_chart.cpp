#include "charts/stability_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "charts/chart_axes.h"
#include "charts/speed_chart.h"
#include "draw/canvas.h"
#include "draw/text_layout.h"
#include "kernel/methods.h"
#include "render/gl_objects.h"

namespace pcf {

namespace {

float scaleFor(glm::ivec2 size) {
    return std::clamp(std::min(size.x / 1280.0f, size.y / 720.0f), 0.35f, 4.0f);
}

// The next tick step up from `step` (0.2 -> 0.25 -> 0.5 -> 1, or the next round one): where the
// plot is too short for labels a line apart.
double widerTickStep(double step) {
    if (std::abs(step - 0.2) < 1e-9) return 0.25;
    return chartNiceStep(step * 1.5);
}

// A type size at scale s, not below minPx (the chart's floor: 8, or a lesson frame's).
float px(float base, float s, float minPx) { return std::max(minPx, std::round(base * s)); }

// The width the y axis's tick labels need left of the plot: "100%", or a log axis's floor
// ("<=0.1%") where that is wider.
float yTickRoom(float s, float tickFont, const std::string& widest) {
    float w = std::max(measureText(FontFace::Sans, tickFont, "100%").x,
                       measureText(FontFace::Sans, tickFont, widest).x);
    return std::round(w + 10.0f * s + 4.0f);
}

// Draws on a Canvas, or (no canvas) only records where each text goes: one code path lays out
// and draws a chart, so the boxes a lesson frame lists are where the texts are drawn.
class Painter {
  public:
    Painter(Canvas* canvas, std::vector<ChartTextBox>* texts) : mCanvas(canvas), mTexts(texts) {}
    // The rect Canvas::text covers (its rounding and alignment), recorded under `role`.
    Rect text(glm::vec2 pos, const std::string& words, const TextStyle& style,
              const std::string& role) {
        glm::vec2 size = measureText(style.face, style.pixelSize, words);
        float x = static_cast<float>(std::lround(pos.x));
        if (style.align == TextAlign::Center) x -= static_cast<float>(std::lround(0.5f * size.x));
        if (style.align == TextAlign::Right) x -= static_cast<float>(std::lround(size.x));
        Rect r{x, static_cast<float>(std::lround(pos.y)), size.x, size.y};
        if (mTexts) mTexts->push_back({r, style.pixelSize, role, words});
        if (mCanvas) mCanvas->text(pos, words, style);
        return r;
    }
    // Records the box a legend entry's mark covers with its clearance (role "chart-swatch",
    // named by the entry's words): the layout checks keep it off every text, its own words too.
    void swatch(const Rect& r, const std::string& entry) {
        if (mTexts)
            mTexts->push_back({r.expanded(CHART_MARK_CLEARANCE), 0.0f, "chart-swatch", entry});
    }
    void line(glm::vec2 a, glm::vec2 b, float w, const Colour& c) {
        if (mCanvas) mCanvas->line(a, b, w, c);
    }
    void circle(glm::vec2 p, float r, const Colour& c) {
        if (mCanvas) mCanvas->circle(p, r, c);
    }
    void fillRect(const Rect& r, const Colour& c) {
        if (mCanvas) mCanvas->fillRect(r, c);
    }
    void strokeRect(const Rect& r, float w, const Colour& c) {
        if (mCanvas) mCanvas->strokeRect(r, w, c);
    }
    void image(glm::ivec2 topLeft, std::shared_ptr<const CanvasImage> img) {
        if (mCanvas) mCanvas->image(topLeft, std::move(img));
    }
    void pushClip(const Rect& r) {
        if (mCanvas) mCanvas->pushClip(r);
    }
    void popClip() {
        if (mCanvas) mCanvas->popClip();
    }

  private:
    Canvas* mCanvas;
    std::vector<ChartTextBox>* mTexts;
};

// `text`'s lines each wrapped to maxWidth, joined by '\n'.
std::string wrapLines(const std::string& text, float font, float maxWidth) {
    std::string out;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        for (const std::string& line :
             wrapText(FontFace::Sans, font, text.substr(start, end - start), maxWidth)) {
            out += (out.empty() ? "" : "\n") + line;
        }
        start = end + 1;
    }
    return out;
}

// Title and subtitle at the top, each wrapped to the chart's width; returns the y below them.
float drawHeader(Painter& c, float s, float minPx, float width, const std::string& title,
                 const std::string& subtitle) {
    float pad = std::round(12.0f * s);
    float titlePx = std::max(px(20, s, minPx), std::round(minPx * 1.25f));
    float subPx = px(13, s, minPx);
    Rect t = c.text({pad, pad * 0.6f}, wrapLines(title, titlePx, width - 2.0f * pad),
                    {FontFace::Sans, titlePx, CHART_INK}, "chart-title");
    Rect sub = c.text({pad, t.bottom()}, wrapLines(subtitle, subPx, width - 2.0f * pad),
                      {FontFace::Sans, subPx, CHART_SOFT_INK}, "chart-subtitle");
    return sub.bottom() + 6.0f * s;
}

struct LegendEntry {
    std::string label;
    Colour colour;
    bool dashed;
};

void dashedLine(Painter& c, glm::vec2 a, glm::vec2 b, float width, const Colour& colour,
                float dash) {
    float len = glm::length(b - a);
    if (len <= 0.0f) return;
    glm::vec2 d = (b - a) / len;
    for (float t = 0.0f; t < len; t += 2.0f * dash) {
        c.line(a + d * t, a + d * std::min(t + dash, len), width, colour);
    }
}

}  // namespace

glm::vec4 biasColour(std::string_view bias) {
    // One colour per bias name of docs/methods.md, "Bias modes" (Okabe-Ito, readable on white).
    static const std::pair<std::string_view, glm::vec4> COLOURS[] = {
        {"none", {0.84f, 0.37f, 0.0f, 1.0f}},
        {"constant", {0.0f, 0.45f, 0.70f, 1.0f}},
        {"slope", {0.0f, 0.62f, 0.45f, 1.0f}},
        {"normal", {0.80f, 0.47f, 0.65f, 1.0f}},
        {"receiver-plane", {0.34f, 0.71f, 0.91f, 1.0f}},
        {"soft", {0.90f, 0.62f, 0.0f, 1.0f}},
        {"interpolated", {0.35f, 0.35f, 0.35f, 1.0f}},
    };
    for (const auto& [name, colour] : COLOURS) {
        if (name == bias) return colour;
    }
    return CHART_INK;
}

namespace {

struct LineAxes {
    double xLo, xHi;     // the x range (log10 with logX) shared by all panels
    double yStep, yTop;  // the y tick step and the axis's top (its bottom: spec.yFloor); with
                         // logY both in decades (log10): a tick per decade up to 10^yTop
};

// With logY: the y of a value on the axis, log10 and never under the floor's.
double logAxisY(const LineChartSpec& spec, double y) {
    return std::log10(std::max(y, spec.yFloor));
}

// The y tick labels, bottom up: their values and texts. A log axis labels its floor "<=" (every
// value under it lies there, 0 too) and each decade above.
std::vector<std::pair<double, std::string>> yTickLabels(const LineChartSpec& spec,
                                                        const LineAxes& axes, double yStep) {
    std::vector<std::pair<double, std::string>> out;
    if (spec.logY) {
        double lo = logAxisY(spec, spec.yFloor);
        for (double d = lo; d <= axes.yTop + 1e-9; d += yStep) {
            double v = std::pow(10.0, d);
            std::string t = chartTickText(v, spec.percentY);
            out.emplace_back(v, d == lo ? "<=" + t : t);
        }
        return out;
    }
    for (double y = spec.yFloor; y <= axes.yTop + 0.5 * yStep; y += yStep) {
        out.emplace_back(y, chartTickText(y, spec.percentY));
    }
    return out;
}

// Axis ranges shared by all panels: x over every point, y from the floor up past the largest
// value in round steps (a share ends at exactly 100 %).
LineAxes lineAxesOf(const LineChartSpec& spec) {
    double xLo = 1e300, xHi = -1e300, yHi = spec.yFloor;
    for (const ChartPanel& p : spec.panels) {
        for (const ChartLine& l : p.lines) {
            for (glm::dvec2 q : l.points) {
                double x = spec.logX ? std::log10(std::max(q.x, 1e-12)) : q.x;
                xLo = std::min(xLo, x);
                xHi = std::max(xHi, x);
                yHi = std::max(yHi, q.y);
            }
        }
    }
    if (xLo > xHi) xLo = 0.0, xHi = 1.0;
    if (xHi - xLo < 1e-9) xLo -= 0.5, xHi += 0.5;
    if (spec.logY) {
        // Decades from the floor to the one at or above the largest value (a share: 100 %).
        double top = std::ceil(logAxisY(spec, yHi) - 1e-9);
        if (spec.percentY && yHi <= 1.0) top = 0.0;
        return {xLo, xHi, 1.0, std::max(top, logAxisY(spec, spec.yFloor) + 1.0)};
    }
    double yStep = chartNiceStep(std::max(yHi - spec.yFloor, 1e-6) * 1.05 / 5.0);
    double yTop =
        spec.yFloor + std::ceil((std::max(yHi - spec.yFloor, 1e-6) * 1.05) / yStep) * yStep;
    if (spec.percentY && yHi <= 1.0 && (yTop > 1.0 || yHi > 0.5)) {
        yStep = 0.2;  // a share never passes 100 %: ticks of 20 % up to exactly 100 %
        yTop = 1.0;
    }
    return {xLo, xHi, yStep, yTop};
}

// One legend entry per line label, in order of first appearance over the panels.
std::vector<LegendEntry> lineLegendOf(const LineChartSpec& spec) {
    std::vector<LegendEntry> legend;
    for (const ChartPanel& p : spec.panels) {
        for (const ChartLine& l : p.lines) {
            bool seen = false;
            for (const LegendEntry& e : legend) seen = seen || e.label == l.label;
            if (!seen) legend.push_back({l.label, l.colour, l.dashed});
        }
    }
    return legend;
}

// One panel's plot and the maps from its data to pixels.
struct PanelPlot {
    const LineChartSpec& spec;
    const LineAxes& axes;
    Rect plot;
    float xPixel(double x) const {
        double v = spec.logX ? std::log10(std::max(x, 1e-12)) : x;
        double t = (v - axes.xLo) / (axes.xHi - axes.xLo);
        if (spec.reverseX) t = 1.0 - t;
        return plot.x + static_cast<float>(t) * plot.w;
    }
    float yPixel(double y) const {
        if (spec.logY) {
            double lo = logAxisY(spec, spec.yFloor);
            return plot.bottom() -
                   static_cast<float>((logAxisY(spec, y) - lo) / (axes.yTop - lo)) * plot.h;
        }
        return plot.bottom() -
               static_cast<float>((y - spec.yFloor) / (axes.yTop - spec.yFloor)) * plot.h;
    }
};

// A panel's grid lines and tick labels: y at the round steps, x at the points' own x values
// (sweeps are few points), thinned to fit.
void paintPanelGrid(Painter& c, const PanelPlot& pp, const ChartPanel& panel, float s,
                    float tickFont) {
    const Rect& plot = pp.plot;
    const LineChartSpec& spec = pp.spec;
    float tickH = fontMetrics(FontFace::Sans, tickFont).lineHeight;
    float stroke = std::max(1.0f, std::round(s));
    // Fewer ticks where the panel is short: no two labels closer than a line (a log axis: every
    // second decade, then every third).
    double yStep = pp.axes.yStep;
    double range = pp.axes.yTop - (spec.logY ? logAxisY(spec, spec.yFloor) : spec.yFloor);
    while (plot.h * yStep / range < tickH + 1.0f && yStep < range) {
        yStep = spec.logY ? yStep + 1.0 : widerTickStep(yStep);
    }
    for (const auto& [y, label] : yTickLabels(spec, pp.axes, yStep)) {
        float py = std::round(pp.yPixel(y)) + 0.5f;
        c.line({plot.x, py}, {plot.right(), py}, stroke, CHART_GRID);
        c.text({plot.x - 5.0f * s, py - tickH / 2}, label,
               {FontFace::Sans, tickFont, CHART_SOFT_INK, TextAlign::Right}, "chart-tick");
    }
    std::vector<double> xs;
    for (const ChartLine& l : panel.lines) {
        for (glm::dvec2 q : l.points) {
            if (std::find(xs.begin(), xs.end(), q.x) == xs.end()) xs.push_back(q.x);
        }
    }
    std::sort(xs.begin(), xs.end(),
              [&](double a, double b) { return pp.xPixel(a) < pp.xPixel(b); });
    float lastRight = -1e30f;
    for (double x : xs) {
        float pxX = std::round(pp.xPixel(x)) + 0.5f;
        c.line({pxX, plot.y}, {pxX, plot.bottom()}, stroke, CHART_GRID);
        std::string t = chartTickText(x, false);
        float w = measureText(FontFace::Sans, tickFont, t).x;
        if (pxX - w / 2 - 4.0f * s > lastRight) {
            // Half a line lower than the plot: the lowest y tick's label reaches there.
            c.text({pxX, plot.bottom() + 0.5f * tickH + 3.0f * s}, t,
                   {FontFace::Sans, tickFont, CHART_SOFT_INK, TextAlign::Center}, "chart-tick");
            lastRight = pxX + w / 2;
        }
    }
    c.strokeRect(plot.expanded(stroke), stroke, CHART_SOFT_INK);
}

// A panel's lines (solid or dashed) with a dot at each point, clipped near the plot.
void paintPanelLines(Painter& c, const PanelPlot& pp, const ChartPanel& panel, float s, float lw) {
    c.pushClip(pp.plot.expanded(3.0f * s));
    for (const ChartLine& l : panel.lines) {
        glm::vec2 prev{};
        for (size_t i = 0; i < l.points.size(); ++i) {
            glm::vec2 p{pp.xPixel(l.points[i].x), pp.yPixel(l.points[i].y) + l.offsetPx * s};
            if (i > 0) {
                if (l.dashed) {
                    dashedLine(c, prev, p, lw, l.colour, 5.0f * s);
                } else {
                    c.line(prev, p, lw, l.colour);
                }
            }
            c.circle(p, 3.0f * s, l.colour);
            prev = p;
        }
    }
    c.popClip();
}

// One panel in its cell: its title, grid, ticks and lines (nothing where the cell is too small).
void paintPanel(Painter& c, const LineChartSpec& spec, const LineAxes& axes,
                const ChartPanel& panel, Rect cell, float s, float lw) {
    float mn = spec.minFontPx;
    float tickFont = px(12, s, mn);
    float tickH = fontMetrics(FontFace::Sans, tickFont).lineHeight;
    float titleH = fontMetrics(FontFace::Sans, px(14, s, mn)).lineHeight;
    std::string floorTick = spec.logY ? yTickLabels(spec, axes, axes.yStep).front().second : "";
    float left = std::max(58.0f * s, yTickRoom(s, tickFont, floorTick));
    // The top tick's label reaches half a line above the plot: the panel's title stays clear.
    float titleRoom = titleH + std::max(4.0f * s, 0.5f * tickH + 2.0f);
    Rect plot{std::round(cell.x + left), std::round(cell.y + titleRoom),
              std::round(cell.w - left - 12.0f * s),
              std::round(cell.h - titleRoom - 1.5f * tickH - 14.0f * s)};
    if (plot.w < 8.0f || plot.h < 8.0f) return;
    // Centred over the plot, moved in so it stays inside its cell (a long title on a small
    // chart ran under the legend beside the cell).
    float titleW = measureText(FontFace::Sans, px(14, s, mn), panel.title).x;
    float titleX = std::clamp(plot.centre().x, cell.x + 0.5f * titleW,
                              std::max(cell.x + 0.5f * titleW, cell.right() - 0.5f * titleW));
    c.text({titleX, cell.y}, panel.title,
           {FontFace::Sans, px(14, s, mn), CHART_INK, TextAlign::Center}, "chart-title");
    PanelPlot pp{spec, axes, plot};
    if (panel.band) {
        float a = pp.xPixel(panel.band->x), b = pp.xPixel(panel.band->y);
        float lo = std::min(a, b), hi = std::max(a, b), minW = 8.0f * s;
        if (hi - lo < minW) {
            lo -= 0.5f * (minW - (hi - lo));
            hi = lo + minW;
        }
        c.fillRect({lo, plot.y, hi - lo, plot.h}, CHART_BAND);
    }
    paintPanelGrid(c, pp, panel, s, tickFont);
    paintPanelLines(c, pp, panel, s, lw);
}

// The legend box at the chart's right: a line sample and the label per entry, then the notes.
void paintLineLegend(Painter& c, const LineChartSpec& spec, const std::vector<LegendEntry>& legend,
                     Rect box, float s, float lw, float legendFont) {
    float lineH = fontMetrics(FontFace::Sans, legendFont).lineHeight;
    float stroke = std::max(1.0f, std::round(s));
    c.fillRect(box, {0.97f, 0.97f, 0.98f, 1.0f});
    c.strokeRect(box, stroke, CHART_GRID);
    float y = box.y + 6.0f * s;
    for (const LegendEntry& e : legend) {
        glm::vec2 a{box.x + 8.0f * s, y + lineH / 2}, b{box.x + 32.0f * s, y + lineH / 2};
        if (e.dashed) {
            dashedLine(c, a, b, lw, e.colour, 5.0f * s);
        } else {
            c.line(a, b, lw, e.colour);
        }
        c.swatch({a.x, a.y - 0.5f * lw, b.x - a.x, lw}, e.label);
        c.text({box.x + 38.0f * s, y}, e.label, {FontFace::Sans, legendFont, CHART_INK},
               "chart-legend");
        y += lineH;
    }
    for (const std::string& note : spec.notes) {
        c.text({box.x + 8.0f * s, y}, note, {FontFace::Sans, legendFont, CHART_SOFT_INK},
               "chart-legend");
        y += lineH;
    }
}

void paintLineChart(const LineChartSpec& spec, glm::ivec2 size, Painter& c) {
    if (size.x < 64 || size.y < 64) {
        throw std::invalid_argument("drawLineChart: the chart needs at least 64 x 64 pixels");
    }
    if (spec.panels.empty()) throw std::invalid_argument("drawLineChart: no panel");
    float s = scaleFor(size);
    float mn = spec.minFontPx;
    // Lines as heavy as the type asks (a projector's 18 px text wants lines over 2 px).
    float lw = std::max(2.0f * s, mn * 0.14f);
    LineAxes axes = lineAxesOf(spec);
    std::vector<LegendEntry> legend = lineLegendOf(spec);

    float top = drawHeader(c, s, mn, static_cast<float>(size.x), spec.title, spec.subtitle);
    float legendFont = px(13, s, mn), axisFont = px(14, s, mn);
    float lineH = fontMetrics(FontFace::Sans, legendFont).lineHeight;
    float legendW = 0.0f;
    for (const LegendEntry& e : legend) {
        legendW = std::max(legendW, measureText(FontFace::Sans, legendFont, e.label).x);
    }
    for (const std::string& n : spec.notes) {
        legendW = std::max(legendW, measureText(FontFace::Sans, legendFont, n).x);
    }
    legendW = std::round(legendW + 48.0f * s);
    Rect yName = c.text({12.0f * s, top}, wrapLines(spec.yLabel, axisFont, size.x - 24.0f * s),
                        {FontFace::Sans, axisFont, CHART_INK}, "chart-axis");
    top = yName.bottom() + 4.0f * s;
    float areaW = size.x - legendW - 20.0f * s;
    std::string xName = wrapLines(spec.xLabel, axisFont, areaW - 8.0f * s);
    float bottomText = measureText(FontFace::Sans, axisFont, xName).y + 6.0f * s;
    Rect area{0.0f, top, areaW, size.y - top - bottomText};
    c.text({area.centre().x, area.bottom() + 2.0f * s}, xName,
           {FontFace::Sans, axisFont, CHART_INK, TextAlign::Center}, "chart-axis");

    // The panels in a grid of cells: one row of up to two, then two or three columns.
    int n = static_cast<int>(spec.panels.size());
    int cols = n <= 2 ? n : (n <= 4 ? 2 : 3);
    int rowsN = (n + cols - 1) / cols;
    float cellW = area.w / cols, cellH = area.h / rowsN;
    for (int k = 0; k < n; ++k) {
        Rect cell{area.x + (k % cols) * cellW, area.y + (k / cols) * cellH, cellW, cellH};
        paintPanel(c, spec, axes, spec.panels[k], cell, s, lw);
    }

    Rect box{size.x - legendW - 12.0f * s, top, legendW,
             (legend.size() + spec.notes.size()) * lineH + 12.0f * s};
    paintLineLegend(c, spec, legend, box, s, lw, legendFont);
}

}  // namespace

std::vector<uint8_t> drawLineChart(const LineChartSpec& spec, glm::ivec2 size) {
    lineChartTextBoxes(spec, size);  // throws for a bad size or spec before any GL work
    return drawChartOffscreen(size, [&](Canvas& canvas) {
        Painter painter(&canvas, nullptr);
        paintLineChart(spec, size, painter);
    });
}

std::vector<ChartTextBox> lineChartTextBoxes(const LineChartSpec& spec, glm::ivec2 size) {
    std::vector<ChartTextBox> out;
    Painter painter(nullptr, &out);
    paintLineChart(spec, size, painter);
    return out;
}

namespace {

const Colour BAR_SERIES[] = {{0.0f, 0.45f, 0.70f, 1.0f},
                             {0.55f, 0.55f, 0.58f, 1.0f},
                             {0.84f, 0.37f, 0.0f, 1.0f},
                             {0.0f, 0.62f, 0.45f, 1.0f}};

struct BarAxis {
    double yStep, yTop;
};

// The y axis: 0 up past the largest value in round steps (ending at exactly 1 for changes of
// visibility, which never pass it).
BarAxis barAxisOf(const BarChartSpec& spec) {
    double yMax = 0.0;
    for (const BarGroup& g : spec.groups) {
        for (double v : g.values) yMax = std::max(yMax, v);
    }
    double yStep = chartNiceStep(std::max(yMax, 1e-6) * 1.1 / 5.0);
    double yTop = std::ceil(std::max(yMax, 1e-6) * 1.1 / yStep) * yStep;
    if (yMax > 0.5 && yMax <= 1.0) {
        yStep = 0.2;  // changes of visibility never pass 1
        yTop = 1.0;
    }
    return {yStep, yTop};
}

// The width of the widest line of t.
float widestLine(const std::string& t, float font) {
    float w = 0.0f;
    size_t start = 0;
    while (true) {
        size_t end = t.find('\n', start);
        w = std::max(w, measureText(FontFace::Sans, font,
                                    t.substr(start, end == std::string::npos ? std::string::npos
                                                                             : end - start))
                            .x);
        if (end == std::string::npos) return w;
        start = end + 1;
    }
}

struct BarLabels {
    std::vector<std::string> texts;  // per group, with '\n' between its lines
    int lines = 1;                   // the most lines a label has
    int rows = 1;                    // group g's label goes in row g % rows
};

// The groups' labels for groups groupW wide. On two lines when the group is narrow: "method" /
// "bias"; a word a line when even that is too wide ("pcf-gather" / "5x5" / "none" in large
// type); and when a word is wider than its group, every other label one block lower, so that
// each may take the width of two groups.
BarLabels barLabelsFor(const BarChartSpec& spec, float groupW, float s, float tickFont) {
    BarLabels out;
    bool stagger = false;
    for (float room : {groupW - 4.0f * s, 2.0f * groupW - 8.0f * s}) {
        out.texts.clear();
        out.lines = 1;
        bool fitsAll = true;
        for (const BarGroup& group : spec.groups) {
            std::string label = group.label;
            if (widestLine(label, tickFont) > room) {
                size_t space = label.rfind(' ');
                if (space != std::string::npos) label[space] = '\n';
            }
            if (widestLine(label, tickFont) > room) {
                std::replace(label.begin(), label.end(), ' ', '\n');
            }
            fitsAll = fitsAll && widestLine(label, tickFont) <= room;
            out.lines = std::max(
                out.lines, 1 + static_cast<int>(std::count(label.begin(), label.end(), '\n')));
            out.texts.push_back(label);
        }
        if (fitsAll) break;
        stagger = true;
    }
    // Rows of labels: the fewest in which no label reaches the next one of its row (a word
    // wider than two groups needs a third row).
    const std::vector<std::string>& labels = out.texts;
    int rows = 1;
    for (; rows < 4; ++rows) {
        bool clear = true;
        for (size_t g = 0; g + rows < labels.size(); ++g) {
            float gap = groupW * static_cast<float>(rows);
            clear =
                clear &&
                (widestLine(labels[g], tickFont) + widestLine(labels[g + rows], tickFont)) * 0.5f +
                        4.0f * s <=
                    gap;
        }
        if (clear) break;
    }
    if (stagger) rows = std::max(rows, 2);
    out.rows = rows;
    return out;
}

// The bars of each group, the series side by side, with the group's label below the plot.
void paintBars(Painter& c, const BarChartSpec& spec, const Rect& plot, double yTop,
               const BarLabels& labels, float labelsTop, float s, float tickFont) {
    float tickH = fontMetrics(FontFace::Sans, tickFont).lineHeight;
    float stroke = std::max(1.0f, std::round(s));
    size_t groups = std::max<size_t>(spec.groups.size(), 1);
    float groupW = plot.w / groups;
    size_t bars = std::max<size_t>(spec.series.size(), 1);
    float barW = std::max(2.0f, std::floor(groupW * 0.8f / bars));
    for (size_t g = 0; g < spec.groups.size(); ++g) {
        const BarGroup& group = spec.groups[g];
        float x0 = plot.x + g * groupW + (groupW - barW * bars) / 2;
        for (size_t b = 0; b < group.values.size() && b < bars; ++b) {
            float y = plot.bottom() - static_cast<float>(group.values[b] / yTop) * plot.h;
            float left = std::round(x0 + b * barW);
            if (group.values[b] == 0.0) {
                // A bar of height 0 draws nothing: a stub on the axis and a "0" over it say that
                // the series was measured here and is zero (the snapped shimmer, all 0).
                c.fillRect({left, plot.bottom() - 2 * stroke, barW - stroke, 2 * stroke},
                           BAR_SERIES[b % 4]);
                c.text({left + (barW - stroke) / 2, plot.bottom() - 2 * stroke - tickH}, "0",
                       {FontFace::Sans, tickFont, BAR_SERIES[b % 4], TextAlign::Center},
                       "chart-value");
                continue;
            }
            c.fillRect({left, std::round(y), barW - stroke, std::round(plot.bottom() - y)},
                       BAR_SERIES[b % 4]);
        }
        float below = static_cast<float>(static_cast<int>(g) % labels.rows * labels.lines) * tickH;
        c.text({plot.x + (g + 0.5f) * groupW, plot.bottom() + labelsTop + below}, labels.texts[g],
               {FontFace::Sans, tickFont, CHART_INK, TextAlign::Center}, "chart-label");
    }
}

// The legend box: a swatch and the name per series.
void paintBarLegend(Painter& c, const BarChartSpec& spec, const Rect& box, float s,
                    float legendFont) {
    float lineH = fontMetrics(FontFace::Sans, legendFont).lineHeight;
    float stroke = std::max(1.0f, std::round(s));
    c.fillRect(box, {0.97f, 0.97f, 0.98f, 1.0f});
    c.strokeRect(box, stroke, CHART_GRID);
    float y = box.y + 6.0f * s;
    for (size_t b = 0; b < spec.series.size(); ++b) {
        Rect mark{box.x + 8.0f * s, y + 2.0f * s, 22.0f * s, lineH - 4.0f * s};
        c.fillRect(mark, BAR_SERIES[b % 4]);
        c.swatch(mark, spec.series[b]);
        c.text({box.x + 36.0f * s, y}, spec.series[b], {FontFace::Sans, legendFont, CHART_INK},
               "chart-legend");
        y += lineH;
    }
}

void paintBarChart(const BarChartSpec& spec, glm::ivec2 size, Painter& c) {
    if (size.x < 64 || size.y < 64) {
        throw std::invalid_argument("drawBarChart: the chart needs at least 64 x 64 pixels");
    }
    float s = scaleFor(size);
    float mn = spec.minFontPx;
    BarAxis axis = barAxisOf(spec);
    float top = drawHeader(c, s, mn, static_cast<float>(size.x), spec.title, spec.subtitle);
    float tickFont = px(12, s, mn), axisFont = px(14, s, mn), legendFont = px(13, s, mn);
    Rect yName = c.text({12.0f * s, top}, wrapLines(spec.yLabel, axisFont, size.x - 24.0f * s),
                        {FontFace::Sans, axisFont, CHART_INK}, "chart-axis");
    top = yName.bottom() + 4.0f * s;
    float tickH = fontMetrics(FontFace::Sans, tickFont).lineHeight;
    float lineH = fontMetrics(FontFace::Sans, legendFont).lineHeight;
    float legendW = 0.0f;
    for (const std::string& n : spec.series) {
        legendW = std::max(legendW, measureText(FontFace::Sans, legendFont, n).x);
    }
    legendW = std::round(legendW + 40.0f * s);
    top += tickH / 2;  // room for the top tick's label
    float left = std::max(62.0f * s, yTickRoom(s, tickFont, ""));
    float plotW = std::round(size.x - legendW - left - 28.0f * s);
    size_t groups = std::max<size_t>(spec.groups.size(), 1);
    BarLabels labels = barLabelsFor(spec, plotW / groups, s, tickFont);
    // The labels start half a tick line below the plot: the "0" tick's label reaches there.
    float labelsTop = tickH * 0.5f + 4.0f * s;
    float labelsH = labelsTop + std::max(2, labels.rows * labels.lines) * tickH;
    Rect plot{std::round(left), std::round(top), plotW,
              std::round(size.y - top - labelsH - 16.0f * s)};
    float stroke = std::max(1.0f, std::round(s));
    // Fewer ticks where the plot is short: no two labels closer than a line.
    while (plot.h * axis.yStep / axis.yTop < tickH + 1.0f && axis.yStep < axis.yTop) {
        axis.yStep = widerTickStep(axis.yStep);
    }
    for (double y = 0.0; y <= axis.yTop + 0.5 * axis.yStep; y += axis.yStep) {
        float py = std::round(plot.bottom() - static_cast<float>(y / axis.yTop) * plot.h) + 0.5f;
        c.line({plot.x, py}, {plot.right(), py}, stroke, CHART_GRID);
        c.text({plot.x - 5.0f * s, py - tickH / 2}, chartTickText(y, false),
               {FontFace::Sans, tickFont, CHART_SOFT_INK, TextAlign::Right}, "chart-tick");
    }
    paintBars(c, spec, plot, axis.yTop, labels, labelsTop, s, tickFont);
    c.strokeRect(plot.expanded(stroke), stroke, CHART_SOFT_INK);
    Rect box{size.x - legendW - 12.0f * s, plot.y, legendW, spec.series.size() * lineH + 12.0f * s};
    paintBarLegend(c, spec, box, s, legendFont);
}

}  // namespace

std::vector<uint8_t> drawBarChart(const BarChartSpec& spec, glm::ivec2 size) {
    barChartTextBoxes(spec, size);  // throws for a bad size or spec before any GL work
    return drawChartOffscreen(size, [&](Canvas& canvas) {
        Painter painter(&canvas, nullptr);
        paintBarChart(spec, size, painter);
    });
}

std::vector<ChartTextBox> barChartTextBoxes(const BarChartSpec& spec, glm::ivec2 size) {
    std::vector<ChartTextBox> out;
    Painter painter(nullptr, &out);
    paintBarChart(spec, size, painter);
    return out;
}

namespace {

// The image resampled (nearest pixel) to `size`, as the canvas takes it.
std::shared_ptr<const CanvasImage> scaledImage(const ImageChartSpec& spec, glm::ivec2 size) {
    std::vector<glm::vec4> pixels(static_cast<size_t>(size.x) * size.y);
    for (int y = 0; y < size.y; ++y) {
        int sy = std::min(spec.imageSize.y - 1, y * spec.imageSize.y / size.y);
        for (int x = 0; x < size.x; ++x) {
            int sx = std::min(spec.imageSize.x - 1, x * spec.imageSize.x / size.x);
            const uint8_t* p = &spec.rgba[(static_cast<size_t>(sy) * spec.imageSize.x + sx) * 4];
            pixels[static_cast<size_t>(y) * size.x + x] =
                glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
        }
    }
    return std::make_shared<const CanvasImage>(size, std::move(pixels));
}

// The colour bar, its ticks and label in `box` (label on top, swatches at the bottom).
void paintColourScale(Painter& c, const ColourScale& scale, Rect box, float s, float font) {
    float lineH = fontMetrics(FontFace::Sans, font).lineHeight;
    Rect label =
        c.text({box.x, box.y}, scale.label, {FontFace::Sans, font, CHART_INK}, "chart-legend");
    float barTop = label.bottom() + lineH * 0.5f + 4.0f * s;
    float barBottom = box.bottom() - (scale.swatches.size() + 0.5f) * lineH - 8.0f * s;
    Rect bar{box.x, std::round(barTop), std::round(24.0f * s), std::round(barBottom - barTop)};
    size_t n = scale.colours.size();
    for (size_t i = 0; i < n; ++i) {
        float y0 = bar.bottom() - bar.h * static_cast<float>(i + 1) / n;
        float y1 = bar.bottom() - bar.h * static_cast<float>(i) / n;
        c.fillRect({bar.x, std::floor(y0), bar.w, std::ceil(y1) - std::floor(y0)},
                   scale.colours[i]);
    }
    float stroke = std::max(1.0f, std::round(s));
    c.strokeRect(bar.expanded(stroke), stroke, CHART_SOFT_INK);
    for (const auto& [t, words] : scale.ticks) {
        float y = std::round(bar.bottom() - static_cast<float>(t) * bar.h) + 0.5f;
        c.line({bar.right(), y}, {bar.right() + 6.0f * s, y}, stroke, CHART_SOFT_INK);
        c.text({bar.right() + 9.0f * s, y - lineH / 2}, words, {FontFace::Sans, font, CHART_INK},
               "chart-legend");
    }
    float y = bar.bottom() + lineH * 0.5f + 8.0f * s;
    for (const auto& [colour, words] : scale.swatches) {
        Rect mark{bar.x, y + 2.0f * s, bar.w, lineH - 4.0f * s};
        c.fillRect(mark, colour);
        c.swatch(mark, words);
        c.text({bar.right() + 9.0f * s, y}, words, {FontFace::Sans, font, CHART_INK},
               "chart-legend");
        y += lineH;
    }
}

void paintImageChart(const ImageChartSpec& spec, glm::ivec2 size, Painter& c) {
    if (size.x < 64 || size.y < 64) {
        throw std::invalid_argument("drawImageChart: the chart needs at least 64 x 64 pixels");
    }
    if (spec.imageSize.x < 1 || spec.imageSize.y < 1 ||
        spec.rgba.size() != static_cast<size_t>(spec.imageSize.x) * spec.imageSize.y * 4) {
        throw std::invalid_argument("drawImageChart: the image's pixels do not match its size");
    }
    float s = scaleFor(size);
    float mn = spec.minFontPx;
    float top = drawHeader(c, s, mn, static_cast<float>(size.x), spec.title, spec.subtitle);
    float font = px(13, s, mn), pad = std::round(12.0f * s);
    float scaleW = 0.0f;
    for (const auto& [t, words] : spec.scale.ticks) {
        scaleW = std::max(scaleW, measureText(FontFace::Sans, font, words).x);
    }
    for (const auto& [colour, words] : spec.scale.swatches) {
        scaleW = std::max(scaleW, measureText(FontFace::Sans, font, words).x);
    }
    scaleW = std::max(scaleW + 33.0f * s, measureText(FontFace::Sans, font, spec.scale.label).x);
    Rect area{pad, top + 4.0f * s, size.x - scaleW - 3.0f * pad, size.y - top - 4.0f * s - pad};
    float f = std::min(area.w / spec.imageSize.x, area.h / spec.imageSize.y);
    glm::ivec2 shown = glm::max(glm::ivec2(1), glm::ivec2(glm::vec2(spec.imageSize) * f));
    c.image(glm::ivec2(area.x, area.y), scaledImage(spec, shown));
    Rect box{std::round(area.x + shown.x + pad * 2.0f), area.y, scaleW,
             std::min(area.h, static_cast<float>(shown.y))};
    paintColourScale(c, spec.scale, box, s, font);
}

}  // namespace

std::vector<uint8_t> drawImageChart(const ImageChartSpec& spec, glm::ivec2 size) {
    imageChartTextBoxes(spec, size);  // throws for a bad size or spec before any GL work
    return drawChartOffscreen(size, [&](Canvas& canvas) {
        Painter painter(&canvas, nullptr);
        paintImageChart(spec, size, painter);
    });
}

std::vector<ChartTextBox> imageChartTextBoxes(const ImageChartSpec& spec, glm::ivec2 size) {
    std::vector<ChartTextBox> out;
    Painter painter(nullptr, &out);
    paintImageChart(spec, size, painter);
    return out;
}

}  // namespace pcf
