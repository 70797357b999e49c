#include "charts/chart_facts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "base/input_file.h"
#include "charts/chart_axes.h"
#include "charts/speed_chart.h"
#include "charts/stability_bleed_figures.h"
#include "charts/stability_cascades_figures.h"
#include "charts/stability_chart.h"
#include "charts/stability_figures.h"
#include "charts/step_chart.h"
#include "measure/advise_read.h"
#include "measure/bench_report.h"
#include "measure/stability_bleed.h"
#include "measure/stability_report.h"

namespace pcf {

namespace {

// A chart as the step names it (step_chart.h): the file, the view, bench, stability or advise.
using ChartData = StepChartRef;

// The view of the facts an advise chart answers (FACTS below).
constexpr std::string_view ADVISE_FACTS = "advise.csv";

std::string percent(double share) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g%%", 100.0 * share);
    return buf;
}

// "measured on NAME": the renderer the file records contains NAME.
ChartFactAnswer measuredOn(const ChartData& c, const std::string& name) {
    std::string renderer;
    if (c.kind == StepChartKind::Advise) {
        renderer = readStepAdvise(c).glRenderer;
    } else if (c.bench()) {
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

// The cascades chart's lines (stability_cascades_figures.h, as it draws them): per cascade
// ("cascade K"), its texels per pixel (the median over its receivers) at each lambda swept.
std::vector<ChartLine> cascadeLines(const ChartData& c) {
    std::vector<StabilityRow> rows = parseStabilityCsv(readInputFile(c.path), c.path);
    LineChartSpec spec = cascadeChartSpec(rows, "", 0.0f);
    if (spec.panels.empty()) return {};
    return spec.panels.front().lines;
}

// A number of the words ("0.5"), or std::invalid_argument naming what it should be.
double factNumber(const std::string& text, const char* what) {
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size()) {
        throw std::invalid_argument("'" + text + "' is not " + what);
    }
    return v;
}

// Line `label`'s value at lambda x; nullopt where the line has no point there (its cascade holds
// no receiver on screen).
std::optional<double> cascadeAt(const ChartLine& line, double lambda) {
    for (glm::dvec2 p : line.points) {
        if (std::fabs(p.x - lambda) < 1e-9) return p.y;
    }
    return std::nullopt;
}

std::string cascadeValueText(const ChartLine& line, double lambda) {
    std::optional<double> v = cascadeAt(line, lambda);
    return line.label + " " + (v ? chartTickText(*v) : std::string("none"));
}

// "at lambda L, cascade K reads the fewest texels per pixel" (or "the most"): at L, line
// "cascade K" is strictly below (above) every other line with a point there.
ChartFactAnswer cascadeExtreme(const ChartData& c, const std::string& arg) {
    size_t comma = arg.find(", cascade ");
    size_t verb = arg.find(" reads the ");
    if (comma == std::string::npos || verb == std::string::npos || verb < comma) {
        throw std::invalid_argument(
            "say: at lambda L, cascade K reads the fewest (most) texels "
            "per pixel");
    }
    double lambda = factNumber(arg.substr(0, comma), "a lambda");
    std::string name = "cascade " + arg.substr(comma + 10, verb - comma - 10);
    std::string which = arg.substr(verb + 11);
    if (which != "fewest" && which != "most") {
        throw std::invalid_argument("'" + which + "': say the fewest or the most");
    }
    std::vector<ChartLine> lines = cascadeLines(c);
    auto mine = std::find_if(lines.begin(), lines.end(),
                             [&](const ChartLine& l) { return l.label == name; });
    if (mine == lines.end()) throw std::invalid_argument("'" + name + "' is no line of the chart");
    std::optional<double> v = cascadeAt(*mine, lambda);
    if (!v) return {false, cascadeValueText(*mine, lambda)};
    std::string why;
    bool holds = true;
    for (const ChartLine& other : lines) {
        why += (why.empty() ? "" : ", ") + cascadeValueText(other, lambda);
        std::optional<double> o = cascadeAt(other, lambda);
        if (&other == &*mine || !o) continue;
        if (which == "fewest" ? *o <= *v : *o >= *v) holds = false;
    }
    return {holds, "at lambda " + chartTickText(lambda) + ": " + why};
}

// "at lambda L, cascade K holds no receiver": line "cascade K" has no point at L.
ChartFactAnswer cascadeEmpty(const ChartData& c, const std::string& arg) {
    size_t comma = arg.find(", cascade ");
    if (comma == std::string::npos) {
        throw std::invalid_argument("say: at lambda L, cascade K holds no receiver");
    }
    double lambda = factNumber(arg.substr(0, comma), "a lambda");
    std::string name = "cascade " + arg.substr(comma + 10);
    for (const ChartLine& line : cascadeLines(c)) {
        if (line.label == name) return {!cascadeAt(line, lambda), cascadeValueText(line, lambda)};
    }
    throw std::invalid_argument("'" + name + "' is no line of the chart");
}

// The ratio of the most to the fewest texels per pixel over the cascades at lambda (those with
// a point there), and the words that show it.
std::pair<double, std::string> cascadeSpread(const std::vector<ChartLine>& lines, double lambda) {
    double lo = 0.0, hi = 0.0;
    for (const ChartLine& line : lines) {
        std::optional<double> v = cascadeAt(line, lambda);
        if (!v || !(*v > 0.0)) continue;
        lo = lo > 0.0 ? std::min(lo, *v) : *v;
        hi = std::max(hi, *v);
    }
    double ratio = lo > 0.0 ? hi / lo : 0.0;
    char times[32];
    std::snprintf(times, sizeof times, "%.3gx", ratio);
    return {ratio, "at lambda " + chartTickText(lambda) + " " + chartTickText(lo) + " to " +
                       chartTickText(hi) + " (" + times + ")"};
}

// "the cascades spread less at lambda A than at lambda B": the ratio of the most to the fewest
// texels per pixel over the cascades (those with receivers) is smaller at A than at B, both
// measured on two cascades or more.
ChartFactAnswer cascadesSpreadLess(const ChartData& c, const std::string& arg) {
    size_t than = arg.find(" than at lambda ");
    double a = factNumber(arg.substr(0, than), "a lambda");
    double b = factNumber(arg.substr(than + 16), "a lambda");
    std::vector<ChartLine> lines = cascadeLines(c);
    auto [ra, wa] = cascadeSpread(lines, a);
    auto [rb, wb] = cascadeSpread(lines, b);
    return {ra > 0.0 && rb > 0.0 && ra < rb, wa + "; " + wb};
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

// An advise chart's facts: the folder read back (step_chart.h readStepAdvise), settings named as
// advise names them (adviseSettingName: "hw2x2 map 512 bias none").

// "edge", "edge and shimmer", "edge, acne and leak": constraints as a sentence lists them.
std::string constraintList(const std::vector<AdviseConstraint>& cs) {
    std::string s;
    for (size_t k = 0; k < cs.size(); ++k) {
        s += (k == 0               ? ""
              : k + 1 == cs.size() ? " and "
                                   : ", ") +
             std::string(adviseConstraintName(cs[k]));
    }
    return s.empty() ? "none" : s;
}

// The measured setting `name` names, or std::invalid_argument naming the measured ones.
size_t settingNamed(const AdviseReport& a, const std::string& name) {
    std::string names;
    for (size_t k = 0; k < a.result.measured.size(); ++k) {
        std::string mine = adviseSettingName(a.result.measured[k].setting);
        if (mine == name) return k;
        names += (names.empty() ? "" : ", ") + mine;
    }
    throw std::invalid_argument("'" + name + "' is no setting the chart measured (" + names + ")");
}

std::string nameOf(const AdviseReport& a, std::optional<size_t> k) {
    return k ? adviseSettingName(a.result.measured[*k].setting) : std::string("none");
}

// "the choice is X" / "the runner-up is X".
ChartFactAnswer choiceIs(const ChartData& c, const std::string& name) {
    AdviseReport a = readStepAdvise(c);
    settingNamed(a, name);
    return {nameOf(a, a.result.choice) == name, "the choice is " + nameOf(a, a.result.choice)};
}

// ("the runner-up is none": no other measured setting meets the budget.)
ChartFactAnswer runnerUpIs(const ChartData& c, const std::string& name) {
    AdviseReport a = readStepAdvise(c);
    if (name != "none") settingNamed(a, name);
    return {nameOf(a, a.result.runnerUp) == name,
            "the runner-up is " + nameOf(a, a.result.runnerUp)};
}

// "X meets the budget": X breaks none of its bounds.
ChartFactAnswer meetsBudget(const ChartData& c, const std::string& name) {
    AdviseReport a = readStepAdvise(c);
    const AdviseCandidate& x = a.result.measured[settingNamed(a, name)];
    return {x.feasible(), name + " breaks " + constraintList(x.broken)};
}

// "X breaks the edge and shimmer budget(s)": the bounds X breaks are exactly those.
ChartFactAnswer breaksBudgets(const ChartData& c, const std::string& arg) {
    const std::string verb = " breaks the ";
    size_t at = arg.rfind(verb);
    AdviseReport a = readStepAdvise(c);
    const AdviseCandidate& x = a.result.measured[settingNamed(a, arg.substr(0, at))];
    std::string got = constraintList(x.broken);
    return {got == arg.substr(at + verb.size()), "it breaks " + got};
}

// "the edge and shimmer budgets bind" (or "the edge budget binds"): adviseBinds names those.
ChartFactAnswer budgetsBind(const ChartData& c, const std::string& list) {
    std::string got = constraintList(adviseBinds(readStepAdvise(c).result));
    return {got == list, "binds: " + got};
}

// "X reads N texels": the texel reads per lookup advise.csv records for X (the method table's).
ChartFactAnswer readsTexels(const ChartData& c, const std::string& arg) {
    size_t at = arg.rfind(" reads ");
    AdviseReport a = readStepAdvise(c);
    const AdviseCandidate& x = a.result.measured[settingNamed(a, arg.substr(0, at))];
    return {std::to_string(x.texelReads) == arg.substr(at + 7),
            "it reads " + std::to_string(x.texelReads)};
}

// "the search measured M of G settings": the CSV's settings and advise.json's grid_size.
ChartFactAnswer measuredOf(const ChartData& c, const std::string& counts) {
    AdviseReport a = readStepAdvise(c);
    std::string got =
        std::to_string(a.result.measured.size()) + " of " + std::to_string(a.result.gridSize);
    return {got == counts, "measured " + got};
}

// "N settings meet the budget".
ChartFactAnswer feasibleCount(const ChartData& c, const std::string& count) {
    AdviseReport a = readStepAdvise(c);
    size_t n = static_cast<size_t>(std::count_if(a.result.measured.begin(), a.result.measured.end(),
                                                 [](const auto& m) { return m.feasible(); }));
    return {std::to_string(n) == count, std::to_string(n) + " meet it"};
}

// "the budget is edge 0.1, acne 0.01, leak 2, shimmer 0.5": each bound advise.json sets, in
// the constraints' order, as chartTickText writes a number.
ChartFactAnswer budgetIs(const ChartData& c, const std::string& words) {
    AdviseReport a = readStepAdvise(c);
    std::string got;
    for (AdviseConstraint k : ALL_ADVISE_CONSTRAINTS) {
        if (std::optional<double> limit = adviseLimit(a.budget, k)) {
            got += (got.empty() ? "" : ", ") + std::string(adviseConstraintName(k)) + " " +
                   chartTickText(*limit);
        }
    }
    return {got == words, "the budget is " + got};
}

// "the timer cannot order X and Y": the choice's tie (AdviseResult::tied) is exactly X and Y.
ChartFactAnswer timerTie(const ChartData& c, const std::string& pair) {
    size_t and_ = pair.find(" and ");
    AdviseReport a = readStepAdvise(c);
    std::vector<size_t> named = {settingNamed(a, pair.substr(0, and_)),
                                 settingNamed(a, pair.substr(and_ + 5))};
    std::vector<size_t> tied = a.result.tied;
    std::sort(named.begin(), named.end());
    std::sort(tied.begin(), tied.end());
    std::string got;
    for (size_t k : tied) got += (got.empty() ? "" : ", ") + nameOf(a, k);
    return {named == tied, "tied: " + (got.empty() ? std::string("none") : got)};
}

// "X costs more than Y": X's cost median is above Y's and their spreads (median -+ IQR/2) lie
// apart, so the timer can order them.
ChartFactAnswer costsMore(const ChartData& c, const std::string& pair) {
    size_t than = pair.find(" costs more than ");
    AdviseReport a = readStepAdvise(c);
    const AdviseMetrics& x = a.result.measured[settingNamed(a, pair.substr(0, than))].metrics;
    const AdviseMetrics& y = a.result.measured[settingNamed(a, pair.substr(than + 17))].metrics;
    return {x.costMs > y.costMs && !adviseSpreadsOverlap(x, y),
            chartTickText(x.costMs) + " ms (IQR " + chartTickText(x.costIqr) + ") against " +
                chartTickText(y.costMs) + " ms (IQR " + chartTickText(y.costIqr) + ")"};
}

// A fact's words around its one argument: PREFIX ARG SUFFIX; `view` the chart it applies to
// ("" any bench chart, "*" any chart, ADVISE_FACTS an advise chart, else a stability chart's
// name).
// The bleed chart's line `label` ("vsm 5x5") over setting `key` at the chart's gap, or
// std::invalid_argument naming the lines.
BleedSeries bleedLineOf(const ChartData& c, const std::string& label, const std::string& key) {
    // A step that names its panels ("#bleed:lbr") shows no line of the others.
    if (!c.panels.empty() && std::find(c.panels.begin(), c.panels.end(), key) == c.panels.end()) {
        throw std::invalid_argument("the chart shows no '" + key + "' panel (it names " +
                                    chartPanelList(c.panels) + ")");
    }
    std::vector<StabilityRow> rows = parseStabilityCsv(readInputFile(c.path), c.path);
    std::vector<BleedPoint> points = bleedPoints(rows);
    std::string names;
    for (const BleedSeries& s : bleedSeries(points, bleedChartGap(rows))) {
        std::string name = chartMethodLabel(s.method, s.kernel);
        if (name == label && s.key == key) return s;
        if (!s.key.empty()) names += (names.empty() ? "" : ", ") + name + " over " + s.key;
    }
    throw std::invalid_argument(
        "'" + label + "' over '" + key +
        "' is no line of the bleed chart (lines: " + (names.empty() ? "none" : names) + ")");
}

// "vsm 5x5: leak falls under 0.001 from lbr 0.3": the line's first value with its leak's 99th
// percentile under BLEED_LEAK_TARGET is that value.
ChartFactAnswer bleedCleanFrom(const ChartData& c, const std::string& arg) {
    const std::string infix = ": leak falls under " + chartTickText(BLEED_LEAK_TARGET) + " from ";
    size_t at = arg.find(infix);
    std::string setting = arg.substr(at + infix.size());
    size_t space = setting.find(' ');
    if (space == std::string::npos) {
        throw std::invalid_argument("'" + setting + "' is no setting and value (lbr 0.3)");
    }
    BleedSeries s = bleedLineOf(c, arg.substr(0, at), setting.substr(0, space));
    const BleedPoint* clean = firstCleanPoint(s);
    if (!clean) return {false, "its leak stays at or over the target at every value"};
    return {clean->value == setting.substr(space + 1),
            "first under it at " + clean->value + " (leak " + chartTickText(clean->leakP99) + ")"};
}

struct FactEntry {
    std::string_view prefix;
    std::string_view suffix;
    std::string_view view;
    ChartFactAnswer (*test)(const ChartData&, const std::string& arg);
    // Words the argument must hold (its two parts' joint: "X costs more than Y"); "" none.
    std::string_view infix = {};
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
    {"", "", "bleed", bleedCleanFrom, ": leak falls under 0.001 from "},
    {"at lambda ", " texels per pixel", "cascades", cascadeExtreme},
    {"at lambda ", " holds no receiver", "cascades", cascadeEmpty},
    {"the cascades spread less at lambda ", "", "cascades", cascadesSpreadLess, " than at lambda "},
    {"the choice is ", "", ADVISE_FACTS, choiceIs},
    {"the runner-up is ", "", ADVISE_FACTS, runnerUpIs},
    {"", " settings meet the budget", ADVISE_FACTS, feasibleCount},
    {"", " meets the budget", ADVISE_FACTS, meetsBudget},
    {"", " budgets", ADVISE_FACTS, breaksBudgets, " breaks the "},
    {"", " budget", ADVISE_FACTS, breaksBudgets, " breaks the "},
    {"the ", " budgets bind", ADVISE_FACTS, budgetsBind},
    {"the ", " budget binds", ADVISE_FACTS, budgetsBind},
    {"the search measured ", " settings", ADVISE_FACTS, measuredOf, " of "},
    {"", " texels", ADVISE_FACTS, readsTexels, " reads "},
    {"the budget is ", "", ADVISE_FACTS, budgetIs},
    {"the timer cannot order ", "", ADVISE_FACTS, timerTie, " and "},
    {"", "", ADVISE_FACTS, costsMore, " costs more than "},
};

// The entry whose words match `fact` on this chart, and its argument; or invalid_argument.
std::pair<const FactEntry*, std::string> matchFact(const ChartData& c, const std::string& fact) {
    std::string known;
    for (const FactEntry& e : FACTS) {
        bool applies = e.view == "*" ||
                       (e.view == ADVISE_FACTS ? c.kind == StepChartKind::Advise
                        : e.view.empty()       ? c.bench()
                                         : c.kind == StepChartKind::Stability && e.view == c.view);
        if (!applies) continue;
        known += std::string(known.empty() ? "" : "; ") + std::string(e.prefix) + "X" +
                 (e.infix.empty() ? "" : std::string(e.infix) + "Y") + std::string(e.suffix);
        if (fact.size() <= e.prefix.size() + e.suffix.size()) continue;
        if (!fact.starts_with(e.prefix) || !fact.ends_with(e.suffix)) continue;
        std::string arg =
            fact.substr(e.prefix.size(), fact.size() - e.prefix.size() - e.suffix.size());
        if (!e.infix.empty() && arg.find(e.infix) == std::string::npos) continue;
        return {&e, arg};
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
