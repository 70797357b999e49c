#include "render/depth_readback.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "render/gl_objects.h"
#include "render/render_settings.h"
#include "render/shader_loader.h"

namespace pcf {

namespace {

// A float target of as many channels as the map's texels.
GLenum floatTargetFormat(int channels) {
    static const GLenum FORMATS[] = {GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F};
    return FORMATS[std::clamp(channels, 1, 4) - 1];
}

}  // namespace

namespace {

// One 2D texture's texels as texelFetch returns them, `channels` floats each, GL row order.
std::vector<float> readSampledTexels(GLuint texture, int width, int height, int channels) {
    GlProgram program = buildProgram({
        ShaderStage{GL_VERTEX_SHADER, {"fullscreen.vert"}, "", {}},
        ShaderStage{GL_FRAGMENT_SHADER, {"depth_fetch.frag"}, "", {}},
    });
    OffscreenTarget target = createOffscreenTarget(width, height, {floatTargetFormat(channels)});
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
    std::vector<float> texels =
        readPixelsFloat(target.framebuffer.id(), GL_COLOR_ATTACHMENT0, width, height, channels);
    flipRows(texels, static_cast<size_t>(width) * channels, static_cast<size_t>(height));
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(oldFramebuffer));
    glViewport(oldViewport[0], oldViewport[1], oldViewport[2], oldViewport[3]);
    if (depthTest) glEnable(GL_DEPTH_TEST);
    if (blend) glEnable(GL_BLEND);
    return texels;
}

}  // namespace

ShadowMap readSampledDepth(GLuint texture, const MapSpec& map) {
    if (auto why = checkMapSpec(map)) throw std::invalid_argument(*why);
    int channels = map.texel().channels;
    if (map.layers.size() == 1) {
        return ShadowMap(map, readSampledTexels(texture, map.size.x, map.size.y, channels));
    }
    // An array texture (cascades): each layer through a 2D view of it, layer after layer.
    std::vector<float> texels;
    for (size_t k = 0; k < map.layers.size(); ++k) {
        GlTexture view = textureLayerView(texture, glTexelFormat(map.texels), static_cast<int>(k));
        std::vector<float> layer = readSampledTexels(view.id(), map.size.x, map.size.y, channels);
        texels.insert(texels.end(), layer.begin(), layer.end());
    }
    return ShadowMap(map, std::move(texels));
}

float unormDepthAsSampled(uint32_t k, int bits) {
    float scale = 1.0f / static_cast<float>((1u << bits) - 1u);
    return static_cast<float>(k) * scale;
}

}  // namespace pcf
