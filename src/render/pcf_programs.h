// pcf_programs.h: GL programs that run the shared PCF kernel, one per set of the defines that
// select its code (PcfVariant), compiled on first use and kept.
#pragma once

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "kernel/pcf.h"
#include "kernel/settings.h"
#include "render/gl_objects.h"

namespace pcf {

// The shared kernel's files, in the order GLSL needs them (each uses what the ones before it
// declare; src/kernel/pcf_shared.h includes them so in C++), then `after` (relative to shaders/).
std::vector<std::string> pcfSharedFiles(std::vector<std::string> after = {});

// Everything that picks which code of the kernel a fragment runs. Each is a define of the
// program, not a uniform (issue 23): llvmpipe runs every side of a branch on a uniform under a
// lane mask, so a uniform choice costs the bodies of all its choices on every fragment; as a
// define the driver folds the choice and keeps one body. One program per variant used.
//   PCF_METHOD, PCF_KERNEL      the method and N (pcf_filter.h's pcfFilterRef dispatch)
//   PCF_WEIGHTS                 PCF_WEIGHTS_*: pcf-naive's and pcf-gather's box or weighted path
//   PCF_PRECISION               PCF_PRECISION_*: the texture unit's model (mapPrecision)
//   PCF_FIXED_POINT             1 for a 16/24-bit depth map: D_ref clamped (mapFixedPoint)
//   PCF_ROTATE_PER_PIXEL        1: poisson's disk turned per lookup, by its texel
//   (pcfTexelRotation)
//   PCF_MAP_LAYERS              the map's layers: the length of uPcfMapLayers
//   PCF_CASCADE_BLEND           1: cascades with a blend band (cascade_blend > 0)
struct PcfVariant {
    int method = 0;
    int kernel = 3;
    int weights = 0;
    int precision = 0;
    int fixedPoint = 0;
    int rotatePerPixel = 0;
    int perspective = 0;  // pcss under a spot: depth made linear (a uniform would cost every tap)
    int layers = 1;
    // Cascades with a blend band (--cascade-blend > 0): the camera pass also filters the next
    // cascade in the band (scene.frag). A define, since llvmpipe pays for a branch's body on
    // every fragment even when no fragment takes it.
    int cascadeBlend = 0;

    auto key() const {
        return std::make_tuple(method, kernel, weights, precision, fixedPoint, rotatePerPixel,
                               perspective, layers, cascadeBlend);
    }
    bool operator<(const PcfVariant& o) const { return key() < o.key(); }
};

// The variant that runs these parameters on this map (its texel kind and layer count).
PcfVariant pcfVariant(const PcfParams& prm, bool rotatePerPixel, const MapSpec& map);

// Sets the uniform array uPcfMapLayers of `program` (declared by paramUniformsGlsl, one entry
// per layer, PcfMapLayer of shaders/shared/pcf_kernel.h) from the map's layers.
void setMapUniforms(GLuint program, const MapSpec& map);

// The "#define NAME VALUE" lines of a variant, in PcfVariant's order.
std::string pcfVariantDefines(const PcfVariant& variant);

// The GLSL a stage that filters gets from the parameter table (kernel/settings.h) and the
// variant, between the kernel and the stage: a declaration of each table uniform (float for a
// float parameter, int for the others), of the map's layers (uPcfMapLayers[PCF_MAP_LAYERS],
// setMapUniforms) and of uPenumbraScale (pcss's light in the map, not a setting), and the two
// structs the kernel filters with, built from the variant's defines, the
// uniforms and what the stage gives:
//   PcfParams pcfProgramParams(vec2 rotation)    PCF_METHOD, PCF_KERNEL, PCF_WEIGHTS, rotation,
//                                                uPenumbraScale, and every PcfParams member the
//                                                table's uniforms fill
//   PcfBias pcfProgramBias(int mode, vec2 dzduv) mode, dzduv and every PcfBias member the
//                                                table's uniforms fill
// A parameter added to the table with a uniform and a kernel member reaches both programs
// (lookup.frag, scene.frag) with no edit to them.
std::string paramUniformsGlsl();

// Where a program reads the table's uniforms: one location per row of allParams(), -1 for a
// row with no uniform or one the program does not read, and pcss's two uniforms. Looked up once
// per program (PcfProgramCache keeps them with it), not by name on every draw.
struct ParamUniformLocations {
    std::vector<GLint> params;
    GLint penumbraScale = -1;
    GLint pcssDepthRange = -1;
    GLint evsmExponents = -1;
    GLint pcssReciprocals = -1;  // pcss: the table of 1 / k (pcf_prelude.h)
};
ParamUniformLocations paramUniformLocations(GLuint program);

// A program of a PcfProgramCache and where it reads the table's uniforms.
struct PcfProgram {
    GlProgram program;
    ParamUniformLocations uniforms;
    GLuint id() const { return program.id(); }
};

// Sets the table's uniforms in `program` (a location of -1, a uniform the program does not use,
// is skipped by GL): one that fills a kernel member from that member of prm or bias, the others
// from `settings` (the scene pass's per-lookup bias; skipped without settings, as in the lookup
// pass, which reads its ref from its input). Numbers as their type, flags and names as int.
// uPenumbraScale and uPcssDepthRange from prm.
void setParamUniforms(const PcfProgram& program, const PcfParams& prm, const PcfBias& bias,
                      const ShadowSettings* settings = nullptr);
// The same for a program of no cache (a reference pass), its locations looked up first.
void setParamUniforms(GLuint program, const PcfParams& prm, const PcfBias& bias,
                      const ShadowSettings* settings = nullptr);

// The files of a fragment stage that filters: prelude, kernel, shading, the table's uniforms
// (paramUniformsGlsl), then the stage itself, with the variant's defines (docs/architecture.md,
// "One kernel for the CPU and the GPU": #version, defines, prelude, kernel, stage).
class PcfProgramCache {
  public:
    // extraDefines: more "#define NAME VALUE" lines for every program of this cache.
    PcfProgramCache(std::string vertexFile, std::string fragmentFile,
                    std::string extraDefines = "");

    // The program for this variant; compiles it (and looks up its uniforms) the first time.
    // Throws std::runtime_error with the driver's log (file:line) if the GLSL does not build.
    const PcfProgram& get(const PcfVariant& variant);

  private:
    std::string mVertexFile;
    std::string mFragmentFile;
    std::string mExtraDefines;
    std::map<PcfVariant, PcfProgram> mPrograms;
};

// Binds the shadow map the way pcf_prelude.h expects it: unit 0 = uPcfDepth (nearest, no
// comparison: texel reads), unit 1 = uPcfCompare (GL_LINEAR, GL_LEQUAL comparison), the same
// texture on both. Sets the two sampler uniforms of `program` (which must be in use).
struct PcfSamplers {
    GlSampler nearest;
    GlSampler compare;
};
PcfSamplers createPcfSamplers();
void bindShadowMap(GLuint program, GLuint depthTexture, const PcfSamplers& samplers);
// The same with the map the kernel reads apart from the depth texture the comparison sampler
// takes: a moments map (unit 0, nearest) beside the light's depths (unit 1, compare).
void bindShadowMap(GLuint program, GLuint mapTexture, GLuint depthTexture,
                   const PcfSamplers& samplers);

}  // namespace pcf
