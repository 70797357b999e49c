// reference/tent.frag: tent, the textbook way (see README.md here): Castaño's N x N tent filter
// (Castaño, "Shadow Mapping Summary Part 1", 2013) from hardware comparison taps placed between
// texels so the texture unit's lerp makes the tent's weights. Per axis, q = uv * size,
// b = floor(q + 0.5), s = q + 0.5 - b:
//   3: w = 3-2s, 1+2s                        o = (2-s)/w0 - 1, s/w1 + 1               D = 16
//   5: w = 4-3s, 7, 1+3s                     o = (3-2s)/w0 - 2, (3+s)/w1, s/w2 + 2    D = 144
//   7: w = 5s-6, 11s-28, -(11s+17), -(5s+1)  o = (4s-5)/w0 - 3, (4s-16)/w1 - 1,
//                                                -(7s+5)/w2 + 1, -s/w3 + 3            D = 2704
// tap (i, j) at uv' = (b - 0.5 + (o_i, o_j)) / size, weight w_i w_j; visibility = sum / D.
// N (3, 5 or 7) is a define.
uniform sampler2DShadow uPcfCompare;  // GL_LINEAR, GL_LEQUAL comparison, clamp to edge
uniform sampler2D uLookups;           // RGBA32F: u, v, ref, unused

layout(location = 0) out float oVisibility;

#if N == 3
const int TAPS = 2;
const float D = 16.0f;
void axis(float s, out float w[TAPS], out float o[TAPS]) {
    w[0] = 3.0f - 2.0f * s;
    w[1] = 1.0f + 2.0f * s;
    o[0] = (2.0f - s) / w[0] - 1.0f;
    o[1] = s / w[1] + 1.0f;
}
#elif N == 5
const int TAPS = 3;
const float D = 144.0f;
void axis(float s, out float w[TAPS], out float o[TAPS]) {
    w[0] = 4.0f - 3.0f * s;
    w[1] = 7.0f;
    w[2] = 1.0f + 3.0f * s;
    o[0] = (3.0f - 2.0f * s) / w[0] - 2.0f;
    o[1] = (3.0f + s) / w[1];
    o[2] = s / w[2] + 2.0f;
}
#else
const int TAPS = 4;
const float D = 2704.0f;
void axis(float s, out float w[TAPS], out float o[TAPS]) {
    w[0] = 5.0f * s - 6.0f;
    w[1] = 11.0f * s - 28.0f;
    w[2] = -(11.0f * s + 17.0f);
    w[3] = -(5.0f * s + 1.0f);
    o[0] = (4.0f * s - 5.0f) / w[0] - 3.0f;
    o[1] = (4.0f * s - 16.0f) / w[1] - 1.0f;
    o[2] = -(7.0f * s + 5.0f) / w[2] + 1.0f;
    o[3] = -s / w[3] + 3.0f;
}
#endif

void main() {
    vec4 lookup = texelFetch(uLookups, ivec2(gl_FragCoord.xy), 0);
    vec2 size = vec2(textureSize(uPcfCompare, 0));
    // precise: a fused multiply-add could land floor() on the other texel than the CPU's.
    precise vec2 q = lookup.xy * size + 0.5f;
    vec2 b = floor(q);
    vec2 s = q - b;
    float wx[TAPS], ox[TAPS], wy[TAPS], oy[TAPS];
    axis(s.x, wx, ox);
    axis(s.y, wy, oy);
    vec2 texelUv = 1.0f / size;
    vec2 baseUv = (b - 0.5f) * texelUv;
    float sum = 0.0f;
    for (int j = 0; j < TAPS; ++j) {
        for (int i = 0; i < TAPS; ++i) {
            vec2 uv = baseUv + vec2(ox[i], oy[j]) * texelUv;
            sum += wx[i] * wy[j] * texture(uPcfCompare, vec3(uv, lookup.z));
        }
    }
    oVisibility = sum / D;
}
