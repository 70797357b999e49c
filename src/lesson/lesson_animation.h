// lesson_animation.h: the lesson's words for motion (a step's `animate = { sweep = "sun", ... }`,
// lesson.h: StepAnimation): which quantity a sweep moves, its name and unit, and the range its
// from / to may take. The lesson parser checks a step's animate with them, so a lesson is checked
// without the renderer; app/animation.h plays the sweeps, and `pcfscope animate --sweep` takes
// the same names.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace pcf {

// What moves:
//   light     the light's texel grid slid under the world 1/32 texel a frame (looping each
//             texel), exactly as `stability`'s shimmer sweep (measure/stability.h:
//             shimmerShadowFit); with `snap`, snapped to whole texels (Valient's stable fit)
//   camera    the camera slid right and up by 1/6 pixel a frame (stability's camera shimmer)
//   sun       the light's elevation from 90 down to 2 degrees (acne arriving, per bias mode)
//   bias      the constant bias from 0.0005 to 0.064, log steps (acne giving way to peter
//             panning); a step with bias `none` gets `constant`
//   map-size  the shadow map from 32 to 2048 texels a side, log steps (aliasing)
//   turn      the camera turned about the vertical line through the pinned point, from 0 to 45
//             degrees (a game's camera looking round: the point stays at its pixel and view
//             depth while the view turns under the sun, and cascades are fitted to each frame)
enum class AnimationSweep { Light, Camera, Sun, Bias, MapSize, Turn };

std::string_view animationSweepName(AnimationSweep sweep);
std::optional<AnimationSweep> animationSweepFromName(std::string_view name);
constexpr std::string_view ANIMATION_SWEEP_NAMES = "light, camera, sun, bias, map-size, turn";
// The swept quantity's unit in words: "deg elevation", "texels a side", ...
std::string_view animationSweepUnit(AnimationSweep sweep);

// Why `value` cannot be the first or last value (from / to) of `sweep`, or nullopt: light and
// camera have none (they move by a fixed step a frame); sun takes [1, 90] degrees, bias (0, 1],
// map-size 4..4096 texels, turn [-180, 180] degrees. The words follow "from / to" in a message: "
// must be in [1, 90] for the sun sweep".
std::optional<std::string> animationEndProblem(AnimationSweep sweep, double value);

}  // namespace pcf
