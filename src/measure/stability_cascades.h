// stability_cascades.h: cascaded shadow maps measured one cascade at a time (stability.h's
// cascades sweep). On its own scene (cascadeSweepScene: a long ground, a wall along it whose
// shadow's edge runs away from the camera across every split, posts beside it, a sun from the
// side) with 4 cascades to CASCADE_SWEEP_DISTANCE, for each lambda of the options (0 written as
// the uniform split, 1 as the log split, the others as practical, kernel/cascades.h), each fit
// (box, sphere), snapped or not, along a camera path that turns and moves (cascadePathCamera), per
// cascade:
//   texel_world_min, _max   the extremes of one texel's world size over the path (the layer's
//                           texelWs): a box fit's swings as the camera turns, a sphere's does not
//   flicker_rate            of the static receivers (frame 0's receiver points, every
//                           CASCADE_RECEIVER_STRIDE-th pixel each way) that stay in this cascade
//                           and inside its map (CASCADE_MAP_MARGIN texels from its edges) at
//                           every step, the share whose
//                           visibility changes by more than CASCADE_FLICKER_STEP between any two
//                           steps (the shimmer sweep's 1/512)
//   seam_difference         on frame 0, the largest jump of visibility across the split at this
//                           cascade's far end (seamProbe), without a blend band, and with the
//                           options' band (seam_difference_blended); none for the last cascade
//   texels_per_pixel_median on frame 0, the cascade's measured texel density (cascade_density.h,
//                           the area ratio) over the receivers that read it
// Bias mode normal (its texels are the cascade's own) with the run's constant bias and offset.
// The rows (stability.csv, x_name "lambda") name the fit, the snap and the cascade in the
// metric, "sphere:snap:c2:flicker_rate"; stability_cascades.csv lays them out one line per
// cascade (cascadeCsv).
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/shadow_map.h"
#include "measure/stability.h"
#include "scene/cascade_fit.h"

namespace pcf {

constexpr int CASCADE_SWEEP_CASCADES = 4;
constexpr float CASCADE_SWEEP_DISTANCE = 60.0f;  // the shadow distance, scene units
constexpr int CASCADE_RECEIVER_STRIDE = 2;
constexpr float CASCADE_FLICKER_STEP = 1.0f / 512.0f;
constexpr float CASCADE_MAP_MARGIN = 4.0f;  // texels

// The sweep's scene and its camera at `step` of `steps` along the path: from the scene's camera
// it turns by CASCADE_PATH_TURN_DEG about the vertical, steadily, and walks forward and sideways.
// The turn runs from where a box fit's square is widest toward where it is narrowest under the
// scene's sun (about 1.25x to 1.3x apart), so that the swing shows within one path.
constexpr float CASCADE_PATH_TURN_DEG = 45.0f;
Scene cascadeSweepScene();
Camera cascadePathCamera(const Camera& start, int step, int steps);

// A frame's surfaces as the renderer read them back (top-down, 4 floats per pixel each): the
// light-space target (alpha 1 on receivers), the world positions, the normals with cos(theta).
struct FrameSurfaces {
    glm::ivec2 size{0, 0};
    std::vector<float> lightSpace;
    std::vector<float> positions;
    std::vector<float> normals;
};

// The seam probe at the split between cascade i and i + 1 (i < layers - 1): every receiver of
// the frame that lies within CASCADE_SEAM_REACH of the split's view depth (a share of it) from
// the split along its own surface, is moved along that surface onto the split (a surface seen
// edge-on, whose view depth barely changes along it, is left out), and looked up from both sides at
// the split's view depth: as the last depth of cascade i (its lookup, blended with cascade i + 1's
// by the band's weight there, pcfCascadeBlendWeight) and as the first of cascade i + 1 (its lookup
// alone). `difference`: the largest |left - right| over the points, `points` how many, `edgePoints`
// how many lie on a shadow edge (either side strictly between 0.02 and 0.98, or the two differing
// by more than 0.02). With a band the two sides meet; without, they differ where the cascades'
// texels draw the edge differently.
constexpr float CASCADE_SEAM_REACH = 0.05f;
struct SeamProbe {
    double difference = 0.0;
    int points = 0;
    int edgePoints = 0;
};
SeamProbe seamProbe(const ShadowMap& map, const Camera& camera, const ShadowSettings& s,
                    const PcfParams& prm, const FrameSurfaces& frame, int split);

// The cascade options' problem (a lambda outside [0, 1], fewer than 2 path steps, a blend band
// outside (0, 1], no method of the run that cascades work with: cascadeProblem), nullopt when
// none: part of validateStabilityOptions.
std::optional<ParamProblem> validateCascadeOptions(const StabilityOptions& options);

// Runs the sweep with the run's methods that cascades work with and appends its rows. Needs a
// current OpenGL 4.5 context.
void runCascadeSweep(const StabilityOptions& options,
                     const std::function<void(const std::string&)>& say,
                     std::vector<StabilityRow>& rows);

// One line of stability_cascades.csv.
struct CascadePoint {
    int method = -1;
    int kernel = 0;
    double lambda = 0.0;
    std::string fit;  // "box", "sphere"
    bool snap = false;
    int cascade = 0;
    double texelWorldMin = 0.0;
    double texelWorldMax = 0.0;
    double flickerRate = 0.0;
    double staticReceivers = 0.0;
    std::optional<double> seamDifference;  // none for the last cascade
    std::optional<double> seamDifferenceBlended;
    double texelsPerPixelMedian = 0.0;
};

// The split scheme a lambda is written as: "uniform" (0), "log" (1), "practical".
std::string_view cascadeSplitOfLambda(double lambda);

// The cascades rows' points, in the rows' order.
std::vector<CascadePoint> cascadePoints(std::span<const StabilityRow> rows);

inline constexpr std::string_view CASCADE_CSV_NAME = "stability_cascades.csv";
inline constexpr std::string_view CASCADE_CSV_HEADER =
    "method,kernel,split,lambda,fit,snap,cascade,texel_world_min,texel_world_max,flicker_rate,"
    "static_receivers,seam_difference,seam_difference_blended,texels_per_pixel_median";

// The header, then one line per point (9 significant digits; an empty seam for the last
// cascade).
std::string cascadeCsv(std::span<const StabilityRow> rows);

}  // namespace pcf
