// pcf_shading.h: the camera pass's own math around the filter, in the subset of C++ and GLSL
// that pcf_kernel.h is written in (after pcf_prelude.h): where a receiver point is looked up,
// and the picture's gamma. Shared so that the CPU looks up a lesson's pinned scene point with the
// very formulas the fragment shader runs, and a C++ test can bound the gamma the shader applies.
// see: shaders/scene.frag (the caller), src/kernel/shading.h (C++), src/lesson/lesson_pick.h,
// tests/shading_test.cpp

// Where the camera pass looks a receiver point up: (u, v) in the map, its depth z, the depth z0
// before any bias and ref = z - bias. GL convention: ndc = clip / w, uv = ndc.xy * 0.5 + 0.5,
// depth = ndc.z * 0.5 + 0.5. cosTheta = dot(n, toLight) of the unit normal n facing the camera.
// Normal offset moves the point along n before it is projected (pcfNormalOffsetDistance: Holbert
// 2011, Castano 2013); a texel's world size grows with clip.w under a spot light's perspective and
// is constant under a directional light's (w = 1). Every other mode looks up where the point is.
// Slope bias scales with tan(theta) and is capped (pcfSlopeBias); every mode but none subtracts
// constantBias (0 for none).
struct PcfReceiverLookup {
    float u;
    float v;
    float z;    // the looked-up point's depth in [0,1], 0 = near the light
    float z0;   // the receiver point's own depth, before any bias or offset
    float ref;  // z - bias: the depth compared with the map
};

// A point's clip coordinates under the light's matrix m. On a cascade's grid (onGrid: a map of
// cascades, whose matrices are orthographic, w = 1) x and y are the point's own part, the
// rotation and scale rows times p, rounded to a multiple of 2^-23, plus the translation. A
// snapped cascade's translation is a whole number of texels of its power-of-two map, a multiple
// of 2 / size, so the sum is exact (both multiples of 2^-23, at most 1 in size inside the map),
// and so are u = x * 0.5 + 0.5 and the texel position u * size after it: a point seen through the
// map moved by whole texels lands in the same place of the same texel, bit for bit, and no tap
// flips as the camera turns (the stabilised cascades of Valient, "Stable Rendering of Cascaded
// Shadow Maps", ShaderX6, 2008). Without the rounding the sum's last bit depends on the
// translation, which moves a point 1.5e-5 texel from a texel's edge from one side to the other.
// The rounding moves a point by at most 2^-24 of the map's width. A map of one layer keeps the
// plain product (its matrix may be a spot light's perspective).
PCF_FN float pcfClipGrid(float a) {
    if (abs(a) >= 1.0f) return a;               // a multiple of 2^-23 already
    PCF_PRECISE float scaled = a * 8388608.0f;  // 2^23: exact
    return floor(scaled + 0.5f) * (1.0f / 8388608.0f);
}

PCF_FN vec4 pcfLightClip(mat4 m, vec3 p, bool onGrid) {
    vec4 clip = m * vec4(p, 1.0f);
    if (!onGrid) return clip;
    PCF_PRECISE float ax = m[0][0] * p.x + m[1][0] * p.y + m[2][0] * p.z;
    PCF_PRECISE float ay = m[0][1] * p.x + m[1][1] * p.y + m[2][1] * p.z;
    PCF_PRECISE float x = pcfClipGrid(ax) + m[3][0];
    PCF_PRECISE float y = pcfClipGrid(ay) + m[3][1];
    return vec4(x, y, clip.z, 1.0f);
}

PCF_FN PcfReceiverLookup pcfReceiverLookup(mat4 shadowClipFromWorld, vec3 posWs, vec3 n,
                                           float cosTheta, int biasMode, float constantBias,
                                           float slopeBias, float slopeMax, float normalOffset,
                                           float shadowTexelWs, bool onGrid) {
    vec4 clip0 = pcfLightClip(shadowClipFromWorld, posWs, onGrid);
    float z0 = (clip0.z / clip0.w) * 0.5f + 0.5f;
    vec4 clip = clip0;
    if (biasMode == PCF_BIAS_NORMAL) {
        float d = pcfNormalOffsetDistance(cosTheta, normalOffset, shadowTexelWs * clip0.w);
        clip = pcfLightClip(shadowClipFromWorld, posWs + n * d, onGrid);
    }
    float u = (clip.x / clip.w) * 0.5f + 0.5f;
    float v = (clip.y / clip.w) * 0.5f + 0.5f;
    float z = (clip.z / clip.w) * 0.5f + 0.5f;
    float bias = biasMode == PCF_BIAS_NONE ? 0.0f : constantBias;  // none subtracts nothing
    if (biasMode == PCF_BIAS_SLOPE)
        bias = pcfSlopeBias(cosTheta, constantBias, slopeBias, slopeMax);
    return PcfReceiverLookup(u, v, z, z0, z - bias);
}

// A receiver point's view depth: its distance from the camera's eye along the unit view
// direction, scene units, in the one order of operations both sides keep (PCF_PRECISE: no fused
// multiply-add), so the CPU, given the point the GPU shaded, picks the very same cascade.
PCF_FN float pcfViewDepth(vec3 posWs, vec3 eyeWs, vec3 viewDirWs) {
    PCF_PRECISE float dx = posWs.x - eyeWs.x;
    PCF_PRECISE float dy = posWs.y - eyeWs.y;
    PCF_PRECISE float dz = posWs.z - eyeWs.z;
    PCF_PRECISE float d = dx * viewDirWs.x + dy * viewDirWs.y + dz * viewDirWs.z;
    return d;
}

// Which cascade a receiver at view depth `viewDepth` reads, of `count` (1..4) whose view depths
// end at cascadeFar (x, y, z, w: cascades 0..3, scene/cascade_fit.h): the first that ends beyond
// it. `count` for a receiver beyond the last (past the shadow distance), which no cascade
// covers: it is lit.
PCF_FN int pcfCascadeLayer(float viewDepth, vec4 cascadeFar, int count) {
    int layer = 0;
    for (int k = 0; k < count; ++k) {
        if (viewDepth >= cascadeFar[k]) layer = k + 1;
    }
    return layer;
}

// The blend band between cascades (--cascade-blend B). Without it a receiver's visibility jumps
// where its view depth crosses a split, since the two cascades' texels differ in size (a seam).
// The band is the blending between cascades of Microsoft's "Cascaded Shadow Maps" (Windows
// DirectX technical article, 2011) and of MJP's Shadows sample (Pettineo, "A Sampling of Shadow
// Techniques", 2013): the last fraction B of cascade i's view depths [near, far] fades into
// cascade i + 1's lookup of the same point,
//   start = far - B (far - near),   w = clamp((d - start) / (far - start), 0, 1)
//   visibility = (1 - w) v_i + w v_(i+1)
// so that w reaches 1 where the next cascade begins and the two sides of the split agree. The
// weight is 0 for B = 0, before the band, past the last cascade and in the last (nothing comes
// after it). d: the receiver's view depth (pcfViewDepth), scene units; w in [0, 1].
PCF_FN float pcfCascadeBlendWeight(float viewDepth, vec2 layerViewDepth, float blend, int layer,
                                   int count) {
    if (!(blend > 0.0f) || layer + 1 >= count) return 0.0f;
    float farZ = layerViewDepth.y;
    float band = blend * (farZ - layerViewDepth.x);
    float start = farZ - band;
    return clamp((viewDepth - start) / band, 0.0f, 1.0f);
}

// The blended visibility of a receiver in the band: its own cascade's visibility v, the next
// cascade's vNext, the weight w of pcfCascadeBlendWeight: v + w (vNext - v), in [0, 1].
PCF_FN float pcfCascadeBlend(float visibility, float nextVisibility, float weight) {
    return visibility + weight * (nextVisibility - visibility);
}

// What the camera pass draws on the receivers (the `shading` setting, kernel/settings.h Shading):
// lit, the picture, albedo * (ambient + diffuse * N.L * visibility) gamma-encoded; or the
// visibility alone, the grey level v (0 black, 1 white: the byte is 255 v), no N.L, no albedo,
// no gamma, so that a pixel's byte reads back as the filter's result.
PCF_CONST int PCF_SHADING_LIT = 0;
PCF_CONST int PCF_SHADING_VISIBILITY = 1;
PCF_CONST int PCF_SHADING_CASCADES = 2;

// Gamma 2.2, encode: g(x) = x^(1/2.2) for the scene's light factor x in [0.25, 1] (ambient 0.25
// to full sun; scene.frag). The exponent is the conventional display gamma of "GPU Gems 3,
// Chapter 24: The Importance of Being Linear" (Gritz and d'Eon, 2007).
// A pow() is log2 and exp2, each a long polynomial on llvmpipe; this is one sqrt and a degree-4
// polynomial (pcfscope's own fit, interpolation at the 5 Chebyshev nodes of [0.5, 1]):
//   s = sqrt(x) in [0.5, 1],   x^(1/2.2) = s^(1/1.1) = s * s^(-1/11),   s^(-1/11) ~ q(s)
//   q(s) = c0 + c1 s + c2 s^2 + c3 s^3 + c4 s^4 (Horner)
// |g(x) - x^(1/2.2)| <= 6e-6 on [0.25, 1] (tests/shading_test.cpp), 0.0015 of one 8-bit step.
PCF_FN float pcfGammaEncode(float x) {
    float s = sqrt(x);
    float q = 0.0957764306f;
    q = q * s - 0.379465962f;
    q = q * s + 0.620897234f;
    q = q * s - 0.5769154f;
    q = q * s + 1.2397127f;
    return s * q;
}
