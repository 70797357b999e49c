#include "charts/advise_chart.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "charts/chart_axes.h"
#include "draw/canvas.h"
#include "draw/text_layout.h"
#include "measure/bench_report.h"

namespace pcf {

namespace {

const Colour FEASIBLE_RING{0.1f, 0.6f, 0.2f, 1.0f};
const Colour BUDGET_INK{0.75f, 0.1f, 0.1f, 1.0f};
const Colour CHOICE_RING{0.95f, 0.55f, 0.05f, 1.0f};

std::string brokenLabel(const AdviseCandidate& c) {
    std::string s;
    for (AdviseConstraint k : c.broken) {
        s += (s.empty() ? "" : "+") + std::string(adviseConstraintName(k));
    }
    return s;
}

bool overlapsAny(const Rect& r, const std::vector<Rect>& taken) {
    return std::any_of(taken.begin(), taken.end(),
                       [&](const Rect& t) { return !r.intersect(t).empty(); });
}

// How far a point lies from a box (0 inside).
float distanceTo(const Rect& r, glm::vec2 p) {
    glm::vec2 nearest = glm::clamp(p, r.position(), r.position() + r.size());
    return glm::length(p - nearest);
}

// A label's box beside its dot: right, left, above, below, then the diagonals, the first in the
// plot on no text, dot, bar or other label and nearer its own dot than any other; else right of
// the dot.
Rect placeLabel(glm::vec2 dot, glm::vec2 size, float gap, const Rect& plot,
                const std::vector<Rect>& taken, const std::vector<glm::vec2>& dots) {
    const glm::vec2 offsets[] = {{gap, -size.y / 2},
                                 {-gap - size.x, -size.y / 2},
                                 {-size.x / 2, -gap - size.y},
                                 {-size.x / 2, gap},
                                 {gap, -gap - size.y},
                                 {gap, gap},
                                 {-gap - size.x, -gap - size.y},
                                 {-gap - size.x, gap}};
    for (glm::vec2 o : offsets) {
        Rect r{dot.x + o.x, dot.y + o.y, size.x, size.y};
        bool inside = r.x >= plot.x && r.right() <= plot.right() && r.y >= plot.y &&
                      r.bottom() <= plot.bottom();
        bool own = std::all_of(dots.begin(), dots.end(), [&](glm::vec2 other) {
            return other == dot || distanceTo(r, other) > distanceTo(r, dot);
        });
        if (inside && own && !overlapsAny(r, taken)) return r;
    }
    return {dot.x + offsets[0].x, dot.y + offsets[0].y, size.x, size.y};
}

}  // namespace

std::vector<BenchRow> adviseChartRows(const AdviseResult& result,
                                      const std::vector<BenchRow>& rows) {
    std::vector<BenchRow> out;
    for (size_t k = 0; k < result.measured.size() && k < rows.size(); ++k) {
        // The cost the search compared (timed again for the feasible settings), in the field
        // the chart reads: process CPU time on a CPU rasteriser (bench_report.h benchPassMs).
        BenchRow r = rows[k];
        const AdviseMetrics& m = result.measured[k].metrics;
        if (benchTimesByCpu(r)) {
            r.lookupCpuMs = m.costMs;
            r.lookupCpuMsIqr = m.costIqr;
        } else {
            r.lookupMs = m.costMs;
            r.lookupMsIqr = m.costIqr;
        }
        out.push_back(r);
    }
    return out;
}

bool adviseBudgetLineShown(const AdviseResult& result, const AdviseBudget& budget) {
    return std::any_of(result.measured.begin(), result.measured.end(),
                       [&](const auto& c) { return c.metrics.edgeRmse >= budget.maxEdgeRmse; });
}

SpeedChartText adviseChartText(const AdviseResult& result, const AdviseBudget& budget,
                               const std::string& title, const std::string& glRenderer) {
    SpeedChartText text;
    text.title = title;
    text.subtitle =
        chartRendererLine(glRenderer) +
        "\ngreen ring: meets the whole budget; orange ring: the choice; the words beside a "
        "dot: the budgets it breaks; " +
        (adviseBudgetLineShown(result, budget)
             ? std::string("dashed: the edge-RMSE budget, ")
             : std::string("every dot is within the edge-RMSE budget, ")) +
        chartTickText(budget.maxEdgeRmse);
    text.xLabel = "lookup pass, process CPU time, ms (log scale)";
    text.yLabel = "edge-band RMSE of visibility";
    text.minFontPx = STANDALONE_CHART_MIN_PX;
    text.keptLabelsOnly = true;
    return text;
}

AdviseChartOverlay layoutAdviseChart(const AdviseResult& result, const std::vector<BenchRow>& rows,
                                     const AdviseBudget& budget, glm::ivec2 size,
                                     const std::string& title, const std::string& glRenderer) {
    std::vector<BenchRow> chartRows = adviseChartRows(result, rows);
    SpeedChartText text = speedChartTextFor(
        chartRows, adviseChartText(result, budget, title, glRenderer), size, ChartTiming::Lookup);
    AdviseChartOverlay o;
    o.chart = layoutSpeedChart(chartRows, size, ChartTiming::Lookup, ChartAccuracy::EdgeRmse,
                               text.highlight, text.minFontPx, text.keptLabelsOnly,
                               subtitleLineCount(text.subtitle));
    const SpeedChartLayout& L = o.chart;
    o.fontPx = std::max(STANDALONE_CHART_MIN_PX, L.labelPx);
    std::vector<Rect> taken;
    for (const ChartTextBox& b : speedChartTextBoxes(L, text)) taken.push_back(b.rect);
    for (size_t k = 0; k < chartRows.size(); ++k) {
        taken.push_back(speedChartDotBox(L, k));
        taken.push_back(speedChartBarBox(L, k));
    }
    double e = budget.maxEdgeRmse;
    o.budgetShown = adviseBudgetLineShown(result, budget) && L.yHi > L.yLo;
    o.budgetY = L.plot.bottom() - static_cast<float>((e - L.yLo) / (L.yHi - L.yLo)) * L.plot.h;
    if (o.budgetShown)
        taken.push_back({L.plot.x, o.budgetY - 2.0f * L.scale, L.plot.w, 4.0f * L.scale});
    o.labels.assign(chartRows.size(), "");
    o.labelBoxes.assign(chartRows.size(), Rect{});
    for (size_t k = 0; k < chartRows.size(); ++k) {
        bool chosen = result.choice && *result.choice == k;
        if (result.measured[k].feasible() && !chosen) continue;
        o.labels[k] =
            chosen ? "choice: " + chartLabel(chartRows[k].point) : brokenLabel(result.measured[k]);
        glm::vec2 extent = measureText(FontFace::Sans, o.fontPx, o.labels[k]);
        float gap = speedChartMarkRadius(L, k) + 2.0f * L.scale;
        o.labelBoxes[k] = placeLabel(L.points[k], extent, gap, L.plot, taken, L.points);
        taken.push_back(o.labelBoxes[k]);
    }
    return o;
}

std::vector<uint8_t> drawAdviseChart(const AdviseResult& result, const std::vector<BenchRow>& rows,
                                     const AdviseBudget& budget, glm::ivec2 size,
                                     const std::string& title, const std::string& glRenderer) {
    std::vector<BenchRow> chartRows = adviseChartRows(result, rows);
    std::vector<uint8_t> base =
        drawSpeedChart(chartRows, size, adviseChartText(result, budget, title, glRenderer),
                       ChartTiming::Lookup, ChartAccuracy::EdgeRmse);
    AdviseChartOverlay o = layoutAdviseChart(result, rows, budget, size, title, glRenderer);
    const SpeedChartLayout& L = o.chart;
    std::vector<glm::vec4> pixels(base.size() / 4);
    for (size_t k = 0; k < pixels.size(); ++k) {
        pixels[k] =
            glm::vec4(base[4 * k], base[4 * k + 1], base[4 * k + 2], base[4 * k + 3]) / 255.0f;
    }
    auto picture = std::make_shared<const CanvasImage>(size, std::move(pixels));
    return drawChartOffscreen(size, [&](Canvas& c) {
        c.image({0, 0}, picture);
        float s = L.scale;
        if (o.budgetShown) {
            float dash = 8.0f * s;
            for (float x = L.plot.x; x < L.plot.right(); x += 2.0f * dash) {
                c.line({x, o.budgetY}, {std::min(x + dash, L.plot.right()), o.budgetY},
                       std::max(1.5f, 2.0f * s), BUDGET_INK);
            }
        }
        if (result.choice && *result.choice < L.points.size()) {
            size_t k = *result.choice;
            c.ring(L.points[k], speedChartMarkRadius(L, k) + 5.5f * s, std::max(2.5f, 3.0f * s),
                   CHOICE_RING);
        }
        for (size_t k = 0; k < result.measured.size() && k < L.points.size(); ++k) {
            if (result.measured[k].feasible()) {
                c.ring(L.points[k], speedChartMarkRadius(L, k) + 2.0f * s, std::max(2.0f, 2.0f * s),
                       FEASIBLE_RING);
            }
            if (!o.labels[k].empty()) {
                bool chosen = result.choice && *result.choice == k;
                TextStyle style{FontFace::Sans, o.fontPx, chosen ? CHART_INK : CHART_SOFT_INK,
                                TextAlign::Left};
                c.text(o.labelBoxes[k].position(), o.labels[k], style);
            }
        }
    });
}

}  // namespace pcf
