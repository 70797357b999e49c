#include "app/magnifier.h"

#include <algorithm>
#include <cmath>

#include "app/step_view.h"

namespace pcf {

namespace {

// Where the light's ray through light ndc (x, y) meets the plane through `point`: the ray is the
// inverse fit of two depths, so it holds for orthographic (directional) and perspective (spot)
// fits alike.
glm::vec3 onPlane(const glm::mat4& worldFromLightClip, glm::vec2 ndc, const ScenePoint& point) {
    glm::vec4 a = worldFromLightClip * glm::vec4(ndc, -1.0f, 1.0f);
    glm::vec4 b = worldFromLightClip * glm::vec4(ndc, 1.0f, 1.0f);
    glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
    glm::vec3 d = p1 - p0;
    float denom = glm::dot(point.normalWs, d);
    if (std::abs(denom) < 1e-12f) return point.posWs;  // grazing: no footprint to measure
    float t = glm::dot(point.normalWs, point.posWs - p0) / denom;
    return p0 + d * t;
}

}  // namespace

TexelFootprint texelFootprint(const glm::mat4& lightClipFromWorld, int mapSize,
                              const ScenePoint& point) {
    glm::vec4 c = lightClipFromWorld * glm::vec4(point.posWs, 1.0f);
    glm::vec2 ndc = glm::vec2(c) / c.w;
    // One texel is 1 / mapSize of uv, 2 / mapSize of ndc (uv = ndc * 0.5 + 0.5).
    float step = 2.0f / static_cast<float>(mapSize);
    glm::mat4 inverse = glm::inverse(lightClipFromWorld);
    glm::vec3 here = onPlane(inverse, ndc, point);
    return {onPlane(inverse, ndc + glm::vec2(step, 0.0f), point) - here,
            onPlane(inverse, ndc + glm::vec2(0.0f, step), point) - here};
}

glm::vec2 texelPixels(const Camera& camera, glm::ivec2 sceneSize, const ScenePoint& point,
                      const TexelFootprint& texel) {
    glm::vec2 size(sceneSize);
    glm::mat4 clip = clipFromWorld(camera, size.x / size.y);
    auto pixelOf = [&](glm::vec3 p) {
        glm::vec4 c = clip * glm::vec4(p, 1.0f);
        return (glm::vec2(c) / c.w * 0.5f + 0.5f) * size;
    };
    // The derivative at the point (a sixteenth of a texel, scaled up): a whole texel's step
    // would be foreshortened across its own length in a close-up.
    constexpr float PART = 16.0f;
    glm::vec2 at = pixelOf(point.posWs);
    return {glm::length(pixelOf(point.posWs + texel.uWs / PART) - at) * PART,
            glm::length(pixelOf(point.posWs + texel.vWs / PART) - at) * PART};
}

Camera magnifierCamera(const Camera& wide, glm::ivec2 sceneSize, const ScenePoint& point,
                       const TexelFootprint& texel) {
    float want = static_cast<float>(sceneSize.y) / MAGNIFIER_TEXELS_ACROSS;
    Camera c = wide;
    c.targetWs = point.posWs;
    glm::vec3 back = wide.eyeWs - point.posWs;  // from the point toward the wide view's eye
    float distance = glm::length(back);
    // A point at the view's centre shrinks as 1 / distance: a few rounds absorb the change of
    // foreshortening as the eye comes closer.
    for (int round = 0; round < 4; ++round) {
        c.eyeWs = point.posWs + back * (distance / glm::length(back));
        c.nearZ = distance * 0.05f;
        c.farZ = std::max(wide.farZ, 0.0f) + glm::length(wide.eyeWs - c.eyeWs) + distance;
        glm::vec2 px = texelPixels(c, sceneSize, point, texel);
        float shorter = std::min(px.x, px.y);
        if (!(shorter > 0.0f)) break;
        distance *= shorter / want;
    }
    c.eyeWs = point.posWs + back * (distance / glm::length(back));
    c.nearZ = distance * 0.05f;
    c.farZ = std::max(wide.farZ, 0.0f) + glm::length(wide.eyeWs - c.eyeWs) + distance;
    return c;
}

Camera stepCamera(const Scene& scene, const LessonSettings& s,
                  const std::optional<ScenePoint>& point, glm::ivec2 sceneSize) {
    // A frozen view backs away from the camera the cascades stay fitted to.
    if (s.freezeCascades && s.cascades > 1) return cascadeOverviewCamera(scene.camera, s);
    if (!s.magnify || !point || sceneSize.x <= 0 || sceneSize.y <= 0) return scene.camera;
    LessonSettings unslid = s;
    unslid.originShift = 0.0f;
    unslid.snap = false;
    int mapSize = renderSettingsFor(unslid, sceneSize).mapSize;
    TexelFootprint texel = texelFootprint(lessonShadowFit(scene, unslid, mapSize), mapSize, *point);
    return magnifierCamera(scene.camera, sceneSize, *point, texel);
}

void magnifySession(Session& session, const Camera& wide) {
    if (!session.point()) return;
    ScenePoint point = *session.point();
    glm::ivec2 scene(session.layout().scene.size());
    TexelFootprint texel =
        texelFootprint(session.renderedShadowFit(), session.settings().mapSize, point);
    session.setCamera(magnifierCamera(wide, scene, point, texel));
    session.pinPoint(point);
}

}  // namespace pcf
