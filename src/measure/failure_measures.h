// failure_measures.h: the measures of where a filter fails, shared by `bench` (bench.h) and the
// stability sweeps (stability.h), so both split a picture's error the same way:
//
//   clean lit    the truth says fully lit at the pixel AND at every point of a grid spanning
//                +-reach texels of the map around it (footprintPoints, below): a filter
//                may not darken it at all; where it does, that is false shadow (acne), a bias
//                error, not the filter's legitimate penumbra next to a real edge.
//   clean umbra  the same for fully shadowed: where a filter lights it, that is false light
//                (a leak, peter panning).
//   shimmer      |v(t) - v(t-1)| between frames whose shadow-map grid slid by a sub-texel step
//                under a still world, over the compared pixels; and over the FLICKERING ones
//                only (whose value changes visibly, by more than 1/512, in any frame pair).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "measure/error_metrics.h"
#include "measure/ground_truth.h"
#include "scene/raycast.h"
#include "scene/scene.h"

namespace pcf {

// A clean lit pixel darker than this shows false shadow; a clean umbra pixel brighter than
// LEAK_LEVEL shows false light.
constexpr float FULLY_LIT_LEVEL = 0.99f;
constexpr float LEAK_LEVEL = 0.01f;
// A change a display can show: half a step of an 8-bit channel. Smaller ones (float rounding of
// the filter weights as the grid slides, ~1e-7) do not make a pixel flicker.
constexpr float VISIBLE_CHANGE = 1.0f / 512.0f;
constexpr int FOOTPRINT_GRID = 3;  // footprint test points per side

// The camera's hit at each pixel centre, rows top-down like the truth; `threads` 0 = all cores.
std::vector<std::optional<Hit>> centreHits(const Scene& scene, glm::ivec2 size, int threads);

// 1 where the pixel is compared (error_metrics.h) and the truth is `wantLit` (fully lit, or
// fully shadowed) at the pixel and over its whole footprint: +-reachTexels of a mapSize map
// whose clip transform is shadowClip. With stride > 1 only the pixels whose x and y are both
// multiples of it are tested (the others are 0): a share measured over them is an unbiased
// sample at 1/stride^2 of the ray casts.
std::vector<uint8_t> cleanPixelMask(const Scene& scene, const GroundTruth& truth,
                                    const ErrorRegions& regions,
                                    const std::vector<std::optional<Hit>>& hits,
                                    const glm::mat4& shadowClip, int mapSize, float reachTexels,
                                    bool wantLit, int threads, int stride = 1);

struct FailureRate {
    double share = 0.0;  // of the mask's pixels, those that fail
    double mean = 0.0;   // false shadow: mean darkening 1 - v; false light: mean v
    int count = 0;       // the mask's pixels
};

// Over a clean lit mask: the share with v < FULLY_LIT_LEVEL and the mean darkening 1 - v.
FailureRate falseShadow(const std::vector<float>& visibility, const std::vector<uint8_t>& cleanLit);
// Over a clean umbra mask: the share with v > LEAK_LEVEL and the mean v.
FailureRate falseLight(const std::vector<float>& visibility,
                       const std::vector<uint8_t>& cleanUmbra);

// The leak's width, robustly: a leaking pixel (clean umbra, v > LEAK_LEVEL) counts only when it
// belongs to a connected run (8-neighbours, so a one-pixel diagonal band holds together) of at
// least LEAK_MIN_RUN leaking pixels. Why 8: the strays the default run showed are single pixels
// (a leak rate of 0.0003 of 3287 clean umbra pixels is one pixel) at widths of 32 and 101
// texels, while a real leak is a band along the contact, some 190 pixels at the default frame
// (5.75 % of 3287); 8 lies well between, and at --quick's 160x90 frame a one-texel band along a
// contact is still more than 8 pixels (about 4.6 pixels per texel there).
constexpr int LEAK_MIN_RUN = 8;

struct LeakWidth {
    double texels = 0.0;  // the largest distance from the caster of a counted pixel, map texels
    double world = 0.0;   // the same in world units
    int support = 0;      // the counted pixels (in runs of >= minRun)
    int stray = 0;        // leaking pixels left out (in shorter runs)
};

// Over the frame (size.x * size.y pixels, rows top-down): leaking pixels are those of the umbra
// mask with visibility > LEAK_LEVEL; texels / world give each pixel's distance from the caster.
// A mask tested on every stride-th pixel only (cleanPixelMask's stride) is connected at that
// stride: a pixel's neighbours are the tested pixels around it, stride pixels away.
LeakWidth leakWidth(const std::vector<float>& visibility, const std::vector<uint8_t>& cleanUmbra,
                    const std::vector<float>& texels, const std::vector<float>& world,
                    glm::ivec2 size, int minRun = LEAK_MIN_RUN, int stride = 1);

// Per pixel (rows top-down, the truth's size), how far the surface seen at its centre lies from
// the nearest caster (nearestCasterPoint): in world units, and in texels of a mapSize map whose
// clip transform is shadowClip (the two points' map positions apart). Filled only where leakWidth
// reads them: compared pixels the truth calls fully shadowed (visibility 0) with a caster near;
// 0 elsewhere.
struct CasterDistances {
    std::vector<float> world;
    std::vector<float> texels;
};
CasterDistances casterDistances(const Scene& scene, const GroundTruth& truth,
                                const ErrorRegions& regions,
                                const std::vector<std::optional<Hit>>& hits,
                                const glm::mat4& shadowClip, int mapSize);

struct ShimmerStats {
    double mean = 0.0;          // mean |dv| over the compared pixels of every frame pair
    double p99 = 0.0;           // its 99th percentile
    double flickerShare = 0.0;  // share of the compared pixels that flicker
    double flickerMean = 0.0;   // mean |dv| over the flickering pixels of every frame pair
    double flickerP99 = 0.0;    // its 99th percentile
    double max = 0.0;           // the largest |dv|
    // The 99th percentile over the mask's pixels of each pixel's LARGEST |dv| over the frame
    // pairs. The mean over a fixed population cannot tell a hard edge from a soft one: as an
    // edge of height 1 slides by d, the changes |v(x + d) - v(x)| add up to d whatever its
    // profile. How far single pixels jump can: a hard edge's crossing pixels jump by 1, a
    // 5x5 ramp's by a sliver.
    double peakP99 = 0.0;
};

// frames: visibilities of consecutive frames (each the compared mask's size); fewer than two
// frames give zeros.
ShimmerStats shimmerStats(const std::vector<std::vector<float>>& frames,
                          const std::vector<uint8_t>& compared);

// One point's flicker: the mean of |v(t) - v(t-1)| along its visibility curve across a sweep's
// frames (0 for fewer than two). Over every compared pixel's curve, the mean of these is
// shimmerStats' `mean` (each curve has the same number of frame pairs). The flicker trace of
// `animate` prints it for its pinned point; `stability --pixel` writes it as *_pinned_flicker.
double curveFlicker(const std::vector<float>& curve);

// The mean of `values`; 0 when empty.
double meanOf(const std::vector<float>& values);

// The q-quantile (0..1, nearest rank) of `values` (reordered); 0 when empty.
double quantileOf(std::vector<float>& values, double q);

// The surface points a +-reachTexels grid (gridSide x gridSide points) around `hit` covers in
// the shadow map: each grid point moved across the map's plane and carried along the light
// onto the plane of the hit's surface. Empty when the surface is edge-on to the light.
std::vector<glm::vec3> footprintPoints(const Scene& scene, const glm::mat4& shadowClipFromWorld,
                                       int mapSize, glm::vec3 posWs, glm::vec3 normalWs,
                                       float reachTexels, int gridSide);

// The nearest point of any caster that is not a plane (a box, a sphere) to p, or nullopt when
// there is none: on the ground, the nearest point of a standing caster's contact line.
std::optional<glm::vec3> nearestCasterPoint(const Scene& scene, glm::vec3 p);

// 1 where `pixels` is 1 and the surface seen at the pixel centre (hits, rows top-down) lies
// within `distance` world units of a caster (nearestCasterPoint): the pixels near a contact.
std::vector<uint8_t> nearContactMask(const Scene& scene,
                                     const std::vector<std::optional<Hit>>& hits,
                                     std::span<const uint8_t> pixels, float distance);

}  // namespace pcf
