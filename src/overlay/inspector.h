// inspector.h: the teaching frame: the rendered scene on the left with the picked pixel and the
// shadow-map texel grid projected around it, and on the right the inspector: the magnified texel
// neighbourhood (depth, comparison bit and weight per texel, the sub-texel point, the fetches),
// the formula with its numbers, the steps, a thumbnail of the map, and a status line. Drawn with
// Canvas only, so the window and an export give the same pixels.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "kernel/shadow_map.h"
#include "kernel/trace.h"
#include "overlay/canvas.h"
#include "overlay/rect.h"
#include "render/gl_objects.h"

namespace pcf {

// Where things go in a frame of a given size. The scene keeps 16:9 (the frame lessons pick their
// pixels in), top-left; the step text sits under it; the inspector fills the right.
struct InspectorLayout {
    glm::ivec2 frameSize{0, 0};
    Rect scene;      // the rendered scene, 16:9, whole pixels
    Rect steps;      // lesson title, step list and the current step's text
    Rect inspector;  // the neighbourhood, the formula, the thumbnail
    Rect status;     // one line along the bottom
    float scale = 1.0f;  // 1 at 1600 x 900; fonts and lines scale with it
};
InspectorLayout inspectorLayout(glm::ivec2 frameSize, bool presentation);

// Everything the frame shows; the caller fills it from the lesson, the renderer and the trace.
struct InspectorModel {
    std::string title;                    // lesson title (or "pcfscope")
    std::vector<std::string> stepTitles;  // all steps, in order
    int currentStep = 0;
    std::string stepText;                 // the current step's text, placeholders filled
    glm::ivec2 pixel{0, 0};               // picked pixel in scene coordinates (top-left origin)
    std::optional<Trace> trace;           // the picked pixel's lookup; none off the receivers
    const ShadowMap* map = nullptr;       // for the thumbnail
    // A region of the scene's light-space target (u, v, ref, mask per pixel, rows top-down)
    // around the pixel, for the texel grid drawn on the receiver. May be null.
    const std::vector<float>* lightSpace = nullptr;
    glm::ivec2 lightSpaceOrigin{0, 0};    // the region's top-left pixel in the scene
    glm::ivec2 lightSpaceSize{0, 0};      // the region's size
    glm::ivec2 sceneSize{0, 0};           // size of the rendered scene (== layout.scene size)
    std::string status;                   // method, kernel, bias, map, frame time
    bool presentation = false;            // large type, thick lines, high contrast
    bool help = false;                    // the key list over everything
    bool showScene = true;                // false: a chart fills the scene's place (no overlay)
};

// A frame is drawn in layers: the panels' backgrounds (clearInspectorPanels) and the scene's
// pixels blitted into layout.scene; then
// drawInspector (everything but the map thumbnail's pixels), flushed; then thumbnailImage blitted
// into thumbnailRect; then drawInspectorTop (the thumbnail's frame and box, the help), flushed.
void drawInspector(Canvas& canvas, const InspectorLayout& layout, const InspectorModel& model);
void drawInspectorTop(Canvas& canvas, const InspectorLayout& layout, const InspectorModel& model);
void clearInspectorPanels(GLuint framebuffer, const InspectorLayout& layout);

// The texels the neighbourhood view shows: the weights' bounding box grown to hold the 2x2 at
// base and the lookup point, at least 2 x 2.
struct Neighbourhood {
    glm::ivec2 origin{0, 0};
    glm::ivec2 size{2, 2};
};
Neighbourhood neighbourhoodOf(const Trace& trace);

// The light-space region the scene overlay reads around `pixel` (clipped by the caller).
constexpr int gridRadius(glm::ivec2 sceneSize) { return sceneSize.y / 7 > 24 ? sceneSize.y / 7 : 24; }

// Where the shadow-map thumbnail goes (square, whole pixels), and its pixels: the caller blits
// thumbnailImage(map, side) there before drawInspector draws the frame and the box on it.
Rect thumbnailRect(const InspectorLayout& layout, bool presentation);
std::vector<uint8_t> thumbnailImage(const ShadowMap& map, int side);  // RGBA8, rows top-down

// Where the neighbourhood view of this trace sits in the inspector panel.
Rect neighbourhoodArea(const InspectorLayout& layout, const Trace& trace, bool presentation);

// The rect of texel (i, j) in the neighbourhood view inside `area` (rows j down, as stored).
Rect texelCellRect(const Neighbourhood& n, const Rect& area, glm::ivec2 texel);

// The key list the help overlay shows (also `pcfscope view --help`'s epilogue).
const std::vector<std::pair<std::string, std::string>>& viewerKeys();

// Colours of the comparison bits, shared with tests that look for them in exported frames.
constexpr Colour LIT_COLOUR{0.98f, 0.84f, 0.36f, 1.0f};
constexpr Colour SHADOWED_COLOUR{0.22f, 0.27f, 0.40f, 1.0f};

}  // namespace pcf
