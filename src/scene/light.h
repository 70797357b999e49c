// light.h: the light, the shadow map's matrices fitted to the scene, and the exact direction to
// the light that ray-cast ground truth shoots its shadow rays along.
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "kernel/settings.h"
#include "scene/aabb.h"

namespace pcf {

enum class LightType { Directional, Spot };

struct Light {
    LightType type = LightType::Directional;
    // The unit direction the light travels (from the light into the scene).
    glm::vec3 directionWs = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
    // Spot only: where the light is, and the half-angle of its cone in degrees, in
    // [MIN_SPOT_CONE_DEG, MAX_SPOT_CONE_DEG].
    glm::vec3 positionWs{0.0f, 5.0f, 0.0f};
    float coneDeg = 30.0f;
    // The light's size, 0 for an ideal point or direction (the default). It shapes only the
    // area-light truth (measure/ground_truth.h) and penumbra estimates: the shadow map is
    // always rendered from the light's centre (the direction, or positionWs).
    // Directional: the angular diameter of the light's disk in degrees, in [0,
    // MAX_ANGULAR_DIAMETER_DEG] (the sun's is about 0.53).
    float angularDiameterDeg = 0.0f;
    // Spot: the radius of a disk centred on positionWs and facing along directionWs, scene
    // units, >= 0.
    float radius = 0.0f;
};

// A spot's cone, half-angle in degrees: below 0.01 degrees the map's perspective divides by a
// tangent that float cannot hold (1e-45 gave infinite light-space coordinates); at 90 the map
// would see a half-space.
constexpr double MIN_SPOT_CONE_DEG = 0.01;
constexpr double MAX_SPOT_CONE_DEG = 89.0;

// A light's size is in the ranges of the settings that override it (kernel/settings.h
// light_size and light_radius); scene files are read in the same.
constexpr float MAX_ANGULAR_DIAMETER_DEG = MAX_LIGHT_SIZE_DEG;
constexpr float MAX_SPOT_RADIUS = MAX_LIGHT_RADIUS;

// Whether the light has an area (a size above 0): the area-light truth applies.
bool hasSize(const Light& light);

// Why the settings' light size does not fit this light, or nullopt: light_size is a directional
// light's angular diameter, light_radius a spot light's radius, and each given (above 0) for the
// other kind of light is a mistake, not something to ignore. In the kernel's words (the
// settings named as the lesson files' keys).
std::optional<ParamProblem> lightSizeProblem(const Light& light, const ShadowSettings& s);
// The light with the settings' size where one is given (above 0): the light pcss filters for and
// the area-light truth integrates over.
Light applyLightSize(Light light, const ShadowSettings& s);

// The shadow pass's view: right-handed, looking down -z along the light direction, y up as far
// as the direction allows (world Y, or world Z when the light is within ~8 degrees of vertical).
// Directional: the eye is placed behind the bounds' centre; only the direction matters, the
// projection is fitted. Spot: the eye is the light's position.
glm::mat4 lightFromWorld(const Light& light, const Aabb& sceneBoundsWs);

// The shadow pass's projection, in GL's convention (clip z in [-w, w]).
// Directional: glm::ortho fitted tightly to the scene: the 8 corners of the bounds in light view
// space give min/max x, y, z, each side pushed out by SHADOW_FIT_MARGIN of the bounds' diagonal
// (so that nothing is clipped by rounding), so every texel of the map covers the scene.
// Spot: glm::perspective with fov = 2 * cone, aspect 1, near / far from the corners' depths
// along the spot direction, pushed out by the same margin; near clamped to >= SPOT_MIN_NEAR.
glm::mat4 clipFromLight(const Light& light, const Aabb& sceneBoundsWs);

// Relative margin of the fitted light frustum (of the bounds' diagonal), and the least near
// distance of a spot light, scene units.
constexpr float SHADOW_FIT_MARGIN = 1e-3f;
constexpr float SPOT_MIN_NEAR = 0.05f;

// The light's direction turned to `elevationDeg` above the ground (the XZ plane): 90 = straight
// down, 0 = along the ground. The direction's compass heading (its XZ part) is kept; a straight
// down direction, which has none, gets the heading +X. Unit.
//   direction = (cos(e) * heading.x, -sin(e), cos(e) * heading.z)
glm::vec3 directionAtElevation(glm::vec3 directionWs, float elevationDeg);

// Moves where the shadow map's texel grid lies over the world, leaving what it sees alone: the
// map's image is translated by `offsetTexels` (x along u, y along v, fractions allowed), i.e.
// clip.xy += offset * 2 / mapSize * clip.w. With snapToTexels the result is then translated by
// less than half a texel so that the world origin falls on a texel corner: the "stable" fit of
// Valient, "Stable Rendering of Cascaded Shadow Maps" (ShaderX6, 2008), as MJP's "A Sampling of
// Shadow Techniques" (2013) does it: o = M * (0,0,0,1); t = o.xy * mapSize / 2;
// M.xy += (round(t) - t) * 2 / mapSize. For an orthographic (directional) light this makes every
// snapped fit differ from another by whole texels, so the map's content only moves, never
// changes; for a spot light the shift is a valid map too but snapping cannot make it stable.
glm::mat4 shiftShadowOrigin(const glm::mat4& shadowClipFromWorld, glm::vec2 offsetTexels,
                            int mapSize, bool snapToTexels);

// The same map with its depth range `ratio` times as deep (ratio >= 1): the far plane pushed
// away so the scene fills 1 / ratio of [0, 1] near depth 0, what a loosely fitted light frustum
// does to depth precision: depth' = depth / ratio, i.e. clip.z' = (clip.z + clip.w) / ratio -
// clip.w.
glm::mat4 widenShadowDepthRange(const glm::mat4& shadowClipFromWorld, float ratio);

// Where a world point lands in the shadow map, exactly as GL computes it after
// clip = shadowClipFromWorld * (posWs, 1):
//   ndc = clip.xyz / clip.w;  uvSm = ndc.xy * 0.5 + 0.5;  depth = ndc.z * 0.5 + 0.5
// uvSm in [0,1] across the map (u along the light's view x, v along its y; v = 0 is texel row
// 0), depth in [0,1] with 0 = near the light (glDepthRange default). Outside those ranges the
// point is outside the light's frustum. For a spot light depth is the usual perspective
// (hyperbolic) depth, not the distance.
struct ShadowCoord {
    glm::vec2 uvSm;
    float depth;
};
ShadowCoord shadowCoord(const glm::mat4& shadowClipFromWorld, glm::vec3 posWs);

// The light as seen from a world point, for shadow rays.
struct LightSample {
    glm::vec3 dirWs;  // unit, toward the light: -direction, or normalize(position - p)
    float distance;   // to the light, scene units; +infinity for a directional light
    bool insideCone;  // always true for a directional light
};
LightSample towardLight(const Light& light, glm::vec3 posWs);

}  // namespace pcf
