// step_player.h: a lesson step that is an animation (lesson.h: `animate = {...}`) played in the
// viewer. On such a step Space plays and pauses (elsewhere it turns the page), `.` and `,` show
// the next and the previous frame (`.` past the last starts over); Left and Right still move
// between steps, as a slide clicker sends them. The frames are app/animation.h's, as `export`
// writes them to MP4; leaving the step puts the session's light, camera and fit back.
#pragma once

#include <memory>
#include <optional>

#include "app/animation.h"
#include "app/live_keys.h"

namespace pcf {

class StepPlayer {
  public:
    explicit StepPlayer(Session& session) : mSession(session) {}

    // Whether the current step is an animation the player shows, and whether it plays.
    bool active() const { return mAnimation != nullptr; }
    bool playing() const { return mPlaying; }
    int frame() const { return mFrame; }

    // Space, `.` and `,` on an animation step; returns whether `k` was one of them.
    bool press(KeyPress k);
    // Around a key that may change the step or its settings: before, the session is put back
    // as the step left it; after, an animation step starts again from its first frame on the
    // new state (a new step paused, the same one playing on if it played).
    void beforeChange();
    void afterChange();
    // While playing: moves to the frame due at `seconds` (a steady clock), looping at the end.
    // Returns the seconds until the next frame is due, or nullopt when not playing.
    std::optional<double> tick(double seconds);

  private:
    void show(int frame);

    Session& mSession;
    std::unique_ptr<Animation> mAnimation;
    AnimationOptions mOptions;
    int mStep = -1;  // the step mAnimation belongs to
    int mFrame = 0;
    int mFps = 12;
    bool mPlaying = false;
    double mNextDue = 0.0;  // when playing: the steady-clock second the next frame is due
};

}  // namespace pcf
