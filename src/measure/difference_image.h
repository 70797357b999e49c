// difference_image.h: the signed error of a rendered shadow as a picture, because people would
// rather look than read a table.
//
// e = rendered - truth, per compared pixel (error_metrics.h), drawn on a diverging map:
//   e = -fullScale  blue  (0, 0, 255)    the render is too DARK: shadow where there is light
//   e = 0           white (255, 255, 255)
//   e = +fullScale  red   (255, 0, 0)    the render is too BRIGHT: light leaking into shadow
// linear in between (per byte), clamped beyond. Pixels that are not compared (background,
// surfaces facing away from the light) are dark grey, so the white of "no error" stands out.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "measure/error_metrics.h"
#include "measure/ground_truth.h"

namespace pcf {

constexpr glm::u8vec4 DIFFERENCE_BACKGROUND{64, 64, 64, 255};

// The colour of signed error e; fullScale > 0.
glm::u8vec4 signedErrorColour(float e, float fullScale = 1.0f);

// RGBA8, rows top-down (ready for writePngRgba8), the truth's size. visibility: the rendered
// visibility, top-down; throws std::invalid_argument when the sizes differ.
std::vector<uint8_t> differenceImage(const GroundTruth& truth, const ErrorRegions& regions,
                                     std::span<const float> visibility, float fullScale = 1.0f);

}  // namespace pcf
