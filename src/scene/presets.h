// presets.h: the built-in scenes, by name, each a small TOML scene (scene_file.h) kept in
// presets.cpp and parsed by the same parser as any scene file. The list of them is PRESETS
// there, one place: each entry's name and its TOML, which opens with what the scene shows (the
// box on the ground, the sphere's ellipse, the pole's peter panning, the post in a wide sun and
// under a spot with a radius, the grazing light's acne, the stairs' receivers at several
// depths). `pcfscope render --help` lists the names.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace pcf {

// In PRESETS' order.
std::vector<std::string_view> presetNames();
// "box-on-plane, sphere-over-plane, ...": every name, for help and errors.
std::string presetNameList();

// The scene (Scene::name = the preset's name), or nullopt for an unknown name.
std::optional<Scene> presetScene(std::string_view name);

// The preset's TOML text (what `presetScene` parses), e.g. to start a scene file from it.
std::optional<std::string_view> presetSceneToml(std::string_view name);

}  // namespace pcf
