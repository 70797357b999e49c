// random_map.h: the random shadow map the kernel tests share: uniform random depths in [0,1], so
// random receivers see edges, corners and single texels; and the random lookups the GPU tests run
// on it.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <random>
#include <vector>

#include "kernel/shadow_map.h"

namespace pcf {

inline ShadowMap randomMap(int w, int h, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    ShadowMap map(w, h);
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) map.setDepth(i, j, u(rng));
    }
    return map;
}

// width x rows lookups (u, v, ref, 0) on a map of mapSize: u and v a little past [0, 1] (the
// clamp to the edge), ref in [0, 1]; the first 64 (or all, when fewer) on texel centres and
// edges, where floor() decides.
inline std::vector<glm::vec4> randomLookups(glm::ivec2 mapSize, int width, int rows,
                                            uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_real_distribution<float> around(-0.03f, 1.03f);
    std::vector<glm::vec4> lookups(static_cast<size_t>(width) * rows);
    for (glm::vec4& l : lookups) {
        float u = around(rng);
        float v = around(rng);
        l = glm::vec4(u, v, unit(rng), 0.0f);
    }
    for (int k = 0; k < 64 && k < static_cast<int>(lookups.size()); ++k) {
        lookups[k].x = (k % mapSize.x + 0.5f * (k % 3)) / mapSize.x;
        lookups[k].y = (k % mapSize.y + 0.5f * (k % 2)) / mapSize.y;
    }
    return lookups;
}

}  // namespace pcf
