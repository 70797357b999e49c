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

float RenderSettings::depthBias() const { return biasParams().baseBias(); }

BiasParams RenderSettings::biasParams() const { return biasParamsOf(*this); }

GLenum glDepthFormat(DepthFormat format) {
    switch (format) {
        case DepthFormat::D16:
            return GL_DEPTH_COMPONENT16;
        case DepthFormat::D24:
            return GL_DEPTH_COMPONENT24;
        default:
            return GL_DEPTH_COMPONENT32F;
    }
}

}  // namespace pcf
