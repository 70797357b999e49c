// session_motion.cpp: the parts of Session that animations use (session.h, "Motion"): the scene's
// light and camera moved between frames, the shadow fit given from outside, the scene-only
// frame and the flicker trace.
#include <algorithm>
#include <cmath>

#include "app/session.h"
#include "render/frame_ops.h"

namespace pcf {

void Session::setLight(const Light& light) {
    mLesson.scene.light = light;
    if (mRenderer) mRenderer->setLight(light);
    mRendered.reset();  // a new light is a new map
    mSceneDirty = true;
}

void Session::setCamera(const Camera& camera) {
    mLesson.scene.camera = camera;
    if (mRenderer) mRenderer->setCamera(camera);
    mSceneDirty = true;
    // A moving camera keeps its pixel, not its scene point: the pick becomes the point under the
    // same pixel of the moved view (what a student watching that pixel sees change).
    if (mPoint) setPixel(mPixel);
}

void Session::setShadowFit(const std::optional<glm::mat4>& shadowClipFromWorld) {
    if (shadowClipFromWorld == mShadowFit) return;
    mShadowFit = shadowClipFromWorld;
    mRendered.reset();
    mSceneDirty = true;
}

glm::mat4 Session::renderedShadowFit() const {
    return mShadowFit ? *mShadowFit : lessonShadowFit(mLesson.scene, mSettings, mSettings.mapSize);
}

void Session::pinPoint(const ScenePoint& point) {
    mPoint = point;
    repick();
}

void Session::setSceneOnly(bool on) {
    if (on == mSceneOnly) return;
    mSceneOnly = on;
    glm::ivec2 size = mLayout.frameSize;
    mLayout.frameSize = glm::ivec2(0);  // setFrameSize lays the frame out again
    setFrameSize(size);
}

std::optional<float> Session::visibilityWith(int method, int kernel) const {
    if (!mLookup) return std::nullopt;
    LessonSettings s = mSettings;
    s.method = method;
    s.kernel = kernel;
    PcfParams pcss = mRenderer->pcfParams(s);  // pcss's light in this map (scene/pcss.h)
    PcfParams prm = s.pcfParams(mLookup->uv, mMap.width(), pcss.penumbraScale);
    prm.depthNear = pcss.depthNear;
    prm.depthFar = pcss.depthFar;
    const PixelLookup& at = *mLookup;
    if (!at.cascade.covered) return 1.0f;  // past the shadow distance: drawn lit
    return traceLookup(mMap, at.uv, at.z, at.ref, prm, at.bias, at.dzduv, at.cascade.index)
        .visibility;
}

// The scene over the whole frame, the pinned point ringed, and the flicker trace when set.
void Session::composeSceneOnly(GLuint fbo) {
    mTarget = fbo;
    glm::ivec2 frame = mLayout.frameSize;
    blitColour(mRenderer->frameFramebuffer(), {0, 0, frame.x, frame.y}, fbo,
               {0, 0, frame.x, frame.y});
    mBoxes.clear();
    bindFramebuffer(fbo);
    mCanvas.begin(frame);
    drawFrozenCascades(mLayout.scene);
    float r = std::max(6.0f, std::round(frame.y / 90.0f));
    glm::vec2 centre = glm::vec2(mPixel) + 0.5f;
    mCanvas.ring(centre, r + 1.0f, 3.0f, {0.0f, 0.0f, 0.0f, 0.8f});
    mCanvas.ring(centre, r, 1.5f, FLICKER_MAIN_COLOUR);
    if (mFlicker) drawFlicker(mLayout);
    mCanvas.flush();
    bindFramebuffer(0);
}

void Session::drawFlicker(const InspectorLayout& layout) {
    std::vector<LayoutBox> boxes;
    if (!layout.trace.empty()) {
        boxes = drawFlickerTrace(mCanvas, layout.trace, mFlicker(), typeSizes(layout).number);
    } else {
        // Over the scene alone: type that scales with the frame.
        float textPx = std::max(12.0f, std::round(mLayout.frameSize.y / 48.0f));
        boxes =
            drawFlickerTrace(mCanvas, flickerTraceRect(mLayout.scene, textPx), mFlicker(), textPx);
    }
    mBoxes.insert(mBoxes.end(), boxes.begin(), boxes.end());
}

}  // namespace pcf
