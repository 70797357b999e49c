// predict.h: what a predict step's question hides (docs/teaching.md, "Predict, then reveal"). The
// answer is a placeholder (lesson/lesson_predict.h); each placeholder a question may ask for shows
// one kind of number in the frame, and asking for it hides those numbers, and the ones it follows
// from at a glance, until the reveal: a visibility hides the result and the bits (the depths and
// ref stay, to compare), a weight the weights, a fraction the fractions and the weights, a ref the
// refs and the bias amount, a count the fetch counts. The formula, which holds them all, is
// hidden with any of them (overlay/inspector.h: HiddenNumbers).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "lesson/lesson.h"
#include "overlay/inspector.h"

namespace pcf {

// The numbers a question whose answer is placeholder `name` (canonical: "tap[K].weight") hides;
// nullopt when the name is no number the lookup computes (a setting such as {kernel}, which the
// status line shows, or a position such as {uv.x}).
std::optional<HiddenNumbers> hiddenForAnswer(std::string_view name);

// The problem with a lesson's predict steps that needs these tables, or nullopt: an answer that
// cannot be asked for, or an ask that prints a number the answer hides. Blamed on the predict
// table's line by loadLessonChecked.
std::optional<std::string> predictStepProblem(const StepPredict& p);

}  // namespace pcf
