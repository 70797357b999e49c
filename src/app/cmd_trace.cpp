// pcfscope trace: one lookup's step-through, as text or as the JSON object of docs/user-guide.md,
// "trace".
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/raw_folder.h"
#include "app/render_options.h"
#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/moment_footprint.h"
#include "kernel/moments.h"
#include "kernel/settings.h"
#include "kernel/shading.h"
#include "kernel/trace.h"
#include "kernel/trace_explain.h"
#include "kernel/trace_json.h"
#include "render/image_io.h"
#include "scene/cascade_fit.h"

namespace pcf {

namespace {

// pcss without a scene: the light's size in the map (texels of penumbra per unit of light depth)
// when --penumbra-scale is not given. On the example map (caster 0.3, ground 0.55) a receiver
// at 0.5 gets a penumbra of about 3 texels, inside the 8 x 8 map.
constexpr float DEFAULT_TRACE_PENUMBRA_SCALE = 16.0f;
constexpr float MAX_TRACE_PENUMBRA_SCALE = 1.0e6f;

struct TraceOptions {
    std::string mapPath;
    bool example = false;
    std::string rawDir;  // a `render --raw` folder: trace one of its pixels (--pixel)
    std::string pixel;
    std::string uv;
    float z = 0.0f;
    // The filter's and the bias's options, the parameter table's (trace's defaults: bilinear2x2,
    // no bias).
    SettingOptions shadow;
    SettingOptions mapOptions;  // the map group's --moment-format
    float angleDeg = 0.0f;      // slope: the angle between the receiver's normal and the light
    std::string dzduv;          // receiver-plane: "DU,DV"
    CLI::App* sub = nullptr;    // to ask which options were given
    float rotationDeg = 0.0f;
    float penumbraScale = DEFAULT_TRACE_PENUMBRA_SCALE;
    bool json = false;
    std::string depthFormat = "32f";
};

// Beyond this |uv| every tap of every method already reads edge texels (the widest reach is a
// 64-texel Poisson disk on a 4-texel map: 16 uv units), so clamping there changes no result and
// keeps uv * size far from int overflow.
constexpr float UV_LIMIT = 20.0f;

// The built-in example's lookup: bits 1 and 0 at fx = 0.2, as in "What Is PCF"'s worked example.
constexpr const char* EXAMPLE_UV = "0.4625,0.3875";
constexpr float EXAMPLE_Z = 0.5f;

// The settings given: the shared options' parsing (render_options.h), each value given checked
// in its range whether or not the method uses it.
ShadowSettings traceSettings(const TraceOptions& o) {
    ShadowSettings s;
    o.shadow.applyTo(s, false);
    o.mapOptions.applyTo(s, false);
    return s;
}

// The filter's parameters: the settings', and trace's own --rotation.
PcfParams traceParams(const TraceOptions& o, const ShadowSettings& s) {
    float rad = o.rotationDeg * 0.0174532925f;
    PcfParams prm = s.pcfParams(vec2(std::cos(rad), std::sin(rad)), o.penumbraScale);
    if (auto why = cliParamsProblem(prm)) throw UsageError(*why);
    requireRange("--rotation", o.rotationDeg, -360.0f, 360.0f);
    requireRange("--penumbra-scale", o.penumbraScale, 0.0f, MAX_TRACE_PENUMBRA_SCALE);
    if (o.sub->count("--penumbra-scale") > 0 && !methodInfo(prm.method).searchesBlockers) {
        throw UsageError("--penumbra-scale is for --method pcss (the light's size in the map)");
    }
    return prm;
}

// The bias: the settings' (checked), and trace's --angle and --dzduv that stand in for the
// receiver the renderer would know; returns the receiver plane, --dzduv's.
vec2 traceDzDuv(const TraceOptions& o, const ShadowSettings& s) {
    if (auto why = cliRangeProblem(s)) throw UsageError(*why);
    // trace's default mode is none: a parameter given without a mode would do nothing.
    if (!o.shadow.given("bias")) {
        for (const ParamInfo& p : allParams()) {
            if (p.group == ParamGroup::Bias && o.shadow.given(p.key)) {
                throw UsageError(settingFlag(p.key) +
                                 " needs --bias NAME (trace's default is none)");
            }
        }
    }
    checkBiasOptions(s);
    requireRange("--angle", o.angleDeg, 0.0f, 90.0f);
    if (o.sub->count("--angle") > 0 && s.bias != BiasMode::Slope) {
        throw UsageError("--angle is for --bias slope (the angle its tan(theta) reads)");
    }
    vec2 dzduv(0.0f);
    if (o.sub->count("--dzduv") > 0) {
        if (s.bias != BiasMode::ReceiverPlane) {
            throw UsageError("--dzduv is for --bias receiver-plane (the receiver's plane)");
        }
        dzduv = parseVec2("--dzduv", o.dzduv);
        requireRange("--dzduv u", dzduv.x, -1.0e6f, 1.0e6f);
        requireRange("--dzduv v", dzduv.y, -1.0e6f, 1.0e6f);
    }
    return dzduv;
}

// Pixel k of a `render --raw` folder in a blend band (cascade_blend): the next cascade's lookup
// of its point and the band's weight, as scene/cascade_fit.h cascadeVisibilityIn gives them (the
// CPU path tests/cascade_parity_test.cpp holds to the GPU), from the pixel's world position,
// normal, planes in both cascades and render.json's cascade camera; the result mixes the
// trace's own visibility (the taps it shows, from the pixel's u, v and ref) with the next one.
// No band (next -1) outside it, in the last cascade, past it, or without a band.
TraceCascadeBlend rawCascadeBlend(const RawImages& img, const RawSettings& r, size_t k, int layer,
                                  const PcfParams& prm, float visibility, const std::string& dir) {
    const ShadowSettings& s = r.settings;
    if (!(s.cascadeBlend > 0.0f) || layer + 1 >= img.map.layers()) return {};
    if (img.normals.data.empty()) {
        throw UsageError(dir +
                         " has no normals.exr: a blend band's next lookup is made from "
                         "the pixel's normal");
    }
    std::optional<vec2> nextPlane = nextReceiverPlane(img, k);
    if (s.bias == BiasMode::ReceiverPlane && !nextPlane) {
        throw UsageError(dir +
                         " has no next_dzduv.exr: under receiver-plane bias a blend band "
                         "filters the next cascade with the receiver's plane there");
    }
    const float* p = &img.positions.data[4 * k];
    const float* n = &img.normals.data[4 * k];
    vec2 dzduv(img.planes.data[4 * k], img.planes.data[4 * k + 1]);
    CascadeLookup c = cascadeVisibilityIn(img.map, layer, pixelViewDepth(img, r, k), s, prm,
                                          vec3(p[0], p[1], p[2]), vec3(n[0], n[1], n[2]), n[3],
                                          dzduv, nextPlane.value_or(vec2(0.0f)));
    if (c.next < 0) return {};
    return {c.next, c.weight, c.nextVisibility,
            pcfCascadeBlend(visibility, c.nextVisibility, c.weight)};
}

// --raw DIR --pixel X,Y: the lookup the camera pass made at that pixel (top-left origin) of a
// `render --raw` folder, traced by the CPU kernel on the layer it read (a cascaded map's: the
// cascade its view depth falls in, raw_folder.h pixelLayer), with the settings and the map
// render.json names; a cascade's density from render.json's "cascades"; in a blend band the
// next cascade's lookup and the mix (rawCascadeBlend).
Trace traceRawPixel(const TraceOptions& o) {
    // Everything else the folder's render.json says.
    for (const CLI::Option* opt : o.sub->get_options()) {
        std::string name = opt->get_name();
        if (opt->count() > 0 && name != "--raw" && name != "--pixel" && name != "--json") {
            throw UsageError(name + " does not go with --raw (render.json says it)");
        }
    }
    if (o.pixel.empty()) throw UsageError("trace --raw needs --pixel X,Y");
    std::filesystem::path dir(o.rawDir);
    RawSettings r = readRawSettings(dir);
    RawImages img = readRawImages(dir, r);
    checkMapTexels(r, (dir / "render.json").string());
    glm::ivec2 px = parseIvec2("--pixel", o.pixel);
    const FloatImage& ls = img.lightSpace;
    if (px.x < 0 || px.y < 0 || px.x >= ls.width || px.y >= ls.height) {
        throw UsageError("--pixel " + o.pixel + " is outside the " + std::to_string(ls.width) +
                         "x" + std::to_string(ls.height) + " frame of " + o.rawDir);
    }
    size_t k = static_cast<size_t>(px.y) * ls.width + px.x;
    if (ls.data[4 * k + 3] != 1.0f) {
        throw UsageError("--pixel " + o.pixel + " is not on a shadow receiver");
    }
    if (img.map.layers() > 1 && img.positions.data.empty()) {
        throw UsageError(o.rawDir +
                         " has no positions.exr: a cascaded pixel's layer is chosen "
                         "from its position");
    }
    vec2 uv(ls.data[4 * k], ls.data[4 * k + 1]);
    float ref = ls.data[4 * k + 2];
    PcfParams prm = r.prm;
    if (r.settings.rotate) prm.rotation = pcfTexelRotation(uv, img.map.size());
    vec2 dzduv(img.planes.data[4 * k], img.planes.data[4 * k + 1]);
    int layer = pixelLayer(img, r, k);
    bool covered = layer < img.map.layers();
    Trace tr = traceLookup(img.map, uv, img.planes.data[4 * k + 2], ref, prm, r.settings, dzduv,
                           std::min(layer, img.map.layers() - 1));
    if (!covered) tr.visibility = 1.0f;  // past the shadow distance: drawn lit
    if (img.map.layers() > 1) tr.cascadeTexelsPerPixelMax = rawCascadeDensity(dir, tr.layer);
    if (covered)
        tr.cascadeBlend = rawCascadeBlend(img, r, k, layer, r.prm, tr.visibility, o.rawDir);
    return tr;
}

// The trace on stdout, as text or (--json) as one JSON object.
int printTrace(const TraceOptions& o, const Trace& tr) {
    std::string out = o.json ? traceToJson(tr) + "\n" : traceToText(tr);
    std::fwrite(out.data(), 1, out.size(), stdout);
    return 0;
}

// The depth map --map FILE or --example names; for --map the lookup's --uv and --z are needed
// (the example has its own).
ShadowMap traceDepthMap(const TraceOptions& o) {
    if (o.example) return exampleShadowMap();
    if (o.uv.empty() || o.sub->count("--z") == 0) {
        throw UsageError("trace --map needs --uv U,V and --z Z");
    }
    try {
        return readDepthImage(o.mapPath);
    } catch (const ImageError& e) {
        throw UsageError(e.what());
    }
}

int runTrace(const TraceOptions& o) {
    int sources = (o.example ? 1 : 0) + (o.mapPath.empty() ? 0 : 1) + (o.rawDir.empty() ? 0 : 1);
    if (sources != 1) {
        throw UsageError("trace needs exactly one of --map FILE, --example or --raw DIR");
    }
    if (!o.rawDir.empty()) return printTrace(o, traceRawPixel(o));
    if (!o.pixel.empty()) throw UsageError("--pixel is for --raw DIR");
    ShadowSettings settings = traceSettings(o);
    PcfParams prm = traceParams(o, settings);
    TexelKind format = depthFormatOption(o.depthFormat);
    vec2 dzduv = traceDzDuv(o, settings);

    ShadowMap map = traceDepthMap(o);
    std::string uvText = o.uv.empty() ? EXAMPLE_UV : o.uv;  // --map has its own (traceDepthMap)
    bool zGiven = o.sub->count("--z") > 0;                  // every float, NaN included, is a value
    float z = zGiven ? o.z : EXAMPLE_Z;
    map.setTexelKind(format);
    // The moment methods read the moments map the moments pass makes of these depths.
    ShadowMap depthMap;
    if (readsMoments(prm.method)) {
        depthMap = map;
        map = momentsMap(map, prm, mapTexelKind(prm.method, format, settings.momentBits));
        bool warps = methodInfo(prm.method).warps > 0;
        if (warps && prm.evsmExponents != settings.evsmExponents) {
            std::string note = "trace: --evsm-exponents " + exponentsText(settings.evsmExponents) +
                               " used as " + exponentsText(prm.evsmExponents) + " (" +
                               std::string(momentFormatName(settings.momentBits)) +
                               " moments hold exponents up to " +
                               formatNumber(evsmExponentLimit(settings.momentBits)) + ")\n";
            std::fputs(note.c_str(), stderr);
        }
    }
    // Any finite uv: texels outside the map clamp to the edge, as the GPU's sampler does; the
    // trace marks the taps that did.
    vec2 uv = glm::clamp(parseVec2("--uv", uvText), vec2(-UV_LIMIT), vec2(1.0f + UV_LIMIT));
    requireRange("--z", z, 0.0f, 1.0f);

    // The per-lookup bias (kernel/bias.h); normal offset has already moved the point given.
    float ref = z - settings.lookupBias(std::cos(o.angleDeg * 0.0174532925f));
    Trace tr = traceLookup(map, uv, z, ref, prm, settings, dzduv);
    // The depths the moments average, and PCF of them (kernel/moment_footprint.h).
    if (readsMoments(prm.method)) addMomentFootprint(tr, depthMap);
    return printTrace(o, tr);
}

}  // namespace

Command addTraceCommand(CLI::App& app) {
    auto o = std::make_shared<TraceOptions>();
    CLI::App* sub = app.add_subcommand(
        "trace", "explain one PCF lookup step by step: texels, bits, weights, result");
    sub->add_option("--map", o->mapPath,
                    "single-channel float depth image (EXR, TIFF); row 0 = first scanline");
    sub->add_flag("--example", o->example,
                  "use the built-in 8x8 example map (default lookup: What Is PCF's 0.8 example)");
    sub->add_option("--raw", o->rawDir,
                    "a `render --raw` folder: trace the lookup drawn at --pixel, with its "
                    "render.json's settings (a cascaded map: in the cascade the pixel read)");
    sub->add_option("--pixel", o->pixel, "with --raw: X,Y, the frame pixel from the top left");
    sub->add_option("--uv", o->uv,
                    "shadow-map coordinates U,V; any finite values (outside [0,1] the taps clamp "
                    "to the edge)");
    o->sub = sub;
    sub->add_option("--z", o->z, "receiver depth in [0,1] as the light sees it");
    ShadowSettings defaults;
    defaults.method = PCF_BILINEAR2X2;
    defaults.bias = BiasMode::None;
    // trace has --rotation (degrees) in the place of --rotate.
    // pcss's light size is --penumbra-scale here: trace has no scene to measure the light in.
    o->shadow.addTo(sub, {ParamGroup::Filter, ParamGroup::Bias}, defaults,
                    {"rotate", "light_size", "light_radius"});
    o->mapOptions.addTo(sub, {ParamGroup::Map}, defaults, {"depth_format", "map_size", "cull"});
    sub->add_option(
        "--angle", o->angleDeg,
        "slope: angle in degrees between the receiver's normal and the light (default 0)");
    sub->add_option(
        "--dzduv", o->dzduv,
        "receiver-plane: the receiver's DU,DV = d(depth)/d(u, v) (render --raw writes them in "
        "dzduv.exr). For --bias normal give --uv and --z of the point already moved "
        "(lightspace.exr holds them)");
    sub->add_option("--rotation", o->rotationDeg, "poisson, pcss: disk rotation in degrees");
    sub->add_option("--penumbra-scale", o->penumbraScale,
                    "pcss: the light's size in the map, texels of penumbra per unit of light "
                    "depth between receiver and blocker (default 16)");
    sub->add_flag("--json", o->json, "print the trace as one JSON object");
    sub->add_option(
        "--depth-format", o->depthFormat,
        "the map's format: " + depthFormatNames() + " (fixed-point ones: ref clamped to [0,1])");
    return {sub, [o] { return runTrace(*o); }};
}

}  // namespace pcf
