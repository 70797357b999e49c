// overlay.frag: solid colour for shapes, glyph coverage for text (src/overlay/canvas.h).
// Glyph quads sit on whole pixels with texel coordinates that advance one texel per pixel, so
// floor(vUv) at a pixel centre is exactly the glyph's texel: texelFetch, no filtering, crisp.
// The atlas is chosen per vertex; indexing a sampler array with a non-uniform value is not
// allowed in GLSL 4.50, so each slot is read under its own constant index.

in vec2 vUv;
in vec4 vColour;
flat in int vSlot;

layout(binding = 0) uniform sampler2D uAtlas[8];
// Canvas::image's picture (RGBA32F, straight alpha): texel floor(vUv) is the pixel's colour.
layout(binding = 8) uniform sampler2D uImage;

layout(location = 0) out vec4 outColour;

// SINGLE_ATLAS: the variant for draws with one atlas (most of them). llvmpipe runs every case
// of the switch below for each glyph pixel, masked, so one fetch instead of eight is far cheaper.
float coverage(int slot, ivec2 texel) {
#ifdef SINGLE_ATLAS
    return texelFetch(uAtlas[0], texel, 0).r;
#else
    switch (slot) {
        case 0:
            return texelFetch(uAtlas[0], texel, 0).r;
        case 1:
            return texelFetch(uAtlas[1], texel, 0).r;
        case 2:
            return texelFetch(uAtlas[2], texel, 0).r;
        case 3:
            return texelFetch(uAtlas[3], texel, 0).r;
        case 4:
            return texelFetch(uAtlas[4], texel, 0).r;
        case 5:
            return texelFetch(uAtlas[5], texel, 0).r;
        case 6:
            return texelFetch(uAtlas[6], texel, 0).r;
        case 7:
            return texelFetch(uAtlas[7], texel, 0).r;
    }
    return 1.0;
#endif
}

void main() {
    // Shapes skip the atlas switch entirely: on llvmpipe a branch taken by no fragment of a
    // block costs nothing, while the switch would otherwise run for every shape pixel.
    if (vSlot == -1) {
        outColour = vColour;
        return;
    }
    if (vSlot == -2) {
        // The texel's colour as a fillRect of it would give it; transparent texels draw nothing.
        vec4 c = texelFetch(uImage, ivec2(floor(vUv)), 0);
        if (c.a == 0.0) discard;
        outColour = c;
        return;
    }
    float a = coverage(vSlot, ivec2(floor(vUv)));
    outColour = vec4(vColour.rgb, vColour.a * a);
}
