#include "app/session.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "app/cascade_lines.h"
#include "app/cli_util.h"
#include "app/frame_json.h"
#include "app/magnifier.h"
#include "app/step_words.h"
#include "kernel/methods.h"
#include "kernel/trace_json.h"
#include "lesson/lesson_claims.h"
#include "lesson/lesson_pick.h"
#include "lesson/lesson_text.h"
#include "measure/stability.h"
#include "render/frame_ops.h"

namespace pcf {

namespace {

// The state, what the keys changed from the step's (`changed`: changedSettings), the scene's
// size and the frame time.
std::string statusLine(const LessonSettings& s, bool hideBiasAmounts,
                       const std::vector<std::string>& changed, glm::ivec2 sceneSize,
                       double frameTimeMs) {
    std::ostringstream line;
    line << settingsSummary(s, hideBiasAmounts);
    for (size_t k = 0; k < changed.size(); ++k) line << (k == 0 ? "   keys: " : ", ") << changed[k];
    line << "   scene " << sceneSize.x << "x" << sceneSize.y;
    if (frameTimeMs >= 0.0) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "   %.1f ms", frameTimeMs);
        line << buf;
    }
    return line.str();
}

}  // namespace

Json motionJson(const FrameMotion& motion) {
    return {{"sweep", motion.sweep},   {"frame", motion.frame},
            {"frames", motion.frames}, {"value", jsonNumber(static_cast<float>(motion.value))},
            {"words", motion.swept},   {"steps_own", motion.stepsOwn}};
}

Session::Session(glm::ivec2 frameSize, bool presentation) : mPresentation(presentation) {
    setFrameSize(frameSize);
}

void Session::loadLesson(const std::string& path) { setLesson(loadLessonChecked(path)); }

void Session::setLesson(Lesson lesson) {
    mLesson = std::move(lesson);
    mRenderer = std::make_unique<SceneRenderer>(mLesson.scene);
    mPartRenderer.reset();
    mBaseLight = mLesson.scene.light;
    mLessonCamera = mLesson.scene.camera;
    mStepMagnified = false;
    mLitSun = glm::vec2(0.0f);
    mRendered.reset();
    mSceneDirty = true;
    goToStep(0);
}

void Session::goToStep(int step) {
    if (mLesson.steps.empty()) return;
    mStep = std::clamp(step, 0, stepCount() - 1);
    const LessonStep& s = mLesson.steps[static_cast<size_t>(mStep)];
    mTextPage = 0;
    mRevealed = false;
    mTyped.clear();
    mGrid = s.settings.grid;
    mHeatmap = s.settings.heatmap;
    setSettings(s.settings);
    // The step's scene point, found in the lesson's own view (a close-up may not see it), shown
    // at whichever pixel holds it in this frame (lesson_pick.h).
    if (mStepMagnified) {
        mLesson.scene.camera = mLessonCamera;
        if (mRenderer) mRenderer->setCamera(mLessonCamera);
        mStepMagnified = false;
        mSceneDirty = true;
    }
    mPoint = stepPoint(mLesson.scene, s.settings);
    applyStepCamera();
    repick();
    mStepEdited = false;
}

void Session::applyStepCamera() {
    bool frozen = mSettings.freezeCascades && mSettings.cascades > 1;
    if (!mSettings.magnify && !frozen && !mStepMagnified) return;
    Scene wide = mLesson.scene;
    wide.camera = mLessonCamera;
    Camera camera = stepCamera(wide, mSettings, mPoint, glm::ivec2(mLayout.scene.size()));
    mLesson.scene.camera = camera;
    if (mRenderer) mRenderer->setCamera(camera);
    mStepMagnified = (mSettings.magnify && mPoint.has_value()) || frozen;
    mSceneDirty = true;
}

std::optional<Camera> Session::cascadeCamera() const {
    if (mStepMagnified) return mLessonCamera;
    return std::nullopt;
}

void Session::repick() {
    glm::ivec2 size(mLayout.scene.size());
    mPickInFrame = false;
    mJitter = glm::vec2(0.0f);
    // Moving the pick re-renders the camera pass: the camera's jitter and the pixel the pinned
    // lookup is shown at change with it.
    mSceneDirty = true;
    if (!mPoint || size.x <= 0 || size.y <= 0) return;
    FramePick pick = framePick(mLesson.scene.camera, mPoint->posWs, size);
    mPixel = pick.pixel;
    mPickInFrame = pick.inFrame;
    mJitter = pick.jitterNdc;
}

namespace {

// Equal apart from the picked point, which is part of the settings but not of the picture.
bool samePicture(LessonSettings a, const LessonSettings& b) {
    a.point = b.point;
    return a == b;
}

}  // namespace

void Session::setSettings(const LessonSettings& s) {
    // Moving the pixel re-traces without re-rendering.
    if (!samePicture(s, mSettings) || !mRendered) mSceneDirty = true;
    bool refreeze = s.freezeCascades != mSettings.freezeCascades;
    mSettings = s;
    // Y froze or thawed the cascades: the camera backs away from the lesson's, or returns.
    if (refreeze) {
        applyStepCamera();
        if (mPoint) repick();
    }
    // The sun the keys moved (lesson_pick.h: lessonLight): a new light is a new map.
    if (glm::vec2(s.sunTilt, s.sunTurn) != mLitSun) {
        mLitSun = glm::vec2(s.sunTilt, s.sunTurn);
        setLight(lessonLight(mBaseLight, s));
    }
    // Keys changed what the step's words were written for (goToStep clears it).
    mStepEdited = !mLesson.steps.empty() &&
                  !sameForTheWords(s, mLesson.steps[static_cast<size_t>(mStep)].settings);
}

void Session::setPixel(glm::ivec2 scenePixel) {
    glm::ivec2 size(mLayout.scene.size());
    mPixel = glm::clamp(scenePixel, glm::ivec2(0), size - glm::ivec2(1));
    if (!mRenderer || size.x <= 0 || size.y <= 0) return;
    // A pick on screen pins the scene point under the pixel's centre (as the frame shows it,
    // jitter and all), so that it stays the same lookup when the frame is resized.
    glm::ivec2 gl(mPixel.x, size.y - 1 - mPixel.y);
    float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    mPoint = pointAtNdc(mLesson.scene, pixelCentreNdc(gl, size), aspect, mJitter);
    if (mPoint) {
        repick();
    } else {
        mPickInFrame = false;  // no surface there: the pixel as it is, nothing pinned
        mSceneDirty = true;
    }
}

bool Session::sceneShown() const {
    return mLesson.steps.empty() || mLesson.steps[static_cast<size_t>(mStep)].chart.empty();
}

bool Session::clickFrame(glm::vec2 framePoint) {
    // The scene where this step's frame draws it: an inset maps back to the scene's pixels.
    Rect scene = stepLayout().scene;
    if (!sceneShown() || !scene.contains(framePoint)) return false;
    float scale = mLayout.scene.w / std::max(1.0f, scene.w);
    setPixel(glm::ivec2(glm::floor((framePoint - scene.position()) * scale)));
    return true;
}

InspectorLayout Session::stepLayout() const {
    if (mLesson.steps.empty()) return mLayout;
    const LessonStep& step = mLesson.steps[static_cast<size_t>(mStep)];
    InspectorLayout l = focusLayout(mLayout, stepFocus(step));
    // An animation's frames give the flicker trace (the method on screen and its comparison) a
    // room of its own, off the scene and the step's words.
    if (mFlicker && step.chart.empty()) l = motionLayout(l, 2);
    return l;
}

void Session::setFrameSize(glm::ivec2 frameSize) {
    if (frameSize == mLayout.frameSize && mFrame.framebuffer) return;
    glm::ivec2 oldScene(mLayout.scene.size());
    mLayout = inspectorLayout(frameSize, mPresentation);
    if (mSceneOnly) mLayout.scene = Rect{0.0f, 0.0f, float(frameSize.x), float(frameSize.y)};
    mFrame = createOffscreenTarget(frameSize.x, frameSize.y, {GL_RGBA8});
    glm::ivec2 newScene(mLayout.scene.size());
    if (oldScene.x > 0 && oldScene != newScene) {
        mPixel = mPixel * newScene / oldScene;
    }
    mPixel = glm::clamp(mPixel, glm::ivec2(0), newScene - glm::ivec2(1));
    // A close-up is sized to the scene (a texel a sixteenth of its height).
    if (mStepMagnified) applyStepCamera();
    // The pinned point stays: its pixel and the camera's jitter are derived for the new size.
    repick();
    mSceneDirty = true;
}

void Session::setPresentation(bool on) {
    mPresentation = on;
    // Presentation mode sizes the panels anew: the scene is laid out, picked and rendered again.
    glm::ivec2 size = mLayout.frameSize;
    mLayout.frameSize = glm::ivec2(0);
    setFrameSize(size);
    mThumbnailDirty = true;
}

namespace {

// Uploads a top-down RGBA8 image with its rows reversed, so that texture row 0 is the image's
// bottom row, as GL counts rows. The frame then takes it with an unflipped blit, which llvmpipe
// copies as memory instead of running a shader over every pixel; the bytes are the same.
void uploadBottomUp(const OffscreenTarget& target, int w, int h, const std::vector<uint8_t>& rgba) {
    std::vector<uint8_t> flipped(rgba.size());
    size_t row = static_cast<size_t>(w) * 4;
    for (int y = 0; y < h; ++y) {
        std::copy_n(
            rgba.begin() + static_cast<std::ptrdiff_t>(row * static_cast<size_t>(h - 1 - y)), row,
            flipped.begin() + static_cast<std::ptrdiff_t>(row * static_cast<size_t>(y)));
    }
    uploadRgba8(target.colors[0].id(), w, h, flipped);
}

}  // namespace

void Session::blitThumbnail(const InspectorLayout& layout) {
    Rect r = thumbnailRect(layout, mPresentation);
    int side = static_cast<int>(r.w);
    if (side <= 0 || mMap.width() <= 0) return;
    if (mThumbnailDirty || mThumbnail.width != side ||
        (mMap.layers() > 1 && mTrace && mTrace->layer != mThumbnailLayer)) {
        mThumbnail = createOffscreenTarget(side, side, {GL_RGBA8});
        // A cascaded map: the layer the traced lookup read.
        int layer = mTrace ? mTrace->layer : 0;
        std::vector<uint8_t> rgba =
            thumbnailImage(mMap.layers() > 1 ? mMap.layerMap(layer) : mMap, side);
        mThumbnailLayer = layer;
        uploadBottomUp(mThumbnail, side, side, rgba);
        mThumbnailDirty = false;
    }
    // Texture row 0 holds the image's bottom row (uploadBottomUp): a straight copy.
    int frameH = mLayout.frameSize.y;
    int x = static_cast<int>(r.x);
    int top = frameH - static_cast<int>(r.y);
    blitColour(mThumbnail.framebuffer.id(), {0, 0, side, side}, mTarget,
               {x, top - side, x + side, top});
}

void Session::setHelp(bool on) { mHelp = on; }

bool Session::nextPage() {
    if (mTextPage + 1 >= mTextPages) {
        // The question's last page: the answer is the next.
        if (!questionShown()) return false;
        setRevealed(true);
        return true;
    }
    ++mTextPage;
    return true;
}

bool Session::previousPage() {
    if (mTextPage <= 0) {
        if (!predictStep() || !mRevealed) return false;
        // Back to the question's last page.
        mRevealed = false;
        mTextPage = LAST_TEXT_PAGE;
        return true;
    }
    --mTextPage;
    return true;
}

void Session::setFrameTimeMs(double ms) { mFrameTimeMs = ms; }

void Session::blitChart(const InspectorLayout& layout) {
    glm::ivec2 size(layout.scene.size());
    const LessonStep& step = mLesson.steps[static_cast<size_t>(mStep)];
    // The chart's texts are placed with the scene rect's origin, so the key has it too.
    std::string key = step.chart + "@" + std::to_string(size.x) + "x" + std::to_string(size.y) +
                      "+" + std::to_string(layout.scene.x) + "," + std::to_string(layout.scene.y) +
                      "#" + step.chartHighlight + (layout.presentation ? "P" : "");
    if (key != mChartKey) {
        std::vector<uint8_t> rgba = drawStepChart(step, size, layout.presentation);
        mChart = createOffscreenTarget(size.x, size.y, {GL_RGBA8});
        uploadBottomUp(mChart, size.x, size.y, rgba);
        mChartBoxes = stepChartBoxes(step, layout);
        mChartKey = key;
    }
    // Texture row 0 holds the chart's bottom row (uploadBottomUp): a straight copy.
    int frameH = mLayout.frameSize.y;
    int x = static_cast<int>(layout.scene.x);
    int top = frameH - static_cast<int>(layout.scene.y);
    blitColour(mChart.framebuffer.id(), {0, 0, size.x, size.y}, mTarget,
               {x, top - size.y, x + size.x, top});
}

void Session::renderScene() {
    // The step's view (step_view.h): an animation's fit (setShadowFit), else the lesson's, and
    // the pinned point's pixel showing the point's own lookup.
    StepView view = stepView(mLesson.scene, mSettings, mPoint, glm::ivec2(mLayout.scene.size()),
                             mShadowFit, cascadeCamera());
    RenderSettings r = view.render;
    // A cascaded map's density is measured on the frame, from its world positions.
    r.writePositions = r.cascades > 1;
    mRenderer->setPick(view.pick);
    mRenderer->setCascadeCamera(view.cascadeCamera);
    // The map is drawn again when the one it would draw is another value (its size, texel kind,
    // or fit: the texel grid slid and snapped as the lesson says, light.h shiftShadowOrigin, or
    // the cascades refitted to a moved camera), or the depth pass draws it otherwise (culling,
    // polygon offset).
    mRenderer->setShadowClipFromWorld(view.fit);
    bool mapChanged = !mRendered || mRenderer->mapSpecFor(r) != mRenderer->mapSpec() ||
                      mRendered->cull != r.cull || mRendered->polygonOffset != r.polygonOffset;
    mHeatDirty = true;
    // Only what changed: the shadow pass when the map did (renderStepView renders both).
    if (mapChanged) mRenderer->renderShadowPass(r);
    mRenderer->renderCameraPass(r);
    if (mapChanged) {
        mMap = mRenderer->readShadowMap();
        // A moments map's depths, for the inspector's footprint (kernel/moment_footprint.h).
        mDepthMap = mMap.spec().texel().depth ? ShadowMap() : mRenderer->readDepthMap();
        mThumbnailDirty = true;
    }
    measureCascades(r);
    mRendered = r;
    mSceneDirty = false;
}

void Session::drawFrozenCascades(const Rect& sceneRect) {
    std::optional<Camera> frozen = cascadeCamera();
    if (!mSettings.freezeCascades || !frozen || mRenderer->mapSpec().layers.size() < 2) return;
    std::vector<CascadeLine> lines =
        cascadeFrameLines(mRenderer->mapSpec(), *frozen, LESSON_CASCADE_ASPECT);
    float scale = std::max(1.0f, static_cast<float>(mLayout.frameSize.y) / 720.0f);
    mCanvas.pushClip(sceneRect);
    drawCascadeLines(mCanvas, sceneRect, glm::ivec2(mLayout.scene.size()), mLesson.scene.camera,
                     lines, scale);
    mCanvas.popClip();
}

void Session::measureCascades(const RenderSettings& r) {
    mCascadeDensity.clear();
    if (mRenderer->mapSpec().layers.size() < 2) return;
    if (!r.writePositions) return;
    mCascadeDensity =
        cascadeDensities(mRenderer->readLightSpace(), mRenderer->readPositions(),
                         mRenderer->frameSize(), mRenderer->mapSpec(), mRenderer->cascadeCamera());
}

void Session::traceAtPixel() {
    mTrace.reset();
    glm::ivec2 size(mLayout.scene.size());
    // Only the region the overlay draws around the pixel comes back from the GPU.
    int radius = gridRadius(size) + 1;
    mLightSpaceOrigin = mPixel - glm::ivec2(radius);
    mLightSpaceSize = glm::ivec2(2 * radius + 1);
    mLightSpace = mRenderer->readLightSpaceRegion(mLightSpaceOrigin, mLightSpaceSize);
    mLookup = tracePixel(*mRenderer, mMap, mSettings, mPixel, &mDepthMap);
    // A cascaded map: the density of the cascade read, as measured on this frame.
    if (mLookup && mLookup->trace.layer < static_cast<int>(mCascadeDensity.size())) {
        mLookup->trace.cascadeTexelsPerPixelMax = static_cast<float>(
            mCascadeDensity[static_cast<size_t>(mLookup->trace.layer)].texelsPerPixelMax);
    }
    // A cascaded map's blend band at the pinned point: the next cascade's lookup and its weight.
    if (mLookup && mPoint && mMap.layers() > 1 && mLookup->cascade.covered) {
        mLookup->trace.cascadeBlend = pinnedCascadeBlend(
            mMap, mLesson.scene.light, mSettings, mLookup->trace.params, *mPoint,
            mLookup->cascade.index, mLookup->dzduv, cascadeCamera().value_or(mLesson.scene.camera));
    }
    if (mLookup) mTrace = mLookup->trace;
    tracePartsOfText();
}

// A step whose words read its split view (part[K].visibility): each part's map rendered with its
// settings by a renderer of its own (the scene's keeps its map), the point traced on each.
void Session::tracePartsOfText() {
    mPartVisibility.clear();
    const LessonStep& step = mLesson.steps[static_cast<size_t>(mStep)];
    if (step.compare.empty() || !mPoint || step.text.find("{part[") == std::string::npos) return;
    if (!mPartRenderer) mPartRenderer = std::make_unique<SceneRenderer>(mLesson.scene);
    try {
        mPartVisibility = comparePartVisibilities(*mPartRenderer, mLesson.scene, mShadowFit,
                                                  mSettings, step.compare, *mPoint);
    } catch (const std::invalid_argument&) {
        // The live settings cannot take the split (a bias the method refuses): "n/a".
    }
}

std::string Session::stepText() const { return stepWords().text; }

FrameWords Session::stepWords() const {
    if (mLesson.steps.empty()) return {};
    const LessonStep& s = mLesson.steps[static_cast<size_t>(mStep)];
    // The window's own way to play an animation step, which no written frame shows.
    std::string hint = mInteractive && s.animate ? std::string(PLAY_HINT) + "\n\n" : "";
    if (!mTrace) {
        return {hint + (s.text.find('{') == std::string::npos
                            ? s.text
                            : "(The picked pixel is not on a shadow receiver, so this step's "
                              "numbers cannot be shown. Pick a point on the ground.)")};
    }
    StepContext ctx =
        makeStepContext(mSettings, mPixel, mPoint ? lightAngleDeg(mLesson.scene, *mPoint) : -1.0f);
    ctx.partVisibility = mPartVisibility;
    std::string text = fillText(s.text, *mTrace, ctx);
    if (!mStepEdited && !mMotion) return {hint + text};
    ClaimWorld world;
    world.onPlane = mPoint && std::holds_alternative<Plane>(
                                  mLesson.scene.objects[static_cast<size_t>(mPoint->object)].shape);
    // A step's motion claim (`flickers`) is about its own sweep: another sweep does not make it.
    if (mMotion && !mMotion->stepsOwn) {
        world.flickerCurve = []() -> std::variant<std::vector<float>, std::string> {
            return std::string("another sweep than the step's own");
        };
    }
    WordsInput in{s, mMotion ? mMotion->base : mSettings, text, *mTrace, ctx, world, mInteractive};
    FrameWords words = mMotion ? wordsForMovingFrame(in, mMotion->swept) : wordsForLiveState(in);
    words.text = hint + words.text;
    return words;
}

void Session::compose() { composeInto(mFrame.framebuffer.id()); }

void Session::composeInto(GLuint fbo) {
    if (!mRenderer) throw std::logic_error("Session::compose before loadLesson");
    if (mSceneDirty) renderScene();
    traceAtPixel();
    if (mSceneOnly) return composeSceneOnly(fbo);

    mTarget = fbo;
    const LessonStep& step = mLesson.steps[static_cast<size_t>(mStep)];
    const std::string& chart = step.chart;
    // The step's focus composes the frame (a chart step in presentation mode gives the chart the
    // inspector's room too; a neighbourhood step gives it the inspector).
    InspectorLayout layout = stepLayout();
    clearInspectorPanels(fbo, layout);
    blitSceneOrChart(fbo, layout);
    glm::ivec2 frame = mLayout.frameSize;
    InspectorModel m = model();
    FramePlan plan = planFrame(layout, m);
    mTextPages = plan.textPages;
    if (mTextPage >= mTextPages) {
        // A smaller type or frame may leave fewer pages: show the last.
        mTextPage = mTextPages - 1;
        m.textPage = mTextPage;
        plan = planFrame(layout, m);
    }
    mBoxes = plan.boxes;
    mDrawnTexels = plan.drawnTexels;
    mDrawnFetches = plan.drawnFetches;
    mFormulaWhole = plan.formulaWhole;
    mSceneTexels = plan.sceneTexels;
    // blitChart above placed them with the chart it drew or kept.
    if (!chart.empty()) mBoxes.insert(mBoxes.end(), mChartBoxes.begin(), mChartBoxes.end());
    bindFramebuffer(fbo);
    mCanvas.begin(frame);
    drawPlan(mCanvas, plan.base);
    if (chart.empty()) drawFrozenCascades(layout.scene);
    mCanvas.flush();
    blitThumbnail(layout);
    bindFramebuffer(fbo);
    mCanvas.begin(frame);
    drawPlan(mCanvas, plan.top);
    // (The heat map is drawn over a full-size scene only, not an inset.)
    bool heat = mHeatmap && chart.empty() && !layout.sceneInset;
    if (heat) drawHeatLegend();
    if (mFlicker && chart.empty()) drawFlicker(layout);
    mCanvas.flush();
    bindFramebuffer(0);
    if (!heat) mHeatValues.clear();
}

void Session::blitSceneOrChart(GLuint fbo, const InspectorLayout& layout) {
    const std::string& chart = mLesson.steps[static_cast<size_t>(mStep)].chart;
    // The scene goes top-left. GL rows count from the bottom, so its top edge is frame height.
    glm::ivec2 frame = mLayout.frameSize;
    glm::ivec2 scene(mLayout.scene.size());
    if (chart.empty() && layout.sceneInset) {
        // Rendered at the full scene size, drawn scaled into the inset (filtered: a nearest
        // downscale would alias the very edges the step is about).
        const Rect& r = layout.scene;
        int x0 = static_cast<int>(r.x), x1 = static_cast<int>(r.right());
        int top = frame.y - static_cast<int>(r.y), bottom = frame.y - static_cast<int>(r.bottom());
        blitColour(mRenderer->frameFramebuffer(), {0, 0, scene.x, scene.y}, fbo,
                   {x0, bottom, x1, top}, true);
    } else if (chart.empty()) {
        blitColour(mRenderer->frameFramebuffer(), {0, 0, scene.x, scene.y}, fbo,
                   {0, frame.y - scene.y, scene.x, frame.y});
        if (mHeatmap) blitHeatmap();
    } else {
        blitChart(layout);
    }
}

// The heat map replaces the scene on its receivers (each pixel the colour of its pixels per
// texel); elsewhere the scene stays. Computed once per rendered scene: moving the pixel reuses it.
void Session::blitHeatmap() {
    glm::ivec2 size(mLayout.scene.size());
    if (mHeatDirty || mHeat.width != size.x || mHeat.height != size.y) {
        mHeatValues = pixelsPerTexel(mRenderer->readLightSpace(), size, mRendered->mapSize);
        std::vector<uint8_t> rgba = mRenderer->readColour();
        for (size_t k = 0; k < mHeatValues.size(); ++k) {
            if (mHeatValues[k] <= 0.0f) continue;
            glm::vec3 c = aliasingHeatColour(mHeatValues[k]);
            for (int i = 0; i < 3; ++i) {
                rgba[k * 4 + i] = static_cast<uint8_t>(std::lround(c[i] * 255.0f));
            }
        }
        mHeat = createOffscreenTarget(size.x, size.y, {GL_RGBA8});
        uploadBottomUp(mHeat, size.x, size.y, rgba);
        mHeatDirty = false;
    }
    // Texture row 0 holds the image's bottom row (uploadBottomUp): a straight copy.
    int frameH = mLayout.frameSize.y;
    blitColour(mHeat.framebuffer.id(), {0, 0, size.x, size.y}, mTarget,
               {0, frameH - size.y, size.x, frameH});
}

// The legend in the scene's bottom-left corner: the colour ramp from 1/16 to 16 screen pixels
// per texel, and the median over the receivers.
void Session::drawHeatLegend() {
    const Rect& scene = mLayout.scene;
    float font = std::max(12.0f, std::round((mPresentation ? 18.0f : 14.0f) * mLayout.scale));
    std::vector<float> measured;
    for (float v : mHeatValues) {
        if (v > 0.0f) measured.push_back(v);
    }
    std::string title = "screen pixels per texel";
    if (!measured.empty()) {
        std::nth_element(measured.begin(), measured.begin() + measured.size() / 2, measured.end());
        char median[32];
        std::snprintf(median, sizeof median, ", median %.3g",
                      static_cast<double>(measured[measured.size() / 2]));
        title += median;
    }
    float pad = std::round(font * 0.6f);
    float lineH = std::round(font * 1.35f);
    float barH = std::round(font * 0.9f);
    float barW = std::max(std::round(font * 14.0f), measureText(FontFace::Sans, font, title).x);
    barW = std::min(barW, scene.w - 4.0f * pad);
    Rect box{scene.x + pad, 0.0f, barW + 2.0f * pad, 2.0f * pad + 2.0f * lineH + barH};
    box.y = scene.y + scene.h - pad - box.h;
    mCanvas.fillRect(box, {0.08f, 0.09f, 0.11f, 0.85f});
    TextStyle text{FontFace::Sans, font, {0.92f, 0.93f, 0.95f, 1.0f}};
    mCanvas.text({box.x + pad, box.y + pad}, title, text);
    float barY = box.y + pad + lineH;
    const int steps = 64;
    for (int i = 0; i < steps; ++i) {
        float x0 = std::round(box.x + pad + barW * i / steps);
        float x1 = std::round(box.x + pad + barW * (i + 1) / steps);
        float t = (i + 0.5f) / steps * 2.0f - 1.0f;  // log2 / range, -1 .. 1
        glm::vec3 c = aliasingHeatColour(std::exp2(t * ALIASING_HEAT_LOG2_RANGE));
        mCanvas.fillRect({x0, barY, x1 - x0, barH}, {c, 1.0f});
    }
    float labelY = barY + barH + std::round(font * 0.2f);
    mCanvas.text({box.x + pad, labelY}, "1/16", text);
    TextStyle centre = text;
    centre.align = TextAlign::Center;
    mCanvas.text({box.x + pad + barW / 2.0f, labelY}, "1", centre);
    TextStyle right = text;
    right.align = TextAlign::Right;
    mCanvas.text({box.x + pad + barW, labelY}, "16", right);
}

std::string Session::statusText() const {
    if (mLesson.steps.empty()) return settingsSummary(mSettings);
    return statusLine(
        mSettings, hiddenNumbers().refs,
        changedSettings(mLesson.steps[static_cast<size_t>(mStep)].settings, mSettings, mBaseLight),
        glm::ivec2(mLayout.scene.size()), mFrameTimeMs);
}

InspectorModel Session::model() const {
    glm::ivec2 scene(mLayout.scene.size());
    const std::string& chart = mLesson.steps[static_cast<size_t>(mStep)].chart;
    InspectorModel m;
    m.title = mLesson.title;
    for (const LessonStep& s : mLesson.steps) m.stepTitles.push_back(s.title);
    m.currentStep = mStep;
    m.stepText = stepText();
    m.pixel = mPixel;
    m.trace = mTrace;
    m.map = &mMap;
    m.lightSpace = &mLightSpace;
    m.lightSpaceOrigin = mLightSpaceOrigin;
    m.lightSpaceSize = mLightSpaceSize;
    m.sceneSize = scene;
    m.status = statusText();
    m.markers = mMarkers;
    m.interactive = mInteractive;
    m.singleFrame = mMotion.has_value() && !mInteractive;
    m.presentation = mPresentation;
    m.help = mHelp;
    m.showScene = chart.empty();
    m.grid = mGrid;
    m.textPage = mTextPage;
    m.highlightFetch = mLesson.steps[static_cast<size_t>(mStep)].highlightFetch - 1;
    m.focus = stepFocus(mLesson.steps[static_cast<size_t>(mStep)]);
    m.plays = mLesson.steps[static_cast<size_t>(mStep)].animate.has_value();
    fillPredictPanel(m);
    return m;
}

std::vector<uint8_t> Session::readFrame() const {
    return readPixelsRgba8(mFrame.framebuffer.id(), GL_COLOR_ATTACHMENT0, mFrame.width,
                           mFrame.height);
}

std::string Session::stepJson() const {
    // Every setting the step is made with, from the parameter table.
    Json settings = paramsJson(mSettings, ParamSet::All);
    FrameWords words = stepWords();
    Json j = {
        {"lesson", mLesson.name},
        {"title", mLesson.title},
        {"step", mStep + 1},
        {"step_title", mLesson.steps.empty() ? "" : mLesson.steps[mStep].title},
        {"text",
         drawnStepText(questionShown() && filledPredict() ? filledPredict()->ask : words.text)},
        {"words", wordsShownName(words.shown)},
        {"pixel", jsonPair(mPixel)},
        {"point", mPoint ? Json::array({jsonNumber(mPoint->posWs.x), jsonNumber(mPoint->posWs.y),
                                        jsonNumber(mPoint->posWs.z)})
                         : Json(nullptr)},
        {"scene_size", jsonPair(glm::ivec2(mLayout.scene.size()))},
        {"settings", settings},
        {"trace", mTrace ? traceJson(*mTrace) : Json(nullptr)},
        {"frame_size", jsonPair(mLayout.frameSize)},
        {"presentation", mPresentation},
        {"text_page", mTextPage + 1},
        {"text_pages", mTextPages},
        {"layout", layoutJson(mBoxes)}};
    // A question's frame and its answer's (docs/teaching.md, "Predict, then reveal"): the roles the
    // question does not draw.
    if (predictStep()) {
        Json masked = Json::array();
        for (const std::string& role : hiddenRoles(hiddenNumbers())) masked.push_back(role);
        j["predict"] = {{"phase", mRevealed ? "reveal" : "question"}, {"masked", masked}};
        // The question's choices; the answer only in the answer's frame.
        if (std::optional<FilledPredict> f = filledPredict(); f && !mRevealed) {
            j["predict"]["choices"] = f->choices;
        } else if (f) {
            j["predict"]["answer"] = f->answer;
            j["predict"]["answer_line"] = answerLine(*mLesson.steps[mStep].predict, *f, mTyped);
        }
    }
    if (!mLesson.steps.empty()) j["focus"] = focusName(stepFocus(mLesson.steps[mStep]));
    if (mMotion) j["motion"] = motionJson(*mMotion);
    if (mTrace) {
        j.update(
            drawnAndReadJson(*mTrace, mDrawnTexels, mDrawnFetches, mFormulaWhole, mSceneTexels));
        // Where the cells are on the frame (texelCellRect of this view and rect gives a cell).
        InspectorLayout layout = stepLayout();
        if (!layout.inspector.empty() && !mDrawnTexels.empty()) {
            InspectorModel m = model();
            j["drawn"]["cells"] =
                cellsJson(neighbourhoodView(layout, m), neighbourhoodArea(layout, m));
        }
    }
    return jsonDump(j);
}

}  // namespace pcf
