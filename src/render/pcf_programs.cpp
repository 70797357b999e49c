#include "render/pcf_programs.h"

#include "render/shader_loader.h"

namespace pcf {

PcfProgramCache::PcfProgramCache(std::string vertexFile, std::string fragmentFile,
                                 std::string extraDefines)
    : mVertexFile(std::move(vertexFile)),
      mFragmentFile(std::move(fragmentFile)),
      mExtraDefines(std::move(extraDefines)) {}

GLuint PcfProgramCache::get(int method, int kernel) {
    auto key = std::make_pair(method, kernel);
    auto it = mPrograms.find(key);
    if (it != mPrograms.end()) return it->second.id();
    std::string defines = "#define PCF_METHOD " + std::to_string(method) + "\n#define PCF_KERNEL " +
                          std::to_string(kernel) + "\n" + mExtraDefines;
    GlProgram program = buildProgram({
        ShaderStage{GL_VERTEX_SHADER, {mVertexFile}, "", {}},
        ShaderStage{
            GL_FRAGMENT_SHADER,
            {"shared/pcf_prelude.h", "shared/pcf_kernel.h", "shared/pcf_shading.h", mFragmentFile},
            defines,
            {}},
    });
    GLuint id = program.id();
    mPrograms.emplace(key, std::move(program));
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
