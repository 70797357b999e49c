// reference/nearest.frag: nearest, the textbook way (see README.md here): the depth of the one
// texel the lookup falls in, floor(uv * size), through the nearest sampler, compared once
// (GL_LEQUAL: lit when ref <= depth; docs/methods.md, "Conventions" and "The methods").
uniform sampler2D uPcfDepth;  // nearest, clamp to edge
uniform sampler2D uLookups;   // RGBA32F: u, v, ref, unused

layout(location = 0) out float oVisibility;

void main() {
    vec4 lookup = texelFetch(uLookups, ivec2(gl_FragCoord.xy), 0);
    float depth = texture(uPcfDepth, lookup.xy).r;
    oVisibility = lookup.z <= depth ? 1.0f : 0.0f;
}
