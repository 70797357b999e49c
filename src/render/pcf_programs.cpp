#include "render/pcf_programs.h"

#include "render/shader_loader.h"

namespace pcf {

PcfProgramCache::PcfProgramCache(std::string vertexFile, std::string fragmentFile,
                                 std::string extraDefines)
    : mVertexFile(std::move(vertexFile)),
      mFragmentFile(std::move(fragmentFile)),
      mExtraDefines(std::move(extraDefines)) {}

PcfVariant pcfVariant(const PcfParams& prm, bool rotatePerPixel, bool fixedPoint) {
    return PcfVariant{prm.method,    prm.kernel,         prm.weights,
                      prm.precision, fixedPoint ? 1 : 0, rotatePerPixel ? 1 : 0};
}

std::string pcfVariantDefines(const PcfVariant& variant) {
    auto line = [](const char* name, int value) {
        return std::string("#define ") + name + " " + std::to_string(value) + "\n";
    };
    return line("PCF_METHOD", variant.method) + line("PCF_KERNEL", variant.kernel) +
           line("PCF_WEIGHTS", variant.weights) + line("PCF_PRECISION", variant.precision) +
           line("PCF_FIXED_POINT", variant.fixedPoint) +
           line("PCF_ROTATE_PER_PIXEL", variant.rotatePerPixel);
}

GLuint PcfProgramCache::get(const PcfVariant& variant) {
    auto it = mPrograms.find(variant);
    if (it != mPrograms.end()) return it->second.id();
    std::string defines = pcfVariantDefines(variant) + mExtraDefines;
    GlProgram program = buildProgram({
        ShaderStage{GL_VERTEX_SHADER, {mVertexFile}, "", {}},
        ShaderStage{
            GL_FRAGMENT_SHADER,
            {"shared/pcf_prelude.h", "shared/pcf_kernel.h", "shared/pcf_shading.h", mFragmentFile},
            defines,
            {}},
    });
    GLuint id = program.id();
    mPrograms.emplace(variant, std::move(program));
    return id;
}

PcfSamplers createPcfSamplers() { return {createNearestSampler(), createCompareSampler()}; }

void bindShadowMap(GLuint program, GLuint depthTexture, const PcfSamplers& samplers) {
    glBindTextureUnit(0, depthTexture);
    glBindSampler(0, samplers.nearest.id());
    glBindTextureUnit(1, depthTexture);
    glBindSampler(1, samplers.compare.id());
    glProgramUniform1i(program, glGetUniformLocation(program, "uPcfDepth"), 0);
    glProgramUniform1i(program, glGetUniformLocation(program, "uPcfCompare"), 1);
}

}  // namespace pcf
