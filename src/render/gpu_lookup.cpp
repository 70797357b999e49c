#include "render/gpu_lookup.h"

#include <stdexcept>
#include <string>

#include "kernel/methods.h"
#include "render/depth_readback.h"
#include "render/shader_loader.h"

namespace pcf {

GpuLookup::GpuLookup() : mSamplers(createPcfSamplers()), mEmptyVao(createVertexArray()) {}

std::vector<float> GpuLookup::run(const ShadowMap& map, std::span<const glm::vec4> lookups,
                                  int width, const PcfParams& prm, bool rotatePerPixel) {
    return run(map, lookups, width, prm, rotatePerPixel,
               PcfBias(PCF_BIAS_CONSTANT, glm::vec2(0.0f), 0.0f, PCF_DZDUV_UNCLAMPED), {});
}

std::vector<float> GpuLookup::run(const ShadowMap& map, std::span<const glm::vec4> lookups,
                                  int width, const PcfParams& prm, bool rotatePerPixel,
                                  const PcfBias& bias, std::span<const glm::vec2> dzduv) {
    setMap(map);
    setLookups(lookups, width, dzduv, bias.dzduv);
    draw(prm, rotatePerPixel, bias);
    return read();
}

// The map is uploaded in its own texel kind: 32F, or 16/24-bit (GL rounds the floats to
// integers); storedMap() then holds what the GPU compares with.
void GpuLookup::setMap(const ShadowMap& map) {
    mDepth = createDepthTexture(map);
    mStored = readSampledDepth(mDepth.id(), map.spec());
}

void GpuLookup::setLookups(std::span<const glm::vec4> lookups, int width,
                           std::span<const glm::vec2> dzduv, glm::vec2 planeForAll) {
    if (width <= 0 || lookups.empty() || lookups.size() % static_cast<size_t>(width) != 0) {
        throw std::invalid_argument("lookups must fill whole rows of the grid");
    }
    if (!dzduv.empty() && dzduv.size() != lookups.size()) {
        throw std::invalid_argument("dzduv needs one entry per lookup");
    }
    int height = static_cast<int>(lookups.size() / static_cast<size_t>(width));
    mInput = createTexture2d(GL_RGBA32F, width, height);
    glTextureSubImage2D(mInput.id(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, lookups.data());
    std::vector<glm::vec2> planes(dzduv.begin(), dzduv.end());
    if (planes.empty()) planes.assign(lookups.size(), planeForAll);
    mPlanes = createTexture2d(GL_RG32F, width, height);
    glTextureSubImage2D(mPlanes.id(), 0, 0, 0, width, height, GL_RG, GL_FLOAT, planes.data());
    if (mWidth != width || mHeight != height) {
        mTarget = createOffscreenTarget(width, height, {GL_R32F});
        mWidth = width;
        mHeight = height;
    }
}

void GpuLookup::draw(const PcfParams& prm, bool rotatePerPixel, const PcfBias& bias) {
    if (!mDepth || !mInput) throw std::logic_error("GpuLookup::draw before setMap and setLookups");
    auto programs = mPrograms.find(bias.mode);
    if (programs == mPrograms.end()) {
        std::string defines = "#define PCF_LOOKUP_BIAS " + std::to_string(bias.mode) + "\n";
        programs =
            mPrograms.try_emplace(bias.mode, "fullscreen.vert", "lookup.frag", defines).first;
    }
    const PcfProgram& program =
        programs->second.get(pcfVariant(prm, rotatePerPixel, mStored.spec()));
    glUseProgram(program.id());
    setParamUniforms(program, prm, bias);
    drawOver(program.id());
}

// The shadow map, the lookups and the planes bound, one full-screen triangle into the target:
// what the kernel's pass and the reference passes share.
void GpuLookup::drawOver(GLuint program) {
    bindShadowMap(program, mDepth.id(), mSamplers);
    glBindTextureUnit(2, mInput.id());
    glBindSampler(2, mSamplers.nearest.id());
    glProgramUniform1i(program, glGetUniformLocation(program, "uLookups"), 2);
    glBindTextureUnit(3, mPlanes.id());
    glBindSampler(3, mSamplers.nearest.id());
    glProgramUniform1i(program, glGetUniformLocation(program, "uPlanes"), 3);
    glBindFramebuffer(GL_FRAMEBUFFER, mTarget.framebuffer.id());
    glViewport(0, 0, mWidth, mHeight);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(mEmptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    for (GLuint unit : {0u, 1u, 2u, 3u}) glBindSampler(unit, 0);
}

void GpuLookup::drawReference(const PcfParams& prm) {
    if (!mDepth || !mInput) {
        throw std::logic_error("GpuLookup::drawReference before setMap and setLookups");
    }
    // The method's reference pass and its N, from its entry in the method table.
    const MethodInfo& m = methodInfo(prm.method);
    auto key =
        std::make_pair(std::string(m.referencePass), m.referenceTakesKernel ? prm.kernel : 1);
    auto it = mReferencePrograms.find(key);
    if (it == mReferencePrograms.end()) {
        std::string defines = "#define N " + std::to_string(key.second) + "\n";
        GlProgram program = buildProgram({
            ShaderStage{GL_VERTEX_SHADER, {"fullscreen.vert"}, "", {}},
            ShaderStage{GL_FRAGMENT_SHADER, {key.first}, defines, {}},
        });
        it = mReferencePrograms.emplace(key, std::move(program)).first;
    }
    GLuint program = it->second.id();
    glUseProgram(program);
    // The table's uniforms a reference pass reads (uRadius: reference/poisson.frag) and
    // uPenumbraScale (reference/pcss.frag), by the same names as the kernel's pass.
    setParamUniforms(program, prm, pcfPlainRef(0.0f, glm::vec2(0.0f)).bias);
    drawOver(program);
}

std::vector<float> GpuLookup::read() const {
    // readPixelsFloat returns rows top-down; the lookups went in GL order.
    std::vector<float> out =
        readPixelsFloat(mTarget.framebuffer.id(), GL_COLOR_ATTACHMENT0, mWidth, mHeight, 1);
    flipRows(out, static_cast<size_t>(mWidth), static_cast<size_t>(mHeight));
    return out;
}

}  // namespace pcf
