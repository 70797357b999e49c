#include "render/depth_readback.h"

#include <vector>

#include "render/gl_objects.h"
#include "render/shader_loader.h"

namespace pcf {

ShadowMap readSampledDepth(GLuint texture, int width, int height, int fixedPointBits) {
    GlProgram program = buildProgram({
        ShaderStage{GL_VERTEX_SHADER, {"fullscreen.vert"}, "", {}},
        ShaderStage{GL_FRAGMENT_SHADER, {"depth_fetch.frag"}, "", {}},
    });
    OffscreenTarget target = createOffscreenTarget(width, height, {GL_R32F});
    GlVertexArray vao = createVertexArray();
    GlSampler nearest = createNearestSampler();
    GLint oldFramebuffer = 0;
    GLint oldViewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &oldFramebuffer);
    glGetIntegerv(GL_VIEWPORT, oldViewport);
    GLboolean depthTest = glIsEnabled(GL_DEPTH_TEST);
    GLboolean blend = glIsEnabled(GL_BLEND);

    glUseProgram(program.id());
    glBindTextureUnit(0, texture);
    glBindSampler(0, nearest.id());
    glProgramUniform1i(program.id(), glGetUniformLocation(program.id(), "uDepth"), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(0, 0);

    // readPixelsFloat returns rows top-down; ShadowMap keeps GL row order.
    std::vector<float> depths =
        readPixelsFloat(target.framebuffer.id(), GL_COLOR_ATTACHMENT0, width, height, 1);
    flipRows(depths, static_cast<size_t>(width), static_cast<size_t>(height));
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(oldFramebuffer));
    glViewport(oldViewport[0], oldViewport[1], oldViewport[2], oldViewport[3]);
    if (depthTest) glEnable(GL_DEPTH_TEST);
    if (blend) glEnable(GL_BLEND);
    ShadowMap map(width, height, std::move(depths));
    map.setFixedPointBits(fixedPointBits);
    return map;
}

float unormDepthAsSampled(uint32_t k, int bits) {
    float scale = 1.0f / static_cast<float>((1u << bits) - 1u);
    return static_cast<float>(k) * scale;
}

}  // namespace pcf
