#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace pcf {

Aabb sceneBounds(const Scene& scene) {
    Aabb b;
    for (const SceneObject& object : scene.objects) b.extend(bounds(object.shape));
    return b;
}

glm::mat4 lightFromWorld(const Scene& scene) {
    return lightFromWorld(scene.light, sceneBounds(scene));
}

glm::mat4 clipFromLight(const Scene& scene) {
    return clipFromLight(scene.light, sceneBounds(scene));
}

float shadowTexelWs(const Scene& scene, int mapSize) {
    glm::mat4 proj = clipFromLight(scene);
    return 2.0f /
           (std::min(std::fabs(proj[0][0]), std::fabs(proj[1][1])) * static_cast<float>(mapSize));
}

glm::mat4 shadowClipFromWorld(const Scene& scene) {
    Aabb b = sceneBounds(scene);
    return clipFromLight(scene.light, b) * lightFromWorld(scene.light, b);
}

int casterCount(const Scene& scene) {
    int n = 0;
    for (const SceneObject& object : scene.objects) n += object.castsShadow ? 1 : 0;
    return n;
}

int receiverCount(const Scene& scene) {
    int n = 0;
    for (const SceneObject& object : scene.objects) n += object.receivesShadow ? 1 : 0;
    return n;
}

}  // namespace pcf
