// truth_option.h: --truth hard|area, for the commands that measure against the ground truth
// (bench, advise), and the words their reports say it in.
#pragma once

#include <string>

#include "kernel/settings.h"
#include "scene/scene.h"

namespace pcf {

// Parses --truth: false for "hard" (the light's centre), true for "area" (its disk), after
// making the scene's light carry the size the area truth integrates over (a sun's: the
// settings' light_size when above 0, else its angular_diameter, else the sun's; a spot's: the
// settings' light_radius when above 0, else its radius). Throws UsageError for another name, a
// light size given for the other kind of light (whichever truth), a spot without a radius or
// casters a spot's disk cannot take.
bool applyTruthOption(const std::string& truth, Scene& scene, const ShadowSettings& s);

// "hard (the light's centre)", "area (a sun disk of 2 degrees)", "area (a spot disk of radius
// 0.3)": bench.md's, bench.csv's truth column's and advise.json's words.
std::string truthWordsFor(const Scene& scene, bool area);

}  // namespace pcf
