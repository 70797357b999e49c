#include "lesson/lesson_text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

namespace pcf {

namespace {

// A placeholder's value: a number (integers kept apart so that they print without decimals), a
// piece of text, or nothing (an index past the trace's reads).
struct Value {
    enum Kind { Number, Integer, Text, Missing } kind = Missing;
    double number = 0.0;
    std::string text;
};

Value number(double v) { return {Value::Number, v, {}}; }
Value integer(int v) { return {Value::Integer, static_cast<double>(v), {}}; }
Value text(std::string s) { return {Value::Text, 0.0, std::move(s)}; }

using Getter = std::function<Value(const Trace&, const StepContext&)>;

struct Simple {
    std::string_view name;
    Getter get;
};

float angleDeg(vec2 rotation) {
    // The same expression as the trace's Poisson step, so both print the same angle.
    return std::atan2(rotation.y, rotation.x) * 57.2957795f;
}

int distinctTexels(const Trace& tr) {
    std::set<std::pair<int, int>> seen;
    for (const TapRecord& t : tr.taps) seen.insert({t.texel.x, t.texel.y});
    return static_cast<int>(seen.size());
}

int litCount(const Trace& tr) {
    int n = 0;
    for (const TapRecord& t : tr.taps) n += t.lit >= 0.5f ? 1 : 0;
    return n;
}

PcfFootprint footprint(const Trace& tr) {
    int n = std::max(1, tr.params.kernel);
    return pcfKernelFootprint(tr.uv, tr.map.size, n);
}

// A field of the cascade the lookup read: a count or index as an integer; missing for a map of
// one layer, and a density no frame measured (negative).
template <class T>
Value cascadeValue(const Trace& t, T TraceCascade::*field) {
    std::optional<TraceCascade> c = cascadeOfTrace(t);
    if (!c) return {};
    if constexpr (std::is_same_v<T, int>) {
        return integer((*c).*field);
    } else {
        if ((*c).*field < 0.0f) return {};
        return number((*c).*field);
    }
}

// Where the lookup falls: its uv, depths, texel position and the fractions the methods lerp by.
const std::vector<Simple>& positionNames() {
    static const std::vector<Simple> names = {
        {"uv.x", [](const Trace& t, const StepContext&) { return number(t.uv.x); }},
        {"uv.y", [](const Trace& t, const StepContext&) { return number(t.uv.y); }},
        {"z", [](const Trace& t, const StepContext&) { return number(t.z); }},
        {"ref", [](const Trace& t, const StepContext&) { return number(t.ref); }},
        {"depth_bias", [](const Trace& t, const StepContext&) { return number(t.z - t.ref); }},
        {"texel.x", [](const Trace& t, const StepContext&) { return number(t.pos.p.x); }},
        {"texel.y", [](const Trace& t, const StepContext&) { return number(t.pos.p.y); }},
        {"base.x", [](const Trace& t, const StepContext&) { return integer(t.pos.base.x); }},
        {"base.y", [](const Trace& t, const StepContext&) { return integer(t.pos.base.y); }},
        {"frac.x", [](const Trace& t, const StepContext&) { return number(t.pos.frac.x); }},
        {"frac.y", [](const Trace& t, const StepContext&) { return number(t.pos.frac.y); }},
        // Where the point lies inside the texel floor(uv * size) (nearest's): fract(p + 0.5).
        {"in_texel.x",
         [](const Trace& t, const StepContext&) {
             return number(t.pos.frac.x + 0.5f - std::floor(t.pos.frac.x + 0.5f));
         }},
        {"in_texel.y",
         [](const Trace& t, const StepContext&) {
             return number(t.pos.frac.y + 0.5f - std::floor(t.pos.frac.y + 0.5f));
         }},
        {"1-frac.x",
         [](const Trace& t, const StepContext&) { return number(1.0f - t.pos.frac.x); }},
        {"1-frac.y",
         [](const Trace& t, const StepContext&) { return number(1.0f - t.pos.frac.y); }},
        {"g.x", [](const Trace& t, const StepContext&) { return number(footprint(t).frac.x); }},
        {"g.y", [](const Trace& t, const StepContext&) { return number(footprint(t).frac.y); }},
        {"1-g.x",
         [](const Trace& t, const StepContext&) { return number(1.0f - footprint(t).frac.x); }},
        {"1-g.y",
         [](const Trace& t, const StepContext&) { return number(1.0f - footprint(t).frac.y); }},
        {"tent.s", [](const Trace& t,
                      const StepContext&) { return number(pcfTentBase(t.uv, t.map.size).frac.x); }},
        {"tent.t", [](const Trace& t,
                      const StepContext&) { return number(pcfTentBase(t.uv, t.map.size).frac.y); }},
    };
    return names;
}

// The result, as the texture unit's precisions give it and counted either way.
const std::vector<Simple>& resultNames() {
    static const std::vector<Simple> names = {
        {"visibility", [](const Trace& t, const StepContext&) { return number(t.visibility); }},
        // Issue 10: the texture unit's 8-bit position (hw8) next to the float one.
        {"frac_hw8.x", [](const Trace& t, const StepContext&) { return number(t.fracHw8.x); }},
        {"frac_hw8.y", [](const Trace& t, const StepContext&) { return number(t.fracHw8.y); }},
        {"steps_hw8.x",
         [](const Trace& t, const StepContext&) {
             return integer(static_cast<int>(std::lround(t.fracHw8.x * 256.0f)));
         }},
        {"visibility_exact",
         [](const Trace& t, const StepContext&) { return number(t.visibilityExact); }},
        {"visibility_hw8",
         [](const Trace& t, const StepContext&) { return number(t.visibilityHw8); }},
        // The same result counted the other way (1 = in shadow), as some articles do.
        {"1-visibility",
         [](const Trace& t, const StepContext&) { return number(1.0f - t.visibility); }},
        {"shadow", [](const Trace& t, const StepContext&) { return number(1.0f - t.visibility); }},
    };
    return names;
}

// The method, its parameters and what it read (fetch counts, taps, the weight table).
const std::vector<Simple>& readNames() {
    static const std::vector<Simple> names = {
        {"method",
         [](const Trace& t, const StepContext&) {
             if (t.params.method < 0 || t.params.method >= PCF_METHOD_COUNT) return text("?");
             return text(std::string(methodInfo(t.params.method).name));
         }},
        {"kernel", [](const Trace& t, const StepContext&) { return integer(t.params.kernel); }},
        {"kernel_sq",
         [](const Trace& t, const StepContext&) {
             return integer(t.params.kernel * t.params.kernel);
         }},
        {"radius", [](const Trace& t, const StepContext&) { return number(t.params.radius); }},
        {"rotation",
         [](const Trace& t, const StepContext&) { return number(angleDeg(t.params.rotation)); }},
        {"map_size", [](const Trace& t, const StepContext&) { return integer(t.map.size.x); }},
        {"taps", [](const Trace& t,
                    const StepContext&) { return integer(static_cast<int>(t.taps.size())); }},
        {"texels", [](const Trace& t, const StepContext&) { return integer(t.counts.texels); }},
        {"gathers", [](const Trace& t, const StepContext&) { return integer(t.counts.gathers); }},
        {"hw_taps", [](const Trace& t, const StepContext&) { return integer(t.counts.hwTaps); }},
        {"fetches", [](const Trace& t,
                       const StepContext&) { return integer(static_cast<int>(t.fetches.size())); }},
        {"distinct", [](const Trace& t, const StepContext&) { return integer(distinctTexels(t)); }},
        {"lit_count", [](const Trace& t, const StepContext&) { return integer(litCount(t)); }},
        {"shadowed_count",
         [](const Trace& t, const StepContext&) {
             return integer(static_cast<int>(t.taps.size()) - litCount(t));
         }},
        {"weights.origin.x",
         [](const Trace& t, const StepContext&) { return integer(t.weights.origin.x); }},
        {"weights.origin.y",
         [](const Trace& t, const StepContext&) { return integer(t.weights.origin.y); }},
        {"weights.w", [](const Trace& t, const StepContext&) { return integer(t.weights.size.x); }},
        {"weights.h", [](const Trace& t, const StepContext&) { return integer(t.weights.size.y); }},
    };
    return names;
}

// The pick, the shadow pass's settings (bias, cull, depth format) and what the bias did to the
// taps.
const std::vector<Simple>& biasNames() {
    static const std::vector<Simple> names = {
        {"pixel.x", [](const Trace&, const StepContext& c) { return integer(c.pixel.x); }},
        {"pixel.y", [](const Trace&, const StepContext& c) { return integer(c.pixel.y); }},
        {"bias",
         [](const Trace&, const StepContext& c) {
             return text(std::string(biasModeName(c.settings.bias)));
         }},
        {"constant_bias",
         [](const Trace&, const StepContext& c) { return number(c.settings.constantBias); }},
        {"dzduv.u", [](const Trace& t, const StepContext&) { return number(t.dzduv.x); }},
        {"dzduv.v", [](const Trace& t, const StepContext&) { return number(t.dzduv.y); }},
        // The plane's depth change over half a texel of this map: dz/du * 0.5 / size.
        {"half_texel_dz.u",
         [](const Trace& t, const StepContext&) { return number(t.dzduv.x * 0.5 / t.map.size.x); }},
        {"half_texel_dz.v",
         [](const Trace& t, const StepContext&) { return number(t.dzduv.y * 0.5 / t.map.size.y); }},
        {"origin_shift", [](const Trace&, const StepContext& c) { return number(c.originShift); }},
        {"light_angle",
         [](const Trace&, const StepContext& c) {
             return c.lightAngleDeg >= 0.0f ? number(c.lightAngleDeg) : Value{};
         }},
        {"plane_changed",
         [](const Trace& t, const StepContext&) { return integer(tapsChangedByPlane(t)); }},
        {"lookup_shadowed_count",
         [](const Trace& t, const StepContext&) {
             int n = 0;
             for (const TapRecord& tap : t.taps) n += pcfCompare(tap.depth, t.ref) < 0.5f;
             return integer(n);
         }},
        {"cull",
         [](const Trace&, const StepContext& c) {
             return text(std::string(cullModeName(c.settings.cull)));
         }},
        {"depth_format",
         [](const Trace&, const StepContext& c) {
             TexelKind format = c.settings.depthFormat;
             return text(std::string(depthFormatName(format)));
         }},
    };
    return names;
}

// pcss (Fernando 2005): the blocker search and the penumbra estimate, as the kernel found them
// (Trace::pcss); 0 for the other methods. And the disk the poisson methods fill.
const std::vector<Simple>& pcssNames() {
    static const std::vector<Simple> names = {
        {"pcss.scale",
         [](const Trace& t, const StepContext&) { return number(t.params.penumbraScale); }},
        {"pcss.search_radius",
         [](const Trace& t, const StepContext&) { return number(t.pcss.searchRadius); }},
        {"pcss.search_taps",
         [](const Trace& t, const StepContext&) {
             bool pcss = methodInfo(t.params.method).searchesBlockers;
             return integer(pcss ? std::min(static_cast<int>(t.taps.size()), PCF_PCSS_TAPS) : 0);
         }},
        {"pcss.blockers",
         [](const Trace& t, const StepContext&) { return integer(t.pcss.blockers); }},
        {"pcss.blocker_depth",
         [](const Trace& t, const StepContext&) { return number(t.pcss.blockerDepth); }},
        {"pcss.penumbra",
         [](const Trace& t, const StepContext&) { return number(t.pcss.penumbra); }},
        {"pcss.filter_radius",
         [](const Trace& t, const StepContext&) { return number(t.pcss.filterRadius); }},
        {"pcss.search_reach",
         [](const Trace& t, const StepContext&) {
             return number(t.pcss.searchRadius * poissonSetReach());
         }},
        {"disk_reach",
         [](const Trace& t, const StepContext&) {
             const MethodInfo& info = methodInfo(t.params.method);
             bool pcss = info.searchesBlockers;
             if (!info.hasDisk) return number(0.0);
             float scale = pcss ? t.pcss.filterRadius : t.params.radius;
             return number(scale * poissonSetReach());
         }},
    };
    return names;
}

// The cascade the lookup read (kernel/trace.h cascadeOfTrace); n/a with one map.
const std::vector<Simple>& cascadeNames() {
    static const std::vector<Simple> names = {
        {"cascade",
         [](const Trace& t, const StepContext&) { return cascadeValue(t, &TraceCascade::index); }},
        {"cascade.count",
         [](const Trace& t, const StepContext&) { return cascadeValue(t, &TraceCascade::count); }},
        {"cascade.near",
         [](const Trace& t, const StepContext&) { return cascadeValue(t, &TraceCascade::nearZ); }},
        {"cascade.far",
         [](const Trace& t, const StepContext&) { return cascadeValue(t, &TraceCascade::farZ); }},
        {"cascade.texel_world",
         [](const Trace& t, const StepContext&) {
             return cascadeValue(t, &TraceCascade::texelWs);
         }},
        {"cascade.texels_per_pixel_max",
         [](const Trace& t, const StepContext&) {
             return cascadeValue(t, &TraceCascade::texelsPerPixelMax);
         }},
        // The blend band (kernel/trace.h TraceCascadeBlend): the weight of the next cascade, 0
        // outside the band; the next cascade and its own visibility, n/a outside the band; the
        // result shown, the cascade's own visibility outside the band.
        {"cascade.blend_weight",
         [](const Trace& t, const StepContext&) {
             return cascadeOfTrace(t) ? number(t.cascadeBlend.weight) : Value{};
         }},
        {"cascade.next",
         [](const Trace& t, const StepContext&) {
             return cascadeOfTrace(t) && t.cascadeBlend.next >= 0 ? integer(t.cascadeBlend.next)
                                                                  : Value{};
         }},
        {"cascade.next_visibility",
         [](const Trace& t, const StepContext&) {
             return cascadeOfTrace(t) && t.cascadeBlend.next >= 0
                        ? number(t.cascadeBlend.nextVisibility)
                        : Value{};
         }},
        {"cascade.blended",
         [](const Trace& t, const StepContext&) {
             if (!cascadeOfTrace(t)) return Value{};
             return number(t.cascadeBlend.next >= 0 ? t.cascadeBlend.blended : t.visibility);
         }},
    };
    return names;
}

// The moment methods' estimate (trace.h: Trace::moments), as the kernel computed it; missing
// for a method that compares depths.
Getter momentField(float PcfMomentEstimate::*field) {
    return [field](const Trace& t, const StepContext&) {
        if (!readsMoments(t.params.method)) return Value{};
        return number(t.moments.*field);
    };
}

const std::vector<Simple>& momentNames() {
    static const std::vector<Simple> names = {
        {"mean", momentField(&PcfMomentEstimate::mean)},
        {"variance", momentField(&PcfMomentEstimate::variance)},
        {"receiver", momentField(&PcfMomentEstimate::receiver)},
        {"bound", momentField(&PcfMomentEstimate::bound)},
        {"neg_bound", momentField(&PcfMomentEstimate::negBound)},
        {"lbr",
         [](const Trace& t, const StepContext&) {
             return readsMoments(t.params.method) ? number(t.params.lbr) : Value{};
         }},
    };
    return names;
}

// Every simple name, group by group (placeholderNames lists them in this order).
const std::vector<Simple>& allSimpleNames() {
    static const std::vector<Simple> names = [] {
        std::vector<Simple> all;
        for (const std::vector<Simple>* group :
             {&positionNames(), &resultNames(), &readNames(), &biasNames(), &pcssNames(),
              &cascadeNames(), &momentNames()}) {
            all.insert(all.end(), group->begin(), group->end());
        }
        return all;
    }();
    return names;
}

// How many moments the method's map holds per texel (2 or 4; 0: it reads depths).
int momentCount(int method) {
    switch (methodInfo(method).mapPass) {
        case MapPass::Depth:
            return 0;
        case MapPass::Moments2:
            return 2;
        case MapPass::Moments4:
            return 4;
    }
    return 0;
}

constexpr std::string_view TAP_FIELDS[] = {"i",   "j",      "depth", "ref",          "margin",
                                           "lit", "weight", "shift", "lookup_margin"};
constexpr std::string_view FETCH_FIELDS[] = {"value", "weight", "u", "v"};
constexpr std::string_view PART_FIELDS[] = {"visibility"};
constexpr int MAX_MOMENTS = 4;  // moment[K], K 0..3

// A placeholder's name, taken apart: a simple name, or an indexed one (tap[K].field,
// fetch[K].field, weight[I,J], moment[K]).
struct Name {
    const Simple* simple = nullptr;
    std::string_view family;  // "tap", "fetch", "part", "weight" or "moment" for indexed names
    std::string_view field;   // tap / fetch field
    int index = 0;            // K, or I for weight
    int index2 = 0;           // J for weight
};

// A non-negative decimal integer filling all of s.
std::optional<int> parseIndex(std::string_view s) {
    if (s.empty() || s.size() > 6) return std::nullopt;
    int v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || v < 0) return std::nullopt;
    return v;
}

std::optional<Name> parseName(std::string_view s) {
    for (const Simple& simple : allSimpleNames()) {
        if (simple.name == s) return Name{&simple, {}, {}, 0, 0};
    }
    size_t open = s.find('[');
    size_t close = s.find(']');
    if (open == std::string_view::npos || close == std::string_view::npos || close < open) {
        return std::nullopt;
    }
    std::string_view family = s.substr(0, open);
    std::string_view inside = s.substr(open + 1, close - open - 1);
    std::string_view rest = s.substr(close + 1);
    Name name;
    name.family = family;
    if (family == "weight") {
        size_t comma = inside.find(',');
        if (!rest.empty() || comma == std::string_view::npos) return std::nullopt;
        std::optional<int> i = parseIndex(inside.substr(0, comma));
        std::optional<int> j = parseIndex(inside.substr(comma + 1));
        if (!i || !j) return std::nullopt;
        name.index = *i;
        name.index2 = *j;
        return name;
    }
    if (family == "moment") {
        std::optional<int> k = parseIndex(inside);
        if (!k || *k >= MAX_MOMENTS || !rest.empty()) return std::nullopt;
        name.index = *k;
        return name;
    }
    if (family != "tap" && family != "fetch" && family != "part") return std::nullopt;
    std::optional<int> k = parseIndex(inside);
    if (!k || rest.size() < 2 || rest[0] != '.') return std::nullopt;
    name.index = *k;
    name.field = rest.substr(1);
    bool known = false;
    if (family == "tap") {
        for (std::string_view f : TAP_FIELDS) known = known || f == name.field;
    } else if (family == "part") {
        for (std::string_view f : PART_FIELDS) known = known || f == name.field;
    } else {
        for (std::string_view f : FETCH_FIELDS) known = known || f == name.field;
    }
    if (!known) return std::nullopt;
    return name;
}

Value valueOf(const Name& name, const Trace& tr, const StepContext& ctx) {
    if (name.simple) return name.simple->get(tr, ctx);
    if (name.family == "weight") {
        return number(tr.weights.at(tr.weights.origin + ivec2(name.index, name.index2)));
    }
    if (name.family == "moment") {
        // The filtered moments read at the lookup (msm: after the moment bias).
        if (name.index >= momentCount(tr.params.method)) return {};
        return number(tr.moments.moments[name.index]);
    }
    if (name.family == "tap") {
        if (name.index >= static_cast<int>(tr.taps.size())) return {};
        const TapRecord& t = tr.taps[static_cast<size_t>(name.index)];
        if (name.field == "i") return integer(t.texel.x);
        if (name.field == "j") return integer(t.texel.y);
        if (name.field == "depth") return number(t.depth);
        if (name.field == "ref") return number(t.ref);
        if (name.field == "margin") return number(t.depth - t.ref);
        if (name.field == "lit") return integer(t.lit >= 0.5f ? 1 : 0);
        if (name.field == "shift") return number(t.ref - tr.ref);
        if (name.field == "lookup_margin") return number(t.depth - tr.ref);
        return number(t.weight);
    }
    if (name.family == "part") {
        if (name.index >= static_cast<int>(ctx.partVisibility.size())) return {};
        return number(ctx.partVisibility[static_cast<size_t>(name.index)]);
    }
    if (name.index >= static_cast<int>(tr.fetches.size())) return {};
    const FetchRecord& f = tr.fetches[static_cast<size_t>(name.index)];
    if (name.field == "value") {
        // What the instruction returned, rebuilt from its reads as the trace's steps do.
        float sum = 0.0f;
        for (const TapRecord& t : tr.taps) {
            if (t.fetch == name.index) sum += t.weight * t.lit;
        }
        return number(f.weight > 0.0f ? sum / f.weight : 0.0f);
    }
    if (name.field == "weight") return number(f.weight);
    if (name.field == "u") return number(f.uv.x);
    return number(f.uv.y);
}

// One placeholder: {name[*factor][:decimals]}.
struct Placeholder {
    Name name;
    std::optional<double> factor;
    std::optional<int> decimals;
};

// Parses the inside of the braces, or says what is wrong with it.
// Edits (insertions, deletions, substitutions) that turn a into b (Levenshtein).
size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = up;
        }
    }
    return row[b.size()];
}

// " (did you mean {frac.x}?)" for the simple name nearest a misspelt one, two edits or fewer;
// empty when none is that near.
std::string nearestNameHint(std::string_view name) {
    std::string_view best;
    size_t bestDistance = 3;
    for (const Simple& s : allSimpleNames()) {
        size_t d = editDistance(name, s.name);
        if (d < bestDistance) best = s.name, bestDistance = d;
    }
    return best.empty() ? "" : " (did you mean {" + std::string(best) + "}?)";
}

std::variant<Placeholder, std::string> parsePlaceholder(std::string_view inside) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on chains of +.
    std::string shown = "{";
    shown.append(inside);
    shown.append("}");
    Placeholder ph;
    std::string_view body = inside;
    size_t colon = body.rfind(':');
    if (colon != std::string_view::npos) {
        std::string_view digits = body.substr(colon + 1);
        std::optional<int> n = parseIndex(digits);
        if (!n || *n > 9) {
            return "placeholder " + shown + " has a bad format: :N takes N = 0..9 decimals";
        }
        ph.decimals = *n;
        body = body.substr(0, colon);
    }
    size_t star = body.find('*');
    if (star != std::string_view::npos) {
        std::string_view f = body.substr(star + 1);
        double v = 0.0;
        auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
        if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v)) {
            return "placeholder " + shown + " has a bad factor: *F takes a number, e.g. *9";
        }
        ph.factor = v;
        body = body.substr(0, star);
    }
    std::optional<Name> name = parseName(body);
    if (!name) {
        return "unknown placeholder {" + std::string(body) + "}" + nearestNameHint(body) +
               " (the names: docs/lesson-authoring.md#placeholders; write {{ for a literal "
               "brace)";
    }
    ph.name = *name;
    bool isText =
        name->simple && (name->simple->name == "method" || name->simple->name == "bias" ||
                         name->simple->name == "cull" || name->simple->name == "depth_format");
    if (isText && (ph.factor || ph.decimals)) {
        return "placeholder " + shown + " is text: it takes no *F or :N";
    }
    return ph;
}

std::string formatDecimals(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s = buf;
    // "-0.000" says nothing a student should read as negative.
    if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
    return s;
}

std::string format(const Value& v, const Placeholder& ph) {
    if (v.kind == Value::Missing) return "n/a";
    if (v.kind == Value::Text) return v.text;
    double x = v.number * ph.factor.value_or(1.0);
    if (ph.decimals) return formatDecimals(x, *ph.decimals);
    if (v.kind == Value::Integer && !ph.factor) return std::to_string(static_cast<int>(v.number));
    return formatNumber(static_cast<float>(x));
}

// Walks text, calling onLiteral for plain text and onPlaceholder for each placeholder. Returns
// the first problem met, if any.
template <class OnLiteral, class OnPlaceholder>
std::optional<PlaceholderProblem> scan(std::string_view text, OnLiteral onLiteral,
                                       OnPlaceholder onPlaceholder) {
    size_t i = 0;
    while (i < text.size()) {
        char c = text[i];
        if (c == '{' && i + 1 < text.size() && text[i + 1] == '{') {
            onLiteral("{");
            i += 2;
        } else if (c == '}' && i + 1 < text.size() && text[i + 1] == '}') {
            onLiteral("}");
            i += 2;
        } else if (c == '}') {
            return PlaceholderProblem{i, "a lone } (write }} for a literal brace)"};
        } else if (c == '{') {
            size_t close = text.find_first_of("{}\n", i + 1);
            if (close == std::string_view::npos || text[close] != '}') {
                return PlaceholderProblem{
                    i, "a { with no closing } on its line (write {{ for a literal brace)"};
            }
            auto parsed = parsePlaceholder(text.substr(i + 1, close - i - 1));
            if (auto* problem = std::get_if<std::string>(&parsed)) {
                return PlaceholderProblem{i, *problem};
            }
            if (std::optional<std::string> problem =
                    onPlaceholder(std::get<Placeholder>(parsed), i)) {
                return PlaceholderProblem{i, *problem};
            }
            i = close + 1;
        } else {
            size_t next = text.find_first_of("{}", i);
            if (next == std::string_view::npos) next = text.size();
            onLiteral(text.substr(i, next - i));
            i = next;
        }
    }
    return std::nullopt;
}

}  // namespace

std::vector<std::string> placeholderNames() {
    std::vector<std::string> names;
    for (const Simple& s : allSimpleNames()) names.emplace_back(s.name);
    for (std::string_view f : TAP_FIELDS) names.push_back("tap[K]." + std::string(f));
    for (std::string_view f : FETCH_FIELDS) names.push_back("fetch[K]." + std::string(f));
    for (std::string_view f : PART_FIELDS) names.push_back("part[K]." + std::string(f));
    names.emplace_back("weight[I,J]");
    names.emplace_back("moment[K]");
    return names;
}

std::optional<PlaceholderProblem> checkPlaceholders(std::string_view text, int tapCount,
                                                    int fetchCount, int partCount,
                                                    ivec2 weightSize) {
    return scan(
        text, [](std::string_view) {},
        [&](const Placeholder& ph, size_t) -> std::optional<std::string> {
            const Name& n = ph.name;
            if (n.family == "tap" && tapCount >= 0 && n.index >= tapCount) {
                return "tap[" + std::to_string(n.index) + "] is past the " +
                       std::to_string(tapCount) + " reads this step's method makes (K is 0.." +
                       std::to_string(tapCount - 1) + ")";
            }
            if (n.family == "fetch" && fetchCount >= 0 && n.index >= fetchCount) {
                return "fetch[" + std::to_string(n.index) + "] is past the " +
                       std::to_string(fetchCount) +
                       " fetch instructions this step's method issues (K is 0.." +
                       std::to_string(fetchCount - 1) + ")";
            }
            if (n.family == "part" && partCount >= 0 && n.index >= partCount) {
                return "part[" + std::to_string(n.index) + "] is past the " +
                       std::to_string(partCount) + " parts of this step's compare";
            }
            if (n.family == "weight" && weightSize.x >= 0 &&
                (n.index >= weightSize.x || n.index2 >= weightSize.y)) {
                return "weight[" + std::to_string(n.index) + "," + std::to_string(n.index2) +
                       "] is past the " + std::to_string(weightSize.x) + " x " +
                       std::to_string(weightSize.y) +
                       " weights this step's method merges (I is 0.." +
                       std::to_string(weightSize.x - 1) + ", J is 0.." +
                       std::to_string(weightSize.y - 1) + ")";
            }
            return std::nullopt;
        });
}

std::vector<PlaceholderProblem> placeholderProblems(std::string_view text, int tapCount,
                                                    int fetchCount, int partCount,
                                                    ivec2 weightSize) {
    std::vector<PlaceholderProblem> out;
    size_t from = 0;
    while (from < text.size()) {
        std::optional<PlaceholderProblem> p =
            checkPlaceholders(text.substr(from), tapCount, fetchCount, partCount, weightSize);
        if (!p) break;
        p->offset += from;
        // Read on after the offending braces: past its }, or past a lone brace (a { with no }
        // on its line spoils only that line).
        size_t at = p->offset;
        size_t next = at + 1;
        if (text[at] == '{') {
            size_t close = text.find_first_of("{}\n", at + 1);
            next = close == std::string_view::npos ? text.size()
                   : text[close] == '}'            ? close + 1
                                                   : close;
        }
        out.push_back(std::move(*p));
        from = next;
    }
    return out;
}

std::string fillText(std::string_view text, const Trace& trace, const StepContext& ctx) {
    std::string out;
    out.reserve(text.size());
    std::optional<PlaceholderProblem> problem = scan(
        text, [&](std::string_view literal) { out.append(literal); },
        [&](const Placeholder& ph, size_t) -> std::optional<std::string> {
            out.append(format(valueOf(ph.name, trace, ctx), ph));
            return std::nullopt;
        });
    if (problem) throw std::invalid_argument(problem->problem);
    return singularAfterOne(out);
}

std::optional<std::string> numberPlaceholderProblem(std::string_view inside) {
    auto parsed = parsePlaceholder(inside);
    if (auto* problem = std::get_if<std::string>(&parsed)) return *problem;
    const Name& n = std::get<Placeholder>(parsed).name;
    if (n.simple && (n.simple->name == "method" || n.simple->name == "bias" ||
                     n.simple->name == "cull" || n.simple->name == "depth_format")) {
        // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on chains of +.
        std::string problem = "{";
        problem.append(inside);
        problem.append("} is a word, not a number");
        return problem;
    }
    return std::nullopt;
}

std::optional<double> placeholderNumber(std::string_view inside, const Trace& trace,
                                        const StepContext& ctx) {
    if (std::optional<std::string> problem = numberPlaceholderProblem(inside)) {
        throw std::invalid_argument(*problem);
    }
    const Placeholder ph = std::get<Placeholder>(parsePlaceholder(inside));
    Value v = valueOf(ph.name, trace, ctx);
    if (v.kind != Value::Number && v.kind != Value::Integer) return std::nullopt;
    return v.number * ph.factor.value_or(1.0);
}

std::string singularAfterOne(std::string text) {
    // Counts are placeholders, so the words after them were written for many: "{fetches}
    // lookups" must read "1 lookup" when a key makes it one. Only a whole "1" (not 0.1, 21).
    static const std::pair<std::string_view, std::string_view> PLURALS[] = {
        {"hardware taps", "hardware tap"},
        {"texel reads", "texel read"},
        {"gather instructions", "gather instruction"},
        {"lookups", "lookup"},
        {"gathers", "gather"},
        {"taps", "tap"},
        {"reads", "read"},
        {"texels", "texel"},
        {"fetches", "fetch"},
        {"points", "point"},
        {"samples", "sample"}};
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i) {
        out += text[i];
        bool wholeOne =
            text[i] == '1' &&
            (i == 0 || std::string_view(" (\n").find(text[i - 1]) != std::string_view::npos) &&
            i + 1 < text.size() && text[i + 1] == ' ';
        if (!wholeOne) continue;
        std::string_view rest = std::string_view(text).substr(i + 2);
        for (const auto& [plural, singular] : PLURALS) {
            bool wordEnds = rest.size() == plural.size() ||
                            (rest.size() > plural.size() &&
                             !std::isalnum(static_cast<unsigned char>(rest[plural.size()])));
            if (rest.starts_with(plural) && wordEnds) {
                out += ' ';
                out += singular;
                i += 1 + plural.size();
                break;
            }
        }
    }
    return out;
}

}  // namespace pcf
