// reference/msm.frag: msm (Hamburger), the textbook way (see README.md here), after Peters and
// Klein, "Moment Shadow Mapping", 2015 (its algorithm for four moments). The map holds the
// filtered moments b = (E[z], E[z^2], E[z^3], E[z^4]); one bilinear read at the lookup, then:
//   b' = (1 - alpha) b + alpha (0.5, 0.5, 0.5, 0.5)                      the moment bias
//   solve [1 b1 b2; b1 b2 b3; b2 b3 b4] c = (1, zf, zf^2) by Cholesky    zf: the receiver
//   z2 <= z3: the roots of c3 z^2 + c2 z + c1 = 0
//   zf <= z2: G = 0
//   zf <= z3: G = (zf z3 - b1 (zf + z3) + b2) / ((z3 - z2) (zf - z2))
//   else:     G = 1 - (z2 z3 - b1 (z2 + z3) + b2) / ((zf - z2) (zf - z3))
// visibility = 1 - G. zf is the lookup's ref held to [0, 1].
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
    float v = 1.0f - clamp(g, 0.0f, 1.0f);
    oVisibility = isnan(v) ? 1.0f : v;
}
