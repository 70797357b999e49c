#include "render/render_settings.h"

#include "kernel/methods.h"

namespace pcf {

PcfParams RenderSettings::pcfParams() const {
    PcfParams p = makeParams(method, kernel, radius);
    p.weights = weights;
    p.sigma = sigma;
    p.precision = precision;
    return p;
}

int depthFormatFixedPointBits(DepthFormat format) {
    switch (format) {
        case DepthFormat::D16: return 16;
        case DepthFormat::D24: return 24;
        default: return 0;
    }
}

float RenderSettings::depthBias() const { return bias == BiasMode::None ? 0.0f : constantBias; }

GLenum glDepthFormat(DepthFormat format) {
    switch (format) {
        case DepthFormat::D16: return GL_DEPTH_COMPONENT16;
        case DepthFormat::D24: return GL_DEPTH_COMPONENT24;
        default: return GL_DEPTH_COMPONENT32F;
    }
}

std::string_view depthFormatName(DepthFormat format) {
    switch (format) {
        case DepthFormat::D16: return "16";
        case DepthFormat::D24: return "24";
        default: return "32f";
    }
}

std::optional<DepthFormat> depthFormatFromName(std::string_view name) {
    if (name == "16") return DepthFormat::D16;
    if (name == "24") return DepthFormat::D24;
    if (name == "32f" || name == "32F" || name == "32") return DepthFormat::D32F;
    return std::nullopt;
}

std::string_view biasModeName(BiasMode mode) {
    return mode == BiasMode::None ? "none" : "constant";
}

std::optional<BiasMode> biasModeFromName(std::string_view name) {
    if (name == "none") return BiasMode::None;
    if (name == "constant") return BiasMode::Constant;
    return std::nullopt;
}

std::string_view cullModeName(CullMode mode) {
    switch (mode) {
        case CullMode::Back: return "back";
        case CullMode::Front: return "front";
        default: return "none";
    }
}

std::optional<CullMode> cullModeFromName(std::string_view name) {
    if (name == "back") return CullMode::Back;
    if (name == "front") return CullMode::Front;
    if (name == "none") return CullMode::None;
    return std::nullopt;
}

}  // namespace pcf
