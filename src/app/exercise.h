// exercise.h: questions drawn from a lesson for a tutorial (`pcfscope exercise`, the viewer's N):
// each item a point of the lesson's scene on a shadow's edge, a method and a kernel the lesson
// uses, and the question "what visibility does it give here?", asked as a predict step (lesson.h:
// StepPredict) whose answer is the trace's visibility, to within 1/16. The items are a lesson of
// their own, so the session, the frames and the answer key show them as any predict step.
#pragma once

#include <cstdint>
#include <string>

#include "lesson/lesson.h"

namespace pcf {

// How far a typed visibility may be from the trace's and count as right.
constexpr double EXERCISE_TOLERANCE = 1.0 / 16.0;
constexpr int MAX_EXERCISE_ITEMS = 32;  // MAX_LESSON_STEPS

// `count` items (1..MAX_EXERCISE_ITEMS) drawn from `lesson` with `seed`: the same seed gives the
// same items on the same build and driver. Each item: one of the lesson's steps' states (not a
// chart step's), with a method the lesson uses and, for a method with a kernel, a kernel size the
// lesson uses with it (3 when none), and a point on the ground where that filter's visibility
// lies between 0.1 and 0.9 (the edge band). Renders the shadow maps: needs a current
// OpenGL 4.5 context. Throws UsageError when the lesson has no step with a scene, or a method
// finds no edge in view.
Lesson makeExercise(const Lesson& lesson, int count, std::uint64_t seed);

}  // namespace pcf
