#include "scene/primitives.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace pcf {

namespace {

template <class... Fs>
struct Overloaded : Fs... {
    using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

}  // namespace

std::optional<Plane> makePlane(glm::vec3 centreWs, glm::vec3 normalWs, glm::vec2 size,
                               std::optional<glm::vec3> tangentWs) {
    glm::dvec3 n(normalWs);
    double len = glm::length(n);
    if (!(len > 0.0)) return std::nullopt;
    n /= len;
    glm::dvec3 ref;
    if (tangentWs) {
        ref = glm::dvec3(*tangentWs);
    } else {
        ref = std::abs(n.x) > 0.999 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(1.0, 0.0, 0.0);
    }
    // Gram-Schmidt: the part of the reference axis that lies in the plane.
    glm::dvec3 u = ref - n * glm::dot(n, ref);
    double uLen = glm::length(u);
    if (!(uLen > 1e-6 * glm::length(ref))) return std::nullopt;
    u /= uLen;
    glm::dvec3 v = glm::cross(n, u);
    Plane plane;
    plane.centreWs = centreWs;
    plane.normalWs = glm::vec3(n);
    plane.halfUWs = glm::vec3(u * (0.5 * size.x));
    plane.halfVWs = glm::vec3(v * (0.5 * size.y));
    return plane;
}

BoxAxes boxAxes(const Box& box) {
    // Every ray against a box asks for these (the ground truth casts millions), and a scene's
    // boxes mostly share one angle: the last angle's cos and sin are kept per thread, so the
    // same angle gives the very same axes without another sincos.
    // Compared bit for bit, so -0 and NaN are angles of their own.
    thread_local uint32_t lastBits = std::bit_cast<uint32_t>(0.0f);
    thread_local double lastCos = 1.0;
    thread_local double lastSin = 0.0;
    if (std::bit_cast<uint32_t>(box.rotateYDeg) != lastBits) {
        // glm::rotate(angle, Y) maps x to (cos, 0, -sin) and z to (sin, 0, cos).
        double a = glm::radians(static_cast<double>(box.rotateYDeg));
        lastCos = std::cos(a);
        lastSin = std::sin(a);
        lastBits = std::bit_cast<uint32_t>(box.rotateYDeg);
    }
    return {glm::dvec3(lastCos, 0.0, -lastSin), glm::dvec3(lastSin, 0.0, lastCos)};
}

glm::vec3 boxWorldFromLocal(const Box& box, glm::vec3 posLocal) {
    BoxAxes ax = boxAxes(box);
    glm::dvec3 p = glm::dvec3(box.centreWs) + ax.xWs * static_cast<double>(posLocal.x) +
                   glm::dvec3(0.0, posLocal.y, 0.0) + ax.zWs * static_cast<double>(posLocal.z);
    return glm::vec3(p);
}

glm::vec3 boxLocalFromWorld(const Box& box, glm::vec3 posWs) {
    BoxAxes ax = boxAxes(box);
    glm::dvec3 d = glm::dvec3(posWs) - glm::dvec3(box.centreWs);
    return glm::vec3(glm::dot(d, ax.xWs), d.y, glm::dot(d, ax.zWs));
}

Aabb bounds(const Primitive& primitive) {
    return std::visit(
        Overloaded{
            [](const Plane& p) {
                glm::vec3 r = glm::abs(p.halfUWs) + glm::abs(p.halfVWs);
                return Aabb{p.centreWs - r, p.centreWs + r};
            },
            [](const Box& b) {
                // The extent of a rotated box along each world axis: sum of |axis_k . e_i| h_k.
                BoxAxes ax = boxAxes(b);
                glm::dvec3 h(b.halfExtents);
                glm::dvec3 r =
                    glm::abs(ax.xWs) * h.x + glm::dvec3(0.0, h.y, 0.0) + glm::abs(ax.zWs) * h.z;
                return Aabb{b.centreWs - glm::vec3(r), b.centreWs + glm::vec3(r)};
            },
            [](const Sphere& s) {
                return Aabb{s.centreWs - glm::vec3(s.radius), s.centreWs + glm::vec3(s.radius)};
            },
        },
        primitive);
}

std::string_view primitiveTypeName(const Primitive& primitive) {
    return std::visit(Overloaded{
                          [](const Plane&) { return std::string_view("plane"); },
                          [](const Box&) { return std::string_view("box"); },
                          [](const Sphere&) { return std::string_view("sphere"); },
                      },
                      primitive);
}

}  // namespace pcf
