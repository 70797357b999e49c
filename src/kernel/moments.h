// moments.h: the moments pass on the CPU: a depth map into the filtered moments map the moment
// methods read (vsm, evsm2, evsm4, msm, msm-hausdorff), texel by texel with the shared kernel's
// pcfMomentsTexel, the same code the GPU's moments pass runs (shaders/moments.frag).
#pragma once

#include "kernel/pcf.h"
#include "kernel/shadow_map.h"

namespace pcf {

// The moments map of `depthMap` for method prm.method (its kernel, weights and exponents), in
// texel kind `kind` (Moments2/4, 16F or 32F: a 16F map's moments are rounded to half floats, as
// the GPU's RG16F / RGBA16F target stores them). Same size and layers as depthMap.
ShadowMap momentsMap(const ShadowMap& depthMap, const PcfParams& prm, TexelKind kind);

// The map `prm.method` reads made of `depthMap`: its moments map (32F) for a moment method,
// depthMap itself for the others.
ShadowMap mapForMethod(const ShadowMap& depthMap, const PcfParams& prm);

// v rounded to the nearest half float (IEEE 754 binary16) and back.
float roundToHalf(float v);

}  // namespace pcf
