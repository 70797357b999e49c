// shading.h: the CPU side of shaders/shared/pcf_shading.h, the camera pass's gamma encoding,
// compiled here as C++ (in pcf.h's dialect) and by the GL driver as GLSL, so tests bound the
// function the fragment shader runs.
#pragma once

#include "kernel/pcf.h"

namespace pcf {

#include "shaders/shared/pcf_shading.h"

}  // namespace pcf
