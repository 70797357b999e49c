// pcf_kernel.h: the PCF methods of pcfscope that compare depths, written once for C++ and GLSL
// (see pcf_prelude.h for the rules this file follows); the methods on the Poisson disk (poisson,
// pcss) follow in pcf_disk.h, the moment methods in pcf_moments.h and the dispatch over all of
// them in pcf_filter.h. C++ side: src/kernel/pcf.h.
// GLSL side: shaders/scene.frag.
//
// Conventions (docs/methods.md, "Conventions"):
//   shadow map W x H, depth in [0,1], 0 = near the light; texel (i, j) = column i, row j as
//   stored; its centre is at uv = ((i + 0.5) / W, (j + 0.5) / H);
//   texel position of a lookup: p = uv * size - 0.5, base = floor(p), frac = p - base
//   (GL's bilinear convention); texels outside the map clamp to the edge;
//   a tap is lit (1) when ref <= depth (GL_LEQUAL), shadowed (0) otherwise;
//   visibility 1 = fully lit, 0 = fully shadowed.

// Method ids, in the order of docs/methods.md, "The methods" (the command line's names:
// src/kernel/methods).
PCF_CONST int PCF_NEAREST = 0;
PCF_CONST int PCF_BOX2X2 = 1;
PCF_CONST int PCF_BILINEAR2X2 = 2;
PCF_CONST int PCF_HW2X2 = 3;
PCF_CONST int PCF_NAIVE = 4;
PCF_CONST int PCF_GATHER = 5;
PCF_CONST int PCF_HW = 6;
PCF_CONST int PCF_TENT = 7;
PCF_CONST int PCF_POISSON = 8;
PCF_CONST int PCF_PCSS = 9;
PCF_CONST int PCF_VSM = 10;
PCF_CONST int PCF_EVSM2 = 11;
PCF_CONST int PCF_EVSM4 = 12;
PCF_CONST int PCF_MSM = 13;
PCF_CONST int PCF_MSM_HAUSDORFF = 14;
PCF_CONST int PCF_METHOD_COUNT = 15;
// What pcfFilterRef returns for a method id it has no branch for: outside [0,1], so a method
// missing from the dispatch fails the tests instead of running another method.
PCF_CONST float PCF_UNDISPATCHED = -1.0f;

// What one fetch instruction is, for the trace and the fetch counts.
PCF_CONST int PCF_FETCH_POINT = 0;   // one texel read (nearest sampler, texel's centre)
PCF_CONST int PCF_FETCH_LOOKUP = 1;  // a software bilinear lookup: four texel reads
PCF_CONST int PCF_FETCH_GATHER = 2;  // one textureGather on the comparison sampler
PCF_CONST int PCF_FETCH_HW = 3;      // one hardware comparison tap (sampler2DShadow, GL_LINEAR)

// One layer of a shadow map: the fit the light saw it through. C++: kernel/shadow_map.h's
// MapSpec holds one per layer; GLSL: the uniform array uPcfMapLayers (render/pcf_programs.h,
// paramUniformsGlsl), one entry per layer, set from the same MapSpec (setMapUniforms).
struct PcfMapLayer {
    // The light's clip space from world: uv = 0.5 * xy / w + 0.5, depth = 0.5 * z / w + 0.5
    mat4 shadowClipFromWorld;
    // A perspective (spot) map's near and far planes, scene units; (0, 0): orthographic
    vec2 depthRange;
    // One texel's world size at clip w = 1 (normal offset's unit); 0 when not known
    float texelWs;
    // A cascade's view depths (scene units along the camera's view direction, near and far):
    // the receivers it serves (scene/cascade_fit.h); (0, 0): not a cascade, every receiver
    vec2 viewDepth PCF_DEFAULT(vec2(0.0f));
};

// What a method needs besides the lookup itself.
struct PcfParams {
    int method;     // PCF_NEAREST .. PCF_PCSS
    int kernel;     // N: 1..8 for pcf-naive, pcf-gather and pcf-hw; 3, 5 or 7 for tent
    float radius;   // poisson: disk radius in texels (Jimmy 2010 uses 1)
    vec2 rotation;  // poisson: (cos, sin) of the disk's rotation; (1, 0) for none
    int weights;    // pcf-naive, pcf-gather: PCF_WEIGHTS_BOX (0), _BINOMIAL or _GAUSSIAN
    float sigma;    // gaussian weights: standard deviation in texels
    // pcss: the light's size in the map, texels of penumbra width per unit of light depth
    // between receiver and blocker (scene/pcss.h computes it from the light and the map)
    float penumbraScale;
    // pcss under a perspective (spot) map: its near and far planes, scene units, to make depth
    // linear (pcfPcssLinearDepth); near 0: an orthographic map, depth already linear
    float depthNear;
    float depthFar;
#ifdef __cplusplus
    // The CPU's model of the texture unit (PCF_PRECISION_EXACT or _HW8). In GLSL the same
    // choice is the define PCF_PRECISION, read through mapPrecision(map) (pcf_prelude.h).
    int precision = 0;
#endif
    // The moment methods (vsm .. msm-hausdorff, pcf_moments.h): the light-bleeding
    // reduction's cut (linstep's low end, 0: none), the least variance the bound takes (light
    // depth squared), the EVSM exponents (positive, negative) as used, after the clamp to what
    // the moment format holds, and MSM's moment bias alpha.
    float lbr PCF_DEFAULT(0.0f);
    float minVariance PCF_DEFAULT(0.0f);
    vec2 evsmExponents PCF_DEFAULT(vec2(0.0f));
    float momentBias PCF_DEFAULT(0.0f);
};

// Where a lookup falls in texel space.
struct PcfTexelPos {
    vec2 p;      // uv * size - 0.5, in texels
    ivec2 base;  // floor(p): the lower-left texel of the bilinear 2x2
    vec2 frac;   // p - base, in [0,1): the sub-texel position that weights the lerp
};

PCF_FN PcfTexelPos pcfTexelPos(vec2 uv, ivec2 size) {
    PCF_PRECISE vec2 p = uv * vec2(size) - vec2(0.5f);
    vec2 b = floor(p);
    return PcfTexelPos(p, ivec2(b), p - b);
}

PCF_FN ivec2 pcfClampTexel(ivec2 texel, ivec2 size) {
    return clamp(texel, ivec2(0), size - ivec2(1));
}

// ---- The texture unit's own arithmetic (issue 10) ----------------------------------------
//
// Fixed-point depth (GL 4.5 core profile, section 8.23.1, "Depth Texture Comparison Mode"): for
// a fixed-point depth format (16, 24 bit) both D_ref and D_t are clamped to [0,1] before the
// comparison; for 32F neither is. The stored D_t of a fixed-point map is already in [0,1], so
// only D_ref needs the clamp. mapFixedPoint(map) is 1 for a 16/24-bit map (CPU: ShadowMap's
// format; GLSL: the define PCF_FIXED_POINT). Every method clamps, texelFetch ones included, so
// that bilinear2x2 stays equal to the hardware tap it emulates.
PCF_MAP_FN float pcfDepthRef(Map map, float ref) {
    return mapFixedPoint(map) != 0 ? clamp(ref, 0.0f, 1.0f) : ref;
}

// Precision of the texel position inside hardware taps and gathers.
//   exact: float, what llvmpipe does (measured, docs/methods.md, "Conventions");
//   hw8:   the position kept with 8 fractional bits, i.e. in steps of 1/256 texel, as NVIDIA and
//          AMD texture units do. Sources: Direct3D 12 functional spec, constant
//          D3D12_SUBTEXEL_FRACTIONAL_BIT_COUNT = 8; Inigo Quilez, "hardware interpolation"
//          (iquilezles.org, 2008): the interpolant is 24.8 fixed point; the Vulkan spec only
//          requires subTexelPrecisionBits >= 4.
PCF_CONST int PCF_PRECISION_EXACT = 0;
PCF_CONST int PCF_PRECISION_HW8 = 1;
PCF_CONST float PCF_SUBTEXEL_STEPS = 256.0f;  // 2^8 steps per texel

// hw8's rounding: round to nearest, ties up, of p * 256: q = floor(p * 256 + 0.5) / 256. Both
// steps are exact in float for |p| < 2^15 texels (p * 256 is a power-of-two scaling), so CPU and
// GPU agree bit for bit. The result is in [p - 1/512, p + 1/512].
PCF_FN vec2 pcfQuantiseTexelPos(vec2 p) {
    PCF_PRECISE vec2 s = p * PCF_SUBTEXEL_STEPS + vec2(0.5f);
    return floor(s) / PCF_SUBTEXEL_STEPS;
}

// The texel position the texture unit works with for a tap or gather at uv.
PCF_MAP_FN vec2 pcfUnitTexelPos(Map map, vec2 uv) {
    vec2 p = pcfTexelPos(uv, mapSize(map)).p;
    return mapPrecision(map) == PCF_PRECISION_HW8 ? pcfQuantiseTexelPos(p) : p;
}

// The uv handed to a hardware tap or a gather: unchanged for exact; for hw8, the uv of the
// quantised position, so that an exact texture unit (llvmpipe) computes what an 8-bit one
// would, and an 8-bit unit rounds it back to the same step (|error| << 1/512 texel).
PCF_MAP_FN vec2 pcfUnitUv(Map map, vec2 uv) {
    if (mapPrecision(map) != PCF_PRECISION_HW8) return uv;
    PCF_PRECISE vec2 q = pcfUnitTexelPos(map, uv) + vec2(0.5f);
    return q / vec2(mapSize(map));
}

// The depth comparison (GL_LEQUAL): 1 = lit, 0 = shadowed.
PCF_FN float pcfCompare(float depth, float ref) { return ref <= depth ? 1.0f : 0.0f; }

// ---- Bias modes (docs/methods.md, "Bias modes", names them; see: src/kernel/bias.h for names and
// checks) ---- The per-lookup part of every bias (constant, slope, normal offset) is already in ref
// when the kernel is called: the scene shader (shaders/scene.frag) computes it where the normal and
// the light are known. What the kernel itself must do per tap lives here: the receiver plane's ref
// at each tap, the soft comparison of "PCF Shadow Acne 2", and the comparison against
// interpolated depth of "PCF Shadow Acne".
PCF_CONST int PCF_BIAS_NONE = 0;            // ref = z
PCF_CONST int PCF_BIAS_CONSTANT = 1;        // ref = z - b
PCF_CONST int PCF_BIAS_SLOPE = 2;           // ref = z - min(b + s * tan(theta), max)
PCF_CONST int PCF_BIAS_NORMAL = 3;          // receiver moved along its normal, then ref = z' - b
PCF_CONST int PCF_BIAS_RECEIVER_PLANE = 4;  // per tap: ref + dot(dz/duv, tap uv - uv)
PCF_CONST int PCF_BIAS_SOFT = 5;            // lit = (depth > ref) * saturate((depth - ref) * k)
PCF_CONST int PCF_BIAS_INTERPOLATED = 6;    // one comparison against the bilinear depth
PCF_CONST int PCF_BIAS_COUNT = 7;

// What the kernel needs of the bias mode per tap.
struct PcfBias {
    int mode;         // PCF_BIAS_NONE .. PCF_BIAS_INTERPOLATED
    vec2 dzduv;       // receiver-plane: d(depth)/d(u, v) of the receiver, light depth per uv unit
    float softScale;  // soft: "PCF Shadow Acne 2"'s Z_CMP_CORRECTION_SCALE, 1/depth
    float rpdbMax;    // receiver-plane: cap on |dz/du|, |dz/dv|, light depth per uv unit
};

// A cap so large no receiver reaches it: the receiver plane as measured (tests, old callers).
PCF_CONST float PCF_DZDUV_UNCLAMPED = 1.0e30f;

// A lookup's comparison depth with what varies it per tap.
struct PcfRef {
    float ref;  // the lookup's ref, light depth [0,1], after the per-lookup bias
    vec2 uv;    // the lookup's uv: the receiver plane passes through (uv, ref)
    PcfBias bias;
};

// One ref for every tap: what every method did before per-tap biases.
PCF_FN PcfRef pcfPlainRef(float ref, vec2 uv) {
    return PcfRef(ref, uv, PcfBias(PCF_BIAS_CONSTANT, vec2(0.0f), 0.0f, PCF_DZDUV_UNCLAMPED));
}

// The centre of texel t in uv (docs/methods.md, "Conventions"): ((i + 0.5) / W, (j + 0.5) / H).
PCF_FN vec2 pcfTexelCentreUv(ivec2 t, ivec2 size) { return (vec2(t) + vec2(0.5f)) / vec2(size); }

// Receiver-plane depth bias (Isidoro, "Shadow Mapping: GPU-based Tips and Techniques", GDC
// 2006): the receiver is taken to be the plane through (uv, ref) with slope dz/duv, so a tap at
// tapUv compares against that plane's depth there, not against the lookup's one ref:
//   ref_tap = ref + dz/du * (tapU - u) + dz/dv * (tapV - v)        (light depth, [0,1] scale)
// Other modes return ref unchanged.
PCF_FN float pcfRefAt(PcfRef r, vec2 tapUv) {
    if (r.bias.mode != PCF_BIAS_RECEIVER_PLANE) return r.ref;
    PCF_PRECISE float du = tapUv.x - r.uv.x;
    PCF_PRECISE float dv = tapUv.y - r.uv.y;
    PCF_PRECISE float dz = r.bias.dzduv.x * du + r.bias.dzduv.y * dv;
    PCF_PRECISE float tapRef = r.ref + dz;
    return tapRef;
}

// The receiver plane's slope, capped. The slope comes from screen-space derivatives, and where
// a pixel's 2x2 quad straddles two surfaces (an outline, a box's edge) or the surface is edge-on
// to the light, dz/duv is no usable slope (on `grazing` up to ~2e5 light depth per uv unit, where
// the ground has 1.3) and the plane sends the taps' refs far off. Engines therefore clamp it
// before use: DiligentFX (DiligentGraphics, Shaders/Common/public/Shadows.fxh,
// fReceiverPlaneDepthBiasClamp) clamps each component of dz/duv, in depth per uv unit, before it
// scales it to texels:
//   dz/du' = clamp(dz/du, -M, M),  dz/dv' = clamp(dz/dv, -M, M)     (light depth per uv unit)
// Per uv unit, as there, the cap is a property of the surface's tilt and means the same at every
// map size. A slope within the cap is returned unchanged, bit for bit.
// (MJP's Shadows sample, Mesh.hlsl, caps a related static term instead,
// min(dot(texelSize, |dz/duv|), 0.01), and Unity's UnityShadowLibrary.cginc does the same with
// its own constant; pcfscope has no such term: --constant-bias plays its part.)
PCF_FN vec2 pcfClampDzDuv(vec2 dzduv, float maxPerUv) {
    return vec2(clamp(dzduv.x, -maxPerUv, maxPerUv), clamp(dzduv.y, -maxPerUv, maxPerUv));
}

// The soft comparison of "PCF Shadow Acne 2": a tap counts as lit only when the
// stored depth is strictly beyond ref, and then only in proportion to how far, saturated:
//   lit = (depth > ref) * saturate((depth - ref) * scale)         (scale in 1/depth units)
// so a texel just behind the receiver's own surface fades in instead of flipping. As scale
// grows it becomes the hard comparison (except at depth == ref, where it says 0).
PCF_FN float pcfCompareSoft(float depth, float ref, float scale) {
    float ahead = ref < depth ? 1.0f : 0.0f;
    PCF_PRECISE float ramp = (depth - ref) * scale;
    return ahead * clamp(ramp, 0.0f, 1.0f);
}

// The comparison a tap makes under the bias mode: soft for PCF_BIAS_SOFT, else GL_LEQUAL.
PCF_FN float pcfCompareBiased(float depth, float ref, PcfBias b) {
    if (b.mode == PCF_BIAS_SOFT) return pcfCompareSoft(depth, ref, b.softScale);
    return pcfCompare(depth, ref);
}

// Slope-scaled bias as most engines write it (opengl-tutorial.org, Tutorial 16 "Shadow
// mapping": bias = b * tan(acos(n.l)), clamped; Castano, "Shadow Mapping Summary Part 1",
// 2013, the same tan with a cap): with theta the angle between the normal and the direction to
// the light,
//   bias = min(b + s * tan(theta), max)     tan(theta) = sqrt(1 - c^2) / c, c = cos(theta)
// c is held >= 1e-4 so a surface edge-on to the light gets max, not infinity.
PCF_FN float pcfSlopeBias(float cosTheta, float b, float s, float maxBias) {
    float c = clamp(cosTheta, 1.0e-4f, 1.0f);
    float tanTheta = sqrt(max(1.0f - c * c, 0.0f)) / c;
    return min(b + s * tanTheta, maxBias);
}

// Normal offset (Holbert, "Saying Goodbye to Shadow Acne", GDC 2011; the scale by the sine is
// Castano's, "Shadow Mapping Summary Part 1", 2013): before it is projected into the map, the
// receiver point moves along its unit normal by
//   d = k * texelWs * sin(theta)     sin(theta) = sqrt(1 - c^2), c = cos(theta) clamped to [0,1]
// world units, where texelWs is the world size of one shadow-map texel at the point and k is
// in texels. Facing the light (theta = 0) it does not move; edge-on it moves k texels.
PCF_FN float pcfNormalOffsetDistance(float cosTheta, float k, float texelWs) {
    float c = clamp(cosTheta, 0.0f, 1.0f);
    return k * texelWs * sqrt(max(1.0f - c * c, 0.0f));
}

// dz/duv from screen-space derivatives (Isidoro, GDC 2006; the same in MJP's Shadows sample):
// with dx = d(u, v, z)/dx and dy = d(u, v, z)/dy across the screen, the 2x2 Jacobian
// J = [du/dx dv/dx; du/dy dv/dy] maps d(uv) to screen steps, and
//   (dz/du, dz/dv) = J^-1 (dz/dx, dz/dy)    (the inverse transpose of d(uv)/d(x, y))
//   dz/du = (dv/dy * dz/dx - dv/dx * dz/dy) / det,  dz/dv = (du/dx * dz/dy - du/dy * dz/dx) / det
// with det = du/dx * dv/dy - dv/dx * du/dy. A degenerate (det = 0) or non-finite result gives 0.
PCF_FN vec2 pcfReceiverPlaneDzDuv(vec3 dx, vec3 dy) {
    float det = dx.x * dy.y - dx.y * dy.x;
    if (det == 0.0f) return vec2(0.0f);
    float a = (dy.y * dx.z - dx.y * dy.z) / det;
    float b = (dx.x * dy.z - dy.x * dx.z) / det;
    // NaN fails both comparisons; so does anything beyond float range.
    if (!(abs(a) < 3.0e38f) || !(abs(b) < 3.0e38f)) return vec2(0.0f);
    return vec2(a, b);
}

// Compares the depth read for texel `texel` (clamped to the edge) and reports the tap with its
// weight in the final result.
// The tap's own ref is the receiver plane's at the (unclamped) texel's centre under
// receiver-plane bias, and the lookup's ref otherwise; on fixed-point maps it is then clamped to
// [0,1] (pcfDepthRef); the soft mode compares softly.
PCF_MAP_FN float pcfCompareTexel(Map map, ivec2 texel, float depth, PcfRef ref, float weight) {
    pcfTapWanted(map, texel);  // the trace marks taps that clamp to the edge
    ivec2 size = mapSize(map);
    ivec2 t = pcfClampTexel(texel, size);  // in GLSL only the (empty) pcfTap reads it
    // The texel's centre only where the plane needs it: the other modes pay nothing per tap.
    float tapRef = ref.ref;
    if (ref.bias.mode == PCF_BIAS_RECEIVER_PLANE) {
        tapRef = pcfRefAt(ref, pcfTexelCentreUv(texel, size));
    }
    float r = pcfDepthRef(map, tapRef);  // fixed-point maps: D_ref clamped to [0,1]
    float lit = pcfCompareBiased(depth, r, ref.bias);
    pcfTap(map, t, depth, r, lit, weight);
    return lit;
}

// Reads one texel (clamped to the edge) and compares it (pcfCompareTexel).
PCF_MAP_FN float pcfFetchCompare(Map map, ivec2 texel, PcfRef ref, float weight) {
    float depth = fetchDepth(map, pcfClampTexel(texel, mapSize(map)));
    return pcfCompareTexel(map, texel, depth, ref, weight);
}

// The bilinear weights of the four texels of a 2x2, row-major: (0,0), (1,0), (0,1), (1,1).
PCF_FN vec4 pcfBilinearWeights(vec2 f) {
    return vec4((1.0f - f.x) * (1.0f - f.y), f.x * (1.0f - f.y), (1.0f - f.x) * f.y, f.x * f.y);
}

// "What Is PCF": compare the four texels around texel position p, then lerp the four bits by the
// sub-texel position: lerp(lerp(b00, b10, fx), lerp(b01, b11, fx), fy). This is what NVIDIA's
// hardware PCF does, and what pcfscope takes a hardware comparison tap to be. weight is the
// share of the final result this lookup carries (for the trace only).
PCF_MAP_FN float pcfBilinearAt(Map map, vec2 p, PcfRef ref, float weight) {
    vec2 b = floor(p);
    ivec2 base = ivec2(b);
    vec2 f = p - b;
    vec4 w = pcfBilinearWeights(f) * weight;
    float b00 = pcfFetchCompare(map, base, ref, w.x);
    float b10 = pcfFetchCompare(map, base + ivec2(1, 0), ref, w.y);
    float b01 = pcfFetchCompare(map, base + ivec2(0, 1), ref, w.z);
    float b11 = pcfFetchCompare(map, base + ivec2(1, 1), ref, w.w);
    return mix(mix(b00, b10, f.x), mix(b01, b11, f.x), f.y);
}

PCF_MAP_FN float pcfBilinearCore(Map map, vec2 uv, PcfRef ref, float weight) {
    return pcfBilinearAt(map, pcfTexelPos(uv, mapSize(map)).p, ref, weight);
}

PCF_MAP_FN float pcfBilinearLookup(Map map, vec2 uv, PcfRef ref, float weight) {
    pcfFetch(map, PCF_FETCH_LOOKUP, uv, weight);
    return pcfBilinearCore(map, uv, ref, weight);
}

#ifdef __cplusplus
// On the CPU a hardware comparison tap is modelled exactly as the bilinear 2x2 (docs/methods.md,
// "Conventions"). With hw8 the position is quantised before floor and frac (pcfUnitTexelPos).
template <class Map>
inline float hwTap(Map map, vec2 uv, float ref, float weight) {
    return pcfBilinearAt(map, pcfUnitTexelPos(map, uv), pcfPlainRef(ref, uv), weight);
}

// On the CPU a comparison gather is four texel comparisons, returned in GL's component order.
template <class Map>
inline vec4 gatherCompare(Map map, vec2 uv, float ref, vec4 weights) {
    ivec2 base = ivec2(floor(pcfUnitTexelPos(map, uv)));
    PcfRef r = pcfPlainRef(ref, uv);
    float x = pcfFetchCompare(map, base + ivec2(0, 1), r, weights.x);
    float y = pcfFetchCompare(map, base + ivec2(1, 1), r, weights.y);
    float z = pcfFetchCompare(map, base + ivec2(1, 0), r, weights.z);
    float w = pcfFetchCompare(map, base + ivec2(0, 0), r, weights.w);
    return vec4(x, y, z, w);
}

// On the CPU a gather of raw depths is the four texels, in GL's component order.
template <class Map>
inline vec4 gatherDepth(Map map, vec2 uv) {
    ivec2 size = mapSize(map);
    PcfTexelPos tp = pcfTexelPos(uv, size);
    return vec4(fetchDepth(map, pcfClampTexel(tp.base + ivec2(0, 1), size)),
                fetchDepth(map, pcfClampTexel(tp.base + ivec2(1, 1), size)),
                fetchDepth(map, pcfClampTexel(tp.base + ivec2(1, 0), size)),
                fetchDepth(map, pcfClampTexel(tp.base + ivec2(0, 0), size)));
}

// On the CPU the point read at texel position p is the texel floor(p), clamped to the edge.
template <class Map>
inline float pointDepth(Map map, vec2 p) {
    return fetchDepth(map, pcfClampTexel(ivec2(floor(p)), mapSize(map)));
}
#endif

// A hardware tap compares its four texels against one ref: under receiver-plane bias that is
// the plane's depth at the tap's own uv (per tap, as engines do; not per texel).
PCF_MAP_FN float pcfHwTap(Map map, vec2 uv, PcfRef ref, float weight) {
    pcfFetch(map, PCF_FETCH_HW, uv, weight);
    return hwTap(map, pcfUnitUv(map, uv), pcfRefAt(ref, uv), weight);
}

// "PCF Shadow Acne", Solution 2: interpolate the stored depth bilinearly at uv and
// compare once. For a planar receiver the interpolated depth follows the surface, so the
// receiver's own texels stop shadowing it; but the sub-texel fraction is spent on the depth, so
// the result is one hard bit and cannot be a filter (hence nearest only: src/kernel/bias.cpp).
// The four texels are recorded with their bilinear weights, each carrying the one bit.
PCF_MAP_FN float pcfInterpolatedCompare(Map map, vec2 uv, float ref, float weight) {
    ivec2 size = mapSize(map);
    PcfTexelPos tp = pcfTexelPos(uv, size);
    vec4 w = pcfBilinearWeights(tp.frac);
    ivec2 t00 = pcfClampTexel(tp.base, size);
    ivec2 t10 = pcfClampTexel(tp.base + ivec2(1, 0), size);
    ivec2 t01 = pcfClampTexel(tp.base + ivec2(0, 1), size);
    ivec2 t11 = pcfClampTexel(tp.base + ivec2(1, 1), size);
    float d00 = fetchDepth(map, t00);
    float d10 = fetchDepth(map, t10);
    float d01 = fetchDepth(map, t01);
    float d11 = fetchDepth(map, t11);
    PCF_PRECISE float depth = w.x * d00 + w.y * d10 + w.z * d01 + w.w * d11;
    ref = pcfDepthRef(map, ref);
    float lit = pcfCompare(depth, ref);
    pcfTap(map, t00, d00, ref, lit, w.x * weight);
    pcfTap(map, t10, d10, ref, lit, w.y * weight);
    pcfTap(map, t01, d01, ref, lit, w.z * weight);
    pcfTap(map, t11, d11, ref, lit, w.w * weight);
    return lit;
}

// "PCF Shadow Acne 2"'s gather of raw depths, the soft comparison made in the shader (its 3x3 code
// gathers depths through a point sampler, not comparisons). Bits in GL's gather order.
PCF_MAP_FN vec4 pcfGatherSoft(Map map, vec2 uv, PcfRef ref, vec4 weights) {
    ivec2 size = mapSize(map);
    ivec2 base = pcfTexelPos(uv, size).base;
    vec4 d = gatherDepth(map, uv);
    float s = ref.bias.softScale;
    float r = pcfDepthRef(map, ref.ref);
    vec4 bits = vec4(pcfCompareSoft(d.x, r, s), pcfCompareSoft(d.y, r, s),
                     pcfCompareSoft(d.z, r, s), pcfCompareSoft(d.w, r, s));
    pcfTap(map, pcfClampTexel(base + ivec2(0, 1), size), d.x, r, bits.x, weights.x);
    pcfTap(map, pcfClampTexel(base + ivec2(1, 1), size), d.y, r, bits.y, weights.y);
    pcfTap(map, pcfClampTexel(base + ivec2(1, 0), size), d.z, r, bits.z, weights.z);
    pcfTap(map, pcfClampTexel(base + ivec2(0, 0), size), d.w, r, bits.w, weights.w);
    return bits;
}

// nearest at texel position p (texels, uv * size): the one texel floor(p). Hard: 0 or 1. uv is
// the same point in uv, what the trace records and the interpolated comparison reads.
PCF_MAP_FN float pcfNearestAt(Map map, vec2 p, vec2 uv, PcfRef ref, float weight) {
    if (ref.bias.mode == PCF_BIAS_INTERPOLATED) {
        pcfFetch(map, PCF_FETCH_LOOKUP, uv, weight);
        return pcfInterpolatedCompare(map, uv, ref.ref, weight);
    }
    pcfFetch(map, PCF_FETCH_POINT, uv, weight);
    // pointDepth, not fetchDepth of the int texel: in GLSL the sampler clamps, in float.
    return pcfCompareTexel(map, ivec2(floor(p)), pointDepth(map, p), ref, weight);
}

// nearest: the one texel the lookup falls in, floor(uv * size). Hard: 0 or 1.
PCF_MAP_FN float pcfNearest(Map map, vec2 uv, PcfRef ref, float weight) {
    PCF_PRECISE vec2 p = uv * vec2(mapSize(map));
    return pcfNearestAt(map, p, uv, ref, weight);
}

// box2x2: the bilinear 2x2 texels, averaged without weights: only 0, .25, .5, .75 or 1.
PCF_MAP_FN float pcfBox2x2(Map map, vec2 uv, PcfRef ref) {
    PcfTexelPos tp = pcfTexelPos(uv, mapSize(map));
    float sum = 0.0f;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            pcfFetch(map, PCF_FETCH_POINT, uv, 0.25f);
            sum += pcfFetchCompare(map, tp.base + ivec2(i, j), ref, 0.25f);
        }
    }
    return sum * 0.25f;
}

// Offset of lookup k of an N-wide kernel, in texels: k - (N-1)/2 (half texels when N is even).
PCF_FN float pcfKernelOffset(int k, int n) { return float(k) - 0.5f * float(n - 1); }

// pcf-naive: N x N bilinear lookups one texel apart, averaged ("PCF Shadow Acne"): 4 N^2 reads.
// The lookups step in texel space (p + offset), so every lookup has the fraction of p exactly
// and the sum equals pcf-gather's to float rounding.
PCF_MAP_FN float pcfNaive(Map map, vec2 uv, PcfRef ref, int n) {
    ivec2 size = mapSize(map);
    vec2 p = pcfTexelPos(uv, size).p;
    vec2 texelUv = vec2(1.0f) / vec2(size);
    float w = 1.0f / float(n * n);
    float sum = 0.0f;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            vec2 offset = vec2(pcfKernelOffset(i, n), pcfKernelOffset(j, n));
            PCF_PRECISE vec2 pk = p + offset;
            pcfFetch(map, PCF_FETCH_LOOKUP, uv + offset * texelUv, w);
            sum += pcfBilinearAt(map, pk, ref, w);
        }
    }
    return sum * w;
}

// pcf-hw: the same N x N loop with one hardware comparison tap per lookup (ogldev 42's loop).
PCF_MAP_FN float pcfHw(Map map, vec2 uv, PcfRef ref, int n) {
    vec2 texelUv = vec2(1.0f) / vec2(mapSize(map));
    float w = 1.0f / float(n * n);
    float sum = 0.0f;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            vec2 offset = vec2(pcfKernelOffset(i, n), pcfKernelOffset(j, n));
            sum += pcfHwTap(map, uv + offset * texelUv, ref, w);
        }
    }
    return sum * w;
}

// Where the N x N lookups of pcf-naive land, as one footprint: all N^2 lookups share one
// fraction g, and lookup (i, j) has its 2x2 at origin + (i, j). So the (N+1) x (N+1) texels
// from origin carry, per axis, the weight of "PCF Shadow Acne 2"'s table generalised to any N:
//   m = 0: 1 - g      0 < m < N: 1      m = N: g        (then divided by N)
struct PcfFootprint {
    ivec2 origin;  // lower-left texel of the (N+1) x (N+1) footprint
    vec2 frac;     // g: the fraction every lookup of the kernel shares
};

PCF_FN PcfFootprint pcfKernelFootprint(vec2 uv, ivec2 size, int n) {
    PCF_PRECISE vec2 q = pcfTexelPos(uv, size).p + vec2(pcfKernelOffset(0, n));
    vec2 b = floor(q);
    return PcfFootprint(ivec2(b), q - b);
}

// The per-axis weight of footprint texel m (0..N) before the 1/N, for fraction g.
PCF_FN float pcfFootprintWeight(int m, int n, float g) {
    float w = 0.0f;
    if (m < n) w += 1.0f - g;
    if (m > 0) w += g;
    return w;
}

// pcf-gather: the result of pcf-naive from the (N+1)^2 distinct texels, each read once, by
// ceil((N+1)/2)^2 comparison gathers weighted by the footprint table ("PCF Shadow Acne 2", N = 3).
// Each gather is placed at the shared corner of its 2x2 block, so the texture unit's own
// floor() cannot pick another block.
PCF_MAP_FN float pcfGather(Map map, vec2 uv, PcfRef ref, int n) {
    ivec2 size = mapSize(map);
    PcfFootprint fp = pcfKernelFootprint(uv, size, n);
    vec2 texelUv = vec2(1.0f) / vec2(size);
    float norm = 1.0f / float(n * n);
    int blocks = (n + 2) / 2;
    float sum = 0.0f;
    for (int by = 0; by < blocks; ++by) {
        for (int bx = 0; bx < blocks; ++bx) {
            int mx = 2 * bx;
            int my = 2 * by;
            float wx0 = pcfFootprintWeight(mx, n, fp.frac.x);
            float wx1 = mx + 1 <= n ? pcfFootprintWeight(mx + 1, n, fp.frac.x) : 0.0f;
            float wy0 = pcfFootprintWeight(my, n, fp.frac.y);
            float wy1 = my + 1 <= n ? pcfFootprintWeight(my + 1, n, fp.frac.y) : 0.0f;
            // GL's gather order: x = (0,1), y = (1,1), z = (1,0), w = (0,0).
            vec4 w = vec4(wx0 * wy1, wx1 * wy1, wx1 * wy0, wx0 * wy0) * norm;
            // The shared corner: a whole number of texels, so an ulp either way of the product
            // still lands the gather on this block (half a texel from either neighbour).
            vec2 corner = vec2(fp.origin + ivec2(mx + 1, my + 1)) * texelUv;
            pcfFetch(map, PCF_FETCH_GATHER, corner, 1.0f);
            // A comparison gather has one ref for its four texels: under receiver-plane bias
            // the plane's depth at the gather's centre (its block's shared corner). The soft
            // comparison needs the depths themselves: a gather of raw depth ("PCF Shadow Acne 2").
            vec2 unitUv = pcfUnitUv(map, corner);
            vec4 bits = ref.bias.mode == PCF_BIAS_SOFT
                            ? pcfGatherSoft(map, unitUv, ref, w)
                            : gatherCompare(map, unitUv, pcfRefAt(ref, corner), w);
            // Row by row, the 1 / N^2 once at the end: six operations a block, not twelve.
            sum += wy0 * (wx0 * bits.w + wx1 * bits.z) + wy1 * (wx0 * bits.x + wx1 * bits.y);
        }
    }
    return sum * norm;
}

// ---- Weighted kernels (issue 10) --------------------------------------------------------
//
// "PCF Shadow Acne" (blog post) suggests weighting the N x N lookups with a binomial or a
// Gaussian kernel instead of the box. The weights are separable: lookup (i, j) weighs
// a_i * a_j, with per-axis weights a_k (k = 0..N-1, offset x_k = k - (N-1)/2) summing to 1:
//   box:      a_k = 1/N
//   binomial: a_k = C(N-1, k) / 2^(N-1)       (Pascal's row: N = 3 gives 1/4, 1/2, 1/4)
//   gaussian: a_k = exp(-x_k^2 / (2 sigma^2)) / sum_k exp(...)     sigma in texels, > 0
PCF_CONST int PCF_WEIGHTS_BOX = 0;
PCF_CONST int PCF_WEIGHTS_BINOMIAL = 1;
PCF_CONST int PCF_WEIGHTS_GAUSSIAN = 2;

PCF_FN float pcfAxisWeightRaw(int k, int n, int weights, float sigma) {
    if (weights == PCF_WEIGHTS_BINOMIAL) {
        float c = 1.0f;  // C(n-1, k), built up as a product: exact for n <= 8
        for (int t = 0; t < k; ++t) c = c * float(n - 1 - t) / float(t + 1);
        return c;
    }
    if (weights == PCF_WEIGHTS_GAUSSIAN) {
        float x = pcfKernelOffset(k, n);
        return exp(-x * x / (2.0f * sigma * sigma));
    }
    return 1.0f;
}

// a_k, normalised so that the N weights sum to 1.
PCF_FN float pcfAxisWeight(int k, int n, int weights, float sigma) {
    float total = 0.0f;
    for (int t = 0; t < n; ++t) total += pcfAxisWeightRaw(t, n, weights, sigma);
    return pcfAxisWeightRaw(k, n, weights, sigma) / total;
}

// pcf-naive with weights: the same N x N bilinear lookups (4 N^2 reads), lookup (i, j)
// weighted a_i * a_j.
PCF_MAP_FN float pcfNaiveWeighted(Map map, vec2 uv, PcfRef ref, int n, int weights, float sigma) {
    ivec2 size = mapSize(map);
    vec2 p = pcfTexelPos(uv, size).p;
    vec2 texelUv = vec2(1.0f) / vec2(size);
    float sum = 0.0f;
    for (int j = 0; j < n; ++j) {
        float aj = pcfAxisWeight(j, n, weights, sigma);
        for (int i = 0; i < n; ++i) {
            float w = pcfAxisWeight(i, n, weights, sigma) * aj;
            vec2 offset = vec2(pcfKernelOffset(i, n), pcfKernelOffset(j, n));
            PCF_PRECISE vec2 pk = p + offset;
            pcfFetch(map, PCF_FETCH_LOOKUP, uv + offset * texelUv, w);
            sum += w * pcfBilinearAt(map, pk, ref, w);
        }
    }
    return sum;
}

// The footprint table for any separable weights: footprint texel m (0..N) is the 2x2's right
// texel of lookup m-1 and the left texel of lookup m, so per axis it weighs
//   W_m = a_m (1 - g) [m < N] + a_(m-1) g [m > 0]
// (box: (1-g, 1, ..., 1, g) / N, "PCF Shadow Acne 2"'s table for N = 3).
PCF_FN float pcfFootprintWeightW(int m, int n, float g, int weights, float sigma) {
    float w = 0.0f;
    if (m < n) w += pcfAxisWeight(m, n, weights, sigma) * (1.0f - g);
    if (m > 0) w += pcfAxisWeight(m - 1, n, weights, sigma) * g;
    return w;
}

// pcf-gather with weights: the same ceil((N+1)/2)^2 gathers at the blocks' shared corners,
// weighted by pcfFootprintWeightW. Equals pcfNaiveWeighted to float rounding.
PCF_MAP_FN float pcfGatherWeighted(Map map, vec2 uv, PcfRef ref, int n, int weights, float sigma) {
    ivec2 size = mapSize(map);
    PcfFootprint fp = pcfKernelFootprint(uv, size, n);
    int blocks = (n + 2) / 2;
    float sum = 0.0f;
    for (int by = 0; by < blocks; ++by) {
        for (int bx = 0; bx < blocks; ++bx) {
            int mx = 2 * bx;
            int my = 2 * by;
            float wx0 = pcfFootprintWeightW(mx, n, fp.frac.x, weights, sigma);
            float wx1 =
                mx + 1 <= n ? pcfFootprintWeightW(mx + 1, n, fp.frac.x, weights, sigma) : 0.0f;
            float wy0 = pcfFootprintWeightW(my, n, fp.frac.y, weights, sigma);
            float wy1 =
                my + 1 <= n ? pcfFootprintWeightW(my + 1, n, fp.frac.y, weights, sigma) : 0.0f;
            // GL's gather order: x = (0,1), y = (1,1), z = (1,0), w = (0,0).
            vec4 w = vec4(wx0 * wy1, wx1 * wy1, wx1 * wy0, wx0 * wy0);
            vec2 corner = vec2(fp.origin + ivec2(mx + 1, my + 1)) / vec2(size);
            pcfFetch(map, PCF_FETCH_GATHER, corner, 1.0f);
            // A comparison gather has one ref for its four texels: under receiver-plane bias
            // the plane's depth at the gather's centre (its block's shared corner). The soft
            // comparison needs the depths themselves: a gather of raw depth ("PCF Shadow Acne 2").
            vec2 unitUv = pcfUnitUv(map, corner);
            vec4 bits = ref.bias.mode == PCF_BIAS_SOFT
                            ? pcfGatherSoft(map, unitUv, ref, w)
                            : gatherCompare(map, unitUv, pcfRefAt(ref, corner), w);
            sum += dot(bits, w);
        }
    }
    return sum;
}

// Castano's tent filters (2013; also MJP's Shadows sample): an N x N tent (N = 3, 5, 7) from
// 4, 9 or 16 hardware taps, each placed between two texels so that the texture unit's lerp
// produces the right ratio of their weights. Per axis, with q = uv * size, b = floor(q + 0.5),
// s = q + 0.5 - b in [0,1):
//   3: w = 3-2s, 1+2s                        o = (2-s)/w0 - 1, s/w1 + 1               D = 16
//   5: w = 4-3s, 7, 1+3s                     o = (3-2s)/w0 - 2, (3+s)/w1, s/w2 + 2    D = 144
//   7: w = 5s-6, 11s-28, -(11s+17), -(5s+1)  o = (4s-5)/w0 - 3, (4s-16)/w1 - 1,
//                                                -(7s+5)/w2 + 1, -s/w3 + 3            D = 2704
// tap (i, j) samples uv' = (b - 0.5 + (o_i, o_j)) / size with weight w_i w_j / D.
struct PcfTentAxis {
    vec4 w;  // tap weights (unused ones 0); the 7x7 weights are all negative, D positive
    vec4 o;  // tap offsets in texels from b - 0.5
    int taps;
};

PCF_FN PcfTentAxis pcfTentAxis(float s, int n) {
    if (n <= 3) {
        vec4 w = vec4(3.0f - 2.0f * s, 1.0f + 2.0f * s, 0.0f, 0.0f);
        vec4 o = vec4((2.0f - s) / w.x - 1.0f, s / w.y + 1.0f, 0.0f, 0.0f);
        return PcfTentAxis(w, o, 2);
    }
    if (n <= 5) {
        vec4 w = vec4(4.0f - 3.0f * s, 7.0f, 1.0f + 3.0f * s, 0.0f);
        vec4 o = vec4((3.0f - 2.0f * s) / w.x - 2.0f, (3.0f + s) / w.y, s / w.z + 2.0f, 0.0f);
        return PcfTentAxis(w, o, 3);
    }
    vec4 w = vec4(5.0f * s - 6.0f, 11.0f * s - 28.0f, -(11.0f * s + 17.0f), -(5.0f * s + 1.0f));
    vec4 o = vec4((4.0f * s - 5.0f) / w.x - 3.0f, (4.0f * s - 16.0f) / w.y - 1.0f,
                  -(7.0f * s + 5.0f) / w.z + 1.0f, -s / w.w + 3.0f);
    return PcfTentAxis(w, o, 4);
}

PCF_FN float pcfTentNorm(int n) {
    if (n <= 3) return 16.0f;
    if (n <= 5) return 144.0f;
    return 2704.0f;
}

// The tent's own texel position: b = floor(q + 0.5), s = q + 0.5 - b.
PCF_FN PcfFootprint pcfTentBase(vec2 uv, ivec2 size) {
    PCF_PRECISE vec2 q = uv * vec2(size) + vec2(0.5f);
    vec2 b = floor(q);
    return PcfFootprint(ivec2(b), q - b);
}

PCF_MAP_FN float pcfTent(Map map, vec2 uv, PcfRef ref, int n) {
    ivec2 size = mapSize(map);
    PcfFootprint tb = pcfTentBase(uv, size);
    PcfTentAxis ax = pcfTentAxis(tb.frac.x, n);
    PcfTentAxis ay = pcfTentAxis(tb.frac.y, n);
    vec2 texelUv = vec2(1.0f) / vec2(size);
    vec2 baseUv = (vec2(tb.origin) - vec2(0.5f)) * texelUv;
    float norm = 1.0f / pcfTentNorm(n);
    float sum = 0.0f;
    for (int j = 0; j < ax.taps; ++j) {
        for (int i = 0; i < ax.taps; ++i) {
            float w = ax.w[i] * ay.w[j] * norm;
            vec2 tapUv = baseUv + vec2(ax.o[i], ay.o[j]) * texelUv;
            sum += w * pcfHwTap(map, tapUv, ref, w);
        }
    }
    return sum;
}
