// reference/msm_hausdorff.frag: msm-hausdorff, the textbook way (see README.md here), after
// Peters and Klein, "Moment Shadow Mapping", 2015: the Hamburger answer of reference/msm.frag
// (the same steps, repeated here so each file stands alone) while its depths z2, z3 lie in
// [0, 1]; otherwise the depths are held to [0, 1] by a distribution on the four depths
// {0, zf, x, 1}, x free, with all four moments b'. Writing u_k = b_k - b_(k+1) (k = 1, 2, 3),
// each point z adds w z^k (1 - z) to u_k, the points 0 and 1 nothing, so
//   u_(k+1) - zf u_k = C x^k (x - zf)  with C = w_x (1 - x):  x = (u3 - zf u2) / (u2 - zf u1)
//   w_x = (u2 - zf u1) / (x (x - zf) (1 - x)),  w_f = (u1 - w_x x (1 - x)) / (zf (1 - zf))
//   w_1 = b1 - w_f zf - w_x x,  w_0 = 1 - w_f - w_x - w_1
// and the shadow is w_0, plus w_x when x < zf (Hamburger's answer stands if that is NaN).
uniform sampler2D uPcfDepth;  // the moments map: texelFetch, out-of-range texels clamp to the edge
uniform sampler2D uLookups;   // RGBA32F: u, v, ref, unused
uniform float uMomentBias;

layout(location = 0) out float oVisibility;

vec4 texelAt(ivec2 t, ivec2 size) { return texelFetch(uPcfDepth, clamp(t, ivec2(0), size - 1), 0); }

void main() {
    vec4 lookup = texelFetch(uLookups, ivec2(gl_FragCoord.xy), 0);
    ivec2 size = textureSize(uPcfDepth, 0);
    precise vec2 p = lookup.xy * vec2(size) - 0.5f;
    vec2 base = floor(p);
    vec2 f = p - base;
    ivec2 t = ivec2(base);
    // The bilinear weights of the four texels, (1 - fx)(1 - fy), fx (1 - fy), (1 - fx) fy, fx fy.
    vec4 m = (1.0f - f.x) * (1.0f - f.y) * texelAt(t, size) +
             f.x * (1.0f - f.y) * texelAt(t + ivec2(1, 0), size) +
             (1.0f - f.x) * f.y * texelAt(t + ivec2(0, 1), size) +
             f.x * f.y * texelAt(t + ivec2(1, 1), size);
    vec4 b = (1.0f - uMomentBias) * m + uMomentBias * vec4(0.5f);
    float zf = clamp(lookup.z, 0.0f, 1.0f);
    // B = L D L^T with L unit lower triangular: the rows (1, 0, 0), (b1, 1, 0), (b2, l32, 1).
    float d2 = b.y - b.x * b.x;
    float l32 = (b.z - b.x * b.y) / d2;
    float d3 = b.w - b.y * b.y - d2 * l32 * l32;
    // L y = (1, zf, zf^2), D w = y, L^T c = w.
    float y2 = zf - b.x;
    float y3 = zf * zf - b.y - l32 * y2;
    float c3 = y3 / d3;
    float c2 = y2 / d2 - l32 * c3;
    float c1 = 1.0f - b.x * c2 - b.y * c3;
    float half_p = 0.5f * c2 / c3;
    float root = sqrt(max(half_p * half_p - c1 / c3, 0.0f));
    float z2 = -half_p - root;
    float z3 = -half_p + root;
    float g;
    if (zf <= z2) {
        g = 0.0f;
    } else if (zf <= z3) {
        g = (zf * z3 - b.x * (zf + z3) + b.y) / ((z3 - z2) * (zf - z2));
    } else {
        g = 1.0f - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((zf - z2) * (zf - z3));
    }
    if (z2 < 0.0f || z3 > 1.0f) {
        float u1 = b.x - b.y;
        float u2 = b.y - b.z;
        float u3 = b.z - b.w;
        float x = (u3 - zf * u2) / (u2 - zf * u1);
        float wx = (u2 - zf * u1) / (x * (x - zf) * (1.0f - x));
        float wf = (u1 - wx * x * (1.0f - x)) / (zf * (1.0f - zf));
        float w1 = b.x - wf * zf - wx * x;
        float w0 = 1.0f - wf - wx - w1;
        float shadow = w0 + (x < zf ? wx : 0.0f);
        if (!isnan(shadow)) g = shadow;
    }
    float v = 1.0f - clamp(g, 0.0f, 1.0f);
    oVisibility = isnan(v) ? 1.0f : v;
}
