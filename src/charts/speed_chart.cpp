#include "charts/speed_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "charts/chart_axes.h"
#include "charts/speed_chart_labels.h"
#include "draw/canvas.h"
#include "draw/text_layout.h"
#include "kernel/methods.h"
#include "measure/bench_report.h"
#include "measure/pareto.h"
#include "render/gl_objects.h"

namespace pcf {

namespace {

const Colour FRONT{0.05f, 0.05f, 0.05f, 1.0f};
const Colour HIGHLIGHT_RING{1.0f, 0.55f, 0.0f, 1.0f};  // round the dots a lesson step rings

struct Fonts {
    float title, subtitle, axis, tick, label, legend;
};

// The type sizes at scale s, none below minPx (the title a quarter above it).
Fonts fontsFor(float s, float minPx) {
    auto px = [&](float base) { return std::max(minPx, std::round(base * s)); };
    return {std::max(px(20.0f), std::round(minPx * 1.25f)),
            px(13.0f),
            px(14.0f),
            px(12.0f),
            px(11.0f),
            px(13.0f)};
}

double safeLog(double ms) { return std::log10(std::max(ms, 1e-6)); }

// The bar's stroke width and its end ticks' half height (drawErrorBars draws them).
float barStroke(float s) { return std::max(1.0f, 1.25f * s); }
float barTickHalf(float s) { return 3.0f * s; }

}  // namespace

std::string spreadNote() {
    return "bars: IQR of the repeated times, centred on the median; the front's line joins only "
           "dots whose bars are apart";
}

std::string speedChartXLabel(std::span<const BenchRow> rows, ChartTiming timing) {
    bool cpu = !rows.empty() && std::all_of(rows.begin(), rows.end(), benchTimesByCpu);
    std::string pass =
        timing == ChartTiming::Lookup ? "filter time: bare lookup pass" : "camera pass";
    return pass + (cpu ? ", process CPU time" : ", time") + ", ms (log scale)";
}

std::string speedChartRenderer(std::span<const BenchRow> rows) {
    for (const BenchRow& r : rows) {
        if (!r.glRenderer.empty()) return r.glRenderer;
    }
    return "";
}

std::string speedChartTruth(std::span<const BenchRow> rows) {
    for (const BenchRow& r : rows) {
        if (!r.truth.empty()) return r.truth;
    }
    return "";
}

std::string contactAxisLabel(std::span<const BenchRow> rows, bool brief) {
    int pixels = rows.empty() ? 0 : rows.front().contact.edgePixels;
    double distance = rows.empty() ? 0.0 : rows.front().contactDistance;
    char within[64];
    std::snprintf(within, sizeof within, "within %g world unit%s of a caster", distance,
                  distance == 1.0 ? "" : "s");
    if (brief) return "edge-band RMSE " + std::string(within);
    return "aliasing near the contacts: edge-band RMSE over the " + std::to_string(pixels) +
           " edge pixels " + within;
}

SpeedChartText speedChartTextFor(std::span<const BenchRow> rows, const SpeedChartText& text,
                                 glm::ivec2 size, ChartTiming timing) {
    SpeedChartText out = text;
    bool anyBar = false;
    for (const BenchRow& r : rows) anyBar = anyBar || chartIqr(r, timing) > 0.0;
    float s = std::clamp(std::min(size.x / 1280.0f, size.y / 720.0f), 0.35f, 4.0f);
    // As speedChartTextBoxes places it: 12 px (scaled) in from the left, as much kept on the right.
    float width = std::max(16.0f, size.x - 2.0f * std::round(12.0f * s));
    out.subtitle.clear();
    std::string full = text.subtitle;
    // The bars' meaning on a line of its own: a line break never splits it from its words.
    if (anyBar) full += (full.empty() ? "" : "\n") + spreadNote();
    for (const std::string& line :
         wrapText(FontFace::Sans, fontsFor(s, text.minFontPx).subtitle, full, width)) {
        out.subtitle += (out.subtitle.empty() ? "" : "\n") + line;
    }
    return out;
}

int subtitleLineCount(const std::string& subtitle) {
    return 1 + static_cast<int>(std::count(subtitle.begin(), subtitle.end(), '\n'));
}

std::vector<size_t> chartRowsMatching(std::span<const BenchRow> rows,
                                      const std::string& selectors) {
    std::vector<bool> on(rows.size(), false);
    size_t start = 0;
    while (start <= selectors.size()) {
        size_t comma = selectors.find(',', start);
        if (comma == std::string::npos) comma = selectors.size();
        std::string sel = selectors.substr(start, comma - start);
        start = comma + 1;
        sel.erase(0, sel.find_first_not_of(' '));
        sel.erase(sel.find_last_not_of(' ') + 1);
        if (sel.empty()) continue;
        bool any = false;
        if (sel == "front") {
            for (size_t k : benchParetoFront(rows, false)) on[k] = any = true;
        } else {
            for (size_t k = 0; k < rows.size(); ++k) {
                std::string label = chartLabel(rows[k].point);
                if (label == sel || label.starts_with(sel + " ")) on[k] = any = true;
            }
        }
        if (!any) throw std::invalid_argument("'" + sel + "' names no dot of the chart");
    }
    std::vector<size_t> out;
    for (size_t k = 0; k < rows.size(); ++k) {
        if (on[k]) out.push_back(k);
    }
    return out;
}

std::string chartLabel(const BenchPoint& point) {
    std::string s(methodInfo(point.method).shortName);
    if (point.kernel > 0) s += std::to_string(point.kernel);
    if (point.weights == PCF_WEIGHTS_BINOMIAL) s += " binom";
    if (point.weights == PCF_WEIGHTS_GAUSSIAN) s += " gauss" + chartTickText(point.sigma);
    return s + " " + std::to_string(point.mapSize);
}

glm::vec4 methodColour(int method) {
    if (method < 0 || method >= PCF_METHOD_COUNT) return CHART_INK;
    return methodInfo(method).chartColour;
}

double chartMs(const BenchRow& row, ChartTiming timing) {
    return benchPassMs(row, timing == ChartTiming::Lookup);
}

double chartIqr(const BenchRow& row, ChartTiming timing) {
    return benchPassIqr(row, timing == ChartTiming::Lookup);
}

double chartAccuracy(const BenchRow& row, ChartAccuracy accuracy) {
    switch (accuracy) {
        case ChartAccuracy::Shimmer:
            return row.shimmer.flickerP99;
        case ChartAccuracy::ContactRmse:
            return row.contact.edgeRmse;
        case ChartAccuracy::EdgeRmse:
            break;
    }
    return row.error.edgeRmse;
}

namespace {

// The front's legend mark: a line of half-length frontHalfLine through a dot ringed at
// frontRingRadius with a ring frontRingWidth wide (drawLegendMarks draws it, layoutLegend makes
// room for it).
float frontHalfLine(float s) { return 8.0f * s; }
float frontRingRadius(const SpeedChartLayout& L) { return L.dotRadius + 2.5f * L.scale; }
float frontRingWidth(float s) { return std::max(1.5f, 1.5f * s); }
// The orange ring round a highlighted dot, outside the front's.
float highlightRingRadius(const SpeedChartLayout& L) { return L.dotRadius + 5.5f * L.scale; }
float highlightRingWidth(float s) { return std::max(2.5f, 3.0f * s); }

// The badges' radius: a number of as many digits as the most badges there can be, at the names'
// size, with room round it.
float badgeRadiusFor(const SpeedChartLayout& L) {
    std::string widest(std::to_string(std::max<size_t>(1, L.mustName.size())).size(), '8');
    float w = measureText(FontFace::Sans, L.labelPx, widest).x;
    return std::ceil(0.5f * std::max(w + 0.3f * L.labelPx, 1.0f * L.labelPx));
}

// A line of the key: as tall as the legend's type or a badge with its clearance.
float keyLineHeight(const SpeedChartLayout& L) {
    return std::max(fontMetrics(FontFace::Sans, L.legendPx).lineHeight,
                    2.0f * (L.badgeRadius + CHART_MARK_CLEARANCE));
}
// The gap between the marks' column and the names: a quarter of the type, so a projector's large
// marks and words stay apart.
float legendGap(float s, float legendPx) {
    return std::max(6.0f * s, std::round(0.25f * legendPx));
}

// The front's ring with its clearance is taller than a line of small type: its line gets this
// much more room above and below, so the mark stays off the names above and below it.
float frontLineExtra(const SpeedChartLayout& L, float lineH) {
    float ring = frontRingRadius(L) + 0.5f * frontRingWidth(L.scale) + CHART_MARK_CLEARANCE;
    return std::max(0.0f, std::ceil(ring - 0.5f * lineH));
}

// The orange ring's legend mark: as wide overall as the front's ring (a thicker line a little
// further in), so that the marks' column and the plot keep their widths.
float legendHighlightRadius(const SpeedChartLayout& L) {
    return frontRingRadius(L) + 0.5f * frontRingWidth(L.scale) - 0.5f * highlightRingWidth(L.scale);
}

// The legend: the methods present (in the rows' order), then the front's entry. Its marks' column
// is as wide as the largest mark at the chart's dot size (a projector's large dots were wider
// than the fixed column they had, and the front's ring ran into "Pareto front"); the names start
// past it. Returns the legend's width and height; the marks' boxes are placed by placeLegend.
glm::vec2 layoutLegend(SpeedChartLayout& L, std::span<const BenchRow> rows, const Fonts& f,
                       float s) {
    for (const BenchRow& r : rows) {
        if (std::find(L.legendMethods.begin(), L.legendMethods.end(), r.point.method) ==
            L.legendMethods.end()) {
            L.legendMethods.push_back(r.point.method);
        }
    }
    float legendText = measureText(FontFace::Sans, f.legend, FRONT_LEGEND).x;
    bool ringed = !L.highlight.empty();
    if (ringed) {
        legendText =
            std::max(legendText, measureText(FontFace::Sans, f.legend, HIGHLIGHT_LEGEND).x);
    }
    for (int m : L.legendMethods) {
        legendText =
            std::max(legendText, measureText(FontFace::Sans, f.legend, methodInfo(m).name).x);
    }
    float lineH = fontMetrics(FontFace::Sans, f.legend).lineHeight;
    float half = std::max(frontHalfLine(s), frontRingRadius(L) + 0.5f * frontRingWidth(s));
    float legendW =
        std::round(8.0f * s + 2.0f * half + legendGap(s, f.legend) + legendText + 8.0f * s);
    float legendH = std::round((static_cast<float>(L.legendMethods.size()) + 1.0f) * lineH +
                               2.0f * frontLineExtra(L, lineH) + 12.0f * s);
    if (ringed) legendH += std::round(lineH + 2.0f * frontLineExtra(L, lineH));
    return {legendW, legendH};
}

// The marks' boxes (with CHART_MARK_CLEARANCE), one per legend line, in the legend's column, and
// where the names start.
void placeLegend(SpeedChartLayout& L, float legendPx) {
    float s = L.scale;
    float lineH = fontMetrics(FontFace::Sans, legendPx).lineHeight;
    float half = std::max(frontHalfLine(s), frontRingRadius(L) + 0.5f * frontRingWidth(s));
    float centreX = L.legend.x + 8.0f * s + half;
    float y = L.legend.y + 6.0f * s;
    L.legendSwatches.clear();
    for (size_t k = 0; k < L.legendMethods.size(); ++k, y += lineH) {
        float r = L.dotRadius + CHART_MARK_CLEARANCE;
        L.legendSwatches.push_back({centreX - r, y + lineH / 2 - r, 2 * r, 2 * r});
    }
    float ring = frontRingRadius(L) + 0.5f * frontRingWidth(s) + CHART_MARK_CLEARANCE;
    float w = half + CHART_MARK_CLEARANCE;
    y += frontLineExtra(L, lineH);
    L.legendSwatches.push_back({centreX - w, y + lineH / 2 - ring, 2 * w, 2 * ring});
    if (!L.highlight.empty()) {
        // The orange ring's line: below the front's, with the room its ring takes.
        y += lineH + 2.0f * frontLineExtra(L, lineH);
        L.legendSwatches.push_back({centreX - ring, y + lineH / 2 - ring, 2 * ring, 2 * ring});
    }
    L.legendTextX = std::round(centreX + half + legendGap(s, legendPx));
}

// The y axis: 0 to the largest error, in round steps. Returns the step.
double layoutYRange(SpeedChartLayout& L, std::span<const BenchRow> rows, ChartAccuracy accuracy) {
    double yMax = 0.0;
    for (const BenchRow& r : rows) yMax = std::max(yMax, chartAccuracy(r, accuracy));
    double yStep = chartNiceStep(std::max(yMax * 1.08, 1e-6) / 7.0);
    L.yLo = 0.0;
    L.yHi = std::ceil(std::max(yMax * 1.08, 1e-6) / yStep) * yStep;
    return yStep;
}

// The plot's and the legend's rectangles: the title above, the y tick labels on the left, the
// legend on the right and the x ticks and name below.
void layoutFrame(SpeedChartLayout& L, const Fonts& f, float s, double yStep, glm::vec2 legendSize) {
    // The subtitle's lines (the stand-alone chart's: the renderer, then how it was timed).
    float titleH = fontMetrics(FontFace::Sans, f.title).lineHeight +
                   L.subtitleLines * fontMetrics(FontFace::Sans, f.subtitle).lineHeight +
                   fontMetrics(FontFace::Sans, f.axis).lineHeight + 14.0f * s;
    float yTickW = 0.0f;
    for (double v = 0.0; v <= L.yHi + 0.5 * yStep; v += yStep) {
        std::string t = chartTickText(std::round(v / yStep) * yStep);
        yTickW = std::max(yTickW, measureText(FontFace::Sans, f.tick, t).x);
    }
    float left = std::round(std::max(62.0f * s, yTickW + 12.0f * s + 4.0f));
    float right = std::round(legendSize.x + 28.0f * s);
    float top = std::round(titleH);
    float bottom = std::round(fontMetrics(FontFace::Sans, f.tick).lineHeight +
                              fontMetrics(FontFace::Sans, f.axis).lineHeight + 20.0f * s +
                              static_cast<float>(L.keyLines) * keyLineHeight(L));
    L.plot = {left, top, std::max(16.0f, L.size.x - left - right),
              std::max(16.0f, L.size.y - top - bottom)};
    L.legend = {L.plot.right() + 16.0f * s, L.plot.y, legendSize.x, legendSize.y};
}

// A row's error bar ends on the log axis. The bar's low end stays above a tenth of the median.
double barLogLo(const BenchRow& r, ChartTiming timing) {
    double ms = chartMs(r, timing);
    return safeLog(std::max(ms - 0.5 * chartIqr(r, timing), 0.1 * ms));
}

double barLogHi(const BenchRow& r, ChartTiming timing) {
    return safeLog(chartMs(r, timing) + 0.5 * chartIqr(r, timing));
}

// The x axis: log10 of the time, padded by 6% of the span (at least 0.1 decade a side).
void layoutXRange(SpeedChartLayout& L, std::span<const BenchRow> rows, ChartTiming timing) {
    double xMin = 1e300, xMax = -1e300;
    for (const BenchRow& r : rows) {
        xMin = std::min(xMin, barLogLo(r, timing));
        xMax = std::max(xMax, barLogHi(r, timing));
    }
    if (rows.empty()) xMin = xMax = 0.0;
    double pad = std::max(0.1, 0.06 * (xMax - xMin));
    L.xLogLo = xMin - pad;
    L.xLogHi = xMax + pad;
}

float xPixelOf(const SpeedChartLayout& L, double logMs) {
    return L.plot.x + static_cast<float>((logMs - L.xLogLo) / (L.xLogHi - L.xLogLo)) * L.plot.w;
}

float yPixelOf(const SpeedChartLayout& L, double e) {
    return L.plot.bottom() - static_cast<float>((e - L.yLo) / (L.yHi - L.yLo)) * L.plot.h;
}

// Whether a labelled x tick lies within `reach` (log10 units) of log time lv.
bool labelledTickNear(const SpeedChartLayout& L, double lv, double reach) {
    for (const ChartTick& t : L.xTicks) {
        if (!t.text.empty() && std::abs(std::log10(t.value) - lv) <= reach + 1e-9) return true;
    }
    return false;
}

// Labels the x tick at v (adding its gridline where there is none).
void labelXTick(SpeedChartLayout& L, double v) {
    for (ChartTick& t : L.xTicks) {
        if (std::abs(t.value - v) <= 1e-9 * v) {
            t.text = chartTickText(v);
            return;
        }
    }
    L.xTicks.push_back({v, xPixelOf(L, std::log10(v)), chartTickText(v)});
}

// The round values a label may be added at, m x 10^k inside the axis (m in 1, 1.5, 2, 2.5, 3..9:
// every time lies within a factor of 1.23 of one).
std::vector<double> xTickCandidates(const SpeedChartLayout& L) {
    std::vector<double> out;
    for (int k = static_cast<int>(std::floor(L.xLogLo)); k <= static_cast<int>(std::ceil(L.xLogHi));
         ++k) {
        for (double m : {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0}) {
            double v = m * std::pow(10.0, k);
            double lv = std::log10(v);
            if (lv >= L.xLogLo && lv <= L.xLogHi) out.push_back(v);
        }
    }
    return out;
}

// The x axis's round ticks at m x 10^k: m = 1, 2, 5 (1, 2, 3, 5 under 1.5 decades, every integer
// mantissa under 0.7), all labelled but on a wide axis (over 3 decades), where only the 1s are,
// so that a few labels always show.
void addRoundXTicks(SpeedChartLayout& L) {
    double span = L.xLogHi - L.xLogLo;
    std::vector<double> mantissas{1, 2, 5};
    if (span < 1.5) mantissas = {1, 2, 3, 5};
    if (span < 0.7) {
        mantissas.clear();
        for (int m = 1; m <= 9; ++m) mantissas.push_back(m);
    }
    bool wide = span > 3.0;
    for (int k = static_cast<int>(std::floor(L.xLogLo)); k <= static_cast<int>(std::ceil(L.xLogHi));
         ++k) {
        for (double m : mantissas) {
            double v = m * std::pow(10.0, k);
            double lv = std::log10(v);
            if (lv < L.xLogLo || lv > L.xLogHi) continue;
            L.xTicks.push_back({v, xPixelOf(L, lv), (!wide || m == 1.0) ? chartTickText(v) : ""});
        }
    }
}

// The candidate in [lo, hi) nearest log time lv (log10 units); 0 when none lies there.
double nearestXCandidate(const std::vector<double>& candidates, double lv, double lo, double hi) {
    double best = 0.0, bestD = 1e300;
    for (double v : candidates) {
        double d = std::abs(std::log10(v) - lv);
        if (v >= lo && v < hi && d < bestD) {
            best = v;
            bestD = d;
        }
    }
    return best;
}

// Every dot readable off the axis: a labelled tick in its decade, and one within a factor of
// SPEED_CHART_TICK_REACH (speed_chart.h) of its time, labelling the nearest candidate where
// there is none.
void labelEveryDotsTime(SpeedChartLayout& L, std::span<const BenchRow> rows, ChartTiming timing,
                        const std::vector<double>& candidates) {
    for (const BenchRow& r : rows) {
        double lv = std::clamp(safeLog(chartMs(r, timing)), L.xLogLo, L.xLogHi);
        double decade = std::pow(10.0, std::floor(lv));
        bool decadeLabelled = false;
        for (const ChartTick& t : L.xTicks) {
            decadeLabelled |= !t.text.empty() && t.value >= decade && t.value < 10.0 * decade;
        }
        if (!decadeLabelled) {
            if (double v = nearestXCandidate(candidates, lv, decade, 10.0 * decade); v > 0.0) {
                labelXTick(L, v);
            }
        }
        if (!labelledTickNear(L, lv, std::log10(SPEED_CHART_TICK_REACH))) {
            if (double v = nearestXCandidate(candidates, lv, 0.0, 1e300); v > 0.0) labelXTick(L, v);
        }
    }
}

// At least 3 labels on the x axis (speed_chart.h, SPEED_CHART_TICK_REACH): the candidate
// farthest from every label is labelled until there are, or every candidate is.
void labelAtLeastThree(SpeedChartLayout& L, const std::vector<double>& candidates) {
    auto labelCount = [&] {
        return std::count_if(L.xTicks.begin(), L.xTicks.end(),
                             [](const ChartTick& t) { return !t.text.empty(); });
    };
    while (labelCount() < 3) {
        double best = 0.0, bestD = -1.0;
        for (double v : candidates) {
            double d = 1e300;
            for (const ChartTick& t : L.xTicks) {
                if (!t.text.empty()) d = std::min(d, std::abs(std::log10(t.value / v)));
            }
            if (d > bestD) {
                best = v;
                bestD = d;
            }
        }
        if (bestD <= 1e-9) break;  // every candidate is labelled
        labelXTick(L, best);
    }
}

// The ticks of both axes: the x axis's round ticks (addRoundXTicks), then a labelled tick near
// every dot's time (labelEveryDotsTime) and 3 labels at least (labelAtLeastThree), in order of
// value; the y axis's every yStep from 0, all labelled.
void layoutTicks(SpeedChartLayout& L, double yStep, std::span<const BenchRow> rows,
                 ChartTiming timing) {
    addRoundXTicks(L);
    std::vector<double> candidates = xTickCandidates(L);
    labelEveryDotsTime(L, rows, timing, candidates);
    labelAtLeastThree(L, candidates);
    std::sort(L.xTicks.begin(), L.xTicks.end(),
              [](const ChartTick& a, const ChartTick& b) { return a.value < b.value; });
    for (double v = 0.0; v <= L.yHi + 0.5 * yStep; v += yStep) {
        L.yTicks.push_back({v, yPixelOf(L, v), chartTickText(std::round(v / yStep) * yStep)});
    }
}

// The dots, their error bars and their label texts.
void layoutDots(SpeedChartLayout& L, std::span<const BenchRow> rows, ChartTiming timing,
                ChartAccuracy accuracy) {
    for (const BenchRow& r : rows) {
        L.points.emplace_back(xPixelOf(L, safeLog(chartMs(r, timing))),
                              yPixelOf(L, chartAccuracy(r, accuracy)));
        L.errorBars.emplace_back(xPixelOf(L, barLogLo(r, timing)),
                                 xPixelOf(L, barLogHi(r, timing)));
        L.labelTexts.push_back(chartLabel(r.point));
    }
}

// The Pareto front of the medians over every row (bench_report.h: benchParetoFront), and the
// rows the chart must name: the highlighted, or the front's where none is.
void layoutFront(SpeedChartLayout& L, std::span<const BenchRow> rows, ChartTiming timing,
                 ChartAccuracy accuracy, std::span<const size_t> highlight) {
    std::vector<glm::dvec2> frontPoints;
    for (const BenchRow& r : rows) {
        frontPoints.emplace_back(chartMs(r, timing), chartAccuracy(r, accuracy));
    }
    L.front = paretoFront(frontPoints, PARETO_ERROR_TOLERANCE);
    L.frontJoined.assign(L.front.size(), false);
    for (size_t k = 1; k < L.front.size(); ++k) {
        L.frontJoined[k] = !benchSpreadsOverlap(rows[L.front[k - 1]], rows[L.front[k]],
                                                timing == ChartTiming::Lookup);
    }
    for (size_t k : highlight) {
        if (k < rows.size()) L.highlight.push_back(k);
    }
    L.mustName = L.highlight.empty() ? L.front : L.highlight;
}

// The key under the x axis's name (speed_chart_labels.h: a dot whose name found no room gets a
// badge): its entries in the badges' order, each a badge and the dot's name in the legend's
// type, left to right from the plot's left edge, wrapped at the chart's right margin. Returns
// the lines it takes (keyBadges is laid out in L.keyLines' room when they suffice).
int placeKey(SpeedChartLayout& L) {
    L.keyBadges.clear();
    if (L.keyRows.empty()) return 0;
    float s = L.scale;
    float r = L.badgeRadius;
    float lineH = keyLineHeight(L);
    float tickH = fontMetrics(FontFace::Sans, L.tickPx).lineHeight;
    float axisH = fontMetrics(FontFace::Sans, L.axisPx).lineHeight;
    float top = L.plot.bottom() + 8.0f * s + tickH + axisH + 4.0f * s;
    float left = L.plot.x, right = L.size.x - std::round(12.0f * s);
    float x = left, y = top;
    int lines = 1;
    for (size_t i = 0; i < L.keyRows.size(); ++i) {
        float words = measureText(FontFace::Sans, L.legendPx, L.labelTexts[L.keyRows[i]]).x;
        float width = 2.0f * r + legendGap(s, L.legendPx) + words;
        if (x > left && x + width > right) {
            x = left;
            y += lineH;
            ++lines;
        }
        L.keyBadges.push_back(
            {std::round(x), std::round(y + 0.5f * lineH - r), 2.0f * r, 2.0f * r});
        x += width + 2.0f * legendGap(s, L.legendPx) + r;
    }
    return lines;
}

}  // namespace

SpeedChartLayout layoutSpeedChart(std::span<const BenchRow> rows, glm::ivec2 size,
                                  ChartTiming timing, ChartAccuracy accuracy,
                                  std::span<const size_t> highlight, float minFontPx,
                                  bool keptLabelsOnly, int subtitleLines) {
    if (size.x < 64 || size.y < 64) {
        throw std::invalid_argument("layoutSpeedChart: the chart needs at least 64 x 64 pixels");
    }
    SpeedChartLayout L;
    L.size = size;
    L.subtitleLines = std::max(1, subtitleLines);
    float s = std::clamp(std::min(size.x / 1280.0f, size.y / 720.0f), 0.35f, 4.0f);
    L.scale = s;
    Fonts f = fontsFor(s, minFontPx);
    L.titlePx = f.title;
    L.subtitlePx = f.subtitle;
    L.axisPx = f.axis;
    L.tickPx = f.tick;
    L.labelPx = f.label;
    L.legendPx = f.legend;

    L.dotRadius = std::max(4.5f * s, std::round(f.label * 0.25f));
    layoutFront(L, rows, timing, accuracy, highlight);
    L.badgeRadius = badgeRadiusFor(L);
    glm::vec2 legendSize = layoutLegend(L, rows, f, s);
    double yStep = layoutYRange(L, rows, accuracy);
    // Laid out once without room for a key, and where badges want one, again with as many
    // lines as it takes (a plot shortened for it may need another line, at most twice).
    const SpeedChartLayout bare = L;
    for (int tries = 0;; ++tries) {
        layoutFrame(L, f, s, yStep, legendSize);
        placeLegend(L, f.legend);
        layoutXRange(L, rows, timing);
        layoutTicks(L, yStep, rows, timing);
        layoutDots(L, rows, timing, accuracy);
        placeSpeedChartLabels(L, keptLabelsOnly);
        int lines = placeKey(L);
        if (lines <= L.keyLines || tries == 2) break;
        int keyLines = lines;
        L = bare;
        L.keyLines = keyLines;
    }
    return L;
}

Rect speedChartDotBox(const SpeedChartLayout& L, size_t row) {
    glm::vec2 p = L.points[row];
    float r = L.dotRadius;
    return {p.x - r, p.y - r, 2.0f * r, 2.0f * r};
}

float speedChartMarkRadius(const SpeedChartLayout& L, size_t row) {
    float r = L.dotRadius;
    if (std::find(L.front.begin(), L.front.end(), row) != L.front.end()) {
        r = std::max(r, frontRingRadius(L) + 0.5f * frontRingWidth(L.scale));
    }
    if (std::find(L.highlight.begin(), L.highlight.end(), row) != L.highlight.end()) {
        r = std::max(r, highlightRingRadius(L) + 0.5f * highlightRingWidth(L.scale));
    }
    return r;
}

Rect speedChartBarBox(const SpeedChartLayout& L, size_t row) {
    glm::vec2 bar = L.errorBars[row];
    if (bar.y - bar.x < 1.0f) return {};
    float w = barStroke(L.scale);
    float half = barTickHalf(L.scale) + 0.5f * w;
    return {bar.x - 0.5f * w, L.points[row].y - half, bar.y - bar.x + w, 2.0f * half};
}

float speedChartLegendGap(const SpeedChartLayout& L) { return legendGap(L.scale, L.legendPx); }

namespace {

// The grid lines at the ticks and the plot's frame.
void drawGrid(Canvas& c, const SpeedChartLayout& L) {
    float stroke = std::max(1.0f, std::round(L.scale));
    for (const ChartTick& t : L.xTicks) {
        float x = std::round(t.pixel) + 0.5f;
        c.line({x, L.plot.y}, {x, L.plot.bottom()}, stroke, CHART_GRID);
    }
    for (const ChartTick& t : L.yTicks) {
        float y = std::round(t.pixel) + 0.5f;
        c.line({L.plot.x, y}, {L.plot.right(), y}, stroke, CHART_GRID);
    }
    c.strokeRect(L.plot.expanded(stroke), stroke, CHART_SOFT_INK);
}

// Error bars: the IQR of the time, with end ticks.
void drawErrorBars(Canvas& c, const SpeedChartLayout& L, std::span<const BenchRow> rows) {
    float s = L.scale;
    for (size_t k = 0; k < rows.size(); ++k) {
        glm::vec2 bar = L.errorBars[k];
        if (bar.y - bar.x < 1.0f) continue;
        float y = L.points[k].y;
        glm::vec4 ink = methodColour(rows[k].point.method) * 0.7f;
        ink.a = 1.0f;
        float w = barStroke(s);
        float h = barTickHalf(s);
        c.line({bar.x, y}, {bar.y, y}, w, ink);
        c.line({bar.x, y - h}, {bar.x, y + h}, w, ink);
        c.line({bar.y, y - h}, {bar.y, y + h}, w, ink);
    }
}

// Inside the plot, bottom to top: the front's line, the error bars, the front's rings, the
// highlighted dots' rings and the dots.
void drawPlotMarks(Canvas& c, const SpeedChartLayout& L, std::span<const BenchRow> rows) {
    float s = L.scale;
    c.pushClip(L.plot.expanded(2.0f * s));
    for (size_t k = 1; k < L.front.size(); ++k) {
        if (!L.frontJoined[k]) continue;
        c.line(L.points[L.front[k - 1]], L.points[L.front[k]], std::max(1.5f, 1.5f * s), FRONT);
    }
    float dotR = L.dotRadius;
    float ring = std::max(1.5f, 1.5f * s);  // the front's line and rings
    drawErrorBars(c, L, rows);
    for (size_t k : L.front) c.ring(L.points[k], dotR + 2.5f * s, ring, FRONT);
    // The dots a lesson step talks about: a thick orange ring outside the front's.
    for (size_t k : L.highlight) {
        c.ring(L.points[k], highlightRingRadius(L), highlightRingWidth(s), HIGHLIGHT_RING);
    }
    for (size_t k = 0; k < rows.size(); ++k) {
        c.circle(L.points[k], dotR, methodColour(rows[k].point.method));
    }
    c.popClip();
}

// Leaders, where a crowd pushed a label away from its dot.
void drawLeaders(Canvas& c, const SpeedChartLayout& L, size_t rowCount) {
    for (size_t k = 0; k < rowCount; ++k) {
        if (std::optional<ChartLeader> leader = speedChartLeader(L, k)) {
            // Dark enough to follow: a leader a reader misses leaves the name by another dot.
            c.line(leader->from, leader->to, std::max(1.0f, 0.75f * L.scale),
                   CHART_GRID * 0.4f + CHART_SOFT_INK * 0.6f);
        }
    }
}

// The colour of a dot's name, its badge's ring and number: a darker shade of its method's.
Colour labelInk(const BenchRow& row) {
    Colour ink = methodColour(row.point.method) * 0.55f;
    ink.a = 1.0f;
    return ink;
}

// The badges' discs, by their dots and in the key: white, ringed in the dot's colour (the
// numbers are texts of speedChartTextBoxes, in the name's colour). A badge drawn in its dot's
// place keeps the dot's orange (or the front's black) ring round it.
void drawBadges(Canvas& c, const SpeedChartLayout& L, std::span<const BenchRow> rows) {
    float s = L.scale;
    auto badge = [&](const Rect& box, size_t row) {
        c.circle(box.centre(), L.badgeRadius, methodColour(rows[row].point.method));
        c.circle(box.centre(), L.badgeRadius - std::max(1.5f, 1.5f * s), {1.0f, 1.0f, 1.0f, 1.0f});
    };
    for (size_t k = 0; k < rows.size(); ++k) {
        if (L.badge[k] == 0) continue;
        if (L.badgeOnDot[k]) {
            glm::vec2 at = L.badgeBoxes[k].centre();
            float r = L.badgeRadius;
            bool ringed = std::find(L.highlight.begin(), L.highlight.end(), k) != L.highlight.end();
            if (ringed) {
                c.ring(at, r + 0.5f * highlightRingWidth(s), highlightRingWidth(s), HIGHLIGHT_RING);
            } else {
                c.ring(at, r + 0.5f * frontRingWidth(s), frontRingWidth(s), FRONT);
            }
        }
        badge(L.badgeBoxes[k], k);
    }
    for (size_t i = 0; i < L.keyRows.size(); ++i) badge(L.keyBadges[i], L.keyRows[i]);
}

// The legend's box and swatches (the names are texts of speedChartTextBoxes).
void drawLegendMarks(Canvas& c, const SpeedChartLayout& L) {
    float s = L.scale;
    float stroke = std::max(1.0f, std::round(s));
    float dotR = L.dotRadius;
    c.fillRect(L.legend, {0.97f, 0.97f, 0.98f, 1.0f});
    c.strokeRect(L.legend, stroke, CHART_GRID);
    for (size_t k = 0; k < L.legendMethods.size(); ++k) {
        c.circle(L.legendSwatches[k].centre(), dotR, methodColour(L.legendMethods[k]));
    }
    glm::vec2 front = L.legendSwatches[L.legendMethods.size()].centre();
    c.line(front - glm::vec2(frontHalfLine(s), 0.0f), front + glm::vec2(frontHalfLine(s), 0.0f),
           1.5f * s, FRONT);
    c.ring(front, frontRingRadius(L), frontRingWidth(s), FRONT);
    if (!L.highlight.empty()) {
        glm::vec2 ringed = L.legendSwatches.back().centre();
        c.ring(ringed, legendHighlightRadius(L), highlightRingWidth(s), HIGHLIGHT_RING);
        c.circle(ringed, dotR, CHART_SOFT_INK);
    }
}

// Every text where speedChartTextBoxes put it; a dot's label in a darker shade of its colour.
void drawTexts(Canvas& c, std::span<const ChartTextBox> texts, std::span<const BenchRow> rows) {
    for (const ChartTextBox& b : texts) {
        if (b.role == "chart-swatch") continue;  // a mark's box: drawLegendMarks draws it
        Colour ink = CHART_INK;
        if (b.role == "chart-subtitle" || b.role == "chart-tick") ink = CHART_SOFT_INK;
        if (b.row >= 0 && static_cast<size_t>(b.row) < rows.size()) {
            ink = labelInk(rows[static_cast<size_t>(b.row)]);
        }
        glm::vec2 at = b.rect.position();
        if (b.role == "chart-badge") {  // the number in the middle of its disc
            glm::vec2 size = measureText(FontFace::Sans, b.fontPx, b.text);
            at = glm::round(b.rect.centre() - 0.5f * size);
        }
        c.text(at, b.text, {FontFace::Sans, b.fontPx, ink});
    }
}

}  // namespace

std::vector<uint8_t> drawSpeedChart(std::span<const BenchRow> rows, glm::ivec2 size,
                                    const SpeedChartText& text, ChartTiming timing,
                                    ChartAccuracy accuracy) {
    SpeedChartText fitted = speedChartTextFor(rows, text, size, timing);
    SpeedChartLayout L =
        layoutSpeedChart(rows, size, timing, accuracy, text.highlight, text.minFontPx,
                         text.keptLabelsOnly, subtitleLineCount(fitted.subtitle));
    std::vector<ChartTextBox> texts = speedChartTextBoxes(L, fitted);

    return drawChartOffscreen(size, [&](Canvas& c) {
        drawGrid(c, L);
        drawPlotMarks(c, L, rows);
        drawLeaders(c, L, rows.size());
        drawLegendMarks(c, L);
        drawBadges(c, L, rows);
        drawTexts(c, texts, rows);
    });
}

}  // namespace pcf
