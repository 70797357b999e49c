#include "scene/mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

namespace pcf {

void Mesh::append(const Mesh& other) {
    auto base = static_cast<std::uint32_t>(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    indices.reserve(indices.size() + other.indices.size());
    for (std::uint32_t i : other.indices) indices.push_back(base + i);
}

namespace {

// A quad a, b, c, d counter-clockwise seen from its front, all with one normal.
void addQuad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n) {
    auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    for (glm::vec3 p : {a, b, c, d}) mesh.vertices.push_back({p, n});
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
}

}  // namespace

Mesh tessellate(const Plane& plane) {
    // cross(halfU, halfV) points along the normal, so -U-V, +U-V, +U+V, -U+V turns
    // counter-clockwise seen from the front.
    glm::vec3 c = plane.centreWs;
    glm::vec3 u = plane.halfUWs;
    glm::vec3 v = plane.halfVWs;
    Mesh mesh;
    addQuad(mesh, c - u - v, c + u - v, c + u + v, c - u + v, glm::normalize(plane.normalWs));
    return mesh;
}

Mesh tessellate(const Box& box) {
    Mesh mesh;
    mesh.vertices.reserve(24);
    mesh.indices.reserve(36);
    BoxAxes ax = boxAxes(box);
    const glm::vec3 axes[3] = {glm::vec3(ax.xWs), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(ax.zWs)};
    // Each face: the outward axis k with sign s, and two in-face axes (i, j) with
    // cross(axis_i, axis_j) = s * axis_k, so corners -i-j, +i-j, +i+j, -i+j are counter-clockwise
    // seen from outside. The local frame is right-handed: x cross y = z, y cross z = x,
    // z cross x = y.
    for (int k = 0; k < 3; ++k) {
        for (float s : {1.0f, -1.0f}) {
            int i = (k + 1) % 3;
            int j = (k + 2) % 3;
            if (s < 0.0f) std::swap(i, j);
            glm::vec3 c = box.centreWs + axes[k] * (s * box.halfExtents[k]);
            glm::vec3 di = axes[i] * box.halfExtents[i];
            glm::vec3 dj = axes[j] * box.halfExtents[j];
            addQuad(mesh, c - di - dj, c + di - dj, c + di + dj, c - di + dj, axes[k] * s);
        }
    }
    return mesh;
}

Mesh tessellate(const Sphere& sphere, const TessellationOptions& options) {
    int slices = std::max(options.sphereSlices, 3);
    int stacks = std::max(options.sphereStacks, 2);
    Mesh mesh;
    mesh.vertices.reserve(static_cast<size_t>(slices + 1) * (stacks + 1));
    // Vertex (i, j): longitude phi = 2 pi i / slices, colatitude theta = pi j / stacks (j = 0 at
    // the north pole, +Y). n = (sin theta sin phi, cos theta, sin theta cos phi): phi turns
    // from +Z toward +X, counter-clockwise seen from above.
    for (int j = 0; j <= stacks; ++j) {
        double theta = std::numbers::pi * j / stacks;
        for (int i = 0; i <= slices; ++i) {
            double phi = 2.0 * std::numbers::pi * (i % slices) / slices;
            glm::dvec3 n(std::sin(theta) * std::sin(phi), std::cos(theta),
                         std::sin(theta) * std::cos(phi));
            if (j == 0 || j == stacks) n = glm::dvec3(0.0, j == 0 ? 1.0 : -1.0, 0.0);
            mesh.vertices.push_back({sphere.centreWs + glm::vec3(n) * sphere.radius, glm::vec3(n)});
        }
    }
    // Quad (i, j) has corners a = (i, j) top-left, b = (i, j + 1), c = (i + 1, j + 1),
    // d = (i + 1, j): going down then along +phi is counter-clockwise seen from outside.
    auto at = [slices](int i, int j) { return static_cast<std::uint32_t>(j * (slices + 1) + i); };
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            std::uint32_t a = at(i, j);
            std::uint32_t b = at(i, j + 1);
            std::uint32_t c = at(i + 1, j + 1);
            std::uint32_t d = at(i + 1, j);
            if (j != 0) mesh.indices.insert(mesh.indices.end(), {a, b, d});
            if (j != stacks - 1) mesh.indices.insert(mesh.indices.end(), {d, b, c});
        }
    }
    return mesh;
}

Mesh tessellate(const Primitive& primitive, const TessellationOptions& options) {
    if (const Plane* p = std::get_if<Plane>(&primitive)) return tessellate(*p);
    if (const Box* b = std::get_if<Box>(&primitive)) return tessellate(*b);
    return tessellate(std::get<Sphere>(primitive), options);
}

Mesh objectMesh(const SceneObject& object, const TessellationOptions& options) {
    return tessellate(object.shape, options);
}

}  // namespace pcf
