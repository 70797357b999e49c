#include "scene/raycast.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace pcf {

namespace {

// The double-precision core: a ray, and what a primitive reports back.
struct RayD {
    glm::dvec3 o;
    glm::dvec3 d;
};

struct HitD {
    double t;
    glm::dvec3 pos;
    glm::dvec3 normal;
    bool front;
};

RayD toDouble(const Ray& ray) { return {glm::dvec3(ray.originWs), glm::dvec3(ray.dirWs)}; }

Hit toHit(const HitD& h, int object) {
    return Hit{static_cast<float>(h.t), glm::vec3(h.pos), glm::vec3(h.normal), h.front, object};
}

// Ray / finite rectangle: t = n.(c - o) / n.d, then the hit's coordinates along the half axes
// a = (p - c).halfU / |halfU|^2, b likewise, inside when |a| <= 1 and |b| <= 1.
std::optional<HitD> hitPlane(const Plane& plane, const RayD& ray, double tMin, double tMax) {
    glm::dvec3 n(plane.normalWs);
    glm::dvec3 c(plane.centreWs);
    double denom = glm::dot(n, ray.d);
    if (std::abs(denom) <= 1e-12 * glm::length(ray.d)) return std::nullopt;
    double t = glm::dot(n, c - ray.o) / denom;
    if (!(t > tMin && t < tMax)) return std::nullopt;
    glm::dvec3 p = ray.o + t * ray.d;
    glm::dvec3 local = p - c;
    glm::dvec3 u(plane.halfUWs);
    glm::dvec3 v(plane.halfVWs);
    double a = glm::dot(local, u) / glm::dot(u, u);
    double b = glm::dot(local, v) / glm::dot(v, v);
    if (std::abs(a) > 1.0 || std::abs(b) > 1.0) return std::nullopt;
    p -= n * glm::dot(n, local);  // onto the plane
    return HitD{t, p, n, denom < 0.0};
}

// Ray / box, the slab method (Kay and Kajiya 1986; Williams et al. 2005) in the box's local
// frame: per axis the ray is inside the slab |x_i| <= h_i for t between (-h_i - o_i) / d_i and
// (h_i - o_i) / d_i; the box is the intersection of the three intervals [tEnter, tExit].
std::optional<HitD> hitBox(const Box& box, const RayD& ray, double tMin, double tMax) {
    BoxAxes ax = boxAxes(box);
    const glm::dvec3 axes[3] = {ax.xWs, glm::dvec3(0.0, 1.0, 0.0), ax.zWs};
    glm::dvec3 rel = ray.o - glm::dvec3(box.centreWs);
    glm::dvec3 h(box.halfExtents);
    double tEnter = -std::numeric_limits<double>::infinity();
    double tExit = std::numeric_limits<double>::infinity();
    int enterAxis = -1;
    int exitAxis = -1;
    double enterSign = 0.0;
    double exitSign = 0.0;
    for (int i = 0; i < 3; ++i) {
        double o = glm::dot(rel, axes[i]);
        double d = glm::dot(ray.d, axes[i]);
        if (d == 0.0) {
            // Parallel to the slab: inside it for every t, or never (boundary counts as inside).
            if (o < -h[i] || o > h[i]) return std::nullopt;
            continue;
        }
        double t0 = (-h[i] - o) / d;
        double t1 = (h[i] - o) / d;
        // Entering through the face the ray meets first: the -h face when d > 0.
        double sign = d > 0.0 ? -1.0 : 1.0;
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > tEnter) {
            tEnter = t0;
            enterAxis = i;
            enterSign = sign;
        }
        if (t1 < tExit) {
            tExit = t1;
            exitAxis = i;
            exitSign = -sign;
        }
    }
    if (tEnter > tExit || enterAxis < 0) return std::nullopt;
    int axis;
    double sign;
    double t;
    bool front;
    if (tEnter > tMin && tEnter < tMax) {
        t = tEnter;
        axis = enterAxis;
        sign = enterSign;
        front = true;
    } else if (tExit > tMin && tExit < tMax) {
        t = tExit;
        axis = exitAxis;
        sign = exitSign;
        front = false;
    } else {
        return std::nullopt;
    }
    glm::dvec3 n = axes[axis] * sign;
    glm::dvec3 p = ray.o + t * ray.d;
    // Onto the face: its local coordinate along the axis is exactly sign * h.
    double along = glm::dot(p - glm::dvec3(box.centreWs), axes[axis]);
    p += axes[axis] * (sign * h[axis] - along);
    return HitD{t, p, n, front};
}

// Ray / sphere with the numerically stable quadratic of Haines, Guenther and Akenine-Moller,
// "Precision Improvements for Ray/Sphere Intersection" (Ray Tracing Gems, 2019, ch. 7):
//   f = o - c, a = d.d, b' = -f.d, c = f.f - r^2
//   discriminant a * (r^2 - |f + (b'/a) d|^2)  (the distance of the centre from the line, which
//   avoids b'^2 - a c cancelling for far origins)
//   q = b' + sign(b') sqrt(disc), roots c / q and q / a (no subtraction of near-equal values).
std::optional<HitD> hitSphere(const Sphere& sphere, const RayD& ray, double tMin, double tMax) {
    glm::dvec3 centre(sphere.centreWs);
    double r = sphere.radius;
    glm::dvec3 f = ray.o - centre;
    double a = glm::dot(ray.d, ray.d);
    double bq = -glm::dot(f, ray.d);
    glm::dvec3 l = f + (bq / a) * ray.d;
    double disc = a * (r * r - glm::dot(l, l));
    if (disc < 0.0) return std::nullopt;
    double c = glm::dot(f, f) - r * r;
    double q = bq + std::copysign(std::sqrt(disc), bq);
    double t0;
    double t1;
    if (q == 0.0) {
        t0 = t1 = bq / a;  // tangent with the closest point at the origin
    } else {
        t0 = c / q;
        t1 = q / a;
    }
    if (t0 > t1) std::swap(t0, t1);
    double t;
    if (t0 > tMin && t0 < tMax) {
        t = t0;
    } else if (t1 > tMin && t1 < tMax) {
        t = t1;
    } else {
        return std::nullopt;
    }
    glm::dvec3 n = glm::normalize(ray.o + t * ray.d - centre);
    return HitD{t, centre + r * n, n, glm::dot(n, ray.d) < 0.0};
}

std::optional<HitD> hitPrimitive(const Primitive& primitive, const RayD& ray, double tMin,
                                 double tMax) {
    if (const Plane* p = std::get_if<Plane>(&primitive)) return hitPlane(*p, ray, tMin, tMax);
    if (const Box* b = std::get_if<Box>(&primitive)) return hitBox(*b, ray, tMin, tMax);
    return hitSphere(std::get<Sphere>(primitive), ray, tMin, tMax);
}

std::optional<Hit> wrap(const std::optional<HitD>& h) {
    if (!h) return std::nullopt;
    return toHit(*h, -1);
}

}  // namespace

std::optional<Hit> intersect(const Plane& plane, const Ray& ray, float tMin, float tMax) {
    return wrap(hitPlane(plane, toDouble(ray), tMin, tMax));
}

std::optional<Hit> intersect(const Box& box, const Ray& ray, float tMin, float tMax) {
    return wrap(hitBox(box, toDouble(ray), tMin, tMax));
}

std::optional<Hit> intersect(const Sphere& sphere, const Ray& ray, float tMin, float tMax) {
    return wrap(hitSphere(sphere, toDouble(ray), tMin, tMax));
}

std::optional<Hit> intersect(const Primitive& primitive, const Ray& ray, float tMin, float tMax) {
    return wrap(hitPrimitive(primitive, toDouble(ray), tMin, tMax));
}

std::optional<Hit> intersect(const Scene& scene, const Ray& ray, float tMin, float tMax) {
    RayD rayD = toDouble(ray);
    double tBest = tMax;
    std::optional<HitD> best;
    int bestObject = -1;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        std::optional<HitD> h = hitPrimitive(scene.objects[i].shape, rayD, tMin, tBest);
        if (h) {
            best = h;
            tBest = h->t;
            bestObject = static_cast<int>(i);
        }
    }
    if (!best) return std::nullopt;
    return toHit(*best, bestObject);
}

float shadowRayTMin(glm::vec3 originWs, glm::vec3 dirWs) {
    glm::vec3 a = glm::abs(originWs);
    float scale = std::max({1.0f, a.x, a.y, a.z});
    return SHADOW_RAY_EPSILON * scale / glm::length(dirWs);
}

bool occluded(const Scene& scene, glm::vec3 originWs, glm::vec3 dirWs, float maxT, int skipObject) {
    RayD ray{glm::dvec3(originWs), glm::dvec3(dirWs)};
    double tMin = shadowRayTMin(originWs, dirWs);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (static_cast<int>(i) == skipObject || !scene.objects[i].castsShadow) continue;
        if (hitPrimitive(scene.objects[i].shape, ray, tMin, maxT)) return true;
    }
    return false;
}

bool litByLight(const Scene& scene, const Hit& hit) {
    LightSample toLight = towardLight(scene.light, hit.posWs);
    if (!toLight.insideCone) return false;
    glm::vec3 facing = hit.frontFace ? hit.normalWs : -hit.normalWs;
    if (glm::dot(facing, toLight.dirWs) <= 0.0f) return false;
    if (hit.object < 0 || hit.object >= static_cast<int>(scene.objects.size())) {
        return !occluded(scene, hit.posWs, toLight.dirWs, toLight.distance);
    }
    if (!scene.objects[hit.object].receivesShadow) return true;
    return !occluded(scene, hit.posWs, toLight.dirWs, toLight.distance, hit.object);
}

}  // namespace pcf
