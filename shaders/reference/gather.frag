// reference/gather.frag: pcf-gather, the textbook way (see README.md here): the N x N bilinear
// lookups of pcf-naive read (N+1)^2 distinct texels; read each once with comparison gathers of
// 2x2 blocks and weight it by the table of "PCF Shadow Acne" part 2 (there for N = 3: four
// gathers), per axis for texel m = 0..N of the footprint, with g the sub-texel position every
// lookup shares:
//   m = 0: 1 - g      0 < m < N: 1      m = N: g          weight(x, y) = W(mx) W(my) / N^2
// The footprint starts at floor(q), q = uv * size - 0.5 - (N-1)/2; g = q - floor(q). Each
// gather sits on the shared corner of its block, and returns GL's order x = (0,1), y = (1,1),
// z = (1,0), w = (0,0). N is a define.
uniform sampler2DShadow uPcfCompare;  // GL_LEQUAL comparison, clamp to edge
uniform sampler2D uLookups;           // RGBA32F: u, v, ref, unused

layout(location = 0) out float oVisibility;

float footprintWeight(int m, float g) {
    return (m < N ? 1.0f - g : 0.0f) + (m > 0 ? g : 0.0f);
}

void main() {
    vec4 lookup = texelFetch(uLookups, ivec2(gl_FragCoord.xy), 0);
    vec2 size = vec2(textureSize(uPcfCompare, 0));
    // precise: a fused multiply-add could land floor() on the other texel than the CPU's.
    precise vec2 p = lookup.xy * size - 0.5f;
    precise vec2 q = p - 0.5f * float(N - 1);
    vec2 origin = floor(q);
    vec2 g = q - origin;
    float sum = 0.0f;
    for (int by = 0; by < (N + 2) / 2; ++by) {
        for (int bx = 0; bx < (N + 2) / 2; ++bx) {
            int mx = 2 * bx;
            int my = 2 * by;
            float wx0 = footprintWeight(mx, g.x);
            float wx1 = mx + 1 <= N ? footprintWeight(mx + 1, g.x) : 0.0f;
            float wy0 = footprintWeight(my, g.y);
            float wy1 = my + 1 <= N ? footprintWeight(my + 1, g.y) : 0.0f;
            vec2 corner = (origin + vec2(mx + 1, my + 1)) / size;
            vec4 bits = textureGather(uPcfCompare, corner, lookup.z);
            sum += dot(bits, vec4(wx0 * wy1, wx1 * wy1, wx1 * wy0, wx0 * wy0));
        }
    }
    oVisibility = sum / float(N * N);
}
