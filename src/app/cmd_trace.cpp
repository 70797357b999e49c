// pcfscope trace: one lookup's step-through, as text or as DESIGN.md section 4's JSON.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/render_options.h"
#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "kernel/trace.h"
#include "kernel/trace_json.h"
#include "render/image_io.h"

namespace pcf {

namespace {

struct TraceOptions {
    std::string mapPath;
    bool example = false;
    std::string uv;
    float z = 0.0f;
    std::string bias = "none";  // a bias mode name, as render's --bias
    float constantBias = DEFAULT_CONSTANT_BIAS;
    float slopeBias = DEFAULT_SLOPE_BIAS;
    float slopeMax = DEFAULT_SLOPE_MAX;
    float normalOffset = DEFAULT_NORMAL_OFFSET;
    float softScale = DEFAULT_SOFT_SCALE;
    float rpdbMax = DEFAULT_RPDB_MAX;
    float angleDeg = 0.0f;    // slope: the angle between the receiver's normal and the light
    std::string dzduv;        // receiver-plane: "DU,DV"
    CLI::App* sub = nullptr;  // to ask which options were given
    std::string method = "bilinear2x2";
    int kernel = 3;
    float radius = 1.0f;
    float rotationDeg = 0.0f;
    bool json = false;
    std::string weights = "box";
    float sigma = 1.0f;
    std::string precision = "exact";
    std::string depthFormat = "32f";
};

// Beyond this |uv| every tap of every method already reads edge texels (the widest reach is a
// 64-texel Poisson disk on a 4-texel map: 16 uv units), so clamping there changes no result and
// keeps uv * size far from int overflow.
constexpr float UV_LIMIT = 20.0f;

// The built-in example's lookup: bits 1 and 0 at fx = 0.2, as in "What Is PCF"'s worked example.
constexpr const char* EXAMPLE_UV = "0.4625,0.3875";
constexpr float EXAMPLE_Z = 0.5f;

// The filter's parameters: the shared options' parsing and checks (render_options.h), and
// trace's own --rotation.
PcfParams traceParams(const TraceOptions& o) {
    int method = methodOption(o.method);
    checkGivenKernelOptions(o.sub->count("--kernel") > 0, o.kernel, o.sub->count("--radius") > 0,
                            o.radius);
    float rad = o.rotationDeg * 0.0174532925f;
    PcfParams prm = makeParams(method, o.kernel, o.radius, vec2(std::cos(rad), std::sin(rad)));
    prm.weights = weightsOption(o.weights);
    prm.sigma = o.sigma;
    prm.precision = precisionOption(o.precision);
    if (auto why = cliParamsProblem(prm)) throw UsageError(*why);
    requireRange("--rotation", o.rotationDeg, -360.0f, 360.0f);
    return prm;
}

// The bias: the shared options, and trace's --angle and --dzduv that stand in for the receiver
// the renderer would know.
BiasParams traceBias(const TraceOptions& o, int method) {
    BiasParams bias;
    bias.mode = static_cast<int>(biasModeOption(o.bias));
    bias.constant = o.constantBias;
    bias.slope = o.slopeBias;
    bias.slopeMax = o.slopeMax;
    bias.normalOffset = o.normalOffset;
    bias.softScale = o.softScale;
    bias.rpdbMax = o.rpdbMax;
    if (auto why = cliBiasProblem(bias)) throw UsageError(*why);
    // trace's default mode is none: a parameter given without a mode would do nothing.
    if (o.sub->count("--bias") == 0) {
        for (const char* p : {"--constant-bias", "--slope-bias", "--slope-max", "--normal-offset",
                              "--soft-scale", "--rpdb-max"}) {
            if (o.sub->count(p) > 0) {
                throw UsageError(std::string(p) + " needs --bias NAME (trace's default is none)");
            }
        }
    }
    checkBiasOptions(bias, method);
    requireRange("--angle", o.angleDeg, 0.0f, 90.0f);
    if (o.sub->count("--angle") > 0 && bias.mode != PCF_BIAS_SLOPE) {
        throw UsageError("--angle is for --bias slope (the angle its tan(theta) reads)");
    }
    if (o.sub->count("--dzduv") > 0) {
        if (bias.mode != PCF_BIAS_RECEIVER_PLANE) {
            throw UsageError("--dzduv is for --bias receiver-plane (the receiver's plane)");
        }
        bias.dzduv = parseVec2("--dzduv", o.dzduv);
        requireRange("--dzduv u", bias.dzduv.x, -1.0e6f, 1.0e6f);
        requireRange("--dzduv v", bias.dzduv.y, -1.0e6f, 1.0e6f);
    }
    return bias;
}

int runTrace(const TraceOptions& o) {
    if (o.example == !o.mapPath.empty()) {
        throw UsageError("trace needs exactly one of --map FILE or --example");
    }
    PcfParams prm = traceParams(o);
    int fixedBits = depthFormatFixedPointBits(depthFormatOption(o.depthFormat));
    BiasParams bias = traceBias(o, prm.method);

    ShadowMap map;
    std::string uvText = o.uv;
    bool zGiven = o.sub->count("--z") > 0;  // every float, NaN included, is a value
    float z = zGiven ? o.z : EXAMPLE_Z;
    if (o.example) {
        map = exampleShadowMap();
        if (uvText.empty()) uvText = EXAMPLE_UV;
    } else {
        if (uvText.empty() || !zGiven) {
            throw UsageError("trace --map needs --uv U,V and --z Z");
        }
        try {
            map = readDepthImage(o.mapPath);
        } catch (const ImageError& e) {
            throw UsageError(e.what());
        }
    }
    map.setFixedPointBits(fixedBits);
    // Any finite uv: texels outside the map clamp to the edge, as the GPU's sampler does; the
    // trace marks the taps that did.
    vec2 uv = glm::clamp(parseVec2("--uv", uvText), vec2(-UV_LIMIT), vec2(1.0f + UV_LIMIT));
    requireRange("--z", z, 0.0f, 1.0f);

    // The per-lookup bias (kernel/bias.h); normal offset has already moved the point given.
    float ref = z - bias.lookupBias(std::cos(o.angleDeg * 0.0174532925f));
    Trace tr = traceLookup(map, uv, z, ref, prm, bias);
    std::string out = o.json ? traceToJson(tr) + "\n" : traceToText(tr);
    std::fwrite(out.data(), 1, out.size(), stdout);
    return 0;
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
    sub->add_option("--uv", o->uv,
                    "shadow-map coordinates U,V; any finite values (outside [0,1] the taps clamp "
                    "to the edge)");
    o->sub = sub;
    sub->add_option("--z", o->z, "receiver depth in [0,1] as the light sees it");
    addBiasOptions(sub, o->bias, o->constantBias, o->slopeBias, o->slopeMax, o->normalOffset,
                   o->softScale, o->rpdbMax);
    sub->add_option(
        "--angle", o->angleDeg,
        "slope: angle in degrees between the receiver's normal and the light (default 0)");
    sub->add_option(
        "--dzduv", o->dzduv,
        "receiver-plane: the receiver's DU,DV = d(depth)/d(u, v) (render --raw writes them in "
        "dzduv.exr). For --bias normal give --uv and --z of the point already moved "
        "(lightspace.exr holds them)");
    addFilterOptions(sub, o->method, o->kernel, o->radius, o->weights, o->sigma, o->precision);
    sub->add_option("--rotation", o->rotationDeg, "poisson: disk rotation in degrees");
    sub->add_flag("--json", o->json, "print the trace as one JSON object");
    sub->add_option("--depth-format", o->depthFormat,
                    "the map's format: 16, 24 (fixed-point: ref clamped to [0,1]) or 32f");
    return {sub, [o] { return runTrace(*o); }};
}

}  // namespace pcf
