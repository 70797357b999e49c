// step_player.cpp: an animation step played in the viewer (step_player.h).
#include "app/step_player.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

namespace pcf {

bool StepPlayer::press(KeyPress k) {
    if (!mAnimation) return false;
    switch (k.key) {
        case GLFW_KEY_SPACE:
            mPlaying = !mPlaying;
            mNextDue = 0.0;  // the first tick sets the clock
            return true;
        case GLFW_KEY_PERIOD:
            // Past the last frame it starts over; the trace's curve with it.
            mPlaying = false;
            show((mFrame + 1) % mOptions.frames);
            return true;
        case GLFW_KEY_COMMA:
            // Frames are shown in order, so the trace's curve is the frames so far: no wrap.
            mPlaying = false;
            show(std::max(0, mFrame - 1));
            return true;
        default:
            return false;
    }
}

void StepPlayer::beforeChange() {
    if (mAnimation) mAnimation->restore();
}

void StepPlayer::afterChange() {
    const Lesson& lesson = mSession.lesson();
    int step = mSession.step();
    bool animated = step >= 0 && step < mSession.stepCount() &&
                    lesson.steps[static_cast<size_t>(step)].animate.has_value();
    if (!animated) {
        mAnimation.reset();
        mPlaying = false;
        mStep = -1;
        return;
    }
    const LessonStep& s = lesson.steps[static_cast<size_t>(step)];
    // A new step starts paused; a key on this one starts it again from the first frame (the
    // flicker trace's curve holds the frames in order from there), playing on if it played.
    if (step != mStep) mPlaying = false;
    mStep = step;
    mFrame = 0;
    // Checked when the lesson was loaded (loadLessonChecked), so this does not throw.
    mOptions = stepAnimationOptions(s);
    mFps = s.animate->fps;
    // The frames start from the state now on screen (a key may have changed it).
    mAnimation = std::make_unique<Animation>(mSession, mOptions);
    show(mFrame);
}

std::optional<double> StepPlayer::tick(double seconds) {
    if (!mAnimation || !mPlaying) return std::nullopt;
    double period = 1.0 / mFps;
    if (mNextDue == 0.0) mNextDue = seconds + period;
    if (seconds >= mNextDue) {
        show((mFrame + 1) % mOptions.frames);
        mNextDue += period;
        // Frames slower than the rate are not made up for by hurrying: the clock restarts.
        if (mNextDue < seconds) mNextDue = seconds + period;
    }
    return std::max(0.0, mNextDue - seconds);
}

void StepPlayer::show(int frame) {
    mFrame = frame;
    mAnimation->showFrame(frame);
}

}  // namespace pcf
