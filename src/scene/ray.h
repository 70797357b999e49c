// ray.h: a ray and what it hits, shared by the camera (primary rays) and the ray caster.
#pragma once

#include <glm/glm.hpp>

namespace pcf {

// Points originWs + t * dirWs. dirWs need not be unit, t is in units of its length; the camera
// and the light give unit directions, so t is then a distance in scene units.
struct Ray {
    glm::vec3 originWs{0.0f};
    glm::vec3 dirWs{0.0f, 0.0f, -1.0f};
};

struct Hit {
    float t = 0.0f;
    glm::vec3 posWs{0.0f};
    // The surface's outward unit normal (a plane's own normal), whichever side the ray came from.
    glm::vec3 normalWs{0.0f, 1.0f, 0.0f};
    // Whether the ray met the outside: dot(dirWs, normalWs) < 0. False from inside a sphere or a
    // box, or behind a plane.
    bool frontFace = true;
    // Index into Scene::objects; -1 for a hit on a lone primitive.
    int object = -1;
};

}  // namespace pcf
