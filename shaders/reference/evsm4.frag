// reference/evsm4.frag: evsm4, the textbook way (see README.md here). The map holds the
// filtered moments of the exponentially warped depth (Lauritzen and McCool, "Layered Variance
// Shadow Maps", 2008): with x = 2z - 1,
//   positive warp e+ = exp(c+ x): (E[e+], E[e+^2]);  negative e- = -exp(-c- x): (E[e-], E[e-^2])
// One bilinear read at the lookup, then Chebyshev's bound (Donnelly and Lauritzen, "Variance
// Shadow Maps", 2006) on each warp with the receiver warped alike, the smaller taken, then the
// light-bleeding reduction linstep(lbr, 1, p). The variance floor is minVariance carried through
// the warp's slope at the receiver, minVariance (de/dz)^2 with de/dz = 2 c e.
uniform sampler2D uPcfDepth;  // the moments map: texelFetch, out-of-range texels clamp to the edge
uniform sampler2D uLookups;   // RGBA32F: u, v, ref, unused
uniform float uLbr;
uniform float uMinVariance;
uniform vec2 uEvsmExponents;  // c+, c-

layout(location = 0) out float oVisibility;

vec4 texelAt(ivec2 t, ivec2 size) { return texelFetch(uPcfDepth, clamp(t, ivec2(0), size - 1), 0); }

// Chebyshev's upper bound on the share at or beyond `receiver` of a distribution with these
// first two moments, its variance at least `least`.
float chebyshev(vec2 moments, float receiver, float least) {
    if (receiver <= moments.x) return 1.0f;
    float s2 = max(moments.y - moments.x * moments.x, least);
    float d = receiver - moments.x;
    return s2 / (s2 + d * d);
}

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
    float x = 2.0f * clamp(lookup.z, 0.0f, 1.0f) - 1.0f;
    float cp = uEvsmExponents.x;
    float ep = exp(cp * x);
    float pmax = chebyshev(m.xy, ep, uMinVariance * (2.0f * cp * ep) * (2.0f * cp * ep));
    float cn = uEvsmExponents.y;
    float en = -exp(-cn * x);
    pmax = min(pmax, chebyshev(m.zw, en, uMinVariance * (2.0f * cn * en) * (2.0f * cn * en)));
    float v = clamp((pmax - uLbr) / (1.0f - uLbr), 0.0f, 1.0f);
    oVisibility = isnan(v) ? 1.0f : v;
}
