#include "lesson/lesson_pick.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kernel/shading.h"
#include "scene/cascade_fit.h"
#include "scene/cascade_view.h"
#include "scene/pcss.h"
#include "scene/raycast.h"
#include "scene/shadow_fit.h"

namespace pcf {

namespace {

std::optional<ScenePoint> pointOfHit(const std::optional<Hit>& hit) {
    if (!hit) return std::nullopt;
    // scene.frag turns the normal of a surface seen from behind (gl_FrontFacing).
    return ScenePoint{hit->posWs, hit->frontFace ? hit->normalWs : -hit->normalWs, hit->object};
}

// The camera pass's (u, v, depth) of a world point, in double: ndc = clip / w, * 0.5 + 0.5.
glm::dvec3 lightSpace(const glm::mat4& shadowClipFromWorld, glm::dvec3 posWs) {
    glm::dvec4 clip = glm::dmat4(shadowClipFromWorld) * glm::dvec4(posWs, 1.0);
    return glm::dvec3(clip) / clip.w * 0.5 + 0.5;
}

// The receiver's plane in the map fitted by shadowClipFromWorld, from two steps along the surface
// instead of two screen pixels: any two independent directions give the same dz/duv of a plane
// (pcfReceiverPlaneDzDuv). In double, so the steps' differences keep their digits.
glm::vec2 receiverPlane(const glm::mat4& shadowClipFromWorld, const ScenePoint& point) {
    glm::dvec3 nd(point.normalWs);
    glm::dvec3 t1 = glm::normalize(
        glm::cross(nd, std::fabs(nd.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    glm::dvec3 t2 = glm::cross(nd, t1);
    const double step = 1e-3;
    glm::dvec3 p(point.posWs);
    glm::dvec3 d1 = lightSpace(shadowClipFromWorld, p + step * t1) -
                    lightSpace(shadowClipFromWorld, p - step * t1);
    glm::dvec3 d2 = lightSpace(shadowClipFromWorld, p + step * t2) -
                    lightSpace(shadowClipFromWorld, p - step * t2);
    return pcfReceiverPlaneDzDuv(glm::vec3(d1), glm::vec3(d2));
}

}  // namespace

std::optional<ScenePoint> seenPoint(const Scene& scene, glm::vec3 pointWs) {
    glm::vec3 toPoint = pointWs - scene.camera.eyeWs;
    float distance = glm::length(toPoint);
    if (!(distance > 0.0f)) return std::nullopt;
    std::optional<Hit> hit = intersect(scene, Ray{scene.camera.eyeWs, toPoint / distance});
    if (!hit || std::fabs(hit->t - distance) > POINT_TOLERANCE) return std::nullopt;
    return pointOfHit(hit);
}

std::string pointKeyText(glm::vec3 posWs) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "point = [%.6f, %.6f, %.6f]", static_cast<double>(posWs.x),
                  static_cast<double>(posWs.y), static_cast<double>(posWs.z));
    return buf;
}

std::optional<ScenePoint> pointAtNdc(const Scene& scene, glm::vec2 ndc, float aspect,
                                     glm::vec2 jitterNdc) {
    return pointOfHit(intersect(scene, cameraRay(scene.camera, ndc - jitterNdc, aspect)));
}

std::optional<ScenePoint> stepPoint(const Scene& scene, const LessonSettings& s) {
    if (s.point) return seenPoint(scene, *s.point);
    // The middle of the view is the same point at every aspect (the field of view is vertical).
    return pointAtNdc(scene, glm::vec2(0.0f), 1.0f, glm::vec2(0.0f));
}

FramePick framePick(const Camera& camera, glm::vec3 posWs, glm::ivec2 frameSize) {
    glm::dvec2 size(frameSize);
    glm::dmat4 clipFromWorldD(clipFromWorld(camera, static_cast<float>(size.x / size.y)));
    glm::dvec4 clip = clipFromWorldD * glm::dvec4(glm::dvec3(posWs), 1.0);
    glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    // GL window coordinates (row 0 at the bottom), then the pixel holding them.
    glm::dvec2 window = (ndc * 0.5 + 0.5) * size;
    glm::ivec2 gl(std::floor(window.x), std::floor(window.y));
    FramePick pick;
    pick.inFrame =
        clip.w > 0.0 && gl.x >= 0 && gl.y >= 0 && gl.x < frameSize.x && gl.y < frameSize.y;
    gl = glm::clamp(gl, glm::ivec2(0), frameSize - 1);
    pick.pixel = glm::ivec2(gl.x, frameSize.y - 1 - gl.y);
    if (pick.inFrame) {
        glm::dvec2 centre = (glm::dvec2(gl) + 0.5) / size * 2.0 - 1.0;
        pick.jitterNdc = glm::vec2(centre - ndc);
    }
    return pick;
}

FramePick stepPick(const Scene& scene, const LessonSettings& s, glm::ivec2 frameSize) {
    if (std::optional<ScenePoint> p = stepPoint(scene, s)) {
        return framePick(scene.camera, p->posWs, frameSize);
    }
    FramePick pick;
    pick.pixel = frameSize / 2;
    return pick;
}

namespace {

glm::vec3 toLightWs(const Light& light, glm::vec3 posWs) {
    // scene.frag: toLight is -direction, or towards a spot light's position.
    return light.type == LightType::Spot ? glm::normalize(light.positionWs - posWs)
                                         : -glm::normalize(light.directionWs);
}

}  // namespace

float lightAngleDeg(const Scene& scene, const ScenePoint& point) {
    float c = glm::dot(point.normalWs, toLightWs(scene.light, point.posWs));
    return glm::degrees(std::acos(std::clamp(c, -1.0f, 1.0f)));
}

Light lessonLight(const Light& sceneLight, const LessonSettings& s) {
    if (s.sunTilt == 0.0f && s.sunTurn == 0.0f) return sceneLight;
    Light light = sceneLight;
    glm::vec3 d = glm::normalize(light.directionWs);
    // Turned about world Y (right-handed: positive degrees turn +X towards -Z).
    float a = glm::radians(s.sunTurn);
    d = glm::vec3(std::cos(a) * d.x + std::sin(a) * d.z, d.y,
                  -std::sin(a) * d.x + std::cos(a) * d.z);
    light.directionWs = d;
    float elevation =
        std::clamp(lightElevationDeg(light) + s.sunTilt, MIN_SUN_ELEVATION_DEG, 90.0f);
    light.directionWs = directionAtElevation(d, elevation);
    return light;
}

float lightElevationDeg(const Light& light) {
    glm::vec3 d = glm::normalize(light.directionWs);
    return glm::degrees(std::asin(std::clamp(-d.y, -1.0f, 1.0f)));
}

Trace tracePinned(const ShadowMap& map, const Scene& scene, const glm::mat4& shadowClipFromWorld,
                  const LessonSettings& s, const ScenePoint& point) {
    return tracePinned(map, scene, shadowClipFromWorld, s, point, scene.camera);
}

Trace tracePinned(const ShadowMap& map, const Scene& scene, const glm::mat4& shadowClipFromWorld,
                  const LessonSettings& s, const ScenePoint& point, const Camera& cascadeCamera) {
    PinnedLookup at = pinnedLookup(scene, shadowClipFromWorld, s, point, cascadeCamera);
    PcfParams pcss =
        pcssPcfParams(scene.light, shadowMapLayer(scene, shadowClipFromWorld, s.mapSize), s);
    PcfParams prm = s.pcfParams(at.uv, map.width(), pcss.penumbraScale);
    prm.depthNear = pcss.depthNear;
    prm.depthFar = pcss.depthFar;
    Trace trace = traceLookup(map, at.uv, at.z0, at.ref, prm, s, at.dzduv, at.cascade.index);
    // Past the shadow distance no cascade covers the point: the camera pass draws it lit.
    if (!at.cascade.covered) trace.visibility = 1.0f;
    if (at.cascade.covered && map.layers() > 1) {
        trace.cascadeBlend = pinnedCascadeBlend(map, scene.light, s, trace.params, point,
                                                at.cascade.index, at.dzduv, cascadeCamera);
    }
    return trace;
}

TraceCascadeBlend pinnedCascadeBlend(const ShadowMap& map, const Light& light,
                                     const LessonSettings& s, const PcfParams& prm,
                                     const ScenePoint& point, int layer, glm::vec2 dzduv,
                                     const Camera& cascadeCamera) {
    const std::vector<PcfMapLayer>& layers = map.spec().layers;
    glm::vec2 nextPlane(0.0f);
    if (layer + 1 < static_cast<int>(layers.size())) {
        nextPlane =
            receiverPlane(layers[static_cast<size_t>(layer) + 1].shadowClipFromWorld, point);
    }
    float viewDepth =
        pcfViewDepth(point.posWs, cascadeCamera.eyeWs, cameraViewDirWs(cascadeCamera));
    float cosTheta = glm::dot(point.normalWs, toLightWs(light, point.posWs));
    CascadeLookup c = cascadeVisibilityIn(map, layer, viewDepth, s, prm, point.posWs,
                                          point.normalWs, cosTheta, dzduv, nextPlane);
    return {c.next, c.weight, c.nextVisibility, c.blended};
}

PinnedLookup pinnedLookup(const Scene& scene, const glm::mat4& shadowClipFromWorld,
                          const LessonSettings& s, const ScenePoint& point) {
    return pinnedLookup(scene, shadowClipFromWorld, s, point, scene.camera);
}

PinnedLookup pinnedLookup(const Scene& scene, const glm::mat4& fit, const LessonSettings& s,
                          const ScenePoint& point, const Camera& cascadeCamera) {
    // The layer the point reads (one, or its cascade) and that layer's fit and texel size.
    MapSpec map = cascadedMapSpec(scene, s, fit, cascadeCamera, LESSON_CASCADE_ASPECT);
    PointCascade cascade = pointCascade(map, cascadeCamera, point.posWs);
    const PcfMapLayer& layer = map.layers[static_cast<size_t>(cascade.index)];
    const glm::mat4& shadowClipFromWorld = layer.shadowClipFromWorld;
    glm::vec3 n = point.normalWs;
    glm::vec3 toLight = toLightWs(scene.light, point.posWs);
    PcfReceiverLookup at =
        layerReceiverLookup(layer, s, point.posWs, n, glm::dot(n, toLight), map.layers.size() > 1);
    PinnedLookup out;
    out.uv = glm::vec2(at.u, at.v);
    out.z0 = at.z0;
    out.ref = at.ref;
    out.dzduv = receiverPlane(shadowClipFromWorld, point);
    out.cascade = cascade;
    out.layerFit = shadowClipFromWorld;
    return out;
}

StepContext makeStepContext(const LessonStep& step, glm::ivec2 pixel) {
    return makeStepContext(step.settings, pixel, -1.0f);
}

StepContext makeStepContext(const LessonSettings& s, glm::ivec2 pixel, float lightAngleDeg) {
    StepContext ctx;
    ctx.pixel = pixel;
    ctx.originShift = s.originShift;
    ctx.settings = s;
    ctx.lightAngleDeg = lightAngleDeg;
    return ctx;
}

}  // namespace pcf
