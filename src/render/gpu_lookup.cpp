#include "render/gpu_lookup.h"

#include <stdexcept>

#include "render/depth_readback.h"

namespace pcf {

GpuLookup::GpuLookup()
    : mPrograms("fullscreen.vert", "lookup.frag"),
      mSamplers(createPcfSamplers()),
      mEmptyVao(createVertexArray()) {}

std::vector<float> GpuLookup::run(const ShadowMap& map, std::span<const glm::vec4> lookups,
                                  int width, const PcfParams& prm, bool rotatePerPixel) {
    if (width <= 0 || lookups.empty() || lookups.size() % static_cast<size_t>(width) != 0) {
        throw std::invalid_argument("lookups must fill whole rows of the grid");
    }
    int height = static_cast<int>(lookups.size() / static_cast<size_t>(width));
    GlTexture depth = createDepthTexture(map);
    if (map.isFixedPoint()) {
        GLenum format = map.fixedPointBits() == 16 ? GL_DEPTH_COMPONENT16 : GL_DEPTH_COMPONENT24;
        depth = createTexture2d(format, map.width(), map.height());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage2D(depth.id(), 0, 0, 0, map.width(), map.height(), GL_DEPTH_COMPONENT,
                            GL_FLOAT, map.depths().data());
    }
    mStored = readSampledDepth(depth.id(), map.width(), map.height(), map.fixedPointBits());
    GlTexture input = createTexture2d(GL_RGBA32F, width, height);
    glTextureSubImage2D(input.id(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, lookups.data());
    OffscreenTarget target = createOffscreenTarget(width, height, {GL_R32F});

    GLuint program = mPrograms.get(prm.method, prm.kernel);
    glUseProgram(program);
    bindShadowMap(program, depth.id(), mSamplers);
    glBindTextureUnit(2, input.id());
    glBindSampler(2, mSamplers.nearest.id());
    glProgramUniform1i(program, glGetUniformLocation(program, "uLookups"), 2);
    glProgramUniform1f(program, glGetUniformLocation(program, "uRadius"), prm.radius);
    glProgramUniform1i(program, glGetUniformLocation(program, "uRotatePerPixel"),
                       rotatePerPixel ? 1 : 0);
    glProgramUniform1i(program, glGetUniformLocation(program, "uWeights"), prm.weights);
    glProgramUniform1f(program, glGetUniformLocation(program, "uSigma"), prm.sigma);
    glProgramUniform1i(program, glGetUniformLocation(program, "uPcfPrecision"), prm.precision);
    glProgramUniform1i(program, glGetUniformLocation(program, "uPcfFixedPoint"),
                       map.isFixedPoint() ? 1 : 0);

    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(mEmptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    for (GLuint unit : {0u, 1u, 2u}) glBindSampler(unit, 0);

    // readPixelsFloat returns rows top-down; the lookups went in GL order.
    std::vector<float> out =
        readPixelsFloat(target.framebuffer.id(), GL_COLOR_ATTACHMENT0, width, height, 1);
    flipRows(out, static_cast<size_t>(width), static_cast<size_t>(height));
    return out;
}

}  // namespace pcf
