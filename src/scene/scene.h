// scene.h: a scene is a camera, a light and a list of named, coloured analytic objects. The
// renderer draws it (mesh.h), the ray caster gives its exact shadows (raycast.h), scene files and
// presets describe it (scene_file.h, presets.h).
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "scene/aabb.h"
#include "scene/camera.h"
#include "scene/light.h"
#include "scene/primitives.h"

namespace pcf {

struct SceneObject {
    std::string name;
    Primitive shape;
    glm::vec3 colour{0.8f};   // linear albedo, each channel in [0,1]
    bool castsShadow = true;  // drawn into the shadow map, blocks shadow rays
    bool receivesShadow =
        true;  // looks the shadow map up (else always lit where it faces the light)
};

struct Scene {
    std::string name;
    Camera camera;
    Light light;
    std::vector<SceneObject> objects;
};

// Union of the objects' bounds (all of them, casters or not): what the light's frustum and the
// camera's clip planes are fitted to.
Aabb sceneBounds(const Scene& scene);

// The shadow pass's matrices for this scene (light.h): clipFromLight * lightFromWorld maps the
// whole scene into GL clip space.
glm::mat4 lightFromWorld(const Scene& scene);
glm::mat4 clipFromLight(const Scene& scene);
glm::mat4 shadowClipFromWorld(const Scene& scene);
// One shadow-map texel's world size at clip.w = 1 for a map of mapSize texels: 2 / (P00 * size)
// across x, likewise y, the larger of the two (ortho: w = 1; perspective: the shader scales it by
// w). What normal offset's distance is measured in (pcfNormalOffsetDistance).
float shadowTexelWs(const Scene& scene, int mapSize);

int casterCount(const Scene& scene);
int receiverCount(const Scene& scene);

}  // namespace pcf
