// pcss.h: what percentage-closer soft shadows need from the scene: the light's size in the
// shadow map's own units (the kernel's penumbraScale, shaders/shared/pcf_disk.h pcfPcss).
#pragma once

#include "kernel/settings.h"
#include "scene/scene.h"

namespace pcf {

// The sun's angular diameter, degrees (about 32 arc minutes): pcss's light when neither the
// settings nor the scene's light give a size.
constexpr float SUN_ANGULAR_DIAMETER_DEG = 0.53f;

// The light size pcss uses, degrees: the settings' light_size when above 0, else the scene
// light's angular_diameter when above 0, else the sun's.
float effectiveLightSizeDeg(const Light& light, float lightSizeDeg);

// The kernel's penumbraScale: texels of penumbra width per unit of light depth between the
// receiver and its blocker, for a directional light of angular diameter theta and the map
// shadowClipFromWorld * (x, 1) of mapSize texels. Fernando, "Percentage-Closer Soft Shadows"
// (2005), with the light at infinity: width_ws = (d_receiver_ws - d_blocker_ws) * 2 tan(theta/2).
// The map is orthographic: its matrix's rows are the light's axes scaled, so with row lengths
// L0, L1 (u, v) and L2 (depth), one unit of light depth is 2 / L2 world units
// (depth = 0.5 * ndc.z + 0.5) and one texel 2 / (min(L0, L1) * mapSize) (as shadowTexelWs):
//   S = 2 tan(theta / 2) * (2 / L2) / texelWs
// The matrix, not the scene: a widened depth range or a shifted grid (light.h) changes S with
// the map.
// A spot light of radius R (light.radius; lightSizeDeg does not apply, light_radius does through
// pcssPcfParams): its map is perspective,
// and the kernel works in linear distance (pcf_disk.h, Fernando 2005 with w_light = 2 R):
//   S = 2 R * P00 * mapSize / 2 = R * P00 * mapSize
// P00 the projection's x scale (the u row of the matrix, without the part along its w row that
// a shifted grid adds; the least of the u and v rows'). R = 0: S = 0, and pcss filters as
// poisson with radius 1 (the kernel's PCF_PCSS_MIN_RADIUS).
float penumbraScale(const Light& light, const glm::mat4& shadowClipFromWorld, int mapSize,
                    float lightSizeDeg);

// The near and far planes (scene units, along the light's axis) of a perspective shadow matrix,
// read from its depth row z_clip = A * z_view + B (w_clip = -z_view): depth 0 at n = B / (A - 1),
// depth 1 at f = B / (A + 1) (glm::perspectiveRH_NO; a widened depth range moves f, past
// infinity to a negative f, which the kernel's formula still inverts). (0, 0) for an
// orthographic matrix: the kernel's depthNear, depthFar (pcf_kernel.h).
glm::vec2 pcssDepthRange(const glm::mat4& shadowClipFromWorld);

// The settings' kernel parameters, with what a blocker search (pcss) takes from the light and
// the map's layer it reads (kernel/shadow_map.h): the penumbraScale for this light (its size the
// settings' where given: light.h applyLightSize) and the
// layer's fit, and under a spot the layer's depth range (PcfMapLayer::depthRange).
PcfParams pcssPcfParams(const Light& light, const PcfMapLayer& layer, const ShadowSettings& s,
                        vec2 rotation = vec2(1.0f, 0.0f));

}  // namespace pcf
