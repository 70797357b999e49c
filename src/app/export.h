// export.h: writing a lesson's frames, shared by `pcfscope export`, the main job and the
// viewer's E key.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/output_files.h"

namespace pcf {

struct ExportPlan {
    std::string dir;
    glm::ivec2 steps{1, 1};          // 1-based, inclusive
    std::vector<std::string> stems;  // DIR/LESSON-STEP, one per step, without extension
};

// Checks every output before anything is written and adds it to `outputs` (which creates the
// folder and takes the frames back if the export fails): throws UsageError if a file exists
// (unless the outputs were made with force) or the folder cannot be written.
ExportPlan planExport(OutputFiles& outputs, const std::string& dir, const std::string& lessonName,
                      glm::ivec2 steps);

// Renders and writes each planned step headless; progress and frames/s on stderr.
void exportFrames(const std::string& lessonPath, const ExportPlan& plan, glm::ivec2 size,
                  bool presentation, bool progress);

}  // namespace pcf
