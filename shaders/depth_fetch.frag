// depth_fetch.frag: copies each texel of a depth texture, as texelFetch returns it, into an R32F
// target. This is how the CPU reads "the map the sampler compares against": for 16- and 24-bit
// maps the driver's own unorm-to-float conversion, not glGetTextureImage's (which can differ by
// one float step, issue 10). see: src/render/depth_readback.cpp
uniform sampler2D uDepth;
layout(location = 0) out float oDepth;

void main() { oDepth = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r; }
