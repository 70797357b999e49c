// chart_axes.h: what the stability charts (stability_chart.h) and the speed chart (speed_chart.h)
// share: the ink and grid colours, round tick steps and their labels (chartTickText, from
// measure/number_text.h), and the offscreen target a chart is painted into and read back from.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "draw/canvas.h"
#include "draw/rect.h"
#include "measure/number_text.h"
#include "render/frame_ops.h"
#include "render/gl_objects.h"

namespace pcf {

inline const Colour CHART_WHITE{1.0f, 1.0f, 1.0f, 1.0f};        // the background
inline const Colour CHART_INK{0.13f, 0.13f, 0.15f, 1.0f};       // titles, labels, legend
inline const Colour CHART_SOFT_INK{0.35f, 0.35f, 0.38f, 1.0f};  // subtitles, ticks, frames
inline const Colour CHART_GRID{0.88f, 0.88f, 0.9f, 1.0f};       // grid lines

// Pixels a legend's mark keeps clear of any text: its box in the layout lists ("chart-swatch")
// is the mark grown by this on every side, so a ring that touches its words counts as on them.
constexpr float CHART_MARK_CLEARANCE = 2.0f;

// The stand-alone charts (the PNGs `stability` and `bench` write) draw no text smaller than this:
// readable when the PNG is projected or printed at its own size (issue 19: 11 px was not).
constexpr float STANDALONE_CHART_MIN_PX = 14.0f;

// What a chart says of the renderer it was measured on: "rendered on NAME" (GL_RENDERER), and for
// Mesa's llvmpipe, a CPU rasteriser, " (LLVMPIPE_NOTE)". An empty name: RENDERER_UNKNOWN.
inline constexpr std::string_view LLVMPIPE_NOTE =
    "llvmpipe: a CPU rasteriser; a GPU's times, and their ratios, differ";
inline constexpr std::string_view RENDERER_UNKNOWN =
    "renderer not recorded (a file older than its gl_renderer column)";
std::string chartRendererLine(const std::string& glRenderer);

// A round step (1, 2 or 5 times a power of ten) at or above `rough` (> 0).
double chartNiceStep(double rough);

// Draws into a white offscreen target of `size` and reads it back (RGBA8, rows top-down as
// readPixelsRgba8 returns them); `paint` records the commands on a Canvas. The caller's framebuffer
// bindings are restored.
template <class Paint>
std::vector<uint8_t> drawChartOffscreen(glm::ivec2 size, Paint&& paint) {
    FramebufferBindingsKept kept;
    OffscreenTarget target = createOffscreenTarget(size.x, size.y, {GL_RGBA8});
    clearColour(target.framebuffer.id(), CHART_WHITE);
    bindFramebuffer(target.framebuffer.id());
    {
        Canvas c;
        c.begin(size);
        paint(c);
        c.flush();
    }
    return readPixelsRgba8(target.framebuffer.id(), GL_COLOR_ATTACHMENT0, size.x, size.y);
}

}  // namespace pcf
