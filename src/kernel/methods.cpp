#include "kernel/methods.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "kernel/settings.h"
#include "kernel/sigma_limits.h"

namespace pcf {

namespace {

// Tent builds its N x N tent from 2, 3 or 4 hardware taps per axis (Castano, 2013, "Shadow
// Mapping Summary Part 1"): N = 3, 5 or 7.
constexpr int TENT_SIZES[] = {3, 5, 7};
// The moments pass blurs each texel over the N x N texels centred on it: N odd.
constexpr int MOMENT_SIZES[] = {1, 3, 5, 7};

// The charts' colours: Tableau 10, with the yellow and pink darkened to read on white.
constexpr std::array<MethodInfo, PCF_METHOD_COUNT> METHODS = {{
    {.id = PCF_NEAREST,
     .name = "nearest",
     .shortName = "nearest",
     .summary = "the one texel under the lookup, floor(uv * size): hard edges",
     .reads = MethodReads::Texels,
     .chartColour = {0.31f, 0.47f, 0.65f, 1.0f},
     .referencePass = "reference/nearest.frag",
     .hard = true,
     .nearestTexels = true,
     .reach = MethodReach::OneTexel},
    {.id = PCF_BOX2X2,
     .name = "box2x2",
     .shortName = "box",
     .summary = "the 2x2 texels at base averaged: only 0, .25, .5, .75, 1",
     .reads = MethodReads::Texels,
     .chartColour = {0.95f, 0.56f, 0.17f, 1.0f},
     .referencePass = "reference/box.frag",
     .reach = MethodReach::Block2x2},
    {.id = PCF_BILINEAR2X2,
     .name = "bilinear2x2",
     .shortName = "bilin",
     .summary =
         "the same 4 bits lerped by the sub-texel fraction (NVIDIA's hardware PCF, emulated)",
     .reads = MethodReads::Texels,
     .chartColour = {0.88f, 0.34f, 0.35f, 1.0f},
     .referencePass = "reference/naive.frag",
     .reach = MethodReach::Block2x2},
    {.id = PCF_HW2X2,
     .name = "hw2x2",
     .shortName = "hw2x2",
     .summary = "one tap of the hardware comparison sampler (sampler2DShadow, linear)",
     .reads = MethodReads::HwTaps,
     .chartColour = {0.36f, 0.66f, 0.64f, 1.0f},
     .referencePass = "reference/hw.frag",
     .reach = MethodReach::Block2x2},
    {.id = PCF_NAIVE,
     .name = "pcf-naive",
     .shortName = "naive",
     .summary = "N x N bilinear lookups one texel apart, averaged",
     .usesKernel = true,
     .takesWeights = true,
     .reads = MethodReads::Texels,
     .chartColour = {0.35f, 0.63f, 0.31f, 1.0f},
     .referencePass = "reference/naive.frag",
     .referenceTakesKernel = true,
     .overlappingLookups = true,
     .reach = MethodReach::Kernel},
    {.id = PCF_GATHER,
     .name = "pcf-gather",
     .shortName = "gather",
     .summary = "pcf-naive's result from the (N+1)^2 distinct texels, read by comparison gathers",
     .usesKernel = true,
     .takesWeights = true,
     .reads = MethodReads::Gathers,
     .chartColour = {0.80f, 0.62f, 0.05f, 1.0f},
     .referencePass = "reference/gather.frag",
     .referenceTakesKernel = true,
     .reach = MethodReach::Kernel},
    {.id = PCF_HW,
     .name = "pcf-hw",
     .shortName = "hw",
     .summary = "N x N hardware comparison taps one texel apart, averaged",
     .usesKernel = true,
     .reads = MethodReads::HwTaps,
     .chartColour = {0.69f, 0.48f, 0.63f, 1.0f},
     .referencePass = "reference/hw.frag",
     .referenceTakesKernel = true,
     .overlappingLookups = true,
     .reach = MethodReach::Kernel},
    {.id = PCF_TENT,
     .name = "tent",
     .shortName = "tent",
     .summary = "Castano's N x N tent (N = 3, 5, 7) from 4, 9 or 16 hardware taps",
     .usesKernel = true,
     .reads = MethodReads::HwTaps,
     .kernelSizes = TENT_SIZES,
     .chartColour = {0.84f, 0.30f, 0.62f, 1.0f},
     .referencePass = "reference/tent.frag",
     .referenceTakesKernel = true,
     .reach = MethodReach::Kernel},
    {.id = PCF_POISSON,
     .name = "poisson",
     .shortName = "poisson",
     .summary = "16 nearest-texel comparisons on a Poisson disk of radius R texels, optionally "
                "rotated",
     .usesRadius = true,
     .reads = MethodReads::Texels,
     .chartColour = {0.61f, 0.46f, 0.37f, 1.0f},
     .referencePass = "reference/poisson.frag",
     .nearestTexels = true,
     .hasDisk = true,
     .reach = MethodReach::Disk},
    {.id = PCF_PCSS,
     .name = "pcss",
     .shortName = "pcss",
     .summary = "soft shadows: a blocker search, a penumbra width from the light size, then "
                "poisson that wide",
     .reads = MethodReads::Texels,
     .chartColour = {0.47f, 0.47f, 0.47f, 1.0f},
     .referencePass = "reference/pcss.frag",
     .nearestTexels = true,
     .hasDisk = true,
     .searchesBlockers = true,
     .reach = MethodReach::BlockerDisk},
    {.id = PCF_VSM,
     .name = "vsm",
     .shortName = "vsm",
     .summary = "variance shadow map: mean and variance of the filtered depths, Chebyshev's "
                "bound",
     .usesKernel = true,
     .takesWeights = true,
     .reads = MethodReads::Texels,
     .kernelSizes = MOMENT_SIZES,
     .chartColour = {0.09f, 0.55f, 0.80f, 1.0f},
     .referencePass = "reference/vsm.frag",
     .reach = MethodReach::Kernel,
     .mapPass = MapPass::Moments2,
     .wantsLitFacesInMap = true},
    {.id = PCF_EVSM2,
     .name = "evsm2",
     .shortName = "evsm2",
     .summary = "exponential variance shadow map: Chebyshev's bound on exp(c+ (2z - 1))",
     .usesKernel = true,
     .takesWeights = true,
     .reads = MethodReads::Texels,
     .kernelSizes = MOMENT_SIZES,
     .chartColour = {0.55f, 0.34f, 0.75f, 1.0f},
     .referencePass = "reference/evsm2.frag",
     .reach = MethodReach::Kernel,
     .mapPass = MapPass::Moments2,
     .warps = 1,
     .wantsLitFacesInMap = true},
    {.id = PCF_EVSM4,
     .name = "evsm4",
     .shortName = "evsm4",
     .summary = "evsm2 and the negative warp -exp(-c- (2z - 1)), the smaller bound",
     .usesKernel = true,
     .takesWeights = true,
     .reads = MethodReads::Texels,
     .kernelSizes = MOMENT_SIZES,
     .chartColour = {0.36f, 0.20f, 0.55f, 1.0f},
     .referencePass = "reference/evsm4.frag",
     .reach = MethodReach::Kernel,
     .mapPass = MapPass::Moments4,
     .warps = 2,
     .wantsLitFacesInMap = true},
    {.id = PCF_MSM,
     .name = "msm",
     .shortName = "msm",
     .summary = "moment shadow map (Hamburger): four moments, the least shadow of any "
                "three-depth distribution with them",
     .usesKernel = true,
     .takesWeights = true,
     .reads = MethodReads::Texels,
     .kernelSizes = MOMENT_SIZES,
     .chartColour = {0.05f, 0.50f, 0.40f, 1.0f},
     .referencePass = "reference/msm.frag",
     .reach = MethodReach::Kernel,
     .mapPass = MapPass::Moments4,
     .reconstructs = true,
     .wantsLitFacesInMap = true},
    {.id = PCF_MSM_HAUSDORFF,
     .name = "msm-hausdorff",
     .shortName = "msm-h",
     .summary = "msm with the depths held to [0, 1] (Hausdorff): a four-depth distribution "
                "where three fall outside",
     .usesKernel = true,
     .takesWeights = true,
     .reads = MethodReads::Texels,
     .kernelSizes = MOMENT_SIZES,
     .chartColour = {0.60f, 0.40f, 0.10f, 1.0f},
     .referencePass = "reference/msm_hausdorff.frag",
     .reach = MethodReach::Kernel,
     .mapPass = MapPass::Moments4,
     .reconstructs = true,
     .wantsLitFacesInMap = true},
}};

// The table is in id order: methodInfo indexes it by id.
constexpr bool inIdOrder() {
    for (size_t k = 0; k < METHODS.size(); ++k) {
        if (METHODS[k].id != static_cast<int>(k)) return false;
    }
    return true;
}
static_assert(inIdOrder());
static_assert(static_cast<int>(Method::MsmHausdorff) == PCF_MSM_HAUSDORFF &&
              PCF_METHOD_COUNT == 15);

}  // namespace

std::span<const MethodInfo> allMethods() { return METHODS; }

const MethodInfo& methodInfo(int method) { return METHODS.at(static_cast<size_t>(method)); }

Method methodOf(int method) { return methodInfo(method).method(); }

std::optional<int> methodFromName(std::string_view name) {
    for (const MethodInfo& m : METHODS) {
        if (m.name == name) return m.id;
    }
    return std::nullopt;
}

float poissonSetReach() {
    static const float reach = [] {
        float r = 0.0f;
        for (int k = 0; k < 16; ++k) r = std::max(r, glm::length(PCF_POISSON_DISK[k]));
        return r;
    }();
    return reach;
}

std::string methodNameList() {
    std::string list;
    for (const MethodInfo& m : METHODS) {
        if (!list.empty()) list += ", ";
        list += m.name;
    }
    return list;
}

FetchCounts fetchCounts(int method, int kernel) {
    int n = kernel;
    switch (methodOf(method)) {
        case Method::Nearest:
            return {1, 0, 0};
        case Method::Box2x2:
            return {4, 0, 0};
        case Method::Bilinear2x2:
            return {4, 0, 0};
        case Method::Hw2x2:
            return {4, 0, 1};
        case Method::Naive:
            return {4 * n * n, 0, 0};
        case Method::Gather: {
            int blocks = (n + 2) / 2;  // ceil((N + 1) / 2) per axis
            return {4 * blocks * blocks, blocks * blocks, 0};
        }
        case Method::Hw:
            return {4 * n * n, 0, n * n};
        case Method::Tent: {
            int taps = n <= 3 ? 4 : n <= 5 ? 9 : 16;
            return {4 * taps, 0, taps};
        }
        case Method::Poisson:
            return {16, 0, 0};
        case Method::Pcss:  // at most: the 16 search taps, then 16 filter taps unless none blocks
            return {2 * PCF_PCSS_TAPS, 0, 0};
        case Method::Vsm:    // the lookup's one bilinear read of the moments map (the blur is
        case Method::Evsm2:  // the moments pass's, once per texel, not per lookup)
        case Method::Evsm4:
        case Method::Msm:
        case Method::MsmHausdorff:
            return {4, 0, 0};
    }
    throw std::out_of_range("fetchCounts: unknown method");
}

float reachTexels(int method, int kernel, float radius) {
    switch (methodInfo(method).reach) {
        case MethodReach::OneTexel:
            return 0.5f;
        case MethodReach::Block2x2:
            return 1.0f;
        case MethodReach::Kernel:
            return 0.5f * static_cast<float>(std::max(kernel, 1) + 1);
        case MethodReach::Disk:
            return radius + 0.5f;
        case MethodReach::BlockerDisk:  // its disks' radius follows the blocker: at most the cap
            return PCF_PCSS_MAX_RADIUS + 0.5f;
    }
    throw std::out_of_range("reachTexels: unknown reach");
}

TexelKind mapTexelKind(int method, TexelKind depthFormat, int momentBits) {
    bool half = momentBits == 16;
    switch (methodInfo(method).mapPass) {
        case MapPass::Depth:
            return depthFormat;
        case MapPass::Moments2:
            return half ? TexelKind::Moments2F16 : TexelKind::Moments2F32;
        case MapPass::Moments4:
            return half ? TexelKind::Moments4F16 : TexelKind::Moments4F32;
    }
    throw std::out_of_range("mapTexelKind: unknown map pass");
}

bool readsMoments(int method) { return methodInfo(method).mapPass != MapPass::Depth; }

std::optional<int> momentFormatFromName(std::string_view name) {
    if (name == "16f" || name == "16") return 16;
    if (name == "32f" || name == "32") return 32;
    return std::nullopt;
}

std::string_view momentFormatName(int bits) { return bits == 16 ? "16f" : "32f"; }

float evsmExponentLimit(int momentBits) { return momentBits == 16 ? 5.54f : 42.0f; }

PcfParams makeParams(int method, int kernel, float radius, vec2 rotation) {
    // Member by member: a parameter added to PcfParams starts at zero here without an edit, and
    // ShadowSettings::pcfParams sets it from the settings (kernel/settings.cpp).
    PcfParams p{};
    p.method = method;
    p.kernel = kernel;
    p.radius = radius;
    p.rotation = rotation;
    p.weights = PCF_WEIGHTS_BOX;
    p.sigma = 1.0f;
    // The moment methods' parameters at the settings' defaults (kernel/settings.h).
    const ShadowSettings defaults;
    p.lbr = defaults.lbr;
    p.minVariance = defaults.minVariance;
    p.evsmExponents = defaults.evsmExponentsUsed();
    p.momentBias = defaults.momentBias;
    return p;
}

std::optional<int> weightsFromName(std::string_view name) {
    if (name == "box") return PCF_WEIGHTS_BOX;
    if (name == "binomial") return PCF_WEIGHTS_BINOMIAL;
    if (name == "gaussian") return PCF_WEIGHTS_GAUSSIAN;
    return std::nullopt;
}

std::string_view weightsName(int weights) {
    if (weights == PCF_WEIGHTS_BINOMIAL) return "binomial";
    if (weights == PCF_WEIGHTS_GAUSSIAN) return "gaussian";
    return "box";
}

std::optional<int> precisionFromName(std::string_view name) {
    if (name == "exact") return PCF_PRECISION_EXACT;
    if (name == "hw8") return PCF_PRECISION_HW8;
    return std::nullopt;
}

std::string_view precisionName(int precision) {
    return precision == PCF_PRECISION_HW8 ? "hw8" : "exact";
}

std::optional<ParamProblem> checkParams(const PcfParams& prm) {
    auto problem = [](std::string setting, std::string before, const auto&... after) {
        std::ostringstream s;
        (s << ... << after);
        return ParamProblem{std::move(setting), std::move(before), s.str()};
    };
    if (prm.method < 0 || prm.method >= PCF_METHOD_COUNT) {
        return problem("", "unknown method id ", prm.method);
    }
    const MethodInfo& info = methodInfo(prm.method);
    if (info.usesKernel && (prm.kernel < MIN_KERNEL || prm.kernel > MAX_KERNEL)) {
        return problem("kernel", "", " ", prm.kernel, " is out of range (", MIN_KERNEL, "..",
                       MAX_KERNEL, ")");
    }
    if (!kernelFits(prm.method, prm.kernel)) {
        return problem("kernel", std::string(info.name) + " takes ", " ",
                       kernelSizesText(prm.method), ", not ", prm.kernel);
    }
    if (info.usesRadius &&
        !(std::isfinite(prm.radius) && prm.radius > 0.0f && prm.radius <= MAX_POISSON_RADIUS)) {
        return problem("radius", "", " ", prm.radius, " is out of range (0, ", MAX_POISSON_RADIUS,
                       "] texels");
    }
    if (prm.weights < PCF_WEIGHTS_BOX || prm.weights > PCF_WEIGHTS_GAUSSIAN) {
        return problem("", "unknown weights id ", prm.weights);
    }
    if (prm.weights != PCF_WEIGHTS_BOX && !info.takesWeights) {
        std::string takers;
        for (const MethodInfo& m : METHODS) {
            if (m.takesWeights) takers += (takers.empty() ? "" : ", ") + std::string(m.name);
        }
        return problem("weights", "", " ", weightsName(prm.weights), " applies to ", takers,
                       ", not ", info.name);
    }
    if (prm.weights == PCF_WEIGHTS_GAUSSIAN &&
        !(std::isfinite(prm.sigma) && prm.sigma >= MIN_SIGMA && prm.sigma <= MAX_SIGMA)) {
        return problem("sigma", "", " ", prm.sigma, " is out of range [", MIN_SIGMA, ", ",
                       MAX_SIGMA, "] texels");
    }
    // The moment methods' numbers, in their rows' ranges (kernel/settings.cpp PARAMS).
    const std::pair<const char*, float> momentValues[] = {
        {"lbr", prm.lbr}, {"min_variance", prm.minVariance}, {"moment_bias", prm.momentBias}};
    for (const auto& [key, value] : momentValues) {
        const ParamInfo* row = findParam(key);
        if (std::isfinite(value) && value >= static_cast<float>(row->min) &&
            value <= static_cast<float>(row->max)) {
            continue;
        }
        return problem(key, "", " ", value, " is out of range [", row->min, ", ", row->max, "]");
    }
    if (prm.precision != PCF_PRECISION_EXACT && prm.precision != PCF_PRECISION_HW8) {
        return problem("", "unknown precision id ", prm.precision);
    }
    return std::nullopt;
}

std::optional<std::string> validateParams(const PcfParams& prm) {
    if (auto p = checkParams(prm)) return p->text();
    return std::nullopt;
}

namespace {

// The sizes `method` takes when they are not all of MIN_KERNEL..MAX_KERNEL (tent's), or empty.
std::span<const int> listedSizes(int method) {
    if (method < 0 || method >= PCF_METHOD_COUNT) return {};
    return methodInfo(method).kernelSizes;
}

}  // namespace

bool kernelFits(int method, int n) {
    std::span<const int> sizes = listedSizes(method);
    if (!sizes.empty()) return std::ranges::find(sizes, n) != sizes.end();
    if (method < 0 || method >= PCF_METHOD_COUNT || !methodInfo(method).usesKernel) return true;
    return n >= MIN_KERNEL && n <= MAX_KERNEL;
}

std::string kernelSizesText(int method) {
    std::span<const int> sizes = listedSizes(method);
    if (sizes.empty()) return std::to_string(MIN_KERNEL) + ".." + std::to_string(MAX_KERNEL);
    std::string text;
    for (size_t k = 0; k < sizes.size(); ++k) {
        if (k > 0) text += k + 1 == sizes.size() ? " or " : ", ";
        text += std::to_string(sizes[k]);
    }
    return text;
}

int fitKernel(int method, int n) {
    if (kernelFits(method, n)) return n;
    std::span<const int> sizes = listedSizes(method);
    return sizes.empty() ? std::clamp(n, MIN_KERNEL, MAX_KERNEL) : sizes.front();
}

int stepKernel(int method, int n, int direction) {
    if (!kernelFits(method, n)) return fitKernel(method, n);
    std::span<const int> sizes = listedSizes(method);
    if (!sizes.empty()) {
        auto at = std::ranges::find(sizes, n);
        std::ptrdiff_t k =
            std::clamp<std::ptrdiff_t>((at - sizes.begin()) + direction, 0, std::ssize(sizes) - 1);
        return sizes[static_cast<size_t>(k)];
    }
    return std::clamp(n + direction, MIN_KERNEL, MAX_KERNEL);
}

}  // namespace pcf
