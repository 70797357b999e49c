#include "scene/cascade_view.h"

#include "kernel/cascades.h"
#include "scene/cascade_fit.h"
#include "scene/shadow_fit.h"

namespace pcf {

MapSpec cascadedMapSpec(const Scene& scene, const ShadowSettings& s, const glm::mat4& fit,
                        const Camera& cascadeCamera, float aspect,
                        std::optional<glm::vec2> visible) {
    if (s.cascades <= 1) return shadowMapSpec(scene, s, fit, aspect);
    Scene seen = scene;
    seen.camera = cascadeCamera;
    return shadowMapSpec(seen, s, fit, aspect, visible);
}

std::optional<ParamProblem> cascadeMethodProblem(const ShadowSettings& s) {
    if (s.cascades <= 1) return std::nullopt;
    Scene probe;
    probe.light.type = LightType::Directional;
    probe.camera.nearZ = 0.1f;
    probe.camera.farZ = 100.0f;
    ShadowSettings within = s;
    within.shadowDistance = 0.0f;  // the probe camera's far plane
    return cascadeProblem(probe, within);
}

std::optional<ParamProblem> lessonCascadeProblem(const Scene& scene, const ShadowSettings& s,
                                                 bool freeze) {
    if (std::optional<ParamProblem> why = cascadeProblem(scene, s)) return why;
    if (s.cascades > 1 && s.cascadeBounds == CASCADE_BOUNDS_DEPTH) {
        return ParamProblem{"cascade_bounds", "",
                            " depth is not for a lesson: its bounds are measured on the frame "
                            "drawn, but a lesson's cascades are fitted once for every frame size "
                            "(use fixed)"};
    }
    if (freeze && s.cascades < 2) {
        return ParamProblem{"freeze_cascades", "",
                            " needs cascades 2..4, not " + std::to_string(s.cascades)};
    }
    return std::nullopt;
}

Camera cascadeOverviewCamera(const Camera& camera, const ShadowSettings& s) {
    float f = cascadeFarDepth(camera, s);
    glm::vec3 dir = cameraViewDirWs(camera);
    glm::vec3 up = glm::normalize(camera.upWs);
    Camera c = camera;
    c.eyeWs = camera.eyeWs - dir * (0.35f * f) + up * (0.45f * f);
    c.targetWs = camera.eyeWs + dir * (0.45f * f);
    c.nearZ = 0.01f * f;
    c.farZ = 3.0f * f + camera.farZ;
    return c;
}

PointCascade pointCascade(const MapSpec& map, const Camera& cascadeCamera, glm::vec3 posWs) {
    return pointCascadeOfLayer(map, cascadeOfPoint(map, cascadeCamera, posWs));
}

PointCascade pointCascadeOfLayer(const MapSpec& map, int k) {
    PointCascade out;
    out.count = static_cast<int>(map.layers.size());
    out.covered = k < out.count;
    out.index = std::min(k, out.count - 1);
    const PcfMapLayer& layer = map.layers[static_cast<size_t>(out.index)];
    out.nearZ = layer.viewDepth.x;
    out.farZ = layer.viewDepth.y;
    out.texelWs = layer.texelWs;
    return out;
}

namespace {

// The 12 edges of a cube's corners numbered by bits (x 1, y 2, z 4): pairs differing in one bit.
constexpr std::array<std::array<int, 2>, 12> CUBE_EDGES{{{0, 1},
                                                         {2, 3},
                                                         {4, 5},
                                                         {6, 7},
                                                         {0, 2},
                                                         {1, 3},
                                                         {4, 6},
                                                         {5, 7},
                                                         {0, 4},
                                                         {1, 5},
                                                         {2, 6},
                                                         {3, 7}}};

}  // namespace

std::vector<CascadeLine> cascadeFrameLines(const MapSpec& map, const Camera& cascadeCamera,
                                           float aspect) {
    std::vector<CascadeLine> lines;
    if (map.layers.size() < 2) return lines;
    for (size_t k = 0; k < map.layers.size(); ++k) {
        const PcfMapLayer& layer = map.layers[k];
        int cascade = static_cast<int>(k);
        // The light box: clip space's cube taken back to the world (orthographic, w = 1).
        glm::mat4 worldFromClip = glm::inverse(layer.shadowClipFromWorld);
        std::array<glm::vec3, 8> box;
        for (int c = 0; c < 8; ++c) {
            glm::vec4 clip(c & 1 ? 1.0f : -1.0f, c & 2 ? 1.0f : -1.0f, c & 4 ? 1.0f : -1.0f, 1.0f);
            glm::vec4 w = worldFromClip * clip;
            box[static_cast<size_t>(c)] = glm::vec3(w) / w.w;
        }
        for (const auto& e : CUBE_EDGES) {
            lines.push_back(
                {box[static_cast<size_t>(e[0])], box[static_cast<size_t>(e[1])], cascade, false});
        }
        // Where the cascade ends: the frustum's rectangle at its far view depth (corners 4..7 of
        // the slice, x bit 1, y bit 2).
        std::array<glm::vec3, 8> slice = frustumSliceWs(
            cascadeCamera, aspect, CascadeRange{layer.viewDepth.x, layer.viewDepth.y});
        constexpr std::array<std::array<int, 2>, 4> RECT{{{4, 5}, {5, 7}, {7, 6}, {6, 4}}};
        for (const auto& e : RECT) {
            lines.push_back({slice[static_cast<size_t>(e[0])], slice[static_cast<size_t>(e[1])],
                             cascade, true});
        }
    }
    return lines;
}

bool projectSegment(const Camera& camera, glm::ivec2 frameSize, glm::vec3 a, glm::vec3 b,
                    std::array<glm::vec2, 2>& out) {
    glm::mat4 clip = clipFromWorld(camera, frameAspect(frameSize));
    glm::vec4 ca = clip * glm::vec4(a, 1.0f);
    glm::vec4 cb = clip * glm::vec4(b, 1.0f);
    // Cut at the near plane (clip z = -w): the part in front of it has z + w >= 0.
    float da = ca.z + ca.w, db = cb.z + cb.w;
    if (da < 0.0f && db < 0.0f) return false;
    if (da < 0.0f) ca = glm::mix(ca, cb, da / (da - db));
    if (db < 0.0f) cb = glm::mix(cb, ca, db / (db - da));
    glm::vec2 size(frameSize);
    auto toPixels = [&](glm::vec4 c) {
        glm::vec2 ndc = glm::vec2(c) / std::max(c.w, 1e-6f);
        return glm::vec2((ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y);
    };
    out = {toPixels(ca), toPixels(cb)};
    return true;
}

}  // namespace pcf
