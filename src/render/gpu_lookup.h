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
    // The map is uploaded in its own format: 32F, or 16/24-bit when map.fixedPointBits() says
    // so (GL rounds the floats to integers); storedMap() then holds what the GPU compared with.
    // Lookups fill a grid `width` wide, row by row from GL row 0; the result has the same order.
    std::vector<float> run(const ShadowMap& map, std::span<const glm::vec4> lookups, int width,
                           const PcfParams& prm, bool rotatePerPixel);

    // The last map run() used, read back as the sampler sees it (depth_readback.h).
    const ShadowMap& storedMap() const { return mStored; }

private:
    ShadowMap mStored;
    PcfProgramCache mPrograms;
    PcfSamplers mSamplers;
    GlVertexArray mEmptyVao;
};

}  // namespace pcf
