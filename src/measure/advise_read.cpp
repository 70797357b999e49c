#include "measure/advise_read.h"

#include <cmath>
#include <limits>

#include "base/input_error.h"
#include "kernel/trace_json.h"
#include "measure/advise_report.h"
#include "measure/csv_lines.h"

namespace pcf {

namespace {

// advise.csv's columns, by name (ADVISE_CSV_HEADER's order).
enum Column : size_t {
    METHOD,
    KERNEL,
    WEIGHTS,
    SIGMA,
    MAP_SIZE,
    BIAS,
    BIAS_AMOUNT,
    TEXEL_READS,
    EDGE_RMSE,
    ACNE_SHARE,
    LEAK_TEXELS,
    SHIMMER_P99,
    COST_MS,
    COST_IQR_MS,
    FEASIBLE,
    BROKEN,
    CHOSEN,
    RMSE,
    MAX_ERR,
    EDGE_MAX_ERR,
    ACNE_DARKENING,
    ACNE_PIXELS,
    LEAK_SHARE,
    LEAK_WORLD,
    LEAK_PIXELS,
    SHIMMER_MEAN,
    FLICKER_SHARE,
    LOOKUP_MS,
    LOOKUP_MS_IQR,
    LOOKUP_CPU_MS,
    NOISY,
    RETIMED,
    COLUMNS
};

// "leak+shimmer" or "-", as advise_report.cpp writes a candidate's broken budgets.
std::string brokenText(const std::vector<AdviseConstraint>& broken) {
    std::string s;
    for (AdviseConstraint k : broken)
        s += (s.empty() ? "" : "+") + std::string(adviseConstraintName(k));
    return s.empty() ? "-" : s;
}

// The setting a line names; its names must be the method, weights and bias tables'.
AdviseSetting settingOf(const CsvFields& f) {
    std::optional<int> method = methodFromName(f.text(METHOD));
    if (!method) f.fail("unknown method '" + f.text(METHOD) + "'");
    std::optional<int> weights = weightsFromName(f.text(WEIGHTS));
    if (!weights) f.fail("unknown weights '" + f.text(WEIGHTS) + "'");
    std::optional<int> bias = biasFromName(f.text(BIAS));
    if (!bias) f.fail("unknown bias '" + f.text(BIAS) + "'");
    AdviseSetting s;
    s.filter = {*method, f.count(KERNEL), *weights, static_cast<float>(f.measure(SIGMA))};
    s.mapSize = f.count(MAP_SIZE);
    s.bias = {static_cast<BiasMode>(*bias), static_cast<float>(f.measure(BIAS_AMOUNT))};
    return s;
}

// One line: the candidate (its broken budgets derived from the budget and checked against the
// line's own marks) and its bench row.
std::pair<AdviseCandidate, BenchRow> candidateOf(const CsvFields& f, const AdviseBudget& budget) {
    AdviseCandidate c;
    c.setting = settingOf(f);
    c.texelReads = f.count(TEXEL_READS);
    AdviseMetrics& m = c.metrics;
    m.edgeRmse = f.measure(EDGE_RMSE);
    m.acneShare = f.measure(ACNE_SHARE);
    m.leakTexels = f.measure(LEAK_TEXELS);
    m.shimmerP99 = f.measure(SHIMMER_P99);
    m.costMs = f.measure(COST_MS);
    m.costIqr = f.measure(COST_IQR_MS);
    c.retimed = f.flag(RETIMED);
    c.broken = adviseBroken(budget, m);
    if (brokenText(c.broken) != f.text(BROKEN) || c.feasible() != f.flag(FEASIBLE)) {
        f.fail("marked '" + f.text(BROKEN) + "', but advise.json's budget gives '" +
               brokenText(c.broken) + "'");
    }
    BenchRow r;
    r.point = {c.setting.filter.method, c.setting.filter.kernel, c.setting.mapSize,
               c.setting.filter.weights, c.setting.filter.sigma};
    r.texelReads = c.texelReads;
    r.error = {f.measure(RMSE), f.measure(MAX_ERR), m.edgeRmse, f.measure(EDGE_MAX_ERR), 0, 0};
    r.acne = {m.acneShare, f.measure(ACNE_DARKENING), f.count(ACNE_PIXELS)};
    r.leak.share = f.measure(LEAK_SHARE);
    r.leakWidth = {m.leakTexels, f.measure(LEAK_WORLD), f.count(LEAK_PIXELS), 0};
    r.shimmer.mean = f.measure(SHIMMER_MEAN);
    r.shimmer.p99 = m.shimmerP99;
    r.shimmer.flickerShare = f.measure(FLICKER_SHARE);
    // The cost the search compared stands in the lookup time (advise_chart.h adviseChartRows
    // puts it there again): the chart's x axis.
    r.lookupMs = m.costMs;
    r.lookupMsIqr = m.costIqr;
    r.noisy = f.flag(NOISY);
    return {c, r};
}

double jsonMeasure(const Json& j, const char* key, const std::string& source) {
    auto it = j.find(key);
    if (it == j.end() || !it->is_number() || !std::isfinite(it->get<double>()) ||
        it->get<double>() < 0.0) {
        throw InputError(source, 0, std::string("\"") + key + "\" is not a number 0 or more");
    }
    return it->get<double>();
}

std::string jsonString(const Json& j, const char* key, const std::string& source) {
    auto it = j.find(key);
    if (it == j.end() || !it->is_string()) {
        throw InputError(source, 0, std::string("\"") + key + "\" is not a string");
    }
    return it->get<std::string>();
}

// advise.json's budget: each constraint's bound, null for one not checked; the edge is required.
AdviseBudget budgetOf(const Json& j, const std::string& source) {
    auto it = j.find("budget");
    if (it == j.end() || !it->is_object()) throw InputError(source, 0, "no \"budget\" object");
    AdviseBudget b;
    b.maxEdgeRmse = jsonMeasure(*it, adviseConstraintName(AdviseConstraint::Edge), source);
    std::optional<double>* optional[] = {nullptr, &b.maxAcne, &b.maxLeakTexels, &b.maxShimmer};
    for (AdviseConstraint c : ALL_ADVISE_CONSTRAINTS) {
        std::optional<double>* bound = optional[static_cast<size_t>(c)];
        const char* key = adviseConstraintName(c);
        if (bound == nullptr || !it->contains(key) || (*it)[key].is_null()) continue;
        *bound = jsonMeasure(*it, key, source);
    }
    return b;
}

}  // namespace

AdviseReport parseAdviseReport(std::string_view csvText, const std::string& csvSource,
                               std::string_view jsonText, const std::string& jsonSource) {
    Json j = Json::parse(jsonText, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        throw InputError(jsonSource, 0, "not a JSON object (advise.json)");
    }
    AdviseReport report;
    report.budget = budgetOf(j, jsonSource);
    report.scene = jsonString(j, "scene", jsonSource);
    report.truth = jsonString(j, "truth", jsonSource);
    report.glRenderer = jsonString(j, "gl_renderer", jsonSource);
    double grid = jsonMeasure(j, "grid_size", jsonSource);
    if (grid != std::floor(grid) || grid > std::numeric_limits<int>::max()) {
        throw InputError(jsonSource, 0, "\"grid_size\" is not a whole number");
    }
    report.result.gridSize = static_cast<size_t>(grid);
    std::vector<CsvLine> lines = csvLines(csvText);
    if (lines.empty() || lines.front().text != ADVISE_CSV_HEADER) {
        throw InputError(
            csvSource, 1,
            "not an advise.csv header: expected '" + std::string(ADVISE_CSV_HEADER) + "'");
    }
    std::optional<size_t> chosen;
    for (size_t k = 1; k < lines.size(); ++k) {
        if (lines[k].text.empty()) continue;
        CsvFields f(lines[k].text, csvSource, lines[k].number);
        if (f.size() != COLUMNS) {
            f.fail("expected " + std::to_string(COLUMNS) + " fields, got " +
                   std::to_string(f.size()));
        }
        auto [c, r] = candidateOf(f, report.budget);
        r.glRenderer = report.glRenderer;
        r.truth = report.truth;
        if (f.flag(CHOSEN)) {
            if (chosen) f.fail("a second setting marked chosen");
            chosen = report.result.measured.size();
        }
        report.result.measured.push_back(c);
        report.rows.push_back(r);
    }
    if (report.result.measured.empty()) throw InputError(csvSource, 0, "no settings measured");
    if (report.result.measured.size() > report.result.gridSize) {
        throw InputError(jsonSource, 0,
                         "\"grid_size\" " + std::to_string(report.result.gridSize) +
                             " is less than the " + std::to_string(report.result.measured.size()) +
                             " settings of " + csvSource);
    }
    chooseAdvice(report.result, report.budget);
    if (report.result.choice != chosen) {
        throw InputError(csvSource, 0,
                         "the setting marked chosen is not the one its measures and advise.json's "
                         "budget choose");
    }
    report.binding = adviseBinding(report.result, report.budget);
    return report;
}

}  // namespace pcf
