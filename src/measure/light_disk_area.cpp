#include "measure/light_disk_area.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pcf {

namespace {

double diskCross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// The signed sector of the unit disk between the directions of a and b: half the angle from a
// to b, counter-clockwise positive (|angle| < pi for the two ends of an edge that misses the
// centre).
double diskSector(glm::dvec2 a, glm::dvec2 b) {
    return 0.5 * std::atan2(diskCross(a, b), glm::dot(a, b));
}

// The signed area of the unit disk inside the triangle (0, a, b) (see light_disk_area.h). The
// edge's points a + t (b - a) inside the circle are t in tm -+ half around the point nearest
// the centre, tm = -a.d / d.d, half = sqrt((1 - h^2) / d.d), h its distance: computed from that
// point, not from the quadratic's coefficients, which cancel for a long edge far away.
double diskEdgeArea(glm::dvec2 a, glm::dvec2 b) {
    glm::dvec2 d = b - a;
    double dd = glm::dot(d, d);
    if (!(dd > 0.0)) return 0.0;
    double tm = -glm::dot(a, d) / dd;
    glm::dvec2 m = a + d * tm;
    double h2 = glm::dot(m, m);
    if (h2 >= 1.0) return diskSector(a, b);
    double half = std::sqrt((1.0 - h2) / dd);
    double t0 = std::max(tm - half, 0.0);
    double t1 = std::min(tm + half, 1.0);
    if (!(t0 < t1)) return diskSector(a, b);
    glm::dvec2 p = t0 > 0.0 ? a + d * t0 : a;
    glm::dvec2 q = t1 < 1.0 ? a + d * t1 : b;
    return diskSector(a, p) + 0.5 * diskCross(p, q) + diskSector(q, b);
}

// The branch of the inclusion-exclusion sum below the intersection `current` of a subset whose
// size has parity `sign` (+1: odd, its term added): each polygon after `next` joins it.
struct DiskUnionSum {
    const std::vector<ConvexPolygon>& polygons;
    int maxTerms;
    double area = 0.0;
    int terms = 0;

    bool branch(const ConvexPolygon& current, size_t next, double sign) {
        for (size_t j = next; j < polygons.size(); ++j) {
            ConvexPolygon both = intersectConvex(current, polygons[j]);
            if (both.size() < 3) continue;
            double a = unitDiskPolygonArea(both);
            if (!(a > 0.0)) continue;  // misses the disk: so does every larger subset
            if (++terms > maxTerms) return false;
            area -= sign * a;
            if (!branch(both, j + 1, -sign)) return false;
        }
        return true;
    }
};

}  // namespace

double unitDiskPolygonArea(std::span<const glm::dvec2> polygon) {
    double area = 0.0;
    size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i) area += diskEdgeArea(polygon[i], polygon[(i + 1) % n]);
    return area;
}

void clipToHalfPlane(std::span<const glm::dvec2> poly, glm::dvec2 n, double c, ConvexPolygon& out) {
    out.clear();
    size_t count = poly.size();
    for (size_t i = 0; i < count; ++i) {
        glm::dvec2 a = poly[i];
        glm::dvec2 b = poly[(i + 1) % count];
        double sa = glm::dot(n, a) - c;
        double sb = glm::dot(n, b) - c;
        if (sa <= 0.0) out.push_back(a);
        if ((sa <= 0.0) != (sb <= 0.0)) out.push_back(a + (b - a) * (sa / (sa - sb)));
    }
}

ConvexPolygon intersectConvex(const ConvexPolygon& a, const ConvexPolygon& b) {
    ConvexPolygon current = a;
    ConvexPolygon next;
    size_t n = b.size();
    for (size_t i = 0; i < n && current.size() >= 3; ++i) {
        // Inside edge (p, q) of a counter-clockwise polygon: diskCross(q - p, x - p) >= 0, that is
        // dot(m, x) <= dot(m, p) with m = (dy, -dx) for (dx, dy) = q - p.
        glm::dvec2 p = b[i];
        glm::dvec2 d = b[(i + 1) % n] - p;
        glm::dvec2 m(d.y, -d.x);
        clipToHalfPlane(current, m, glm::dot(m, p), next);
        std::swap(current, next);
    }
    if (current.size() < 3) current.clear();
    return current;
}

bool coversUnitDisk(std::span<const glm::dvec2> polygon) {
    size_t n = polygon.size();
    if (n < 3) return false;
    for (size_t i = 0; i < n; ++i) {
        glm::dvec2 p = polygon[i];
        glm::dvec2 d = polygon[(i + 1) % n] - p;
        double len = glm::length(d);
        // The centre's distance inside the edge's line, at least 1.
        if (!(len > 0.0) || diskCross(d, -p) < len) return false;
    }
    return true;
}

std::optional<DiskCover> unitDiskUnionArea(const std::vector<ConvexPolygon>& polygons,
                                           int maxTerms) {
    for (const ConvexPolygon& p : polygons) {
        if (coversUnitDisk(p)) return DiskCover{std::numbers::pi, 1, true};
    }
    DiskUnionSum sum{polygons, maxTerms};
    for (size_t i = 0; i < polygons.size(); ++i) {
        if (polygons[i].size() < 3) continue;
        double a = unitDiskPolygonArea(polygons[i]);
        if (!(a > 0.0)) continue;
        if (++sum.terms > maxTerms) return std::nullopt;
        sum.area += a;
        if (!sum.branch(polygons[i], i + 1, 1.0)) return std::nullopt;
    }
    return DiskCover{std::clamp(sum.area, 0.0, std::numbers::pi), sum.terms, false};
}

}  // namespace pcf
