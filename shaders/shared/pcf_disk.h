// pcf_disk.h: the methods whose points lie on the 16-point Poisson disk, poisson and pcss, in the
// subset of C++ and GLSL that pcf_kernel.h is written in (pcf_prelude.h has the rules). It comes
// after pcf_kernel.h (ids, PcfParams, PcfRef, the nearest-texel comparison it places its points
// with) and before pcf_moments.h and pcf_filter.h, whose dispatch calls pcfPoisson and pcfPcss.
// The same files in the same order in both languages: src/kernel/pcf_shared.h (C++) and
// render/pcf_programs.cpp pcfSharedFiles (GLSL).

// The 16-point Poisson disk of Jimmy 2010, scaled by the radius in texels. Not a unit disk: 8 of
// its 16 points lie outside the unit circle, the farthest (the 8th) at 1.234.
// The array macros stand for C++'s and GLSL's array syntax, which clang-format cannot read.
// clang-format off
PCF_CONST_ARRAY(vec2, PCF_POISSON_DISK, 16) PCF_ARRAY_BEGIN(vec2, 16)
    vec2(-0.94201624f, -0.39906216f), vec2(0.94558609f, -0.76890725f),
    vec2(-0.094184101f, -0.92938870f), vec2(0.34495938f, 0.29387760f),
    vec2(-0.91588581f, 0.45771432f), vec2(-0.81544232f, -0.87912464f),
    vec2(-0.38277543f, 0.27676845f), vec2(0.97484398f, 0.75648379f),
    vec2(0.44323325f, -0.97511554f), vec2(0.53742981f, -0.47373420f),
    vec2(-0.26496911f, -0.41893023f), vec2(0.79197514f, 0.19090188f),
    vec2(-0.24188840f, 0.99706507f), vec2(-0.81409955f, 0.91437590f),
    vec2(0.19984126f, 0.78641367f), vec2(0.14383161f, -0.14100790f)
PCF_ARRAY_END;
// clang-format on

// Per-pixel rotations of the disk: (cos, sin) of k * 22.5 degrees, k = 0..15. A table of
// literals, not cos() and sin(), so that the CPU and the GPU rotate by the very same floats.
// clang-format off
PCF_CONST_ARRAY(vec2, PCF_ROTATIONS, 16) PCF_ARRAY_BEGIN(vec2, 16)
    vec2(1.0f, 0.0f), vec2(0.92387953f, 0.38268343f),
    vec2(0.70710678f, 0.70710678f), vec2(0.38268343f, 0.92387953f),
    vec2(0.0f, 1.0f), vec2(-0.38268343f, 0.92387953f),
    vec2(-0.70710678f, 0.70710678f), vec2(-0.92387953f, 0.38268343f),
    vec2(-1.0f, 0.0f), vec2(-0.92387953f, -0.38268343f),
    vec2(-0.70710678f, -0.70710678f), vec2(-0.38268343f, -0.92387953f),
    vec2(0.0f, -1.0f), vec2(0.38268343f, -0.92387953f),
    vec2(0.70710678f, -0.70710678f), vec2(0.92387953f, -0.38268343f)
PCF_ARRAY_END;
// clang-format on

// Jimmy 2010: 16 point-sampled comparisons at the Poisson points scaled by the given radius in
// texels (the farthest 1.234 radius from uv), optionally rotated per pixel (rotation = (cos, sin)).
// The points are placed in texel space: point k reads the texel floor(uv * size + offset_k),
// one add per point from the lookup's own texel position (an offset taken to uv and back
// would cost two multiplies and an add more, on every point, for the same place).
PCF_FN vec2 pcfPoissonOffset(int k, float radius, vec2 rotation) {
    vec2 d = PCF_POISSON_DISK[k];
    PCF_PRECISE float x = d.x * rotation.x - d.y * rotation.y;
    PCF_PRECISE float y = d.x * rotation.y + d.y * rotation.x;
    return vec2(x, y) * radius;
}

PCF_MAP_FN float pcfPoisson(Map map, vec2 uv, PcfRef ref, float radius, vec2 rotation) {
    vec2 size = vec2(mapSize(map));
    vec2 texelUv = vec2(1.0f) / size;
    PCF_PRECISE vec2 centre = uv * size;
    float sum = 0.0f;
    for (int k = 0; k < 16; ++k) {
        PCF_PRECISE vec2 p = centre + pcfPoissonOffset(k, radius, rotation);
        sum += pcfNearestAt(map, p, p * texelUv, ref, 1.0f / 16.0f);
    }
    return sum * (1.0f / 16.0f);
}

// A rotation for the Poisson disk from an integer hash of a cell (a pixel, a texel): the same
// on every driver because it is integer math and a table lookup.
PCF_FN vec2 pcfPixelRotation(ivec2 pixel) {
    uint h = uint(pixel.x) * 73856093u ^ uint(pixel.y) * 19349663u;
    h = (h ^ (h >> 13u)) * 1274126177u;
    return PCF_ROTATIONS[int((h >> 16u) & 15u)];
}

// The disk's rotation for a lookup: the hash of the map texel it falls in, floor(uv * size).
// It belongs to the lookup, not to the screen: a scene point keeps its rotation at every frame
// size and while the camera moves (hashed from the screen pixel, lesson 7's disk turned by -45
// degrees on a 617 x 347 slide and by -157.5 in the 960 x 540 handout).
PCF_FN vec2 pcfTexelRotation(vec2 uv, ivec2 size) {
    PCF_PRECISE vec2 p = uv * vec2(size);
    return pcfPixelRotation(ivec2(floor(p)));
}

// ---- Percentage-closer soft shadows (issue 21) -------------------------------------------
//
// Fernando, "Percentage-Closer Soft Shadows" (NVIDIA, SIGGRAPH 2005 sketch), three steps:
//   1. blocker search: the depths in a region around uv nearer the light than the receiver are
//      blockers; d_blocker = their mean depth;
//   2. penumbra width by similar triangles: w = (d_receiver - d_blocker) * w_light / d_blocker;
//   3. PCF with a kernel of width w.
// A directional light (an orthographic map, depth linear in distance, the light at infinity):
// its disk of angular diameter theta gives the penumbra w = (d_receiver - d_blocker) *
// 2 tan(theta / 2) in world units: the seed's w_light / d_blocker is the angle the light
// subtends. In the map's units (texels, light depth [0,1]):
//   w = (ref - d_blocker) * S        S = penumbraScale, texels per unit of light depth
// The search region: a blocker at depth d can hide part of the light only within
// (ref - d) * S / 2 texels of uv, and d >= 0 (the map's near plane), so its radius is
//   r_search = ref * S / 2
// (the seed's w_light * (d_receiver - near) / d_receiver with the light at infinity).
// A spot light of width w_light (its disk's diameter) at the light's position, a perspective
// map with near n > 0 and far f (prm.depthNear, depthFar): the seed's formulas hold as they
// stand with d the linear distance along the light's axis (pcfPcssLinearDepth of the stored
// depth, each blocker's before the mean). A world width x at distance d covers x * P00 *
// mapSize / (2 d) texels (P00 the projection's x scale), so with S = w_light * P00 * mapSize / 2
// (texels times scene units, scene/pcss.h):
//   w = S * (d_receiver - d_blocker) / (d_blocker * d_receiver)
//   r_search = S * (d_receiver - n) / (d_receiver * n) / 2   (the seed's region, on the near plane)
// Taps: both steps use the 16-point Poisson disk of Jimmy 2010 (the disk of `poisson`; the
// seed's filter is a Poisson-disk PCF too), nearest-texel reads, turned by prm.rotation. The
// filter's radius is w / 2. Both radii are kept in [PCF_PCSS_MIN_RADIUS, PCF_PCSS_MAX_RADIUS]:
// with a light of size 0 pcss is exactly poisson with radius 1.
PCF_CONST float PCF_PCSS_MIN_RADIUS = 1.0f;   // texels: the poisson default (Jimmy 2010)
PCF_CONST float PCF_PCSS_MAX_RADIUS = 32.0f;  // texels: 16 taps spread wider say nothing
PCF_CONST int PCF_PCSS_TAPS = 16;

// 1 / k for k = 0..16 as literals (entry 0 unused): the mean blocker depth is sum * (1 / count)
// with the same float on the CPU and the GPU (a GLSL division may be a reciprocal estimate).
// GLSL reads the table through PCF_PCSS_RECIPROCAL(k): a uniform array set from this C++ copy
// (pcf_prelude.h says why).
// clang-format off
PCF_CONST_ARRAY(float, PCF_PCSS_RECIPROCALS, 17) PCF_ARRAY_BEGIN(float, 17)
    0.0f, 1.0f, 0.5f, 0.333333343f, 0.25f, 0.200000003f, 0.166666672f, 0.142857149f, 0.125f,
    0.111111112f, 0.100000001f, 0.0909090936f, 0.0833333358f, 0.0769230798f, 0.0714285746f,
    0.0666666701f, 0.0625f
PCF_ARRAY_END;
// clang-format on

// What steps 1 and 2 found for one lookup (the trace shows each number).
struct PcfPcssEstimate {
    float searchRadius;  // texels: clamp(r_search, MIN, MAX); r_search = ref * S / 2 (directional)
    int blockers;        // search taps with depth < their ref, 0..16
    float blockerDepth;  // their mean depth, light depth [0,1] (a spot's: distance); 0: none
    float penumbra;      // texels: the full width w (directional: (ref - blockerDepth) * S); 0
                         // without blockers
    float filterRadius;  // texels: clamp(penumbra / 2, MIN, MAX)
};

PCF_FN float pcfPcssRadius(float r) { return clamp(r, PCF_PCSS_MIN_RADIUS, PCF_PCSS_MAX_RADIUS); }

// The distance along the light's axis of a perspective map's depth z, near n, far f: the
// inverse of glm::perspectiveRH_NO's depth (OpenGL's, z = 0.5 * ndc.z + 0.5), Akenine-Moller,
// Haines, Hoffman, "Real-Time Rendering" (4th ed., 2018), perspective projection:
//   d = n * f / (f - z * (f - n))
// z is clamped to [0,1] first (a biased ref may leave it).
PCF_FN float pcfPcssLinearDepth(float z, float n, float f) {
    PCF_PRECISE float zc = clamp(z, 0.0f, 1.0f);
    PCF_PRECISE float d = (n * f) / (f - zc * (f - n));
    return d;
}

// Steps 1 and 2. Each search tap is recorded with weight 0 (it decides the width, not the
// visibility); a blocker is a texel nearer than the tap's ref (the hard comparison, also under
// soft bias: the soft ramp is about the receiver's own acne, not about who blocks).
PCF_MAP_FN PcfPcssEstimate pcfPcssEstimate(Map map, vec2 uv, PcfRef ref, float penumbraScale,
                                           float depthNear, float depthFar, vec2 rotation) {
    ivec2 size = mapSize(map);
    vec2 texelUv = vec2(1.0f) / vec2(size);
    float zr = pcfDepthRef(map, ref.ref);
    bool perspective = depthNear > 0.0f;
    PCF_PRECISE float dr = perspective ? pcfPcssLinearDepth(zr, depthNear, depthFar) : zr;
    PCF_PRECISE float searchHalf = perspective
                                       ? penumbraScale * 0.5f * (dr - depthNear) / (dr * depthNear)
                                       : zr * penumbraScale * 0.5f;
    float search = pcfPcssRadius(searchHalf);
    int blockers = 0;
    PCF_PRECISE float depthSum = 0.0f;
    // The search's points in texel space, as poisson's (pcfPoisson).
    PCF_PRECISE vec2 centre = uv * vec2(size);
    for (int k = 0; k < PCF_PCSS_TAPS; ++k) {
        PCF_PRECISE vec2 p = centre + pcfPoissonOffset(k, search, rotation);
        ivec2 texel = ivec2(floor(p));
        pcfFetch(map, PCF_FETCH_POINT, p * texelUv, 0.0f);
        pcfTapWanted(map, texel);
        ivec2 t = pcfClampTexel(texel, size);
        // pointDepth, not fetchDepth(t): in GLSL the sampler clamps, in float (as pcfNearest).
        float depth = pointDepth(map, p);
        float tapRef = ref.ref;
        if (ref.bias.mode == PCF_BIAS_RECEIVER_PLANE) {
            tapRef = pcfRefAt(ref, pcfTexelCentreUv(texel, size));
        }
        float r = pcfDepthRef(map, tapRef);
        float lit = pcfCompare(depth, r);
        pcfTap(map, t, depth, r, lit, 0.0f);
        if (lit == 0.0f) {
            blockers += 1;
            depthSum += perspective ? pcfPcssLinearDepth(depth, depthNear, depthFar) : depth;
        }
    }
    PCF_PRECISE float blockerDepth = depthSum * PCF_PCSS_RECIPROCAL(blockers);
    PCF_PRECISE float penumbra = 0.0f;
    if (blockers > 0) {
        penumbra = perspective ? penumbraScale * (dr - blockerDepth) / (blockerDepth * dr)
                               : (zr - blockerDepth) * penumbraScale;
    }
    PCF_PRECISE float halfWidth = penumbra * 0.5f;
    return PcfPcssEstimate(search, blockers, blockerDepth, penumbra, pcfPcssRadius(halfWidth));
}

// pcss: no blocker in the region means fully lit (the seed's early out); otherwise step 3,
// poisson's 16 comparisons on a disk of the estimated radius.
PCF_MAP_FN float pcfPcss(Map map, vec2 uv, PcfRef ref, PcfParams prm) {
    PcfPcssEstimate e =
        pcfPcssEstimate(map, uv, ref, prm.penumbraScale, prm.depthNear, prm.depthFar, prm.rotation);
    if (e.blockers == 0) return 1.0f;
    return pcfPoisson(map, uv, ref, e.filterRadius, prm.rotation);
}
