// scene.frag: shades the receivers with the chosen PCF method. The PCF math is not here: it is
// shared/pcf_kernel.h, the same source the CPU kernel compiles (the loader puts the prelude and
// the kernel before this file). PCF_METHOD and PCF_KERNEL arrive as defines, so the driver
// folds the method dispatch and unrolls the kernel loops. PCF_ALL_TARGETS adds outputs: 0 colour
// only (timing), 1 + light-space, visibility and receiver (the inspector), 2 + world position,
// normal and the next cascade's receiver (tests, --raw: what `verify` recomputes each pixel's
// lookup from). The bias mode (PCF_SCENE_BIAS) and the light type (PCF_SCENE_SPOT) are
// defines too, one program each: llvmpipe runs both sides of every branch under a lane mask,
// even when the condition is a uniform, so a branch on a uniform costs its whole body on every
// fragment. As uniforms, the bias modes' branches here and in the kernel's taps made the camera
// pass cost about a third more than the filter alone (docs/measurement.md, "What the passes
// cost").
// The kernel's own choices (weights, precision, fixed point, per-pixel rotation) are defines for
// the same reason: render/pcf_programs.h, PcfVariant.
// The parameter table's uniforms (uConstantBias, uRadius, ...) and pcfProgramParams /
// pcfProgramBias come before this file (render/pcf_programs.h, paramUniformsGlsl).
// see: src/render/scene_renderer.cpp (uniforms, targets), src/kernel/pcf.h (CPU side)
in vec3 vPosWs;
in vec3 vNormalWs;

uniform Map uPcfDepth;  // the shadow map, nearest side (pcf_prelude.h; an array for cascades)
uniform vec3 uAlbedoEncoded;          // pow(linear colour of this object, 1 / 2.2)
uniform int uReceives;                // 1: look the shadow map up; 0: never shadowed
uniform vec3 uLightDirWs;             // the direction the light travels (unit)
uniform vec3 uLightPosWs;             // spot only
uniform float uSpotCosCone;           // spot only: cos of the cone's half angle
uniform ivec2 uPickPixel;             // a lesson's pinned point's pixel (window coords); -1: none
uniform vec4 uPickLookup;             // its u, v, ref, z0, computed on the CPU
uniform vec2 uPickDzDuv;              // its receiver plane, dz/du, dz/dv
uniform int uPickLayer;               // the layer (cascade) its lookup is in
uniform vec3 uEyeWs;                  // the camera's eye and unit view direction: which cascade
uniform vec3 uViewDirWs;              // a receiver reads (pcfViewDepth)

layout(location = 0) out vec4 oColour;
#if PCF_ALL_TARGETS
layout(location = 1) out vec4 oLightSpace;  // u, v, ref, 1 on receivers (cleared to 0)
layout(location = 2) out float oVisibility; // what pcfFilter returned (1 off receivers)
layout(location = 3) out vec4 oReceiver;    // dz/du, dz/dv, z before bias, 1 on receivers
#endif
#if PCF_ALL_TARGETS >= 2
layout(location = 4) out vec4 oPosWs;       // world position, w = 1 where drawn
layout(location = 5) out vec4 oNormalWs;    // the unit normal facing the camera, cos(theta)
// With a blend band: the receiver in the next cascade (the last's own in the last), as oReceiver
// in the cascade read: dz/du, dz/dv, z before bias, 1 on receivers; 0 without a band.
layout(location = 6) out vec4 oNextReceiver;
#endif

const float AMBIENT = 0.25f;
const int BIAS_MODE = PCF_SCENE_BIAS;  // PCF_BIAS_NONE .. (shared/pcf_kernel.h)
const bool SPOT = PCF_SCENE_SPOT != 0;  // false: directional

// Where a receiver point is looked up in one layer of the map under the program's bias (shared/
// pcf_shading.h pcfReceiverLookup; a map of cascades on its exact grid, pcfLightClip).
PcfReceiverLookup layerLookup(PcfMapLayer layer, vec3 posWs, vec3 n, float cosTheta) {
    return pcfReceiverLookup(layer.shadowClipFromWorld, posWs, n, cosTheta, BIAS_MODE,
                             uConstantBias, uSlopeBias, uSlopeMax, uNormalOffset, layer.texelWs,
                             PCF_MAP_LAYERS > 1);
}

#if PCF_MAP_LAYERS > 1
// The receiver plane in one cascade's map, for a cascaded map: the lanes of a pixel quad that
// straddles a split read different cascades, and the derivatives of their (u, v, z) would mix
// two maps' coordinates (a line of acne along every split under receiver-plane bias). Each lane
// instead looks up its neighbours' world positions (this pixel's plus its screen-space
// derivative) in its own cascade and takes the difference: the same plane as dFdx/dFdy of
// (u, v, z) where the quad reads one cascade (Isidoro, "Shadow Mapping: GPU-based Tips and
// Techniques", GDC 2006, pcfReceiverPlaneDzDuv). Called where every lane runs.
vec3 layerUvz(PcfMapLayer layer, vec3 posWs, vec3 n, float cosTheta) {
    PcfReceiverLookup at = layerLookup(layer, posWs, n, cosTheta);
    return vec3(at.u, at.v, at.z);
}

vec2 layerDzDuv(PcfMapLayer layer, vec3 uvz, vec3 n, float cosTheta) {
    vec3 dx = layerUvz(layer, vPosWs + dFdx(vPosWs), n, cosTheta) - uvz;
    vec3 dy = layerUvz(layer, vPosWs + dFdy(vPosWs), n, cosTheta) - uvz;
    return pcfReceiverPlaneDzDuv(dx, dy);
}
#endif

void main() {
    // Directional: a constant direction and no cone. Only a spot pays for the normalize and
    // the cone test.
    vec3 toLight = -uLightDirWs;
    float cone = 1.0f;
    if (SPOT) {
        toLight = normalize(uLightPosWs - vPosWs);
        cone = dot(-toLight, uLightDirWs) >= uSpotCosCone ? 1.0f : 0.0f;
    }
    vec3 n = normalize(vNormalWs);
    if (!gl_FrontFacing) n = -n;  // a plane seen from behind
    float cosTheta = dot(n, toLight);
    float nDotL = max(cosTheta, 0.0f);

    // Where this receiver point is looked up, and its ref (shared/pcf_shading.h, the same
    // function the CPU runs for a lesson's pinned point). BIAS_MODE is a constant: the driver
    // folds the modes this program does not use.
    // The layer of the map this receiver reads (uPcfMapLayers: render/pcf_programs.h): the
    // map's one layer, or the cascade whose view depths hold this receiver's (shared/
    // pcf_shading.h pcfViewDepth and pcfCascadeLayer, which the CPU runs on the same point: the
    // parity test, `verify` and a lesson's pinned point). Past the last cascade: lit.
    int layerIndex = 0;
    bool covered = true;
    float viewDepth = 0.0f;
#if PCF_MAP_LAYERS > 1
    vec4 cascadeFar = vec4(1e30f);
    for (int k = 0; k < PCF_MAP_LAYERS; ++k) cascadeFar[k] = uPcfMapLayers[k].viewDepth.y;
    viewDepth = pcfViewDepth(vPosWs, uEyeWs, uViewDirWs);
    layerIndex = pcfCascadeLayer(viewDepth, cascadeFar, PCF_MAP_LAYERS);
    covered = layerIndex < PCF_MAP_LAYERS;
    layerIndex = min(layerIndex, PCF_MAP_LAYERS - 1);
    pcfMapLayer = layerIndex;
#endif
    PcfMapLayer layer = uPcfMapLayers[layerIndex];
    PcfReceiverLookup at = layerLookup(layer, vPosWs, n, cosTheta);
    float u = at.u;
    float v = at.v;
    float z = at.z;
    float z0 = at.z0;
    float ref = at.ref;
    // The receiver's plane in the map, from this pixel's screen-space derivatives (Isidoro 2006,
    // pcfReceiverPlaneDzDuv); written out so the CPU kernel uses the very same slope. Only
    // receiver-plane bias filters with it, so a colour-only pass in another mode skips it. The kernel
    // caps it (pcfClampDzDuv, uRpdbMax): the target holds the slope as measured.
    vec2 dzduv = vec2(0.0f);
    if (PCF_ALL_TARGETS != 0 || BIAS_MODE == PCF_BIAS_RECEIVER_PLANE) {
#if PCF_MAP_LAYERS > 1
        dzduv = layerDzDuv(layer, vec3(u, v, z), n, cosTheta);
#else
        dzduv = pcfReceiverPlaneDzDuv(dFdx(vec3(u, v, z)), dFdy(vec3(u, v, z)));
#endif
    }

#if PCF_CASCADE_BLEND
    // The next cascade's lookup of this point, for the blend band below; its receiver plane
    // in that cascade (layerDzDuv), taken here where every lane of the quad runs, and written out
    // (oNextReceiver) so that the CPU filters the band with the very same slope.
    PcfMapLayer nextLayer = uPcfMapLayers[min(layerIndex + 1, PCF_MAP_LAYERS - 1)];
    PcfReceiverLookup next = layerLookup(nextLayer, vPosWs, n, cosTheta);
    vec2 nextDzduv = vec2(0.0f);
    if (PCF_ALL_TARGETS >= 2 || BIAS_MODE == PCF_BIAS_RECEIVER_PLANE) {
        nextDzduv = layerDzDuv(nextLayer, vec3(next.u, next.v, next.z), n, cosTheta);
    }
#endif

    // A lesson's pinned scene point (src/lesson/lesson_pick.h): the camera is jittered so that
    // the point projects to this pixel's centre, and its lookup, computed once on the CPU from
    // the point itself, replaces the interpolated one (they differ by rounding only). So the
    // pixel shows exactly the lookup the inspector traces, the same at every frame size. After
    // the derivatives: every lane of the quad measured the plane from its own position.
    if (ivec2(gl_FragCoord.xy) == uPickPixel) {
        u = uPickLookup.x;
        v = uPickLookup.y;
        ref = uPickLookup.z;
        z0 = uPickLookup.w;
        dzduv = uPickDzDuv;
#if PCF_MAP_LAYERS > 1
        covered = uPickLayer < PCF_MAP_LAYERS;
        layerIndex = min(uPickLayer, PCF_MAP_LAYERS - 1);
        pcfMapLayer = layerIndex;
#endif
    }

    float visibility = 1.0f;
    if (uReceives != 0 && covered) {
        // The disk turns with the texel looked up, not the screen pixel (pcfTexelRotation).
        vec2 rotation = PCF_ROTATE_PER_PIXEL != 0
                            ? pcfTexelRotation(vec2(u, v), mapSize(uPcfDepth))
                            : vec2(1.0f, 0.0f);
        PcfRef lookupRef = PcfRef(ref, vec2(u, v), pcfProgramBias(BIAS_MODE, dzduv));
        visibility = pcfFilterRef(uPcfDepth, vec2(u, v), lookupRef, pcfProgramParams(rotation));
#if PCF_CASCADE_BLEND
        // In the blend band the next cascade looks the same point up (its own fit, texel size
        // and receiver plane) and the two visibilities are mixed (shared/pcf_shading.h
        // pcfCascadeBlendWeight, pcfCascadeBlend; the CPU: scene/cascade_fit.h
        // cascadeVisibilityAt; at a lesson's pinned point lesson/lesson_pick.h pinnedCascadeBlend,
        // which the inspector shows beside the cascade's own lookup).
        float blendWeight = pcfCascadeBlendWeight(viewDepth, layer.viewDepth, uCascadeBlend,
                                                  layerIndex, PCF_MAP_LAYERS);
        if (blendWeight > 0.0f) {
            pcfMapLayer = layerIndex + 1;
            vec2 nextUv = vec2(next.u, next.v);
            vec2 nextRotation = PCF_ROTATE_PER_PIXEL != 0
                                    ? pcfTexelRotation(nextUv, mapSize(uPcfDepth))
                                    : vec2(1.0f, 0.0f);
            PcfRef nextRef = PcfRef(next.ref, nextUv, pcfProgramBias(BIAS_MODE, nextDzduv));
            float nextVisibility =
                pcfFilterRef(uPcfDepth, nextUv, nextRef, pcfProgramParams(nextRotation));
            visibility = pcfCascadeBlend(visibility, nextVisibility, blendWeight);
            pcfMapLayer = layerIndex;
        }
#endif
    }
    // Gamma 2.2 of albedo * light, light = ambient + diffuse * visibility (a scalar):
    //   (albedo * light)^(1/2.2) = albedo^(1/2.2) * light^(1/2.2)
    // The albedo's factor is per object, done once on the CPU (uAlbedoEncoded), so a fragment
    // pays for one power, and that one is pcfGammaEncode (shared/pcf_shading.h): a sqrt and a
    // polynomial within 6e-6 of the pow it replaces. On llvmpipe the pow was most of what the
    // camera pass cost beyond the filter (docs/measurement.md, "What the passes cost").
    float light = AMBIENT + (1.0f - AMBIENT) * nDotL * visibility * cone;
    oColour = vec4(uAlbedoEncoded * pcfGammaEncode(light), 1.0f);
    // --shading visibility (uShading, the parameter table's): the visibility alone as the grey
    // level, what reaches the point of the light (outside a spot's cone none does), with no N.L,
    // so that acne under a low sun is black on white (shared/pcf_shading.h).
    if (uShading == PCF_SHADING_VISIBILITY) oColour = vec4(vec3(visibility * cone), 1.0f);
    // --shading cascades: the lit picture over the colour of the cascade read (red, green, blue,
    // yellow for cascades 0..3), untinted past the last and with one map.
    if (uShading == PCF_SHADING_CASCADES) {
        const vec3 CASCADE_TINTS[4] = vec3[4](vec3(1.0f, 0.35f, 0.35f), vec3(0.35f, 1.0f, 0.35f),
                                              vec3(0.45f, 0.55f, 1.0f), vec3(1.0f, 0.9f, 0.2f));
        vec3 tint = PCF_MAP_LAYERS > 1 && covered ? CASCADE_TINTS[layerIndex] : vec3(1.0f);
        oColour = vec4(tint * uAlbedoEncoded * pcfGammaEncode(light), 1.0f);
    }
#if PCF_ALL_TARGETS
    oLightSpace = uReceives != 0 ? vec4(u, v, ref, 1.0f) : vec4(0.0f);
    oVisibility = visibility;
    oReceiver = uReceives != 0 ? vec4(dzduv.x, dzduv.y, z0, 1.0f) : vec4(0.0f);
#endif
#if PCF_ALL_TARGETS >= 2
    oPosWs = vec4(vPosWs, 1.0f);
    oNormalWs = vec4(n, cosTheta);
    oNextReceiver = vec4(0.0f);
#if PCF_CASCADE_BLEND
    if (uReceives != 0) oNextReceiver = vec4(nextDzduv.x, nextDzduv.y, next.z0, 1.0f);
#endif
#endif
}
