#include "scene/shadow_fit.h"

#include "scene/pcss.h"

namespace pcf {

PcfMapLayer shadowMapLayer(const Scene& scene, const glm::mat4& shadowClipFromWorld, int mapSize) {
    return PcfMapLayer{shadowClipFromWorld, pcssDepthRange(shadowClipFromWorld),
                       shadowTexelWs(scene, mapSize)};
}

MapSpec shadowMapSpec(const Scene& scene, const ShadowSettings& s, const glm::mat4& fit) {
    MapSpec spec;
    spec.size = {s.mapSize, s.mapSize};
    spec.texels = mapTexelKind(s.method, s.depthFormat, s.momentBits);
    spec.layers = {shadowMapLayer(scene, fit, s.mapSize)};
    return spec;
}

}  // namespace pcf
