// shadow_fit.h: what the light's depth pass makes for a scene: the map as a value (MapSpec,
// kernel/shadow_map.h), its size and texel kind from the settings and the method, and each
// layer fitted to the scene. The renderer (render/scene_renderer) draws the layers it lists.
#pragma once

#include <glm/glm.hpp>

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
// own fit, shadowClipFromWorld(scene), or a lesson's shifted one).
MapSpec shadowMapSpec(const Scene& scene, const ShadowSettings& s, const glm::mat4& fit);

}  // namespace pcf
