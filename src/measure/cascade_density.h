// cascade_density.h: how finely each cascade of a rendered frame samples its receivers, measured
// on the frame itself: per cascade, the shadow-map texels per screen pixel over the receivers
// that read it (render --raw's render.json, "map" -> "cascades").
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "kernel/shadow_map.h"
#include "scene/camera.h"

namespace pcf {

// One cascade's texel density over the frame: texels per pixel as an area ratio, |det J| of the
// map's texel position (u, v) * size per screen pixel (pixelsPerTexel's reciprocal), its largest
// and its median over the cascade's receivers; `pixels` how many were measured (0: none, and
// both numbers 0).
struct CascadeDensity {
    double texelsPerPixelMax = 0.0;
    double texelsPerPixelMedian = 0.0;
    int pixels = 0;
};

// Per layer of `map`, from a frame's light-space readback (u, v, ref, receiver: 4 floats per
// pixel, top-down) and world positions (4 floats per pixel, top-down) seen by `camera`: each
// receiver is measured against its neighbours that read the same layer only (cascadeOfPoint),
// so no difference spans a split.
std::vector<CascadeDensity> cascadeDensities(const std::vector<float>& lightSpace,
                                             const std::vector<float>& positions,
                                             glm::ivec2 frameSize, const MapSpec& map,
                                             const Camera& camera);

}  // namespace pcf
