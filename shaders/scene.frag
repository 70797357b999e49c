// scene.frag: shades the receivers with the chosen PCF method. The PCF math is not here: it is
// shared/pcf_kernel.h, the same source the CPU kernel compiles (the loader puts the prelude and
// the kernel before this file). PCF_METHOD and PCF_KERNEL arrive as defines, so the driver
// folds the method dispatch and unrolls the kernel loops. PCF_ALL_TARGETS adds outputs: 0 colour
// only (timing), 1 + light-space and visibility (the inspector), 2 + world position (tests, --raw).
// see: src/render/scene_renderer.cpp (uniforms, targets), src/kernel/pcf.h (CPU side)
in vec3 vPosWs;
in vec3 vNormalWs;

uniform sampler2D uPcfDepth;          // the shadow map, texelFetch side (pcf_prelude.h)
uniform mat4 uShadowClipFromWorld;    // light clip space from world
uniform vec3 uAlbedo;                 // linear colour of this object
uniform int uReceives;                // 1: look the shadow map up; 0: never shadowed
uniform int uLightType;               // 0 directional, 1 spot
uniform vec3 uLightDirWs;             // the direction the light travels (unit)
uniform vec3 uLightPosWs;             // spot only
uniform float uSpotCosCone;           // spot only: cos of the cone's half angle
uniform float uConstantBias;          // ref = z - bias, in light depth units ([0,1])
uniform float uRadius;                // poisson radius in texels
uniform int uRotatePerPixel;          // poisson: rotate the disk per pixel
uniform int uWeights;                 // pcf-naive, pcf-gather: PCF_WEIGHTS_*
uniform float uSigma;                 // gaussian weights, texels

layout(location = 0) out vec4 oColour;
#if PCF_ALL_TARGETS
layout(location = 1) out vec4 oLightSpace;  // u, v, ref, 1 on receivers (cleared to 0)
layout(location = 2) out float oVisibility; // what pcfFilter returned (1 off receivers)
#endif
#if PCF_ALL_TARGETS >= 2
layout(location = 3) out vec4 oPosWs;       // world position, w = 1 where drawn
#endif

const float AMBIENT = 0.25f;

void main() {
    vec3 n = normalize(vNormalWs);
    if (!gl_FrontFacing) n = -n;  // a plane seen from behind
    vec3 toLight = uLightType == 0 ? -uLightDirWs : normalize(uLightPosWs - vPosWs);
    float nDotL = max(dot(n, toLight), 0.0f);

    // GL convention: ndc = clip / w, uv = ndc.xy * 0.5 + 0.5, depth = ndc.z * 0.5 + 0.5.
    vec4 clip = uShadowClipFromWorld * vec4(vPosWs, 1.0f);
    vec3 ndc = clip.xyz / clip.w;
    float u = ndc.x * 0.5f + 0.5f;
    float v = ndc.y * 0.5f + 0.5f;
    float z = ndc.z * 0.5f + 0.5f;
    float ref = z - uConstantBias;

    float visibility = 1.0f;
    if (uReceives != 0) {
        vec2 rotation = uRotatePerPixel != 0 ? pcfPixelRotation(ivec2(gl_FragCoord.xy))
                                             : vec2(1.0f, 0.0f);
        visibility = pcfFilter(uPcfDepth, vec2(u, v), ref,
                               PcfParams(PCF_METHOD, PCF_KERNEL, uRadius, rotation, uWeights,
                                         uSigma));
    }
    float cone = 1.0f;
    if (uLightType == 1) cone = dot(-toLight, uLightDirWs) >= uSpotCosCone ? 1.0f : 0.0f;

    vec3 linear = uAlbedo * (AMBIENT + (1.0f - AMBIENT) * nDotL * visibility * cone);
    oColour = vec4(pow(linear, vec3(1.0f / 2.2f)), 1.0f);
#if PCF_ALL_TARGETS
    oLightSpace = uReceives != 0 ? vec4(u, v, ref, 1.0f) : vec4(0.0f);
    oVisibility = visibility;
#endif
#if PCF_ALL_TARGETS >= 2
    oPosWs = vec4(vPosWs, 1.0f);
#endif
}
