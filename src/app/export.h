// export.h: writing a lesson's frames, shared by `pcfscope export`, the main job and the
// viewer's E key.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "app/output_files.h"
#include "lesson/compare_spec.h"

namespace pcf {

// A frame's file stem: "03-bilinear-lerp-step02" (steps counted from 1, two digits, so that
// names sort and never read as a range). The viewer's E key and `export` name frames alike.
std::string frameStem(const std::string& lessonName, int step);

struct ExportPlan {
    std::string dir;
    glm::ivec2 steps{1, 1};          // 1-based, inclusive
    std::vector<std::string> stems;  // DIR/LESSON-stepNN, one per step, without extension
    // Per step: the split view written beside its frame as STEM-compare.png (+ .json), from the
    // step's `compare` or `export --compare`; empty: none (planCompares fills it).
    std::vector<CompareSpec> compares;
    bool magnify = false;  // every frame through the magnifier (magnifier.h)
};

// Checks every output before anything is written and adds it to `outputs` (which creates the
// folder and takes the frames back if the export fails): throws UsageError if a file exists
// (unless the outputs were made with force) or the folder cannot be written. Page files of these
// steps already in the folder (STEM-pageN.*) count as outputs too, so they are refused here.
ExportPlan planExport(OutputFiles& outputs, const std::string& dir, const std::string& lessonName,
                      glm::ivec2 steps);

// Fills plan.compares: `all` (export --compare) for every step, else each step's own `compare`;
// adds their files to `outputs`. Throws UsageError when a step's settings cannot take `all`.
struct Lesson;
void planCompares(OutputFiles& outputs, ExportPlan& plan, const Lesson& lesson,
                  const CompareSpec& all);

// Renders and writes each planned step headless; progress and frames/s on stderr. A step whose
// text pages at this size (inspector.h) also gets one frame per further page, STEM-page2.png
// (+ .json), added to `outputs` (checked like the rest; taken back on failure) when given.
// `outputs` is committed when every frame is written, before the summary line says so.
void exportFrames(const std::string& lessonPath, const ExportPlan& plan, glm::ivec2 size,
                  bool presentation, bool progress, OutputFiles* outputs = nullptr);

}  // namespace pcf
