#include "measure/ground_truth_edges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <variant>

#include "scene/raycast.h"

namespace pcf {

namespace {

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    // atan2 of |a x b| and a . b: accurate at small angles, where acos of a dot is not.
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

struct Corners {
    std::array<glm::dvec3, 8> p;
    int count;
};

// A box's 8 corners (index bits: x, y, z sign) or a rectangle's 4 (bits: u, v sign).
Corners cornersOf(const Primitive& shape) {
    Corners c{};
    if (const Box* b = std::get_if<Box>(&shape)) {
        BoxAxes ax = boxAxes(*b);
        glm::dvec3 h(b->halfExtents);
        for (int k = 0; k < 8; ++k) {
            glm::dvec3 s((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0);
            c.p[k] = glm::dvec3(b->centreWs) + ax.xWs * (s.x * h.x) +
                     glm::dvec3(0.0, s.y * h.y, 0.0) + ax.zWs * (s.z * h.z);
        }
        c.count = 8;
    } else if (const Plane* q = std::get_if<Plane>(&shape)) {
        for (int k = 0; k < 4; ++k) {
            double su = (k & 1) ? 1.0 : -1.0;
            double sv = (k & 2) ? 1.0 : -1.0;
            c.p[k] =
                glm::dvec3(q->centreWs) + glm::dvec3(q->halfUWs) * su + glm::dvec3(q->halfVWs) * sv;
        }
        c.count = 4;
    } else {
        c.count = 0;
    }
    return c;
}

// The edges of a box (corners differing in one bit) or of a rectangle (its 4 sides).
template <typename F>
void forEachEdge(const Primitive& shape, F f) {
    Corners c = cornersOf(shape);
    int bits = c.count == 8 ? 3 : 2;
    for (int k = 0; k < c.count; ++k) {
        for (int b = 0; b < bits; ++b) {
            int other = k | (1 << b);
            if (other != k) f(c.p[k], c.p[other]);
        }
    }
}

// The angle, seen from the eye, between the direction `axis` and the segment [a, b]: the arc of
// directions toward its points (a great-circle arc), nearest point by projection onto its plane.
double angleToSegment(const glm::dvec3& eye, const glm::dvec3& axis, const glm::dvec3& a,
                      const glm::dvec3& b) {
    glm::dvec3 va = a - eye;
    glm::dvec3 vb = b - eye;
    double endpoints = std::min(angleBetween(axis, va), angleBetween(axis, vb));
    glm::dvec3 n = glm::cross(va, vb);
    double nLen = glm::length(n);
    if (nLen <= 1e-300) return endpoints;
    n /= nLen;
    glm::dvec3 w = axis - n * glm::dot(axis, n);
    // w between va and vb (on the short arc): both turns agree with n.
    if (glm::dot(glm::cross(va, w), n) >= 0.0 && glm::dot(glm::cross(w, vb), n) >= 0.0 &&
        glm::length(w) > 0.0) {
        return std::min(endpoints, std::asin(std::min(1.0, std::abs(glm::dot(axis, n)))));
    }
    return endpoints;
}

// Whether the outline of `shape` (the silhouette circle of a sphere, the edges of a box or a
// rectangle, a superset of their outlines) enters the cone.
bool outlineInCone(const RayCone& cone, const Primitive& shape) {
    if (const Sphere* s = std::get_if<Sphere>(&shape)) {
        glm::dvec3 f = glm::dvec3(s->centreWs) - cone.eye;
        double d = glm::length(f);
        if (d <= static_cast<double>(s->radius)) return true;
        double silhouette = std::asin(static_cast<double>(s->radius) / d);
        return std::abs(angleBetween(cone.axis, f) - silhouette) <= cone.halfAngle;
    }
    bool inside = false;
    forEachEdge(shape, [&](const glm::dvec3& a, const glm::dvec3& b) {
        inside = inside || angleToSegment(cone.eye, cone.axis, a, b) <= cone.halfAngle;
    });
    return inside;
}

// The exact signed distance to a box's surface (negative inside), 1-Lipschitz.
double boxSignedDistance(const Box& box, const glm::dvec3& p) {
    BoxAxes ax = boxAxes(box);
    glm::dvec3 rel = p - glm::dvec3(box.centreWs);
    glm::dvec3 q(std::abs(glm::dot(rel, ax.xWs)), std::abs(rel.y), std::abs(glm::dot(rel, ax.zWs)));
    glm::dvec3 d = q - glm::dvec3(box.halfExtents);
    return glm::length(glm::max(d, 0.0)) + std::min(std::max(d.x, std::max(d.y, d.z)), 0.0);
}

// The distance to a primitive's surface (unsigned), 1-Lipschitz.
double surfaceDistance(const Primitive& shape, const glm::dvec3& p) {
    if (const Sphere* s = std::get_if<Sphere>(&shape)) {
        return std::abs(glm::length(p - glm::dvec3(s->centreWs)) - static_cast<double>(s->radius));
    }
    if (const Box* b = std::get_if<Box>(&shape)) return std::abs(boxSignedDistance(*b, p));
    const Plane& q = std::get<Plane>(shape);
    glm::dvec3 rel = p - glm::dvec3(q.centreWs);
    glm::dvec3 hu(q.halfUWs);
    glm::dvec3 hv(q.halfVWs);
    double lu = glm::length(hu);
    double lv = glm::length(hv);
    double du = std::max(std::abs(glm::dot(rel, hu) / lu) - lu, 0.0);
    double dv = std::max(std::abs(glm::dot(rel, hv) / lv) - lv, 0.0);
    double dn = glm::dot(rel, glm::dvec3(q.normalWs));
    return std::sqrt(du * du + dv * dv + dn * dn);
}

double cross2(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

}  // namespace

std::vector<glm::dvec2> convexHull2d(std::vector<glm::dvec2> pts) {
    std::sort(pts.begin(), pts.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    if (pts.size() < 3) return pts;
    std::vector<glm::dvec2> hull(2 * pts.size());
    size_t k = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross2(hull[k - 2], hull[k - 1], pts[i]) <= 0.0) --k;
        hull[k++] = pts[i];
    }
    for (size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross2(hull[k - 2], hull[k - 1], pts[i - 1]) <= 0.0) --k;
        hull[k++] = pts[i - 1];
    }
    hull.resize(k - 1);
    return hull;
}

std::vector<std::array<glm::dvec3, 2>> primitiveEdges(const Primitive& shape) {
    std::vector<std::array<glm::dvec3, 2>> edges;
    forEachEdge(shape, [&](const glm::dvec3& a, const glm::dvec3& b) { edges.push_back({a, b}); });
    return edges;
}

namespace {

double segmentDistance(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    glm::dvec2 ab = b - a;
    double len2 = glm::dot(ab, ab);
    double s = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + s * ab));
}

// The signed distance from p to a convex counter-clockwise polygon's boundary (negative
// inside), exact and so 1-Lipschitz; a degenerate hull (a segment, a point) has no inside.
double hullSignedDistance(const glm::dvec2& p, const std::vector<glm::dvec2>& hull) {
    size_t n = hull.size();
    if (n == 0) return std::numeric_limits<double>::infinity();
    if (n == 1) return glm::length(p - hull[0]);
    double outside = std::numeric_limits<double>::infinity();
    double inside = -std::numeric_limits<double>::infinity();
    bool in = n >= 3;
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec2& a = hull[i];
        const glm::dvec2& b = hull[(i + 1) % n];
        outside = std::min(outside, segmentDistance(p, a, b));
        if (n >= 3) {
            glm::dvec2 e = b - a;
            double line = -cross2(a, b, p) / glm::length(e);  // > 0 right of a->b: outside
            in = in && line <= 0.0;
            inside = std::max(inside, line);
        }
    }
    return in ? inside : outside;
}

}  // namespace

EdgeFinder::EdgeFinder(const Scene& scene) : mScene(scene) {
    mTravel = glm::normalize(glm::dvec3(scene.light.directionWs));
    glm::dvec3 helper = std::abs(mTravel.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    mBasisU = glm::normalize(glm::cross(mTravel, helper));
    mBasisV = glm::cross(mTravel, mBasisU);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (!scene.objects[i].castsShadow) continue;
        Caster c{static_cast<int>(i), {}};
        Corners corners = cornersOf(scene.objects[i].shape);
        std::vector<glm::dvec2> projected;
        for (int k = 0; k < corners.count; ++k) {
            projected.push_back({glm::dot(corners.p[k], mBasisU), glm::dot(corners.p[k], mBasisV)});
        }
        c.hull = convexHull2d(std::move(projected));
        mCasters.push_back(std::move(c));
    }
}

namespace {

// The ball around the points at t in [t0, t1] along the cone's rays (top of ground_truth_edges.h).
Footprint ballFor(const RayCone& cone, double t0, double t1) {
    double tc = 0.5 * (t0 + t1);
    double c = std::cos(cone.halfAngle);
    double r0 = std::sqrt(std::max(0.0, t0 * t0 + tc * tc - 2.0 * t0 * tc * c));
    double r1 = std::sqrt(std::max(0.0, t1 * t1 + tc * tc - 2.0 * t1 * tc * c));
    // A margin for rounding: 1e-9 of the distances involved.
    double slack = 1e-9 * (t1 + glm::length(cone.eye) + 1.0);
    return {cone.eye + cone.axis * tc, std::max(r0, r1) + slack, true};
}

constexpr Footprint UNBOUNDED{glm::dvec3(0.0), 0.0, false};
constexpr Footprint EMPTY{glm::dvec3(0.0), -1.0, true};  // radius < 0: no point at all

// Rays of the cone on the plane through `point` with normal `n`: t = h / (n . d), h the eye's
// distance to the plane, n . d between cos(beta + alpha) and cos(max(beta - alpha, 0)).
Footprint planeFootprint(const RayCone& cone, const glm::dvec3& point, glm::dvec3 n) {
    double h = glm::dot(n, point - cone.eye);
    if (h < 0.0) {
        n = -n;
        h = -h;
    }
    if (h <= 0.0) return UNBOUNDED;
    double beta = angleBetween(cone.axis, n);
    constexpr double HALF_PI = 0.5 * std::numbers::pi;
    if (beta - cone.halfAngle >= HALF_PI) return EMPTY;
    // 1e-6 rad short of parallel: beyond it the rays run off too far to bound usefully.
    if (beta + cone.halfAngle >= HALF_PI - 1e-6) return UNBOUNDED;
    double t0 = h / std::cos(std::max(beta - cone.halfAngle, 0.0));
    double t1 = h / std::cos(beta + cone.halfAngle);
    return ballFor(cone, t0, t1);
}

// Front hits on a sphere of a ray at angle phi from the centre's direction (distance D):
// t(phi) = D cos(phi) - sqrt(r^2 - D^2 sin^2(phi)), growing with phi up to the silhouette.
Footprint sphereFootprint(const RayCone& cone, const Sphere& s) {
    glm::dvec3 f = glm::dvec3(s.centreWs) - cone.eye;
    double d = glm::length(f);
    double r = s.radius;
    if (d <= r) return UNBOUNDED;
    double silhouette = std::asin(r / d);
    double gamma = angleBetween(cone.axis, f);
    if (gamma - cone.halfAngle > silhouette) return EMPTY;
    auto t = [&](double phi) {
        double sn = d * std::sin(phi);
        return d * std::cos(phi) - std::sqrt(std::max(0.0, r * r - sn * sn));
    };
    return ballFor(cone, t(std::max(gamma - cone.halfAngle, 0.0)),
                   t(std::min(gamma + cone.halfAngle, silhouette)));
}

}  // namespace

Footprint EdgeFinder::footprint(const RayCone& cone, int object) const {
    const Primitive& shape = mScene.objects[static_cast<size_t>(object)].shape;
    if (const Sphere* s = std::get_if<Sphere>(&shape)) return sphereFootprint(cone, *s);
    if (const Plane* p = std::get_if<Plane>(&shape)) {
        return planeFootprint(cone, glm::dvec3(p->centreWs), glm::dvec3(p->normalWs));
    }
    // A box: with no edge in the cone, every ray of it that meets the box meets one face, the
    // face the axis meets (or none).
    if (outlineInCone(cone, shape)) return UNBOUNDED;
    std::optional<Hit> hit = intersect(shape, Ray{glm::vec3(cone.eye), glm::vec3(cone.axis)});
    if (!hit) return EMPTY;
    return planeFootprint(cone, glm::dvec3(hit->posWs), glm::dvec3(hit->normalWs));
}

// The signed distance of f.centre to the side of the caster's shadow prism (along L), > 0 out.
double EdgeFinder::across(const Footprint& f, const Caster& caster) const {
    const Primitive& shape = mScene.objects[static_cast<size_t>(caster.object)].shape;
    if (const Sphere* s = std::get_if<Sphere>(&shape)) {
        glm::dvec3 d = f.centre - glm::dvec3(s->centreWs);
        return glm::length(d - mTravel * glm::dot(d, mTravel)) - static_cast<double>(s->radius);
    }
    glm::dvec2 p(glm::dot(f.centre, mBasisU), glm::dot(f.centre, mBasisV));
    return hullSignedDistance(p, caster.hull);
}

bool EdgeFinder::shadowEdgeNear(const Footprint& f, const Caster& caster) const {
    const Primitive& shape = mScene.objects[static_cast<size_t>(caster.object)].shape;
    double side = across(f, caster);
    if (side > f.radius) return false;  // wholly outside the prism: no shadow of it
    // Inside the prism, upstream and downstream of the caster are split by its surface.
    return !(side < -f.radius && surfaceDistance(shape, f.centre) > f.radius);
}

int EdgeFinder::areaHorizon(const RayCone& cone, const Footprint& f, int object,
                            double sinHalf) const {
    const Primitive& shape = mScene.objects[static_cast<size_t>(object)].shape;
    glm::dvec3 toLight = -mTravel;
    if (const Sphere* s = std::get_if<Sphere>(&shape)) {
        // (p - c) . toLight = r (n . toLight) on the sphere, 1-Lipschitz in p.
        double h = glm::dot(f.centre - glm::dvec3(s->centreWs), toLight);
        double margin = f.radius + static_cast<double>(s->radius) * sinHalf;
        return h > margin ? 1 : h < -margin ? 0 : -1;
    }
    // A plane or one box face (the footprint has ruled out a box's edges): one normal, turned
    // toward the eye.
    glm::dvec3 n;
    if (const Plane* p = std::get_if<Plane>(&shape)) {
        n = glm::dvec3(p->normalWs);
        if (glm::dot(n, cone.eye - glm::dvec3(p->centreWs)) < 0.0) n = -n;
    } else {
        std::optional<Hit> hit = intersect(shape, Ray{glm::vec3(cone.eye), glm::vec3(cone.axis)});
        if (!hit) return -1;
        n = glm::dvec3(hit->normalWs);
    }
    double x = glm::dot(n, toLight);
    return x > sinHalf * (1.0 + 1e-9) ? 1 : x < -sinHalf * (1.0 + 1e-9) ? 0 : -1;
}

int EdgeFinder::areaSpotState(const RayCone& cone, int object) const {
    const SceneObject& obj = mScene.objects[static_cast<size_t>(object)];
    const Light& light = mScene.light;
    Footprint f = footprint(cone, object);
    if (!f.bounded) return -1;
    if (f.radius < 0.0) return 1;  // the cone does not meet the object
    glm::dvec3 centre(light.positionWs);
    glm::dvec3 axis = glm::normalize(glm::dvec3(light.directionWs));
    double radius = light.radius;
    glm::dvec3 toBall = f.centre - centre;
    double dist = glm::length(toBall);
    if (dist <= f.radius) return -1;
    double spread = angleBetween(toBall, axis) + std::asin(f.radius / dist);
    if (!(spread < glm::radians(static_cast<double>(light.coneDeg)))) return -1;
    const Primitive& shape = obj.shape;
    glm::dvec3 n;
    if (const Plane* p = std::get_if<Plane>(&shape)) {
        n = glm::dvec3(p->normalWs);
        if (glm::dot(n, cone.eye - glm::dvec3(p->centreWs)) < 0.0) n = -n;
    } else if (std::holds_alternative<Box>(shape)) {
        std::optional<Hit> hit = intersect(shape, Ray{glm::vec3(cone.eye), glm::vec3(cone.axis)});
        if (!hit) return -1;
        n = glm::dvec3(hit->normalWs);
    } else {
        return -1;  // a sphere's normal turns within the ball
    }
    double na = glm::dot(n, axis);
    double lowest =
        glm::dot(n, centre - f.centre) - radius * std::sqrt(std::max(0.0, 1.0 - na * na));
    if (!(lowest > f.radius * (1.0 + 1e-9))) return -1;
    if (!obj.receivesShadow) return 1;
    double reach = std::max(f.radius, radius) * (1.0 + 1e-9);
    glm::dvec3 seg = centre - f.centre;
    double segLength2 = glm::dot(seg, seg);
    for (const Caster& c : mCasters) {
        if (c.object == object) continue;
        const Primitive& casterShape = mScene.objects[static_cast<size_t>(c.object)].shape;
        glm::dvec3 q;
        double s;
        if (const Sphere* sp = std::get_if<Sphere>(&casterShape)) {
            q = glm::dvec3(sp->centreWs);
            s = sp->radius;
        } else {
            Aabb box = bounds(casterShape);
            q = glm::dvec3(box.centreWs());
            s = 0.5 * glm::length(glm::dvec3(box.extentWs()));
        }
        double t = std::clamp(glm::dot(q - f.centre, seg) / segLength2, 0.0, 1.0);
        if (glm::length(q - (f.centre + seg * t)) <= s + reach) return -1;
    }
    return 1;
}

int EdgeFinder::areaState(const RayCone& cone, int object, double tanHalf) const {
    const SceneObject& obj = mScene.objects[static_cast<size_t>(object)];
    if (mScene.light.type != LightType::Directional) return areaSpotState(cone, object);
    Footprint f = footprint(cone, object);
    if (!f.bounded) return -1;
    if (f.radius < 0.0) return 1;  // the cone does not meet the object
    int state = areaHorizon(cone, f, object, tanHalf / std::sqrt(1.0 + tanHalf * tanHalf));
    if (state == 0 || !obj.receivesShadow) return state;
    glm::dvec3 toLight = -mTravel;
    for (const Caster& c : mCasters) {
        if (c.object == object) continue;
        const Primitive& shape = mScene.objects[static_cast<size_t>(c.object)].shape;
        // The caster's farthest reach along toLight from f.centre.
        double reach = -std::numeric_limits<double>::infinity();
        if (const Sphere* s = std::get_if<Sphere>(&shape)) {
            reach = glm::dot(glm::dvec3(s->centreWs) - f.centre, toLight) + s->radius;
        } else {
            Corners corners = cornersOf(shape);
            for (int k = 0; k < corners.count; ++k) {
                reach = std::max(reach, glm::dot(corners.p[k] - f.centre, toLight));
            }
        }
        // Rays toward the light only move toward it: a caster wholly behind the ball is never met.
        if (reach < -f.radius) continue;
        double grow = f.radius + (std::max(reach, 0.0) + f.radius) * tanHalf * (1.0 + 1e-9);
        double side = across(f, c);
        if (side > grow) continue;  // no ray toward the disk meets it
        bool downstream =
            intersect(shape, Ray{glm::vec3(f.centre), glm::vec3(toLight)}).has_value();
        if (side < -grow && downstream && surfaceDistance(shape, f.centre) > f.radius) {
            return 0;  // the umbra
        }
        state = -1;
    }
    return state;
}

bool EdgeFinder::spotShadowEdgeNear(const Footprint& f, const Caster& caster) const {
    const Primitive& shape = mScene.objects[static_cast<size_t>(caster.object)].shape;
    glm::dvec3 light(mScene.light.positionWs);
    Aabb box = bounds(shape);
    glm::dvec3 centre(box.centreWs());
    double radius = 0.5 * glm::length(glm::dvec3(box.extentWs()));
    if (const Sphere* s = std::get_if<Sphere>(&shape)) {
        centre = glm::dvec3(s->centreWs);
        radius = s->radius;
    }
    glm::dvec3 v = centre - light;
    double dc = glm::length(v);
    double dm = glm::length(f.centre - light);
    if (dc <= radius || dm <= f.radius) return true;
    double gamma = std::asin(radius / dc);
    double beta = std::asin(f.radius / dm);
    double theta = angleBetween(f.centre - light, v);
    if (theta > gamma + beta) return false;  // outside the caster's shadow cone
    // Inside a sphere's cone, upstream and downstream are split by its surface; a box's or a
    // rectangle's cone is not followed further here: a pixel in it is refined (safe, only
    // slower; post-under-spot's post is such a box).
    bool sphere = std::holds_alternative<Sphere>(shape);
    return !(sphere && theta < gamma - beta && surfaceDistance(shape, f.centre) > f.radius);
}

bool EdgeFinder::litMayChange(const RayCone& cone, int object) const {
    const SceneObject& obj = mScene.objects[static_cast<size_t>(object)];
    Footprint f = footprint(cone, object);
    if (!f.bounded) return true;
    if (f.radius < 0.0) return false;  // the cone does not meet the object
    const Light& light = mScene.light;
    const Sphere* sphere = std::get_if<Sphere>(&obj.shape);
    if (light.type == LightType::Directional) {
        if (sphere &&
            std::abs(glm::dot(f.centre - glm::dvec3(sphere->centreWs), mTravel)) <= f.radius) {
            return true;  // the terminator
        }
        if (!obj.receivesShadow) return false;
        for (const Caster& c : mCasters) {
            if (c.object != object && shadowEdgeNear(f, c)) return true;
        }
        return false;
    }
    glm::dvec3 l(light.positionWs);
    double dm = glm::length(f.centre - l);
    if (dm <= f.radius) return true;
    double beta = std::asin(f.radius / dm);
    double rim = glm::radians(static_cast<double>(light.coneDeg));
    if (std::abs(angleBetween(f.centre - l, mTravel) - rim) <= beta) return true;
    if (sphere) {
        glm::dvec3 c(sphere->centreWs);
        double r = sphere->radius;
        if (std::abs(glm::dot(f.centre - c, l - c) - r * r) <= glm::length(l - c) * f.radius) {
            return true;  // the terminator
        }
    }
    if (!obj.receivesShadow) return false;
    for (const Caster& c : mCasters) {
        if (c.object != object && spotShadowEdgeNear(f, c)) return true;
    }
    return false;
}

}  // namespace pcf
