#include "kernel/methods.h"

#include <array>
#include <cmath>
#include <sstream>

#include "kernel/settings.h"
#include "kernel/sigma_limits.h"

namespace pcf {

namespace {

constexpr std::array<MethodInfo, PCF_METHOD_COUNT> METHODS = {{
    {PCF_NEAREST, "nearest", "the one texel under the lookup, floor(uv * size): hard edges", false,
     false},
    {PCF_BOX2X2, "box2x2", "the 2x2 texels at base averaged: only 0, .25, .5, .75, 1", false,
     false},
    {PCF_BILINEAR2X2, "bilinear2x2",
     "the same 4 bits lerped by the sub-texel fraction (NVIDIA's hardware PCF, emulated)", false,
     false},
    {PCF_HW2X2, "hw2x2", "one tap of the hardware comparison sampler (sampler2DShadow, linear)",
     false, false},
    {PCF_NAIVE, "pcf-naive", "N x N bilinear lookups one texel apart, averaged", true, false},
    {PCF_GATHER, "pcf-gather",
     "pcf-naive's result from the (N+1)^2 distinct texels, read by comparison gathers", true,
     false},
    {PCF_HW, "pcf-hw", "N x N hardware comparison taps one texel apart, averaged", true, false},
    {PCF_TENT, "tent", "Castano's N x N tent (N = 3, 5, 7) from 4, 9 or 16 hardware taps", true,
     false},
    {PCF_POISSON, "poisson",
     "16 nearest-texel comparisons on a Poisson disk of radius R texels, optionally rotated", false,
     true},
}};

}  // namespace

std::span<const MethodInfo> allMethods() { return METHODS; }

const MethodInfo& methodInfo(int method) { return METHODS.at(static_cast<size_t>(method)); }

std::optional<int> methodFromName(std::string_view name) {
    for (const MethodInfo& m : METHODS) {
        if (m.name == name) return m.id;
    }
    return std::nullopt;
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
    switch (method) {
        case PCF_NEAREST:
            return {1, 0, 0};
        case PCF_BOX2X2:
            return {4, 0, 0};
        case PCF_BILINEAR2X2:
            return {4, 0, 0};
        case PCF_HW2X2:
            return {4, 0, 1};
        case PCF_NAIVE:
            return {4 * n * n, 0, 0};
        case PCF_GATHER: {
            int blocks = (n + 2) / 2;  // ceil((N + 1) / 2) per axis
            return {4 * blocks * blocks, blocks * blocks, 0};
        }
        case PCF_HW:
            return {4 * n * n, 0, n * n};
        case PCF_TENT: {
            int taps = n <= 3 ? 4 : n <= 5 ? 9 : 16;
            return {4 * taps, 0, taps};
        }
        default:
            return {16, 0, 0};
    }
}

PcfParams makeParams(int method, int kernel, float radius, vec2 rotation) {
    return PcfParams{method, kernel, radius, rotation, PCF_WEIGHTS_BOX, 1.0f};
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
    if (prm.method == PCF_POISSON &&
        !(std::isfinite(prm.radius) && prm.radius > 0.0f && prm.radius <= MAX_POISSON_RADIUS)) {
        return problem("radius", "", " ", prm.radius, " is out of range (0, ", MAX_POISSON_RADIUS,
                       "] texels");
    }
    if (prm.weights < PCF_WEIGHTS_BOX || prm.weights > PCF_WEIGHTS_GAUSSIAN) {
        return problem("", "unknown weights id ", prm.weights);
    }
    if (prm.weights != PCF_WEIGHTS_BOX && prm.method != PCF_NAIVE && prm.method != PCF_GATHER) {
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

}  // namespace pcf
