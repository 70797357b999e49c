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
#include "app/raw_folder.h"
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
#include "scene/cascade_fit.h"

namespace pcf {

namespace {

struct VerifyOptions {
    std::string dir;
    int subTexelBits = 4;
    int weightBits = 8;
    int referenceBits = 0;
};

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

// Receiver pixel k looked up in `layer` of render.json's map from its world position, normal and
// cos(theta) (kernel/shading.h layerReceiverLookup, as scene.frag's layerLookup).
PcfReceiverLookup pixelLookupIn(const RawImages& img, const RawSettings& r, size_t k,
                                const PcfMapLayer& layer) {
    const float* p = &img.positions.data[4 * k];
    const float* n = &img.normals.data[4 * k];
    return layerReceiverLookup(layer, r.settings, vec3(p[0], p[1], p[2]), vec3(n[0], n[1], n[2]),
                               n[3], r.map->layers.size() > 1);
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
    // Past the last cascade scene.frag looks up in the last (and draws the pixel lit).
    int count = static_cast<int>(r.map->layers.size());
    return pixelLookupIn(img, r, k, *lookupLayer(r, std::min(pixelLayer(img, r, k), count - 1)));
}

// Every receiver pixel's u, v, depth before bias and ref against recomputedLookup, within
// LOOKUP_SLACK. A label that does not fit the pixels (a bias amount, a relabelled mode: slope
// for a constant-bias render, a slope_bias 50 times the rendered one) is bad input. Returns the
// number of pixels checked.
long checkLookups(const RawImages& img, const RawSettings& r, const std::string& dir) {
    const ShadowSettings& s = r.settings;
    if (!recomputesWhole(img, r) && r.map && r.map->layers.size() > 1) {
        throw UsageError(dir +
                         ": a cascaded map's pixels are checked from positions.exr, "
                         "normals.exr and each layer's fit, which the folder lacks; render it "
                         "again with `pcfscope render --raw`");
    }
    if (img.layers.size() > 1 && s.cascadeBlend > 0.0f && s.bias == BiasMode::ReceiverPlane &&
        img.nextPlanes.data.empty()) {
        throw UsageError(dir +
                         ": under receiver-plane bias a blend band filters the next cascade with "
                         "the receiver's plane there (next_dzduv.exr), which the folder lacks; "
                         "render it again with `pcfscope render --raw`");
    }
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

// How far, relative, the receivers' view depths recomputed from positions.exr may be from
// render.json's depth_min and depth_max (the prepass measured them in another program, the GPU's
// float arithmetic) and a cascade's ends from the split recomputed here.
constexpr double BOUNDS_SLACK = 1.0e-5;

// The smallest and largest view depth of the receiver pixels, along the cascade camera
// (shared/pcf_shading.h pcfViewDepth of positions.exr), and how many lie past the last cascade
// while nearer than the shadow distance (which a cascade should have covered).
struct ReceiverDepths {
    float lo = std::numeric_limits<float>::infinity();
    float hi = -std::numeric_limits<float>::infinity();
    long pastLast = 0;
};

ReceiverDepths receiverDepths(const RawImages& img, const RawSettings& r) {
    ReceiverDepths d;
    int count = static_cast<int>(r.map->layers.size());
    for (size_t k = 0; k < img.lightSpace.data.size() / 4; ++k) {
        if (img.lightSpace.data[4 * k + 3] != 1.0f) continue;
        const float* p = &img.positions.data[4 * k];
        float depth =
            pcfViewDepth(vec3(p[0], p[1], p[2]), r.cascadeEyeDir->first, r.cascadeEyeDir->second);
        d.lo = std::min(d.lo, depth);
        d.hi = std::max(d.hi, depth);
        if (pixelLayer(img, r, k) >= count && depth < r.map->cascadeDepths.y) ++d.pastLast;
    }
    return d;
}

// --cascade-bounds depth (render.json's "map" holds depth_min and depth_max, the frame's visible
// receivers' view depths as the renderer measured them): they must be the receiver pixels' own,
// and the cascades must split [camera_near, shadow_distance] tightened to them
// (scene/cascade_fit.h cascadeRangesOver); a render.json that says otherwise does not describe
// the images. Returns the receiver pixels past the last cascade though nearer than the shadow
// distance (-1 for a folder without depth bounds).
long checkCascadeBounds(const RawImages& img, const RawSettings& r, const std::string& dir) {
    if (!r.map || !r.map->visibleDepths || !r.cascadeEyeDir || img.positions.data.empty())
        return -1;
    const MapSpec& map = *r.map;
    ReceiverDepths d = receiverDepths(img, r);
    auto near = [](double a, double b) { return std::abs(a - b) <= BOUNDS_SLACK * std::abs(b); };
    char buf[200];
    if (!near(d.lo, map.visibleDepths->x) || !near(d.hi, map.visibleDepths->y)) {
        std::snprintf(buf, sizeof buf,
                      "depth_min %.9g and depth_max %.9g, but its receiver pixels' view depths "
                      "run from %.9g to %.9g",
                      static_cast<double>(map.visibleDepths->x),
                      static_cast<double>(map.visibleDepths->y), static_cast<double>(d.lo),
                      static_cast<double>(d.hi));
        throw UsageError(dir + ": render.json does not describe these images: it says " + buf);
    }
    std::vector<CascadeRange> ranges =
        cascadeRangesOver(map.cascadeDepths.x, map.cascadeDepths.y, r.settings, map.visibleDepths);
    for (size_t k = 0; k < ranges.size() && k < map.layers.size(); ++k) {
        vec2 got = map.layers[k].viewDepth;
        if (ranges.size() == map.layers.size() && near(got.x, ranges[k].nearZ) &&
            near(got.y, ranges[k].farZ)) {
            continue;
        }
        std::snprintf(buf, sizeof buf,
                      "cascade %zu covers [%.9g, %.9g], but the split of [%.9g, %.9g] tightened to "
                      "depth_min and depth_max gives [%.9g, %.9g]",
                      k, static_cast<double>(got.x), static_cast<double>(got.y),
                      static_cast<double>(map.cascadeDepths.x),
                      static_cast<double>(map.cascadeDepths.y),
                      static_cast<double>(ranges[k].nearZ), static_cast<double>(ranges[k].farZ));
        throw UsageError(dir + ": render.json does not describe these images: " + buf);
    }
    return d.pastLast;
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

// A pixel in a cascade's blend band (cascade_blend; shared/pcf_shading.h pcfCascadeBlendWeight):
// the camera pass mixed the next cascade's lookup of its point into `env`'s, by the band's
// weight, so its envelope is the same mix of the two cascades' envelopes (a mix of a value in
// each interval lies in the mixed interval). The next lookup is recomputed from the pixel's world
// position and normal (as recomputedLookup); under receiver-plane bias it is filtered with the
// pixel's plane in the next cascade, the GPU's own derivative (next_dzduv.exr).
VisibilityEnvelope blendedEnvelope(const RawImages& img, const RawSettings& r, size_t k, int layer,
                                   VisibilityEnvelope env, PcfParams p, PcfBias b,
                                   const ConformancePrecision& prec) {
    int count = static_cast<int>(img.layers.size());
    if (!r.cascadeEyeDir || layer + 1 >= count || !(r.settings.cascadeBlend > 0.0f)) return env;
    const ShadowSettings& s = r.settings;
    float w = pcfCascadeBlendWeight(pixelViewDepth(img, r, k),
                                    r.map->layers[static_cast<size_t>(layer)].viewDepth,
                                    s.cascadeBlend, layer, count);
    if (!(w > 0.0f)) return env;
    PcfReceiverLookup at = pixelLookupIn(img, r, k, *lookupLayer(r, layer + 1));
    const ShadowMap& map = img.layers[static_cast<size_t>(layer + 1)];
    if (s.rotate) p.rotation = pcfTexelRotation(vec2(at.u, at.v), ivec2(map.width(), map.height()));
    // checkLookups made sure the folder has the next planes receiver-plane bias needs.
    if (b.mode == PCF_BIAS_RECEIVER_PLANE) b.dzduv = *nextReceiverPlane(img, k);
    VisibilityEnvelope other = visibilityEnvelope(map, vec2(at.u, at.v), at.ref, p, b, prec);
    return {pcfCascadeBlend(env.lo, other.lo, w), pcfCascadeBlend(env.hi, other.hi, w)};
}

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
            // The layer the pixel read; past the last cascade the camera pass draws it lit.
            int layer = pixelLayer(img, r, k);
            VisibilityEnvelope env{1.0f, 1.0f};
            if (layer < static_cast<int>(img.layers.size())) {
                env =
                    visibilityEnvelope(img.layers[static_cast<size_t>(layer)], uv, ref, p, b, prec);
                env = blendedEnvelope(img, r, k, layer, env, r.prm, b, prec);
            }
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
    long pastLast = checkCascadeBounds(img, r, dir.string());
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
    if (pastLast >= 0) {
        std::printf(
            "cascade bounds depth [%.7g, %.7g]: the receivers' own view depths; %ld receiver "
            "pixels nearer than the shadow distance past the last cascade\n",
            static_cast<double>(r.map->visibleDepths->x),
            static_cast<double>(r.map->visibleDepths->y), pastLast);
    }
    std::printf("%ld of %ld receiver pixels inside the envelope (%.4f %%)\n", t.inside, t.receivers,
                100.0 * static_cast<double>(t.inside) / static_cast<double>(t.receivers));
    if (pastLast > 0) return 1;
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
