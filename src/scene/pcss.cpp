#include "scene/pcss.h"

#include <algorithm>
#include <cmath>

namespace pcf {

float effectiveLightSizeDeg(const Light& light, float lightSizeDeg) {
    if (lightSizeDeg > 0.0f) return lightSizeDeg;
    if (light.type == LightType::Directional && light.angularDiameterDeg > 0.0f) {
        return light.angularDiameterDeg;
    }
    return SUN_ANGULAR_DIAMETER_DEG;
}

namespace {

glm::dvec4 matrixRow(const glm::mat4& m, int r) { return {m[0][r], m[1][r], m[2][r], m[3][r]}; }

}  // namespace

glm::vec2 pcssDepthRange(const glm::mat4& shadowClipFromWorld) {
    glm::dvec4 depthRow = matrixRow(shadowClipFromWorld, 2);
    glm::dvec4 wRow = matrixRow(shadowClipFromWorld, 3);
    glm::dvec3 axis(wRow);  // -(the light's view z row): unit for a rigid light view
    double axis2 = glm::dot(axis, axis);
    if (axis2 == 0.0) return glm::vec2(0.0f);
    double a = -glm::dot(glm::dvec3(depthRow), axis) / axis2;
    double b = depthRow.w + a * wRow.w;
    return glm::vec2(static_cast<float>(b / (a - 1.0)), static_cast<float>(b / (a + 1.0)));
}

float penumbraScale(const Light& light, const glm::mat4& shadowClipFromWorld, int mapSize,
                    float lightSizeDeg) {
    auto rowLength = [&](int r) {
        const glm::mat4& m = shadowClipFromWorld;
        return glm::length(glm::vec3(m[0][r], m[1][r], m[2][r]));
    };
    if (light.type == LightType::Spot) {
        glm::dvec3 axis(matrixRow(shadowClipFromWorld, 3));
        if (glm::dot(axis, axis) == 0.0) return 0.0f;  // not a perspective map
        auto scaleOf = [&](int r) {
            glm::dvec3 row(matrixRow(shadowClipFromWorld, r));
            return glm::length(row - glm::dot(row, axis) / glm::dot(axis, axis) * axis);
        };
        double p00 = std::min(scaleOf(0), scaleOf(1));
        return static_cast<float>(static_cast<double>(light.radius) * p00 * mapSize);
    }
    float theta = glm::radians(effectiveLightSizeDeg(light, lightSizeDeg));
    float depthUnitWs = 2.0f / rowLength(2);
    float texelWs = 2.0f / (std::min(rowLength(0), rowLength(1)) * static_cast<float>(mapSize));
    return 2.0f * std::tan(0.5f * theta) * depthUnitWs / texelWs;
}

PcfParams pcssPcfParams(const Light& light, const PcfMapLayer& layer, const ShadowSettings& s,
                        vec2 rotation) {
    bool searches = methodInfo(s.method).searchesBlockers;
    float scale = searches ? penumbraScale(applyLightSize(light, s), layer.shadowClipFromWorld,
                                           s.mapSize, s.lightSize)
                           : 0.0f;
    PcfParams p = s.pcfParams(rotation, scale);
    if (searches && light.type == LightType::Spot) {
        p.depthNear = layer.depthRange.x;
        p.depthFar = layer.depthRange.y;
    }
    return p;
}

}  // namespace pcf
