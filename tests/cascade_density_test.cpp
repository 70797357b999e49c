// measure/cascade_density.h: the larger singular value of a pixel's texel Jacobian (Lloyd et al.'s
// per-direction texel density), against matrices whose singular values are known.
#include "measure/cascade_density.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pcf {
namespace {

glm::mat2 rotation(float degrees) {
    float a = glm::radians(degrees);
    return glm::mat2(std::cos(a), std::sin(a), -std::sin(a), std::cos(a));
}

TEST(CascadeDensity, TheLargerSingularValueIsTheLargestStretch) {
    // A stretch of 3 along one axis and 0.5 along the other, turned either side: 3.
    glm::mat2 stretch(3.0f, 0.0f, 0.0f, 0.5f);
    EXPECT_NEAR(largerSingularValue(stretch), 3.0, 1e-6);
    EXPECT_NEAR(largerSingularValue(rotation(30.0f) * stretch * rotation(-75.0f)), 3.0, 1e-5);
    // A shear [1 1; 0 1]: singular values the golden ratio and its reciprocal.
    EXPECT_NEAR(largerSingularValue(glm::mat2(1.0f, 0.0f, 1.0f, 1.0f)),
                (1.0 + std::sqrt(5.0)) / 2.0, 1e-6);
    // Degenerate (a line): the length of the line's step.
    EXPECT_NEAR(largerSingularValue(glm::mat2(3.0f, 4.0f, 0.0f, 0.0f)), 5.0, 1e-6);
    // A uniform scale: the scale itself, the square root of the area ratio.
    EXPECT_NEAR(largerSingularValue(glm::mat2(2.0f)), 2.0, 1e-6);
}

}  // namespace
}  // namespace pcf
