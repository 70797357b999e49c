// session_predict.cpp: a predict step on screen (session.h): the question with the numbers its
// answer needs hidden, then the answer, both filled from the frame's own trace.
#include "app/predict.h"
#include "app/session.h"
#include "app/step_words.h"
#include "lesson/lesson_pick.h"

namespace pcf {

bool Session::predictStep() const {
    return !mLesson.steps.empty() && mLesson.steps[static_cast<size_t>(mStep)].predict.has_value();
}

void Session::setRevealed(bool on) {
    if (!predictStep()) return;
    if (on != mRevealed) mTextPage = 0;
    mRevealed = on;
}

std::optional<FilledPredict> Session::filledPredict() const {
    if (!predictStep() || !mTrace) return std::nullopt;
    StepContext ctx =
        makeStepContext(mSettings, mPixel, mPoint ? lightAngleDeg(mLesson.scene, *mPoint) : -1.0f);
    ctx.partVisibility = mPartVisibility;
    return fillPredict(*mLesson.steps[static_cast<size_t>(mStep)].predict, *mTrace, ctx);
}

HiddenNumbers Session::hiddenNumbers() const {
    if (!questionShown()) return {};
    const StepPredict& p = *mLesson.steps[static_cast<size_t>(mStep)].predict;
    // loadLessonChecked refused an answer the table does not know.
    return hiddenForAnswer(predictAnswerName(p)).value_or(HiddenNumbers{});
}

void Session::fillPredictPanel(InspectorModel& m) const {
    std::optional<FilledPredict> f = filledPredict();
    if (!f) return;
    const StepPredict& p = *mLesson.steps[static_cast<size_t>(mStep)].predict;
    PredictPanel& panel = m.predict;
    panel.on = true;
    panel.revealed = mRevealed;
    panel.ask = f->ask;
    panel.choices = f->choices;
    panel.typed = mTyped;
    panel.answer = answerLine(p, *f, mTyped);
    std::string how = p.choices.empty() ? "type a number" : "type a letter";
    panel.hint = mTypedAnswers ? how + " and Enter, or R to reveal the answer"
                               : "Predict first: the answer follows the question";
    m.hidden = hiddenNumbers();
}

}  // namespace pcf
