// depth_snapped.geom: each triangle of a snapped cascade's depth pass, grown by GROW texels on
// every side, so that the rasterizer's fragments hold every texel centre the triangle covers,
// whatever the clipper does at the map's edges; depth_snapped.frag keeps the ones inside the
// triangle itself. see: src/render/scene_renderer.cpp
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vGrid[];
flat out vec3 gA;
flat out vec3 gB;
flat out vec3 gC;

uniform vec2 uOrigin;    // the world origin's texel corner in the map (whole texels)
uniform float uHalfMap;  // the map's size / 2, texels

const float GROW = 0.5;

void main() {
    vec2 p0 = vGrid[0].xy, p1 = vGrid[1].xy, p2 = vGrid[2].xy;
    // Grown as in Hasselgren, Akenine-Moller and Ohlsson, "Conservative Rasterization" (GPU Gems 2,
    // 2005), here by scaling about the incentre by 1 + GROW / r (r the inradius, twice the area
    // over the perimeter), which moves every side out by GROW.
    float a = distance(p1, p2), b = distance(p2, p0), c = distance(p0, p1);
    float perimeter = a + b + c;
    float area2 = abs((p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x));
    if (!(area2 > 0.0)) return;  // no area: it covers no texel centre
    vec2 incentre = (a * p0 + b * p1 + c * p2) / perimeter;
    float grow = 1.0 + GROW * perimeter / area2;
    for (int k = 0; k < 3; ++k) {
        gA = vGrid[0];
        gB = vGrid[1];
        gC = vGrid[2];
        vec2 grown = incentre + (vGrid[k].xy - incentre) * grow;
        gl_Position = vec4((grown + uOrigin - uHalfMap) / uHalfMap, vGrid[k].z, 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
