// overlay.vert: the canvas's one vertex stage (src/overlay/canvas.h).
// Positions arrive in pixels with the origin at the top-left, y down; GL's clip space has y up,
// hence the flip. A vertex at pixel (x, y) lands exactly on window coordinate
// (x, height - y), so whole-pixel edges fall between pixel centres (see: canvas.h).

layout(location = 0) in vec2 aPos;     // pixels, top-left origin
layout(location = 1) in vec2 aUv;      // glyph atlas texel coordinates
layout(location = 2) in vec4 aColour;  // straight alpha
layout(location = 3) in int aSlot;     // -1 = solid, -2 = image, 0..7 = atlas unit

layout(location = 0) uniform vec2 uTargetSize;  // pixels

out vec2 vUv;
out vec4 vColour;
flat out int vSlot;

void main() {
    vec2 ndc = vec2(aPos.x / uTargetSize.x * 2.0 - 1.0, 1.0 - aPos.y / uTargetSize.y * 2.0);
    gl_Position = vec4(ndc, 0.0, 1.0);
    vUv = aUv;
    vColour = aColour;
    vSlot = aSlot;
}
