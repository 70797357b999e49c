// camera.h: the viewer's pinhole camera, its GL matrices, and the primary rays of ground truth.
#pragma once

#include <glm/glm.hpp>

#include "scene/aabb.h"
#include "scene/ray.h"

namespace pcf {

struct Camera {
    glm::vec3 eyeWs{6.0f, 5.0f, 7.0f};
    glm::vec3 targetWs{0.0f};
    glm::vec3 upWs{0.0f, 1.0f, 0.0f};
    float fovYDeg = 40.0f;  // vertical field of view, degrees, in (1, 179)
    // Distances of the clip planes along the view direction, scene units. 0 = not given:
    // fitCameraPlanes() derives them from the scene bounds (the parser and presets call it).
    float nearZ = 0.0f;
    float farZ = 0.0f;
};

// Fills nearZ / farZ where they are 0 from the depths of the 8 corners of the bounds along the
// view direction: near = max(0.98 * nearest corner, far / 1000, 0.01), far = 1.02 * farthest.
void fitCameraPlanes(Camera& camera, const Aabb& sceneBoundsWs);

// glm::lookAt: right-handed view space, the camera looks down -z, y up.
glm::mat4 viewFromWorld(const Camera& camera);

// glm::perspective in GL's convention: clip z in [-w, w], window depth = ndc.z * 0.5 + 0.5.
// aspect = width / height. Throws std::logic_error when nearZ / farZ were never set.
glm::mat4 clipFromView(const Camera& camera, float aspect);

inline glm::mat4 clipFromWorld(const Camera& camera, float aspect) {
    return clipFromView(camera, aspect) * viewFromWorld(camera);
}

// The ray from the eye through the point of the image at ndc (x right, y up, both in [-1, 1]),
// the inverse of clipFromView * viewFromWorld: a hit point p of this ray projects back to ndc,
// so the ray through a pixel centre meets the surface the rasterizer draws there. Unit
// direction; origin at the eye (not on the near plane), so t is the distance from the eye.
Ray cameraRay(const Camera& camera, glm::vec2 ndc, float aspect);

// The ndc of the centre of pixel (x, y) of a W x H image in GL window coordinates (row 0 at the
// bottom): ndc = ((x + 0.5) / W, (y + 0.5) / H) * 2 - 1.
glm::vec2 pixelCentreNdc(glm::ivec2 pixel, glm::ivec2 size);

}  // namespace pcf
