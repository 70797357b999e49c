// cascade_density.h: how finely each cascade of a rendered frame samples its receivers, measured
// on the frame itself: per cascade, the shadow-map texels per screen pixel over the receivers
// that read it (render --raw's render.json, "map" -> "cascades"; stability --sweep cascades).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "kernel/shadow_map.h"
#include "scene/camera.h"

namespace pcf {

// One cascade's texel density over the frame, from J = d(u, v) * size / d(x, y), the map's texel
// position per screen pixel (stability.h texelJacobians), two ways, each its largest and its
// median over the cascade's receivers:
//   area ratio        |det J|: texels per pixel by area (pixelsPerTexel's reciprocal);
//   singular value    the larger singular value of J: texels per pixel along the screen direction
//                     the map is stretched most, the per-direction measure of Lloyd, Tuft, Yoon
//                     and Manocha, "Warping and Partitioning for Low Error Shadow Maps" (EGSR
//                     2006), whose aliasing error looks at the map's sampling along each
//                     direction rather than by area. For J's singular values s1 >= s2,
//                     s1^2 + s2^2 = |J|_F^2 = a and s1 s2 = |det J| = d, so
//                       s1 = sqrt((a + sqrt(a^2 - 4 d^2)) / 2).
// `pixels`: how many receivers were measured (0: none, and every number 0).
struct CascadeDensity {
    double texelsPerPixelMax = 0.0;
    double texelsPerPixelMedian = 0.0;
    double singularValueMax = 0.0;
    double singularValueMedian = 0.0;
    int pixels = 0;
};

// The larger singular value of a 2x2 matrix (above).
double largerSingularValue(const glm::mat2& j);

// Per layer of `map`, from a frame's light-space readback (u, v, ref, receiver: 4 floats per
// pixel, top-down) and world positions (4 floats per pixel, top-down) seen by `camera`: each
// receiver is measured against its neighbours that read the same layer only (cascadeOfPoint),
// so no difference spans a split.
std::vector<CascadeDensity> cascadeDensities(const std::vector<float>& lightSpace,
                                             const std::vector<float>& positions,
                                             glm::ivec2 frameSize, const MapSpec& map,
                                             const Camera& camera);

}  // namespace pcf
