// trace_json.cpp: a trace written as JSON and as text (trace_json.h).
#include "kernel/trace_json.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "kernel/trace_explain.h"

namespace pcf {

namespace {

// JSON numbers: enough digits to round-trip a float.
std::string jnum(float v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
    return buf;
}
std::string jvec(vec2 v) { return "[" + jnum(v.x) + "," + jnum(v.y) + "]"; }
std::string jvec(ivec2 v) { return "[" + std::to_string(v.x) + "," + std::to_string(v.y) + "]"; }
}  // namespace

std::string jsonQuote(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    out += buf;
                } else {
                    out += c;
                }
        }
    }
    return out + "\"";
}

namespace {

std::string jstr(const std::string& s) { return jsonQuote(s); }
std::string num(float v) { return formatNumber(v); }
std::string pair(vec2 v) { return "(" + num(v.x) + ", " + num(v.y) + ")"; }
// A comparison's result: the bit, or the soft comparison's fraction.
std::string bit(float lit) {
    if (lit == 0.0f || lit == 1.0f) return lit >= 0.5f ? "1" : "0";
    return formatNumber(lit);
}

const char* fetchKindName(int kind) {
    switch (kind) {
        case PCF_FETCH_POINT:
            return "texel";
        case PCF_FETCH_LOOKUP:
            return "bilinear";
        case PCF_FETCH_GATHER:
            return "gather";
        default:
            return "hw";
    }
}

}  // namespace

std::string traceToJson(const Trace& tr) {
    std::ostringstream s;
    s << "{\"method\":" << jstr(std::string(methodInfo(tr.params.method).name))
      << ",\"kernel\":" << tr.params.kernel << ",\"radius\":" << jnum(tr.params.radius)
      << ",\"map_size\":" << jvec(tr.mapSize) << ",\"uv\":" << jvec(tr.uv)
      << ",\"z\":" << jnum(tr.z) << ",\"ref\":" << jnum(tr.ref)
      << ",\"bias\":{\"mode\":" << jstr(std::string(biasName(tr.bias.mode)))
      << ",\"constant\":" << jnum(tr.bias.constant) << ",\"slope\":" << jnum(tr.bias.slope)
      << ",\"slope_max\":" << jnum(tr.bias.slopeMax)
      << ",\"normal_offset\":" << jnum(tr.bias.normalOffset)
      << ",\"soft_scale\":" << jnum(tr.bias.softScale) << ",\"dzduv\":" << jvec(tr.bias.dzduv)
      << ",\"per_tap\":"
      << (tr.bias.mode != PCF_BIAS_RECEIVER_PLANE ? "\"none\""
          : tr.params.method == PCF_GATHER        ? "\"per gather, at its centre\""
          : tr.params.method == PCF_HW2X2 || tr.params.method == PCF_HW ||
                  tr.params.method == PCF_TENT
              ? "\"per hardware tap, at its uv\""
              : "\"per texel, at its centre\"")
      << "},\"texel\":" << jvec(tr.pos.p) << ",\"base\":" << jvec(tr.pos.base)
      << ",\"frac\":" << jvec(tr.pos.frac) << ",\"taps\":[";
    for (size_t k = 0; k < tr.taps.size(); ++k) {
        const TapRecord& t = tr.taps[k];
        s << (k ? "," : "") << "{\"texel\":" << jvec(t.texel) << ",\"depth\":" << jnum(t.depth)
          << ",\"ref\":" << jnum(t.ref) << ",\"ref_shift\":" << jnum(t.ref - tr.ref) << ",\"lit\":"
          << (t.lit == 0.0f || t.lit == 1.0f ? std::to_string(t.lit >= 0.5f ? 1 : 0) : jnum(t.lit))
          << ",\"weight\":" << jnum(t.weight) << ",\"fetch\":" << t.fetch
          << ",\"clamped\":" << (t.clamped ? "true" : "false") << "}";
    }
    s << "],\"fetch_list\":[";
    for (size_t k = 0; k < tr.fetches.size(); ++k) {
        const FetchRecord& f = tr.fetches[k];
        s << (k ? "," : "") << "{\"kind\":\"" << fetchKindName(f.kind) << "\",\"uv\":" << jvec(f.uv)
          << ",\"weight\":" << jnum(f.weight) << "}";
    }
    s << "],\"weights\":{\"origin\":" << jvec(tr.weights.origin)
      << ",\"size\":" << jvec(tr.weights.size) << ",\"values\":[";
    for (size_t k = 0; k < tr.weights.values.size(); ++k) {
        s << (k ? "," : "") << jnum(tr.weights.values[k]);
    }
    s << "]},\"fetches\":{\"texels\":" << tr.counts.texels << ",\"gathers\":" << tr.counts.gathers
      << ",\"hw_taps\":" << tr.counts.hwTaps << "},\"visibility\":" << jnum(tr.visibility)
      << ",\"weights_kind\":" << jstr(std::string(weightsName(tr.params.weights)))
      << ",\"sigma\":" << jnum(tr.params.sigma)
      << ",\"precision\":" << jstr(std::string(precisionName(tr.params.precision)))
      << ",\"fixed_point\":" << (tr.fixedPoint ? "true" : "false")
      << ",\"texture_unit\":{\"frac_exact\":" << jvec(tr.pos.frac)
      << ",\"frac_hw8\":" << jvec(tr.fracHw8)
      << ",\"visibility_exact\":" << jnum(tr.visibilityExact)
      << ",\"visibility_hw8\":" << jnum(tr.visibilityHw8) << "}"
      << ",\"steps\":[";
    for (size_t k = 0; k < tr.steps.size(); ++k) {
        s << (k ? "," : "") << "{\"kind\":" << jstr(stepKindName(tr.steps[k].kind))
          << ",\"title\":" << jstr(tr.steps[k].title) << ",\"text\":" << jstr(tr.steps[k].text)
          << "}";
    }
    s << "]}";
    return s.str();
}

std::string traceToText(const Trace& tr) {
    std::ostringstream s;
    const MethodInfo& info = methodInfo(tr.params.method);
    s << "pcfscope trace: " << info.name;
    if (info.usesKernel) s << ", N = " << tr.params.kernel;
    if (info.usesRadius) s << ", radius " << num(tr.params.radius) << " texels";
    s << "  (" << info.summary << ")\n\n";
    for (size_t k = 0; k < tr.steps.size(); ++k) {
        s << k + 1 << ". " << tr.steps[k].title << "\n   ";
        for (char c : tr.steps[k].text) {
            s << c;
            if (c == '\n') s << "   ";
        }
        s << "\n\n";
    }
    // The neighbourhood as a table: depth, bit and merged weight per texel, rows as stored.
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
            std::string cell = tap ? num(tap->depth) + " / " + bit(tap->lit) + " / " +
                                         num(g.at(texel)) + (clamped ? " *" : "")
                                   : "-";
            char buf[40];
            std::snprintf(buf, sizeof buf, " %-18s", cell.c_str());
            s << buf;
        }
        s << "\n";
    }
    if (anyClamped) s << "* also read for texels outside the map, clamped to the edge\n";
    s << "\nfetches: " << tr.counts.texels << " texel reads, " << tr.counts.gathers << " gathers, "
      << tr.counts.hwTaps << " hardware taps\n";
    s << "visibility = " << num(tr.visibility) << "\n";
    if (tr.usesTextureUnit) {
        s << "texture unit: frac " << pair(tr.pos.frac) << " -> visibility "
          << num(tr.visibilityExact) << " (exact); frac " << pair(tr.fracHw8) << " -> visibility "
          << num(tr.visibilityHw8) << " (hw8, 1/256 texel)\n";
    }
    return s.str();
}

}  // namespace pcf
