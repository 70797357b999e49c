// viewer.h: `pcfscope view`: the lesson in a GLFW window, driven by keys and clicks; keys can be
// replayed from the command line (--keys) and the frame written (--screenshot) for scripts.
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "app/live_keys.h"  // KeyPress, parseKeyName: the --keys names

namespace pcf {

struct ViewerOptions {
    std::string lesson;  // resolved path
    glm::ivec2 windowSize{1600, 900};
    std::string keys;        // "right right m e click:400,300": key names and clicks (live_keys.h)
    std::string screenshot;  // write the frame after the keys, then quit
    bool presentation = false;
    bool force = false;   // the screenshot may overwrite
    int benchFrames = 0;  // > 0: time this many frames, print the medians, quit
};

// Runs the window until Esc (or until the screenshot is written). Throws std::runtime_error
// "no display: ..." when no window can be opened.
int runViewer(const ViewerOptions& options);

}  // namespace pcf
