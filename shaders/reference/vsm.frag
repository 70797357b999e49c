// reference/vsm.frag: vsm, the textbook way (see README.md here). The map holds the filtered
// moments (E[z], E[z^2]) of the depths (the moments pass made them); one bilinear read at the
// lookup gives the footprint's, and Chebyshev's one-tailed inequality bounds the lit fraction
// (Donnelly and Lauritzen, "Variance Shadow Maps", 2006):
//   mu = E[z], s^2 = max(E[z^2] - mu^2, minVariance)
//   p = 1 when t <= mu, else s^2 / (s^2 + (t - mu)^2)
// then the light-bleeding reduction cuts the low values, linstep(lbr, 1, p) (Lauritzen and
// McCool, "Layered Variance Shadow Maps", 2008). t is the lookup's ref held to [0, 1].
uniform sampler2D uPcfDepth;  // the moments map: texelFetch, out-of-range texels clamp to the edge
uniform sampler2D uLookups;   // RGBA32F: u, v, ref, unused
uniform float uLbr;
uniform float uMinVariance;

layout(location = 0) out float oVisibility;

vec4 texelAt(ivec2 t, ivec2 size) { return texelFetch(uPcfDepth, clamp(t, ivec2(0), size - 1), 0); }

void main() {
    vec4 lookup = texelFetch(uLookups, ivec2(gl_FragCoord.xy), 0);
    ivec2 size = textureSize(uPcfDepth, 0);
    precise vec2 p = lookup.xy * vec2(size) - 0.5f;
    vec2 b = floor(p);
    vec2 f = p - b;
    ivec2 t = ivec2(b);
    // The bilinear weights of the four texels, (1 - fx)(1 - fy), fx (1 - fy), (1 - fx) fy, fx fy.
    vec4 m = (1.0f - f.x) * (1.0f - f.y) * texelAt(t, size) +
             f.x * (1.0f - f.y) * texelAt(t + ivec2(1, 0), size) +
             (1.0f - f.x) * f.y * texelAt(t + ivec2(0, 1), size) +
             f.x * f.y * texelAt(t + ivec2(1, 1), size);
    float z = clamp(lookup.z, 0.0f, 1.0f);
    float mu = m.x;
    float s2 = max(m.y - mu * mu, uMinVariance);
    float pmax = z <= mu ? 1.0f : s2 / (s2 + (z - mu) * (z - mu));
    oVisibility = clamp((pmax - uLbr) / (1.0f - uLbr), 0.0f, 1.0f);
}
