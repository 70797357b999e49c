// advise_report.h: what `pcfscope advise` writes (advise.h's result): advise.csv (every setting
// measured, every measure, the cost's median and IQR), advise.json (the choice, the runner-up,
// the binding constraint, the candidates) and the choice as a [settings] table of a lesson or
// scene file. No GL, no files: text.
#pragma once

#include <string>
#include <vector>

#include "measure/advise.h"
#include "measure/bench.h"

namespace pcf {

// What the search ran on, for the JSON's header.
struct AdviseContext {
    std::string scene;
    int frameWidth = 0, frameHeight = 0;
    std::string truth;       // bench.md's words: "hard (the light's centre)"
    std::string glRenderer;  // GL_RENDERER
    // The settings the search leaves alone (culling, depth format, the other bias parameters).
    RenderSettings base;
};

// advise.csv's header line (no newline).
extern const char* const ADVISE_CSV_HEADER;

// One line per measured setting (rows[k] is measured[k]'s bench row), in the order measured.
std::string adviseCsv(const AdviseResult& result, const std::vector<BenchRow>& rows);

// The JSON: scene, frame, truth, renderer, budget, grid_size, measured, choice, runner_up,
// binding, tie, candidates. Indented.
std::string adviseJson(const AdviseResult& result, const AdviseBudget& budget,
                       const AdviseContext& context);

// The setting as a TOML [settings] table, each key the parameter table's (a lesson's or a scene
// file's [settings] takes it as it is): method, kernel and weights where the method takes them,
// map_size, bias and its amount, and culling and depth format where the base is not the
// default. A comment line first says what it is.
std::string adviseSettingsToml(const AdviseSetting& setting, const RenderSettings& base);

}  // namespace pcf
