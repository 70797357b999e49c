// reference/pcss.frag: percentage-closer soft shadows, the textbook way (see README.md here):
// Fernando, "Percentage-Closer Soft Shadows" (NVIDIA, 2005), for a light at infinity whose size
// in the map is uPenumbraScale (texels of penumbra per unit of light depth). 16 point-sampled
// depths on Jimmy's Poisson disk (Jimmy, "Percentage Closer Filtering", ownself.org, 2010) over
// a radius of ref * S / 2 texels find the blockers (depth < ref); none: lit. Otherwise the
// penumbra w = (ref - mean blocker depth) * S, and 16 comparisons on the disk of radius w / 2.
// Both radii in [1, 32] texels. No rotation.
uniform sampler2D uPcfDepth;   // nearest, clamp to edge
uniform sampler2D uLookups;    // RGBA32F: u, v, ref, unused
uniform float uPenumbraScale;  // texels per unit of light depth

layout(location = 0) out float oVisibility;

const vec2 DISK[16] = vec2[16](
    vec2(-0.94201624f, -0.39906216f), vec2(0.94558609f, -0.76890725f),
    vec2(-0.094184101f, -0.92938870f), vec2(0.34495938f, 0.29387760f),
    vec2(-0.91588581f, 0.45771432f), vec2(-0.81544232f, -0.87912464f),
    vec2(-0.38277543f, 0.27676845f), vec2(0.97484398f, 0.75648379f),
    vec2(0.44323325f, -0.97511554f), vec2(0.53742981f, -0.47373420f),
    vec2(-0.26496911f, -0.41893023f), vec2(0.79197514f, 0.19090188f),
    vec2(-0.24188840f, 0.99706507f), vec2(-0.81409955f, 0.91437590f),
    vec2(0.19984126f, 0.78641367f), vec2(0.14383161f, -0.14100790f));

void main() {
    vec4 lookup = texelFetch(uLookups, ivec2(gl_FragCoord.xy), 0);
    vec2 texelUv = 1.0f / vec2(textureSize(uPcfDepth, 0));
    precise float searchRadius = clamp(lookup.z * uPenumbraScale * 0.5f, 1.0f, 32.0f);
    float blockers = 0.0f;
    precise float depthSum = 0.0f;
    for (int k = 0; k < 16; ++k) {
        // precise: the tap's texel is floor(uv * size); a fused multiply-add could pick another.
        precise vec2 uv = lookup.xy + DISK[k] * searchRadius * texelUv;
        float depth = texture(uPcfDepth, uv).r;
        if (depth < lookup.z) {
            blockers += 1.0f;
            depthSum += depth;
        }
    }
    if (blockers == 0.0f) {
        oVisibility = 1.0f;
        return;
    }
    precise float penumbra = (lookup.z - depthSum / blockers) * uPenumbraScale;
    precise float filterRadius = clamp(penumbra * 0.5f, 1.0f, 32.0f);
    float sum = 0.0f;
    for (int k = 0; k < 16; ++k) {
        precise vec2 uv = lookup.xy + DISK[k] * filterRadius * texelUv;
        sum += lookup.z <= texture(uPcfDepth, uv).r ? 1.0f : 0.0f;
    }
    oVisibility = sum / 16.0f;
}
