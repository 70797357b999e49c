// stability_pcss.h: where percentage-closer soft shadows fail (Fernando, "Percentage-Closer Soft
// Shadows", 2005; the kernel's pcfPcss), four sweeps of stability.h measured against the
// area-light truth (ground_truth.h with `area`) or, for acne, the hard one:
//
//   pcss-thin     a pole thinner than the blocker search's tap spacing, under an 8 degree sun
//                 (x: its width in map texels; the search's radius at the pole's foot is a row of
//                 its own): the share of the truth-shadowed pixels (area truth < 1/2) that pcss
//                 returns as lit
//                 (>= FULLY_LIT_LEVEL), over PCSS_THIN_SHIFTS grids slid by quarter texels (the
//                 mean, the least and the most: the miss flickers as the grid moves), and the
//                 share of them whose miss changes from one grid to the next.
//   pcss-overlap  a plank at height x above a low block that sits under the plank's shadow edge:
//                 the search averages the two blockers' depths, so the penumbra is too narrow
//                 where the plank casts it and too wide where the block does. The penumbra
//                 (0.02 < v < 0.98) pixels pcss draws over those of the truth, and the RMSE
//                 over the pixels either calls penumbra; "alone:" the plank without the block
//                 (pcss's own error), "stacked:" with it.
//   pcss-noise    post-in-sun's post under suns of x degrees: pcss's 16 taps with the disk
//                 rotated per pixel ("rotated:", noise) and not ("fixed:", banding). Over the
//                 truth's penumbra pixels, e = v - truth; roughness = the RMS of e(x+1) - e(x)
//                 over horizontal neighbours both in the penumbra (the truth is smooth there, so
//                 what is left is the pattern of the taps), and the RMSE of e.
//   pcss-bias     the bias a wider filter needs: pcss's filter is poisson of radius w/2, so
//                 poisson at radius x texels on the stability scene (light at
//                 pcssBiasElevation), constant and receiver-plane bias at the run's constant
//                 bias: the false-shadow rate over the clean-lit pixels of that reach (acne
//                 as stability.h measures it).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "measure/stability.h"

namespace pcf {

constexpr int PCSS_THIN_SHIFTS = 4;  // grids 0, 1/4, 1/2, 3/4 texel along the diagonal
constexpr float PCSS_PENUMBRA_LO = 0.02f;
constexpr float PCSS_PENUMBRA_HI = 0.98f;

// The scenes the sweeps build (TOML, scene_file.h), for a test or a viewer to look at: the thin
// pole of width `width` world units; the plank at `height` with or without the low block.
Scene pcssThinPoleScene(float width);
Scene pcssOverlapScene(float height, bool withBlock);

// The pcss options' problem (stability.h's pcss* lists out of range), nullopt when none: part of
// validateStabilityOptions.
std::optional<ParamProblem> validatePcssSweepOptions(const StabilityOptions& options);

// Runs one of the four sweeps above and appends its rows to `rows`; `say` gets a line of
// progress. Needs a current OpenGL 4.5 context; the options are checked by
// validateStabilityOptions.
void runPcssSweep(Sweep sweep, const StabilityOptions& options, const Scene& scene,
                  const std::function<void(const std::string&)>& say,
                  std::vector<StabilityRow>& rows);

}  // namespace pcf
