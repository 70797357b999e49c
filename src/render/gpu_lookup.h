// gpu_lookup.h: the shared kernel run by the GPU on lookups of our choosing (not a scene's):
// one lookup per pixel of a float target. The parity tests give the GPU and the CPU the very same
// (u, v, ref) and map, and compare what comes back.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "kernel/pcf.h"
#include "kernel/shadow_map.h"
#include "render/pcf_programs.h"

namespace pcf {

class GpuLookup {
public:
    // Needs a current OpenGL 4.5 context.
    GpuLookup();

    // Visibility of each lookup (u, v, ref; w unused), filtered by the GPU with `prm`
    // (its rotation is ignored: rotatePerPixel picks pcfPixelRotation of each lookup's pixel).
    // Lookups fill a grid `width` wide, row by row from GL row 0; the result has the same order.
    std::vector<float> run(const ShadowMap& map, std::span<const glm::vec4> lookups, int width,
                           const PcfParams& prm, bool rotatePerPixel);
    // The same under a bias mode: lookup k compares per tap as PcfRef(lookup.z, uv, bias) says,
    // with dz/duv = dzduv[k] (empty: bias.dzduv for every lookup).
    std::vector<float> run(const ShadowMap& map, std::span<const glm::vec4> lookups, int width,
                           const PcfParams& prm, bool rotatePerPixel, const PcfBias& bias,
                           std::span<const glm::vec2> dzduv);

  private:
    PcfProgramCache mPrograms;
    PcfSamplers mSamplers;
    GlVertexArray mEmptyVao;
};

}  // namespace pcf
