// trace_json.cpp: a trace written as JSON and as text (trace_json.h).
#include "kernel/trace_json.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include "kernel/trace_explain.h"

namespace pcf {

namespace {

// The kind is the kernel's plain int (PCF_FETCH_*, shaders/shared/pcf_kernel.h: GLSL has no
// enums), so this switch keeps a default; it names no kind the kernel does not have.
const char* fetchKindName(int kind) {
    switch (kind) {
        case PCF_FETCH_POINT:
            return "texel";
        case PCF_FETCH_LOOKUP:
            return "bilinear";
        case PCF_FETCH_GATHER:
            return "gather";
        case PCF_FETCH_HW:
            return "hw";
        default:
            throw std::out_of_range("fetchKindName: no fetch kind " + std::to_string(kind));
    }
}

}  // namespace

Json jsonNumber(float v) {
    if (!std::isfinite(v)) return nullptr;
    if (v == std::trunc(v) && std::fabs(v) < 1e9f) return static_cast<std::int64_t>(v);
    return v;
}

Json jsonPair(vec2 v) { return Json::array({jsonNumber(v.x), jsonNumber(v.y)}); }
Json jsonPair(ivec2 v) { return Json::array({v.x, v.y}); }

std::string jsonDump(const Json& j) {
    return j.dump(-1, ' ', false, nlohmann::detail::error_handler_t::replace);
}

namespace {

// Receiver-plane bias: where each tap's own ref is taken.
const char* perTapName(const Trace& tr) {
    if (tr.bias.bias != BiasMode::ReceiverPlane) return "none";
    switch (methodInfo(tr.params.method).reads) {
        case MethodReads::Gathers:
            return "per gather, at its centre";
        case MethodReads::HwTaps:
            return "per hardware tap, at its uv";
        case MethodReads::Texels:
            return "per texel, at its centre";
    }
    return "?";
}

// The trace's bias: the mode and every parameter (the table's rows, under the lesson files'
// keys), and the receiver plane as given and as used.
Json biasJson(const Trace& tr) {
    ShadowSettings settings;
    static_cast<BiasSettings&>(settings) = tr.bias;
    Json j = paramsJson(settings, ParamSet::Bias);
    j["dzduv"] = jsonPair(tr.dzduv);
    j["dzduv_used"] =
        jsonPair(tr.bias.bias == BiasMode::ReceiverPlane ? pcfClampDzDuv(tr.dzduv, tr.bias.rpdbMax)
                                                         : tr.dzduv);
    j["per_tap"] = perTapName(tr);
    return j;
}

// Whether paramsJson writes row p for `which`.
bool inParamSet(const ParamInfo& p, ParamSet which) {
    switch (which) {
        case ParamSet::All:
            return true;
        case ParamSet::Raw:
            return p.rawJson;
        case ParamSet::Bias:
            return p.group == ParamGroup::Bias;
    }
    return false;
}

// One object per tap, in read order, and one per fetch instruction.
Json tapsJson(const Trace& tr) {
    Json taps = Json::array();
    for (const TapRecord& t : tr.taps) {
        // A comparison bit as 0 or 1; the soft comparison's fraction as a number.
        Json lit = t.lit == 0.0f || t.lit == 1.0f ? Json(t.lit >= 0.5f ? 1 : 0) : jsonNumber(t.lit);
        taps.push_back({{"texel", jsonPair(t.texel)},
                        {"depth", jsonNumber(t.depth)},
                        {"ref", jsonNumber(t.ref)},
                        {"ref_shift", jsonNumber(t.ref - tr.ref)},
                        {"lit", lit},
                        {"weight", jsonNumber(t.weight)},
                        {"fetch", t.fetch},
                        {"clamped", t.clamped}});
    }
    return taps;
}

Json fetchesJson(const Trace& tr) {
    Json fetches = Json::array();
    for (const FetchRecord& f : tr.fetches) {
        fetches.push_back({{"kind", fetchKindName(f.kind)},
                           {"uv", jsonPair(f.uv)},
                           {"weight", jsonNumber(f.weight)}});
    }
    return fetches;
}

// pcss's blocker search and penumbra estimate, and its search taps in read order (taps[k] for
// k < search_taps) with which found a blocker: a depth below its ref (Fernando 2005), as the
// kernel counted them.
Json pcssJson(const Trace& tr) {
    Json search = Json::array();
    size_t n = std::min(tr.taps.size(), static_cast<size_t>(PCF_PCSS_TAPS));
    for (size_t k = 0; k < n; ++k) {
        const TapRecord& t = tr.taps[k];
        search.push_back({{"tap", k},
                          {"texel", jsonPair(t.texel)},
                          {"depth", jsonNumber(t.depth)},
                          {"blocker", t.lit < 0.5f}});
    }
    return {{"penumbra_scale", jsonNumber(tr.params.penumbraScale)},
            {"depth_near", jsonNumber(tr.params.depthNear)},
            {"depth_far", jsonNumber(tr.params.depthFar)},
            {"search_taps", PCF_PCSS_TAPS},
            {"search_radius", jsonNumber(tr.pcss.searchRadius)},
            {"blockers", tr.pcss.blockers},
            {"blocker_depth", jsonNumber(tr.pcss.blockerDepth)},
            {"penumbra", jsonNumber(tr.pcss.penumbra)},
            {"filter_radius", jsonNumber(tr.pcss.filterRadius)},
            {"search", search}};
}

}  // namespace

Json paramsJson(const ShadowSettings& s, ParamSet which) {
    Json j = Json::object();
    for (const ParamInfo& p : allParams()) {
        if (!inParamSet(p, which)) continue;
        std::visit(
            [&](const auto& field) {
                using F = std::decay_t<decltype(field)>;
                if constexpr (std::is_same_v<F, float ShadowSettings::*>) {
                    j[std::string(p.key)] = jsonNumber(s.*field);
                } else if constexpr (std::is_member_object_pointer_v<F>) {
                    j[std::string(p.key)] = s.*field;
                } else {
                    j[std::string(p.key)] = field.name(s.*field.field);
                }
            },
            p.field);
    }
    return j;
}

Json traceJson(const Trace& tr) {
    Json bias = biasJson(tr);
    Json taps = tapsJson(tr);
    Json fetches = fetchesJson(tr);
    Json weights = Json::array();
    for (float w : tr.weights.values) weights.push_back(jsonNumber(w));
    Json steps = Json::array();
    for (const TraceStep& s : explainTrace(tr)) {
        steps.push_back({{"kind", stepKindName(s.kind)}, {"title", s.title}, {"text", s.text}});
    }
    Json j = {{"method", methodInfo(tr.params.method).name},
              {"kernel", tr.params.kernel},
              {"radius", jsonNumber(tr.params.radius)},
              {"map_size", jsonPair(tr.mapSize)},
              {"uv", jsonPair(tr.uv)},
              {"z", jsonNumber(tr.z)},
              {"ref", jsonNumber(tr.ref)},
              {"bias", bias},
              {"texel", jsonPair(tr.pos.p)},
              {"base", jsonPair(tr.pos.base)},
              {"frac", jsonPair(tr.pos.frac)},
              {"taps", taps},
              {"fetch_list", fetches},
              {"weights",
               {{"origin", jsonPair(tr.weights.origin)},
                {"size", jsonPair(tr.weights.size)},
                {"values", weights}}},
              {"fetches",
               {{"texels", tr.counts.texels},
                {"gathers", tr.counts.gathers},
                {"hw_taps", tr.counts.hwTaps}}},
              {"visibility", jsonNumber(tr.visibility)},
              {"weights_kind", weightsName(tr.params.weights)},
              {"sigma", jsonNumber(tr.params.sigma)},
              {"precision", precisionName(tr.params.precision)},
              {"fixed_point", tr.fixedPoint},
              {"texture_unit",
               {{"frac_exact", jsonPair(tr.pos.frac)},
                {"frac_hw8", jsonPair(tr.fracHw8)},
                {"visibility_exact", jsonNumber(tr.visibilityExact)},
                {"visibility_hw8", jsonNumber(tr.visibilityHw8)}}},
              {"steps", steps}};
    // pcss: the blocker search and the penumbra estimate (its first 16 taps are the search's).
    if (tr.params.method == PCF_PCSS) j["pcss"] = pcssJson(tr);
    return j;
}

std::string traceToJson(const Trace& tr) { return jsonDump(traceJson(tr)); }

namespace {

// The neighbourhood as a table: depth, bit and merged weight per texel, rows as stored.
void writeTexelTable(const Trace& tr, std::ostringstream& s) {
    s << "Texels read (depth / bit / weight), row j down, column i across:\n";
    const WeightGrid& g = tr.weights;
    bool anyClamped = false;
    s << "        ";
    for (int i = 0; i < g.size.x; ++i) {
        char buf[32];
        std::snprintf(buf, sizeof buf, " %-18s", ("i=" + std::to_string(g.origin.x + i)).c_str());
        s << buf;
    }
    s << "\n";
    for (int j = 0; j < g.size.y; ++j) {
        char rowLabel[16];
        std::snprintf(rowLabel, sizeof rowLabel, "  j=%-4d", g.origin.y + j);
        s << rowLabel;
        for (int i = 0; i < g.size.x; ++i) {
            ivec2 texel = g.origin + ivec2(i, j);
            const TapRecord* tap = nullptr;
            for (const TapRecord& t : tr.taps) {
                if (t.texel == texel) {
                    tap = &t;
                    break;
                }
            }
            bool clamped = false;
            for (const TapRecord& t : tr.taps) clamped = clamped || (t.texel == texel && t.clamped);
            anyClamped = anyClamped || clamped;
            std::string cell = tap ? formatNumber(tap->depth) + " / " + formatBit(tap->lit) +
                                         " / " + formatNumber(g.at(texel)) + (clamped ? " *" : "")
                                   : "-";
            char buf[40];
            std::snprintf(buf, sizeof buf, " %-18s", cell.c_str());
            s << buf;
        }
        s << "\n";
    }
    if (anyClamped) s << "* also read for texels outside the map, clamped to the edge\n";
}

}  // namespace

std::string traceToText(const Trace& tr) {
    std::ostringstream s;
    const MethodInfo& info = methodInfo(tr.params.method);
    s << "pcfscope trace: " << info.name;
    if (info.usesKernel) s << ", N = " << tr.params.kernel;
    if (info.usesRadius) s << ", radius " << formatNumber(tr.params.radius) << " texels";
    s << "  (" << info.summary << ")\n\n";
    std::vector<TraceStep> steps = explainTrace(tr);
    for (size_t k = 0; k < steps.size(); ++k) {
        s << k + 1 << ". " << steps[k].title << "\n   ";
        for (char c : steps[k].text) {
            s << c;
            if (c == '\n') s << "   ";
        }
        s << "\n\n";
    }
    writeTexelTable(tr, s);
    s << "\nfetches: " << tr.counts.texels << " texel reads, " << tr.counts.gathers << " gathers, "
      << tr.counts.hwTaps << " hardware taps\n";
    s << "visibility = " << formatNumber(tr.visibility) << "\n";
    if (tr.usesTextureUnit) {
        s << "texture unit: frac " << formatPair(tr.pos.frac) << " -> visibility "
          << formatNumber(tr.visibilityExact) << " (exact); frac " << formatPair(tr.fracHw8)
          << " -> visibility " << formatNumber(tr.visibilityHw8) << " (hw8, 1/256 texel)\n";
    }
    return s.str();
}

}  // namespace pcf
