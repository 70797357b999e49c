#include "kernel/methods.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "kernel/sigma_limits.h"

namespace pcf {

namespace {

// Tent builds its N x N tent from 2, 3 or 4 hardware taps per axis (Castano, 2013, "Shadow
// Mapping Summary Part 1"): N = 3, 5 or 7.
constexpr int TENT_SIZES[] = {3, 5, 7};

// The charts' colours: Tableau 10, with the yellow and pink darkened to read on white.
constexpr std::array<MethodInfo, PCF_METHOD_COUNT> METHODS = {{
    {PCF_NEAREST,
     "nearest",
     "nearest",
     "the one texel under the lookup, floor(uv * size): hard edges",
     false,
     false,
     false,
     MethodReads::Texels,
     {},
     {0.31f, 0.47f, 0.65f, 1.0f},
     "reference/nearest.frag",
     false},
    {PCF_BOX2X2,
     "box2x2",
     "box",
     "the 2x2 texels at base averaged: only 0, .25, .5, .75, 1",
     false,
     false,
     false,
     MethodReads::Texels,
     {},
     {0.95f, 0.56f, 0.17f, 1.0f},
     "reference/box.frag",
     false},
    {PCF_BILINEAR2X2,
     "bilinear2x2",
     "bilin",
     "the same 4 bits lerped by the sub-texel fraction (NVIDIA's hardware PCF, emulated)",
     false,
     false,
     false,
     MethodReads::Texels,
     {},
     {0.88f, 0.34f, 0.35f, 1.0f},
     "reference/naive.frag",
     false},
    {PCF_HW2X2,
     "hw2x2",
     "hw2x2",
     "one tap of the hardware comparison sampler (sampler2DShadow, linear)",
     false,
     false,
     false,
     MethodReads::HwTaps,
     {},
     {0.36f, 0.66f, 0.64f, 1.0f},
     "reference/hw.frag",
     false},
    {PCF_NAIVE,
     "pcf-naive",
     "naive",
     "N x N bilinear lookups one texel apart, averaged",
     true,
     false,
     true,
     MethodReads::Texels,
     {},
     {0.35f, 0.63f, 0.31f, 1.0f},
     "reference/naive.frag",
     true},
    {PCF_GATHER,
     "pcf-gather",
     "gather",
     "pcf-naive's result from the (N+1)^2 distinct texels, read by comparison gathers",
     true,
     false,
     true,
     MethodReads::Gathers,
     {},
     {0.80f, 0.62f, 0.05f, 1.0f},
     "reference/gather.frag",
     true},
    {PCF_HW,
     "pcf-hw",
     "hw",
     "N x N hardware comparison taps one texel apart, averaged",
     true,
     false,
     false,
     MethodReads::HwTaps,
     {},
     {0.69f, 0.48f, 0.63f, 1.0f},
     "reference/hw.frag",
     true},
    {PCF_TENT,
     "tent",
     "tent",
     "Castano's N x N tent (N = 3, 5, 7) from 4, 9 or 16 hardware taps",
     true,
     false,
     false,
     MethodReads::HwTaps,
     TENT_SIZES,
     {0.84f, 0.30f, 0.62f, 1.0f},
     "reference/tent.frag",
     true},
    {PCF_POISSON,
     "poisson",
     "poisson",
     "16 nearest-texel comparisons on a Poisson disk of radius R texels, optionally rotated",
     false,
     true,
     false,
     MethodReads::Texels,
     {},
     {0.61f, 0.46f, 0.37f, 1.0f},
     "reference/poisson.frag",
     false},
    {PCF_PCSS,
     "pcss",
     "pcss",
     "soft shadows: a blocker search, a penumbra width from the light size, then poisson that wide",
     false,
     false,
     false,
     MethodReads::Texels,
     {},
     {0.47f, 0.47f, 0.47f, 1.0f},
     "reference/pcss.frag",
     false},
}};

// The table is in id order: methodInfo indexes it by id.
constexpr bool inIdOrder() {
    for (size_t k = 0; k < METHODS.size(); ++k) {
        if (METHODS[k].id != static_cast<int>(k)) return false;
    }
    return true;
}
static_assert(inIdOrder());
static_assert(static_cast<int>(Method::Pcss) == PCF_PCSS && PCF_METHOD_COUNT == 10);

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
    }
    throw std::out_of_range("fetchCounts: unknown method");
}

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
        return problem("kernel", "tent takes ", " ", kernelSizesText(prm.method), ", not ",
                       prm.kernel);
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
        return problem("weights", "", " ", weightsName(prm.weights),
                       " applies to pcf-naive and pcf-gather, not ", info.name);
    }
    if (prm.weights == PCF_WEIGHTS_GAUSSIAN &&
        !(std::isfinite(prm.sigma) && prm.sigma >= MIN_SIGMA && prm.sigma <= MAX_SIGMA)) {
        return problem("sigma", "", " ", prm.sigma, " is out of range [", MIN_SIGMA, ", ",
                       MAX_SIGMA, "] texels");
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
