// live_keys.cpp: the live keys on a session and the --keys script (live_keys.h).
#include "app/live_keys.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <map>
#include <sstream>

#include "app/cli_util.h"
#include "app/session.h"
#include "lesson/lesson_keys.h"

namespace pcf {

namespace {

// The keys --keys knows by a name (letters and digits are their own).
const std::map<std::string, int>& keyNames() {
    static const std::map<std::string, int> NAMES = {
        {"space", GLFW_KEY_SPACE},
        {"right", GLFW_KEY_RIGHT},
        {"left", GLFW_KEY_LEFT},
        {"up", GLFW_KEY_UP},
        {"down", GLFW_KEY_DOWN},
        {"home", GLFW_KEY_HOME},
        {"end", GLFW_KEY_END},
        {"backspace", GLFW_KEY_BACKSPACE},
        {"escape", GLFW_KEY_ESCAPE},
        {"esc", GLFW_KEY_ESCAPE},
        {"left_bracket", GLFW_KEY_LEFT_BRACKET},
        {"[", GLFW_KEY_LEFT_BRACKET},
        {"right_bracket", GLFW_KEY_RIGHT_BRACKET},
        {"]", GLFW_KEY_RIGHT_BRACKET},
        {"minus", GLFW_KEY_MINUS},
        {"-", GLFW_KEY_MINUS},
        {"equal", GLFW_KEY_EQUAL},
        {"plus", GLFW_KEY_EQUAL},
        {"+", GLFW_KEY_EQUAL},
        {"=", GLFW_KEY_EQUAL},
        {"period", GLFW_KEY_PERIOD},
        {".", GLFW_KEY_PERIOD},
        {"comma", GLFW_KEY_COMMA},
        {",", GLFW_KEY_COMMA},
        {"slash", GLFW_KEY_SLASH},
        {"/", GLFW_KEY_SLASH},
        {"enter", GLFW_KEY_ENTER},
        {"return", GLFW_KEY_ENTER},
    };
    return NAMES;
}

}  // namespace

KeyPress parseKeyName(const std::string& token) {
    const std::map<std::string, int>& NAMES = keyNames();
    KeyPress k;
    std::string name = token;
    for (;;) {
        size_t plus = name.find('+');
        if (plus == std::string::npos || plus == 0 || plus + 1 == name.size()) break;
        std::string mod = name.substr(0, plus);
        std::transform(mod.begin(), mod.end(), mod.begin(), ::tolower);
        if (mod == "shift")
            k.mods |= GLFW_MOD_SHIFT;
        else if (mod == "ctrl" || mod == "control")
            k.mods |= GLFW_MOD_CONTROL;
        else if (mod == "alt")
            k.mods |= GLFW_MOD_ALT;
        else
            throw UsageError("--keys: unknown modifier '" + mod + "' in '" + token + "'");
        name = name.substr(plus + 1);
    }
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
    if (auto it = NAMES.find(lower); it != NAMES.end()) {
        k.key = it->second;
    } else if (lower.size() == 1 && lower[0] >= 'a' && lower[0] <= 'z') {
        k.key = GLFW_KEY_A + (lower[0] - 'a');
        if (name[0] >= 'A' && name[0] <= 'Z') k.mods |= GLFW_MOD_SHIFT;
    } else if (lower.size() == 1 && lower[0] >= '0' && lower[0] <= '9') {
        k.key = GLFW_KEY_0 + (lower[0] - '0');
    } else {
        throw UsageError("--keys: unknown key '" + token +
                         "' (GLFW names: space, right, m, "
                         "shift+m, left_bracket ...)");
    }
    return k;
}

std::vector<ScriptedInput> parseScriptedInput(const std::string& keys) {
    std::vector<ScriptedInput> inputs;
    std::istringstream tokens(keys);
    for (std::string t; tokens >> t;) {
        ScriptedInput in;
        if (t.starts_with("click:")) {
            // A frame pixel: whole numbers, as the frame's PNG and JSON count them.
            in.click = glm::vec2(parseIvec2("--keys " + t, t.substr(6))) + 0.5f;
        } else {
            in.key = parseKeyName(t);
        }
        inputs.push_back(in);
    }
    return inputs;
}

std::string settingKeyName(KeyPress k) {
    bool shift = (k.mods & GLFW_MOD_SHIFT) != 0;
    std::string name;
    switch (k.key) {
        case GLFW_KEY_LEFT_BRACKET:
            return "[";
        case GLFW_KEY_RIGHT_BRACKET:
            return "]";
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT:
            return "-";
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD:
            return "+";
        default:
            break;
    }
    if (k.key < GLFW_KEY_A || k.key > GLFW_KEY_Z) return "";
    std::string letter(1, static_cast<char>('A' + (k.key - GLFW_KEY_A)));
    const std::vector<std::string>& names = settingKeyNames();
    auto known = [&](const std::string& n) {
        return std::find(names.begin(), names.end(), n) != names.end();
    };
    if (shift && known("Shift+" + letter)) return "Shift+" + letter;
    return known(letter) ? letter : "";
}

bool isLiveKey(KeyPress k) { return k.key == GLFW_KEY_X || !settingKeyName(k).empty(); }

bool pressLiveKey(Session& session, KeyPress k) {
    if (k.key == GLFW_KEY_X) {
        session.setMarkers(!session.markers());
        return true;
    }
    std::string name = settingKeyName(k);
    if (name.empty()) return false;
    // One table of what each key does (lesson/lesson_keys.h), shared with `lesson check`.
    std::optional<LessonSettings> s = settingsAfterKey(session.settings(), name);
    if (!s) return false;
    session.setSettings(*s);
    return true;
}

}  // namespace pcf
