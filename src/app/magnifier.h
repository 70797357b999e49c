// magnifier.h: a close-up camera on the pinned point (issue 20, "a magnifier"). In a wide view a
// 1024-texel map's texel covers about a pixel, so acne bands, stairs and shimmer turn into moire
// on a projector; moved toward the point along its own line of sight, the camera shows a texel
// many pixels wide while the point, its lookup and the picture's occluders stay what they were
// (the eye slides along a ray the wide view saw unblocked).
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "app/session.h"
#include "lesson/lesson_pick.h"
#include "scene/camera.h"

namespace pcf {

// The magnified view shows about this many texels across the scene's height: a texel is at
// least sceneHeight / MAGNIFIER_TEXELS_ACROSS pixels on its shorter side (45 px in a 720-pixel
// scene, 11 in the smallest 180-pixel one).
constexpr float MAGNIFIER_TEXELS_ACROSS = 16.0f;

// One texel of the map, as it lands on the point's surface: the world vectors of one texel step
// in u and in v from the point (the light's rays through the neighbouring texel centres meet the
// point's tangent plane there). lightClipFromWorld is the map's fit (Session::renderedShadowFit).
struct TexelFootprint {
    glm::vec3 uWs{0.0f};
    glm::vec3 vWs{0.0f};
};
TexelFootprint texelFootprint(const glm::mat4& lightClipFromWorld, int mapSize,
                              const ScenePoint& point);

// The two texel steps' lengths on screen, pixels, for `camera` in a scene of sceneSize: the
// projections of point, point + uWs and point + vWs.
glm::vec2 texelPixels(const Camera& camera, glm::ivec2 sceneSize, const ScenePoint& point,
                      const TexelFootprint& texel);

// `wide` moved toward the point along the line from its eye (and aimed at it) until the shorter
// texel step is sceneSize.y / MAGNIFIER_TEXELS_ACROSS pixels; clip planes refitted to the new
// distance. The field of view stays, so the close-up is an ordinary perspective view.
Camera magnifierCamera(const Camera& wide, glm::ivec2 sceneSize, const ScenePoint& point,
                       const TexelFootprint& texel);

// The camera a lesson step is seen through in a scene of sceneSize: the scene's own (the lesson's
// camera), or with the step's `magnify` (lesson.h) magnifierCamera on the step's point for its
// map as fitted before any slide (origin_shift 0, not snapped), so that steps that only slide
// or snap the grid are seen through the very same camera and differ by the slide alone. With
// `freeze_cascades` (and cascades), the frozen view's camera behind and above the scene's
// (scene/cascade_view.h cascadeOverviewCamera).
Camera stepCamera(const Scene& scene, const LessonSettings& s,
                  const std::optional<ScenePoint>& point, glm::ivec2 sceneSize);

// Puts the magnifier on the session: `wide` (the view it magnifies) moved onto the session's
// pinned point for its map fit and scene size, the point kept. Nothing when no point is pinned.
void magnifySession(Session& session, const Camera& wide);

}  // namespace pcf
