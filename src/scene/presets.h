// presets.h: the built-in scenes, by name, each a small TOML scene (scene_file.h) kept in
// presets.cpp and parsed by the same parser as any scene file.
//
//   box-on-plane       a box resting on the ground, sun at ~40 degrees: the classic
//   sphere-over-plane  a sphere floating above the ground: its shadow is an ellipse
//   pole               a thin tall pole standing on the ground: peter panning opens a gap
//                      between its foot and its shadow
//   grazing            light 82 degrees from the ground's normal: shadow acne across the ground
//   stairs             four steps of rising height: receivers at several depths, each step
//                      shadowing the next
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace pcf {

// In the order above.
std::vector<std::string_view> presetNames();
// "box-on-plane, sphere-over-plane, ...": every name, for help and errors.
std::string presetNameList();

// The scene (Scene::name = the preset's name), or nullopt for an unknown name.
std::optional<Scene> presetScene(std::string_view name);

// The preset's TOML text (what `presetScene` parses), e.g. to start a scene file from it.
std::optional<std::string_view> presetSceneToml(std::string_view name);

}  // namespace pcf
