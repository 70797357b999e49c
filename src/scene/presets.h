// presets.h: the built-in scenes, by name, each a small TOML scene (scene_file.h) kept in
// presets.cpp and parsed by the same parser as any scene file. The list of them is PRESETS
// there, one place: each entry's name and its TOML, which opens with what the scene shows (the
// box on the ground, the sphere's ellipse, the pole's peter panning, the post in a wide sun and
// under a spot with a radius, the grazing light's acne, the stairs' receivers at several
// depths, two stacked cards). `pcfscope render --help` lists the names.
//
// A preset may take numbers (its PresetParam list): a scene file sets them in a [preset] table
// (scene_file.h), e.g. stacked-cards' gap between its cards.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace pcf {

// In PRESETS' order.
std::vector<std::string_view> presetNames();
// "box-on-plane, sphere-over-plane, ...": every name, for help and errors.
std::string presetNameList();

// A number a preset takes: its key in a [preset] table, default, closed range and meaning.
struct PresetParam {
    std::string_view key;  // "gap"
    double defaultValue = 0.0;
    double min = 0.0;
    double max = 0.0;
    std::string_view unit;  // "world units"
    std::string_view help;
};

// The preset's numbers, in order; empty for an unknown name or a preset that takes none.
std::span<const PresetParam> presetParams(std::string_view name);

// The scene (Scene::name = the preset's name) with its numbers at their defaults, or nullopt
// for an unknown name.
std::optional<Scene> presetScene(std::string_view name);

// The scene with its numbers set: one value per presetParams(name), in order. Throws
// std::invalid_argument for a wrong count or a value out of its range (scene files check first
// and say where).
std::optional<Scene> presetScene(std::string_view name, std::span<const double> values);

// The preset's TOML text (what `presetScene` parses), e.g. to start a scene file from it.
std::optional<std::string_view> presetSceneToml(std::string_view name);

}  // namespace pcf
