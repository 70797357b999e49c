#include "scene/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <stdexcept>

namespace pcf {

void fitCameraPlanes(Camera& camera, const Aabb& sceneBoundsWs) {
    if (camera.nearZ > 0.0f && camera.farZ > 0.0f) return;
    glm::vec3 forward = glm::normalize(camera.targetWs - camera.eyeWs);
    float nearest = std::numeric_limits<float>::infinity();
    float farthest = -std::numeric_limits<float>::infinity();
    if (!sceneBoundsWs.empty()) {
        for (int k = 0; k < 8; ++k) {
            float depth = glm::dot(sceneBoundsWs.cornerWs(k) - camera.eyeWs, forward);
            nearest = std::min(nearest, depth);
            farthest = std::max(farthest, depth);
        }
    } else {
        nearest = 0.1f;
        farthest = 100.0f;
    }
    // A scene behind the camera still gets a valid frustum; it just shows nothing.
    float farZ = camera.farZ > 0.0f ? camera.farZ : std::max(1.02f * farthest, 1.0f);
    float nearZ =
        camera.nearZ > 0.0f ? camera.nearZ : std::max({0.98f * nearest, farZ / 1000.0f, 0.01f});
    if (nearZ >= farZ) farZ = 2.0f * nearZ;
    camera.nearZ = nearZ;
    camera.farZ = farZ;
}

glm::mat4 viewFromWorld(const Camera& camera) {
    return glm::lookAtRH(camera.eyeWs, camera.targetWs, camera.upWs);
}

glm::mat4 clipFromView(const Camera& camera, float aspect) {
    if (!(camera.nearZ > 0.0f) || !(camera.farZ > camera.nearZ)) {
        throw std::logic_error("camera near/far not set: call fitCameraPlanes() first");
    }
    return glm::perspectiveRH_NO(glm::radians(camera.fovYDeg), aspect, camera.nearZ, camera.farZ);
}

Ray cameraRay(const Camera& camera, glm::vec2 ndc, float aspect) {
    // glm::perspective: ndc.x = x_v / (-z_v * aspect * tan(fov/2)), ndc.y = y_v / (-z_v *
    // tan(fov/2)). So the view-space direction through ndc is (ndc.x * aspect * t, ndc.y * t,
    // -1) with t = tan(fov/2), turned into world space by lookAt's basis (s, u, -f). Double,
    // so the direction is exact to float rounding once normalised.
    glm::dvec3 eye(camera.eyeWs);
    glm::dvec3 f = glm::normalize(glm::dvec3(camera.targetWs) - eye);
    glm::dvec3 s = glm::normalize(glm::cross(f, glm::dvec3(camera.upWs)));
    glm::dvec3 u = glm::cross(s, f);
    double t = std::tan(0.5 * glm::radians(static_cast<double>(camera.fovYDeg)));
    glm::dvec3 dir =
        f + s * (static_cast<double>(ndc.x) * aspect * t) + u * (static_cast<double>(ndc.y) * t);
    return Ray{camera.eyeWs, glm::vec3(glm::normalize(dir))};
}

glm::vec2 pixelCentreNdc(glm::ivec2 pixel, glm::ivec2 size) {
    return (glm::vec2(pixel) + 0.5f) / glm::vec2(size) * 2.0f - 1.0f;
}

}  // namespace pcf
