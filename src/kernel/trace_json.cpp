// trace_json.cpp: a trace written as JSON and as text (trace_json.h).
#include "kernel/trace_json.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
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
// keys), and the receiver plane as given and as the kernel used it.
Json biasJson(const Trace& tr) {
    ShadowSettings settings;
    static_cast<BiasSettings&>(settings) = tr.bias;
    Json j = paramsJson(settings, ParamSet::Bias);
    j["dzduv"] = jsonPair(tr.dzduv);
    j["dzduv_used"] = jsonPair(tr.lookup.bias.dzduv);  // as the kernel took it (pcfLookupRef)
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

// The depths a moment method's moments average (kernel/moment_footprint.h), each texel with its
// weight, and PCF of the same texels at the same ref.
Json footprintJson(const MomentFootprint& f) {
    Json texels = Json::array();
    for (const FootprintTexel& t : f.texels) {
        texels.push_back({{"texel", jsonPair(t.texel)},
                          {"depth", jsonNumber(t.depth)},
                          {"weight", jsonNumber(t.weight)}});
    }
    return {{"texels", texels},
            {"pcf_method", std::string(methodInfo(f.pcfMethod).name)},
            {"pcf_visibility", jsonNumber(f.pcfVisibility)}};
}

// The moment methods: what the filtered moments say (pcfMomentEstimate), and the parameters
// used: the exponents after the clamp to what the map's floats hold (exponent_limit).
Json momentsJson(const Trace& tr) {
    const PcfMomentEstimate& e = tr.moments;
    int bits = texelKindInfo(tr.map.texels).bits;
    Json points = Json::array();
    Json weights = Json::array();
    bool msm = methodInfo(tr.params.method).reconstructs;
    // Hausdorff's four-point distribution ends with the depth 1 (pcfHausdorffEstimate).
    int count = e.points.w == 1.0f ? 4 : 3;
    for (int k = 0; msm && k < count; ++k) {
        points.push_back(jsonNumber(e.points[k]));
        weights.push_back(jsonNumber(e.weights[k]));
    }
    Json j = {{"moments",
               {jsonNumber(e.moments.x), jsonNumber(e.moments.y), jsonNumber(e.moments.z),
                jsonNumber(e.moments.w)}},
              {"mean", jsonNumber(e.mean)},
              {"variance", jsonNumber(e.variance)},
              {"receiver", jsonNumber(e.receiver)},
              {"bound", jsonNumber(e.bound)},
              {"negative_bound", jsonNumber(e.negBound)},
              {"lbr", jsonNumber(tr.params.lbr)},
              {"min_variance", jsonNumber(tr.params.minVariance)},
              {"exponents_used", jsonPair(tr.params.evsmExponents)},
              {"exponent_limit", jsonNumber(evsmExponentLimit(bits))},
              {"moment_bias", jsonNumber(tr.params.momentBias)},
              {"points", points},
              {"point_weights", weights}};
    if (tr.depths.present) j["footprint"] = footprintJson(tr.depths);
    return j;
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

namespace {

// A cascaded map's layers as its cascades (scene/cascade_fit.h): the view depths [n, f] they
// split (n the camera's near plane, f where the last ends: the shadow distance), and each
// cascade's view depths and texel size in world units. Read from the layers, never stored apart.
Json cascadesJson(const MapSpec& map) {
    Json cascades = Json::array();
    for (size_t k = 0; k < map.layers.size(); ++k) {
        const PcfMapLayer& layer = map.layers[k];
        cascades.push_back({{"index", k},
                            {"near", jsonNumber(layer.viewDepth.x)},
                            {"far", jsonNumber(layer.viewDepth.y)},
                            {"texel_world", jsonNumber(layer.texelWs)}});
    }
    return {{"camera_near", jsonNumber(map.layers.front().viewDepth.x)},
            {"shadow_distance", jsonNumber(map.layers.back().viewDepth.y)},
            {"cascades", cascades}};
}

}  // namespace

Json mapSpecJson(const MapSpec& map) {
    Json layers = Json::array();
    for (const PcfMapLayer& layer : map.layers) {
        Json matrix = Json::array();
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r)
                matrix.push_back(jsonNumber(layer.shadowClipFromWorld[c][r]));
        }
        layers.push_back({{"shadow_clip_from_world", matrix},
                          {"depth_range", jsonPair(layer.depthRange)},
                          {"texel_ws", jsonNumber(layer.texelWs)},
                          {"view_depth", jsonPair(layer.viewDepth)}});
    }
    Json j = {
        {"size", jsonPair(map.size)}, {"texels", texelKindName(map.texels)}, {"layers", layers}};
    if (map.layers.size() > 1) j.update(cascadesJson(map));
    return j;
}

namespace {

// A finite JSON number that a float holds, or nullopt.
std::optional<float> jsonFiniteFloat(const Json& v) {
    if (!v.is_number() || !std::isfinite(v.get<double>()) ||
        std::fabs(v.get<double>()) > static_cast<double>(std::numeric_limits<float>::max())) {
        return std::nullopt;
    }
    return v.get<float>();
}

// A JSON array of n such numbers, or nullopt.
std::optional<std::vector<float>> jsonFloats(const Json& j, size_t n) {
    if (!j.is_array() || j.size() != n) return std::nullopt;
    std::vector<float> out;
    for (const Json& v : j) {
        std::optional<float> f = jsonFiniteFloat(v);
        if (!f) return std::nullopt;
        out.push_back(*f);
    }
    return out;
}

std::optional<PcfMapLayer> mapLayerFromJson(const Json& j, std::string& why) {
    auto matrix = j.is_object() && j.contains("shadow_clip_from_world")
                      ? jsonFloats(j["shadow_clip_from_world"], 16)
                      : std::nullopt;
    auto range =
        j.is_object() && j.contains("depth_range") ? jsonFloats(j["depth_range"], 2) : std::nullopt;
    auto texel =
        j.is_object() && j.contains("texel_ws") ? jsonFiniteFloat(j["texel_ws"]) : std::nullopt;
    if (!matrix || !range || !texel) {
        why =
            "a map layer needs shadow_clip_from_world (16 numbers), depth_range (2) and "
            "texel_ws";
        return std::nullopt;
    }
    PcfMapLayer layer = MapSpec::unfittedLayer();
    for (int k = 0; k < 16; ++k) layer.shadowClipFromWorld[k / 4][k % 4] = (*matrix)[k];
    layer.depthRange = vec2((*range)[0], (*range)[1]);
    layer.texelWs = *texel;
    // A cascade's view depths; files written before cascades have none (not a cascade).
    if (j.contains("view_depth")) {
        auto viewDepth = jsonFloats(j["view_depth"], 2);
        if (!viewDepth) {
            why = "a map layer's view_depth is not 2 numbers";
            return std::nullopt;
        }
        layer.viewDepth = vec2((*viewDepth)[0], (*viewDepth)[1]);
    }
    return layer;
}

}  // namespace

std::optional<MapSpec> mapSpecFromJson(const Json& j, std::string& why) {
    if (!j.is_object() || !j.contains("size") || !j.contains("texels") || !j.contains("layers")) {
        why = "\"map\" needs size, texels and layers";
        return std::nullopt;
    }
    MapSpec spec;
    auto size = jsonFloats(j["size"], 2);
    if (!size || (*size)[0] != std::floor((*size)[0]) || (*size)[1] != std::floor((*size)[1]) ||
        (*size)[0] < 1.0f || (*size)[1] < 1.0f || (*size)[0] > 1e6f || (*size)[1] > 1e6f) {
        why = "\"map\": size is not two whole numbers from 1";
        return std::nullopt;
    }
    spec.size = ivec2(static_cast<int>((*size)[0]), static_cast<int>((*size)[1]));
    std::optional<TexelKind> kind =
        j["texels"].is_string() ? texelKindFromName(j["texels"].get<std::string>()) : std::nullopt;
    if (!kind) {
        why = "\"map\": texels is not a texel kind";
        return std::nullopt;
    }
    spec.texels = *kind;
    const Json& layers = j["layers"];
    if (!layers.is_array() || layers.empty() || layers.size() > MAX_MAP_LAYERS) {
        why = "\"map\": layers is not a list of 1 to " + std::to_string(MAX_MAP_LAYERS);
        return std::nullopt;
    }
    spec.layers.clear();
    for (const Json& l : layers) {
        std::optional<PcfMapLayer> layer = mapLayerFromJson(l, why);
        if (!layer) return std::nullopt;
        spec.layers.push_back(*layer);
    }
    return spec;
}

namespace {

// A cascaded map: the cascade read, named apart from the layers so a reader need not look it up
// (the same numbers as "map" -> "cascades"[layer], and the frame's density when measured).
Json cascadeJson(const TraceCascade& c) {
    Json cascade = {{"index", c.index},
                    {"count", c.count},
                    {"near", jsonNumber(c.nearZ)},
                    {"far", jsonNumber(c.farZ)},
                    {"texel_world", jsonNumber(c.texelWs)}};
    if (c.texelsPerPixelMax >= 0.0f) {
        cascade["texels_per_pixel_max"] = jsonNumber(c.texelsPerPixelMax);
    }
    return cascade;
}

}  // namespace

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
              {"map_size", jsonPair(tr.map.size)},
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
              {"fixed_point", tr.map.texel().fixedPoint},
              {"texture_unit",
               {{"frac_exact", jsonPair(tr.pos.frac)},
                {"frac_hw8", jsonPair(tr.fracHw8)},
                {"visibility_exact", jsonNumber(tr.visibilityExact)},
                {"visibility_hw8", jsonNumber(tr.visibilityHw8)}}},
              {"steps", steps}};
    // pcss: the blocker search and the penumbra estimate (its first 16 taps are the search's).
    if (methodInfo(tr.params.method).searchesBlockers) j["pcss"] = pcssJson(tr);
    if (readsMoments(tr.params.method)) j["moments"] = momentsJson(tr);
    j["map"] = mapSpecJson(tr.map);
    j["layer"] = tr.layer;
    if (std::optional<TraceCascade> c = cascadeOfTrace(tr)) j["cascade"] = cascadeJson(*c);
    // A cascaded map: the blend band's second lookup beside the taps of the layer read.
    if (tr.map.layers.size() > 1) {
        j["cascade_blend"] = {{"next_layer", tr.cascadeBlend.next},
                              {"weight", jsonNumber(tr.cascadeBlend.weight)},
                              {"next_visibility", jsonNumber(tr.cascadeBlend.nextVisibility)},
                              {"visibility", jsonNumber(tr.cascadeBlend.blended)}};
    }
    return j;
}

std::string traceToJson(const Trace& tr) { return jsonDump(traceJson(tr)); }

namespace {

// The neighbourhood as a table: depth, bit and merged weight per texel, rows as stored. A moments
// map's texel holds filtered moments, not a depth, and no texel has a bit of its own (the one
// visibility comes from the bound): its first moment and its bilinear weight.
void writeTexelTable(const Trace& tr, std::ostringstream& s) {
    bool moments = methodInfo(tr.params.method).mapPass != MapPass::Depth;
    s << (moments ? "Texels read (first moment m1 / bilinear weight)"
                  : "Texels read (depth / bit / weight)")
      << ", row j down, column i across:\n";
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
            std::string bit = moments || !tap ? "" : " / " + formatBit(tap->lit);
            std::string cell = tap ? formatNumber(tap->depth) + bit + " / " +
                                         formatNumber(g.at(texel)) + (clamped ? " *" : "")
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

std::string cascadeLine(const TraceCascade& c) {
    std::string line = "cascade " + std::to_string(c.index) + " of " + std::to_string(c.count) +
                       " (0 nearest): view depths " + formatNumber(c.nearZ) + " to " +
                       formatNumber(c.farZ) + ", a texel " + formatNumber(c.texelWs) +
                       " world units wide";
    if (c.texelsPerPixelMax >= 0.0f) {
        line += ", at most " + formatNumber(c.texelsPerPixelMax) + " texels per screen pixel";
    }
    return line;
}

std::string traceToText(const Trace& tr) {
    std::ostringstream s;
    const MethodInfo& info = methodInfo(tr.params.method);
    s << "pcfscope trace: " << info.name;
    if (info.usesKernel) s << ", N = " << tr.params.kernel;
    if (info.usesRadius) s << ", radius " << formatNumber(tr.params.radius) << " texels";
    s << "  (" << info.summary << ")\n\n";
    std::optional<TraceCascade> cascade = cascadeOfTrace(tr);
    if (cascade) s << cascadeLine(*cascade) << "\n\n";
    // In a blend band: the next cascade's lookup and the mix (shared/pcf_shading.h
    // pcfCascadeBlend), before the steps of the cascade read's own.
    const TraceCascadeBlend& b = tr.cascadeBlend;
    if (cascade && b.next >= 0) {
        s << "blend band: cascade " << b.next << " looks the point up too and gives "
          << formatNumber(b.nextVisibility) << ", weight " << formatNumber(b.weight)
          << "; the pixel shows (1 - " << formatNumber(b.weight) << ") * "
          << formatNumber(tr.visibility) << " + " << formatNumber(b.weight) << " * "
          << formatNumber(b.nextVisibility) << " = " << formatNumber(b.blended)
          << "; the steps below are cascade " << cascade->index << "'s\n\n";
    }
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
