// cascade_view.h: the camera and the frame shape a cascaded map is fitted to, where they are not
// the camera and the frame it is drawn through. A lesson's cascades are fitted at one frame shape
// (LESSON_CASCADE_ASPECT) so that its pinned point reads the same lookup at every frame size; a
// magnified step keeps the wide view's cascades; and a frozen view keeps the cascades of the
// moment it froze while the camera moves away, and draws their light boxes and split planes
// (cascadeFrameLines). The splits and fits themselves are scene/cascade_fit.h's.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "kernel/settings.h"
#include "kernel/shadow_map.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace pcf {

// The frame shape (width / height) every lesson step's cascades are fitted to, whatever the
// size of the frame shown: 16:9. A scene panel narrower than that shows less than the cascades
// cover; one wider (none of the viewer's or export's layouts) would show receivers past the sides
// of a box fit.
constexpr float LESSON_CASCADE_ASPECT = 16.0f / 9.0f;

// The map the depth pass makes for settings `s` (scene/shadow_fit.h shadowMapSpec), its cascades
// fitted to `cascadeCamera`'s view at `aspect` instead of the scene's camera; `visible` as
// shadowMapSpec's.
MapSpec cascadedMapSpec(const Scene& scene, const ShadowSettings& s, const glm::mat4& fit,
                        const Camera& cascadeCamera, float aspect,
                        std::optional<glm::vec2> visible = std::nullopt);

// Whether settings s name a method cascades cannot take (scene/cascade_fit.h cascadeProblem on
// any directional light): nullopt with one map or a method that can.
std::optional<ParamProblem> cascadeMethodProblem(const ShadowSettings& s);

// Why a lesson step's cascades do not fit its scene (scene/cascade_fit.h cascadeProblem), or
// why `freeze` asks for what is not there (freeze_cascades without cascades), or why its
// cascade_bounds cannot be depth (a lesson fits its cascades at LESSON_CASCADE_ASPECT and pins its
// point's lookup on the CPU before any frame is drawn, so that the point traces the same lookup
// at every size: bounds measured on a frame would differ from size to size); nullopt when fine.
std::optional<ParamProblem> lessonCascadeProblem(const Scene& scene, const ShadowSettings& s,
                                                 bool freeze);

// The camera a frozen view is seen through: behind and above `camera` (by 0.35 and 0.45 of the
// cascades' far end f, scene/cascade_fit.h cascadeFarDepth), looking at the point f * 0.45 along
// its view, far enough to see the last cascade end.
Camera cascadeOverviewCamera(const Camera& camera, const ShadowSettings& s);

// What a receiver point read, as the camera pass picks it (scene/cascade_fit.h cascadeOfPoint):
// the layer's index, its view depths [near, far] along the cascade camera's view direction, one
// texel's side in world units, and whether a cascade covers the point at all (false past the
// shadow distance: lit, index then the last layer's). A map of one layer: index 0, near and far 0
// (not a cascade).
struct PointCascade {
    int index = 0;
    int count = 1;  // the map's layers
    float nearZ = 0.0f;
    float farZ = 0.0f;
    float texelWs = 0.0f;
    bool covered = true;
};
PointCascade pointCascade(const MapSpec& map, const Camera& cascadeCamera, glm::vec3 posWs);
// The same for a layer already picked: `layer` as the camera pass numbers it (map.layers.size()
// for a point past the last cascade).
PointCascade pointCascadeOfLayer(const MapSpec& map, int layer);

// A segment of the frozen cascades' drawing, world space, and the cascade it belongs to.
struct CascadeLine {
    glm::vec3 a{0.0f};
    glm::vec3 b{0.0f};
    int cascade = 0;
    bool splitPlane = false;  // an edge of a split plane (else of the cascade's light box)
};
// Each cascade's light box (the 12 edges of its orthographic volume, shadowClipFromWorld's
// inverse over clip x, y, z in [-1, 1]) and the plane where it ends (the camera frustum's section
// at the cascade's far view depth, 4 edges), for `cascadeCamera` at `aspect`. Empty for a map of
// one layer.
std::vector<CascadeLine> cascadeFrameLines(const MapSpec& map, const Camera& cascadeCamera,
                                           float aspect);

// A world segment as seen by `camera` at `aspect`: its ends in the frame's pixels (origin
// top-left, y down) of a frame of frameSize, cut at the near plane; false when it lies wholly
// behind it.
bool projectSegment(const Camera& camera, glm::ivec2 frameSize, glm::vec3 a, glm::vec3 b,
                    std::array<glm::vec2, 2>& out);

}  // namespace pcf
