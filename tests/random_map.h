// random_map.h: the random shadow map the kernel tests share: uniform random depths in [0,1], so
// random receivers see edges, corners and single texels.
#pragma once

#include <cstdint>
#include <random>

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

}  // namespace pcf
