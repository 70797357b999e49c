// ground_truth.h: the exact shadow of an analytic scene, per pixel of the camera's frame: what an
// infinitely fine shadow map (and an infinitely fine filter) would give. Every number the bench
// reports as an error is measured against this.
//
// Per pixel (x, y) of a W x H frame, K x K stratified sub-pixel samples (jittered, one per cell
// of a K x K grid over the pixel's square, from a fixed hash: the same truth on every run):
//   ndc = ((x + sx) / W, (y + sy) / H) * 2 - 1      (GL window coordinates, y up)
//   ray = cameraRay(camera, ndc, W / H);  hit = intersect(scene, ray)
//   bit = litByLight(scene, hit)                     (1 lit, 0 in shadow or facing away)
//   visibility = mean of bit over the samples that hit the object seen at the pixel CENTRE
// Samples that land on another object or on nothing are left out: at a silhouette the truth is
// the shadow on the surface the renderer shaded there (its one sample is the pixel centre), not
// a blend of two surfaces, so the error measures the shadow, not the geometric aliasing. When
// no sample lands on the centre's object, the centre's own bit is used.
//
// Rows are TOP-DOWN, like every image pcfscope writes (element (H - 1 - y) * W + x is GL row y).
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"

namespace pcf {

constexpr int DEFAULT_TRUTH_SPP = 8;  // K: K x K samples per pixel
constexpr int MAX_TRUTH_SPP = 64;

struct GroundTruth {
    glm::ivec2 size{0, 0};
    int spp = 0;  // K of the K x K samples
    // Fraction of the samples on the centre's surface that the light reaches, in [0,1]. 1 where
    // the centre's ray meets nothing (as the renderer's visibility target is off receivers).
    std::vector<float> visibility;
    // 1 where the pixel centre's camera ray hits an object that receives shadows: the pixels the
    // renderer looks the shadow map up for (its light-space target has alpha 1 there).
    std::vector<uint8_t> receiver;
    // 1 where the surface at the pixel centre faces the light (dot(n, toLight) > 0) and lies in
    // a spot's cone. Elsewhere the truth is 0 by shading, whatever a shadow map says.
    std::vector<uint8_t> facesLight;

    size_t index(int x, int rowTopDown) const {
        return static_cast<size_t>(rowTopDown) * static_cast<size_t>(size.x) +
               static_cast<size_t>(x);
    }
    size_t pixelCount() const { return static_cast<size_t>(size.x) * static_cast<size_t>(size.y); }
};

struct GroundTruthOptions {
    int spp = DEFAULT_TRUTH_SPP;  // 1..MAX_TRUTH_SPP
    int threads = 0;              // 0: std::thread::hardware_concurrency()
    // Called on the calling thread, about ten times a second and once at the end, with the
    // number of rows done out of the frame's height.
    std::function<void(int rowsDone, int rows)> progress;
};

// Throws std::invalid_argument for a frame side < 1 or spp out of range. The scene's camera must
// have its clip planes set (presets and scene files do).
GroundTruth computeGroundTruth(const Scene& scene, glm::ivec2 frameSize,
                               const GroundTruthOptions& options = {});

// Where sample (i, j) of K x K falls inside pixel `pixel`: ((i + jx) / K, (j + jy) / K), the
// jitter (jx, jy) in [0,1) from a hash of pixel, i, j. Offsets in [0,1) from the pixel's
// lower-left corner, GL window coordinates (y up).
glm::vec2 stratifiedSample(glm::ivec2 pixel, int i, int j, int spp);

// The worker count `threads` stands for: itself when > 0, else hardware_concurrency (at least 1).
int resolveThreadCount(int threads);

}  // namespace pcf
