#include "app/viewer_answer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <exception>

#include "app/exercise.h"
#include "lesson/lesson_predict.h"

namespace pcf {

namespace {

constexpr size_t MAX_TYPED = 16;

// The character a key types into an answer, or 0.
char typedChar(int key) {
    if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return static_cast<char>('0' + key - GLFW_KEY_0);
    if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9) {
        return static_cast<char>('0' + key - GLFW_KEY_KP_0);
    }
    switch (key) {
        case GLFW_KEY_PERIOD:
        case GLFW_KEY_KP_DECIMAL:
            return '.';
        case GLFW_KEY_SLASH:
        case GLFW_KEY_KP_DIVIDE:
            return '/';
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT:
            return '-';
        default:
            return 0;
    }
}

}  // namespace

bool ViewerAnswers::press(Session& session, KeyPress k) {
    if (k.key == GLFW_KEY_N && k.mods == 0) {
        toggleExercise(session);
        return true;
    }
    if (k.key == GLFW_KEY_R && session.predictStep()) {
        if (session.revealed()) {
            session.setRevealed(false);
        } else {
            judge(session);
        }
        return true;
    }
    return session.questionShown() && type(session, k);
}

bool ViewerAnswers::type(Session& session, KeyPress k) {
    std::string typed = session.typed();
    if (k.key == GLFW_KEY_ENTER || k.key == GLFW_KEY_KP_ENTER) {
        judge(session);
        return true;
    }
    if (k.key == GLFW_KEY_BACKSPACE) {
        if (typed.empty()) return false;  // the usual Backspace: the previous step
        typed.pop_back();
        session.setTyped(typed);
        return true;
    }
    const StepPredict& p = *session.lesson().steps[static_cast<size_t>(session.step())].predict;
    int letter = k.key - GLFW_KEY_A;
    if (!p.choices.empty() && letter >= 0 && letter < static_cast<int>(p.choices.size())) {
        session.setTyped(std::string(1, choiceLetter(static_cast<size_t>(letter))));
        return true;
    }
    char c = typedChar(k.key);
    if (c == 0) return false;
    if (typed.size() < MAX_TYPED) session.setTyped(typed + c);
    return true;
}

void ViewerAnswers::judge(Session& session) {
    session.setRevealed(true);
    if (!mExercise || session.typed().empty() || mJudged.count(session.step())) return;
    std::optional<FilledPredict> f = session.filledPredict();
    if (!f) return;
    const StepPredict& p = *session.lesson().steps[static_cast<size_t>(session.step())].predict;
    PredictVerdict v = judgePrediction(p, *f, session.typed());
    if (!v.understood) return;  // not an answer: not counted, the line says so
    mJudged.insert(session.step());
    mRight += v.right ? 1 : 0;
    showScore(session);
}

void ViewerAnswers::showScore(Session& session) const {
    session.setTitle(mTitle + " (" + std::to_string(mRight) + " of " +
                     std::to_string(mJudged.size()) + " right)");
}

void ViewerAnswers::toggleExercise(Session& session) {
    mJudged.clear();
    mRight = 0;
    if (mExercise) {
        mExercise = false;
        session.setLesson(std::move(*mLesson));
        mLesson.reset();
        session.goToStep(mLessonStep);
        return;
    }
    try {
        Lesson items = makeExercise(session.lesson(), VIEWER_EXERCISE_ITEMS, mSeed++);
        mLesson = session.lesson();
        mLessonStep = session.step();
        mTitle = items.title;
        session.setLesson(std::move(items));
        mExercise = true;
        showScore(session);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "view: no exercise: %s\n", e.what());
    }
}

}  // namespace pcf
