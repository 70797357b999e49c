// live_keys.h: the keys that change what a session shows while it is on screen: a lesson's
// settings (lesson/lesson_keys.h names them; `lesson check` presses the same) and the marks over
// the scene, and the scripted input of `--keys` (key names and clicks) that `view` replays and
// `export` applies to every step it writes. The window's other keys (steps, lessons, help,
// fullscreen) are the viewer's own (app/viewer.cpp).
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

namespace pcf {

class Session;

// One key as the viewer understands it, from a --keys token ("m", "shift+m", "space", "right",
// "left_bracket" or "[", "minus" or "-", "equal" or "+"...); throws UsageError on unknown names.
struct KeyPress {
    int key = 0;   // GLFW_KEY_*
    int mods = 0;  // GLFW_MOD_*
};
KeyPress parseKeyName(const std::string& token);

// One input of a --keys script: a key, or a click at a frame pixel (`click:X,Y`, top-left
// origin, the frame's pixels whatever the window's scale).
struct ScriptedInput {
    KeyPress key;
    std::optional<glm::vec2> click;
};
// The whitespace-separated tokens of `--keys`; throws UsageError naming a bad one.
std::vector<ScriptedInput> parseScriptedInput(const std::string& keys);

// The name lesson_keys.h gives the settings key `k` ("V", "Shift+V", "[", "+"), or "" when `k`
// changes no setting. Shift with a key that has no shifted meaning is the key itself.
std::string settingKeyName(KeyPress k);

// Whether `k` is a settings key or X: what pressLiveKey presses.
bool isLiveKey(KeyPress k);
// Presses `k` on the session when it is a settings key or X (the marks on / off); returns
// whether it was one.
bool pressLiveKey(Session& session, KeyPress k);

}  // namespace pcf
