#include "app/step_view.h"

#include "scene/light.h"

namespace pcf {

RenderSettings renderSettingsFor(const LessonSettings& s, glm::ivec2 sceneSize) {
    RenderSettings r;
    static_cast<ShadowSettings&>(r) = s;
    r.frameSize = sceneSize;
    r.cascadeAspect = LESSON_CASCADE_ASPECT;
    return r;
}

glm::mat4 lessonShadowFit(const Scene& scene, const LessonSettings& s, int mapSize) {
    glm::mat4 fit = shadowClipFromWorld(scene);
    if (s.originShift == 0.0f && !s.snap) return fit;
    return shiftShadowOrigin(fit, glm::vec2(s.originShift), mapSize, s.snap);
}

std::optional<CameraPick> cameraPickOf(const Scene& scene, const glm::mat4& shadowFit,
                                       const LessonSettings& s, const ScenePoint& point,
                                       glm::ivec2 frameSize,
                                       const std::optional<Camera>& cascadeCamera) {
    FramePick at = framePick(scene.camera, point.posWs, frameSize);
    if (!at.inFrame) return std::nullopt;
    PinnedLookup lookup =
        pinnedLookup(scene, shadowFit, s, point, cascadeCamera ? *cascadeCamera : scene.camera);
    glm::ivec2 gl(at.pixel.x, frameSize.y - 1 - at.pixel.y);
    // Past the shadow distance: a layer beyond the last, which the camera pass draws lit.
    int layer = lookup.cascade.covered ? lookup.cascade.index : lookup.cascade.count;
    return CameraPick{gl, at.jitterNdc, glm::vec4(lookup.uv, lookup.ref, lookup.z0), lookup.dzduv,
                      layer};
}

StepView stepView(const Scene& scene, const LessonSettings& s,
                  const std::optional<ScenePoint>& point, glm::ivec2 sceneSize,
                  const std::optional<glm::mat4>& fit, const std::optional<Camera>& cascadeCamera) {
    StepView view;
    view.render = renderSettingsFor(s, sceneSize);
    view.fit = fit ? *fit : lessonShadowFit(scene, s, view.render.mapSize);
    view.cascadeCamera = cascadeCamera;
    if (point) view.pick = cameraPickOf(scene, view.fit, s, *point, sceneSize, cascadeCamera);
    return view;
}

void renderStepView(SceneRenderer& renderer, const StepView& view) {
    renderer.setShadowClipFromWorld(view.fit);
    renderer.setCascadeCamera(view.cascadeCamera);
    renderer.setPick(view.pick);
    renderer.render(view.render);
}

std::optional<PixelLookup> tracePixel(const SceneRenderer& renderer, const ShadowMap& map,
                                      const LessonSettings& s, glm::ivec2 pixel) {
    std::vector<float> ls = renderer.readLightSpaceRegion(pixel, glm::ivec2(1));
    if (ls[3] != 1.0f) return std::nullopt;
    PixelLookup out;
    out.uv = glm::vec2(ls[0], ls[1]);
    out.ref = ls[2];
    // The receiver target holds the plane the shader used and the depth before any bias.
    std::vector<float> receiver = renderer.readReceiverRegion(pixel, glm::ivec2(1));
    out.bias = s;
    out.dzduv = glm::vec2(receiver[0], receiver[1]);
    out.z = receiver[3] == 1.0f ? receiver[2] : out.ref + s.baseBias();
    PcfParams pcss = renderer.pcfParams(s);  // pcss's light in this map (scene/pcss.h)
    PcfParams prm = s.pcfParams(out.uv, map.width(), pcss.penumbraScale);
    prm.depthNear = pcss.depthNear;
    prm.depthFar = pcss.depthFar;
    // The layer the pixel read: a cascaded map's is known at the pinned point's pixel (the
    // camera pass reads the pick's layer there); past the shadow distance the pixel is lit.
    int layer = 0;
    if (map.layers() > 1) {
        const std::optional<CameraPick>& pick = renderer.pick();
        glm::ivec2 gl(pixel.x, renderer.frameSize().y - 1 - pixel.y);
        if (!pick || pick->pixelGl != gl) return std::nullopt;
        out.cascade = pointCascadeOfLayer(map.spec(), pick->layer);
        layer = out.cascade.index;
    }
    out.trace = traceLookup(map, out.uv, out.z, out.ref, prm, out.bias, out.dzduv, layer);
    if (!out.cascade.covered) out.trace.visibility = 1.0f;
    return out;
}

std::vector<float> comparePartVisibilities(SceneRenderer& renderer, const Scene& scene,
                                           const std::optional<glm::mat4>& fit,
                                           const LessonSettings& s, const CompareSpec& spec,
                                           const ScenePoint& point) {
    std::vector<float> out;
    renderer.setLight(scene.light);
    for (int i = 0; i < spec.parts(); ++i) {
        LessonSettings part = comparePart(s, spec, i);
        glm::mat4 partFit = fit ? *fit : lessonShadowFit(scene, part, part.mapSize);
        renderer.setShadowClipFromWorld(partFit);
        renderer.renderShadowPass(renderSettingsFor(part, {64, 64}));
        ShadowMap map = renderer.readShadowMap();
        out.push_back(tracePinned(map, scene, partFit, part, point).visibility);
    }
    return out;
}

}  // namespace pcf
