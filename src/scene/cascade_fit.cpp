#include "scene/cascade_fit.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "kernel/cascades.h"
#include "kernel/pcf.h"
#include "kernel/shading.h"

namespace pcf {

float cascadeFarDepth(const Camera& camera, const ShadowSettings& s) {
    return s.shadowDistance > 0.0f ? s.shadowDistance : camera.farZ;
}

std::vector<CascadeRange> cascadeRangesOver(double n, double f, const ShadowSettings& s,
                                            std::optional<glm::vec2> visible) {
    if (s.cascadeBounds != CASCADE_BOUNDS_DEPTH) visible = std::nullopt;
    glm::dvec2 span = cascadeSplitSpan(n, f, visible);
    std::vector<double> splits =
        cascadeSplits(span.x, span.y, s.cascades, s.cascadeSplit, s.cascadeLambda);
    std::vector<CascadeRange> ranges;
    for (double far : splits) {
        float from = ranges.empty() ? static_cast<float>(span.x) : ranges.back().farZ;
        ranges.push_back({from, static_cast<float>(far)});
    }
    return ranges;
}

std::vector<CascadeRange> cascadeRanges(const Camera& camera, const ShadowSettings& s,
                                        std::optional<glm::vec2> visible) {
    return cascadeRangesOver(camera.nearZ, cascadeFarDepth(camera, s), s, visible);
}

namespace {

// A float as the shortest decimal that reads back as it ("0.05", not "0.0500000007").
std::string cascadeNumberText(float v) {
    char text[32];
    auto [end, ec] = std::to_chars(text, text + sizeof text, v);
    return ec == std::errc() ? std::string(text, end) : exactNumberText(v);
}

}  // namespace

std::optional<ParamProblem> cascadeProblem(const Scene& scene, const ShadowSettings& s) {
    if (s.cascades <= 1) return std::nullopt;
    std::string count = " " + std::to_string(s.cascades);
    if (scene.light.type != LightType::Directional) {
        return ParamProblem{"cascades", "",
                            count + " are for a directional light; the scene's light is a spot"};
    }
    if (methodInfo(s.method).searchesBlockers) {
        return ParamProblem{"cascades", "",
                            count + " do not work with " + std::string(methodInfo(s.method).name) +
                                " (one penumbra scale per map)"};
    }
    // A moments map is made from one depth map by its own pass (render/scene_renderer).
    if (!texelKindInfo(mapTexelKind(s.method, s.depthFormat, s.momentBits)).depth) {
        return ParamProblem{"cascades", "",
                            count + " do not work with " + std::string(methodInfo(s.method).name) +
                                " (a moments map has one layer)"};
    }
    if (!(cascadeFarDepth(scene.camera, s) > scene.camera.nearZ)) {
        return ParamProblem{"shadow_distance", "",
                            " " + cascadeNumberText(cascadeFarDepth(scene.camera, s)) +
                                " must lie beyond the camera's near plane " +
                                cascadeNumberText(scene.camera.nearZ)};
    }
    return std::nullopt;
}

std::array<glm::vec3, 8> frustumSliceWs(const Camera& camera, float aspect, CascadeRange r) {
    glm::mat4 worldFromView = glm::inverse(viewFromWorld(camera));
    float tanY = std::tan(glm::radians(camera.fovYDeg) * 0.5f);
    float tanX = tanY * aspect;
    std::array<glm::vec3, 8> corners;
    for (int k = 0; k < 8; ++k) {
        float d = (k & 4) ? r.farZ : r.nearZ;
        glm::vec4 posVs((k & 1 ? 1.0f : -1.0f) * d * tanX, (k & 2 ? 1.0f : -1.0f) * d * tanY, -d,
                        1.0f);
        corners[k] = glm::vec3(worldFromView * posVs);
    }
    return corners;
}

// The smallest sphere around a frustum slice (symmetric about the view axis, so its centre is on
// the axis): with a and b the near and far depths and A, B the squared half-diagonals of the near
// and far rectangles, the centre depth z that is as far from a near corner as from a far one,
//   (z - a)^2 + A = (b - z)^2 + B  =>  z = (b^2 + B - a^2 - A) / (2 (b - a)),
// held to [a, b] (a deep narrow slice's far rectangle alone decides: z = b).
SliceSphere sliceSphere(const Camera& camera, float aspect, CascadeRange r) {
    double tanY = std::tan(glm::radians(static_cast<double>(camera.fovYDeg)) * 0.5);
    double tanX = tanY * aspect;
    double diag2 = tanX * tanX + tanY * tanY;
    double a = r.nearZ, b = r.farZ;
    double nearCorner2 = a * a * diag2, farCorner2 = b * b * diag2;
    double z = (b * b + farCorner2 - a * a - nearCorner2) / (2.0 * (b - a));
    z = std::clamp(z, a, b);
    double radius =
        std::sqrt(std::max((z - a) * (z - a) + nearCorner2, (b - z) * (b - z) + farCorner2));
    // Rounded up to 1/16: the size is the same float from frame to frame.
    return {z, std::ceil(radius * 16.0) / 16.0};
}

namespace {

// A square (or rectangle) of the light's view, x and y: its centre and half-extents.
struct LightBox {
    glm::vec2 centre;
    glm::vec2 half;
};

LightBox boxAround(const glm::mat4& lightView, const std::array<glm::vec3, 8>& corners) {
    glm::vec2 lo(std::numeric_limits<float>::infinity()), hi(-lo);
    for (const glm::vec3& c : corners) {
        glm::vec2 p(lightView * glm::vec4(c, 1.0f));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return {0.5f * (lo + hi), 0.5f * (hi - lo)};
}

// The half-extent is the sphere's radius itself, never hi - lo of a moved box: the same float at
// every frame, as is every scale made from it.
LightBox sphereBox(const Scene& scene, const glm::mat4& lightView, float aspect, CascadeRange r) {
    SliceSphere sphere = sliceSphere(scene.camera, aspect, r);
    glm::mat4 worldFromView = glm::inverse(viewFromWorld(scene.camera));
    glm::vec4 centreWs =
        worldFromView * glm::vec4(0.0f, 0.0f, -static_cast<float>(sphere.depth), 1.0f);
    return {glm::vec2(lightView * centreWs), glm::vec2(static_cast<float>(sphere.radius))};
}

// The snapped box's clip from world, the texel snapping of Valient, "Stable Rendering of Cascaded
// Shadow Maps" (ShaderX6, 2008): x = s (R p) + 2 T / size - 1 (and y alike), where R p is
// the light view's rotation of p (no translation), s = 1 / half the scale, and T the texel corner
// the world origin lands on, the one nearest to where the box centred at `centre` puts it (so the
// box moves by at most half a texel). The rotation rows scaled by s are the same floats whenever
// half is, and the translation is whole texels: a map of the same half-extent is the last one
// moved by T - T', every texel (shaders/depth_snapped.*). z is the ortho's, as the free box's.
glm::mat4 snappedClip(const glm::mat4& lightView, const glm::mat4& zClip, LightBox box,
                      int mapSize) {
    glm::vec2 scale = 1.0f / box.half;
    double halfMap = 0.5 * mapSize;
    glm::mat4 clip = zClip;
    for (int axis = 0; axis < 2; ++axis) {
        for (int col = 0; col < 3; ++col) clip[col][axis] = scale[axis] * lightView[col][axis];
        // Where the world origin lands, in texels from the map's corner, then rounded.
        double origin =
            (static_cast<double>(lightView[3][axis]) - box.centre[axis]) * scale[axis] + 1.0;
        double corner = std::round(origin * halfMap);
        clip[3][axis] = static_cast<float>(corner / halfMap - 1.0);
    }
    return clip;
}

// One texel's world size in an orthographic map of mapSize texels: 2 / (s * mapSize), s the
// scale of clip x (or y) per world unit, the length of the matrix's first (second) row, of the
// wider axis (as shadowTexelWs, with the light's rotation folded in).
float orthoTexelWs(const glm::mat4& clipFromWorld, int mapSize) {
    float sx =
        glm::length(glm::vec3(clipFromWorld[0][0], clipFromWorld[1][0], clipFromWorld[2][0]));
    float sy =
        glm::length(glm::vec3(clipFromWorld[0][1], clipFromWorld[1][1], clipFromWorld[2][1]));
    return 2.0f / (std::min(sx, sy) * static_cast<float>(mapSize));
}

}  // namespace

glm::mat4 cascadeClipFromWorld(const Scene& scene, float aspect, CascadeRange r, int fit, bool snap,
                               int mapSize) {
    Aabb bounds = sceneBounds(scene);
    glm::mat4 lightView = lightFromWorld(scene.light, bounds);
    LightBox box = fit == CASCADE_FIT_SPHERE
                       ? sphereBox(scene, lightView, aspect, r)
                       : boxAround(lightView, frustumSliceWs(scene.camera, aspect, r));
    // Snapping moves the box by up to half a texel: one texel more on every side keeps the whole
    // slice inside it (half-extent e -> e * size / (size - 2), so the pad is one new texel).
    if (snap && mapSize > 2) {
        box.half *= static_cast<float>(mapSize) / static_cast<float>(mapSize - 2);
    }
    // Deep enough for every caster of the scene, whatever the slice holds: the scene's bounds in
    // the light's view depth (view space looks down -z), with clipFromLight's margin.
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (int k = 0; k < 8; ++k) {
        float z = (lightView * glm::vec4(bounds.cornerWs(k), 1.0f)).z;
        lo = std::min(lo, z);
        hi = std::max(hi, z);
    }
    float margin = std::max(SHADOW_FIT_MARGIN * glm::length(bounds.extentWs()), 1e-4f);
    glm::vec2 from = box.centre - box.half, to = box.centre + box.half;
    glm::mat4 clip =
        glm::orthoRH_NO(from.x, to.x, from.y, to.y, -hi - margin, -lo + margin) * lightView;
    return snap ? snappedClip(lightView, clip, box, mapSize) : clip;
}

glm::vec3 cameraViewDirWs(const Camera& camera) {
    return glm::normalize(camera.targetWs - camera.eyeWs);
}

int cascadeOfPoint(const MapSpec& map, const Camera& camera, glm::vec3 posWs) {
    int count = static_cast<int>(map.layers.size());
    if (count <= 1) return 0;
    vec4 cascadeFar(1e30f);
    for (int k = 0; k < count; ++k) cascadeFar[k] = map.layers[k].viewDepth.y;
    return pcfCascadeLayer(pcfViewDepth(posWs, camera.eyeWs, cameraViewDirWs(camera)), cascadeFar,
                           count);
}

namespace {

// One cascade's visibility of the point, its lookup as scene.frag makes it: with `rotate` the
// disk turned by the texel this cascade looks up (pcfTexelRotation).
float cascadeLayerVisibility(const ShadowMap& map, int layer, const ShadowSettings& s,
                             PcfParams prm, glm::vec3 posWs, glm::vec3 normalWs, float cosTheta,
                             glm::vec2 dzduv) {
    const PcfMapLayer& fit = map.spec().layers[static_cast<size_t>(layer)];
    PcfReceiverLookup at = layerReceiverLookup(fit, s, posWs, normalWs, cosTheta, map.layers() > 1);
    if (s.rotate) prm.rotation = pcfTexelRotation(vec2(at.u, at.v), map.size());
    return filterLayerVisibility(map, layer, vec2(at.u, at.v), at.ref, prm, s.kernelBias(dzduv));
}

}  // namespace

CascadeLookup cascadeVisibilityIn(const ShadowMap& map, int layer, float viewDepth,
                                  const ShadowSettings& s, const PcfParams& prm, glm::vec3 posWs,
                                  glm::vec3 normalWs, float cosTheta, glm::vec2 dzduv,
                                  glm::vec2 nextDzduv) {
    CascadeLookup out;
    out.layer = layer;
    out.viewDepth = viewDepth;
    out.visibility = cascadeLayerVisibility(map, layer, s, prm, posWs, normalWs, cosTheta, dzduv);
    out.nextVisibility = out.visibility;
    out.blended = out.visibility;
    const PcfMapLayer& fit = map.spec().layers[static_cast<size_t>(layer)];
    out.weight =
        pcfCascadeBlendWeight(viewDepth, fit.viewDepth, s.cascadeBlend, layer, map.layers());
    if (out.weight > 0.0f) {
        out.next = layer + 1;
        out.nextVisibility =
            cascadeLayerVisibility(map, out.next, s, prm, posWs, normalWs, cosTheta, nextDzduv);
        out.blended = pcfCascadeBlend(out.visibility, out.nextVisibility, out.weight);
    }
    return out;
}

CascadeLookup cascadeVisibilityAt(const ShadowMap& map, const Camera& camera,
                                  const ShadowSettings& s, const PcfParams& prm, glm::vec3 posWs,
                                  glm::vec3 normalWs, float cosTheta, glm::vec2 dzduv,
                                  glm::vec2 nextDzduv) {
    float viewDepth = pcfViewDepth(posWs, camera.eyeWs, cameraViewDirWs(camera));
    int layer = cascadeOfPoint(map.spec(), camera, posWs);
    if (layer >= map.layers()) {  // past the last cascade: lit
        CascadeLookup lit;
        lit.layer = layer;
        lit.viewDepth = viewDepth;
        return lit;
    }
    return cascadeVisibilityIn(map, layer, viewDepth, s, prm, posWs, normalWs, cosTheta, dzduv,
                               nextDzduv);
}

std::vector<PcfMapLayer> cascadeLayers(const Scene& scene, const ShadowSettings& s, float aspect,
                                       std::optional<glm::vec2> visible) {
    std::vector<PcfMapLayer> layers;
    for (const CascadeRange& r : cascadeRanges(scene.camera, s, visible)) {
        glm::mat4 clip =
            cascadeClipFromWorld(scene, aspect, r, s.cascadeFit, s.cascadeSnap, s.mapSize);
        PcfMapLayer layer{clip, vec2(0.0f), orthoTexelWs(clip, s.mapSize)};
        layer.viewDepth = vec2(r.nearZ, r.farZ);
        layers.push_back(layer);
    }
    return layers;
}

}  // namespace pcf
