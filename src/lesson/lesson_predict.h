// lesson_predict.h: a predict step's question (lesson.h: StepPredict): its texts checked when
// the lesson is read, filled from the step's trace when it is shown, and a typed answer judged.
// The answer is never typed by the author: it is a placeholder, so it is what the kernel
// computed for the frame on screen.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/trace.h"
#include "lesson/lesson.h"
#include "lesson/lesson_text.h"

namespace pcf {

// What is wrong with a predict table as written, or nullopt: an answer that is not one number
// placeholder, an unknown or out-of-range placeholder in ask, choices or answer (taps, fetches,
// parts as checkPlaceholders takes them), a choice list of 1 or more than MAX_PREDICT_CHOICES,
// choices with a tolerance, or a number answer without a tolerance (toleranceGiven) or with one
// that is negative or not finite.
std::optional<std::string> predictProblem(const StepPredict& p, bool toleranceGiven, int taps,
                                          int fetches, int parts);

// A placeholder's name with its indices written as placeholderNames() lists them and its *F and
// :N dropped: "tap[2].weight*9:2" -> "tap[K].weight", "weight[1,0]" -> "weight[I,J]".
std::string canonicalPlaceholder(std::string_view inside);
// The canonical names of the placeholders in `text`, in order ({{ and }} are no placeholders).
std::vector<std::string> placeholdersIn(std::string_view text);
// The answer's canonical name ("visibility").
std::string predictAnswerName(const StepPredict& p);

// The question for one trace: its texts filled, the answer as the words print it and as a
// number, and which choice it is.
struct FilledPredict {
    std::string ask;
    std::vector<std::string> choices;
    std::string answer;
    std::optional<double> value;  // nullopt: the answer's index is past the trace's reads
    int choice = -1;              // the choice the answer is; -1: none (or no choices)
};
FilledPredict fillPredict(const StepPredict& p, const Trace& trace, const StepContext& ctx);

// With choices, the answer must be exactly one of them (compared as printed): what `lesson
// check` reports when it is none or several, or nullopt.
std::optional<std::string> predictChoiceProblem(const StepPredict& p, const FilledPredict& f);

// A typed answer judged: a choice's letter (A, b, ...) or its text, or a number ("0.75", "3/4",
// "12/16") within the step's tolerance of the answer.
struct PredictVerdict {
    bool understood = false;  // the typed text is a letter, a choice or a number
    bool right = false;
};
PredictVerdict judgePrediction(const StepPredict& p, const FilledPredict& f,
                               std::string_view typed);

// The line the reveal shows above the step's words: "Answer: B, 0.02." or "Answer: 0.8125
// (within 0.0625 counts).", then, when something was typed, what it was and whether it is right.
std::string answerLine(const StepPredict& p, const FilledPredict& f, std::string_view typed = "");

// A choice's letter: A, B, ...
inline char choiceLetter(size_t k) { return static_cast<char>('A' + k); }

}  // namespace pcf
