// raycast.h: exact ray casting against the analytic primitives (not their tessellation): the
// ground truth that shadow-map filtering is measured against.
//
// All intersection math runs in double: a shadow ray starts on a surface, and the quantities
// that decide whether it leaves that surface (f.f - r^2 for a sphere, n.(c - o) for a plane)
// are differences of nearly equal numbers. Results are rounded to float once, at the end.
#pragma once

#include <glm/glm.hpp>
#include <limits>
#include <optional>

#include "scene/primitives.h"
#include "scene/ray.h"
#include "scene/scene.h"

namespace pcf {

constexpr float RAY_T_MAX = std::numeric_limits<float>::infinity();

// Hits with tMin < t < tMax count. A ray that starts inside a sphere or a box hits its far side
// (frontFace false). Touching counts as a hit: a ray tangent to a sphere, or through a box's
// edge. A ray parallel to a plane misses it, even lying in it (a rectangle seen edge-on has no
// area). Hit::posWs is snapped onto the surface (the hit face's plane, the sphere's radius), so
// a shadow ray starts on the surface to double precision, not o + t * d's rounding.
std::optional<Hit> intersect(const Plane& plane, const Ray& ray, float tMin = 0.0f,
                             float tMax = RAY_T_MAX);
std::optional<Hit> intersect(const Box& box, const Ray& ray, float tMin = 0.0f,
                             float tMax = RAY_T_MAX);
std::optional<Hit> intersect(const Sphere& sphere, const Ray& ray, float tMin = 0.0f,
                             float tMax = RAY_T_MAX);
std::optional<Hit> intersect(const Primitive& primitive, const Ray& ray, float tMin = 0.0f,
                             float tMax = RAY_T_MAX);

// The nearest hit over all objects (casters or not), with Hit::object set.
std::optional<Hit> intersect(const Scene& scene, const Ray& ray, float tMin = 0.0f,
                             float tMax = RAY_T_MAX);

// Shadow rays start on a surface, where the float position is off the true surface by about
// 6e-8 of its magnitude (float rounding). A shadow ray ignores hits closer than
//   tMin = SHADOW_RAY_EPSILON * max(1, max_i |origin_i|) / |dir|      (scene units along the ray)
// i.e. 1e-4 scene units for a scene within [-1, 1], relative beyond: ~1000x the rounding, and
// far below a texel of any shadow map (a 4096^2 map over 1 unit is 2.4e-4 per texel).
// The surface the ray starts on is best left out entirely with skipObject (see litByLight):
// every primitive is convex, so a ray leaving it toward the light cannot meet it again, at any
// grazing angle, with no epsilon at all.
constexpr float SHADOW_RAY_EPSILON = 1e-4f;
float shadowRayTMin(glm::vec3 originWs, glm::vec3 dirWs);

// Whether any shadow caster (castsShadow) other than skipObject blocks the segment from originWs
// along dirWs, for shadowRayTMin < t < maxT (maxT = +infinity for a directional light). Stops
// at the first blocker found: no nearest-hit search, no allocation.
bool occluded(const Scene& scene, glm::vec3 originWs, glm::vec3 dirWs, float maxT,
              int skipObject = -1);

// Ground truth for a surface point a camera ray found: lit by the light (not in shadow).
// Unlit when outside a spot's cone, when the side of the surface facing the ray faces away
// from the light (dot <= 0: the object's own shadow side), or, for a shadow receiver, when a
// caster other than the object itself blocks the way to the light.
bool litByLight(const Scene& scene, const Hit& hit);

}  // namespace pcf
