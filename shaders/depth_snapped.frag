// depth_snapped.frag: a snapped cascade's depth, from the triangle itself in texels from the world
// origin's corner (depth_snapped.geom), never from where the map's edges cut it: a texel is
// covered, and its depth interpolated, from the same numbers at every step of the camera, so the
// map is the last one moved by whole texels, bit for bit. see: src/render/scene_renderer.cpp
flat in vec3 gA;
flat in vec3 gB;
flat in vec3 gC;

uniform vec2 uOrigin;          // the world origin's texel corner in the map (whole texels)
uniform vec2 uPolygonOffset;   // glPolygonOffset's factor and units, which gl_FragDepth bypasses
uniform float uDepthUnit;      // r: one step of a fixed-point depth format, 0 for float

// Pineda's edge function ("A Parallel Algorithm for Polygon Rasterization", SIGGRAPH 1988): twice
// the signed area of (p, q, x), > 0 when x lies left of p -> q; the three of a triangle over its
// area are x's barycentric weights.
double edgeFunction(dvec2 p, dvec2 q, dvec2 x) {
    return (x.x - p.x) * (q.y - p.y) - (x.y - p.y) * (q.x - p.x);
}

void main() {
    dvec2 x = dvec2(gl_FragCoord.xy) - dvec2(uOrigin);  // exact: a texel centre less whole texels
    dvec2 a = dvec2(gA.xy), b = dvec2(gB.xy), c = dvec2(gC.xy);
    double area = edgeFunction(a, b, c);
    if (area == 0.0) discard;  // a triangle seen edge-on covers nothing
    double wa = edgeFunction(b, c, x) / area;
    double wb = edgeFunction(c, a, x) / area;
    double wc = edgeFunction(a, b, x) / area;
    // Inside, edges included (a depth map has no blending, so a centre on a shared side may be
    // written by both triangles).
    if (wa < 0.0 || wb < 0.0 || wc < 0.0) discard;
    double z = wa * double(gA.z) + wb * double(gB.z) + wc * double(gC.z);
    float depth = float(z * 0.5 + 0.5);
    if (uPolygonOffset != vec2(0.0)) {
        // GL 4.5 (14.6.5): o = m * factor + r * units, m the depth's largest slope per texel.
        dvec2 dz = 0.5 * (double(gA.z) * dvec2(b.y - c.y, c.x - b.x) +
                          double(gB.z) * dvec2(c.y - a.y, a.x - c.x) +
                          double(gC.z) * dvec2(a.y - b.y, b.x - a.x)) / area;
        float m = float(max(abs(dz.x), abs(dz.y)));
        // r of a float depth: 2^(E - 23), E the exponent of the triangle's largest depth.
        int e;
        frexp(max(max(gA.z, gB.z), gC.z) * 0.5 + 0.5, e);
        float r = uDepthUnit > 0.0 ? uDepthUnit : ldexp(1.0, e - 24);
        depth += m * uPolygonOffset.x + r * uPolygonOffset.y;
    }
    gl_FragDepth = depth;
}
