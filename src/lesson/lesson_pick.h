// lesson_pick.h: the pick belongs to the scene. A lesson pins its lookup to a point of the scene
// (`point = [x, y, z]`, world units, on a surface the camera sees); every frame derives the pixel
// that shows the point, jitters the camera by less than half a pixel so that the point lands on
// that pixel's centre, and looks the point up on the CPU with the camera pass's own formulas
// (shared/pcf_shading.h: pcfReceiverLookup). So the lookup (uv, ref, frac) is the same at every
// frame size and mode, and the renderer shows exactly that lookup at the pixel
// (SceneRenderer::setPick): the picture, the trace and the words agree on every slide.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "kernel/trace.h"
#include "lesson/lesson.h"
#include "lesson/lesson_text.h"
#include "scene/camera.h"
#include "scene/cascade_view.h"
#include "scene/scene.h"

namespace pcf {

// A point given in a lesson lies on the surface the camera sees in its direction when it is
// within this distance of it (scene units): four decimals, as lessons write points, are closer.
constexpr float POINT_TOLERANCE = 1e-3f;

struct ScenePoint {
    glm::vec3 posWs{0.0f};                 // on the surface
    glm::vec3 normalWs{0.0f, 1.0f, 0.0f};  // unit, on the side the camera sees
    int object = -1;                       // index into Scene::objects
};

// The surface point the camera sees towards pointWs when that is pointWs itself (within
// POINT_TOLERANCE), snapped onto the surface; nullopt when the camera sees no surface there or
// sees another one in front of it.
std::optional<ScenePoint> seenPoint(const Scene& scene, glm::vec3 pointWs);

// The surface point seen through `ndc` (x right, y up, in [-1, 1]) of the camera at this aspect,
// rendered with jitterNdc added to every position (a click on a jittered frame); nullopt: none.
std::optional<ScenePoint> pointAtNdc(const Scene& scene, glm::vec2 ndc, float aspect,
                                     glm::vec2 jitterNdc);

// The point as a lesson's `point` key takes it: "point = [x, y, z]", six decimals (a step that
// claims a fraction to three digits needs them). What a click in the viewer and `pcfscope pick`
// print.
std::string pointKeyText(glm::vec3 posWs);

// The point a step pins: its settings' `point`, or the one seen through the middle of the view;
// nullopt when that is on no surface.
std::optional<ScenePoint> stepPoint(const Scene& scene, const LessonSettings& s);

// Where a scene point shows in a frame.
struct FramePick {
    glm::ivec2 pixel{0, 0};     // the pixel holding it, origin top-left, y down
    glm::vec2 jitterNdc{0.0f};  // added to every ndc position: the point lands on that centre
    bool inFrame = false;       // false: it projects outside (pixel clamped, no jitter)
};
FramePick framePick(const Camera& camera, glm::vec3 posWs, glm::ivec2 frameSize);
// The pick of a step's point in a frame; a frame-centred pick when it is on no surface.
FramePick stepPick(const Scene& scene, const LessonSettings& s, glm::ivec2 frameSize);

// What the camera pass looks up for the point (scene.frag's formulas) with the step's bias and
// map, in the map fitted by shadowClipFromWorld; with cascades (s.cascades > 1), in the layer of
// the cascade the point falls in, the cascades fitted to cascadeCamera (default: the scene's) at
// LESSON_CASCADE_ASPECT (scene/cascade_view.h), the fit unused.
struct PinnedLookup {
    glm::vec2 uv{0.0f};
    float z0 = 0.0f;           // the depth before bias
    float ref = 0.0f;          // the depth compared
    glm::vec2 dzduv{0.0f};     // the receiver's plane in the map (Isidoro 2006), unclamped
    PointCascade cascade;      // the layer read: index 0 of one
    glm::mat4 layerFit{1.0f};  // that layer's light clip from world
};
PinnedLookup pinnedLookup(const Scene& scene, const glm::mat4& shadowClipFromWorld,
                          const LessonSettings& s, const ScenePoint& point);
PinnedLookup pinnedLookup(const Scene& scene, const glm::mat4& shadowClipFromWorld,
                          const LessonSettings& s, const ScenePoint& point,
                          const Camera& cascadeCamera);

// The angle between the point's normal and the direction to the light, degrees: 0 the light
// straight above, 90 grazing, more: the point faces away from the light.
float lightAngleDeg(const Scene& scene, const ScenePoint& point);

// The scene's light with the sun moved as the settings say (LessonSettings::sunTilt, sunTurn):
// its heading turned about the vertical by sunTurn degrees, then its elevation above the ground
// raised by sunTilt degrees (scene/light.h: directionAtElevation), kept within
// [MIN_SUN_ELEVATION_DEG, 90]. A spot light turns its direction the same way and stays where it
// is. Unchanged when both are 0. The session, export and `lesson check` render with it.
Light lessonLight(const Light& sceneLight, const LessonSettings& s);
// The light's elevation above the ground (the XZ plane) in degrees: 90 straight down.
float lightElevationDeg(const Light& light);
// The lowest sun the keys make: the `animate --sweep sun` sweep ends at 2 degrees.
constexpr float MIN_SUN_ELEVATION_DEG = 1.0f;

// The trace of the point's lookup on `map` (the shadow map rendered with the step's settings and
// shadowClipFromWorld): what the session traces at the point's pixel, without rendering the
// camera pass (the pixel shows this very lookup: SceneRenderer::setPick).
// With cascades, the layer pinnedLookup names (Trace::layer); past the shadow distance the
// visibility is 1, as the camera pass draws it.
Trace tracePinned(const ShadowMap& map, const Scene& scene, const glm::mat4& shadowClipFromWorld,
                  const LessonSettings& s, const ScenePoint& point);
Trace tracePinned(const ShadowMap& map, const Scene& scene, const glm::mat4& shadowClipFromWorld,
                  const LessonSettings& s, const ScenePoint& point, const Camera& cascadeCamera);

// A cascaded map's blend band at the point, which reads cascade `layer` with the receiver plane
// dzduv (kernel/trace.h TraceCascadeBlend): in the last `cascade_blend` of that cascade's view
// depths (measured from cascadeCamera), the next cascade's own lookup of the point (its receiver
// plane in that cascade's fit) and the weight the camera pass mixes it in with (the shared
// kernel's pcfCascadeBlendWeight and pcfCascadeBlend, through scene/cascade_fit.h
// cascadeVisibilityIn); next -1, weight 0 and the cascade's own visibility elsewhere. prm: the
// lookup's parameters (Trace::params). tracePinned fills a trace's with it; the session its
// pinned pixel's.
TraceCascadeBlend pinnedCascadeBlend(const ShadowMap& map, const Light& light,
                                     const LessonSettings& s, const PcfParams& prm,
                                     const ScenePoint& point, int layer, glm::vec2 dzduv,
                                     const Camera& cascadeCamera);

// The context of a step: its state, and the pixel that shows its point in the frame rendered
// (framePick).
StepContext makeStepContext(const LessonStep& step, glm::ivec2 pixel = glm::ivec2(0));
// The context of settings `s` (a step's, or the live state after keys) at `pixel`, the point's
// angle to the light `lightAngleDeg` (negative: not known).
StepContext makeStepContext(const LessonSettings& s, glm::ivec2 pixel, float lightAngleDeg);

}  // namespace pcf
