// pcf_moments.h: the moment methods (vsm, evsm2, evsm4, msm, msm-hausdorff), in the subset of
// C++ and GLSL that pcf_kernel.h is written in (pcf_prelude.h has the rules). It comes after
// pcf_kernel.h (ids, PcfParams, the bilinear weights and the axis weights it uses) and
// pcf_disk.h, and before pcf_filter.h, whose dispatch calls pcfMomentEstimate. The same files in
// the same order in both languages: src/kernel/pcf_shared.h (C++) and render/pcf_programs.cpp
// pcfSharedFiles (GLSL).
// Each formula names its paper above it: Donnelly and Lauritzen, "Variance Shadow Maps", 2006;
// Lauritzen and McCool, "Layered Variance Shadow Maps", 2008; Peters and Klein, "Moment Shadow
// Mapping", 2015.

// ---- Filterable maps: variance and moment shadow maps (issue 33) -------------------------
//
// A filterable map stores, per texel, moments of the depths under it instead of one depth:
// averages of z, z^2 (and z^3, z^4, or exponentials of z). Averages can be filtered before the
// lookup (the moments pass: an N x N box, binomial or Gaussian blur of each texel's moments,
// pcfMomentsTexel), and one bilinear read at the lookup (pcfMomentsRead) gives the moments of
// the whole footprint. What no average can say is how the depths are spread: each method
// bounds or reconstructs the fraction of the footprint nearer than the receiver from those few
// numbers (pcfMomentEstimate). The map these methods read is a moments map (kernel/shadow_map.h
// TexelKind::Moments*), read through fetchMoments(map, texel): channels the texture lacks read
// as GL's (0, 0, 0, 1).

// EVSM's warps (Lauritzen and McCool, "Layered Variance Shadow Maps", 2008, section on the
// exponential warp): with the depth moved to [-1, 1], x = 2z - 1,
//   positive warp  w+ = exp(c+ x),     negative warp  w- = -exp(-c- x)
// both increasing in z, so a receiver beyond the occluders is beyond them after the warp too.
PCF_FN float pcfEvsmPositive(float z, float c) { return exp(c * (2.0f * z - 1.0f)); }
PCF_FN float pcfEvsmNegative(float z, float c) { return -exp(-c * (2.0f * z - 1.0f)); }

// What one depth adds to a texel's moments, per method:
//   vsm (Donnelly and Lauritzen, "Variance Shadow Maps", 2006): (z, z^2)
//   evsm2: (w+, w+^2);  evsm4: (w+, w+^2, w-, w-^2)   (Lauritzen and McCool 2008)
//   msm, msm-hausdorff (Peters and Klein, "Moment Shadow Mapping", 2015): (z, z^2, z^3, z^4)
PCF_FN vec4 pcfDepthMoments(int method, float z, vec2 exponents) {
    if (method == PCF_EVSM2 || method == PCF_EVSM4) {
        float p = pcfEvsmPositive(z, exponents.x);
        float n = method == PCF_EVSM4 ? pcfEvsmNegative(z, exponents.y) : 0.0f;
        return vec4(p, p * p, n, n * n);
    }
    float z2 = z * z;
    if (method == PCF_VSM) return vec4(z, z2, 0.0f, 0.0f);
    return vec4(z, z2, z2 * z, z2 * z2);
}

// The moments pass: texel t of the moments map is the weighted mean of the moments of the N x N
// depths around it (N odd: offsets -(N-1)/2 .. (N-1)/2 texels, clamped to the edge), weighted
// a_i * a_j as the weighted kernels are (box, binomial, Gaussian: pcfAxisWeight). The blur and
// the lookup's bilinear read together weigh the (N+1) x (N+1) depths around a lookup exactly as
// pcf-naive's N x N lookups weigh their comparisons.
PCF_MAP_FN vec4 pcfMomentsTexel(Map depthMap, ivec2 t, PcfParams prm) {
    ivec2 size = mapSize(depthMap);
    int n = prm.kernel;
    int reach = (n - 1) / 2;
    vec4 sum = vec4(0.0f);
    for (int j = 0; j < n; ++j) {
        float aj = pcfAxisWeight(j, n, prm.weights, prm.sigma);
        for (int i = 0; i < n; ++i) {
            float w = pcfAxisWeight(i, n, prm.weights, prm.sigma) * aj;
            ivec2 at = pcfClampTexel(t + ivec2(i - reach, j - reach), size);
            sum += w * pcfDepthMoments(prm.method, fetchDepth(depthMap, at), prm.evsmExponents);
        }
    }
    return sum;
}

// The one bilinear read of the filtered moments at uv (GL's convention, the texels clamped to
// the edge), done as four texel reads so that the CPU and the GPU weigh them alike.
PCF_MAP_FN vec4 pcfMomentsRead(Map map, vec2 uv) {
    ivec2 size = mapSize(map);
    PcfTexelPos tp = pcfTexelPos(uv, size);
    vec4 w = pcfBilinearWeights(tp.frac);
    vec4 m00 = fetchMoments(map, pcfClampTexel(tp.base, size));
    vec4 m10 = fetchMoments(map, pcfClampTexel(tp.base + ivec2(1, 0), size));
    vec4 m01 = fetchMoments(map, pcfClampTexel(tp.base + ivec2(0, 1), size));
    vec4 m11 = fetchMoments(map, pcfClampTexel(tp.base + ivec2(1, 1), size));
    return w.x * m00 + w.y * m10 + w.z * m01 + w.w * m11;
}

// a / b with b kept at least 1e-30 from 0 (its sign kept): degenerate moments (a flat
// footprint, no bias) give a large finite number, never Inf or NaN.
PCF_FN float pcfSafeDivide(float a, float b) {
    float m = max(abs(b), 1.0e-30f);
    return a / (b < 0.0f ? -m : m);
}

// Chebyshev's one-tailed inequality (Donnelly and Lauritzen, "Variance Shadow Maps", 2006):
// with mean mu = E[x] and variance s^2 = E[x^2] - mu^2 (held at least minVariance), the
// fraction of the footprint at or beyond the receiver's t is at most
//   p_max(t) = s^2 / (s^2 + (t - mu)^2)    for t > mu,   1 for t <= mu
// and VSM takes p_max as the visibility: exact for one flat occluder over a flat receiver.
PCF_FN float pcfChebyshev(float mean, float variance, float t) {
    if (t <= mean) return 1.0f;
    float d = t - mean;
    return pcfSafeDivide(variance, variance + d * d);
}

// Light-bleeding reduction (Lauritzen, "Summed-Area Variance Shadow Maps", GPU Gems 3, 2007;
// used again in Lauritzen and McCool 2008): the bound's low values are cut to 0 and the rest
// stretched back to [0, 1], linstep(amount, 1, p) = clamp((p - amount) / (1 - amount), 0, 1).
PCF_FN float pcfLightBleedReduce(float p, float amount) {
    return clamp((p - amount) / max(1.0f - amount, 1.0e-6f), 0.0f, 1.0f);
}

// What the moments at a lookup say, for the visibility and for the trace.
struct PcfMomentEstimate {
    vec4 moments;    // the bilinear read of the filtered moments (msm: after the moment bias)
    float mean;      // vsm, evsm: E[x] of the (positive-warped) depth; msm: E[z]
    float variance;  // E[x^2] - E[x]^2, before the floor
    float receiver;  // the receiver's t in the same warp (vsm, msm: ref itself)
    float bound;     // vsm, evsm: the Chebyshev bound of the positive warp (before LBR)
    float negBound;  // evsm4: the negative warp's bound; 1 for the others
    vec4 points;     // msm: the reconstructed depths (z_f, z2, z3, hausdorff's fourth)
    vec4 weights;    // msm: their weights (sum 1); 0 for the others
    float visibility;
};

// The variance floor of a warped depth: minVariance is in light depth squared; a warp w(z)
// stretches a small spread s of depth into |dw/dz| s, so the floor is minVariance (dw/dz)^2 at
// the receiver (first-order propagation of the spread; dw/dz = 2 c w for both warps).
PCF_FN float pcfWarpedFloor(float minVariance, float c, float w) {
    float s = sqrt(minVariance) * 2.0f * c * abs(w);
    return s * s;
}

// vsm, evsm2 and evsm4: the Chebyshev bound on each warp, the smaller taken (evsm4), then the
// light-bleeding reduction.
PCF_FN PcfMomentEstimate pcfVarianceEstimate(vec4 m, float t, PcfParams prm) {
    bool warped = prm.method != PCF_VSM;
    float c = prm.evsmExponents.x;
    float tp = warped ? pcfEvsmPositive(t, c) : t;
    float floorP = warped ? pcfWarpedFloor(prm.minVariance, c, tp) : prm.minVariance;
    float variance = m.y - m.x * m.x;
    float bound = pcfChebyshev(m.x, max(variance, floorP), tp);
    float negBound = 1.0f;
    if (prm.method == PCF_EVSM4) {
        float cn = prm.evsmExponents.y;
        float tn = pcfEvsmNegative(t, cn);
        float floorN = pcfWarpedFloor(prm.minVariance, cn, tn);
        negBound = pcfChebyshev(m.z, max(m.w - m.z * m.z, floorN), tn);
    }
    float v = pcfLightBleedReduce(min(bound, negBound), prm.lbr);
    return PcfMomentEstimate(m, m.x, variance, tp, bound, negBound, vec4(0.0f), vec4(0.0f), v);
}

// The weight a distribution on three depths (a, b, c) with mean b1 and second moment b2 puts on
// a (the Vandermonde system's solution): (b2 - b1 (b + c) + b c) / ((a - b) (a - c)).
PCF_FN float pcfThreePointWeight(float a, float b, float c, float b1, float b2) {
    return pcfSafeDivide(b2 - b1 * (b + c) + b * c, (a - b) * (a - c));
}

// Hamburger 4MSM (Peters and Klein, "Moment Shadow Mapping", 2015, the algorithm for four
// moments): bias the moments towards (0.5, 0.5, 0.5, 0.5), b' = (1 - alpha) b + alpha 0.5, then
// find the depths z2 <= z3 such that a distribution on {z_f, z2, z3} (z_f the receiver) has the
// moments b'. With the Hankel matrix B = [1 b1 b2; b1 b2 b3; b2 b3 b4] = L D L^T (Cholesky, D
// diagonal), solve B c = (1, z_f, z_f^2); z2, z3 are the roots of c0 + c1 z + c2 z^2. The shadow
// is the least weight such a distribution can put before z_f: the weights of the points below
// z_f (pcfThreePointWeight), the receiver's own point counted as lit.
PCF_FN PcfMomentEstimate pcfHamburgerEstimate(vec4 b, float zf) {
    float d22 = b.y - b.x * b.x;
    float l32 = pcfSafeDivide(b.z - b.x * b.y, d22);
    float d33 = b.w - b.y * b.y - l32 * l32 * d22;
    float y1 = zf - b.x;
    float y2 = zf * zf - b.y - l32 * y1;
    float c2 = pcfSafeDivide(y2, d33);
    float c1 = pcfSafeDivide(y1, d22) - l32 * c2;
    float c0 = 1.0f - b.x * c1 - b.y * c2;
    float p = pcfSafeDivide(c1, c2);
    float q = pcfSafeDivide(c0, c2);
    float r = sqrt(max(0.25f * p * p - q, 0.0f));
    float z2 = -0.5f * p - r;
    float z3 = -0.5f * p + r;
    float wf = pcfThreePointWeight(zf, z2, z3, b.x, b.y);
    float w2 = pcfThreePointWeight(z2, zf, z3, b.x, b.y);
    float w3 = pcfThreePointWeight(z3, zf, z2, b.x, b.y);
    float shadow = (z2 < zf ? w2 : 0.0f) + (z3 < zf ? w3 : 0.0f);
    float v = 1.0f - clamp(shadow, 0.0f, 1.0f);
    return PcfMomentEstimate(b, b.x, d22, zf, 1.0f, 1.0f, vec4(zf, z2, z3, 0.0f),
                             vec4(wf, w2, w3, 0.0f), v);
}

// Hausdorff 4MSM (Peters and Klein 2015): depths live in [0, 1]. When Hamburger's z2 or z3
// falls outside, the bound comes from a distribution on {0, z_f, z_free, 1} instead, whose
// free depth makes it match all four moments. With u_k = b_{k+1} - b_k (k = 1, 2, 3; b_0 = 1)
// the two inner points' terms follow u_{k+2} = (z_f + z_free) u_{k+1} - z_f z_free u_k, so
//   z_free = (u_3 - z_f u_2) / (u_2 - z_f u_1)
// and the weights of z_f and z_free solve u_1, u_2; the weight at 1 is b1 minus theirs, the
// rest is at 0. The shadow is the weight at 0, and at z_free when it lies before z_f.
PCF_FN PcfMomentEstimate pcfHausdorffEstimate(vec4 b, float zf) {
    PcfMomentEstimate e = pcfHamburgerEstimate(b, zf);
    if (e.points.y >= 0.0f && e.points.z <= 1.0f) return e;
    float u1 = b.y - b.x;
    float u2 = b.z - b.y;
    float u3 = b.w - b.z;
    float zfree = pcfSafeDivide(u3 - zf * u2, u2 - zf * u1);
    float wf = pcfSafeDivide(u2 - zfree * u1, zf * (zf - 1.0f) * (zf - zfree));
    float wfree = pcfSafeDivide(u2 - zf * u1, zfree * (zfree - 1.0f) * (zfree - zf));
    float w1 = b.x - wf * zf - wfree * zfree;
    float w0 = 1.0f - wf - wfree - w1;
    float shadow = w0 + (zfree < zf ? wfree : 0.0f);
    if (isnan(shadow)) return e;  // no four-point answer: Hamburger's stands
    e.points = vec4(zf, zfree, 0.0f, 1.0f);
    e.weights = vec4(wf, wfree, w0, w1);
    e.visibility = 1.0f - clamp(shadow, 0.0f, 1.0f);
    return e;
}

// The trace's record of the bilinear read: each of its four texels (its first moment as the
// tap's depth) with its bilinear weight and the lookup's visibility (nothing in GLSL).
PCF_MAP_FN void pcfMomentTaps(Map map, vec2 uv, float ref, float visibility) {
    ivec2 size = mapSize(map);
    PcfTexelPos tp = pcfTexelPos(uv, size);
    vec4 w = pcfBilinearWeights(tp.frac);
    for (int k = 0; k < 4; ++k) {
        ivec2 wanted = tp.base + ivec2(k % 2, k / 2);
        ivec2 t = pcfClampTexel(wanted, size);
        pcfTapWanted(map, wanted);
        pcfTap(map, t, fetchMoments(map, t).x, ref, visibility, w[k]);
    }
}

// Every moment method at one lookup: the bilinear read, then its bound or reconstruction. The
// four texels read are recorded with their bilinear weights, each carrying the one visibility
// (as the interpolated comparison records its one bit), so visibility = sum(weight * lit).
// The receiver is taken at clamp(ref, 0, 1), where the moments' depths are: a warp of a ref far
// outside would overflow. Moments no arithmetic can resolve (a NaN, from a map that holds no
// spread: not a moments pass's) count as lit.
PCF_MAP_FN PcfMomentEstimate pcfMomentEstimate(Map map, vec2 uv, float lookupRef, PcfParams prm) {
    pcfFetch(map, PCF_FETCH_LOOKUP, uv, 1.0f);
    vec4 m = pcfMomentsRead(map, uv);
    float ref = clamp(lookupRef, 0.0f, 1.0f);
    PcfMomentEstimate e;
    if (prm.method == PCF_MSM || prm.method == PCF_MSM_HAUSDORFF) {
        vec4 b = mix(m, vec4(0.5f), prm.momentBias);
        e = prm.method == PCF_MSM ? pcfHamburgerEstimate(b, ref) : pcfHausdorffEstimate(b, ref);
    } else {
        e = pcfVarianceEstimate(m, ref, prm);
    }
    if (isnan(e.visibility)) e.visibility = 1.0f;
    pcfMomentTaps(map, uv, ref, e.visibility);
    return e;
}
