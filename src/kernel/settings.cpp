#include "kernel/settings.h"

#include <algorithm>

namespace pcf {

static_assert(static_cast<int>(BiasMode::None) == PCF_BIAS_NONE &&
              static_cast<int>(BiasMode::ReceiverPlane) == PCF_BIAS_RECEIVER_PLANE &&
              static_cast<int>(BiasMode::Interpolated) == PCF_BIAS_INTERPOLATED);

namespace {

// Tent builds its N x N tent from 2, 3 or 4 hardware taps per axis (Castano, 2013, "Shadow
// Mapping Summary Part 1"): N = 3, 5 or 7.
constexpr int TENT_SIZES[] = {3, 5, 7};

}  // namespace

bool kernelFits(int method, int n) {
    if (method == PCF_TENT) return std::ranges::find(TENT_SIZES, n) != std::end(TENT_SIZES);
    if (method < 0 || method >= PCF_METHOD_COUNT || !methodInfo(method).usesKernel) return true;
    return n >= MIN_KERNEL && n <= MAX_KERNEL;
}

std::string kernelSizesText(int method) {
    if (method == PCF_TENT) return "3, 5 or 7";
    return std::to_string(MIN_KERNEL) + ".." + std::to_string(MAX_KERNEL);
}

int fitKernel(int method, int n) {
    if (kernelFits(method, n)) return n;
    return method == PCF_TENT ? TENT_SIZES[0] : std::clamp(n, MIN_KERNEL, MAX_KERNEL);
}

int stepKernel(int method, int n, int direction) {
    if (!kernelFits(method, n)) return fitKernel(method, n);
    if (method == PCF_TENT) {
        const int* at = std::ranges::find(TENT_SIZES, n);
        std::ptrdiff_t k =
            std::clamp<std::ptrdiff_t>((at - TENT_SIZES) + direction, 0, std::size(TENT_SIZES) - 1);
        return TENT_SIZES[k];
    }
    return std::clamp(n + direction, MIN_KERNEL, MAX_KERNEL);
}

std::string_view depthFormatName(DepthFormat format) {
    switch (format) {
        case DepthFormat::D16:
            return "16";
        case DepthFormat::D24:
            return "24";
        default:
            return "32f";
    }
}

std::optional<DepthFormat> depthFormatFromName(std::string_view name) {
    if (name == "16") return DepthFormat::D16;
    if (name == "24") return DepthFormat::D24;
    if (name == "32f" || name == "32F" || name == "32") return DepthFormat::D32F;
    return std::nullopt;
}

int depthFormatFixedPointBits(DepthFormat format) {
    switch (format) {
        case DepthFormat::D16:
            return 16;
        case DepthFormat::D24:
            return 24;
        default:
            return 0;
    }
}

std::string_view biasModeName(BiasMode mode) { return biasName(static_cast<int>(mode)); }

std::optional<BiasMode> biasModeFromName(std::string_view name) {
    std::optional<int> id = biasFromName(name);
    if (!id) return std::nullopt;
    return static_cast<BiasMode>(*id);
}

std::string_view cullModeName(CullMode mode) {
    switch (mode) {
        case CullMode::Back:
            return "back";
        case CullMode::Front:
            return "front";
        default:
            return "none";
    }
}

std::optional<CullMode> cullModeFromName(std::string_view name) {
    if (name == "back") return CullMode::Back;
    if (name == "front") return CullMode::Front;
    if (name == "none") return CullMode::None;
    return std::nullopt;
}

}  // namespace pcf
