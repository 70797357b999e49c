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
// (snap the fit to whole texels).
const std::vector<std::string>& settingKeyNames();

// The settings after pressing `key` once; nullopt for a name settingKeyNames() does not hold.
std::optional<LessonSettings> settingsAfterKey(const LessonSettings& s, std::string_view key);

// Whether `to` is `from` after at most `presses` presses of the keys (a step's `keys`): the
// state its words were written to survive.
bool reachableByKeys(const LessonSettings& from, const LessonSettings& to,
                     const std::vector<std::string>& keys, int presses = 8);

}  // namespace pcf
