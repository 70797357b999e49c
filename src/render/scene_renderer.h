// scene_renderer.h: the shadow-mapped scene on the GPU. Two passes: the light's depth pass into
// the shadow map, then the camera pass that shades the receivers with the chosen PCF method
// (shaders/scene.frag, which includes the shared kernel) into these targets:
//   colour      RGBA8    what the class sees
//   lightspace  RGBA32F  u, v, ref per pixel as the shader filtered them; alpha 1 on receivers
//   visibility  R32F     what pcfFilter returned (1 off receivers)
//   receiver    RGBA32F  dz/du, dz/dv (the receiver plane the bias used), z before bias; alpha 1
//                        on receivers
//   position    RGBA32F  world position, alpha 1 where drawn (RenderSettings::writePositions)
//   normal      RGBA32F  the unit normal facing the camera and cos(theta), its dot with the
//                        direction to the light (RenderSettings::writePositions)
//   next receiver RGBA32F with a blend band (cascade_blend), the receiver in the next cascade:
//                        dz/du, dz/dv, z before bias; alpha 1 on receivers; 0 without a band
//                        (RenderSettings::writePositions)
// Readbacks are rows TOP-DOWN (first row = top of the frame) except the shadow map, which keeps
// GL row order (ShadowMap's convention).
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "kernel/shadow_map.h"
#include "render/gl_objects.h"
#include "render/gpu_timer.h"
#include "render/pcf_programs.h"
#include "render/render_settings.h"
#include "scene/scene.h"
#include "scene/shadow_fit.h"

namespace pcf {

// What the camera pass needs to show a pinned scene point at one pixel (SceneRenderer::setPick).
struct CameraPick {
    glm::ivec2 pixelGl{-1, -1};  // window coordinates, row 0 at the bottom
    glm::vec2 jitterNdc{0.0f};   // added to every ndc position: the point lands on the centre
    glm::vec4 lookup{0.0f};      // u, v, ref, z0 (shared/pcf_shading.h: pcfReceiverLookup)
    glm::vec2 dzduv{0.0f};       // the receiver plane, dz/du and dz/dv
    // The map's layer the lookup is in (a cascade; scene/cascade_view.h pointCascade): the pixel
    // reads it whatever cascade its own interpolated position would pick near a split.
    int layer = 0;
};

// clipFromWorld followed by a shift of every ndc position by jitterNdc.
glm::mat4 jitterClip(const glm::mat4& clipFromWorld, glm::vec2 jitterNdc);

class SceneRenderer {
  public:
    // Uploads the scene's meshes. Needs a current OpenGL 4.5 context, which must outlive this.
    explicit SceneRenderer(const Scene& scene);

    // Both passes: shadow map, then the camera pass.
    void render(const RenderSettings& settings);
    // The light's depth pass alone: the map of shadowMapSpec (scene/shadow_fit.h) for these
    // settings and the current fit (re-created when its size or texel kind change).
    void renderShadowPass(const RenderSettings& settings);
    // The camera pass alone, reading the current shadow map (its layers' fits: mapSpec()).
    void renderCameraPass(const RenderSettings& settings);
    // Median time of the camera pass over `repeats` draws (gpu_timer.h says which timer), drawn
    // the way an engine would: colour only, into an RGBA8 target of the frame's size, so the
    // extra float targets the inspector needs do not weigh on the method's cost.
    // warmUp false: no untimed draw first (the caller warmed up and samples one at a time).
    TimingResult timeCameraPass(const RenderSettings& settings, int repeats, bool warmUp = true);

    std::vector<uint8_t> readColour() const;    // RGBA8, top-down
    std::vector<float> readLightSpace() const;  // 4 floats per pixel, top-down
    std::vector<float> readVisibility() const;  // 1 float per pixel, top-down
    std::vector<float> readReceiver() const;    // 4 floats per pixel, top-down
    // 4 floats per pixel, top-down; needs a frame rendered with writePositions.
    std::vector<float> readPositions() const;
    // The normal target: n.x, n.y, n.z, cos(theta) per pixel, top-down; as readPositions.
    std::vector<float> readNormals() const;
    // The next receiver target: 4 floats per pixel, top-down; as readPositions.
    std::vector<float> readNextReceiver() const;
    // The light-space target's pixels x..x+w-1, y..y+h-1 (top-left origin), clipped to the
    // frame: 4 floats per pixel, top-down, w * h pixels (outside the frame: zeros).
    std::vector<float> readLightSpaceRegion(glm::ivec2 topLeft, glm::ivec2 size) const;
    // The receiver target's pixels, the same way.
    std::vector<float> readReceiverRegion(glm::ivec2 topLeft, glm::ivec2 size) const;
    // The map the last depth pass made, its texels as the sampler reads them, GL row order.
    ShadowMap readShadowMap() const;
    // The depths the last depth pass wrote, as the moments pass read them: for a moments map the
    // depth map under it (kernel/moment_footprint.h), else readShadowMap's map.
    ShadowMap readDepthMap() const;
    // What the last depth pass made: size, texel kind, each layer's fit. The camera pass's
    // uniforms, readShadowMap's spec and render.json's "map" all come from it.
    const MapSpec& mapSpec() const { return mMap; }

    glm::ivec2 frameSize() const { return {mFrame.width, mFrame.height}; }
    GLuint frameFramebuffer() const { return mFrame.framebuffer.id(); }
    const Scene& scene() const { return mScene; }
    // The fit the next depth pass uses (its layer's light clip from world).
    glm::mat4 shadowClipFromWorld() const { return mShadowClipFromWorld; }
    // The kernel's parameters the camera pass filters with: the settings', and pcss's
    // penumbraScale for this light and this shadow matrix (scene/pcss.h).
    PcfParams pcfParams(const ShadowSettings& settings, vec2 rotation = vec2(1.0f, 0.0f)) const;
    glm::mat4 clipFromWorld() const;
    // What the sweeps of measure/stability.h change between frames without re-uploading the
    // meshes: the light (the shadow matrix is re-fitted to it), the camera, or the shadow
    // matrix itself (e.g. light.h's shiftShadowOrigin); each takes effect at the next pass.
    void setLight(const Light& light);
    void setCamera(const Camera& camera);
    void setShadowClipFromWorld(const glm::mat4& shadowClipFromWorld);
    // A lesson's pinned scene point (lesson/lesson_pick.h) for the camera passes that follow:
    // the camera is jittered by jitterNdc and the fragment at pixelGl (GL window coordinates)
    // takes the CPU's lookup of the point instead of its interpolated one. nullopt: none.
    void setPick(const std::optional<CameraPick>& pick);
    const std::optional<CameraPick>& pick() const { return mPick; }
    // The camera a cascaded map is fitted to and its receivers pick their cascade by (nullopt:
    // the scene's camera): a magnified step's wide view, a frozen view's cascades
    // (scene/cascade_view.h). Takes effect at the next depth pass.
    void setCascadeCamera(const std::optional<Camera>& camera);
    const Camera& cascadeCamera() const { return mCascadeCamera ? *mCascadeCamera : mScene.camera; }
    // The map the depth pass makes for these settings with the current fit, light and cascade
    // camera (scene/cascade_view.h cascadedMapSpec), the frame shape settings.cascadeAspect
    // (0: settings.frameSize's).
    MapSpec mapSpecFor(const RenderSettings& settings) const;

  private:
    struct GpuMesh {
        GlVertexArray vao;
        GlBuffer vertices;
        GlBuffer indices;
        GLsizei indexCount = 0;
    };
    void ensureTargets(const RenderSettings& settings);
    // The depth target for `map` in `depthFormat`, and for a moments map its moments target
    // (each re-created when its size or texel kind change).
    void ensureShadowTarget(const MapSpec& map, TexelKind depthFormat);
    // The moments pass: the depth target's depths into the moments target (moments.frag).
    void renderMomentsPass(const RenderSettings& settings);
    // The texture the camera pass reads as its map: the moments target's for a moments map,
    // else the depth target's.
    GLuint mapTexture() const;
    std::vector<float> readRegion(GLenum attachment, glm::ivec2 topLeft, glm::ivec2 size) const;
    void drawObjects(GLuint program, bool castersOnly, bool setMaterial);
    // depth_snapped.*'s uniforms: the pass's, and one layer's from its clip matrix.
    void setSnappedDepthUniforms(GLuint program, const RenderSettings& settings);
    void setSnappedLayerUniforms(GLuint program, const glm::mat4& clip);
    // The camera pass into `target`, writing `targets` (scene.frag's PCF_ALL_TARGETS: 0 colour
    // only, 1 the four targets, 2 and the world position).
    void drawCameraPass(const RenderSettings& settings, int targets, const OffscreenTarget& target);
    // The programs for these targets, this bias mode and the scene's light type (scene.frag
    // takes all three as defines), made on first use.
    PcfProgramCache& programsFor(int targets, int biasMode);

    Scene mScene;
    glm::mat4 mShadowClipFromWorld{1.0f};
    std::optional<CameraPick> mPick;
    std::optional<Camera> mCascadeCamera;
    std::vector<GpuMesh> mMeshes;
    GlProgram mDepthProgram;
    GlProgram mDepthSnappedProgram;  // snapped cascades (shaders/depth_snapped.*)
    // By (targets, bias mode, spot light): one PcfProgramCache per combination used.
    std::map<std::tuple<int, int, int>, PcfProgramCache> mPrograms;
    PcfSamplers mSamplers;
    OffscreenTarget mShadow;
    TexelKind mShadowDepthFormat = TexelKind::D32F;  // mShadow's depth format
    OffscreenTarget mMoments;  // the moments pass's target (moment methods only)
    PcfProgramCache mMomentsPrograms{"fullscreen.vert", "moments.frag", ""};
    GlVertexArray mEmptyVao;
    MapSpec mMap;  // what the last depth pass made (the target's size and texel kind)
    OffscreenTarget mFrame;
    OffscreenTarget mTimingFrame;
};

}  // namespace pcf
