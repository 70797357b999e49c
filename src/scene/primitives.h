// primitives.h: the analytic shapes of a scene. The ray caster intersects them exactly; the
// rasterizer draws their tessellation (mesh.h). All coordinates are world space, in scene units.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string_view>
#include <variant>

#include "scene/aabb.h"

namespace pcf {

// A finite rectangle: the points centre + a * halfU + b * halfV with a, b in [-1, 1]. halfU and
// halfV are perpendicular to each other and to the unit normal, and cross(halfU, halfV) points
// along the normal (so its two triangles wind counter-clockwise seen from the front).
struct Plane {
    glm::vec3 centreWs{0.0f};
    glm::vec3 normalWs{0.0f, 1.0f, 0.0f};
    glm::vec3 halfUWs{5.0f, 0.0f, 0.0f};
    glm::vec3 halfVWs{0.0f, 0.0f, -5.0f};
};

// A box with half extents along its own axes, turned by rotateYDeg about the world Y axis through
// its centre (counter-clockwise seen from above, +Y, as glm::rotate turns it).
struct Box {
    glm::vec3 centreWs{0.0f};
    glm::vec3 halfExtents{0.5f};
    float rotateYDeg = 0.0f;
};

struct Sphere {
    glm::vec3 centreWs{0.0f};
    float radius = 0.5f;
};

using Primitive = std::variant<Plane, Box, Sphere>;

// A plane from what a scene file gives: centre, normal (need not be unit), full size along its
// two axes. The U axis is `tangent` projected onto the plane when given, else world X projected
// onto the plane (world Z when the normal is along X): a ground plane with normal +Y gets U = +X,
// V = cross(normal, U) = -Z, so size = (extent along x, extent along z). nullopt when the normal
// is zero or the tangent is parallel to it.
std::optional<Plane> makePlane(glm::vec3 centreWs, glm::vec3 normalWs, glm::vec2 size,
                               std::optional<glm::vec3> tangentWs = std::nullopt);

// The box's local axes in world space (unit; the box's Y stays world Y).
struct BoxAxes {
    glm::dvec3 xWs;
    glm::dvec3 zWs;
};
BoxAxes boxAxes(const Box& box);
// A point of the box's local frame (centred, unrotated) in world space, and back.
glm::vec3 boxWorldFromLocal(const Box& box, glm::vec3 posLocal);
glm::vec3 boxLocalFromWorld(const Box& box, glm::vec3 posWs);

// The tightest world-space axis-aligned box around the primitive.
Aabb bounds(const Primitive& primitive);

// "plane", "box" or "sphere": the scene file's type names.
std::string_view primitiveTypeName(const Primitive& primitive);

}  // namespace pcf
