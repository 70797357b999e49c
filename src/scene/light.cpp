#include "scene/light.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace pcf {

namespace {

// Any up vector not parallel to the view direction works; world Y keeps the map upright for the
// usual sideways light, world Z takes over for a light coming (almost) straight down.
glm::vec3 lightUp(glm::vec3 directionWs) {
    return std::abs(directionWs.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f)
                                           : glm::vec3(0.0f, 1.0f, 0.0f);
}

float diagonal(const Aabb& b) { return b.empty() ? 0.0f : glm::length(b.extentWs()); }

// The margin the fitted frusta are pushed out by, scene units; never 0, so that a scene of one
// flat plane still gets a valid depth range.
float fitMargin(const Aabb& b) { return std::max(SHADOW_FIT_MARGIN * diagonal(b), 1e-4f); }

struct ViewRange {
    glm::vec3 lo;
    glm::vec3 hi;
};

ViewRange cornersInView(const glm::mat4& viewFromWorld, const Aabb& b) {
    ViewRange r{glm::vec3(std::numeric_limits<float>::infinity()),
                glm::vec3(-std::numeric_limits<float>::infinity())};
    for (int k = 0; k < 8; ++k) {
        glm::vec3 p = glm::vec3(viewFromWorld * glm::vec4(b.cornerWs(k), 1.0f));
        r.lo = glm::min(r.lo, p);
        r.hi = glm::max(r.hi, p);
    }
    return r;
}

}  // namespace

glm::mat4 lightFromWorld(const Light& light, const Aabb& sceneBoundsWs) {
    glm::vec3 dir = glm::normalize(light.directionWs);
    glm::vec3 up = lightUp(dir);
    if (light.type == LightType::Spot) {
        return glm::lookAtRH(light.positionWs, light.positionWs + dir, up);
    }
    glm::vec3 centre = sceneBoundsWs.empty() ? glm::vec3(0.0f) : sceneBoundsWs.centreWs();
    float back = std::max(diagonal(sceneBoundsWs), 1.0f);
    return glm::lookAtRH(centre - dir * back, centre, up);
}

glm::mat4 clipFromLight(const Light& light, const Aabb& sceneBoundsWs) {
    Aabb b = sceneBoundsWs;
    if (b.empty()) b = Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)};
    glm::mat4 view = lightFromWorld(light, b);
    ViewRange r = cornersInView(view, b);
    float m = fitMargin(b);
    // View space looks down -z: the nearest corner has the largest z.
    float nearZ = -r.hi.z - m;
    float farZ = -r.lo.z + m;
    if (light.type == LightType::Spot) {
        nearZ = std::max(nearZ, SPOT_MIN_NEAR);
        farZ = std::max(farZ, nearZ + m);  // a scene wholly behind the light: any valid range
        float fov = glm::radians(2.0f * light.coneDeg);
        return glm::perspectiveRH_NO(fov, 1.0f, nearZ, farZ);
    }
    return glm::orthoRH_NO(r.lo.x - m, r.hi.x + m, r.lo.y - m, r.hi.y + m, nearZ, farZ);
}

glm::vec3 directionAtElevation(glm::vec3 directionWs, float elevationDeg) {
    glm::vec2 heading(directionWs.x, directionWs.z);
    float len = glm::length(heading);
    heading = len > 1e-6f ? heading / len : glm::vec2(1.0f, 0.0f);
    float e = glm::radians(elevationDeg);
    return glm::normalize(
        glm::vec3(std::cos(e) * heading.x, -std::sin(e), std::cos(e) * heading.y));
}

glm::mat4 shiftShadowOrigin(const glm::mat4& shadowClipFromWorld, glm::vec2 offsetTexels,
                            int mapSize, bool snapToTexels) {
    float toNdc = 2.0f / static_cast<float>(std::max(mapSize, 1));
    // Translating clip.xy by d * clip.w: row 3 gets d * (row 3 of w), i.e. M' = T * M.
    glm::mat4 shift(1.0f);
    shift[3][0] = offsetTexels.x * toNdc;
    shift[3][1] = offsetTexels.y * toNdc;
    glm::mat4 m = shift * shadowClipFromWorld;
    if (snapToTexels) {
        glm::vec4 origin = m * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        glm::vec2 texels = glm::vec2(origin) / origin.w / toNdc;
        glm::vec2 rounding = glm::round(texels) - texels;
        glm::mat4 snap(1.0f);
        snap[3][0] = rounding.x * toNdc;
        snap[3][1] = rounding.y * toNdc;
        m = snap * m;
    }
    return m;
}

glm::mat4 widenShadowDepthRange(const glm::mat4& shadowClipFromWorld, float ratio) {
    float r = std::max(ratio, 1.0f);
    glm::mat4 widen(1.0f);
    widen[2][2] = 1.0f / r;  // z' = z / r + w / r - w
    widen[3][2] = 1.0f / r - 1.0f;
    return widen * shadowClipFromWorld;
}

ShadowCoord shadowCoord(const glm::mat4& shadowClipFromWorld, glm::vec3 posWs) {
    glm::vec4 clip = shadowClipFromWorld * glm::vec4(posWs, 1.0f);
    glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {glm::vec2(ndc) * 0.5f + 0.5f, ndc.z * 0.5f + 0.5f};
}

bool hasSize(const Light& light) {
    return light.type == LightType::Directional ? light.angularDiameterDeg > 0.0f
                                                : light.radius > 0.0f;
}

std::optional<ParamProblem> lightSizeProblem(const Light& light, const ShadowSettings& s) {
    bool spot = light.type == LightType::Spot;
    if (spot && s.lightSize > 0.0f) {
        return ParamProblem{"light_size", "",
                            " (a directional light's angular diameter) does not apply to a spot "
                            "light, whose size is its radius"};
    }
    if (!spot && s.lightRadius > 0.0f) {
        return ParamProblem{"light_radius", "",
                            " (a spot light's radius) does not apply to a directional light, "
                            "whose size is its angular diameter"};
    }
    return std::nullopt;
}

Light applyLightSize(Light light, const ShadowSettings& s) {
    if (light.type == LightType::Directional && s.lightSize > 0.0f) {
        light.angularDiameterDeg = s.lightSize;
    }
    if (light.type == LightType::Spot && s.lightRadius > 0.0f) light.radius = s.lightRadius;
    return light;
}

LightSample towardLight(const Light& light, glm::vec3 posWs) {
    glm::vec3 dir = glm::normalize(light.directionWs);
    if (light.type == LightType::Directional) {
        return {-dir, std::numeric_limits<float>::infinity(), true};
    }
    glm::dvec3 d = glm::dvec3(light.positionWs) - glm::dvec3(posWs);
    double dist = glm::length(d);
    if (!(dist > 0.0)) return {-dir, 0.0f, false};
    glm::dvec3 toLight = d / dist;
    // Inside the cone when the angle between the spot axis and (p - position) is <= cone:
    // dot(-toLight, axis) >= cos(cone).
    double cosCone = std::cos(glm::radians(static_cast<double>(light.coneDeg)));
    bool inside = glm::dot(-toLight, glm::dvec3(dir)) >= cosCone;
    return {glm::vec3(toLight), static_cast<float>(dist), inside};
}

}  // namespace pcf
