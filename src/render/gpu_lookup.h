// gpu_lookup.h: the shared kernel run by the GPU on lookups of our choosing (not a scene's):
// one lookup per pixel of a float target. The parity tests give the GPU and the CPU the very same
// (u, v, ref) and map, and compare what comes back.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "kernel/pcf.h"
#include "kernel/shadow_map.h"
#include "render/pcf_programs.h"

namespace pcf {

class GpuLookup {
  public:
    // Needs a current OpenGL 4.5 context.
    GpuLookup();

    // Visibility of each lookup (u, v, ref; w unused), filtered by the GPU with `prm`
    // (its rotation is ignored: rotate picks pcfTexelRotation of each lookup's uv).
    // The map is uploaded in its own texel kind (map.spec()): 32F, or 16/24-bit (GL rounds the
    // floats to integers); storedMap() then holds what the GPU compared with.
    // Lookups fill a grid `width` wide, row by row from GL row 0; the result has the same order.
    // run() is these four in a row: setMap, setLookups, draw, read.
    std::vector<float> run(const ShadowMap& map, std::span<const glm::vec4> lookups, int width,
                           const PcfParams& prm, bool rotate);
    // The same under a bias mode: lookup k compares per tap as PcfRef(lookup.z, uv, bias) says,
    // with dz/duv = dzduv[k] (empty: bias.dzduv for every lookup).
    std::vector<float> run(const ShadowMap& map, std::span<const glm::vec4> lookups, int width,
                           const PcfParams& prm, bool rotate, const PcfBias& bias,
                           std::span<const glm::vec2> dzduv);

    // The parts of run(), for timing the bare lookup pass (bench.h): upload once, then draw as
    // often as needed, with no upload or readback in the timed part.
    void setMap(const ShadowMap& map);
    // Throws std::invalid_argument unless the lookups fill whole rows of a `width`-wide grid
    // (and dzduv, when given, has one entry per lookup; empty: planeForAll for every lookup).
    void setLookups(std::span<const glm::vec4> lookups, int width,
                    std::span<const glm::vec2> dzduv = {}, glm::vec2 planeForAll = glm::vec2(0.0f));
    // One full-screen pass of the kernel over the lookups into an R32F target, each lookup
    // compared per tap as PcfRef(lookup.z, uv, bias with its own dz/duv) says. Throws
    // std::logic_error before setMap and setLookups.
    void draw(const PcfParams& prm, bool rotate,
              const PcfBias& bias = PcfBias(PCF_BIAS_CONSTANT, glm::vec2(0.0f), 0.0f,
                                            PCF_DZDUV_UNCLAMPED));
    // The hand-written textbook pass of prm's method (shaders/reference/, no shared kernel;
    // the file is the method table's, kernel/methods.h referencePass) over the same lookups
    // into the same target: what the method itself costs, for timing the kernel's pass against
    // (bench.h, --reference) and checked against the kernel by tests/reference_pass_test.cpp.
    // The plain comparison only (one ref for every tap, a 32F map, no rotation). Throws
    // std::out_of_range for an unknown method (methodInfo), and std::logic_error before setMap
    // and setLookups.
    void drawReference(const PcfParams& prm);

    // The last draw's visibilities, in the lookups' order.
    std::vector<float> read() const;

    // The last map setMap() uploaded, read back as the sampler sees it (depth_readback.h).
    const ShadowMap& storedMap() const { return mStored; }

  private:
    void drawOver(GLuint program);

    ShadowMap mStored;
    // By bias mode (lookup.frag takes it as a define, PCF_LOOKUP_BIAS), made on first use.
    std::map<int, PcfProgramCache> mPrograms;
    // The reference passes by (file, N), made on first use.
    std::map<std::pair<std::string, int>, GlProgram> mReferencePrograms;
    PcfSamplers mSamplers;
    GlVertexArray mEmptyVao;
    GlTexture mDepth;
    GlTexture mInput;
    GlTexture mPlanes;  // RG32F dz/du, dz/dv per lookup (receiver-plane bias)
    OffscreenTarget mTarget;
    int mWidth = 0;
    int mHeight = 0;
};

}  // namespace pcf
