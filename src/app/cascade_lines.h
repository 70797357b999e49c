// cascade_lines.h: a frozen view's drawing in the scene (lesson key `freeze_cascades`, viewer key
// Y): each frozen cascade's light box and its split plane (scene/cascade_view.h
// cascadeFrameLines), projected through the camera the scene is now seen through and drawn over
// it in the cascade's colour (the same as --shading cascades: red, green, blue, yellow).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "draw/canvas.h"
#include "scene/camera.h"
#include "scene/cascade_view.h"

namespace pcf {

// The colour of cascade k's lines (k 0..3), as shaders/scene.frag tints the cascade.
Colour cascadeLineColour(int k);

// The lines as `view` sees them in a scene of sceneSize pixels, drawn into `sceneRect` of the
// canvas (scaled when the scene is shown as an inset), clipped to it: a split plane's edges
// thicker than a light box's. `scale` is the frame's type scale (1 at 720 rows).
void drawCascadeLines(Canvas& canvas, const Rect& sceneRect, glm::ivec2 sceneSize,
                      const Camera& view, const std::vector<CascadeLine>& lines, float scale);

// A 2D segment clipped to a rectangle (Liang and Barsky, "A New Concept and Method for Line
// Clipping", ACM TOG 1984): false when none of it is inside.
bool clipSegment(const Rect& r, glm::vec2& a, glm::vec2& b);

}  // namespace pcf
