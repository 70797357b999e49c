// methods.h: the PCF methods by name (the command line's ids), what each reads, the kernel sizes
// each takes, and the checks on their parameters.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "kernel/pcf.h"
#include "kernel/shadow_map.h"

namespace pcf {

// The methods, typed: the kernel's PCF_* ids (shaders/shared/pcf_kernel.h, where GLSL selects
// by define) as C++ switches on them. Switches over Method have no `default:`, so the compiler
// names every place a new method must be handled.
enum class Method {
    Nearest,
    Box2x2,
    Bilinear2x2,
    Hw2x2,
    Naive,
    Gather,
    Hw,
    Tent,
    Poisson,
    Pcss,
    Vsm,
    Evsm2,
    Evsm4,
    Msm,
    MsmHausdorff
};

// How a method reads the map: where receiver-plane bias takes each tap's ref (per texel, per
// gather, per hardware tap), whether soft bias can see the depths (not through the texture
// unit's comparison), and whether --precision applies (gathers and hardware taps).
enum class MethodReads { Texels, Gathers, HwTaps };

// How far a method's footprint reaches from the lookup, by its shape (reachTexels says it in
// texels for a kernel size and radius).
enum class MethodReach {
    OneTexel,    // the texel the lookup falls in
    Block2x2,    // the 2x2 texels around the lookup
    Kernel,      // N x N lookups one texel apart: (N + 1) / 2 texels
    Disk,        // the Poisson disk of radius R texels
    BlockerDisk  // a disk whose radius follows the blocker found, at most PCF_PCSS_MAX_RADIUS
};

// Which pass makes the map a method reads, and so the map's texel kind (mapTexelKind): the
// light's depth pass (a depth in --depth-format), or the moments pass after it, which writes 2
// or 4 filtered moments per texel in --moment-format (16f, 32f). Switches over MapPass have no
// `default:`.
enum class MapPass { Depth, Moments2, Moments4 };

// Everything pcfscope says about a method, in its one table entry (methods.cpp). Every question
// about a method asked outside kernel/methods is a column here, never a comparison of ids.
struct MethodInfo {
    int id = 0;                               // PCF_NEAREST .. PCF_MSM_HAUSDORFF, the kernel's id
    std::string_view name{};                  // the command line's id, e.g. "pcf-gather"
    std::string_view shortName{};             // the charts' label, e.g. "gather"
    std::string_view summary{};               // one line for `pcfscope methods`
    bool usesKernel = false;                  // takes --kernel N
    bool usesRadius = false;                  // takes --radius R
    bool takesWeights = false;                // takes --weights (binomial, gaussian)
    MethodReads reads = MethodReads::Texels;  // HwTaps: uses the hardware comparison taps
    // The kernel sizes it takes when not every one of MIN_KERNEL..MAX_KERNEL (tent); empty: all.
    std::span<const int> kernelSizes{};
    vec4 chartColour{0.0f};  // its dots and swatches in the charts (RGBA, 0..1)
    // Its hand-written textbook pass, no shared kernel (render/gpu_lookup.h drawReference): the
    // file under shaders/, and whether the pass takes the kernel size as its N (else N = 1:
    // bilinear2x2 is pcf-naive's lookup once, hw2x2 pcf-hw's tap once).
    std::string_view referencePass{};
    bool referenceTakesKernel = false;
    // One texel, one comparison: a visibility of 0 or 1 only (a hard edge). The only methods
    // interpolated-depth bias combines with; the inspector shows their edge in the scene, and
    // a split view sets pcf-gather beside them (the others beside nearest).
    bool hard = false;
    // Compares the texel each of its points falls in (floor(uv * size)): no 2x2 footprint and
    // no sub-texel fraction to show.
    bool nearestTexels = false;
    // Its points lie on the 16-point Poisson disk (PCF_POISSON_DISK), drawn as rings.
    bool hasDisk = false;
    // Searches the map for blockers first and sizes its filter by them (pcss): its first
    // PCF_PCSS_TAPS taps are the search's; it takes the light's size in the map (penumbraScale)
    // and, in a perspective map, the map's depth range (PcfMapLayer::depthRange).
    bool searchesBlockers = false;
    // N x N lookups one texel apart, each compared with its own ref: one texel is read by up to
    // four of them (the trace lists each read; the inspector marks each lookup).
    bool overlappingLookups = false;
    MethodReach reach = MethodReach::OneTexel;
    MapPass mapPass = MapPass::Depth;
    // evsm: how many exponential warps its moments are of (evsm2 1, evsm4 2; 0 for the others):
    // it takes --evsm-exponents, clamped to the moment format's limit.
    int warps = 0;
    // msm: reconstructs a distribution of depths from the moments (its points and weights).
    bool reconstructs = false;
    // Wants the casters' faces toward the light in its map (back faces culled in the shadow
    // pass): a bound from the footprint's moments is tight only where the occluders stand well
    // in front of the receiver, and back faces lie on the receiver where a caster rests on it
    // (box-on-plane: the box's bottom on the ground, so a penumbra mixes depths at the ground's
    // and leaks). bench, which culls front faces for the depth-comparing methods (the map's back
    // faces keep acne off the lit faces), culls back faces for such a method unless --cull is
    // given; render culls back faces by default for every method.
    bool wantsLitFacesInMap = false;

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

// How far from the lookup the method reads, in texels, at kernel size `kernel` and disk radius
// `radius` (texels): the footprint's half-width, from the lookup point to the outer edge of the
// farthest texel it reads.
float reachTexels(int method, int kernel, float radius);

// The texel kind of the map `method` reads, made with settings' formats (--depth-format, and
// --moment-format's bits per channel, 16 or 32).
TexelKind mapTexelKind(int method, TexelKind depthFormat, int momentBits = 32);
// Whether `method` reads a moments map (its mapPass is not the depth pass).
bool readsMoments(int method);

// --moment-format: the moments' float bits per channel by name ("16f" 16, "32f" 32).
std::optional<int> momentFormatFromName(std::string_view name);
std::string_view momentFormatName(int bits);
// The largest EVSM exponent a moment format holds (Lauritzen and McCool 2008's warp exp(c x),
// x in [-1, 1], and its square, both finite): 42 in 32F (exp(84) < 3.4e38), 5.54 in 16F
// (exp(11.08) < 65504).
float evsmExponentLimit(int momentBits);

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
