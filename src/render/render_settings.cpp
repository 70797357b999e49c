#include "render/render_settings.h"

#include "kernel/methods.h"

namespace pcf {

static_assert(static_cast<int>(BiasMode::None) == PCF_BIAS_NONE &&
              static_cast<int>(BiasMode::ReceiverPlane) == PCF_BIAS_RECEIVER_PLANE &&
              static_cast<int>(BiasMode::Interpolated) == PCF_BIAS_INTERPOLATED);

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

float RenderSettings::depthBias() const { return biasParams().baseBias(); }

BiasParams RenderSettings::biasParams() const {
    BiasParams b;
    b.mode = static_cast<int>(bias);
    b.constant = constantBias;
    b.slope = slopeBias;
    b.slopeMax = slopeMax;
    b.normalOffset = normalOffset;
    b.softScale = softScale;
    b.rpdbMax = rpdbMax;
    return b;
}

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

std::string_view biasModeName(BiasMode mode) { return biasName(static_cast<int>(mode)); }

std::optional<BiasMode> biasModeFromName(std::string_view name) {
    std::optional<int> id = biasFromName(name);
    if (!id) return std::nullopt;
    return static_cast<BiasMode>(*id);
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
