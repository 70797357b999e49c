#include "measure/cascade_density.h"

#include "measure/failure_measures.h"
#include "measure/stability.h"
#include "scene/cascade_fit.h"

namespace pcf {

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
        std::vector<float> texelsPerPixel;
        for (float ppt : pixelsPerTexel(only, frameSize, map.size.x)) {
            if (ppt > 0.0f) texelsPerPixel.push_back(1.0f / ppt);
        }
        CascadeDensity d;
        d.pixels = static_cast<int>(texelsPerPixel.size());
        if (!texelsPerPixel.empty()) {
            d.texelsPerPixelMax = quantileOf(texelsPerPixel, 1.0);
            d.texelsPerPixelMedian = quantileOf(texelsPerPixel, 0.5);
        }
        out.push_back(d);
    }
    return out;
}

}  // namespace pcf
