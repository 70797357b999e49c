// ground_truth.h: the exact shadow of an analytic scene, per pixel of the camera's frame: what an
// infinitely fine shadow map (and an infinitely fine filter) would give, with a stated error bound
// per pixel. Every number the bench reports as an error is measured against this.
//
// Definition: the visibility of pixel (x, y) is the fraction of the pixel's square (in window
// coordinates, uniform measure) whose camera ray meets the object seen at the pixel CENTRE at a
// point the light reaches (litByLight), over the part of the square whose ray meets that object
// at all. Parts of the square on another object or on nothing are left out: at a silhouette the
// truth is the shadow on the surface the renderer shaded there (its one sample is the pixel
// centre), not a blend of two surfaces, so the error measures the shadow, not the geometric
// aliasing.
//
// Computed in two passes (threaded by rows):
// 1. First pass: K x K stratified jittered samples per pixel (K = spp, from a fixed hash: the same
//    truth on every run); each is lit, unlit, or off the centre's object.
// 2. Refinement of every pixel where the answer may not be uniform: its own lit samples and
//    unlit samples both occur, any of its 8 neighbours is mixed or has a different uniform
//    answer, or the analytic geometry cannot rule an edge out of the pixel's cone of rays (a
//    shadow edge, a terminator, a spot's rim within reach of the ball that holds every point
//    the pixel sees on its object: ground_truth_edges.h). The last test is conservative, so a
//    sliver too thin for any sample (a terminator grazing a silhouette) is still refined. On
//    such a pixel:
//    - a scanline at height v in [0,1] is cut at every place where the answer may change:
//      inside a pixel every edge of a hard light's answer (a silhouette, a box's edge, the
//      terminator, a shadow's outline, a spot's rim, where two objects cut each other) lies on
//      a conic in the pixel's (x, v), so these are the roots of quadratics in x
//      (ground_truth_conics.h). Each piece between two cuts is read at its middle with the
//      exact ray cast; lit(v) and on(v) are the lit and on-object lengths, exact but for
//      pieces shorter than 1/4096 px (the ray caster's float rounding may misread those), whose
//      lengths are the scanline's error (of lit and of on).
//    - the pixel's integral over v in [0,1] is an adaptive trapezoid rule (the step-halving error
//      estimate of Press et al., "Numerical Recipes", 3rd ed. 2007, 4.2 qtrap, applied per panel
//      as in McKeeman, "Adaptive numerical integration by Simpson's rule", CACM 1962): panels [a,
//      b] with scanlines at a, the middle m and b; per panel a coarse estimate (trapezoid on a, b)
//      and a fine one (on a, m, b), for lit and for on. The first panels end at the conics'
//      critical rows (their tangents along a scanline, their crossings of the pixel's left and
//      right sides and of each other), the widest halved until there are at least 4; then the
//      panel whose estimates differ most is split (two more scanlines, at its quarters) until
//        bound = (sum over panels of 2 |fine - coarse| for lit and for on
//                 + e) / on_total
//      is <= the target (default 1/512), or the pixel has used 513 scanlines (the bound is then
//      what it is, above the target: it says so). The value kept is
//        V = sum of fine lit / sum of fine on
//      e is the integral over v of the scanlines' errors.
//    Why: V - V* = (L - L*) / O + V* (O* - O) / O with V* <= 1, so |V - V*| is at most the lit
//    and on errors over O. Between two critical rows the cuts keep their count and order, so
//    no lit or unlit region begins or ends inside a panel, and lit(v) and on(v) are sums of
//    smooth branches of the conics (at worst a square root at a panel's end, where a conic
//    is tangent to the scanline); halving a panel shrinks the trapezoid error by 4 on smooth
//    parts and by 2^1.5 at a square root, and |e_fine| <= |e_coarse| / 2 gives |e_fine| <=
//    |fine - coarse|; the factor 2 is a margin over rounding and over panels not yet small
//    enough for that. Only the panels that hold an edge's trouble are split.
//    Where an object's edges are not all conics (a sphere receiving another sphere's shadow,
//    a spot's rim on a sphere: quartic curves), its scanline is walked instead: at x = i / 16
//    (i = 0..16), a crossing between two walk points whose states differ found by bisection to
//    1/4096 px (its piece half to each side, its length to the error), and the first panels are
//    the 4 quarters. Assumed there, and not checked: no lit or unlit sliver narrower than
//    1/16 px across the walk, and none between two scanlines.
//    Uniform pixels keep the first pass's 0 or 1 with bound 0.
//
// Rows are TOP-DOWN, like every image pcfscope writes (element (H - 1 - y) * W + x is GL row y).
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"

namespace pcf {

// K: K x K first-pass samples per pixel. 2 is enough to find the edges (the neighbour rule
// catches what slips between them) and keeps the first pass cheap; the bound comes from the
// refinement, not from K.
constexpr int DEFAULT_TRUTH_SPP = 2;
constexpr int MAX_TRUTH_SPP = 64;
// The per-pixel error the refinement aims for: 1/512, a quarter of an 8-bit step.
constexpr float DEFAULT_TRUTH_TARGET_BOUND = 1.0f / 512.0f;
// Refinement scanlines per pixel, at most.
constexpr int MAX_TRUTH_SCANLINES = 513;

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
    // The stated bound on |visibility - exact| per pixel (see the top of this file): 0 where the
    // first pass found the pixel uniform, the refinement's estimate elsewhere.
    std::vector<float> bound;
    int refinedPixels = 0;     // pixels the refinement integrated
    float maxBound = 0.0f;     // the largest bound of the frame
    float targetBound = 0.0f;  // what the refinement aimed for

    size_t index(int x, int rowTopDown) const {
        return static_cast<size_t>(rowTopDown) * static_cast<size_t>(size.x) +
               static_cast<size_t>(x);
    }
    size_t pixelCount() const { return static_cast<size_t>(size.x) * static_cast<size_t>(size.y); }
};

struct GroundTruthOptions {
    int spp = DEFAULT_TRUTH_SPP;  // 1..MAX_TRUTH_SPP
    int threads = 0;              // 0: std::thread::hardware_concurrency()
    // Refine until the bound is at most this (or a pixel used MAX_TRUTH_SCANLINES); <= 0 turns
    // the refinement off (the first pass's mean; bound 1 where its samples disagree: no claim).
    float targetBound = DEFAULT_TRUTH_TARGET_BOUND;
    // The area-light truth: each point's visibility is the fraction of the light's disk it sees
    // (light_visibility.h), integrated over the pixel with the same bound convention (along runs
    // of each scanline on one face: ground_truth_area.h; each point's own bound added). Needs a
    // light with a size (hasSize: a directional light's angular diameter, a spot light's
    // radius). Pixels the geometry proves wholly lit or wholly in the umbra (ground_truth_edges.h,
    // areaState; under a spot only wholly lit) keep 1 or 0 with bound 0.
    bool area = false;
    // The area-light truth with every point's share of the disk sliced into chords
    // (lightVisibleFractionBySlices), not in closed form: the older computation, to compare.
    bool areaBySlices = false;
    // Called on the calling thread, about ten times a second and once at the end, with the
    // number of rows done out of the frame's height.
    std::function<void(int rowsDone, int rows)> progress;
};

// Throws std::invalid_argument for a frame side < 1, spp out of range or a NaN target, and for
// `area` without a light with a size, without a positive target, or with a sphere reaching
// behind a spot light's disk (light_visibility.h: checkSpotDiskCasters). The scene's
// camera must have its clip planes set (presets and scene files do).
GroundTruth computeGroundTruth(const Scene& scene, glm::ivec2 frameSize,
                               const GroundTruthOptions& options = {});

// One pixel of computeGroundTruth's frame, computed alone (the same numbers, bit for bit): for a
// pixel's truth without the frame's cost, e.g. a lesson's or a sweep's one pixel.
struct GroundTruthPixel {
    float visibility;
    float bound;
    bool receiver;
    bool facesLight;
    bool refined;
};
// pixelTopDown: column x, row y counted from the top (as GroundTruth::index). Throws
// std::invalid_argument as computeGroundTruth, and for a pixel outside the frame.
GroundTruthPixel groundTruthAt(const Scene& scene, glm::ivec2 frameSize, glm::ivec2 pixelTopDown,
                               const GroundTruthOptions& options = {});

// Where sample (i, j) of K x K falls inside pixel `pixel`: ((i + jx) / K, (j + jy) / K), the
// jitter (jx, jy) in [0,1) from a hash of pixel, i, j. Offsets in [0,1) from the pixel's
// lower-left corner, GL window coordinates (y up).
glm::vec2 stratifiedSample(glm::ivec2 pixel, int i, int j, int spp);

// The worker count `threads` stands for: itself when > 0, else hardware_concurrency (at least 1).
int resolveThreadCount(int threads);

}  // namespace pcf
