// cascade_fit.h: the layers of a directional light's cascaded map, each fitted to its slice of
// the camera frustum. The splits are kernel/cascades.h's; the map's value (MapSpec, one
// PcfMapLayer per cascade) is made by scene/shadow_fit.h, which calls cascadeLayers when the
// settings ask for more than one cascade.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "kernel/settings.h"
#include "kernel/shadow_map.h"
#include "scene/scene.h"

namespace pcf {

// The view depths one cascade covers, scene units along the camera's view direction.
struct CascadeRange {
    float nearZ;
    float farZ;
};

// The view depths the cascades split: n = the camera's near plane, f = shadow_distance (0: the
// camera's far plane), split by the settings' scheme and lambda (cascadeSplits). One range per
// cascade, back to back from n to f.
float cascadeFarDepth(const Camera& camera, const ShadowSettings& s);
std::vector<CascadeRange> cascadeRanges(const Camera& camera, const ShadowSettings& s);

// Why the settings' cascades do not fit this scene, in the kernel's words (the setting named as
// its key; the command line says its flag, app/cli_util.h cliWords), or nullopt: more than one
// is for a directional light only, not for a method that searches blockers (pcss's penumbra
// scale is one number per map) nor one that reads a moments map (made from one depth map), and
// the shadow distance must lie beyond the camera's near plane.
std::optional<ParamProblem> cascadeProblem(const Scene& scene, const ShadowSettings& s);

// The eight corners of the camera frustum between view depths nearZ and farZ, world space
// (a frame of width / height `aspect`).
std::array<glm::vec3, 8> frustumSliceWs(const Camera& camera, float aspect, CascadeRange r);

// The bounding sphere of a frustum slice's eight corners, in the camera's view space: its centre
// lies on the view axis (at view depth `depth`), and its radius is rounded up to 1/16 of a
// scene unit. Both depend on the slice's depths, the field of view and the aspect alone, never
// on where the camera looks, so a sphere-fitted cascade keeps its size as the camera turns.
struct SliceSphere {
    double depth;
    double radius;
};
SliceSphere sliceSphere(const Camera& camera, float aspect, CascadeRange r);

// One cascade's light clip from world: the light's view (lightFromWorld, the scene's bounds),
// an orthographic box around the slice (fit CASCADE_FIT_BOX: the light-space bounds of its
// corners; CASCADE_FIT_SPHERE: the square around its bounding sphere), deep enough for every
// caster of the scene; with snap, one texel wider on every side and the world origin moved onto
// the nearest texel corner, which shifts the box by up to half a texel. A snapped fit's rows are
// the light view's rotation times one scale made from the half-extent alone (for the sphere, the
// same float at every frame) and its translation whole texels, so that a snapped map is the last
// one moved by whole texels (the depth pass draws it so: shaders/depth_snapped.*).
glm::mat4 cascadeClipFromWorld(const Scene& scene, float aspect, CascadeRange r, int fit, bool snap,
                               int mapSize);

// The camera's unit view direction, from the eye to the target: what a receiver's view depth is
// measured along (shared/pcf_shading.h pcfViewDepth; the camera pass's uViewDirWs).
glm::vec3 cameraViewDirWs(const Camera& camera);

// The layer of `map` a receiver point reads, as the camera pass picks it (pcfCascadeLayer on
// pcfViewDepth): 0 for a map of one layer; for cascades, the first whose view depths end beyond
// the point's, or map.layers.size() for a point past the last (lit: no cascade covers it).
int cascadeOfPoint(const MapSpec& map, const Camera& camera, glm::vec3 posWs);

// A receiver point's visibility in a cascaded map on the CPU, as the camera pass computes it
// (shaders/scene.frag): the cascade its view depth falls in, that cascade's lookup of the point
// (shared/pcf_shading.h pcfReceiverLookup, the settings' bias), and in the blend band the next
// cascade's lookup of the same point and the weight that mixes them (pcfCascadeBlendWeight,
// pcfCascadeBlend). What a trace of a cascaded frame shows beside the taps.
struct CascadeLookup {
    int layer = 0;                // the cascade read; map.layers() when past the last (lit)
    int next = -1;                // the cascade blended in, -1 outside the blend band
    float viewDepth = 0.0f;       // the point's view depth (pcfViewDepth), scene units
    float weight = 0.0f;          // the next cascade's weight, in [0, 1]
    float visibility = 1.0f;      // the cascade read's own visibility
    float nextVisibility = 1.0f;  // the next cascade's (its own lookup); = visibility outside
    float blended = 1.0f;         // the result: pcfCascadeBlend(visibility, nextVisibility, weight)
};

// The lookup of point posWs (its unit normal facing the camera, cos(theta) to the light), with
// the receiver plane dzduv for the cascade read and nextDzduv for the next one (receiver-plane
// bias; light depth per uv unit, each in its own cascade's uv). prm: the settings' parameters
// (SceneRenderer::pcfParams); with the settings' rotate each lookup's disk turns by the texel it
// looks up (pcfTexelRotation), as scene.frag turns it; `blend` the band
// (ShadowSettings::cascadeBlend).
CascadeLookup cascadeVisibilityAt(const ShadowMap& map, const Camera& camera,
                                  const ShadowSettings& s, const PcfParams& prm, glm::vec3 posWs,
                                  glm::vec3 normalWs, float cosTheta,
                                  glm::vec2 dzduv = glm::vec2(0.0f),
                                  glm::vec2 nextDzduv = glm::vec2(0.0f));

// The same with the cascade and the view depth given instead of found from the camera (the seam
// probe's two sides of a split, stability_cascades.h): the point looked up in `layer` (< the
// map's layers), blended with the next by the band's weight at viewDepth.
CascadeLookup cascadeVisibilityIn(const ShadowMap& map, int layer, float viewDepth,
                                  const ShadowSettings& s, const PcfParams& prm, glm::vec3 posWs,
                                  glm::vec3 normalWs, float cosTheta,
                                  glm::vec2 dzduv = glm::vec2(0.0f),
                                  glm::vec2 nextDzduv = glm::vec2(0.0f));

// One layer per cascade (shadowMapLayer's fields, plus the view depths it covers), for a map of
// s.mapSize texels seen by a camera whose frame is `aspect` wide per unit of height.
std::vector<PcfMapLayer> cascadeLayers(const Scene& scene, const ShadowSettings& s, float aspect);

}  // namespace pcf
