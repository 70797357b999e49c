// ground_truth_rays.h: what the ground truth's passes share inside src/measure (not an
// interface of the truth: ground_truth.h is): the camera's rays in double, a sample's state and
// a scanline's lengths.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>

#include "scene/camera.h"
#include "scene/light.h"
#include "scene/raycast.h"
#include "scene/scene.h"

namespace pcf {

// Camera rays from window coordinates in double: the basis of cameraRay (camera.h) computed once,
// and the sub-pixel position kept in double until the direction is normalised, so a bisection
// step of 1/4096 px is not lost to float rounding of the window position.
struct CameraRays {
    glm::dvec3 f, s, u;
    glm::vec3 eye;
    glm::dvec3 eyeD;
    double tanHalfFov, aspect;
    glm::dvec2 size;
    CameraRays(const Camera& camera, glm::ivec2 frameSize)
        : eye(camera.eyeWs),
          eyeD(camera.eyeWs),
          tanHalfFov(std::tan(0.5 * glm::radians(static_cast<double>(camera.fovYDeg)))),
          aspect(static_cast<double>(frameSize.x) / static_cast<double>(frameSize.y)),
          size(frameSize) {
        f = glm::normalize(glm::dvec3(camera.targetWs) - glm::dvec3(camera.eyeWs));
        s = glm::normalize(glm::cross(f, glm::dvec3(camera.upWs)));
        u = glm::cross(s, f);
    }
    // window: GL window coordinates in pixels (y up), e.g. (x + 0.5, y + 0.5) for a centre.
    glm::dvec3 dirAt(glm::dvec2 window) const {
        glm::dvec2 ndc = window / size * 2.0 - 1.0;
        return glm::normalize(f + s * (ndc.x * aspect * tanHalfFov) + u * (ndc.y * tanHalfFov));
    }
    Ray at(glm::dvec2 window) const { return Ray{eye, glm::vec3(dirAt(window))}; }
    // dirAt before normalising is D0 + x Dx + v Dv at window (X + x, Y + v): the rays of pixel
    // (X, Y) as ground_truth_conics.h takes them.
    glm::dvec3 rawAt(glm::dvec2 window) const {
        glm::dvec2 ndc = window / size * 2.0 - 1.0;
        return f + s * (ndc.x * aspect * tanHalfFov) + u * (ndc.y * tanHalfFov);
    }
    glm::dvec3 stepX() const { return s * (2.0 / size.x * aspect * tanHalfFov); }
    glm::dvec3 stepY() const { return u * (2.0 / size.y * tanHalfFov); }
};

enum SampleState : uint8_t { UNLIT = 0, LIT = 1, OFF = 2 };  // OFF: not on the centre's object

inline SampleState sampleState(const Scene& scene, const Ray& ray, int object) {
    std::optional<Hit> hit = intersect(scene, ray);
    if (!hit || hit->object != object) return OFF;
    return litByLight(scene, *hit) ? LIT : UNLIT;
}

struct Scanline {
    double lit = 0.0;     // lit length on the centre's object, pixels
    double on = 0.0;      // length on the centre's object, pixels
    double litErr = 0.0;  // what lit may be off by: the crossings' pieces of 1/4096 px
    double onErr = 0.0;   // likewise for on: those where the object seen changes
};

// A piece shorter than this (pixels) may be read wrong at its middle: the ray caster rounds the
// direction and the hit to float, which moves a state's border by about 1e-5 px (6e-8 rad
// against 4e-3 rad per pixel at 320x180; 6e-5 px at 1280x720); such a piece counts whole as
// error.
constexpr double UNSURE_PX = 1.0 / 4096.0;

}  // namespace pcf
