// frame_json.h: the parts of a step's JSON sidecar (Session::stepJson) that describe the frame:
// settings as the text prints them, the layout's boxes, and what the frame drew against what the
// trace read.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "kernel/trace.h"
#include "kernel/trace_json.h"
#include "overlay/inspector.h"

namespace pcf {

// The frame's layout (planFrame's boxes) as a JSON array.
Json layoutJson(const std::vector<LayoutBox>& boxes);
// {"drawn": {"texels", "fetches", "formula_whole", "scene_texels"}, "read": {"texels",
// "fetches"}}.
Json drawnAndReadJson(const Trace& tr, const std::vector<glm::ivec2>& texels,
                      const std::vector<int>& fetches, bool formulaWhole,
                      const std::vector<glm::ivec2>& sceneTexels);

// Where the cells are: {"origin": [i, j], "size": [w, h], "rect": [x, y, w, h]}.
Json cellsJson(const Neighbourhood& view, const Rect& rect);

}  // namespace pcf
