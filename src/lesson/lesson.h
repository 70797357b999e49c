// lesson.h: a lesson is a scene, a starting state of the renderer and a list of steps, each with
// a title and a text about one picked pixel. The viewer (`pcfscope view`) and the exporter
// (`pcfscope export`) render the scene with a step's state, trace the picked pixel's lookup with
// the CPU kernel (traceLookup) and show the step's text with its placeholders filled from that
// trace (lesson_text.h). So every number a step says about its pixel is the number computed.
//
// The format, one TOML file per lesson in lessons/ (file names sort in teaching order):
//
//   title = "The bilinear lerp"       required, the lesson's title
//   scene = "box-on-plane"            a preset name (scene/presets.h), OR the scene's own
//                                     [camera], [light] and [[object]] tables at the top level
//                                     (scene/scene_file.h), never both; a preset with a
//                                     [camera] table alone: the preset seen from that camera
//
//   [settings]                        optional: the state before the first step. Every key is
//                                     optional. The shadow settings' keys, their types, ranges
//                                     and defaults are the parameter table's (kernel/settings.h
//                                     PARAMS: method, kernel, radius, rotate, weights, sigma,
//                                     precision, depth_format, map_size, bias and its
//                                     parameters, cull); names are their canonical spelling
//   method        = "bilinear2x2"     e.g. a method id (kernel/methods.h)
//   constant_bias = 0.002             e.g. light depth units: every bias mode but none subtracts it
//   grid          = true              the shadow map's texel grid drawn on the receiver around
//                                     the picked pixel (G toggles it), default true; off for
//                                     steps where its lines would hide what they show
//   point         = [1.4486, 0, -0.0163]  the scene point whose lookup the step traces, world
//                                     units, on a surface the camera sees (within 0.001); default
//                                     the point seen in the middle of the view. The pick belongs
//                                     to the scene: each frame shows the point at the pixel that
//                                     holds it, so every size and mode traces the same lookup
//                                     (lesson_pick.h). `pcfscope view` prints the point of a click
//                                     (the step's JSON "point" too)
//   heatmap, origin_shift, snap,      the view's: see LessonSettings
//   magnify, freeze_cascades
//
//   [[step]]                          one table per step, at least one, shown in file order
//   title = "..."                     required, not empty
//   text  = """..."""                 required, not empty; {placeholders} are filled from the
//                                     step's trace (lesson_text.h lists them). Newlines are
//                                     kept (line and paragraph breaks); end a source line with
//                                     a backslash to run on into the next (TOML's
//                                     line-ending backslash). A line that starts with two
//                                     spaces is preformatted: drawn in monospace with its
//                                     spaces kept; consecutive such lines whose cells are
//                                     separated by two or more spaces are aligned as a table
//                                     (overlay/inspector_text.cpp alignTables). A lone operator
//                                     ("1 - g") never breaks across lines
//   chart = "figures/bench.csv"       the step shows that chart instead of the scene
//   chart_highlight = "gather3"       the chart's dots the text talks about (see LessonStep)
//   highlight = 1                     the fetch the text talks about (see LessonStep)
//   claims = ["{shadowed_count} = 0", "penumbra"]
//                                     what the step's words state about its numbers, checked
//                                     by `pcfscope lesson check` at its settings (the syntax:
//                                     lesson_claims.h); not inherited
//   keys = ["O"]                      viewer keys the words invite: the claims must hold after
//                                     each too (lesson_keys.h names them); after any other key
//                                     a failing claim withholds the words in the viewer
//   compare = { bias = ["none", "constant", "slope"] }
//                                     the split view the viewer's C key and `export` show: 2
//                                     or 3 parts, each this step with those parameter-table
//                                     keys set (compare_spec.h); several keys take one value
//                                     per part each. Not inherited
//   predict = { ask = "...", answer = "{visibility}", tolerance = 0.05 }
//                                     the step asks first and reveals the answer on a key
//                                     (StepPredict); choices = [...] instead of a tolerance for
//                                     a multiple choice. Not inherited
//   method = "hw2x2"                  any [settings] key: it changes the state from this step
//                                     on; the steps after it inherit it
//
// Every number a step's text states about its pixel is a placeholder, so the words follow the
// kernel. What the words claim in prose (in shadow, half lit, near 0.8) depends on the point
// picked: tests/lesson_pixels_test.cpp renders every step at the scene sizes of every frame size
// and mode and checks those claims on the traced lookup.
//
// Every problem throws InputError `file:line: what is wrong`, with the line of the offending
// value (or of its table when a key is missing): TOML syntax, unknown keys, wrong types, unknown
// names, values out of range, a method with a kernel it does not take (blamed on whichever of
// the two was set last), an unknown placeholder in a step's text (the line of the placeholder),
// an unknown preset, a step without title or text, a lesson without steps.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/input_error.h"
#include "kernel/bias.h"
#include "kernel/pcf.h"
#include "kernel/settings.h"
#include "lesson/compare_spec.h"
#include "lesson/lesson_animation.h"
#include "lesson/lesson_focus.h"
#include "scene/scene.h"

namespace pcf {

// The renderer's state at one step, fully resolved: the shadow settings (kernel/settings.h,
// every key of its parameter table) and what the view shows besides.
struct LessonSettings : ShadowSettings {
    // The scene point traced (key `point`), world units; nullopt: the middle of the view.
    std::optional<glm::vec3> point;
    bool grid = true;      // the texel grid overlay on the scene
    bool heatmap = false;  // the aliasing heat map over the scene (viewer key A)
    // The scene seen through the magnifier (app/magnifier.h, viewer key Z): the lesson's camera
    // moved toward the point until a texel of the step's map, unslid, is a sixteenth of the
    // scene's height, so that a quarter-texel slide moves the stair steps by several pixels.
    bool magnify = false;
    // A cascaded map's cascades frozen (viewer key Y): they stay fitted to the lesson's camera
    // while the scene is seen from behind and above it (scene/cascade_view.h
    // cascadeOverviewCamera), each cascade's light box and split plane drawn in the scene. Needs
    // cascades 2..4.
    bool freezeCascades = false;
    // The shadow map's texel grid slid under the world by (s, s) texels (light.h's
    // shiftShadowOrigin), then with `snap` moved to the nearest whole-texel fit (viewer keys
    // O / Shift+O step s by 1/8 texel, S toggles snap). 0 and false: the plain fit.
    float originShift = 0.0f;  // origin_shift, texels
    bool snap = false;         // snap
    // The sun moved from the scene's light by the viewer's keys (lesson_keys.h: U / Shift+U,
    // T / Shift+T): degrees added to its elevation (kept within 1..90 degrees when applied) and
    // to its compass heading (turned about the vertical). 0: the scene's light (lessonLight in
    // lesson_pick.h applies them).
    float sunTilt = 0.0f;
    float sunTurn = 0.0f;

    // The kernel's parameters for a lookup at uv in a map of mapSize texels: the Poisson disk
    // turns with the texel looked up (pcfTexelRotation), as the shaders turn it; pcss's
    // penumbraScale is the caller's (scene/pcss.h, for the scene's light and map).
    PcfParams pcfParams(glm::vec2 uv, int mapSize, float penumbraScale = 0.0f) const;

    bool operator==(const LessonSettings&) const = default;
};

class ParsedClaim;  // lesson_claims.h

// A claim of a step's words about its numbers (lesson_claims.h), as written and parsed. Copies
// share the parse.
struct StepClaim {
    std::string text;
    int line = 0;  // its line in the lesson file
    std::shared_ptr<const ParsedClaim> parsed;
};

// `animate = { sweep = "sun", from = 90, to = 2, frames = 60 }`: the step plays as an animation
// of its frame with one quantity swept (lesson_animation.h; app/animation.h plays it): the
// viewer plays it, `export` writes it as LESSON-stepNN.mp4 beside the still. The sweep's name and
// its from/to range are checked here, at `line`; a chart step cannot move.
struct StepAnimation {
    AnimationSweep sweep = AnimationSweep::Light;
    std::optional<double> from;  // the swept quantity's first value (sun, bias, map-size); nullopt:
    std::optional<double> to;    // the sweep's own ends
    int frames = 60;             // 2..MAX_ANIMATION_FRAMES
    int fps = 12;                // 1..60, the video's and the viewer's playback rate
    bool snap = false;           // light: the creeping grid snapped to whole texels
    int line = 0;
};
constexpr int MAX_ANIMATION_FRAMES = 600;

// `predict = { ask = "...", choices = ["{depth_bias*-1}", "{depth_bias}"], answer =
// "{depth_bias}" }` or `{ ask = "...", answer = "{visibility}", tolerance = 0.05 }`: the step
// asks before it tells (docs/teaching.md, "Predict, then reveal"). Its frame first shows `ask` with
// the numbers that would give the answer away hidden; a key (or, exported, the next frame) reveals
// the answer, filled from the trace, above the step's text. ask and choices may hold placeholders
// (none of the quantities the answer hides: app/predict.h checks). The answer is one number
// placeholder; with choices it must equal exactly one of them at every size (lesson check), and
// a typed answer is judged by the choice it names; without, a typed number is right within
// `tolerance`.
struct StepPredict {
    std::string ask;
    std::vector<std::string> choices;  // 2..6 of them, or none
    std::string answer;                // "{visibility}": one number placeholder
    double tolerance = 0.0;            // a number answer's: how far off a typed one may be
    int line = 0;                      // the line of the predict table
};
constexpr size_t MAX_PREDICT_CHOICES = 6;

struct LessonStep {
    std::string title;
    std::string text;  // with {placeholders}; fill with fillText (lesson_text.h)
    int line = 0;      // the line of the step's [[step]] header in the lesson file
    // Where the text is in the file: the line its value starts on, and the offsets in `text` at
    // which each later line of the file begins (a line-ending backslash joins lines without a
    // newline in the text). stepTextLine turns an offset into its line.
    int textLine = 0;
    std::vector<size_t> textLineStarts;
    LessonSettings settings;  // the state at this step: [settings], then every step up to here
    // `chart = "figures/bench.csv"`: this step shows the speed/accuracy chart drawn from that
    // bench.csv (a path relative to the lesson file) where the scene would be. Not inherited.
    // A stability.csv names its chart after a '#': "figures/stability.csv#acne" (or #leak,
    // #tradeoff, #shimmer, #precision), kept in `chart` after the resolved path.
    std::string chart;
    int chartLine = 0;  // the line of the `chart` key
    // `chart_highlight = "front"` or `"gather3, tent3 256"`: the bench chart's dots the step's
    // text talks about, ringed in the highlight colour: "front" (the Pareto front), or a dot's
    // label ("gather3 256") or its first word ("gather3": every map size). Needs `chart`.
    std::string chartHighlight;
    int chartHighlightLine = 0;
    // `highlight = 1`: the fetch instruction (1-based, in issue order) this step's text talks
    // about, drawn in the highlight colour in the inspector; 0: none. Not inherited.
    int highlightFetch = 0;
    // `claims = ["...", ...]`: what the words state about the numbers, checked (lesson_claims.h).
    // Not inherited.
    std::vector<StepClaim> claims;
    // `keys = ["O"]`: the viewer keys (lesson_keys.h) the words are written to survive: the
    // claims must hold after each of them too. Not inherited.
    std::vector<std::string> keys;
    int keysLine = 0;
    // `focus = "neighbourhood"` (in the step, or at the lesson's top for every step): what the
    // step's words are about, which decides the frame's composition (lesson_focus.h: its names,
    // checked here at focusLine). nullopt: derived from the method and the step (app/session.h:
    // stepFocus).
    std::optional<Focus> focus;
    int focusLine = 0;
    // `animate = {...}`: the step is an animation (StepAnimation). Not inherited.
    std::optional<StepAnimation> animate;
    // `compare = { bias = ["none", "constant", "slope"] }`: the split view this step offers (the
    // viewer's C key, `export`): 2 or 3 parts, each the step with those parameters set
    // (compare_spec.h). Checked against the step's settings. Not inherited.
    CompareSpec compare;
    int compareLine = 0;
    // `predict = {...}`: the step is a question first (StepPredict). Not inherited.
    std::optional<StepPredict> predict;
};

// What a lesson may hold; more is refused with one line naming the limit. The lessons that ship
// use a tenth of each (titles ~35 characters, texts ~800, 6 steps); the limits keep a file that
// is wrong by mistake (or by malice) from costing minutes and gigabytes to lay out.
constexpr int MAX_LESSON_STEPS = 32;
constexpr std::size_t MAX_TITLE_CHARS = 120;       // the lesson's title and each step's, in UTF-8
constexpr std::size_t MAX_STEP_TEXT_CHARS = 4000;  // characters (code points), not bytes

struct Lesson {
    std::string name;  // the file's stem, e.g. "03-bilinear-lerp"
    std::string title;
    std::string sourcePath;  // the path given to parseLessonFile (the source name for strings)
    Scene scene;             // the preset, or the scene tables of the file
    std::vector<LessonStep> steps;
};

// Reads and parses a lesson file. A missing file: InputError `path: cannot open file`.
Lesson parseLessonFile(const std::string& path);

// Parses lesson text; sourceName names it in error messages and gives the lesson's name (its
// stem) and sourcePath.
Lesson parseLessonString(std::string_view text, const std::string& sourceName);
// The same, reading on past each problem: every one is appended to `problems`, in file order
// (`lesson check` reports them all). The lesson returned is then as far as it could be read.
Lesson parseLessonString(std::string_view text, const std::string& sourceName,
                         std::vector<InputError>& problems);

// How many times this process has parsed a lesson (file or string): a command parses and checks
// its lesson once, then hands the Lesson on (tests/lesson_once_test.cpp counts).
long lessonParseCount();

// The line of the lesson file that holds offset `offset` of the step's text.
int stepTextLine(const LessonStep& step, size_t offset);

}  // namespace pcf
