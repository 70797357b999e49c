// depth_fetch.frag: copies each texel of a map's texture, as texelFetch returns it, into a float
// target of as many channels as the map's texels (R32F for a depth). This is how the CPU reads
// "the map the sampler compares against": for 16- and 24-bit maps the driver's own unorm-to-float
// conversion, not glGetTextureImage's (which can differ by one float step, issue 10).
// see: src/render/depth_readback.cpp
uniform sampler2D uDepth;
layout(location = 0) out vec4 oTexel;

void main() { oTexel = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0); }
