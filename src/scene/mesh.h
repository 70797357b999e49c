// mesh.h: triangle meshes of the analytic primitives, for the rasterizer (the shadow pass and
// the camera pass). Ground truth never uses these: it intersects the primitives exactly.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "scene/primitives.h"
#include "scene/scene.h"

namespace pcf {

struct Vertex {
    glm::vec3 posWs;
    glm::vec3 normalWs;  // unit; flat per face for planes and boxes, radial for spheres
};

// Indexed triangles, three indices each, counter-clockwise seen from outside (GL's default
// front face), ready for one glDrawElements(GL_TRIANGLES, GL_UNSIGNED_INT).
struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;

    std::size_t triangleCount() const { return indices.size() / 3; }
    // Appends other, re-basing its indices.
    void append(const Mesh& other);
};

struct TessellationOptions {
    // UV sphere: slices around the Y axis (longitude), stacks from pole to pole (latitude).
    // The vertices lie on the sphere, so the mesh is inscribed: its silhouette is smaller than
    // the exact sphere's by r * (1 - cos(pi / slices)) at most, 0.2% of r for 48 slices.
    int sphereSlices = 48;
    int sphereStacks = 24;
};

// Two triangles, 4 vertices.
Mesh tessellate(const Plane& plane);
// 12 triangles, 24 vertices (4 per face, so each face has its own flat normal).
Mesh tessellate(const Box& box);
// (slices + 1) * (stacks + 1) vertices (the seam and the poles repeated, one per column);
// slices * (2 * stacks - 2) triangles (one per quad at the poles, where the quad is a triangle).
Mesh tessellate(const Sphere& sphere, const TessellationOptions& options = {});
Mesh tessellate(const Primitive& primitive, const TessellationOptions& options = {});

// The mesh the renderer draws for one object (it draws objects one at a time, each with its
// own colour).
Mesh objectMesh(const SceneObject& object, const TessellationOptions& options = {});

}  // namespace pcf
