// viewer_answer.h: the viewer's keys for questions (a predict step, an exercise item), kept apart
// from viewer.cpp's key table. On a question not yet revealed, digits, '.', '/', '-' and, with
// choices, the choices' letters type an answer (those keys do nothing else there), Backspace
// takes a character back, Enter judges it and reveals the answer, R reveals (and hides) it
// without one. N is the exercise mode: questions drawn from the lesson (app/exercise.h), each
// answer typed and scored, the score in the title; N again goes back to the lesson's step.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>

#include "app/live_keys.h"
#include "app/session.h"

namespace pcf {

// How many questions an exercise in the viewer asks.
constexpr int VIEWER_EXERCISE_ITEMS = 8;

class ViewerAnswers {
  public:
    // Returns whether the key was one of these (and was taken).
    bool press(Session& session, KeyPress k);
    bool exercising() const { return mExercise; }
    int answered() const { return static_cast<int>(mJudged.size()); }
    int right() const { return mRight; }

  private:
    bool type(Session& session, KeyPress k);
    void judge(Session& session);
    void toggleExercise(Session& session);
    void showScore(Session& session) const;

    bool mExercise = false;
    // The lesson the exercise was drawn from, as it was read (never read again), and its step.
    std::optional<Lesson> mLesson;
    int mLessonStep = 0;
    std::string mTitle;     // the exercise's title, before the score
    std::set<int> mJudged;  // the items answered (each scored once)
    int mRight = 0;
    std::uint64_t mSeed = 1;  // a new set of questions each time N is pressed
};

}  // namespace pcf
