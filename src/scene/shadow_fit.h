// shadow_fit.h: what the light's depth pass makes for a scene: the map as a value (MapSpec,
// kernel/shadow_map.h), its size and texel kind from the settings and the method, and each
// layer fitted to the scene. The renderer (render/scene_renderer) draws the layers it lists.
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "kernel/settings.h"
#include "kernel/shadow_map.h"
#include "scene/scene.h"

namespace pcf {

// One layer of a square map of mapSize texels over `scene`, seen through shadowClipFromWorld:
// that matrix, a perspective map's near and far (pcssDepthRange; (0, 0) when orthographic) and
// one texel's world size (shadowTexelWs).
PcfMapLayer shadowMapLayer(const Scene& scene, const glm::mat4& shadowClipFromWorld, int mapSize);

// The map the depth pass makes for settings `s`: mapSize x mapSize texels of the kind the
// method reads (mapTexelKind: a depth in --depth-format), one layer fitted by `fit` (the scene's
// own fit, shadowClipFromWorld(scene), or a lesson's shifted one), or with more than one cascade
// one layer per cascade, each fitted to its slice of the camera's frustum (scene/cascade_fit.h;
// `aspect` is the camera frame's width / height), `fit` unused. Throws std::invalid_argument
// when the cascades do not fit the scene (cascadeProblem). With cascade_bounds depth, `visible`
// is the frame's visible receivers' view depths as measured (SceneRenderer's prepass; nullopt
// when the frame shows none): the cascades split [n, f] tightened to them, and the map keeps
// both (MapSpec::cascadeDepths, visibleDepths).
MapSpec shadowMapSpec(const Scene& scene, const ShadowSettings& s, const glm::mat4& fit,
                      float aspect, std::optional<glm::vec2> visible = std::nullopt);

// A frame's width / height, 1 for an empty frame: the camera's aspect.
inline float frameAspect(glm::ivec2 size) {
    return size.y > 0 ? static_cast<float>(size.x) / static_cast<float>(size.y) : 1.0f;
}

}  // namespace pcf
