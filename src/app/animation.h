// animation.h: a sweep played as a sequence of ordinary frames (docs/user-guide.md, "animate"): the
// lesson step's frame (or the scene alone) with one quantity swept from frame to frame, and a
// flicker trace of the pinned point's visibility. `pcfscope animate` encodes the frames to MP4
// and GIF (video/video_writer.h) and numbered PNGs. Every frame is an ordinary Session frame, so
// the same settings give the same bytes run to run.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/compare_view.h"
#include "app/session.h"
#include "lesson/lesson_animation.h"

namespace pcf {

// The sweeps and their names are the lesson's (lesson/lesson_animation.h: AnimationSweep).
struct AnimationOptions {
    AnimationSweep sweep = AnimationSweep::Light;
    int frames = 120;
    bool snap = false;       // light: snap the creeping grid to whole texels
    bool flicker = true;     // draw the flicker trace
    int compareMethod = -1;  // the trace's second curve; -1: none
    int compareKernel = 3;
    // sun, bias, map-size: the swept quantity's first and last values instead of the sweep's own
    // (a lesson step's `animate = { from = 90, to = 20 }`).
    std::optional<double> from;
    std::optional<double> to;
};

// The flicker trace's second method when none is named: nearest (the hard edge every filter is
// measured against), or pcf-gather when the step's method is nearest.
int defaultCompareMethod(int stepMethod);

// A lesson step's `animate` (lesson/lesson.h: StepAnimation, checked by the lesson parser) as
// options, its trace comparing with defaultCompareMethod. The step must have one.
AnimationOptions stepAnimationOptions(const LessonStep& step);

// The swept quantity at frame k of `frames`: texels of slide, pixels of slide, degrees of
// elevation, constant bias or map texels. Its unit in words: animationSweepUnit.
double animationSweepValue(const AnimationOptions& o, int k);
// Frame k in plain words, the caption's first sentence: what is swept, between which values, and
// its value now ("Frame 30 of 60. The sun sinks from 40 to 6 degrees above the horizon; now it
// stands 23.4 degrees high.").
std::string animationSweepWords(const AnimationOptions& o, int k);
// Whether `o` plays the step's own `animate` (the same sweep, range, frames and snap).
bool isStepsOwnAnimation(const LessonStep& step, const AnimationOptions& o);

// A lesson step's flicker trace, the curves of its `animate` (stepAnimationOptions): the pinned
// point's visibility at each frame of the sweep under the step's method (`main`) and under the
// comparison (`compare`), from the frames the viewer and export compose (Animation), the scene
// alone at `size`: `lesson` on step `step` (from 0) with settings `s` (the step's own, or the
// state after a key). The point belongs to the scene, so a light, sun, bias or map-size sweep
// gives the same curves at every frame size (a camera sweep moves the point: its curves are those
// of `size`). Empty for a step without `animate`. Needs a current OpenGL 4.5 context.
struct FlickerCurves {
    std::vector<float> main;
    std::vector<float> compare;
};
FlickerCurves stepFlickerCurves(const Lesson& lesson, int step, const LessonSettings& s,
                                glm::ivec2 size = MIN_SESSION_SIZE);

// Drives a Session through a sweep. Construct after the session has its lesson, step and frame
// size: the step's settings, light, camera and fit are the sweep's starting point.
class Animation {
  public:
    Animation(Session& session, const AnimationOptions& options);
    // A split view (compare_view.h): the sweep moves `session` (never composed) and every frame
    // is the split view following it; the flicker trace has one curve per part.
    Animation(Session& session, const AnimationOptions& options, CompareView& compare);
    // Puts frame k's state on the session (the frame's motion too, Session::setMotion, so the
    // step's words are checked on it), composes it and records the pinned point's
    // visibility (and the comparison's) for the flicker trace drawn in this and later frames.
    void composeFrame(int k);
    // The pinned point's visibility per composed frame (the curve of the flicker trace): the
    // method on screen, and the comparison (empty without one). -1 where the point is not on a
    // receiver in that frame.
    const std::vector<float>& curve() const { return mCurve; }
    const std::vector<float>& compareCurve() const { return mCompare; }
    // Puts frame k's state on the session without composing (the viewer composes into its
    // window): the flicker trace then records this frame's value at the session's next compose.
    void showFrame(int k);
    // Puts the session back as it was before the first frame: the step's settings, the light,
    // the camera and the lesson's own fit; no flicker trace.
    void restore();
    // With a split view: part i's curve (part 0's is curve(), part 1's compareCurve()).
    const std::vector<float>& partCurve(int part) const {
        return mParts[static_cast<size_t>(part)];
    }

  private:
    void apply(int k);
    void turnCamera(float degrees);
    // The pinned point's visibility (and the comparison's) from the session's last trace.
    void record();
    FlickerTrace flickerTrace() const;
    void composeCompare();

    Session& mSession;
    AnimationOptions mOptions;
    LessonSettings mBase;
    bool mStepsOwn = false;  // the step's own `animate` (its motion claims are about it)
    Scene mScene;
    std::optional<ScenePoint> mPivot;  // the turn sweep's: the point pinned before the first frame
    std::vector<float> mCurve;
    std::vector<float> mCompare;
    CompareView* mSplit = nullptr;
    std::vector<std::vector<float>> mParts;
};

}  // namespace pcf
