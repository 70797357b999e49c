// render_settings.h: what one frame of the scene is rendered with. Its shadow settings, their
// names and ranges live GL-free in kernel/settings.h.
#pragma once

#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "kernel/pcf.h"
#include "kernel/settings.h"  // the vocabulary: depth formats, bias and cull modes, ranges

namespace pcf {

// The shadow settings (kernel/settings.h) and what only a rendered frame needs besides.
struct RenderSettings : ShadowSettings {
    // Slope-scaled bias in the shadow pass: glPolygonOffset(factor, units); 0, 0 = off.
    glm::vec2 polygonOffset{0.0f, 0.0f};
    // Also fill the world-position and normal targets (tests, --raw); the viewer does without.
    bool writePositions = false;
    glm::ivec2 frameSize{1280, 720};
    // The frame shape (width / height) cascades are fitted to; 0: the frame's own (a lesson's
    // is fixed: scene/cascade_view.h LESSON_CASCADE_ASPECT).
    float cascadeAspect = 0.0f;
};

// The GL internal format a map of this texel kind is stored in (kernel/shadow_map.h TexelKind):
// a depth format for depths, a 2- or 4-channel float colour format for moments.
GLenum glTexelFormat(TexelKind kind);

}  // namespace pcf
