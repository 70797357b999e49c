// Tessellation for the rasterizer: counts, winding (counter-clockwise from outside), normals,
// and that the vertices lie on the analytic surface. Also the bounds the frusta are fitted to.
#include "scene/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pcf {
namespace {

glm::vec3 faceNormal(const Mesh& m, size_t tri) {
    glm::vec3 a = m.vertices[m.indices[3 * tri]].posWs;
    glm::vec3 b = m.vertices[m.indices[3 * tri + 1]].posWs;
    glm::vec3 c = m.vertices[m.indices[3 * tri + 2]].posWs;
    return glm::cross(b - a, c - a);  // length = 2 * area; CCW seen from where it points
}

glm::vec3 centroid(const Mesh& m, size_t tri) {
    return (m.vertices[m.indices[3 * tri]].posWs + m.vertices[m.indices[3 * tri + 1]].posWs +
            m.vertices[m.indices[3 * tri + 2]].posWs) /
           3.0f;
}

double totalArea(const Mesh& m) {
    double area = 0.0;
    for (size_t t = 0; t < m.triangleCount(); ++t) area += 0.5 * glm::length(faceNormal(m, t));
    return area;
}

// Signed volume by the divergence theorem: sum over triangles of a . (b x c) / 6. Positive
// for a closed mesh wound counter-clockwise from outside.
double signedVolume(const Mesh& m) {
    double v = 0.0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        glm::dvec3 a(m.vertices[m.indices[3 * t]].posWs);
        glm::dvec3 b(m.vertices[m.indices[3 * t + 1]].posWs);
        glm::dvec3 c(m.vertices[m.indices[3 * t + 2]].posWs);
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

void expectValidIndices(const Mesh& m) {
    ASSERT_EQ(m.indices.size() % 3, 0u);
    for (std::uint32_t i : m.indices) ASSERT_LT(i, m.vertices.size());
}

TEST(Mesh, PlaneIsTwoTrianglesFacingItsNormal) {
    Plane plane = *makePlane({1, 2, 3}, {0, 1, 0}, {4, 2});
    Mesh m = tessellate(plane);
    expectValidIndices(m);
    EXPECT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.triangleCount(), 2u);
    for (size_t t = 0; t < 2; ++t) {
        glm::vec3 n = glm::normalize(faceNormal(m, t));
        EXPECT_NEAR(n.y, 1.0f, 1e-6f);
    }
    for (const Vertex& v : m.vertices) {
        EXPECT_FLOAT_EQ(v.posWs.y, 2.0f);
        EXPECT_FLOAT_EQ(std::abs(v.posWs.x - 1.0f), 2.0f);
        EXPECT_FLOAT_EQ(std::abs(v.posWs.z - 3.0f), 1.0f);
        EXPECT_EQ(v.normalWs, glm::vec3(0, 1, 0));
    }
    EXPECT_NEAR(totalArea(m), 8.0, 1e-5);
    // A tilted plane too: winding follows the normal, whatever it is.
    glm::vec3 n(0.3f, 0.5f, -0.8f);
    Mesh tilted = tessellate(*makePlane({0, 0, 0}, n, {1, 3}));
    for (size_t t = 0; t < 2; ++t) {
        EXPECT_GT(glm::dot(glm::normalize(faceNormal(tilted, t)), glm::normalize(n)), 0.9999f);
    }
    EXPECT_NEAR(totalArea(tilted), 3.0, 1e-5);
}

void expectBox(const Box& box) {
    Mesh m = tessellate(box);
    expectValidIndices(m);
    EXPECT_EQ(m.vertices.size(), 24u);
    EXPECT_EQ(m.triangleCount(), 12u);
    for (size_t t = 0; t < 12; ++t) {
        glm::vec3 n = glm::normalize(faceNormal(m, t));
        // Outward, and flat: each corner carries the face's normal.
        EXPECT_GT(glm::dot(n, centroid(m, t) - box.centreWs), 0.0f) << "triangle " << t;
        for (int k = 0; k < 3; ++k) {
            glm::vec3 vn = m.vertices[m.indices[3 * t + k]].normalWs;
            EXPECT_NEAR(glm::dot(vn, n), 1.0f, 1e-5f) << "triangle " << t;
        }
    }
    // Every vertex is a corner of the box.
    for (const Vertex& v : m.vertices) {
        glm::vec3 local = glm::abs(boxLocalFromWorld(box, v.posWs));
        EXPECT_NEAR(local.x, box.halfExtents.x, 1e-5f);
        EXPECT_NEAR(local.y, box.halfExtents.y, 1e-5f);
        EXPECT_NEAR(local.z, box.halfExtents.z, 1e-5f);
    }
    glm::vec3 h = box.halfExtents;
    EXPECT_NEAR(totalArea(m), 8.0 * (h.x * h.y + h.y * h.z + h.z * h.x), 1e-4);
    EXPECT_NEAR(signedVolume(m), 8.0 * h.x * h.y * h.z, 1e-4);
}

TEST(Mesh, BoxHasFlatOutwardFaces) {
    expectBox(Box{{0, 0.5f, 0}, {0.5f, 0.5f, 0.5f}, 0.0f});
    expectBox(Box{{1, 2, -3}, {0.2f, 1.5f, 0.7f}, 33.0f});
}

TEST(Mesh, UvSphereIsInscribedAndWoundOutward) {
    Sphere s{{1, 2, 3}, 0.75f};
    Mesh m = tessellate(s);
    expectValidIndices(m);
    EXPECT_EQ(m.vertices.size(), 49u * 25u);
    EXPECT_EQ(m.triangleCount(), 48u * (2u * 24u - 2u));
    for (const Vertex& v : m.vertices) {
        EXPECT_NEAR(glm::length(v.posWs - s.centreWs), s.radius, 1e-5f);
        EXPECT_NEAR(glm::length(v.normalWs), 1.0f, 1e-6f);
        glm::vec3 radial = glm::normalize(v.posWs - s.centreWs);
        EXPECT_NEAR(glm::dot(v.normalWs, radial), 1.0f, 1e-5f);
    }
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        glm::vec3 n = faceNormal(m, t);
        ASSERT_GT(glm::length(n), 1e-6f) << "degenerate triangle " << t;
        EXPECT_GT(glm::dot(glm::normalize(n), glm::normalize(centroid(m, t) - s.centreWs)), 0.9f)
            << "triangle " << t;
    }
    // Inscribed: a little less volume than the sphere, within 1%.
    double exact = 4.0 / 3.0 * std::numbers::pi * std::pow(s.radius, 3);
    double v = signedVolume(m) - 0.0;
    EXPECT_LT(v, exact);
    EXPECT_GT(v, 0.99 * exact);
}

TEST(Mesh, CoarseSphere) {
    Mesh m = tessellate(Sphere{{0, 0, 0}, 1.0f}, TessellationOptions{4, 2});
    expectValidIndices(m);
    EXPECT_EQ(m.triangleCount(), 8u);  // an octahedron
    EXPECT_NEAR(signedVolume(m), 4.0 / 3.0, 1e-5);
}

TEST(Mesh, ObjectMeshAndAppend) {
    SceneObject ball{"ball", Sphere{{0, 1, 0}, 0.5f}};
    EXPECT_EQ(objectMesh(ball).triangleCount(),
              tessellate(Sphere{{0, 1, 0}, 0.5f}).triangleCount());
    Mesh a = tessellate(Box{});
    Mesh b = tessellate(*makePlane({0, 0, 0}, {0, 1, 0}, {2, 2}));
    a.append(b);
    EXPECT_EQ(a.vertices.size(), 28u);
    EXPECT_EQ(a.triangleCount(), 14u);
    EXPECT_EQ(a.indices[36], 24u + b.indices[0]);
    expectValidIndices(a);
}

TEST(Bounds, PrimitivesAndScene) {
    Aabb s = bounds(Sphere{{1, 2, 3}, 0.5f});
    EXPECT_EQ(s.minWs, glm::vec3(0.5f, 1.5f, 2.5f));
    EXPECT_EQ(s.maxWs, glm::vec3(1.5f, 2.5f, 3.5f));
    // A 45-degree box reaches out to its corners: sqrt(2) * 1 along x and z.
    Aabb b = bounds(Box{{0, 0.5f, 0}, {1, 0.5f, 1}, 45.0f});
    EXPECT_NEAR(b.maxWs.x, std::numbers::sqrt2_v<float>, 1e-6f);
    EXPECT_NEAR(b.minWs.z, -std::numbers::sqrt2_v<float>, 1e-6f);
    EXPECT_NEAR(b.maxWs.y, 1.0f, 1e-6f);
    // The bounds hold every vertex of the tessellation, and touch it.
    Box box{{0.3f, 1, -2}, {0.4f, 1, 0.2f}, 30.0f};
    Aabb bb = bounds(box);
    Aabb fromMesh;
    for (const Vertex& v : tessellate(box).vertices) fromMesh.extend(v.posWs);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(bb.minWs[i], fromMesh.minWs[i], 1e-5f);
        EXPECT_NEAR(bb.maxWs[i], fromMesh.maxWs[i], 1e-5f);
    }
    // A plane is flat.
    Aabb p = bounds(*makePlane({0, 0, 0}, {0, 1, 0}, {10, 6}));
    EXPECT_EQ(p.minWs, glm::vec3(-5, 0, -3));
    EXPECT_EQ(p.maxWs, glm::vec3(5, 0, 3));

    Scene scene;
    EXPECT_TRUE(sceneBounds(scene).empty());
    scene.objects.push_back({"ground", *makePlane({0, 0, 0}, {0, 1, 0}, {10, 6})});
    scene.objects.push_back({"ball", Sphere{{1, 2, 3}, 0.5f}});
    Aabb all = sceneBounds(scene);
    EXPECT_EQ(all.minWs, glm::vec3(-5, 0, -3));
    EXPECT_EQ(all.maxWs, glm::vec3(5, 2.5f, 3.5f));
}

}  // namespace
}  // namespace pcf
