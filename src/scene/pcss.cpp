#include "scene/pcss.h"

#include <algorithm>
#include <cmath>

namespace pcf {

static_assert(MAX_LIGHT_SIZE_DEG == MAX_ANGULAR_DIAMETER_DEG);

float effectiveLightSizeDeg(const Light& light, float lightSizeDeg) {
    if (lightSizeDeg > 0.0f) return lightSizeDeg;
    if (light.type == LightType::Directional && light.angularDiameterDeg > 0.0f) {
        return light.angularDiameterDeg;
    }
    return SUN_ANGULAR_DIAMETER_DEG;
}

float penumbraScale(const Light& light, const glm::mat4& shadowClipFromWorld, int mapSize,
                    float lightSizeDeg) {
    if (light.type != LightType::Directional) return 0.0f;
    auto rowLength = [&](int r) {
        const glm::mat4& m = shadowClipFromWorld;
        return glm::length(glm::vec3(m[0][r], m[1][r], m[2][r]));
    };
    float theta = glm::radians(effectiveLightSizeDeg(light, lightSizeDeg));
    float depthUnitWs = 2.0f / rowLength(2);
    float texelWs = 2.0f / (std::min(rowLength(0), rowLength(1)) * static_cast<float>(mapSize));
    return 2.0f * std::tan(0.5f * theta) * depthUnitWs / texelWs;
}

PcfParams pcssPcfParams(const Light& light, const glm::mat4& shadowClipFromWorld,
                        const ShadowSettings& s, vec2 rotation) {
    float scale = s.method == PCF_PCSS
                      ? penumbraScale(light, shadowClipFromWorld, s.mapSize, s.lightSize)
                      : 0.0f;
    return s.pcfParams(rotation, scale);
}

}  // namespace pcf
