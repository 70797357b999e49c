// flicker_trace.h: the flicker trace, a small time plot of the pinned point's visibility across
// an animation's sweep: one line per method (the current one and one for comparison), frame
// index along x, visibility 0..1 up. Under a creeping light a flickering filter draws a jagged
// line and a stable one a smooth one. Drawn into a corner of the scene by Session.
#pragma once

#include <string>
#include <vector>

#include "draw/canvas.h"
#include "draw/rect.h"
#include "overlay/inspector.h"

namespace pcf {

struct FlickerCurve {
    std::string label;          // "nearest  mean |dv| 0.031", said beside the line's colour
    std::vector<float> values;  // visibility per frame so far, in [0,1]
    Colour colour{1.0f, 1.0f, 1.0f, 1.0f};
};

struct FlickerTrace {
    std::string title;                 // "visibility at the pinned point, light grid creeping"
    int frameCount = 0;                // the whole sweep: the x axis is this long from the start
    std::vector<FlickerCurve> curves;  // the first is the method on screen
};

// The colours of the first and second curve (the method on screen, the comparison).
constexpr Colour FLICKER_MAIN_COLOUR{0.98f, 0.84f, 0.36f, 1.0f};
constexpr Colour FLICKER_COMPARE_COLOUR{0.45f, 0.80f, 0.98f, 1.0f};

// Where the trace goes over a scene of `scene` that has nothing else on it (`animate
// --scene-only`): its bottom-left corner, about 0.42 of its width (more where the title at textPx
// needs it) and 0.3 of its height.
Rect flickerTraceRect(const Rect& scene, float textPx);

// The height a trace of `curves` lines needs at `textPx`: the title, a label per curve and a
// plot three rows tall. What a lesson frame reserves for it (inspector.h: motionLayout).
float flickerTraceHeight(float textPx, int curves);

// Draws the trace into `box` (a dark panel, axes at 0 and 1, one polyline per curve, the title
// and the labels at `textPx`, elided where `box` is narrower). Frame k sits at
// x = left + k / (frameCount - 1) * width. Returns its texts as the layout lists them (panel
// "trace": "trace-title", "trace-label"), `shortened` where elided.
std::vector<LayoutBox> drawFlickerTrace(Canvas& canvas, const Rect& box, const FlickerTrace& trace,
                                        float textPx);

// The x, y in `box` of frame k's value v (the plot area is `box` less its text rows).
glm::vec2 flickerTracePoint(const Rect& plot, int frameCount, int k, float v);

}  // namespace pcf
