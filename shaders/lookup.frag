// lookup.frag: pcfFilter on arbitrary lookups, one per pixel: the GPU half of the parity tests
// on synthetic maps. Lookup (u, v, ref) comes from a float texture, so the CPU can run the very
// same inputs. The bias mode is a define, PCF_LOOKUP_BIAS, as in scene.frag and for the same
// reason: llvmpipe runs every side of a branch on a uniform, so the kernel's per-tap bias
// branches would cost their bodies in every mode. The weights, the precision model, the
// fixed-point clamp and the per-pixel rotation are defines too (render/pcf_programs.h), and the
// receiver planes are read only by the mode that uses them: a second float texture read per
// pixel is a third of what nearest's pass costs. see: src/render/gpu_lookup.cpp
uniform sampler2D uPcfDepth;
uniform sampler2D uLookups;  // RGBA32F: u, v, ref, unused
uniform sampler2D uPlanes;   // RG32F: dz/du, dz/dv of each lookup (receiver-plane bias)
uniform float uRadius;
uniform float uSoftScale;
uniform float uRpdbMax;      // receiver-plane: cap on dz/duv, depth per uv unit
uniform float uSigma;  // gaussian weights, texels
uniform float uPenumbraScale;  // pcss: texels of penumbra per unit of light depth
uniform vec2 uPcssDepthRange;  // pcss: a spot map's near, far; 0: orthographic

layout(location = 0) out float oVisibility;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 lookup = texelFetch(uLookups, pixel, 0);
    vec2 dzduv = vec2(0.0f);
#if PCF_LOOKUP_BIAS == 4  // PCF_BIAS_RECEIVER_PLANE (the preprocessor cannot read its const)
    vec4 plane = texelFetch(uPlanes, pixel, 0);
    dzduv = vec2(plane.x, plane.y);
#endif
    vec2 uv = vec2(lookup.x, lookup.y);
    // As scene.frag: the disk turns with the texel looked up (pcfTexelRotation).
    vec2 rotation = vec2(1.0f, 0.0f);
#if PCF_ROTATE_PER_PIXEL
    rotation = pcfTexelRotation(uv, textureSize(uPcfDepth, 0));
#endif
    PcfRef ref = PcfRef(lookup.z, uv, PcfBias(PCF_LOOKUP_BIAS, dzduv, uSoftScale, uRpdbMax));
    oVisibility = pcfFilterRef(uPcfDepth, uv, ref,
                               PcfParams(PCF_METHOD, PCF_KERNEL, uRadius, rotation, PCF_WEIGHTS,
                                         uSigma, uPenumbraScale, uPcssDepthRange.x,
                                         uPcssDepthRange.y));
}
