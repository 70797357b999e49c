// lesson_step.h: what a lesson step's frame shows besides the scene: its focus (which panels the
// frame gives room to) and its chart (charts/step_chart.h) at the frame's type sizes, and the
// lesson read with every chart it shows checked.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "charts/step_chart.h"
#include "lesson/lesson.h"
#include "overlay/inspector.h"

namespace pcf {

// Parses a lesson and reads every bench.csv its steps chart, so that a broken chart is reported
// at its lesson line before anything is drawn. Throws InputError (file:line) or UsageError.
Lesson loadLessonChecked(const std::string& path);
// Throws UsageError "PATH: the lesson has no steps" when it has none (a command needs a step).
void requireSteps(const Lesson& lesson, const std::string& path);
// The checks loadLessonChecked makes once the file is parsed that need more than the lesson
// parser knows (a predict step's answer, a claim about motion on a step that moves, each step's
// chart and the chart facts its claims name), every problem appended to `problems`.
void checkLessonSteps(const Lesson& lesson, const std::string& path,
                      std::vector<InputError>& problems);
// Every problem of a lesson file, the parser's and checkLessonSteps's, in line order; empty: the
// file is good. `lesson check` reports them all (loadLessonChecked throws the first). `lesson`,
// when given, receives the lesson as far as it could be read (whole when there is no problem).
std::vector<InputError> lessonProblems(const std::string& path, Lesson* lesson = nullptr);

// A chart step's chart (LessonStep::chart, with its chart_highlight) at the frame's type floors.
// `presentation`: text at the projector's floors and only the dots the step names (and the
// Pareto front) labelled; otherwise at the normal frame's floors.
StepChart stepChart(const LessonStep& step, bool presentation);

// A chart step's chart as RGBA8 of `size`, rows top-down, as the frame shows it in the scene's
// place; `render --lesson L --step S` writes it. Needs a current OpenGL 4.5 context. Throws
// InputError for a bad chart file.
std::vector<uint8_t> drawStepChart(const LessonStep& step, glm::ivec2 size,
                                   bool presentation = false);
// The texts a chart step's chart draws in `layout`'s scene panel (as chartStepLayout places it),
// as layout boxes: ticks are numbers, dot and bar-group names and the legend labels, the rest
// text. The frame's layout lists them. Throws InputError for a bad chart file.
std::vector<LayoutBox> stepChartBoxes(const LessonStep& step, const InspectorLayout& layout);

// What a step is about (inspector.h: Focus): its `focus` key, else derived: a chart step's chart;
// a nearest or heat-map step's scene and texel (hard shadows and the heat map are seen on the
// scene); any other filter's neighbourhood and formula (its words walk through the texels it
// reads). A chart step's focus is its chart whatever the key says. The key's names are checked
// by loadLessonChecked.
Focus stepFocus(const LessonStep& step);

}  // namespace pcf
