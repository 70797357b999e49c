#include "render/gpu_lookup.h"

#include <stdexcept>

namespace pcf {

GpuLookup::GpuLookup()
    : mPrograms("fullscreen.vert", "lookup.frag"),
      mSamplers(createPcfSamplers()),
      mEmptyVao(createVertexArray()) {}

std::vector<float> GpuLookup::run(const ShadowMap& map, std::span<const glm::vec4> lookups,
                                  int width, const PcfParams& prm, bool rotatePerPixel) {
    return run(map, lookups, width, prm, rotatePerPixel,
               PcfBias(PCF_BIAS_CONSTANT, glm::vec2(0.0f), 0.0f), {});
}

std::vector<float> GpuLookup::run(const ShadowMap& map, std::span<const glm::vec4> lookups,
                                  int width, const PcfParams& prm, bool rotatePerPixel,
                                  const PcfBias& bias, std::span<const glm::vec2> dzduv) {
    if (width <= 0 || lookups.empty() || lookups.size() % static_cast<size_t>(width) != 0) {
        throw std::invalid_argument("lookups must fill whole rows of the grid");
    }
    if (!dzduv.empty() && dzduv.size() != lookups.size()) {
        throw std::invalid_argument("dzduv needs one entry per lookup");
    }
    int height = static_cast<int>(lookups.size() / static_cast<size_t>(width));
    GlTexture depth = createDepthTexture(map);
    GlTexture input = createTexture2d(GL_RGBA32F, width, height);
    glTextureSubImage2D(input.id(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, lookups.data());
    std::vector<glm::vec2> planes(dzduv.begin(), dzduv.end());
    if (planes.empty()) planes.assign(lookups.size(), bias.dzduv);
    GlTexture planeTexture = createTexture2d(GL_RG32F, width, height);
    glTextureSubImage2D(planeTexture.id(), 0, 0, 0, width, height, GL_RG, GL_FLOAT, planes.data());
    OffscreenTarget target = createOffscreenTarget(width, height, {GL_R32F});

    GLuint program = mPrograms.get(prm.method, prm.kernel);
    glUseProgram(program);
    bindShadowMap(program, depth.id(), mSamplers);
    glBindTextureUnit(2, input.id());
    glBindSampler(2, mSamplers.nearest.id());
    glProgramUniform1i(program, glGetUniformLocation(program, "uLookups"), 2);
    glBindTextureUnit(3, planeTexture.id());
    glBindSampler(3, mSamplers.nearest.id());
    glProgramUniform1i(program, glGetUniformLocation(program, "uPlanes"), 3);
    glProgramUniform1i(program, glGetUniformLocation(program, "uBiasMode"), bias.mode);
    glProgramUniform1f(program, glGetUniformLocation(program, "uSoftScale"), bias.softScale);
    glProgramUniform1f(program, glGetUniformLocation(program, "uRadius"), prm.radius);
    glProgramUniform1i(program, glGetUniformLocation(program, "uRotatePerPixel"),
                       rotatePerPixel ? 1 : 0);

    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(mEmptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    for (GLuint unit : {0u, 1u, 2u, 3u}) glBindSampler(unit, 0);

    // readPixelsFloat returns rows top-down; the lookups went in GL order.
    std::vector<float> out =
        readPixelsFloat(target.framebuffer.id(), GL_COLOR_ATTACHMENT0, width, height, 1);
    flipRows(out, static_cast<size_t>(width), static_cast<size_t>(height));
    return out;
}

}  // namespace pcf
