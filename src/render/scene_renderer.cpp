#include "render/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "kernel/methods.h"
#include "render/depth_readback.h"
#include "render/shader_loader.h"
#include "scene/cascade_fit.h"
#include "scene/cascade_view.h"
#include "scene/mesh.h"
#include "scene/pcss.h"

namespace pcf {

namespace {

// Where nothing is drawn: a pale grey-blue, so shadows on the ground stand out.
constexpr glm::vec4 BACKGROUND{0.72f, 0.78f, 0.86f, 1.0f};

GLint uniform(GLuint program, const char* name) { return glGetUniformLocation(program, name); }

}  // namespace

SceneRenderer::SceneRenderer(const Scene& scene)
    : mScene(scene),
      mShadowClipFromWorld(pcf::shadowClipFromWorld(scene)),
      mSamplers(createPcfSamplers()) {
    mDepthProgram = buildProgram({
        ShaderStage{GL_VERTEX_SHADER, {"depth.vert"}, "", {}},
        ShaderStage{GL_FRAGMENT_SHADER, {"depth.frag"}, "", {}},
    });
    mDepthSnappedProgram = buildProgram({
        ShaderStage{GL_VERTEX_SHADER, {"depth_snapped.vert"}, "", {}},
        ShaderStage{GL_GEOMETRY_SHADER, {"depth_snapped.geom"}, "", {}},
        ShaderStage{GL_FRAGMENT_SHADER, {"depth_snapped.frag"}, "", {}},
    });
    for (const SceneObject& object : mScene.objects) {
        Mesh mesh = objectMesh(object);
        GpuMesh gpu;
        gpu.vao = createVertexArray();
        gpu.vertices = createBuffer();
        gpu.indices = createBuffer();
        glNamedBufferStorage(gpu.vertices.id(), mesh.vertices.size() * sizeof(Vertex),
                             mesh.vertices.data(), 0);
        glNamedBufferStorage(gpu.indices.id(), mesh.indices.size() * sizeof(std::uint32_t),
                             mesh.indices.data(), 0);
        GLuint vao = gpu.vao.id();
        glVertexArrayVertexBuffer(vao, 0, gpu.vertices.id(), 0, sizeof(Vertex));
        glVertexArrayElementBuffer(vao, gpu.indices.id());
        glEnableVertexArrayAttrib(vao, 0);
        glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, posWs));
        glVertexArrayAttribBinding(vao, 0, 0);
        glEnableVertexArrayAttrib(vao, 1);
        glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, normalWs));
        glVertexArrayAttribBinding(vao, 1, 0);
        gpu.indexCount = static_cast<GLsizei>(mesh.indices.size());
        mMeshes.push_back(std::move(gpu));
    }
}

glm::mat4 SceneRenderer::clipFromWorld() const {
    float aspect = mFrame.height > 0 ? static_cast<float>(mFrame.width) / mFrame.height : 1.0f;
    glm::mat4 clip = pcf::clipFromWorld(mScene.camera, aspect);
    if (!mPick) return clip;
    // The sub-pixel jitter moves ndc by a constant: x' = x + jitter.x * w (clip space).
    return jitterClip(clip, mPick->jitterNdc);
}

glm::mat4 jitterClip(const glm::mat4& clipFromWorld, glm::vec2 jitterNdc) {
    glm::mat4 shift(1.0f);
    shift[3][0] = jitterNdc.x;
    shift[3][1] = jitterNdc.y;
    return shift * clipFromWorld;
}

void SceneRenderer::setPick(const std::optional<CameraPick>& pick) { mPick = pick; }

void SceneRenderer::setLight(const Light& light) {
    mScene.light = light;
    mShadowClipFromWorld = pcf::shadowClipFromWorld(mScene);
}

void SceneRenderer::setCamera(const Camera& camera) { mScene.camera = camera; }

void SceneRenderer::setShadowClipFromWorld(const glm::mat4& shadowClipFromWorld) {
    mShadowClipFromWorld = shadowClipFromWorld;
}

void SceneRenderer::ensureShadowTarget(const MapSpec& map, TexelKind depthFormat) {
    if (auto why = checkMapSpec(map)) throw std::invalid_argument(*why);
    if (map.layers.size() != 1 && !map.texel().depth) {
        throw std::invalid_argument("a moments map has one layer, not " +
                                    std::to_string(map.layers.size()));
    }
    // One layer: a 2D texture; cascades: a 2D array, one layer each (shared/pcf_prelude.h reads
    // it as sampler2DArray when the program's PCF_MAP_LAYERS says so). mMap is the map the
    // target holds now.
    if (!mShadow.framebuffer || mShadow.width != map.size.x || mShadow.height != map.size.y ||
        mShadowDepthFormat != depthFormat || mMap.layers.size() != map.layers.size()) {
        mShadow =
            map.layers.size() == 1
                ? createOffscreenTarget(map.size.x, map.size.y, {}, glTexelFormat(depthFormat))
                : createLayeredDepthTarget(map.size.x, map.size.y,
                                           static_cast<int>(map.layers.size()),
                                           glTexelFormat(depthFormat));
        mShadowDepthFormat = depthFormat;
    }
    if (map.texel().depth) return;
    if (!mMoments.framebuffer || mMoments.width != map.size.x || mMoments.height != map.size.y ||
        mMap.texels != map.texels) {
        mMoments = createOffscreenTarget(map.size.x, map.size.y, {glTexelFormat(map.texels)});
    }
}

GLuint SceneRenderer::mapTexture() const {
    return mMap.texel().depth ? mShadow.depth.id() : mMoments.colors.front().id();
}

void SceneRenderer::renderMomentsPass(const RenderSettings& settings) {
    PcfParams prm = settings.pcfParams();
    const PcfProgram& program = mMomentsPrograms.get(pcfVariant(prm, false, mMap));
    GLuint id = program.id();
    glUseProgram(id);
    setParamUniforms(program, prm, settings.kernelBias(), &settings);
    glBindFramebuffer(GL_FRAMEBUFFER, mMoments.framebuffer.id());
    glViewport(0, 0, mMoments.width, mMoments.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    bindShadowMap(id, mShadow.depth.id(), mSamplers);
    if (!mEmptyVao) mEmptyVao = createVertexArray();
    glBindVertexArray(mEmptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(0, 0);
    glBindSampler(1, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void SceneRenderer::ensureTargets(const RenderSettings& settings) {
    size_t attachments = settings.writePositions ? 7 : 4;
    if (mFrame.width != settings.frameSize.x || mFrame.height != settings.frameSize.y ||
        !mFrame.framebuffer || mFrame.colors.size() != attachments) {
        std::vector<GLenum> formats = {GL_RGBA8, GL_RGBA32F, GL_R32F, GL_RGBA32F};
        if (settings.writePositions) {
            formats.insert(formats.end(), {GL_RGBA32F, GL_RGBA32F, GL_RGBA32F});
        }
        mFrame = createOffscreenTarget(settings.frameSize.x, settings.frameSize.y, formats,
                                       GL_DEPTH_COMPONENT24);
    }
}

void SceneRenderer::drawObjects(GLuint program, bool castersOnly, bool setMaterial) {
    for (size_t k = 0; k < mMeshes.size(); ++k) {
        const SceneObject& object = mScene.objects[k];
        if (castersOnly && !object.castsShadow) continue;
        if (setMaterial) {
            // scene.frag applies gamma 2.2 to the albedo's factor here, once per object.
            glm::vec3 encoded = glm::pow(object.colour, glm::vec3(1.0f / 2.2f));
            glProgramUniform3fv(program, uniform(program, "uAlbedoEncoded"), 1, &encoded.x);
            glProgramUniform1i(program, uniform(program, "uReceives"),
                               object.receivesShadow ? 1 : 0);
        }
        glBindVertexArray(mMeshes[k].vao.id());
        glDrawElements(GL_TRIANGLES, mMeshes[k].indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
}

void SceneRenderer::setCascadeCamera(const std::optional<Camera>& camera) {
    mCascadeCamera = camera;
}

MapSpec SceneRenderer::mapSpecFor(const RenderSettings& settings) const {
    float aspect =
        settings.cascadeAspect > 0.0f ? settings.cascadeAspect : frameAspect(settings.frameSize);
    return cascadedMapSpec(mScene, settings, mShadowClipFromWorld, cascadeCamera(), aspect);
}

void SceneRenderer::renderShadowPass(const RenderSettings& settings) {
    MapSpec map = mapSpecFor(settings);
    ensureShadowTarget(map, settings.depthFormat);
    mMap = std::move(map);
    ensureTargets(settings);
    glBindFramebuffer(GL_FRAMEBUFFER, mShadow.framebuffer.id());
    glViewport(0, 0, mShadow.width, mShadow.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);
    if (settings.cull == CullMode::None) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(settings.cull == CullMode::Front ? GL_FRONT : GL_BACK);
    }
    // Slope-scaled bias: the rasterizer pushes each depth back by factor * its slope plus units
    // of the format's smallest step (glPolygonOffset), before the depth is stored.
    bool offset = settings.polygonOffset != glm::vec2(0.0f);
    if (offset) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(settings.polygonOffset.x, settings.polygonOffset.y);
    }
    // Snapped cascades move by whole texels: their own pass draws each the same, bit for bit.
    bool snapped = mMap.layers.size() > 1 && settings.cascadeSnap;
    GLuint program = snapped ? mDepthSnappedProgram.id() : mDepthProgram.id();
    glUseProgram(program);
    if (snapped) setSnappedDepthUniforms(program, settings);
    // Each layer (cascade) seen through its own fit, into its own layer of the texture.
    for (size_t k = 0; k < mMap.layers.size(); ++k) {
        if (mMap.layers.size() > 1) attachDepthLayer(mShadow, static_cast<int>(k));
        glClear(GL_DEPTH_BUFFER_BIT);
        const glm::mat4& clip = mMap.layers[k].shadowClipFromWorld;
        if (snapped) {
            setSnappedLayerUniforms(program, clip);
        } else {
            glProgramUniformMatrix4fv(program, uniform(program, "uShadowClipFromWorld"), 1,
                                      GL_FALSE, &clip[0][0]);
        }
        drawObjects(program, true, false);
    }
    if (offset) glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!mMap.texel().depth) renderMomentsPass(settings);
}

void SceneRenderer::setSnappedDepthUniforms(GLuint program, const RenderSettings& settings) {
    glProgramUniform1f(program, uniform(program, "uHalfMap"),
                       0.5f * static_cast<float>(mShadow.width));
    glProgramUniform2fv(program, uniform(program, "uPolygonOffset"), 1, &settings.polygonOffset.x);
    int bits = mMap.fixedPointBits();
    glProgramUniform1f(program, uniform(program, "uDepthUnit"),
                       bits > 0 ? std::ldexp(1.0f, -bits) : 0.0f);
}

void SceneRenderer::setSnappedLayerUniforms(GLuint program, const glm::mat4& clip) {
    // The matrix's rows x and y in texels per world unit, and the world origin's texel corner
    // (whole texels: shiftShadowOrigin snapped it).
    float half = 0.5f * static_cast<float>(mShadow.width);
    glm::vec3 texelsX(clip[0][0] * half, clip[1][0] * half, clip[2][0] * half);
    glm::vec3 texelsY(clip[0][1] * half, clip[1][1] * half, clip[2][1] * half);
    glm::vec4 clipZ(clip[0][2], clip[1][2], clip[2][2], clip[3][2]);
    glm::vec2 origin = glm::round((glm::vec2(clip[3][0], clip[3][1]) + 1.0f) * half);
    glProgramUniform3fv(program, uniform(program, "uTexelsX"), 1, &texelsX.x);
    glProgramUniform3fv(program, uniform(program, "uTexelsY"), 1, &texelsY.x);
    glProgramUniform4fv(program, uniform(program, "uClipZ"), 1, &clipZ.x);
    glProgramUniform2fv(program, uniform(program, "uOrigin"), 1, &origin.x);
}

void SceneRenderer::renderCameraPass(const RenderSettings& settings) {
    ensureTargets(settings);
    drawCameraPass(settings, settings.writePositions ? 2 : 1, mFrame);
}

PcfProgramCache& SceneRenderer::programsFor(int targets, int biasMode) {
    int spot = mScene.light.type == LightType::Spot ? 1 : 0;
    auto key = std::make_tuple(targets, biasMode, spot);
    auto it = mPrograms.find(key);
    if (it == mPrograms.end()) {
        std::string defines = "#define PCF_ALL_TARGETS " + std::to_string(targets) +
                              "\n#define PCF_SCENE_BIAS " + std::to_string(biasMode) +
                              "\n#define PCF_SCENE_SPOT " + std::to_string(spot) + "\n";
        it = mPrograms.try_emplace(key, "scene.vert", "scene.frag", defines).first;
    }
    return it->second;
}

void SceneRenderer::drawCameraPass(const RenderSettings& settings, int targets,
                                   const OffscreenTarget& target) {
    GLuint fbo = target.framebuffer.id();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, target.width, target.height);
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const GLfloat one[4] = {1.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(fbo, GL_COLOR, 0, &BACKGROUND.x);
    if (target.colors.size() >= 4) {
        glClearNamedFramebufferfv(fbo, GL_COLOR, 1, zero);
        glClearNamedFramebufferfv(fbo, GL_COLOR, 2, one);
        glClearNamedFramebufferfv(fbo, GL_COLOR, 3, zero);
    }
    if (target.colors.size() >= 5) glClearNamedFramebufferfv(fbo, GL_COLOR, 4, zero);
    if (target.colors.size() >= 7) glClearNamedFramebufferfv(fbo, GL_COLOR, 6, zero);
    const GLfloat farDepth = 1.0f;
    glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &farDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);

    PcfParams prm = pcfParams(settings);
    PcfVariant variant = pcfVariant(prm, settings.rotate, mMap);
    variant.cascadeBlend = mMap.layers.size() > 1 && settings.cascadeBlend > 0.0f ? 1 : 0;
    const PcfProgram& pcfProgram = programsFor(targets, settings.modeId()).get(variant);
    GLuint program = pcfProgram.id();
    glUseProgram(program);
    glm::mat4 clip = clipFromWorld();
    glProgramUniformMatrix4fv(program, uniform(program, "uClipFromWorld"), 1, GL_FALSE,
                              &clip[0][0]);
    setMapUniforms(program, mMap);
    const Light& light = mScene.light;
    glm::vec3 dir = glm::normalize(light.directionWs);
    glProgramUniform3fv(program, uniform(program, "uLightDirWs"), 1, &dir.x);
    glProgramUniform3fv(program, uniform(program, "uLightPosWs"), 1, &light.positionWs.x);
    glProgramUniform1f(program, uniform(program, "uSpotCosCone"),
                       std::cos(glm::radians(light.coneDeg)));
    setParamUniforms(pcfProgram, prm, settings.kernelBias(), &settings);
    // A lesson's pinned point (setPick); pixel -1, -1 matches no fragment.
    glm::ivec2 pickPixel = mPick ? mPick->pixelGl : glm::ivec2(-1);
    glm::vec4 pickLookup = mPick ? mPick->lookup : glm::vec4(0.0f);
    glm::vec2 pickDzDuv = mPick ? mPick->dzduv : glm::vec2(0.0f);
    glProgramUniform2iv(program, uniform(program, "uPickPixel"), 1, &pickPixel.x);
    glProgramUniform4fv(program, uniform(program, "uPickLookup"), 1, &pickLookup.x);
    glProgramUniform2fv(program, uniform(program, "uPickDzDuv"), 1, &pickDzDuv.x);
    glProgramUniform1i(program, uniform(program, "uPickLayer"), mPick ? mPick->layer : 0);
    // The camera as the cascades split it (pcfViewDepth); unused with one layer.
    const Camera& cascades = cascadeCamera();
    glm::vec3 viewDir = cameraViewDirWs(cascades);
    glProgramUniform3fv(program, uniform(program, "uEyeWs"), 1, &cascades.eyeWs.x);
    glProgramUniform3fv(program, uniform(program, "uViewDirWs"), 1, &viewDir.x);
    bindShadowMap(program, mapTexture(), mShadow.depth.id(), mSamplers);
    drawObjects(program, false, true);
    glBindSampler(0, 0);
    glBindSampler(1, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

PcfParams SceneRenderer::pcfParams(const ShadowSettings& settings, vec2 rotation) const {
    return pcssPcfParams(mScene.light, mMap.layers.front(), settings, rotation);
}

void SceneRenderer::render(const RenderSettings& settings) {
    if (auto why = validateParams(settings.pcfParams())) throw std::invalid_argument(*why);
    renderShadowPass(settings);
    renderCameraPass(settings);
}

TimingResult SceneRenderer::timeCameraPass(const RenderSettings& settings, int repeats,
                                           bool warmUp) {
    ensureTargets(settings);
    if (mTimingFrame.width != mFrame.width || mTimingFrame.height != mFrame.height) {
        mTimingFrame =
            createOffscreenTarget(mFrame.width, mFrame.height, {GL_RGBA8}, GL_DEPTH_COMPONENT24);
    }
    return timeGpu([&] { drawCameraPass(settings, 0, mTimingFrame); }, repeats, warmUp);
}

std::vector<uint8_t> SceneRenderer::readColour() const {
    return readPixelsRgba8(mFrame.framebuffer.id(), GL_COLOR_ATTACHMENT0, mFrame.width,
                           mFrame.height);
}

std::vector<float> SceneRenderer::readLightSpace() const {
    return readPixelsFloat(mFrame.framebuffer.id(), GL_COLOR_ATTACHMENT1, mFrame.width,
                           mFrame.height, 4);
}

std::vector<float> SceneRenderer::readVisibility() const {
    return readPixelsFloat(mFrame.framebuffer.id(), GL_COLOR_ATTACHMENT2, mFrame.width,
                           mFrame.height, 1);
}

std::vector<float> SceneRenderer::readReceiver() const {
    return readPixelsFloat(mFrame.framebuffer.id(), GL_COLOR_ATTACHMENT3, mFrame.width,
                           mFrame.height, 4);
}

std::vector<float> SceneRenderer::readPositions() const {
    if (mFrame.colors.size() < 5) {
        throw std::logic_error("readPositions: render with RenderSettings::writePositions");
    }
    return readPixelsFloat(mFrame.framebuffer.id(), GL_COLOR_ATTACHMENT4, mFrame.width,
                           mFrame.height, 4);
}

std::vector<float> SceneRenderer::readNormals() const {
    if (mFrame.colors.size() < 6) {
        throw std::logic_error("readNormals: render with RenderSettings::writePositions");
    }
    return readPixelsFloat(mFrame.framebuffer.id(), GL_COLOR_ATTACHMENT5, mFrame.width,
                           mFrame.height, 4);
}

std::vector<float> SceneRenderer::readNextReceiver() const {
    if (mFrame.colors.size() < 7) {
        throw std::logic_error("readNextReceiver: render with RenderSettings::writePositions");
    }
    return readPixelsFloat(mFrame.framebuffer.id(), GL_COLOR_ATTACHMENT6, mFrame.width,
                           mFrame.height, 4);
}

std::vector<float> SceneRenderer::readLightSpaceRegion(glm::ivec2 topLeft, glm::ivec2 size) const {
    return readRegion(GL_COLOR_ATTACHMENT1, topLeft, size);
}

std::vector<float> SceneRenderer::readReceiverRegion(glm::ivec2 topLeft, glm::ivec2 size) const {
    return readRegion(GL_COLOR_ATTACHMENT3, topLeft, size);
}

std::vector<float> SceneRenderer::readRegion(GLenum attachment, glm::ivec2 topLeft,
                                             glm::ivec2 size) const {
    std::vector<float> out(static_cast<size_t>(size.x) * size.y * 4, 0.0f);
    glm::ivec2 lo = glm::max(topLeft, glm::ivec2(0));
    glm::ivec2 hi = glm::min(topLeft + size, glm::ivec2(mFrame.width, mFrame.height));
    if (hi.x <= lo.x || hi.y <= lo.y) return out;
    glm::ivec2 span = hi - lo;
    std::vector<float> rows(static_cast<size_t>(span.x) * span.y * 4);
    // GL rows count from the bottom: the region's top row is GL row height - lo.y - 1.
    GLint packAlignment = 4;
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, mFrame.framebuffer.id());
    glNamedFramebufferReadBuffer(mFrame.framebuffer.id(), attachment);
    glReadPixels(lo.x, mFrame.height - hi.y, span.x, span.y, GL_RGBA, GL_FLOAT, rows.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
    for (int r = 0; r < span.y; ++r) {
        // GL row r (from the bottom of the span) is region row (span.y - 1 - r) from its top.
        const float* src = rows.data() + static_cast<size_t>(r) * span.x * 4;
        int y = (lo.y - topLeft.y) + (span.y - 1 - r);
        float* dst = out.data() + (static_cast<size_t>(y) * size.x + (lo.x - topLeft.x)) * 4;
        std::copy(src, src + static_cast<size_t>(span.x) * 4, dst);
    }
    return out;
}

// The map the sampler compares against (depth_readback.h), not glGetTextureImage's conversion.
ShadowMap SceneRenderer::readShadowMap() const { return readSampledDepth(mapTexture(), mMap); }

ShadowMap SceneRenderer::readDepthMap() const {
    if (mMap.texel().depth) return readShadowMap();
    MapSpec depth = mMap;
    depth.texels = mShadowDepthFormat;
    return readSampledDepth(mShadow.depth.id(), depth);
}

}  // namespace pcf
