// aabb.h: an axis-aligned bounding box in world space, what the light's and the camera's
// frusta are fitted to.
#pragma once

#include <glm/glm.hpp>
#include <limits>

namespace pcf {

// Empty until the first point is added (min > max). A plane gives a box of zero thickness.
struct Aabb {
    glm::vec3 minWs{std::numeric_limits<float>::infinity()};
    glm::vec3 maxWs{-std::numeric_limits<float>::infinity()};

    bool empty() const { return minWs.x > maxWs.x || minWs.y > maxWs.y || minWs.z > maxWs.z; }
    void extend(glm::vec3 posWs) {
        minWs = glm::min(minWs, posWs);
        maxWs = glm::max(maxWs, posWs);
    }
    void extend(const Aabb& other) {
        minWs = glm::min(minWs, other.minWs);
        maxWs = glm::max(maxWs, other.maxWs);
    }
    glm::vec3 centreWs() const { return 0.5f * (minWs + maxWs); }
    glm::vec3 extentWs() const { return maxWs - minWs; }
    // Corner k = 0..7: bit 0 picks max x, bit 1 max y, bit 2 max z.
    glm::vec3 cornerWs(int k) const {
        return glm::vec3((k & 1) ? maxWs.x : minWs.x, (k & 2) ? maxWs.y : minWs.y,
                         (k & 4) ? maxWs.z : minWs.z);
    }
    bool contains(glm::vec3 posWs, float tolerance = 0.0f) const {
        return glm::all(glm::greaterThanEqual(posWs, minWs - tolerance)) &&
               glm::all(glm::lessThanEqual(posWs, maxWs + tolerance));
    }
};

}  // namespace pcf
