// lesson_keys.h: the viewer's keys that change a lesson's settings, by name, as pure functions of
// the settings: the viewer presses them, and `pcfscope lesson check` presses them to verify that
// a step's claims survive the keys its words invite (lesson_claims.h: a step's `keys`).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lesson/lesson.h"

namespace pcf {

// The names: "M" / "Shift+M" (next / previous method), "[" / "]" (kernel down / up), "-" / "+"
// (map size halved / doubled), "B" / "Shift+B" (next / previous bias mode), "Q" (texture-unit
// precision exact <-> hw8), "O" / "Shift+O" (slide the map's texel grid by +-1/8 texel), "S"
// (snap the fit to whole texels), "V" / "Shift+V" (the constant bias one step up / down
// BIAS_AMOUNT_STEPS), "U" / "Shift+U" (the sun SUN_TILT_STEP_DEG higher / lower), "T" /
// "Shift+T" (the sun turned SUN_TURN_STEP_DEG about the vertical, one way / the other), "W" /
// "Shift+W" (next / previous kernel weights, for the methods that take them), "I" / "Shift+I"
// (the gaussian weights' sigma one step up / down SIGMA_STEPS), "K" (the next cull mode of the
// shadow pass), "D" (the next depth format) and "N" (the shading: lit <-> the visibility alone).
const std::vector<std::string>& settingKeyNames();

// The constant bias's log steps (light depth units): 1, 2, 5 a decade, the range of `stability`'s
// leak sweep (0.0005 .. 0.064) and beyond. V from a value between two steps goes to the next.
constexpr float BIAS_AMOUNT_STEPS[] = {0.00001f, 0.00002f, 0.00005f, 0.0001f, 0.0002f,
                                       0.0005f,  0.001f,   0.002f,   0.005f,  0.01f,
                                       0.02f,    0.05f,    0.1f,     0.2f,    0.5f};
// Gaussian sigma's steps (texels): about sqrt(2) apart, within [MIN_SIGMA, MAX_SIGMA].
constexpr float SIGMA_STEPS[] = {0.25f, 0.35f, 0.5f, 0.7f, 1.0f,  1.4f, 2.0f,
                                 2.8f,  4.0f,  5.6f, 8.0f, 11.0f, 16.0f};
constexpr float SUN_TILT_STEP_DEG = 5.0f;
constexpr float SUN_TURN_STEP_DEG = 15.0f;

// The settings after pressing `key` once; nullopt for a name settingKeyNames() does not hold.
std::optional<LessonSettings> settingsAfterKey(const LessonSettings& s, std::string_view key);

// Whether `to` is `from` after at most `presses` presses of the keys (a step's `keys`): the
// state its words were written to survive.
bool reachableByKeys(const LessonSettings& from, const LessonSettings& to,
                     const std::vector<std::string>& keys, int presses = 8);

}  // namespace pcf
