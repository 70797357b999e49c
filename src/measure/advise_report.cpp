#include "measure/advise_report.h"

#include <cstdio>
#include <variant>

#include "kernel/settings.h"
#include "kernel/trace_json.h"
#include "measure/advise_measure.h"

namespace pcf {

const char* const ADVISE_CSV_HEADER =
    "method,kernel,weights,sigma,map_size,bias,bias_amount,texel_reads,edge_rmse,acne_share,"
    "leak_texels,shimmer_p99,cost_ms,cost_iqr_ms,feasible,broken,chosen,rmse,max_err,"
    "edge_max_err,acne_darkening,acne_pixels,leak_share,leak_world,leak_pixels,shimmer_mean,"
    "flicker_share,lookup_ms,lookup_ms_iqr,lookup_cpu_ms,noisy,retimed";

namespace {

// "leak+shimmer", or "-" for none.
std::string brokenText(const AdviseCandidate& c) {
    std::string s;
    for (AdviseConstraint k : c.broken)
        s += (s.empty() ? "" : "+") + std::string(adviseConstraintName(k));
    return s.empty() ? "-" : s;
}

std::string csvLine(const AdviseCandidate& c, const BenchRow& r, bool chosen) {
    const AdviseSetting& s = c.setting;
    const AdviseMetrics& m = c.metrics;
    char line[1024];
    std::snprintf(
        line, sizeof line,
        "%s,%d,%s,%g,%d,%s,%g,%d,%.6f,%.6f,%.4f,%.6f,%.5f,%.5f,%d,%s,%d,%.6f,%.6f,%.6f,%.6f,%d,"
        "%.6f,%.5f,%d,%.6f,%.6f,%.5f,%.5f,%.5f,%d,%d\n",
        std::string(methodInfo(s.filter.method).name).c_str(), s.filter.kernel,
        std::string(weightsName(s.filter.weights)).c_str(), static_cast<double>(s.filter.sigma),
        s.mapSize, std::string(biasName(static_cast<int>(s.bias.mode))).c_str(),
        static_cast<double>(s.bias.amount), c.texelReads, m.edgeRmse, m.acneShare, m.leakTexels,
        m.shimmerP99, m.costMs, m.costIqr, c.feasible() ? 1 : 0, brokenText(c).c_str(),
        chosen ? 1 : 0, r.error.rmse, r.error.maxErr, r.error.edgeMaxErr, r.acne.mean, r.acne.count,
        r.leak.share, r.leakWidth.world, r.leakWidth.support, r.shimmer.mean,
        r.shimmer.flickerShare, r.lookupMs, r.lookupMsIqr, r.lookupCpuMs, r.noisy ? 1 : 0,
        c.retimed ? 1 : 0);
    return line;
}

Json budgetJson(const AdviseBudget& b) {
    Json j = Json::object();
    for (AdviseConstraint c : ALL_ADVISE_CONSTRAINTS) {
        std::optional<double> limit = adviseLimit(b, c);
        j[adviseConstraintName(c)] = limit ? Json(static_cast<float>(*limit)) : Json(nullptr);
    }
    return j;
}

Json candidateJson(const AdviseCandidate& c, const AdviseBudget& budget) {
    const AdviseSetting& s = c.setting;
    Json j = Json::object();
    j["method"] = std::string(methodInfo(s.filter.method).name);
    j["kernel"] = s.filter.kernel;
    j["weights"] = std::string(weightsName(s.filter.weights));
    if (s.filter.weights == PCF_WEIGHTS_GAUSSIAN) j["sigma"] = jsonNumber(s.filter.sigma);
    j["map_size"] = s.mapSize;
    j["bias"] = std::string(biasName(static_cast<int>(s.bias.mode)));
    Json amounts = Json::object();
    if (const char* key = adviseBiasKey(s.bias.mode); *key != '\0') {
        amounts[key] = jsonNumber(s.bias.amount);
    }
    j["bias_amounts"] = amounts;
    j["texel_reads"] = c.texelReads;
    Json metrics = Json::object();
    for (AdviseConstraint k : ALL_ADVISE_CONSTRAINTS) {
        const char* names[] = {"edge_rmse", "acne_share", "leak_texels", "shimmer_p99"};
        metrics[names[static_cast<int>(k)]] = static_cast<float>(c.metrics.value(k));
    }
    metrics["cost_ms"] = static_cast<float>(c.metrics.costMs);
    metrics["cost_iqr_ms"] = static_cast<float>(c.metrics.costIqr);
    metrics["cost_retimed"] = c.retimed;
    j["metrics"] = metrics;
    j["feasible"] = c.feasible();
    Json broken = Json::array();
    for (AdviseConstraint k : c.broken) broken.push_back(adviseBreakText(c, k, budget));
    j["broken"] = broken;
    return j;
}

}  // namespace

std::string adviseCsv(const AdviseResult& result, const std::vector<BenchRow>& rows) {
    std::string csv = std::string(ADVISE_CSV_HEADER) + "\n";
    for (size_t k = 0; k < result.measured.size() && k < rows.size(); ++k) {
        csv += csvLine(result.measured[k], rows[k], result.choice && *result.choice == k);
    }
    return csv;
}

std::string adviseJson(const AdviseResult& result, const AdviseBudget& budget,
                       const AdviseContext& context) {
    Json j = Json::object();
    j["scene"] = context.scene;
    j["frame"] = Json::array({context.frameWidth, context.frameHeight});
    j["truth"] = context.truth;
    j["gl_renderer"] = context.glRenderer;
    j["cost"] = "lookup pass process CPU time, ms (median and IQR)";
    j["budget"] = budgetJson(budget);
    j["grid_size"] = result.gridSize;
    j["measured"] = result.measured.size();
    auto candidate = [&](const std::optional<size_t>& k) {
        return k ? candidateJson(result.measured[*k], budget) : Json(nullptr);
    };
    j["choice"] = candidate(result.choice);
    j["runner_up"] = candidate(result.runnerUp);
    j["binding"] = adviseBinding(result, budget);
    j["tie"] = adviseTieNote(result);
    Json all = Json::array();
    for (const AdviseCandidate& c : result.measured) all.push_back(candidateJson(c, budget));
    j["candidates"] = all;
    return j.dump(2) + "\n";
}

namespace {

// `key = value` with the parameter table's text, names quoted.
std::string tomlLine(std::string_view key, const ShadowSettings& s) {
    const ParamInfo* p = findParam(key);
    if (p == nullptr) return "";
    bool named = !std::holds_alternative<int ShadowSettings::*>(p->field) &&
                 !std::holds_alternative<float ShadowSettings::*>(p->field) &&
                 !std::holds_alternative<bool ShadowSettings::*>(p->field);
    std::string value = settingText(*p, s);
    return std::string(key) + " = " + (named ? "\"" + value + "\"" : value) + "\n";
}

}  // namespace

std::string adviseSettingsToml(const AdviseSetting& setting, const RenderSettings& base) {
    RenderSettings s = adviseBiasSettings(base, setting.bias);
    s.method = setting.filter.method;
    s.kernel = setting.filter.kernel > 0 ? setting.filter.kernel : s.kernel;
    s.weights = setting.filter.weights;
    if (setting.filter.weights == PCF_WEIGHTS_GAUSSIAN) s.sigma = setting.filter.sigma;
    s.mapSize = setting.mapSize;
    const MethodInfo& m = methodInfo(s.method);
    std::string toml = "# pcfscope advise: " + adviseSettingName(setting) + "\n[settings]\n";
    toml += tomlLine("method", s);
    if (m.usesKernel) toml += tomlLine("kernel", s);
    if (m.takesWeights) toml += tomlLine("weights", s);
    if (m.takesWeights && s.weights == PCF_WEIGHTS_GAUSSIAN) toml += tomlLine("sigma", s);
    toml += tomlLine("map_size", s);
    toml += tomlLine("bias", s);
    if (setting.bias.mode != BiasMode::None) toml += tomlLine("constant_bias", s);
    if (setting.bias.mode == BiasMode::Normal) toml += tomlLine("normal_offset", s);
    ShadowSettings defaults;
    for (std::string_view key : {"cull", "depth_format"}) {
        const ParamInfo* p = findParam(key);
        if (p != nullptr && settingText(*p, s) != settingText(*p, defaults)) {
            toml += tomlLine(key, s);
        }
    }
    return toml;
}

}  // namespace pcf
