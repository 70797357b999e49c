// export.h: writing a lesson's frames, shared by `pcfscope export`, the main job and the
// viewer's E key.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace pcf {

struct ExportPlan {
    std::string dir;
    glm::ivec2 steps{1, 1};          // 1-based, inclusive
    std::vector<std::string> stems;  // DIR/LESSON-STEP, one per step, without extension
};

// Checks every output before anything is written: throws UsageError if a file exists (unless
// force) or dir is not a directory.
ExportPlan planExport(const std::string& dir, const std::string& lessonName, glm::ivec2 steps,
                      bool force);

// Renders and writes each planned step headless; progress and frames/s on stderr.
void exportFrames(const std::string& lessonPath, const ExportPlan& plan, glm::ivec2 size,
                  bool presentation, bool progress);

// Writes text to path through a temporary file and a rename (no half-written file).
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace pcf
