// cascades.h: where a cascaded shadow map splits the camera's view depth, with no GL and no
// scene. A directional light's map may have up to MAX_MAP_LAYERS cascades (kernel/shadow_map.h:
// one layer each); cascade i covers the view depths [C_i, C_(i+1)] of [n, f] (n = the camera's
// near plane, f = shadow_distance). The settings rows (kernel/settings.cpp: cascades,
// cascade_split, cascade_lambda, shadow_distance, cascade_fit, cascade_snap, cascade_blend,
// cascade_bounds) name these ids; the fit of each cascade's light box to its slice of the camera
// frustum is scene/cascade_fit.h.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/shadow_map.h"

namespace pcf {

// How many cascades a map may have: one layer each.
constexpr int MAX_CASCADES = MAX_MAP_LAYERS;

// --cascade-split: where the splits go. uniform: equal steps of view depth; log: equal ratios
// (lambda 1); practical: Zhang et al.'s blend of the two by --cascade-lambda.
constexpr int CASCADE_SPLIT_UNIFORM = 0;
constexpr int CASCADE_SPLIT_LOG = 1;
constexpr int CASCADE_SPLIT_PRACTICAL = 2;
std::string_view cascadeSplitName(int split);  // "uniform", "log", "practical"
std::optional<int> cascadeSplitFromName(std::string_view name);
std::string cascadeSplitNames();  // "uniform, log, practical"

// --cascade-fit: the light's box around each slice of the camera frustum. box: the light-space
// bounds of the slice's eight corners (tight, but its size changes as the camera turns); sphere:
// the bounds of the slice's bounding sphere (larger, and the same size however the camera turns).
constexpr int CASCADE_FIT_BOX = 0;
constexpr int CASCADE_FIT_SPHERE = 1;
std::string_view cascadeFitName(int fit);  // "box", "sphere"
std::optional<int> cascadeFitFromName(std::string_view name);
std::string cascadeFitNames();  // "box, sphere"

// --cascade-bounds: the view depths the splits share out. fixed: [n, f], the camera's near plane
// to the shadow distance, whatever the frame shows; depth: [n, f] tightened to the view depths of
// the receivers the frame shows (cascadeSplitSpan), measured on the frame by a depth prepass
// (render/scene_renderer.h SceneRenderer::visibleDepths), as in Lauritzen, Salvi and Lefohn,
// "Sample Distribution Shadow Maps" (I3D 2011).
constexpr int CASCADE_BOUNDS_FIXED = 0;
constexpr int CASCADE_BOUNDS_DEPTH = 1;
std::string_view cascadeBoundsName(int bounds);  // "fixed", "depth"
std::optional<int> cascadeBoundsFromName(std::string_view name);
std::string cascadeBoundsNames();  // "fixed, depth"

// Whether a setting (its key) is one of the cascades' rows: cascades, cascade_split,
// cascade_lambda, shadow_distance, cascade_fit, cascade_snap, cascade_blend, cascade_bounds. Only
// the commands that render a cascaded map take them (app/render_options.h:
// RenderOptions::cascades).
bool isCascadeSetting(std::string_view key);

// The lambda a split scheme blends with: uniform 0, log 1, practical `lambda` (in [0, 1]).
double splitLambda(int split, double lambda);

// Zhang, Sun, Xu and Lau, "Parallel-Split Shadow Maps for Large-scale Virtual Environments"
// (VRCIA 2006), the practical split scheme: the i-th of `count` split distances over the view
// depths [n, f] blends the logarithmic split (equal ratios, what perspective aliasing asks for)
// with the uniform one (equal steps) by lambda:
//   C_i = lambda * n * (f / n)^(i / N) + (1 - lambda) * (n + (f - n) * i / N),  i = 0..N
// C_0 = n, C_N = f. View depths in scene units, 0 < n < f, lambda in [0, 1].
double cascadeSplitDistance(double n, double f, int i, int count, double lambda);

// The far ends of `count` cascades over [n, f] under a split scheme: C_1 .. C_N (the last is f);
// cascade i covers [i == 0 ? n : C_i, C_(i+1)].
std::vector<double> cascadeSplits(double n, double f, int count, int split, double lambda);

// The reduction of Lauritzen, Salvi and Lefohn's "Sample Distribution Shadow Maps" (2011): the
// smallest and largest view depth over a frame's pixels. `depths` holds one value per pixel, the
// view depth (scene units, > 0) of the receiver the pixel shows, or 0 (or less) where it shows
// none (the background, an object that receives no shadow). nullopt when no pixel shows one.
std::optional<glm::vec2> visibleDepthRange(const float* depths, size_t count);

// How far the measured bounds are widened, each by this fraction of itself: dmin (1 - m),
// dmax (1 + m). Without it the deepest receiver pixel, whose view depth is dmax exactly, would
// be past the last cascade (the camera pass picks cascade k + 1 at a view depth >= cascade k's
// far end: shared/pcf_shading.h pcfCascadeLayer) and drawn lit; the margin also holds a last-bit
// difference between the prepass's view depth and the camera pass's (two programs the driver
// compiles apart), and the CPU's from the position the camera pass wrote. 1e-3: 0.1 units at a
// view depth of 100.
constexpr double CASCADE_BOUNDS_MARGIN = 1.0e-3;

// The view depths the cascades split (--cascade-bounds): [n, f] without `visible`; with the
// measured visible receivers' [dmin, dmax], [max(n, dmin (1 - m)), min(f, dmax (1 + m))]
// (m = CASCADE_BOUNDS_MARGIN), or [n, f] still when that is empty (no visible receiver lies
// between n and f, so no split matters).
glm::dvec2 cascadeSplitSpan(double n, double f, std::optional<glm::vec2> visible);

}  // namespace pcf
