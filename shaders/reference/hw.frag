// reference/hw.frag: pcf-hw, the textbook way (see README.md here): N x N hardware comparison
// taps one texel apart through a sampler2DShadow with GL_LINEAR (ogldev, OpenGL tutorial 42),
// offsets k - (N-1)/2 texels, k = 0..N-1, averaged: visibility = sum / N^2. N = 1 is hw2x2.
// N is a define.
uniform sampler2DShadow uPcfCompare;  // GL_LINEAR, GL_LEQUAL comparison, clamp to edge
uniform sampler2D uLookups;           // RGBA32F: u, v, ref, unused

layout(location = 0) out float oVisibility;

void main() {
    vec4 lookup = texelFetch(uLookups, ivec2(gl_FragCoord.xy), 0);
    vec2 texelUv = 1.0f / vec2(textureSize(uPcfCompare, 0));
    float sum = 0.0f;
    for (int j = 0; j < N; ++j) {
        for (int i = 0; i < N; ++i) {
            vec2 offset = vec2(i, j) - 0.5f * float(N - 1);
            sum += texture(uPcfCompare, vec3(lookup.xy + offset * texelUv, lookup.z));
        }
    }
    oVisibility = sum / float(N * N);
}
