// depth_readback.h: the shadow map as the GPU's sampler sees it.
//
// For a 16- or 24-bit depth texture the stored integer k becomes a float inside the texture
// unit. llvmpipe computes float(k) * float(1 / (2^bits - 1)) in single precision (measured:
// tests/gpu_parity_test.cpp, FixedPointReadbackIsTheSamplersFloat), which differs from the
// correctly rounded k / (2^24 - 1) that glGetTextureImage returns in about 40 % of 24-bit texels.
// So pcfscope does not convert at all: it reads back what the GPU holds, by a texelFetch pass
// into a float target, on any driver. The CPU kernel, `render --raw`'s shadowmap.exr, the trace
// and the inspector all use this map.
#pragma once

#include <epoxy/gl.h>

#include "kernel/shadow_map.h"

namespace pcf {

// The depths of `texture` (width x height, GL row order) as texelFetch returns them, tagged with
// fixedPointBits (16, 24, or 0 for 32F). Needs a current OpenGL 4.5 context.
ShadowMap readSampledDepth(GLuint texture, int width, int height, int fixedPointBits);

// What llvmpipe's sampler makes of the stored integer k of a `bits`-bit unorm depth:
// float(k) * float(1 / (2^bits - 1)), both factors and the product in single precision.
float unormDepthAsSampled(uint32_t k, int bits);

}  // namespace pcf
