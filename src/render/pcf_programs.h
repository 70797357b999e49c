// pcf_programs.h: GL programs that run the shared PCF kernel, one per (method, kernel size),
// compiled on first use and kept.
#pragma once

#include <map>
#include <string>
#include <utility>

#include "kernel/pcf.h"
#include "render/gl_objects.h"

namespace pcf {

// The files of a fragment stage that filters: prelude, kernel, then the stage itself, with
// PCF_METHOD and PCF_KERNEL defined (DESIGN.md 5: #version, defines, prelude, kernel, stage).
class PcfProgramCache {
  public:
    // extraDefines: more "#define NAME VALUE" lines for every program of this cache.
    PcfProgramCache(std::string vertexFile, std::string fragmentFile,
                    std::string extraDefines = "");

    // The program for this method and kernel size; compiles it the first time. Throws
    // std::runtime_error with the driver's log (file:line) if the GLSL does not build.
    GLuint get(int method, int kernel);

  private:
    std::string mVertexFile;
    std::string mFragmentFile;
    std::string mExtraDefines;
    std::map<std::pair<int, int>, GlProgram> mPrograms;
};

// Binds the shadow map the way pcf_prelude.h expects it: unit 0 = uPcfDepth (nearest, no
// comparison: texelFetch), unit 1 = uPcfCompare (GL_LINEAR, GL_LEQUAL comparison), the same
// texture on both. Sets the two sampler uniforms of `program` (which must be in use).
struct PcfSamplers {
    GlSampler nearest;
    GlSampler compare;
};
PcfSamplers createPcfSamplers();
void bindShadowMap(GLuint program, GLuint depthTexture, const PcfSamplers& samplers);

}  // namespace pcf
