// export.h: writing a lesson's frames, shared by `pcfscope export`, the main job and the
// viewer's E key.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "app/live_keys.h"
#include "app/output_files.h"
#include "lesson/compare_spec.h"
#include "lesson/lesson.h"

namespace pcf {

// A frame's file stem: "03-bilinear-lerp-step02" (steps counted from 1, two digits, so that
// names sort and never read as a range). The viewer's E key and `export` name frames alike.
std::string frameStem(const std::string& lessonName, int step);

struct ExportPlan {
    std::string dir;
    glm::ivec2 steps{1, 1};          // 1-based, inclusive
    std::vector<std::string> stems;  // DIR/LESSON-stepNN, one per step, without extension
    // `export --keys`: settings keys, X and clicks (app/live_keys.h) applied to every step
    // before it is written, as the viewer's keys change the step on screen.
    std::vector<ScriptedInput> keys;
    // Steps that are animations (`animate = {...}`) are also written as STEM.mp4 (planExtras
    // lists them); false: stills only (the main job).
    bool videos = false;
    // Per step: the split view written beside its frame as STEM-compare.png (+ .json), from the
    // step's `compare` or `export --compare`; empty: none (planExtras fills it).
    std::vector<CompareSpec> compares;
    bool magnify = false;  // every frame through the magnifier (magnifier.h)
    // The deck files made from the frames once they are written (deck/deck.h), "" for none:
    // `export --deck html|pdf` and `--handout pdf`.
    std::string htmlDeck, pdfDeck, handout;
};

// Checks every output before anything is written and adds it to `outputs` (which creates the
// folder and takes the frames back if the export fails): throws UsageError if a file exists
// (unless the outputs were made with force) or the folder cannot be written. A predict step's
// answer frame (STEM-reveal.*) is one of its outputs. Page files of these steps already in the
// folder (STEM-pageN.*, STEM-reveal-pageN.*) count as outputs too, so they are refused here.
ExportPlan planExport(OutputFiles& outputs, const std::string& dir, const Lesson& lesson,
                      glm::ivec2 steps);

// The frame the extras are made at (the stills' size and mode).
struct ExtrasFrame {
    glm::ivec2 size{0, 0};
    bool presentation = false;
};
// The extras beside the stills, checked and added to `outputs` as the stills are, before anything
// is written: the MP4 of each planned step that is an animation (sets plan.videos), and the split
// view of each step (plan.compares): `compare` (export --compare's KEY=V1,V2 text) for every
// step, else the step's own `compare`. Throws UsageError when the size cannot be an MP4 (odd
// sides) or hold the split, or a spec does not parse or a step's settings cannot take it.
void planExtras(OutputFiles& outputs, ExportPlan& plan, const Lesson& lesson,
                const ExtrasFrame& frame, const std::string& compare);

// Renders and writes each planned step headless; progress and frames/s on stderr. A step whose
// text pages at this size (inspector.h) also gets one frame per further page, STEM-page2.png
// (+ .json), added to `outputs` (checked like the rest; taken back on failure) when given. A
// predict step's frames are its question's (STEM, STEM-pageN), then its answer's (STEM-reveal,
// STEM-reveal-pageN).
// `outputs` is committed when every frame is written, before the summary line says so. The
// lesson is the one the command loaded and checked (loadLessonChecked), not read again.
void exportFrames(const Lesson& lesson, const ExportPlan& plan, glm::ivec2 size, bool presentation,
                  bool progress, OutputFiles* outputs = nullptr);

}  // namespace pcf
