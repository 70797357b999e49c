// reference/naive.frag: pcf-naive, the textbook way (see README.md here): N x N bilinear
// lookups one texel apart, averaged ("PCF Shadow Acne"). Each lookup compares the four texels
// around it and lerps the four bits by the sub-texel position ("What Is PCF and How Does It
// Work?"), in GL's convention p = uv * size - 0.5 (docs/methods.md, "Conventions"):
//   b = floor(p), f = p - b,  v = mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y)
//   offsets k - (N-1)/2, k = 0..N-1;  visibility = sum / N^2
// N = 1 is bilinear2x2. N is a define.
uniform sampler2D uPcfDepth;  // texelFetch; out-of-range texels clamp to the edge
uniform sampler2D uLookups;   // RGBA32F: u, v, ref, unused

layout(location = 0) out float oVisibility;

float lit(ivec2 texel, ivec2 size, float ref) {
    float depth = texelFetch(uPcfDepth, clamp(texel, ivec2(0), size - 1), 0).r;
    return ref <= depth ? 1.0f : 0.0f;
}

void main() {
    vec4 lookup = texelFetch(uLookups, ivec2(gl_FragCoord.xy), 0);
    ivec2 size = textureSize(uPcfDepth, 0);
    // precise: a fused multiply-add could land floor() on the other texel than the CPU's.
    precise vec2 p = lookup.xy * vec2(size) - 0.5f;
    float sum = 0.0f;
    for (int j = 0; j < N; ++j) {
        for (int i = 0; i < N; ++i) {
            precise vec2 q = p + (vec2(i, j) - 0.5f * float(N - 1));
            vec2 b = floor(q);
            vec2 f = q - b;
            ivec2 t = ivec2(b);
            float c00 = lit(t, size, lookup.z);
            float c10 = lit(t + ivec2(1, 0), size, lookup.z);
            float c01 = lit(t + ivec2(0, 1), size, lookup.z);
            float c11 = lit(t + ivec2(1, 1), size, lookup.z);
            sum += mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y);
        }
    }
    oVisibility = sum / float(N * N);
}
