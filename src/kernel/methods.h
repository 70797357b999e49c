// methods.h: the PCF methods by name (the command line's ids), what each reads, the kernel sizes
// each takes, and the checks on their parameters.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "kernel/pcf.h"

namespace pcf {

// The methods, typed: the kernel's PCF_* ids (shaders/shared/pcf_kernel.h, where GLSL selects
// by define) as C++ switches on them. Switches over Method have no `default:`, so the compiler
// names every place a new method must be handled.
enum class Method { Nearest, Box2x2, Bilinear2x2, Hw2x2, Naive, Gather, Hw, Tent, Poisson, Pcss };

// How a method reads the map: where receiver-plane bias takes each tap's ref (per texel, per
// gather, per hardware tap), whether soft bias can see the depths (not through the texture
// unit's comparison), and whether --precision applies (gathers and hardware taps).
enum class MethodReads { Texels, Gathers, HwTaps };

// Everything pcfscope says about a method, in its one table entry (methods.cpp).
struct MethodInfo {
    int id;                      // PCF_NEAREST .. PCF_PCSS, the kernel's id
    std::string_view name;       // the command line's id, e.g. "pcf-gather"
    std::string_view shortName;  // the charts' label, e.g. "gather"
    std::string_view summary;    // one line for `pcfscope methods`
    bool usesKernel;             // takes --kernel N
    bool usesRadius;             // takes --radius R
    bool takesWeights;           // takes --weights (binomial, gaussian)
    MethodReads reads;
    // The kernel sizes it takes when not every one of MIN_KERNEL..MAX_KERNEL (tent); empty: all.
    std::span<const int> kernelSizes;
    vec4 chartColour;  // its dots and swatches in the charts (RGBA, 0..1)
    // Its hand-written textbook pass, no shared kernel (render/gpu_lookup.h drawReference): the
    // file under shaders/, and whether the pass takes the kernel size as its N (else N = 1:
    // bilinear2x2 is pcf-naive's lookup once, hw2x2 pcf-hw's tap once).
    std::string_view referencePass;
    bool referenceTakesKernel;

    Method method() const { return static_cast<Method>(id); }
};

std::span<const MethodInfo> allMethods();
// The entry of kernel id `method`; an id outside the table throws std::out_of_range.
const MethodInfo& methodInfo(int method);
// The typed id of kernel id `method` (checked as methodInfo checks it).
Method methodOf(int method);
std::optional<int> methodFromName(std::string_view name);
// "nearest, box2x2, ..." for error messages.
std::string methodNameList();

// How far the 16-point Poisson set of poisson and pcss (PCF_POISSON_DISK, from Jimmy,
// "Percentage Closer Filtering", 2010) reaches from its centre, in units of the scale it is
// given: max |d_k| over its points, 1.234. The widely copied set is not a unit disk (8 of its 16
// points lie outside radius 1), so the disk its points fill is this much wider than the scale.
// The inspector's rings and the lessons' {disk_reach} both read it.
float poissonSetReach();

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

// Parameters with the defaults of docs/methods.md: N = 3, radius 1 texel, no rotation.
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

// Whether `method` can take kernel size n: MIN_KERNEL..MAX_KERNEL, and for tent 3, 5 or 7 (its
// 4, 9 or 16 hardware taps). Methods without a kernel take any n (they ignore it).
bool kernelFits(int method, int n);
// The kernel sizes `method` takes, in words: "1..8", or "3, 5 or 7" for tent.
std::string kernelSizesText(int method);
// The next kernel size `method` takes after n, going up (direction 1) or down (-1), staying
// at the end of the range; a size the method cannot take becomes its smallest.
int stepKernel(int method, int n, int direction);
// n if the method takes it, else its smallest size (a method change keeps N when it can).
int fitKernel(int method, int n);

}  // namespace pcf
