// pcfscope verify DIR: is every receiver pixel of a `render --raw` folder inside the visibility
// envelope a conformant texture unit may produce (measure/conformance.h)? Exit 0: all inside;
// 1: some outside (the worst is printed with its pixel); 2: bad input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/render_options.h"
#include "base/input_file.h"
#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "kernel/shading.h"
#include "kernel/trace_json.h"
#include "measure/conformance.h"
#include "render/image_io.h"
#include "render/render_settings.h"

namespace pcf {

namespace {

struct VerifyOptions {
    std::string dir;
    int subTexelBits = 4;
    int weightBits = 8;
    int referenceBits = 0;
};

// The render.json that `render --raw` writes, read by nlohmann-json. Throws UsageError naming
// the file when it is not JSON, or a key is missing or of the wrong type.
Json readRenderJson(const std::string& text, const std::string& path) {
    Json j = Json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        throw UsageError("render.json is not a JSON object (" + path + ")");
    }
    return j;
}

std::string jsonField(const Json& json, const std::string& key, const std::string& path) {
    auto it = json.find(key);
    if (it == json.end()) throw UsageError("render.json has no \"" + key + "\" (" + path + ")");
    if (!it->is_string()) {
        throw UsageError("render.json: \"" + key + "\" is not a string (" + path + ")");
    }
    return it->get<std::string>();
}

float jsonFloat(const Json& json, const std::string& key, const std::string& path) {
    auto it = json.find(key);
    if (it == json.end()) throw UsageError("render.json has no \"" + key + "\" (" + path + ")");
    // Asked as a double: 1e300 is a JSON number, but no float (the cast would be undefined).
    if (!it->is_number() || !std::isfinite(it->get<double>()) ||
        std::abs(it->get<double>()) > static_cast<double>(std::numeric_limits<float>::max())) {
        throw UsageError("render.json: \"" + key + "\" is not a number (" + path + ")");
    }
    return it->get<float>();
}

bool jsonBool(const Json& json, const std::string& key, const std::string& path) {
    auto it = json.find(key);
    if (it == json.end()) throw UsageError("render.json has no \"" + key + "\" (" + path + ")");
    if (!it->is_boolean()) {
        throw UsageError("render.json: \"" + key + "\" is not true or false (" + path + ")");
    }
    return it->get<bool>();
}

FloatImage readImage(const std::filesystem::path& path, int channels) {
    FloatImage img;
    try {
        img = readFloatImage(path.string());
    } catch (const ImageError& e) {
        throw UsageError(e.what());
    }
    if (img.channels != channels) {
        throw UsageError(path.string() + ": has " + std::to_string(img.channels) +
                         " channels, expected " + std::to_string(channels));
    }
    return img;
}

// A whole number in render.json, within the table's range of parameter p. Checked as a double
// before the cast: a float outside int's range (1e30) is undefined behaviour there.
int jsonInt(const Json& json, const ParamInfo& p, const std::string& path) {
    std::string key(p.key);
    double v = static_cast<double>(jsonFloat(json, key, path));
    if (!(v >= p.min && v <= p.max) || v != std::floor(v)) {
        throw UsageError("render.json: \"" + key + "\" is not a whole number in [" +
                         std::to_string(static_cast<int>(p.min)) + ", " +
                         std::to_string(static_cast<int>(p.max)) + "] (" + path + ")");
    }
    return static_cast<int>(v);
}

// Parameter p's value in render.json, into s: written as the table's field says
// (app/render_options.h settingsJson): a number, true or false, or a name.
void readParam(const Json& json, const ParamInfo& p, ShadowSettings& s, const std::string& path) {
    std::string key(p.key);
    std::visit(
        [&](const auto& field) {
            using F = std::decay_t<decltype(field)>;
            if constexpr (std::is_same_v<F, float ShadowSettings::*>) {
                s.*field = jsonFloat(json, key, path);
            } else if constexpr (std::is_same_v<F, int ShadowSettings::*>) {
                s.*field = jsonInt(json, p, path);
            } else if constexpr (std::is_same_v<F, bool ShadowSettings::*>) {
                s.*field = jsonBool(json, key, path);
            } else {
                std::string name = jsonField(json, key, path);
                auto value = field.fromName(name);
                if (!value) {
                    throw UsageError("render.json: unknown " + std::string(field.noun) + " '" +
                                     name + "' (" + path + ")");
                }
                s.*field.field = *value;
            }
        },
        p.field);
}

// What `render --raw` rendered with, from its render.json: the settings the parameter table
// marks rawJson, what the kernel filtered with, and the map (whose layer's fit each pixel's
// lookup was computed from besides its position and normal).
struct RawSettings {
    ShadowSettings settings;
    // The map as render.json describes it ("map"); folders written before it have none.
    std::optional<MapSpec> map;
    PcfParams prm;
    PcfBias bias = PcfBias(PCF_BIAS_CONSTANT, vec2(0.0f), 0.0f, DEFAULT_RPDB_MAX);
};

// The layer scene.frag looked each pixel up with besides its position and normal: its fit (the
// light's clip matrix) and one texel's world size at clip w = 1. None for a folder written before
// render.json held the map, or a map without a texel size.
const PcfMapLayer* lookupLayer(const RawSettings& r) {
    if (!r.map || r.map->layers.size() != 1 || !(r.map->layers.front().texelWs > 0.0f)) {
        return nullptr;
    }
    return &r.map->layers.front();
}

RawSettings readRawSettings(const std::filesystem::path& dir) {
    std::filesystem::path jsonPath = dir / "render.json";
    std::string where = jsonPath.string();
    // The input path every text input takes (base/input_file.h): a FIFO or a device is
    // refused before it is opened, a file over the size limit before it is read.
    Json json = readRenderJson(readInputFile(where), where);

    RawSettings r;
    for (const ParamInfo& p : allParams()) {
        if (!p.rawJson) continue;
        // Keys that folders written before the parameter lack: its default (the table says which).
        if (p.rawJsonMayLack && !json.contains(std::string(p.key))) continue;
        readParam(json, p, r.settings, where);
    }
    // In the table's ranges, as every command line and lesson value is.
    if (std::optional<ParamProblem> why = checkSettingRanges(r.settings)) {
        throw UsageError("render.json: " + why->text() + " (" + where + ")");
    }
    // pcss's light size in the map; folders written before pcss have none (0: no method used it).
    float penumbraScale = 0.0f;
    if (json.contains("penumbra_scale")) penumbraScale = jsonFloat(json, "penumbra_scale", where);
    r.prm = r.settings.pcfParams(vec2(1.0f, 0.0f), penumbraScale);
    // A spot map's near and far for pcss; folders written before them have none (0: linear).
    if (json.contains("pcss_depth_near") || json.contains("pcss_depth_far")) {
        r.prm.depthNear = jsonFloat(json, "pcss_depth_near", where);
        r.prm.depthFar = jsonFloat(json, "pcss_depth_far", where);
    }
    r.bias = r.settings.kernelBias();
    if (json.contains("map")) {
        std::string why;
        r.map = mapSpecFromJson(json["map"], why);
        if (!r.map) throw UsageError("render.json: " + why + " (" + where + ")");
    }
    // render.json's keys are the kernel's words.
    if (auto why = validateParams(r.prm))
        throw UsageError("render.json: " + *why + " (" + where + ")");
    return r;
}

// The map shadowmap.exr holds: render.json's "map", which must match the image's size, in the
// texel kind the method reads in the folder's depth_format (checkMapTexels holds "map" to it
// once the image has been checked against that format); for a folder without one, the image's
// size, one layer.
MapSpec rawMapSpec(const ShadowMap& image, const RawSettings& r, const std::string& where) {
    TexelKind kind = mapTexelKind(r.settings.method, r.settings.depthFormat, r.settings.momentBits);
    MapSpec spec = r.map.value_or(MapSpec{image.size(), kind, {MapSpec::unfittedLayer()}});
    spec.texels = kind;
    if (texelKindInfo(kind).channels != image.spec().texel().channels) {
        throw UsageError("shadowmap.exr has " + std::to_string(image.spec().texel().channels) +
                         " channel(s), but " + std::string(methodInfo(r.settings.method).name) +
                         " reads a map of " + std::to_string(texelKindInfo(kind).channels) + " (" +
                         where + ")");
    }
    if (spec.size != image.size() || spec.layers.size() != 1) {
        throw UsageError("render.json: \"map\" is " + std::to_string(spec.size.x) + "x" +
                         std::to_string(spec.size.y) + " in " + std::to_string(spec.layers.size()) +
                         " layer(s), but shadowmap.exr is one layer of " +
                         std::to_string(image.width()) + "x" + std::to_string(image.height()) +
                         " (" + where + ")");
    }
    return spec;
}

// render.json's "map" names the texel kind its method reads in its depth_format.
void checkMapTexels(const RawSettings& r, const std::string& where) {
    TexelKind kind = mapTexelKind(r.settings.method, r.settings.depthFormat, r.settings.momentBits);
    if (!r.map || r.map->texels == kind) return;
    throw UsageError("render.json: \"map\" holds texels " +
                     std::string(texelKindName(r.map->texels)) + ", but " +
                     std::string(methodInfo(r.settings.method).name) + " reads depth_format " +
                     std::string(texelKindName(kind)) + " (" + where + ")");
}

// The folder's images: the map compared with, each pixel's lookup and visibility, each pixel's
// plane (dzduv.exr), and where present what the lookup was computed from: the world position
// (positions.exr) and the normal with cos(theta) (normals.exr).
struct RawImages {
    ShadowMap map;
    FloatImage lightSpace;  // u, v, ref, receiver (1 or 0)
    FloatImage visibility;
    FloatImage planes;     // dz/du, dz/dv, z before bias, 1 on receivers (dzduv.exr)
    FloatImage positions;  // world x, y, z, 1 where drawn; empty when the folder has none
    FloatImage normals;    // n facing the camera, cos(theta); empty when the folder has none
};

// Whether each pixel's lookup can be recomputed whole: the layer's fit, positions and normals.
bool recomputesWhole(const RawImages& img, const RawSettings& r) {
    return lookupLayer(r) && !img.positions.data.empty() && !img.normals.data.empty();
}

// An image of the folder the size of lightspace.exr with 4 channels, or an empty one when the
// file does not exist.
FloatImage readOptionalImage(const std::filesystem::path& path, const FloatImage& like) {
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec))) return {};
    FloatImage img = readImage(path, 4);
    if (img.width != like.width || img.height != like.height) {
        throw UsageError(path.string() + " and lightspace.exr differ in size");
    }
    return img;
}

RawImages readRawImages(const std::filesystem::path& dir, const RawSettings& r) {
    RawImages img;
    try {
        img.map = readMapImage((dir / "shadowmap.exr").string());
    } catch (const ImageError& e) {
        throw UsageError(e.what());
    }
    img.map.setSpec(rawMapSpec(img.map, r, (dir / "render.json").string()));
    img.lightSpace = readImage(dir / "lightspace.exr", 4);
    img.visibility = readImage(dir / "visibility.exr", 1);
    const FloatImage& ls = img.lightSpace;
    if (ls.width != img.visibility.width || ls.height != img.visibility.height) {
        throw UsageError("lightspace.exr and visibility.exr differ in size (" + dir.string() + ")");
    }
    // Each pixel's plane (dz/du, dz/dv, as the shader derived them) and depth before bias.
    img.planes = readImage(dir / "dzduv.exr", 4);
    if (img.planes.width != ls.width || img.planes.height != ls.height) {
        throw UsageError("dzduv.exr and lightspace.exr differ in size (" + dir.string() + ")");
    }
    img.positions = readOptionalImage(dir / "positions.exr", ls);
    img.normals = readOptionalImage(dir / "normals.exr", ls);
    return img;
}

// How far a recomputed lookup may be from the shader's: GLSL rounds each float operation
// correctly, but the driver may order a matrix product's sums otherwise, or turn a division by
// w into a multiply by 1 / w: an ulp or two of values of at most 1.
constexpr float LOOKUP_SLACK = 1.0e-6f;

// The bias render.json names, in words, with the parameters its lookups were made with: those
// the table says act under the mode and the scene pass applies per lookup (no kernel member):
// "slope (constant_bias 0.002, slope_bias 0.001, ...)".
std::string biasWords(const ShadowSettings& s) {
    std::string words(biasModeName(s.bias));
    std::string params;
    for (const ParamInfo& p : allParams()) {
        if (!paramActsUnder(p, s.bias) || !std::holds_alternative<std::monostate>(p.member))
            continue;
        params += (params.empty() ? "" : ", ") + std::string(p.key) + " " + settingText(p, s);
    }
    return params.empty() ? words : words + " (" + params + ")";
}

// The lookup of receiver pixel k as scene.frag made it (shaders/shared/pcf_shading.h
// pcfReceiverLookup, the very function the shader runs), from its world position, its normal
// and cos(theta), render.json's light matrix and bias: every bias mode recomputed exactly.
// Without the normals or the matrix (folders written before render --raw kept them) only ref
// from the depth before bias, for the modes that need nothing else.
PcfReceiverLookup recomputedLookup(const RawImages& img, const RawSettings& r, size_t k) {
    const ShadowSettings& s = r.settings;
    const float* ls = &img.lightSpace.data[4 * k];
    float z0 = img.planes.data[4 * k + 2];
    if (!recomputesWhole(img, r)) return PcfReceiverLookup(ls[0], ls[1], z0, z0, z0 - s.baseBias());
    const PcfMapLayer& layer = *lookupLayer(r);
    const float* p = &img.positions.data[4 * k];
    const float* n = &img.normals.data[4 * k];
    return pcfReceiverLookup(layer.shadowClipFromWorld, vec3(p[0], p[1], p[2]),
                             vec3(n[0], n[1], n[2]), n[3], s.modeId(), s.constantBias, s.slopeBias,
                             s.slopeMax, s.normalOffset, layer.texelWs);
}

// Every receiver pixel's u, v, depth before bias and ref against recomputedLookup, within
// LOOKUP_SLACK. A label that does not fit the pixels (a bias amount, a relabelled mode: slope
// for a constant-bias render, a slope_bias 50 times the rendered one) is bad input. Returns the
// number of pixels checked.
long checkLookups(const RawImages& img, const RawSettings& r, const std::string& dir) {
    const ShadowSettings& s = r.settings;
    if (!recomputesWhole(img, r) && (s.bias == BiasMode::Slope || s.bias == BiasMode::Normal)) {
        throw UsageError(dir + ": bias " + std::string(biasModeName(s.bias)) +
                         " depends on each pixel's angle to the light, and the folder lacks "
                         "normals.exr, positions.exr or render.json's map; "
                         "render it again with `pcfscope render --raw`");
    }
    const FloatImage& ls = img.lightSpace;
    long checked = 0;
    for (int y = 0; y < ls.height; ++y) {
        for (int x = 0; x < ls.width; ++x) {
            size_t k = static_cast<size_t>(y) * ls.width + x;
            if (ls.data[4 * k + 3] != 1.0f) continue;
            PcfReceiverLookup at = recomputedLookup(img, r, k);
            const std::pair<const char*, std::pair<float, float>> quantities[] = {
                {"u", {ls.data[4 * k], at.u}},
                {"v", {ls.data[4 * k + 1], at.v}},
                {"depth before bias", {img.planes.data[4 * k + 2], at.z0}},
                {"ref", {ls.data[4 * k + 2], at.ref}}};
            for (const auto& [what, values] : quantities) {
                if (img.planes.data[4 * k + 3] == 1.0f &&
                    std::abs(values.first - values.second) <= LOOKUP_SLACK) {
                    continue;
                }
                char buf[160];
                std::snprintf(buf, sizeof buf, "pixel (%d, %d) has %s %.9g, recomputed %.9g", x, y,
                              what, static_cast<double>(values.first),
                              static_cast<double>(values.second));
                throw UsageError(dir + ": render.json does not describe these images: " + buf +
                                 " under bias " + biasWords(s));
            }
            ++checked;
        }
    }
    return checked;
}

// A fixed-point map (16 or 24 bits) holds only the values k / (2^n - 1): the depth buffer keeps
// the integer k (OpenGL 4.5 core, 2.3.5 "Fixed-Point Data Conversions"). A texel off that grid
// means the map is not the format render.json names (a 32F map labelled 16). Near 1 a float
// cannot tell 24-bit levels apart; the slack (two float ulps of the texel, in levels) says so.
void checkDepthFormat(const ShadowMap& map, const std::string& path) {
    int bits = map.fixedPointBits();
    TexelKind format = map.spec().texels;
    if (bits == 0) return;
    double levels = std::ldexp(1.0, bits) - 1.0;
    const std::vector<float>& depths = map.depths();
    for (size_t k = 0; k < depths.size(); ++k) {
        float d = depths[k];
        double scaled = static_cast<double>(d) * levels;
        double ulp = static_cast<double>(std::nextafter(d, 2.0f) - d);
        if (std::abs(scaled - std::round(scaled)) <= std::max(1.0e-3, 2.0 * ulp * levels)) continue;
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "texel (%zu, %zu) is %.9g, not a %d-bit depth value (render.json says "
                      "depth_format \"%s\")",
                      k % static_cast<size_t>(map.width()), k / static_cast<size_t>(map.width()),
                      static_cast<double>(d), bits, std::string(depthFormatName(format)).c_str());
        throw UsageError(path + ": " + buf);
    }
}

// Every receiver pixel's visibility against the envelope of what a GPU may return there.
struct EnvelopeTally {
    long receivers = 0;
    long inside = 0;
    float worst = 0.0f;  // the largest distance outside the envelope
    glm::ivec2 worstPixel{-1};
    float worstValue = 0.0f;
    VisibilityEnvelope worstEnv;
};

EnvelopeTally checkEnvelopes(const RawImages& img, const RawSettings& r,
                             const ConformancePrecision& prec) {
    const FloatImage& ls = img.lightSpace;
    EnvelopeTally t;
    for (int y = 0; y < ls.height; ++y) {
        for (int x = 0; x < ls.width; ++x) {
            size_t k = static_cast<size_t>(y) * ls.width + x;
            if (ls.data[4 * k + 3] != 1.0f) continue;
            vec2 uv(ls.data[4 * k], ls.data[4 * k + 1]);
            float ref = ls.data[4 * k + 2];
            if (!std::isfinite(uv.x) || !std::isfinite(uv.y) || !std::isfinite(ref)) {
                throw UsageError("lightspace.exr: pixel (" + std::to_string(x) + ", " +
                                 std::to_string(y) + ") is not finite");
            }
            ++t.receivers;
            PcfParams p = r.prm;
            // The disk turns with the texel looked up, as scene.frag turns it.
            if (r.settings.rotate)
                p.rotation = pcfTexelRotation(uv, ivec2(img.map.width(), img.map.height()));
            PcfBias b = r.bias;
            if (r.bias.mode == PCF_BIAS_RECEIVER_PLANE) {
                b.dzduv = vec2(img.planes.data[4 * k], img.planes.data[4 * k + 1]);
            }
            VisibilityEnvelope env = visibilityEnvelope(img.map, uv, ref, p, b, prec);
            float v = img.visibility.data[k];
            if (env.contains(v)) {
                ++t.inside;
                continue;
            }
            float miss = v < env.lo ? env.lo - v : v - env.hi;
            if (miss > t.worst) {
                t.worst = miss;
                t.worstPixel = {x, y};
                t.worstValue = v;
                t.worstEnv = env;
            }
        }
    }
    return t;
}

int runVerify(const VerifyOptions& o) {
    requireIntRange("--subtexel-bits", o.subTexelBits, 1, 16);
    requireIntRange("--weight-bits", o.weightBits, 1, 16);
    requireIntRange("--reference-bits", o.referenceBits, 0, 24);
    std::filesystem::path dir(o.dir);
    RawSettings r = readRawSettings(dir);
    RawImages img = readRawImages(dir, r);
    checkDepthFormat(img.map, (dir / "shadowmap.exr").string());
    checkMapTexels(r, (dir / "render.json").string());
    long refsChecked = checkLookups(img, r, dir.string());
    ConformancePrecision prec{o.subTexelBits, o.weightBits, o.referenceBits};
    EnvelopeTally t = checkEnvelopes(img, r, prec);
    if (t.receivers == 0) throw UsageError("no receiver pixels in " + dir.string());

    const PcfParams& prm = r.prm;
    std::string what(methodInfo(prm.method).name);
    if (methodInfo(prm.method).usesKernel) what += " N=" + std::to_string(prm.kernel);
    if (prm.weights != PCF_WEIGHTS_BOX) what += " " + std::string(weightsName(prm.weights));
    std::string refBits =
        o.referenceBits > 0 ? std::to_string(o.referenceBits) : std::string("format's");
    std::printf(
        "verify %s: %s, bias %s, map %dx%d %s, precision %s; envelope: %d sub-texel bits, "
        "%d weight bits, %s reference bits\n",
        dir.string().c_str(), what.c_str(), std::string(biasModeName(r.settings.bias)).c_str(),
        img.map.width(), img.map.height(),
        std::string(depthFormatName(r.settings.depthFormat)).c_str(),
        std::string(precisionName(prm.precision)).c_str(), o.subTexelBits, o.weightBits,
        refBits.c_str());
    std::printf("lookup (u, v, ref) of all %ld receiver pixels recomputed from %s: as rendered\n",
                refsChecked,
                recomputesWhole(img, r)
                    ? "position, normal and bias"
                    : "depth and bias (the folder has no normals: u, v not recomputed)");
    std::printf("%ld of %ld receiver pixels inside the envelope (%.4f %%)\n", t.inside, t.receivers,
                100.0 * static_cast<double>(t.inside) / static_cast<double>(t.receivers));
    if (t.inside == t.receivers) return 0;
    std::printf(
        "worst outlier: pixel (%d, %d) (top-left origin): visibility %.7g, envelope "
        "[%.7g, %.7g], outside by %.3g\n",
        t.worstPixel.x, t.worstPixel.y, static_cast<double>(t.worstValue),
        static_cast<double>(t.worstEnv.lo), static_cast<double>(t.worstEnv.hi),
        static_cast<double>(t.worst));
    return 1;
}

}  // namespace

int verifyFolder(const std::string& dir) {
    VerifyOptions o;
    o.dir = dir;
    return runVerify(o);
}

Command addVerifyCommand(CLI::App& app) {
    auto o = std::make_shared<VerifyOptions>();
    CLI::App* sub = app.add_subcommand(
        "verify", "check a `render --raw` folder against the conformance envelope of any GPU");
    sub->add_option("dir", o->dir, "a folder written by `pcfscope render --raw DIR`")->required();
    sub->add_option("--subtexel-bits", o->subTexelBits,
                    "sub-texel precision of the texture unit (default 4: Vulkan's minimum)");
    sub->add_option("--weight-bits", o->weightBits, "precision of the lerp weights (default 8)");
    sub->add_option(
        "--reference-bits", o->referenceBits,
        "precision of the depth comparison (default: 16/24 for fixed-point, 22 for 32F)");
    return {sub, [o] { return runVerify(*o); }};
}

}  // namespace pcf
