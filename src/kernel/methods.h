// methods.h: the PCF methods by name (the command line's ids), what each reads, and the
// checks on their parameters.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "kernel/pcf.h"

namespace pcf {

struct MethodInfo {
    int id;                    // PCF_NEAREST .. PCF_POISSON
    std::string_view name;     // the command line's id, e.g. "pcf-gather"
    std::string_view summary;  // one line for `pcfscope methods`
    bool usesKernel;           // takes --kernel N
    bool usesRadius;           // takes --radius R
};

std::span<const MethodInfo> allMethods();
const MethodInfo& methodInfo(int method);
std::optional<int> methodFromName(std::string_view name);
// "nearest, box2x2, ..." for error messages.
std::string methodNameList();

// What the GPU issues for one lookup: texel reads (every texel any instruction touches, so a
// hardware tap or a gather counts 4), gathers and hardware taps.
struct FetchCounts {
    int texels;
    int gathers;
    int hwTaps;
    bool operator==(const FetchCounts&) const = default;
};
FetchCounts fetchCounts(int method, int kernel);

constexpr int MIN_KERNEL = 1;
constexpr int MAX_KERNEL = 8;
constexpr float MAX_POISSON_RADIUS = 64.0f;  // texels

// Parameters with the defaults of DESIGN.md: N = 3, radius 1 texel, no rotation.
PcfParams makeParams(int method, int kernel = 3, float radius = 1.0f,
                     vec2 rotation = vec2(1.0f, 0.0f));

// --weights (pcf-naive, pcf-gather) and --precision (hardware taps, gathers) by name.
std::optional<int> weightsFromName(std::string_view name);  // box, binomial, gaussian
std::string_view weightsName(int weights);
std::optional<int> precisionFromName(std::string_view name);  // exact, hw8
std::string_view precisionName(int precision);
constexpr float MAX_SIGMA = 16.0f;  // texels

// Why parameters are not valid, in the kernel's words: the setting at fault ("kernel",
// "radius", "weights", "sigma", "slope_max": the lesson files' keys; empty for an unknown id)
// and a sentence that names it once, between `before` and `after`. A lesson file says text();
// the command line says the setting as its flag, in one place (app/cli_util.h: cliWords,
// "--slope-max"). The analysis sweeps' checks use it too, naming their option lists
// ("kernels", "map_sizes").
struct ParamProblem {
    std::string setting;
    std::string before;  // "tent takes "
    std::string after;   // " 3, 5 or 7, not 4"
    std::string say(std::string_view settingName) const {
        return before + std::string(settingName) + after;
    }
    std::string text() const { return say(setting); }  // "tent takes kernel 3, 5 or 7, not 4"
};
std::optional<ParamProblem> checkParams(const PcfParams& prm);
// checkParams's sentence in the kernel's words, or nullopt when the parameters are valid.
std::optional<std::string> validateParams(const PcfParams& prm);

}  // namespace pcf
