#include "kernel/shadow_map.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace pcf {

ShadowMap::ShadowMap(int width, int height, float fill)
    : mSize(width, height), mDepths(static_cast<size_t>(width) * height, fill) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("shadow map size must be positive");
}

ShadowMap::ShadowMap(int width, int height, std::vector<float> depths)
    : mSize(width, height), mDepths(std::move(depths)) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("shadow map size must be positive");
    if (mDepths.size() != static_cast<size_t>(width) * height) {
        throw std::invalid_argument("shadow map holds a wrong number of depths");
    }
}

std::optional<std::string> ShadowMap::findInvalidTexel() const {
    for (int j = 0; j < mSize.y; ++j) {
        for (int i = 0; i < mSize.x; ++i) {
            float d = depth(i, j);
            std::ostringstream s;
            s << "texel (" << i << ", " << j << ") ";
            if (std::isnan(d)) return s.str() + "is NaN";
            if (std::isinf(d)) return s.str() + "is infinite";
            if (d < 0.0f || d > 1.0f) {
                s << "has depth " << d << ", outside [0, 1]";
                return s.str();
            }
        }
    }
    return std::nullopt;
}

ShadowMap exampleShadowMap() {
    ShadowMap map(8, 8);
    for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
            bool occluder = i >= 4 && j >= 2;
            float ground = 0.55f + 0.01f * static_cast<float>(j);
            float caster = 0.30f + 0.01f * static_cast<float>(j - 2);
            map.setDepth(i, j, occluder ? caster : ground);
        }
    }
    return map;
}

}  // namespace pcf
