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

// The texels of `texture`, a one-layer map of `map`'s size and texel kind (its depth, or its
// moments: map.texel().channels floats each), as texelFetch returns them, GL row order, with
// `map` as their spec. Needs a current OpenGL 4.5 context.
ShadowMap readSampledDepth(GLuint texture, const MapSpec& map);

// What llvmpipe's sampler makes of the stored integer k of a `bits`-bit unorm depth:
// float(k) * float(1 / (2^bits - 1)), both factors and the product in single precision.
float unormDepthAsSampled(uint32_t k, int bits);

}  // namespace pcf
