// depth_snapped.vert: the depth pass of a snapped cascade (scene/cascade_fit.h), whose map moves by
// whole texels as the camera moves. see: src/render/scene_renderer.cpp, depth_snapped.geom
//
// A vertex's place in texels from the world origin's texel corner: the same floats at every step,
// since the fit keeps the matrix's rows (all but the translation) the same floats from frame to
// frame and puts the world origin on a whole texel.
layout(location = 0) in vec3 aPosWs;

uniform vec3 uTexelsX;  // the clip matrix's row 0 without its translation, times size / 2
uniform vec3 uTexelsY;  // row 1 likewise
uniform vec4 uClipZ;    // row 2, whole

out vec3 vGrid;  // x, y: texels from the world origin's corner; z: clip z (w is 1)

void main() {
    vGrid = vec3(dot(uTexelsX, aPosWs), dot(uTexelsY, aPosWs), dot(uClipZ.xyz, aPosWs) + uClipZ.w);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);  // the geometry stage places the triangle
}
