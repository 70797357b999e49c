// step_view.h: how a lesson step's scene is rendered and its pinned point traced, the one way
// the viewer, `export`, `animate`, `render --lesson` and the tests all do it: the map fitted with
// the step's texel grid (origin_shift, snap), the camera jittered so that the step's point lands
// on its pixel's centre and that pixel showing the point's own lookup (lesson_pick.h), and the
// trace of what the camera pass drew there, with the step's bias.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "kernel/bias.h"
#include "kernel/shadow_map.h"
#include "kernel/trace.h"
#include "lesson/compare_spec.h"
#include "lesson/lesson.h"
#include "lesson/lesson_pick.h"
#include "render/render_settings.h"
#include "render/scene_renderer.h"
#include "scene/scene.h"

namespace pcf {

RenderSettings renderSettingsFor(const LessonSettings& s, glm::ivec2 sceneSize);

// The shadow map's fit (light clip from world) for a lesson's settings: the scene's own fit with
// its texel grid slid by `origin_shift` and snapped with `snap` (scene/light.h:
// shiftShadowOrigin), for a map of `mapSize` texels.
glm::mat4 lessonShadowFit(const Scene& scene, const LessonSettings& s, int mapSize);

// How the camera pass shows a scene point in a frame of frameSize: the camera's sub-pixel jitter
// that centres the point on its pixel and the point's own lookup there (lesson_pick.h,
// SceneRenderer::setPick); nullopt when the frame does not show it.
// With cascades, the layer of the cascade the point falls in, the cascades fitted to
// cascadeCamera (nullopt: the scene's camera; lesson_pick.h pinnedLookup).
std::optional<CameraPick> cameraPickOf(const Scene& scene, const glm::mat4& shadowFit,
                                       const LessonSettings& s, const ScenePoint& point,
                                       glm::ivec2 frameSize,
                                       const std::optional<Camera>& cascadeCamera = std::nullopt);

// What a step's scene is rendered with.
struct StepView {
    RenderSettings render;           // the settings at the scene's size
    glm::mat4 fit{1.0f};             // the shadow map's fit
    std::optional<CameraPick> pick;  // the pinned point, where the frame shows it
    // The camera the cascades are fitted to (SceneRenderer::setCascadeCamera): nullopt, the
    // scene's; a magnified step's wide view or a frozen view's.
    std::optional<Camera> cascadeCamera;
};
// The view of settings `s` with the pinned `point` (none: no pick) in a scene of sceneSize; `fit`
// replaces lessonShadowFit's (an animation's creeping grid); cascadeCamera the scene camera as
// the cascades' (their fit and the choice of a receiver's cascade).
StepView stepView(const Scene& scene, const LessonSettings& s,
                  const std::optional<ScenePoint>& point, glm::ivec2 sceneSize,
                  const std::optional<glm::mat4>& fit = std::nullopt,
                  const std::optional<Camera>& cascadeCamera = std::nullopt);
// Renders both passes of the view. Needs the renderer's context current.
void renderStepView(SceneRenderer& renderer, const StepView& view);

// A traced lookup and its inputs (another method can look the same point up: traceLookup).
struct PixelLookup {
    Trace trace;
    glm::vec2 uv{0.0f};
    float z = 0.0f;         // the receiver's depth before bias
    float ref = 0.0f;       // the depth compared
    BiasSettings bias;      // the settings' bias
    glm::vec2 dzduv{0.0f};  // the receiver plane the shader used
    PointCascade cascade;   // the layer read (a cascade) and its view depths and texel size
};
// The lookup the last camera pass drew at a scene pixel (origin top-left), traced by the CPU
// kernel on `map` with settings `s`; nullopt when the pixel is not on a shadow receiver, or, for
// a cascaded map, not the pinned point's pixel (the one whose layer is known: CameraPick::layer).
std::optional<PixelLookup> tracePixel(const SceneRenderer& renderer, const ShadowMap& map,
                                      const LessonSettings& s, glm::ivec2 pixel);

// What a step's text and claims say of its split view (lesson_text.h: part[K].visibility): each
// part's visibility at `point`, the map rendered by `renderer` with that part's settings (`s` with
// the part's values, compare_spec.h: comparePart) under the scene's light, fitted as the lesson
// fits it (or `fit` when given: an animation's), and the point traced as `lesson check` traces it
// (lesson_pick.h: tracePinned). Needs a current OpenGL 4.5 context; changes `renderer`'s map.
std::vector<float> comparePartVisibilities(SceneRenderer& renderer, const Scene& scene,
                                           const std::optional<glm::mat4>& fit,
                                           const LessonSettings& s, const CompareSpec& spec,
                                           const ScenePoint& point);

}  // namespace pcf
