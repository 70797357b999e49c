// inspector.h: the teaching frame: the rendered scene on the left with the picked pixel and the
// shadow-map texel grid projected around it, and on the right the inspector: the magnified texel
// neighbourhood (depth, comparison bit and weight per texel, the sub-texel point, the fetches),
// the formula with its numbers, the steps, a thumbnail of the map, and a status line. Drawn with
// Canvas only, so the window and an export give the same pixels.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "draw/canvas.h"
#include "draw/rect.h"
#include "kernel/shadow_map.h"
#include "kernel/trace.h"
#include "lesson/lesson_focus.h"
#include "overlay/inspector_moments.h"
#include "render/gl_objects.h"

namespace pcf {

// What a step is about is its Focus (lesson/lesson_focus.h, the lesson's key `focus`).
// A focus on the neighbourhood alone (a step about the texels, the gathers or the taps drawn in
// the cells, not about the sum): the cells take the inspector's room, and the formula follows on
// a page of its own instead of sharing the first. Any other focus puts the formula under the
// cells when it fits there.
bool cellsAlone(const Focus& focus);

// Where things go in a frame of a given size. The scene keeps 16:9 (the frame lessons pick their
// pixels in), top-left; the step text sits under it; the inspector fills the right. Presentation
// mode gives the scene less of the width so that the step text and the cells can be large.
// Frames much wider than 16:9 put the step panel beside the scene instead of under it, so no
// panel is left a sliver (or a large empty area).
struct InspectorLayout {
    glm::ivec2 frameSize{0, 0};
    Rect scene;          // the rendered scene, 16:9, whole pixels
    Rect steps;          // lesson title, step list and the current step's text
    Rect inspector;      // the neighbourhood, the formula, the thumbnail
    Rect status;         // one line along the bottom
    Rect thumbnail;      // the map's thumbnail (inside steps); empty: none (presentation)
    float scale = 1.0f;  // 1 at 1600 x 900; fonts and lines scale with it
    bool presentation = false;
    bool sceneInset = false;  // the scene is drawn scaled into `scene` (focusLayout)
    Rect trace;               // an animation's flicker trace (motionLayout); empty: none
};
InspectorLayout inspectorLayout(glm::ivec2 frameSize, bool presentation);
// The frame composed for a step's focus. A scene focus (or none) keeps `l`. A focus on the
// neighbourhood or the formula without the scene gives the inspector the room: it takes the
// frame's right 62% (presentation) or 58% over the status line, and the scene shrinks to an inset
// at the top of the left column, above the step text. The scene is still rendered at l.scene's
// size (the pick and its trace do not depend on the focus) and drawn scaled into the inset.
// A chart focus: chartStepLayout.
InspectorLayout focusLayout(const InspectorLayout& l, const Focus& focus);
// The layout of a lesson step that shows a chart instead of the scene. Presentation mode gives
// the chart the scene's and the inspector's width (the inspector's cells would trace a pixel of a
// scene not shown) and the step panel the full width under it, so that the chart's labels can be
// set at projector size; normal mode keeps `l`.
InspectorLayout chartStepLayout(const InspectorLayout& l);
// The frame of an animation (app/animation.h) with its flicker trace of `curves` lines: the trace
// takes the bottom of the inspector's column (the inspector is shorter by it), so that it covers
// neither the scene, whose acne and stairs the frames show, nor the step's words. A frame
// without an inspector (a chart step) keeps `l`.
InspectorLayout motionLayout(const InspectorLayout& l, int curves);

// The type sizes of a frame, in pixels. Every text is drawn at its size or stepped down towards
// its floor, never below; presentation floors are the projector's (step text 22 px, numbers
// 18 px at any frame size).
struct TypeSizes {
    float head = 20, body = 15, item = 13, number = 14, bit = 30, label = 12, status = 14;
    float bodyFloor = 12, itemFloor = 12, numberFloor = 12, labelFloor = 11;
};
TypeSizes typeSizes(const InspectorLayout& layout);

// Every box the frame draws, as the layout placed it (before drawing): what the JSON sidecar's
// `layout` lists and what the layout tests check. Rects are pixels from the frame's top left.
enum class BoxKind { Panel, Text, Number, Label, Mark };
const char* boxKindName(BoxKind kind);
struct LayoutBox {
    BoxKind kind = BoxKind::Text;
    Rect rect;
    std::string panel;       // "scene", "steps", "inspector", "status"
    std::string role;        // what it is: "step-text", "cell-depth", "lookup-point" ...
    float fontPx = 0.0f;     // text, numbers and labels: the pixel size drawn
    bool shortened = false;  // the text did not fit whole (elided, or paged: see the "more" mark)
    std::string text;        // a text, number or label drawn by itself: its words (JSON "text")
};

// The numbers of the trace a frame can hide until they are revealed (a predict step's question,
// an exercise): each hidden quantity is drawn as "?" where the frame would print it, in the
// inspector's header, cells, fraction labels and texel table; the formula, which holds them
// all, is replaced by a line that says it is hidden. Which quantities a question hides is the
// app's (app/predict.h); the roles whose boxes go are hiddenRoles'.
struct HiddenNumbers {
    bool visibility = false;  // the result: the header's visibility, the formula's result
    bool bits = false;        // the comparison bits: the cells' bits and colours, d - ref
    bool weights = false;     // the cells' weights and weight bars, the table's w
    bool fraction = false;    // the fx, fy labels (and their 8-bit steps)
    bool refs = false;        // ref: the header's, the cells' own, the table's; the bias amount
    bool depths = false;      // the cells' and the table's depths
    bool counts = false;      // the header's fetch counts line
    bool any() const {
        return visibility || bits || weights || fraction || refs || depths || counts;
    }
    bool operator==(const HiddenNumbers&) const = default;
};
// The layout roles whose boxes a frame with these numbers hidden does not draw (the JSON's
// predict.masked): "visibility", "cell-bit", "cell-weight", "weight-bar", "formula", ...
std::vector<std::string> hiddenRoles(const HiddenNumbers& hidden);
// What a masked number is drawn as, in place of each hidden quantity.
constexpr const char* HIDDEN_NUMBER = "?";

// A predict step (or an exercise item) in the step panel: before the reveal, its question, the
// choices when it has them and what was typed; after it, the answer above the step's words.
struct PredictPanel {
    bool on = false;                   // the step is a question
    bool revealed = false;             // the answer and the step's words are shown
    std::string ask;                   // the question, placeholders filled
    std::vector<std::string> choices;  // "-0.02", ...; empty: a number to type
    std::string answer;  // revealed: "Answer: 0.02 (B)", with the verdict on what was typed
    std::string typed;   // what the viewer's keyboard has typed so far ("" none)
    std::string hint;    // how to answer and reveal, e.g. "type a number, Enter; R reveals"
};

// Everything the frame shows; the caller fills it from the lesson, the renderer and the trace.
struct InspectorModel {
    std::string title;                    // lesson title (or "pcfscope")
    std::vector<std::string> stepTitles;  // all steps, in order
    int currentStep = 0;
    std::string stepText;            // the current step's text, placeholders filled
    glm::ivec2 pixel{0, 0};          // picked pixel in scene coordinates (top-left origin)
    std::optional<Trace> trace;      // the picked pixel's lookup; none off the receivers
    const ShadowMap* map = nullptr;  // for the thumbnail
    // A region of the scene's light-space target (u, v, ref, mask per pixel, rows top-down)
    // around the pixel, for the texel grid drawn on the receiver. May be null.
    const std::vector<float>* lightSpace = nullptr;
    glm::ivec2 lightSpaceOrigin{0, 0};  // the region's top-left pixel in the scene
    glm::ivec2 lightSpaceSize{0, 0};    // the region's size
    glm::ivec2 sceneSize{0, 0};         // size of the rendered scene (== layout.scene size)
    std::string status;                 // method, kernel, bias, map, frame time
    bool presentation = false;          // large type, thick lines, high contrast
    bool help = false;                  // the key list over everything
    bool showScene = true;              // false: a chart fills the scene's place (no overlay)
    bool grid = true;                   // the texel grid on the receiver (G, lesson `grid`)
    bool markers = true;                // the pick's ring, label and grid on the scene (X)
    int textPage = 0;                   // the page of the step text shown (when it pages)
    int highlightFetch = -1;            // the fetch (0-based) the step talks about; -1: none
    bool plays = false;  // an animation step: Space plays it, so Right alone turns the page
    // The window's frame: only it names the keys (a page's "more Right", "H: keys"); a frame
    // that is written (export, animate) never shows a hint only the window can act on.
    bool interactive = false;
    // A frame of a written video: no page of it follows, so no note points to one (the
    // inspector's "the formula, every term: next page").
    bool singleFrame = false;
    Focus focus{true, true, false, false};  // what the step is about (inspector.h: Focus)
    HiddenNumbers hidden;                   // numbers drawn as "?" (a question not yet revealed)
    PredictPanel predict;                   // a predict step's question or revealed answer
};

// The frame measured and placed, nothing drawn yet: a pure function of the layout and the model
// (fonts are measured with FreeType; no GL). Drawing replays `base` (under the map thumbnail) and
// `top` (over it).
struct FramePlan {
    std::vector<LayoutBox> boxes;
    std::vector<std::function<void(Canvas&)>> base;
    std::vector<std::function<void(Canvas&)>> top;
    // Pages of the step at this size: its frames. The step text pages when it does not fit;
    // the inspector splits into the cells with their fetches (page 1) and the formula with every
    // term (page 2) when both do not fit one panel at the floors. Page k shows the text's page
    // min(k, last) and the inspector's part min(k, last).
    int textPages = 1;
    // Of them: the step text's pages, and the inspector's parts (cells, texel table, formula).
    int stepTextPages = 1;
    int inspectorParts = 1;
    bool gridShown = false;  // the texel grid was drawn on the scene (not hidden or off)
    // The texels read were tinted on the scene (not on an inset, nor off the scene's pixels).
    bool footprintShown = false;
    // The texels tinted and outlined on the scene, in read order: the distinct texels of the
    // trace's taps that some scene pixel shows (the JSON sidecar's drawn.scene_texels).
    std::vector<glm::ivec2> sceneTexels;
    // What this page drew of what the trace read (the JSON sidecar's `drawn`): the texels whose
    // cells are drawn, the fetches (indices into Trace::fetches) whose marks are drawn, and
    // whether the formula is drawn whole, every term (not the short form).
    std::vector<glm::ivec2> drawnTexels;
    std::vector<int> drawnFetches;
    bool formulaWhole = false;
    // The read texels whose numbers (bit, own ref, depth, weight) this page draws whole: in their
    // cell, or as a row of the texel table (the page after the cells when a cell had to drop
    // some of its numbers at this size).
    std::vector<glm::ivec2> numberedTexels;
    // The read texels whose cell shows its comparison bit (the texel table's grids leave the
    // bits to the cells).
    std::vector<glm::ivec2> bitTexels;
    // poisson and pcss: the radii, in texels, of the rings drawn round the lookup point (the
    // disks the Poisson points fill: the filter's, and pcss's blocker search's).
    std::vector<float> diskRadii;
    // Those rings as drawn on this page: centre and radius in pixels, stroke width.
    struct Ring {
        glm::vec2 centre{0.0f};
        float radius = 0.0f;
        float width = 0.0f;
        Rect clip;  // the ring is drawn clipped to this (the cells, a figure's square)
    };
    std::vector<Ring> rings;
    // A moment method's figure as this page planned it (inspector_moments.h): the histogram's
    // bins, the curves, msm's points. None for the other methods.
    std::optional<MomentFigure> moments;
};
FramePlan planFrame(const InspectorLayout& layout, const InspectorModel& model);
void drawPlan(Canvas& canvas, const std::vector<std::function<void(Canvas&)>>& ops);
// The status line along the bottom of `l` (its panel filled; with `interactive` its keys hint)
// and, with `help`, the key list (H) over the frame, as planFrame places them: what a frame
// composed without the inspector (the split view, app/compare_view.h) draws so that it reads and
// answers H as the lesson's frame.
FramePlan planStatusFrame(const InspectorLayout& l, const std::string& status, bool help,
                          bool interactive);
// A step text as the frame draws it: `code spans` without their backticks (a backtick with no
// partner on its line stays), preformatted rows (two leading spaces) as they are, table columns
// padded to line up. What the step JSON sidecar's `text` reports.
std::string drawnStepText(std::string_view text);

// A frame is drawn in layers: the panels' backgrounds (clearInspectorPanels) and the scene's
// pixels blitted into layout.scene; then
// drawInspector (everything but the map thumbnail's pixels), flushed; then thumbnailImage blitted
// into thumbnailRect; then drawInspectorTop (the picked pixel's ring and label, the thumbnail's
// frame and box, the help), flushed.
// Both plan the frame (planFrame) and replay their half of it.
void drawInspector(Canvas& canvas, const InspectorLayout& layout, const InspectorModel& model);
void drawInspectorTop(Canvas& canvas, const InspectorLayout& layout, const InspectorModel& model);
void clearInspectorPanels(GLuint framebuffer, const InspectorLayout& layout);

// The texels the neighbourhood holds: the weights' bounding box grown to hold the 2x2 at base and
// the lookup point, at least 2 x 2. The view may show a window of it (neighbourhoodView) when
// its cells would be too small for their numbers.
struct Neighbourhood {
    glm::ivec2 origin{0, 0};
    glm::ivec2 size{2, 2};
};
Neighbourhood neighbourhoodOf(const Trace& trace);

// The light-space region the scene overlay reads around `pixel` (clipped by the caller).
constexpr int gridRadius(glm::ivec2 sceneSize) {
    return sceneSize.y / 7 > 24 ? sceneSize.y / 7 : 24;
}

// Where the shadow-map thumbnail goes (square, whole pixels), and its pixels: the caller blits
// thumbnailImage(map, side) there before drawInspector draws the frame and the box on it.
Rect thumbnailRect(const InspectorLayout& layout, bool presentation);
std::vector<uint8_t> thumbnailImage(const ShadowMap& map, int side);  // RGBA8, rows top-down

// The texels the view shows (all of neighbourhoodOf: never a window of it, so that every texel
// and fetch the trace read is drawn), and where it sits in the panel.
Neighbourhood neighbourhoodView(const InspectorLayout& layout, const Trace& trace,
                                int highlight = -1);
Rect neighbourhoodArea(const InspectorLayout& layout, const Trace& trace, bool presentation,
                       int highlight = -1);
// The same for a whole model (its legend decides whether the formula fits under the cells, and
// so the cells' size): what planFrame draws for `m`.
Neighbourhood neighbourhoodView(const InspectorLayout& layout, const InspectorModel& m);
Rect neighbourhoodArea(const InspectorLayout& layout, const InspectorModel& m);

// The rect of texel (i, j) in the view of `n` inside `area` (rows j down, as stored).
Rect texelCellRect(const Neighbourhood& n, const Rect& area, glm::ivec2 texel);

// The viewer's keys, one table (inspector_keys.cpp) for the help overlay (H) and `pcfscope view
// --help`'s footer; Viewer::press (app/viewer.cpp) acts on them: a key added there goes here.
const std::vector<std::pair<std::string, std::string>>& viewerKeys();

// Colours of the comparison bits, shared with tests that look for them in exported frames.
constexpr Colour LIT_COLOUR{0.98f, 0.84f, 0.36f, 1.0f};
constexpr Colour SHADOWED_COLOUR{0.22f, 0.27f, 0.40f, 1.0f};

}  // namespace pcf
