#include "measure/difference_image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pcf {

glm::u8vec4 signedErrorColour(float e, float fullScale) {
    float t = std::isfinite(e) ? std::clamp(e / fullScale, -1.0f, 1.0f) : 0.0f;
    // The channels that fade: 255 at t = 0, 0 at |t| = 1; the hue's own channel stays 255.
    auto fade = static_cast<uint8_t>(std::lround(255.0f * (1.0f - std::fabs(t))));
    if (t >= 0.0f) return {255, fade, fade, 255};
    return {fade, fade, 255, 255};
}

std::vector<uint8_t> differenceImage(const GroundTruth& truth, const ErrorRegions& regions,
                                     std::span<const float> visibility, float fullScale) {
    size_t n = truth.pixelCount();
    if (visibility.size() != n || regions.compared.size() != n) {
        throw std::invalid_argument("differenceImage: images of different sizes");
    }
    std::vector<uint8_t> rgba(4 * n);
    for (size_t k = 0; k < n; ++k) {
        glm::u8vec4 c = regions.compared[k]
                            ? signedErrorColour(visibility[k] - truth.visibility[k], fullScale)
                            : DIFFERENCE_BACKGROUND;
        rgba[4 * k + 0] = c.r;
        rgba[4 * k + 1] = c.g;
        rgba[4 * k + 2] = c.b;
        rgba[4 * k + 3] = c.a;
    }
    return rgba;
}

}  // namespace pcf
