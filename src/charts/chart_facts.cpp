#include "charts/chart_facts.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "base/input_file.h"
#include "charts/chart_axes.h"
#include "charts/speed_chart.h"
#include "charts/stability_chart.h"
#include "charts/stability_figures.h"
#include "charts/step_chart.h"
#include "measure/bench_report.h"
#include "measure/stability_report.h"

namespace pcf {

namespace {

// A chart as the step names it (step_chart.h): the file, the view, bench or stability.
using ChartData = StepChartRef;

std::string percent(double share) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g%%", 100.0 * share);
    return buf;
}

// "measured on NAME": the renderer the file records contains NAME.
ChartFactAnswer measuredOn(const ChartData& c, const std::string& name) {
    std::string renderer;
    if (c.bench) {
        renderer = speedChartRenderer(readChartRows(c.path));
    } else {
        std::vector<StabilityRow> rows = parseStabilityCsv(readInputFile(c.path), c.path);
        if (std::optional<StabilitySetup> setup = stabilitySetupOf(rows)) {
            renderer = setup->glRenderer;
        }
    }
    if (renderer.empty()) {
        return {false, c.path + " records no renderer (older than its gl_renderer column)"};
    }
    return {renderer.find(name) != std::string::npos, "measured on " + renderer};
}

// The trade-off of the panel titled `method`, or std::invalid_argument naming the panels.
TradeoffSeries tradeoffOf(const ChartData& c, const std::string& method) {
    std::vector<StabilityRow> rows = parseStabilityCsv(readInputFile(c.path), c.path);
    std::string names;
    for (const TradeoffSeries& t : tradeoffSeries(rows)) {
        if (t.name == method) return t;
        names += (names.empty() ? "" : ", ") + t.name;
    }
    throw std::invalid_argument("'" + method + "' is no panel of the trade-off chart (panels: " +
                                (names.empty() ? "none" : names) + ")");
}

// The largest leak rate of the contact scenes at bias index k (0 where none was measured).
double leakAt(const TradeoffSeries& t, size_t k) {
    double most = 0.0;
    for (const auto& scene : t.leak) most = std::max(most, scene[k].value_or(0.0));
    return most;
}

std::string acneWhy(const TradeoffSeries& t, size_t k) {
    return "acne " + percent(t.acne[k]) + " at bias " + chartTickText(t.biases[k]);
}

std::string leakWhy(const TradeoffSeries& t, size_t k) {
    return "leak " + percent(leakAt(t, k)) + " at bias " + chartTickText(t.biases[k]);
}

ChartFactAnswer acneFalls(const ChartData& c, const std::string& method) {
    TradeoffSeries t = tradeoffOf(c, method);
    if (t.biases.empty()) return {false, "no trade-off rows for " + method};
    size_t last = t.biases.size() - 1;
    return {t.acne.front() >= TRADEOFF_ONSET && t.acne.back() < TRADEOFF_ONSET,
            acneWhy(t, 0) + ", " + acneWhy(t, last)};
}

ChartFactAnswer leakGrows(const ChartData& c, const std::string& method) {
    TradeoffSeries t = tradeoffOf(c, method);
    if (t.biases.empty() || t.leak.empty()) return {false, "no leak rows for " + method};
    size_t last = t.biases.size() - 1;
    return {leakAt(t, 0) < TRADEOFF_ONSET && leakAt(t, last) >= TRADEOFF_ONSET,
            leakWhy(t, 0) + ", " + leakWhy(t, last)};
}

ChartFactAnswer goodBetween(const ChartData& c, const std::string& method) {
    TradeoffSeries t = tradeoffOf(c, method);
    if (!t.good) return {false, "no bias keeps both acne and leak under the onset"};
    bool acneBelow = false, leakAbove = false;
    for (size_t k = 0; k < t.biases.size(); ++k) {
        if (t.biases[k] < t.good->x && t.acne[k] >= TRADEOFF_ONSET) acneBelow = true;
        if (t.biases[k] > t.good->y && leakAt(t, k) >= TRADEOFF_ONSET) leakAbove = true;
    }
    return {acneBelow && leakAbove,
            "good biases " + chartTickText(t.good->x) + " to " + chartTickText(t.good->y) +
                (acneBelow ? "" : "; no acne below") + (leakAbove ? "" : "; no leak above")};
}

// The acne chart's line "PANEL LINE" ("pcf-gather 5x5 normal": the panel's title, a space, the
// bias mode), its points in the order the sun sets (highest elevation first), as the chart draws
// them (acneChartSpec); or std::invalid_argument naming the lines.
std::vector<glm::dvec2> acneLine(const ChartData& c, const std::string& name) {
    std::vector<StabilityRow> rows = parseStabilityCsv(readInputFile(c.path), c.path);
    LineChartSpec spec = acneChartSpec(rows, "", 0.0f);
    std::string names;
    for (const ChartPanel& panel : spec.panels) {
        for (const ChartLine& line : panel.lines) {
            std::string full = panel.title + " " + line.label;
            if (full == name) {
                std::vector<glm::dvec2> points = line.points;
                std::stable_sort(points.begin(), points.end(),
                                 [](glm::dvec2 a, glm::dvec2 b) { return a.x > b.x; });
                return points;
            }
            names += (names.empty() ? "" : ", ") + full;
        }
    }
    throw std::invalid_argument("'" + name + "' is no line of the acne chart (lines: " +
                                (names.empty() ? "none" : names) + ")");
}

std::string rateAt(glm::dvec2 p) { return percent(p.y) + " at " + chartTickText(p.x) + " degrees"; }

// "L: over the onset at every elevation": line L's false-shadow rate is at or over the acne onset
// (TRADEOFF_ONSET, the chart's "1% = acne onset") at every elevation swept, the highest first.
ChartFactAnswer acneEverywhere(const ChartData& c, const std::string& line) {
    std::vector<glm::dvec2> points = acneLine(c, line);
    if (points.empty()) return {false, "no points on " + line};
    for (glm::dvec2 p : points) {
        if (p.y < TRADEOFF_ONSET) return {false, rateAt(p)};
    }
    return {true, "from " + rateAt(points.front())};
}

// "L: crosses the onset above E degrees" (or "below E degrees"): as the sun sets, the first
// elevation where line L reaches the acne onset lies above (below) E; a line that never reaches
// it crosses below every E and above none.
ChartFactAnswer acneCrossing(const ChartData& c, const std::string& arg) {
    for (std::string_view side : {": crosses the onset above ", ": crosses the onset below "}) {
        size_t at = arg.find(side);
        if (at == std::string::npos) continue;
        std::string line = arg.substr(0, at);
        std::string number = arg.substr(at + side.size());
        char* end = nullptr;
        double degrees = std::strtod(number.c_str(), &end);
        if (number.empty() || end != number.c_str() + number.size()) {
            throw std::invalid_argument("'" + number + "' is not a number of degrees");
        }
        bool above = side.find("above") != std::string_view::npos;
        for (glm::dvec2 p : acneLine(c, line)) {
            if (p.y < TRADEOFF_ONSET) continue;
            return {above ? p.x > degrees : p.x < degrees, "first " + rateAt(p)};
        }
        return {!above, line + " never reaches the onset"};
    }
    throw std::invalid_argument("'" + arg +
                                " degrees': say L: crosses the onset above E degrees, or below");
}

// "L: rises over the onset and falls back": as the sun sets, line L starts under the acne onset,
// climbs to it or over, and ends under it again (a hump, not a climb that stays).
ChartFactAnswer acneHump(const ChartData& c, const std::string& line) {
    std::vector<glm::dvec2> points = acneLine(c, line);
    if (points.size() < 3) return {false, "fewer than 3 points on " + line};
    auto peak = std::max_element(points.begin(), points.end(),
                                 [](glm::dvec2 a, glm::dvec2 b) { return a.y < b.y; });
    bool holds = points.front().y < TRADEOFF_ONSET && peak->y >= TRADEOFF_ONSET &&
                 points.back().y < TRADEOFF_ONSET;
    return {holds,
            rateAt(points.front()) + ", peak " + rateAt(*peak) + ", " + rateAt(points.back())};
}

// "measured against the KIND truth": every row's truth (bench.csv's truth column) is KIND.
ChartFactAnswer againstTruth(const ChartData& c, const std::string& kind) {
    std::vector<BenchRow> rows = readChartRows(c.path);
    if (kind != "hard" && kind != "area") {
        throw std::invalid_argument("the truth is hard or area, not '" + kind + "'");
    }
    for (const BenchRow& r : rows) {
        std::string k = benchTruthKind(r);
        if (k.empty()) return {false, c.path + " records no truth (older than its truth column)"};
        if (k != kind) return {false, "measured against the " + r.truth + " truth"};
    }
    if (rows.empty()) return {false, "no rows"};
    return {true, "truth: " + rows.front().truth};
}

// The chart's one dot `label` names (chartRowsMatching), or std::invalid_argument.
size_t oneDot(std::span<const BenchRow> rows, const std::string& label) {
    std::vector<size_t> picked = chartRowsMatching(rows, label);
    if (picked.size() != 1) {
        throw std::invalid_argument("'" + label + "' names " + std::to_string(picked.size()) +
                                    " dots of the chart, not one");
    }
    return picked[0];
}

// "X is the most (least) accurate": X's dot is strictly below (above) every other dot on the
// chart's accuracy axis (the edge RMSE, or near the contacts on a #contact chart).
ChartFactAnswer extremeAccuracy(const ChartData& c, const std::string& label, bool most) {
    std::vector<BenchRow> rows = readChartRows(c.path);
    size_t k = oneDot(rows, label);
    double mine = chartAccuracy(rows[k], c.accuracy);
    for (size_t i = 0; i < rows.size(); ++i) {
        double other = chartAccuracy(rows[i], c.accuracy);
        if (i != k && (most ? other <= mine : other >= mine)) {
            return {false, chartLabel(rows[i].point) + " " + chartTickText(other) + ", " + label +
                               " " + chartTickText(mine)};
        }
    }
    return {true, label + " " + chartTickText(mine)};
}

ChartFactAnswer mostAccurate(const ChartData& c, const std::string& label) {
    return extremeAccuracy(c, label, true);
}

ChartFactAnswer leastAccurate(const ChartData& c, const std::string& label) {
    return extremeAccuracy(c, label, false);
}

// "the front is A, B": the Pareto front the bench chart draws (benchParetoFront of the scene time:
// the dots no other dot beats on both median time and edge RMSE), fastest first, is exactly the
// dots named so (chartLabel's names, comma-separated).
ChartFactAnswer frontIs(const ChartData& c, const std::string& names) {
    std::vector<BenchRow> rows = readChartRows(c.path);
    std::string got;
    for (size_t k : benchParetoFront(rows, false)) {
        got += (got.empty() ? "" : ", ") + chartLabel(rows[k].point);
    }
    return {got == names, "the front is " + (got.empty() ? std::string("empty") : got)};
}

// A fact's words around its one argument: PREFIX ARG SUFFIX; `view` the chart it applies to
// ("" any bench chart, "*" any chart, else a stability chart's name).
struct FactEntry {
    std::string_view prefix;
    std::string_view suffix;
    std::string_view view;
    ChartFactAnswer (*test)(const ChartData&, const std::string& arg);
};

constexpr FactEntry FACTS[] = {
    {"measured on ", "", "*", measuredOn},
    {"measured against the ", " truth", "", againstTruth},
    {"", " is the most accurate", "", mostAccurate},
    {"", " is the least accurate", "", leastAccurate},
    {"the front is ", "", "", frontIs},
    {"", ": acne falls as the bias grows", "tradeoff", acneFalls},
    {"", ": leak grows with the bias", "tradeoff", leakGrows},
    {"", ": a good bias lies between acne and leak", "tradeoff", goodBetween},
    {"", ": over the onset at every elevation", "acne", acneEverywhere},
    {"", " degrees", "acne", acneCrossing},
    {"", ": rises over the onset and falls back", "acne", acneHump},
};

// The entry whose words match `fact` on this chart, and its argument; or invalid_argument.
std::pair<const FactEntry*, std::string> matchFact(const ChartData& c, const std::string& fact) {
    std::string known;
    for (const FactEntry& e : FACTS) {
        bool applies = e.view == "*" || (e.view.empty() ? c.bench : !c.bench && e.view == c.view);
        if (!applies) continue;
        known += std::string(known.empty() ? "" : "; ") + std::string(e.prefix) + "X" +
                 std::string(e.suffix);
        if (fact.size() <= e.prefix.size() + e.suffix.size()) continue;
        if (!fact.starts_with(e.prefix) || !fact.ends_with(e.suffix)) continue;
        return {&e, fact.substr(e.prefix.size(), fact.size() - e.prefix.size() - e.suffix.size())};
    }
    throw std::invalid_argument("unknown chart fact '" + fact +
                                "' (this chart knows: " + (known.empty() ? "none" : known) + ")");
}

}  // namespace

ChartFactAnswer chartFactHolds(const std::string& chart, const std::string& fact) {
    ChartData c = stepChartRef(chart);
    auto [entry, arg] = matchFact(c, fact);
    return entry->test(c, arg);
}

void checkChartFactKnown(const std::string& chart, const std::string& fact) {
    matchFact(stepChartRef(chart), fact);
}

}  // namespace pcf
