// moment_footprint.h: the depths under a moment method's lookup, for the inspector, the trace's
// JSON and the lessons. A moments map holds averages; what the class needs beside them is what
// was averaged: the depth texels the moments pass's blur and the lookup's bilinear read covered,
// with the weight each carries in the moments, and what PCF of those very texels at the same ref
// gives. Both come from the shared kernel run on the depth map the moments were made of.
#pragma once

#include <vector>

#include "kernel/pcf.h"

namespace pcf {

class ShadowMap;
struct Trace;

// One depth texel of the footprint.
struct FootprintTexel {
    ivec2 texel{0};
    float depth = 0.0f;   // as the moments pass read it (the map's sampled value)
    float weight = 0.0f;  // its weight in the filtered moments at the lookup (they sum to 1)
};

// What a moment method's lookup averaged. The moments pass blurs each texel's moments over N x N
// depths (pcfMomentsTexel) and the lookup reads four texels of that bilinearly (pcfMomentsRead):
// together they weigh the (N + 1) x (N + 1) depths round the lookup exactly as pcf-naive's N x N
// bilinear lookups weigh their comparisons (shaders/shared/pcf_moments.h). So the footprint's
// texels and weights are pcf-naive's trace on the depth map (its merged weights), and its
// visibility is PCF of the same footprint at the same ref: what the moments only estimate.
struct MomentFootprint {
    bool present = false;                // filled (a moment method's trace with its depth map)
    std::vector<FootprintTexel> texels;  // each distinct texel once, rows then columns
    int pcfMethod = 0;                   // the PCF method of the same footprint (pcf-naive)
    float pcfVisibility = 1.0f;          // its visibility at the trace's ref
};

// The method whose lookups weigh the depths as the moments pass and its bilinear read do.
int sameFootprintPcfMethod();

// Fills tr.depths from `depthMap`, the depth map tr's moments map was made of (same size; the
// moments pass's input). Nothing for a trace of a method that does not read moments.
void addMomentFootprint(Trace& tr, const ShadowMap& depthMap);

}  // namespace pcf
