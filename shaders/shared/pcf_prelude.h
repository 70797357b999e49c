// pcf_prelude.h: the few words that let one source be both C++20 (with GLM) and GLSL 4.50.
//
// The PCF math in pcf_kernel.h is compiled twice: by the C++ compiler into the CPU kernel that
// the inspector, the tests and the trace use, and by the GL driver into the shaders that render
// the picture. Writing it once is what keeps the two equal (pbrt's PBRT_CPU_GPU idea).
//
// Rules for code in shaders/shared/ (both compilers must accept every line):
//   - float literals carry the f suffix (1.0f), unsigned ones the u suffix;
//   - single components only (v.x), no swizzles (v.xy) and no bool vectors in interfaces;
//   - no out-parameters: return a struct, built with Type(a, b, ...) (C++20 aggregate init);
//   - every function is marked PCF_FN, or PCF_MAP_FN when it reads the shadow map;
//   - the map is read only through fetchDepth(map, ivec2), pointDepth(map, vec2), hwTap(...),
//     gatherCompare(...), gatherDepth(...) and, for a moments map, fetchMoments(map, ivec2);
//     each texel read is reported through pcfTap(...), which records on the CPU and is
//     nothing in GLSL;
//   - values that feed floor() are PCF_PRECISE, so the GLSL compiler cannot fuse a multiply
//     and an add and land on the other side of an integer than the CPU does;
//   - constant arrays use PCF_CONST_ARRAY / PCF_ARRAY_BEGIN / PCF_ARRAY_END;
//   - a member added to a struct the C++ side builds positionally (PcfParams, PcfBias) comes
//     last, with its C++ default: `float x PCF_DEFAULT(1.0f);`. C++ code that builds the struct
//     without it keeps compiling, warning-free; GLSL has no member defaults, and the programs
//     build the structs member by member (render/pcf_programs.h, pcfProgramParams/-Bias);
//   - no #include here: the C++ wrapper (src/kernel/pcf.h) includes GLM, the shader loader
//     concatenates the sources in order.

#ifdef __cplusplus

// C++: functions are inline; those that read the map are templates over the map type, so the
// recording map (tracing) and the plain map (batch rendering) share one source and the plain
// one compiles the recording away.
#define PCF_FN inline
// clang-format off
#define PCF_MAP_FN template <class Map> inline
// clang-format on
#define PCF_PRECISE
#define PCF_CONST inline const
#define PCF_CONST_ARRAY(T, name, n) inline const T name[n] =
#define PCF_ARRAY_BEGIN(T, n) {
#define PCF_ARRAY_END }
#define PCF_DEFAULT(value) = value
#define PCF_PCSS_RECIPROCAL(k) PCF_PCSS_RECIPROCALS[k]

#else  // GLSL

#define PCF_FN
#define PCF_MAP_FN
#define PCF_PRECISE precise
#define PCF_CONST const
#define PCF_CONST_ARRAY(T, name, n) const T name[n] =
#define PCF_ARRAY_BEGIN(T, n) T[n](
#define PCF_ARRAY_END )
#define PCF_DEFAULT(value)
// pcss's table of 1 / k (pcf_disk.h, PCF_PCSS_RECIPROCALS), as a uniform array the program
// is given from the C++ copy of that table (render/pcf_programs.cpp, setParamUniforms): the same
// floats, and a uniform read at a dynamic index costs one load, where llvmpipe turns a dynamic
// index into the const array into a chain of selects (pcss's pass 1.24x -> 1.18x its textbook
// pass, scripts/pass-overhead).
uniform float uPcssReciprocals[17];
#define PCF_PCSS_RECIPROCAL(k) uPcssReciprocals[k]

// In GLSL the map is the depth texture behind a non-comparison sampler (nearest), and the
// same texture is bound a second time behind a comparison sampler (GL_LINEAR,
// GL_COMPARE_REF_TO_TEXTURE, GL_LEQUAL, clamp to edge) for hardware taps and gathers.
// A map of more than one layer (cascades, PCF_MAP_LAYERS > 1) is an array texture; the kernel
// reads the layer pcfMapLayer names, which the stage sets before it filters (scene.frag), so the
// kernel's code is the same for one layer or four. The CPU reads one layer's texels instead
// (kernel/pcf.h plainMap).
#ifndef PCF_MAP_LAYERS
#define PCF_MAP_LAYERS 1
#endif
#if PCF_MAP_LAYERS > 1
#define Map sampler2DArray
uniform sampler2DArrayShadow uPcfCompare;
int pcfMapLayer = 0;
// A map texture coordinate with the layer: (uv, layer) to sample, (uv, layer, ref) to compare.
#define PCF_MAP_UV(uv) vec3(uv, float(pcfMapLayer))
#define PCF_MAP_UV_REF(uv, ref) vec4(uv, float(pcfMapLayer), ref)
#else
#define Map sampler2D
uniform sampler2DShadow uPcfCompare;
#define PCF_MAP_UV(uv) (uv)
#define PCF_MAP_UV_REF(uv, ref) vec3(uv, ref)
#endif

ivec2 mapSize(Map map) { return textureSize(map, 0).xy; }

// The texture unit's state the kernel needs (issue 10): PCF_FIXED_POINT is 1 when the depth
// texture is fixed-point (16, 24 bit: D_ref clamped to [0,1]); PCF_PRECISION is the precision
// model of hardware taps and gathers (0 exact, 1 hw8: positions snapped to 1/256 texel before
// the tap). Defines of the program, not uniforms (issue 23): llvmpipe runs both sides of a
// branch on a uniform, so a uniform here made every tap pay for the clamp and the snapping.
// see: src/render/pcf_programs.cpp (PcfVariant, one program per set of defines)
#ifndef PCF_FIXED_POINT
#define PCF_FIXED_POINT 0
#endif
#ifndef PCF_PRECISION
#define PCF_PRECISION 0
#endif
// PCF_PERSPECTIVE is 1 for pcss on a spot's perspective map: the parameter block
// (pcfProgramParams) passes the map's near and far only then, and 0 otherwise, so the kernel's
// `depthNear > 0` folds away where depth is already linear.
#ifndef PCF_PERSPECTIVE
#define PCF_PERSPECTIVE 0
#endif
int mapFixedPoint(Map map) { return PCF_FIXED_POINT; }
int mapPrecision(Map map) { return PCF_PRECISION; }
// A texel's depth (the kernel clamps texel to the edge first), read through the nearest sampler at
// the texel's centre, not with texelFetch: llvmpipe bounds-checks every texelFetch again after
// the kernel's own clamp, which made the point-sampling methods cost 1.2-1.7x their textbook
// passes (scripts/pass-overhead, issue 23). A centre is half a texel from either edge, so every
// GPU's nearest rounding lands on that texel (GL 4.5 core, 8.14.2: floor(u * size)), whether it
// keeps 8 sub-texel bits (NVIDIA, AMD) or a float (llvmpipe): exactly texelFetch's value.
float fetchDepth(Map map, ivec2 texel) {
    return textureLod(map, PCF_MAP_UV((vec2(texel) + 0.5f) * (1.0f / vec2(mapSize(map)))), 0.0f).r;
}
// The depth of the texel that texel position p (uv * size) falls in, floor(p), clamped to the
// edge: fetchDepth(map, clamp(ivec2(floor(p)))). The same centre read, in float: the sampler's
// clamp to edge is the clamp, and no int conversions (Poisson's 16 taps: 1.24x -> 1.12x).
float pointDepth(Map map, vec2 p) {
    return textureLod(map, PCF_MAP_UV((floor(p) + 0.5f) * (1.0f / vec2(mapSize(map)))), 0.0f).r;
}
// A moments map's texel (kernel/shadow_map.h TexelKind::Moments*), the same centre read: a
// two-channel texture reads (m1, m2, 0, 1).
vec4 fetchMoments(Map map, ivec2 texel) {
    return textureLod(map, PCF_MAP_UV((vec2(texel) + 0.5f) * (1.0f / vec2(mapSize(map)))), 0.0f);
}
void pcfTap(Map map, ivec2 texel, float depth, float ref, float lit, float weight) {}
void pcfFetch(Map map, int kind, vec2 uv, float weight) {}
void pcfTapWanted(Map map, ivec2 texel) {}

// One hardware comparison tap: four comparisons lerped by the texture unit.
float hwTap(Map map, vec2 uv, float ref, float weight) {
    return texture(uPcfCompare, PCF_MAP_UV_REF(uv, ref));
}

// One comparison gather: the four bits around uv, in GL's component order
// x = texel (0,1), y = (1,1), z = (1,0), w = (0,0) relative to the 2x2 block's lower corner.
vec4 gatherCompare(Map map, vec2 uv, float ref, vec4 weights) {
    return textureGather(uPcfCompare, PCF_MAP_UV(uv), ref);
}

// One gather of raw depths (no comparison), same component order: through the nearest side's
// non-comparison sampler (clamp to edge), for comparisons made in the shader (soft bias).
vec4 gatherDepth(Map map, vec2 uv) { return textureGather(map, PCF_MAP_UV(uv), 0); }

#endif
