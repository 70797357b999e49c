// reference/box.frag: box2x2, the textbook way (see README.md here): the four texels of the
// bilinear 2x2 (p = uv * size - 0.5, b = floor(p); docs/methods.md, "Conventions"), each
// compared, averaged without weights, so only 0, .25, .5, .75 or 1 ("What Is PCF and How Does It
// Work?").
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
    ivec2 b = ivec2(floor(p));
    float sum = lit(b, size, lookup.z) + lit(b + ivec2(1, 0), size, lookup.z) +
                lit(b + ivec2(0, 1), size, lookup.z) + lit(b + ivec2(1, 1), size, lookup.z);
    oVisibility = sum * 0.25f;
}
