#include "scene/shadow_fit.h"

#include <stdexcept>

#include "kernel/cascades.h"
#include "scene/cascade_fit.h"
#include "scene/pcss.h"

namespace pcf {

PcfMapLayer shadowMapLayer(const Scene& scene, const glm::mat4& shadowClipFromWorld, int mapSize) {
    return PcfMapLayer{shadowClipFromWorld, pcssDepthRange(shadowClipFromWorld),
                       shadowTexelWs(scene, mapSize)};
}

MapSpec shadowMapSpec(const Scene& scene, const ShadowSettings& s, const glm::mat4& fit,
                      float aspect, std::optional<glm::vec2> visible) {
    MapSpec spec;
    spec.size = {s.mapSize, s.mapSize};
    spec.texels = mapTexelKind(s.method, s.depthFormat, s.momentBits);
    if (s.cascades <= 1) {
        spec.layers = {shadowMapLayer(scene, fit, s.mapSize)};
        return spec;
    }
    if (auto why = cascadeProblem(scene, s)) throw std::invalid_argument(why->text());
    if (s.cascadeBounds != CASCADE_BOUNDS_DEPTH) visible = std::nullopt;
    spec.layers = cascadeLayers(scene, s, aspect, visible);
    spec.cascadeDepths = vec2(scene.camera.nearZ, cascadeFarDepth(scene.camera, s));
    spec.visibleDepths = visible;
    return spec;
}

}  // namespace pcf
