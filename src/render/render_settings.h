// render_settings.h: what one frame of the scene is rendered with. The names and ranges of its
// settings live GL-free in kernel/settings.h.
#pragma once

#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "kernel/pcf.h"
#include "kernel/settings.h"  // the vocabulary: depth formats, bias and cull modes, ranges

namespace pcf {

struct RenderSettings {
    int method = PCF_GATHER;
    int kernel = 3;
    float radius = 1.0f;          // poisson, texels
    bool rotatePerPixel = false;  // poisson
    int weights = 0;              // pcf-naive, pcf-gather: PCF_WEIGHTS_BOX, _BINOMIAL, _GAUSSIAN
    float sigma = 1.0f;           // gaussian weights, texels
    int precision = 0;            // PCF_PRECISION_EXACT or _HW8 (hardware taps and gathers)
    int mapSize = 1024;           // the shadow map is mapSize x mapSize texels
    DepthFormat depthFormat = DepthFormat::D32F;
    BiasMode bias = BiasMode::Constant;
    float constantBias = DEFAULT_CONSTANT_BIAS;  // light depth units: ref = z - constantBias
    // The other modes' parameters (kernel/bias.h says which mode reads which).
    float slopeBias = DEFAULT_SLOPE_BIAS;        // slope: depth units per unit of tan(theta)
    float slopeMax = DEFAULT_SLOPE_MAX;          // slope: the cap, depth units
    float normalOffset = DEFAULT_NORMAL_OFFSET;  // normal: texels
    float softScale = DEFAULT_SOFT_SCALE;        // soft: 1 / depth units
    float rpdbMax = DEFAULT_RPDB_MAX;            // receiver-plane: cap on dz/duv, depth per uv
    CullMode shadowCull = CullMode::Back;
    // Slope-scaled bias in the shadow pass: glPolygonOffset(factor, units); 0, 0 = off.
    glm::vec2 polygonOffset{0.0f, 0.0f};
    // Also fill the world-position target (tests, --raw); the viewer does without.
    bool writePositions = false;
    glm::ivec2 frameSize{1280, 720};

    PcfParams pcfParams() const;
    // The constant depth subtracted from z first: 0 for BiasMode::None (kernel/bias.h).
    float depthBias() const;
    // The mode and its parameters, as the kernel and the trace take them.
    BiasParams biasParams() const;
};

GLenum glDepthFormat(DepthFormat format);

}  // namespace pcf
