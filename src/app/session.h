// session.h: one lesson on screen: the scene rendered with the current step's settings, the
// picked pixel traced by the CPU kernel on the rendered map, and the whole teaching frame
// composed offscreen (scene + inspector). The viewer shows that frame in a window; the exporter
// writes it to a PNG. Same code, same pixels.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/lesson_step.h"
#include "app/step_view.h"
#include "app/step_words.h"
#include "draw/canvas.h"
#include "kernel/trace.h"
#include "kernel/trace_json.h"
#include "lesson/lesson.h"
#include "lesson/lesson_catalogue.h"
#include "lesson/lesson_pick.h"
#include "lesson/lesson_predict.h"
#include "measure/cascade_density.h"
#include "overlay/flicker_trace.h"
#include "overlay/inspector.h"
#include "render/gl_objects.h"
#include "render/render_settings.h"
#include "render/scene_renderer.h"

namespace pcf {

// The smallest frame the scene view and the inspector fit into side by side.
constexpr glm::ivec2 MIN_SESSION_SIZE{320, 180};
// A text page past any step's last: compose() shows the last page there is.
constexpr int LAST_TEXT_PAGE = 1 << 20;

// A frame of an animation (app/animation.h): what is swept and its value now, in words ("The sun
// sinks from 40 to 6 degrees above the horizon: now 23.4."), the state the sweep started from,
// and whether the sweep is the step's own `animate` (its motion claims, `flickers`, are about
// that one). On such a frame the step's words are checked against the frame (step_words.h).
struct FrameMotion {
    std::string swept;
    LessonSettings base;
    bool stepsOwn = false;
    // For the frame's JSON ("motion"): the sweep's name, this frame (from 1) of how many, and
    // the swept quantity's value now (animation.h: animationSweepValue).
    std::string sweep;
    int frame = 0;
    int frames = 0;
    double value = 0.0;
};
// {"sweep", "frame", "frames", "value", "words", "steps_own"}: a moving frame's JSON "motion".
Json motionJson(const FrameMotion& motion);

// The viewer's own hint on an animation step (never in an exported frame or video).
constexpr const char* PLAY_HINT = "Space plays this step; . and , show one frame more or less.";

class Session {
  public:
    // Needs a current OpenGL 4.5 context that outlives the session.
    Session(glm::ivec2 frameSize, bool presentation);

    // Loads a lesson (throws InputError) and goes to its first step.
    void loadLesson(const std::string& path);
    // Shows a lesson made in memory (an exercise's items: app/exercise.h), from its first step.
    void setLesson(Lesson lesson);
    const Lesson& lesson() const { return mLesson; }
    // The title the frame shows (an exercise's carries its score).
    void setTitle(std::string title) { mLesson.title = std::move(title); }

    // Steps: the step's settings and pixel replace the current ones.
    int step() const { return mStep; }
    int stepCount() const { return static_cast<int>(mLesson.steps.size()); }
    void goToStep(int step);

    // The state on screen, which the viewer's keys may change between steps.
    const LessonSettings& settings() const { return mSettings; }
    void setSettings(const LessonSettings& s);
    // Picked pixel in scene coordinates (top-left origin), clamped to the scene: the pixel that
    // shows the pinned scene point (lesson_pick.h). setPixel pins the point under a pixel (a
    // click, the arrow keys); the point, not the pixel, stays when the frame is resized.
    glm::ivec2 pixel() const { return mPixel; }
    void setPixel(glm::ivec2 scenePixel);
    // The pinned scene point; nullopt when the pick is on no surface.
    const std::optional<ScenePoint>& point() const { return mPoint; }
    // The camera's sub-pixel shift (ndc) that centres the pinned point on pixel().
    glm::vec2 jitter() const { return mJitter; }
    // Whether the frame shows the scene: a chart step shows its chart there instead (and in
    // presentation mode over the inspector's room too).
    bool sceneShown() const;
    // A click at a frame pixel (top-left origin): picks the scene pixel under it when the scene
    // is shown and the click is on it; returns whether it did. A click on a chart picks nothing.
    bool clickFrame(glm::vec2 framePoint);

    void setFrameSize(glm::ivec2 frameSize);
    glm::ivec2 frameSize() const { return mLayout.frameSize; }
    const InspectorLayout& layout() const { return mLayout; }
    // The layout the current step's frame is composed in (focusLayout of layout()).
    InspectorLayout stepLayout() const;
    bool presentation() const { return mPresentation; }
    void setPresentation(bool on);
    bool help() const { return mHelp; }
    void setHelp(bool on);
    // The texel grid drawn on the scene (G): starts from the lesson step's `grid` setting.
    bool grid() const { return mGrid; }
    void setGrid(bool on) { mGrid = on; }
    // The aliasing heat map over the scene (A; lesson key `heatmap`): each receiver pixel
    // coloured by its screen pixels per shadow-map texel (measure/stability.h, pixelsPerTexel,
    // aliasingHeatColour), with a legend. heatValues(): the values the last compose() drew,
    // scene pixels top-down, -1 where not measured; empty when the heat map is off.
    bool heatmap() const { return mHeatmap; }
    void setHeatmap(bool on) { mHeatmap = on; }
    // The marks drawn over the scene (X): the pick's ring and label and the texel grid; off, the
    // scene is seen as rendered (acne, stairs) with nothing on it. Stays as set across steps.
    bool markers() const { return mMarkers; }
    void setMarkers(bool on) { mMarkers = on; }
    const std::vector<float>& heatValues() const { return mHeatValues; }
    // Pages of the current step's text at this frame size (the last compose()'s count) and the
    // page shown. nextPage()/previousPage() move within the step's pages and return false at
    // its ends (then the viewer moves to the next or previous step).
    int textPages() const { return mTextPages; }
    int textPage() const { return mTextPage; }
    void setTextPage(int page) { mTextPage = std::max(0, page); }
    bool nextPage();
    bool previousPage();
    // A predict step (lesson.h: StepPredict) shows its question until it is revealed: the
    // numbers its answer needs hidden (app/predict.h), the question in the step panel. goToStep
    // starts every predict step unrevealed; nextPage() past the question's last page reveals it,
    // and previousPage() on the answer's first page goes back to the question's last.
    bool predictStep() const;
    bool questionShown() const { return predictStep() && !mRevealed; }
    bool revealed() const { return mRevealed; }
    void setRevealed(bool on);
    // What the viewer's keyboard typed as the answer: shown under the question, judged in the
    // reveal's answer line.
    const std::string& typed() const { return mTyped; }
    void setTyped(std::string text) { mTyped = std::move(text); }
    // The question's hint says how to answer: typing (the viewer) or the next page (frames).
    void setTypedAnswers(bool on) { mTypedAnswers = on; }
    // The question filled from the current trace; nullopt on a step without one or off the
    // receivers.
    std::optional<FilledPredict> filledPredict() const;
    // The numbers the frame hides now (none once revealed).
    HiddenNumbers hiddenNumbers() const;

    // The frame time the status line shows; negative: none (exports, screenshots).
    void setFrameTimeMs(double ms);
    // The window's frames (the viewer sets it): only they say which keys turn a page, restore a
    // step or play one ("next page (Right)", "H: keys"). Off (the default) for every frame that
    // is written: export, animate, the viewer's E and --screenshot.
    bool interactive() const { return mInteractive; }
    void setInteractive(bool on) { mInteractive = on; }

    // Renders what changed, traces the pixel and composes the frame offscreen.
    void compose();
    // The same frame composed into another framebuffer of the frame's size (0: the window's back
    // buffer). Every pixel is drawn, whatever the target held. The viewer draws its window so:
    // a copy of the offscreen frame into the window's rows-top-down buffer is a shader pass over
    // every pixel on llvmpipe (about 7 ms at 1600 x 900), a third of a moved pixel's frame.
    void composeInto(GLuint framebuffer);
    // Makes the next compose() render the scene again (frame-time measurements).
    void invalidateScene() { mSceneDirty = true; }
    GLuint frameFramebuffer() const { return mFrame.framebuffer.id(); }
    std::vector<uint8_t> readFrame() const;  // RGBA8, rows top-down

    const std::optional<Trace>& trace() const { return mTrace; }
    // The shadow map the last compose() traced on.
    const ShadowMap& shadowMap() const { return mMap; }
    // The current step's text with its placeholders filled from the trace, or what the frame
    // shows in its place (step_words.h: a note, or a caption where a claim fails on this frame).
    std::string stepText() const;
    FrameWords stepWords() const;
    // The step as JSON: lesson, step, title, text, pixel, settings, the trace object, and the
    // layout of the last composed frame (every box drawn: inspector.h LayoutBox).
    std::string stepJson() const;
    // The status line's words: the settings, what the keys changed from the step's, the scene's
    // size and the frame time.
    std::string statusText() const;
    // The boxes the last compose() drew (the JSON sidecar's `layout`), the flicker trace's too.
    const std::vector<LayoutBox>& boxes() const { return mBoxes; }
    // The model the last compose() drew (for layout checks at other sizes without rendering).
    InspectorModel model() const;

    // Motion (app/animation.h drives these between frames; session_motion.cpp). The lesson's
    // scene with its light or camera moved: the next compose() renders it.
    const Scene& scene() const { return mLesson.scene; }
    void setLight(const Light& light);
    void setCamera(const Camera& camera);
    // The shadow map's fit (light clip from world) instead of lessonShadowFit's, or nullopt for
    // the lesson's own: an animation creeps the light's texel grid exactly as `stability` does.
    void setShadowFit(const std::optional<glm::mat4>& shadowClipFromWorld);
    const std::optional<glm::mat4>& shadowFit() const { return mShadowFit; }
    // The camera the cascades are fitted to when it is not the one the scene is seen through: a
    // `magnify` step's or a frozen view's (the lesson's own camera); nullopt: the scene's.
    std::optional<Camera> cascadeCamera() const;
    // The fit the next compose() renders the map with: shadowFit(), else the lesson's.
    glm::mat4 renderedShadowFit() const;
    // Pins this scene point (a split view's parts pin their main view's point; the magnifier
    // keeps its point when it moves the camera): the pixel and jitter follow for this frame.
    void pinPoint(const ScenePoint& point);
    // An animation's frame (FrameMotion), or nullopt for a still: the step's words are then
    // checked on every frame. Animation sets it per frame and clears it when it restores.
    void setMotion(std::optional<FrameMotion> motion) { mMotion = std::move(motion); }
    const std::optional<FrameMotion>& motion() const { return mMotion; }
    // The scene alone over the whole frame (no inspector, steps or status): `animate --scene-only`.
    void setSceneOnly(bool on);
    bool sceneOnly() const { return mSceneOnly; }
    // The flicker trace (overlay/flicker_trace.h), drawn at the bottom of the inspector's column
    // (stepLayout: motionLayout), or in the scene's bottom-left corner when the scene is alone:
    // the source is called by each compose() after the frame's lookup is traced (so the trace
    // can hold this frame's value: trace(), visibilityWith()); empty: none.
    void setFlickerTrace(std::function<FlickerTrace()> source) { mFlicker = std::move(source); }
    // What another method (and kernel) returns for the very lookup the last compose() traced: the
    // same map, uv, depth and bias; nullopt when the pixel is not on a receiver.
    std::optional<float> visibilityWith(int method, int kernel) const;

  private:
    void composeSceneOnly(GLuint fbo);
    // The flicker trace in the layout's trace room, or over the scene's corner (scene alone).
    void drawFlicker(const InspectorLayout& layout);
    void renderScene();
    // Derives the pixel and the camera's jitter that show mPoint in this frame.
    void repick();
    // A step with `magnify` (lesson.h) is seen through the magnifier's close-up on its point
    // (magnifier.h: stepCamera) at this scene size; leaving it brings back the lesson's camera.
    // Steps without it leave the camera alone (an animation's sweep, the viewer's Z).
    void applyStepCamera();
    void traceAtPixel();
    // A cascaded map's texel density per cascade on the frame just rendered (mCascadeDensity,
    // measure/cascade_density.h); cleared for a map of one layer.
    void measureCascades(const RenderSettings& r);
    // A frozen view's light boxes and split planes over the scene (app/cascade_lines.h).
    void drawFrozenCascades(const Rect& sceneRect);
    void tracePartsOfText();
    void blitThumbnail(const InspectorLayout& layout);
    // A step with a chart shows it where the scene goes (lesson.h: LessonStep::chart).
    void blitChart(const InspectorLayout& layout);
    void blitHeatmap();
    // The scene (full size, or scaled into the layout's inset) or the step's chart into `fbo`.
    void blitSceneOrChart(GLuint fbo, const InspectorLayout& layout);
    void drawHeatLegend();

    Lesson mLesson;
    int mStep = 0;
    LessonSettings mSettings;
    // True while the settings differ from the current step's (apart from the pixel): the step
    // text then says which state its words were written for.
    bool mStepEdited = false;
    glm::ivec2 mPixel{0, 0};
    std::optional<ScenePoint> mPoint;  // the pinned scene point
    glm::vec2 mJitter{0.0f};           // the camera's sub-pixel shift that centres it on mPixel
    bool mPickInFrame = false;         // mPoint shows in the frame (at mPixel)
    bool mPresentation = false;
    bool mHelp = false;
    bool mGrid = true;
    bool mHeatmap = false;
    bool mMarkers = true;
    bool mInteractive = false;
    std::optional<FrameMotion> mMotion;
    // The lesson scene's own light, and the sun (sunTilt, sunTurn) the light now has: the keys
    // move the sun from the lesson's light (setSettings).
    Light mBaseLight;
    glm::vec2 mLitSun{0.0f};
    Camera mLessonCamera;  // the lesson scene's own camera, which `magnify` moves from
    // The camera is a `magnify` step's close-up or a frozen view's (magnifier.h stepCamera).
    bool mStepMagnified = false;
    bool mHeatDirty = true;
    std::vector<float> mHeatValues;
    OffscreenTarget mHeat;  // the heat map, rows top-down, blitted over the scene
    int mTextPage = 0;
    int mTextPages = 1;
    bool mRevealed = false;  // a predict step's answer is shown
    std::string mTyped;      // the answer typed in the viewer
    bool mTypedAnswers = false;
    // The step panel's question or answer (session_predict.cpp).
    void fillPredictPanel(InspectorModel& m) const;
    std::vector<LayoutBox> mBoxes;
    std::vector<glm::ivec2> mDrawnTexels;  // what the last composed frame drew (FramePlan)
    std::vector<int> mDrawnFetches;
    bool mFormulaWhole = false;
    std::vector<glm::ivec2> mSceneTexels;  // the texels tinted on the scene (FramePlan)
    double mFrameTimeMs = -1.0;
    InspectorLayout mLayout;

    std::unique_ptr<SceneRenderer> mRenderer;
    std::unique_ptr<SceneRenderer> mPartRenderer;  // the split view's maps for the step's words
    std::vector<float> mPartVisibility;            // part[K].visibility (tracePartsOfText)
    bool mSceneDirty = true;
    std::optional<RenderSettings> mRendered;
    ShadowMap mMap;
    std::vector<CascadeDensity> mCascadeDensity;  // per cascade (measureCascades)
    int mThumbnailLayer = 0;                      // the layer the thumbnail shows
    std::vector<float> mLightSpace;  // a region around the pixel (gridRadius), rows top-down
    glm::ivec2 mLightSpaceOrigin{0, 0};
    glm::ivec2 mLightSpaceSize{0, 0};
    std::optional<Trace> mTrace;
    // The last traced lookup and its inputs (visibilityWith).
    std::optional<PixelLookup> mLookup;
    bool mSceneOnly = false;
    std::optional<glm::mat4> mShadowFit;
    std::function<FlickerTrace()> mFlicker;

    Canvas mCanvas;
    OffscreenTarget mFrame;
    GLuint mTarget = 0;          // what the current compose draws into (mFrame's, or the window's)
    OffscreenTarget mThumbnail;  // the map's thumbnail, rows top-down, blitted into the frame
    OffscreenTarget mChart;      // the step's chart, rows top-down
    std::string mChartKey;       // path, rect and highlight the chart was drawn for
    std::vector<LayoutBox> mChartBoxes;  // its texts as the layout lists them, for mChartKey
    bool mThumbnailDirty = true;
};

}  // namespace pcf
