// stability.h: where shadow-map filtering fails, measured. Six sweeps, each a curve of numbers
// against the exact ground truth (ground_truth.h), for any list of methods and bias modes, and
// four of pcss's own (stability_pcss.h: pcss-thin, pcss-overlap, pcss-noise, pcss-bias), light
// bleeding on two stacked occluders (stability_bleed.h: bleed), and cascaded maps one cascade at
// a time along a turning camera path (stability_cascades.h: cascades):
//
//   acne       the light's elevation swept from 90 down to 2 degrees over the scene; the
//              false-shadow rate = share of the CLEAN LIT pixels where visibility < 0.99, and the
//              mean darkening 1 - v over them. Clean lit: the truth says fully lit at the pixel
//              AND at every point of a grid spanning +-reach texels of the map around it (moved
//              in the map's plane, carried along the light onto the pixel's surface plane), so
//              a filter's legitimate penumbra next to a real shadow is not counted as acne; reach
//              is the method's own footprint (footprintReachTexels) + 1/2 texel.
//   leak       peter panning at the contacts of the `pole` and `box-on-plane` presets, the
//              constant bias swept: the leak rate = share of the CLEAN UMBRA pixels (the truth
//              says fully shadowed there and over the whole footprint, as above) where the
//              method returns > 0.01, and the leak's width: the largest distance from the caster
//              (its nearest point; on the ground that is the contact line) of a leaking pixel
//              that lies in a connected run of at least LEAK_MIN_RUN leaking pixels (so one
//              stray pixel cannot set it; failure_measures.h says why 8), in world units and in
//              shadow-map texels (the two points' map positions apart), with its support (the
//              pixels counted) and the stray pixels left out.
//   tradeoff   the acne sweep's false-shadow rate at ONE elevation (tradeoffElevation) with the
//              constant bias swept over the leak sweep's biases: acne and leak on one bias axis,
//              so that where a good bias lies (acne gone, no leak yet) can be read off one chart.
//   shimmer    the map's texel grid slid under the world by (k/32, k/32) texel for k = 0..31
//              (light.h's shiftShadowOrigin; the world's shadow stays where it is), mean and 99th
//              percentile of |v(t) - v(t-1)| over the compared pixels of all frame pairs; the
//              same with the grid snapped to whole texels (what remains is rasterisation
//              rounding); and the camera slid by sub-pixel steps, where the truth moves too, so
//              the change of the error e = v - truth between frames. Where the picture is still
//              but for the shadow's edges, most receivers never change and the p99 over all of
//              them says little; so the same statistics also over the FLICKERING pixels only
//              (those whose value changes by more than 1/512 in any frame), and their share.
//              Those populations differ from one method and bias to the next, so for charts two
//              FIXED ones, the same pixels for every pair: the lit ground (clean lit at the
//              run's widest footprint: any change there is acne flickering, "lit_") and the
//              edges (every other compared pixel: in or next to a real shadow, "edge_"); on
//              the edges also how far single pixels jump ("edge_peak_p99", failure_measures.h
//              says why the mean cannot tell a hard edge from a soft one), which the chart shows.
//   precision  depth formats 16, 24, 32F with the light's depth range made 1..1e5 times deeper
//              than the scene (light.h's widenShadowDepthRange) at one elevation; the bias is
//              held fixed in WORLD terms (constant bias / ratio), so only the format's precision
//              changes; the false-shadow rate and mean darkening as for acne.
//   aliasing   screen pixels per shadow-map texel at each pixel, the perspective aliasing measure
//              of Lloyd, Tuft, Yoon and Manocha, "Warping and Partitioning for Low Error Shadow
//              Maps" (EGSR 2006) and "Logarithmic Perspective Shadow Maps" (Lloyd et al., ACM
//              TOG 2008): with J = d(u, v) * mapSize / d(x, y) the texels per pixel (finite
//              differences of the light-space target between neighbouring receiver pixels),
//              pixels per texel = 1 / |det J|; > 1 means one texel is smeared over several
//              pixels. Median and 99th percentile over the compared pixels, per map size, and a
//              heat map.
//
// The GPU renders every frame (the same renderer as `render` and `bench`); the CPU measures.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/render_settings.h"
#include "scene/scene.h"

namespace pcf {

enum class Sweep {
    Acne,
    Leak,
    Tradeoff,
    Shimmer,
    Precision,
    Aliasing,
    // pcss's failures (stability_pcss.h)
    PcssThin,
    PcssOverlap,
    PcssNoise,
    PcssBias,
    // light bleeding on stacked cards (stability_bleed.h)
    Bleed,
    // cascades along a camera path: texel size, flicker, seams (stability_cascades.h)
    Cascades,
};

// "acne", "leak", "tradeoff", "shimmer", "precision", "aliasing", "pcss-thin", "pcss-overlap",
// "pcss-noise", "pcss-bias", "bleed", "cascades"
std::string_view sweepName(Sweep sweep);
std::optional<Sweep> sweepFromName(std::string_view name);
std::vector<Sweep> allSweeps();
std::string sweepNameList();  // "acne, leak, tradeoff, shimmer, precision, aliasing"

struct StabilityMethod {
    int method = PCF_NEAREST;
    int kernel = 0;  // N, or 0 for a method that takes none
    bool operator==(const StabilityMethod&) const = default;
};

// Whether the bias mode can combine with the method (kernel/bias.h's validateBias): the sweeps
// skip the pairs that cannot exist (soft with a method whose comparison the texture unit makes,
// interpolated with anything but nearest).
bool stabilityPairExists(const StabilityMethod& m, BiasMode bias);

// "pcf-gather N=5" or "nearest".
std::string stabilityMethodName(const StabilityMethod& m);

// The smallest frame side the sweeps accept (the CLI states it in --size's help).
constexpr int MIN_STABILITY_FRAME_SIDE = 16;
constexpr int SHIMMER_STEPS = 32;  // the light's grid moves 1/32 texel per frame

// A setting the bleed sweep sweeps: its key in the settings table and its values as text.
struct BleedSetting {
    std::string key;
    std::vector<std::string> values;
};

struct StabilityOptions {
    // The extremes of the filters (one texel, a 5x5 footprint) and the biases that differ most;
    // every other method and bias mode runs with --methods / --biases.
    std::vector<StabilityMethod> methods{{PCF_NEAREST, 0}, {PCF_GATHER, 5}};
    std::vector<BiasMode> biases{BiasMode::None, BiasMode::Constant, BiasMode::Normal,
                                 BiasMode::ReceiverPlane};
    std::vector<Sweep> sweeps = allSweeps();
    // Bias parameters, culling, polygon offset, depth format of every frame (method, kernel,
    // bias mode, map and frame size are the sweep's).
    RenderSettings base;
    glm::ivec2 frameSize{480, 270};
    int mapSize = 512;
    int truthSpp = 2;  // K x K ground-truth samples per pixel
    int threads = 0;   // for the truth and the masks; 0 = all cores
    // Degrees; every 3 degrees from 90 to 75, where the default methods' acne sets in (pcf-gather
    // 5x5 with a constant bias passes 1 % between 90 and 75), then coarser as the light sinks.
    std::vector<float> elevations{90, 87, 84, 81, 78, 75, 60, 45, 35, 25, 18, 12, 8, 5, 3, 2};
    std::vector<std::string> leakScenes{"pole", "box-on-plane"};
    std::vector<float> leakBiases{0.0005f, 0.001f, 0.002f, 0.004f, 0.008f, 0.016f, 0.032f, 0.064f};
    int shimmerFrames = SHIMMER_STEPS;  // light-grid frames, 1/32 texel apart
    int cameraFrames = 6;               // camera frames, 1/cameraFrames pixel apart
    std::vector<float> depthRanges{1, 10, 100, 1e3f, 1e4f, 1e5f};
    std::vector<TexelKind> depthFormats{TexelKind::D16, TexelKind::D24, TexelKind::D32F};
    float precisionElevation = 30.0f;  // degrees
    float tradeoffElevation = 30.0f;   // degrees: the tradeoff sweep's light
    std::vector<int> aliasingMapSizes{256, 512, 1024, 2048};
    // pcss's sweeps (stability_pcss.h): the thin pole's widths in map texels, the plank's
    // heights in world units, the suns' angular diameters in degrees, poisson's radii in texels
    // and the light's elevation for the last.
    std::vector<float> pcssPoleWidths{1, 1.5f, 2, 3, 4};
    std::vector<float> pcssPlankHeights{0.5f, 1, 2, 3};
    std::vector<float> pcssLightSizes{1, 2, 4, 8};
    std::vector<float> pcssRadii{1, 2, 4, 8, 16};
    float pcssBiasElevation = 87.0f;
    // The bleed sweep's gaps between the stacked cards, world units (presets.h: stacked-cards'
    // gap; its default, 1, is the chart's).
    std::vector<float> bleedGaps{0.25f, 0.5f, 1.0f, 2.0f};
    // The methods that filter moments, measured by the bleed sweep beside `methods` (the ones
    // that compare depths), and the settings it sweeps on each method they act for
    // (kernel/settings.h: paramActsFor), one at a time, the others at the run's values: by
    // their keys in the settings table and their values as the command line writes them.
    std::vector<StabilityMethod> bleedMethods{
        {PCF_VSM, 5}, {PCF_EVSM2, 5}, {PCF_EVSM4, 5}, {PCF_MSM, 5}, {PCF_MSM_HAUSDORFF, 5}};
    std::vector<BleedSetting> bleedSettings{{"lbr", {"0", "0.1", "0.2", "0.3", "0.4", "0.5"}},
                                            {"evsm_exponents", {"5,5", "20,5", "40,5", "42,42"}},
                                            {"moment_bias", {"3e-5", "3e-4", "3e-3"}},
                                            {"moment_format", {"16f", "32f"}}};
    // The cascades sweep (stability_cascades.h): the split's lambdas (0 is the uniform split, 1
    // the log split), the steps of the camera path, and the blend band of its blended seams.
    std::vector<float> cascadeLambdas{0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
    int cascadePathSteps = 8;
    float cascadeBlend = 0.2f;
    // The area truth's per-pixel bound for pcss's sweeps (ground_truth.h: targetBound): looser
    // than the bench's 1/512, as the sweeps count pixels by thresholds (1/2, 0.02, 0.98).
    float pcssTruthBound = 1.0f / 64.0f;
    // A pinned pixel (frame coordinates, top-left origin): the shimmer sweep also writes the
    // flicker of its visibility curve (failure_measures.h: curveFlicker) as light_pinned_flicker
    // and snapped_pinned_flicker, the number `animate`'s flicker trace shows for that point, and
    // the curve itself, one row per frame (x = frame): light_pinned_visibility and
    // snapped_pinned_visibility.
    std::optional<glm::ivec2> pinnedPixel;
    // The camera's sub-pixel jitter for the shimmer frames when pinnedPixel is set: a viewer's
    // pinned point sits on its pixel's centre under that jitter (app/session.h: Session::jitter),
    // so the pixel's curve is the point's. 0: the plain camera (`--pixel` on the command line).
    glm::vec2 pinnedJitter{0.0f};
};

// The shimmer sweep's shadow fit for frame t: the scene's fit (`fitted`) shrunk by 2 texels a
// side, so that a slide of up to a texel and a half never pushes the scene past the map's edge,
// then slid by (t, t) / SHIMMER_STEPS texels and snapped with `snap` (light.h: shiftShadowOrigin).
// `animate --sweep light` renders with the very same fits.
glm::mat4 shimmerShadowFit(const glm::mat4& fitted, int mapSize, int frame, bool snap);

// The camera slid right and up by `pixels` (a pixel measured at the distance of its target in a
// frame `frameHeight` pixels tall): the camera shimmer sweep's frames, and `animate --sweep
// camera`'s.
Camera cameraSlidByPixels(const Camera& camera, int frameHeight, float pixels);

// --quick: 160x90 frame, 128 map, 1x1 truth sample, 6 elevations, 3 leak biases, 3 camera frames,
// 3 depth ranges, 2 or 3 points of each pcss sweep, 2 gaps, 2 cascade lambdas over a path of 4
// steps; the methods nearest and pcf-gather N=3, and for bleed vsm N=3 over 4 light-bleeding
// reductions.
StabilityOptions quickStabilityOptions();

// Why the options cannot run, nullopt when they can: one sentence naming the option list at fault
// as its field's words ("elevations", "leak_biases"), which the command line says as flags
// (app/cli_util.h: cliWords).
std::optional<ParamProblem> validateStabilityOptions(const StabilityOptions& options);

// One measured point: the columns of stability.csv, in order.
struct StabilityRow {
    std::string sweep;  // sweepName
    int method = -1;    // -1: not per method (aliasing), written "-"
    int kernel = 0;
    std::string bias;   // biasModeName, or "-" (aliasing)
    std::string xName;  // e.g. "elevation_deg", "constant_bias", "texel_step", "depth_range"
    double x = 0.0;
    std::string metric;  // e.g. "false_shadow_rate", "pole:leak_width_texels", "light_p99"
    double y = 0.0;
};

struct StabilityImage {
    std::string name;  // file name, e.g. "aliasing_heatmap.png"
    glm::ivec2 size{0, 0};
    std::vector<uint8_t> rgba;  // rows top-down
};

struct StabilityContext {
    const Scene* scene = nullptr;  // acne, shimmer, precision, aliasing run on it
    // A line of progress ("acne 3/12: 45 deg"), on the calling thread.
    std::function<void(const std::string&)> progress;
};

struct StabilityResult {
    std::vector<StabilityRow> rows;
    std::vector<StabilityImage> images;
};

// Runs the sweeps in the options' order. Needs a current OpenGL 4.5 context. Throws
// std::invalid_argument when validateStabilityOptions objects or the scene is missing.
StabilityResult runStability(const StabilityContext& context, const StabilityOptions& options);

// Reach of a method's footprint from the lookup point, in texels (how far a real shadow edge
// can darken it): (N + 1) / 2 for the N x N filters, 1 for the 2x2 ones, radius + 0.5 for
// poisson, 0.5 for nearest.
float footprintReachTexels(const StabilityMethod& m, float poissonRadius);

// Pixels per texel from a light-space readback (4 floats per pixel, top-down, alpha 1 on
// receivers) for a mapSize map: per pixel 1 / |det J|, or -1 where it cannot be measured (not
// a receiver, no receiver neighbour, or a jump of more than 32 texels to it).
std::vector<float> pixelsPerTexel(const std::vector<float>& lightSpace, glm::ivec2 frameSize,
                                  int mapSize);
// The Jacobian J itself per pixel: its columns the texel-space steps (mapSize texels per uv unit)
// to the next pixel right and up, where both are measured (as above), nullopt elsewhere.
std::vector<std::optional<glm::mat2>> texelJacobians(const std::vector<float>& lightSpace,
                                                     glm::ivec2 frameSize, int mapSize);

// The heat map's colour of one pixels-per-texel value (aliasing_heatmap.png and the viewer's A
// key): log2 of it from -4 (deep blue: 16 texels per pixel) through white (one texel per pixel)
// to +4 (deep red: one texel over 16 pixels), clamped beyond; RGB in [0,1].
constexpr float ALIASING_HEAT_LOG2_RANGE = 4.0f;
glm::vec3 aliasingHeatColour(float pixelsPerTexel);
// The colour of a value not measured (-1 from pixelsPerTexel).
constexpr glm::vec3 ALIASING_HEAT_NONE{0.55f, 0.55f, 0.55f};

}  // namespace pcf
