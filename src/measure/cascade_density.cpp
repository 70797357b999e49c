#include "measure/cascade_density.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "measure/failure_measures.h"
#include "measure/stability.h"
#include "scene/cascade_fit.h"

namespace pcf {

double largerSingularValue(const glm::mat2& j) {
    double a = 0.0;
    for (int c = 0; c < 2; ++c) {
        for (int r = 0; r < 2; ++r) a += static_cast<double>(j[c][r]) * j[c][r];
    }
    double d = std::abs(static_cast<double>(glm::determinant(j)));
    return std::sqrt(0.5 * (a + std::sqrt(std::max(a * a - 4.0 * d * d, 0.0))));
}

std::vector<CascadeDensity> cascadeDensities(const std::vector<float>& lightSpace,
                                             const std::vector<float>& positions,
                                             glm::ivec2 frameSize, const MapSpec& map,
                                             const Camera& camera) {
    size_t pixels = static_cast<size_t>(frameSize.x) * frameSize.y;
    std::vector<int> layerOf(pixels, -1);
    for (size_t k = 0; k < pixels; ++k) {
        if (lightSpace[4 * k + 3] != 1.0f) continue;
        glm::vec3 p(positions[4 * k], positions[4 * k + 1], positions[4 * k + 2]);
        layerOf[k] = cascadeOfPoint(map, camera, p);
    }
    std::vector<CascadeDensity> out;
    for (int layer = 0; layer < static_cast<int>(map.layers.size()); ++layer) {
        // The frame with only this layer's receivers marked as receivers.
        std::vector<float> only = lightSpace;
        for (size_t k = 0; k < pixels; ++k) {
            if (layerOf[k] != layer) only[4 * k + 3] = 0.0f;
        }
        std::vector<float> areas, sigmas;
        for (const std::optional<glm::mat2>& j : texelJacobians(only, frameSize, map.size.x)) {
            float det = j ? std::abs(glm::determinant(*j)) : 0.0f;
            if (!(det > 0.0f)) continue;
            areas.push_back(det);
            sigmas.push_back(static_cast<float>(largerSingularValue(*j)));
        }
        CascadeDensity d;
        d.pixels = static_cast<int>(areas.size());
        if (!areas.empty()) {
            d.texelsPerPixelMax = quantileOf(areas, 1.0);
            d.texelsPerPixelMedian = quantileOf(areas, 0.5);
            d.singularValueMax = quantileOf(sigmas, 1.0);
            d.singularValueMedian = quantileOf(sigmas, 0.5);
        }
        out.push_back(d);
    }
    return out;
}

}  // namespace pcf
