// cascades.h: where a cascaded shadow map splits the camera's view depth, with no GL and no
// scene. A directional light's map may have up to MAX_MAP_LAYERS cascades (kernel/shadow_map.h:
// one layer each); cascade i covers the view depths [C_i, C_(i+1)] of [n, f] (n = the camera's
// near plane, f = shadow_distance). The settings rows (kernel/settings.cpp: cascades,
// cascade_split, cascade_lambda, shadow_distance, cascade_fit, cascade_snap, cascade_blend) name
// these ids; the
// fit of each cascade's light box to its slice of the camera frustum is scene/cascade_fit.h.
#pragma once

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

// Whether a setting (its key) is one of the cascades' rows: cascades, cascade_split,
// cascade_lambda, shadow_distance, cascade_fit, cascade_snap, cascade_blend. Only the commands that
// render a cascaded map take them (app/render_options.h: RenderOptions::cascades).
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

}  // namespace pcf
