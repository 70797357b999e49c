#include "measure/light_disk_shadow.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <variant>
#include <vector>

#include "measure/ground_truth_edges.h"
#include "measure/light_disk_area.h"

namespace pcf {

namespace {

// Every shape is cut to this square about the disk (disk radii) before the areas: the disk lies
// inside it, and every coordinate the areas see is small.
constexpr double SQUARE = 1.25;
// Projected corners farther out than this (disk radii) leave too few digits: slice instead.
constexpr double MAX_COORD = 1e7;
constexpr int MAX_TERMS = 4096;
// A sphere's circle starts as this many arcs, each halved at most MAX_ARC_DEPTH times.
constexpr int SPHERE_ARCS = 16;
constexpr int MAX_ARC_DEPTH = 14;

// The disk seen from p (light_disk_shadow.h): w its unit normal toward it, L = depth, reach the
// farthest a point of the disk lies from p; K the pyramid from p over the square about the disk
// (disk radii SQUARE), its apex p, cut at the disk's plane for a spot's disk: its four sides
// (planes through p and two corners), and the plane z = L.
struct DiskSight {
    LightDiskView d;
    glm::dvec3 w;
    double depth;
    double reach;
    std::array<glm::dvec3, 4> cornerWs;  // the square's corners, counter-clockwise
    std::array<glm::dvec2, 4> corner2d;
    std::array<glm::dvec3, 4> sideNormal;  // into K
    int faces = 4;                         // 5 with the disk's plane
    double maxCoord = 0.0;    // the largest projected coordinate so far, for the rounding
    double pointError = 0.0;  // the largest error of a projected corner (addProjected)

    DiskSight(const LightDiskView& disk, const glm::dvec3& normal)
        : d(disk),
          w(normal),
          depth(glm::dot(normal, disk.centre - disk.p)),
          reach(glm::length(disk.centre - disk.p) + disk.radius) {
        corner2d = {glm::dvec2(-SQUARE, -SQUARE), glm::dvec2(SQUARE, -SQUARE),
                    glm::dvec2(SQUARE, SQUARE), glm::dvec2(-SQUARE, SQUARE)};
        for (int k = 0; k < 4; ++k) {
            cornerWs[k] = d.centre + (d.e1 * corner2d[k].x + d.e2 * corner2d[k].y) * d.radius;
        }
        for (int k = 0; k < 4; ++k) {
            glm::dvec3 n = glm::cross(cornerWs[k] - d.p, cornerWs[(k + 1) % 4] - d.p);
            sideNormal[k] = glm::dot(n, d.centre - d.p) >= 0.0 ? n : -n;
        }
        faces = d.finite ? 5 : 4;
    }
    double ahead(const glm::dvec3& v) const { return glm::dot(v - d.p, w); }
    // Face f of K: >= 0 on K's side.
    double faceSide(int f, const glm::dvec3& q) const {
        return f < 4 ? glm::dot(sideNormal[f], q - d.p) : depth - ahead(q);
    }
    // Inside K, but for rounding (a point computed on one face may stray from it by that).
    bool insideK(const glm::dvec3& q) const {
        double slack = 1e-12 * (glm::length(q - d.p) + reach);
        for (int f = 0; f < faces; ++f) {
            double scale = f < 4 ? glm::length(sideNormal[f]) : 1.0;
            if (faceSide(f, q) < -slack * scale) return false;
        }
        return true;
    }
    // Where the ray from p through v (ahead of p) meets the disk's plane, in disk radii about
    // its centre along e1, e2.
    glm::dvec2 project(const glm::dvec3& v) {
        glm::dvec3 rel = v - d.p;
        glm::dvec3 q = rel * (depth / glm::dot(rel, w)) - (d.centre - d.p);
        glm::dvec2 x(glm::dot(q, d.e1) / d.radius, glm::dot(q, d.e2) / d.radius);
        maxCoord = std::max({maxCoord, std::abs(x.x), std::abs(x.y)});
        return x;
    }
};

const ConvexPolygon& diskSquare() {
    static const ConvexPolygon s{
        {-SQUARE, -SQUARE}, {SQUARE, -SQUARE}, {SQUARE, SQUARE}, {-SQUARE, SQUARE}};
    return s;
}

double cross2d(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// A box, or a rectangle as a box of no thickness: centre, unit axes, half extents (a
// rectangle's along its normal 0).
struct Polytope {
    glm::dvec3 centre;
    glm::dvec3 axis[3];
    double half[3];

    glm::dvec3 corner(int bits) const {
        glm::dvec3 q = centre;
        for (int i = 0; i < 3; ++i) q += axis[i] * ((bits >> i & 1) != 0 ? half[i] : -half[i]);
        return q;
    }
    // The parameters [t0, t1] within [lo, hi] where o + t d lies inside (the slab method of Kay
    // and Kajiya, "Ray Tracing Complex Scenes", SIGGRAPH 1986); false when none.
    bool clip(const glm::dvec3& o, const glm::dvec3& d, double lo, double hi, double& t0,
              double& t1) const {
        t0 = lo;
        t1 = hi;
        for (int i = 0; i < 3; ++i) {
            double oi = glm::dot(o - centre, axis[i]);
            double di = glm::dot(d, axis[i]);
            if (di == 0.0) {
                if (std::abs(oi) > half[i]) return false;
                continue;
            }
            double a = (-half[i] - oi) / di;
            double b = (half[i] - oi) / di;
            t0 = std::max(t0, std::min(a, b));
            t1 = std::min(t1, std::max(a, b));
        }
        return t0 <= t1;
    }
};

Polytope polytopeOf(const Primitive& shape) {
    if (const Plane* q = std::get_if<Plane>(&shape)) {
        glm::dvec3 u(q->halfUWs), v(q->halfVWs);
        return {glm::dvec3(q->centreWs),
                {glm::normalize(u), glm::normalize(v), glm::normalize(glm::dvec3(q->normalWs))},
                {glm::length(u), glm::length(v), 0.0}};
    }
    const Box& b = std::get<Box>(shape);
    BoxAxes ax = boxAxes(b);
    return {glm::dvec3(b.centreWs),
            {ax.xWs, glm::dvec3(0.0, 1.0, 0.0), ax.zWs},
            {b.halfExtents.x, b.halfExtents.y, b.halfExtents.z}};
}

// Adds q's projection, unless q lies so near p that its direction is not known to 1e-6 disk
// radii (light_disk_shadow.h); the largest error kept goes into v.pointError.
void addProjected(DiskSight& v, const glm::dvec3& q, std::vector<glm::dvec2>& out) {
    double away = glm::length(q - v.d.p);
    double error =
        4.0 * DBL_EPSILON * (glm::length(q) + glm::length(v.d.p)) / away * (v.reach / v.d.radius);
    if (!(error <= 1e-6)) return;
    v.pointError = std::max(v.pointError, error);
    out.push_back(v.project(q));
}

// A box's or a rectangle's shadow on the disk within the square (top of light_disk_shadow.h):
// the hull of the projected corners of its part inside the pyramid K from p over the square.
void polygonShadow(const Primitive& shape, DiskSight& v, ConvexPolygon& out) {
    out.clear();
    Polytope c = polytopeOf(shape);
    thread_local std::vector<glm::dvec2> points;
    points.clear();
    // Its corners inside K, and its edges' crossings of K's faces.
    for (int k = 0; k < 8; ++k) {
        glm::dvec3 a = c.corner(k);
        if (v.insideK(a)) addProjected(v, a, points);
        for (int i = 0; i < 3; ++i) {
            if ((k >> i & 1) != 0 || c.half[i] == 0.0) continue;
            glm::dvec3 b = c.corner(k | 1 << i);
            for (int f = 0; f < v.faces; ++f) {
                double sa = v.faceSide(f, a);
                double sb = v.faceSide(f, b);
                if ((sa < 0.0) == (sb < 0.0)) continue;
                glm::dvec3 q = a + (b - a) * (sa / (sa - sb));
                if (v.insideK(q)) addProjected(v, q, points);
            }
        }
    }
    // K's edges through it: a ray from p toward a corner of the square that meets it hides that
    // corner; a side of the square (a spot's, at the disk) hides where it runs inside.
    for (int k = 0; k < 4; ++k) {
        glm::dvec3 toCorner = v.cornerWs[k] - v.d.p;
        double t0, t1;
        double far = v.d.finite ? 1.0 : std::numeric_limits<double>::infinity();
        if (c.clip(v.d.p, toCorner, 0.0, far, t0, t1) && t1 > 1e-12)
            points.push_back(v.corner2d[k]);
        if (!v.d.finite) continue;
        glm::dvec3 side = v.cornerWs[(k + 1) % 4] - v.cornerWs[k];
        if (c.clip(v.cornerWs[k], side, 0.0, 1.0, t0, t1)) {
            glm::dvec2 along = v.corner2d[(k + 1) % 4] - v.corner2d[k];
            points.push_back(v.corner2d[k] + along * t0);
            points.push_back(v.corner2d[k] + along * t1);
        }
    }
    if (points.size() < 3) return;
    ConvexPolygon hull = convexHull2d(points);
    if (hull.size() >= 3) out = std::move(hull);
}

// The disk's points below p's horizon, n . (q - p) <= 0, cut to the square.
void horizonShadow(const DiskSight& v, const glm::dvec3& n, ConvexPolygon& out) {
    glm::dvec2 g(glm::dot(n, v.d.e1) * v.d.radius, glm::dot(n, v.d.e2) * v.d.radius);
    double h = -glm::dot(n, v.d.centre - v.d.p);
    out.clear();
    if (g.x == 0.0 && g.y == 0.0) {
        if (h >= 0.0) out = diskSquare();
        return;
    }
    clipToHalfPlane(diskSquare(), g, h, out);
    if (out.size() < 3) out.clear();
}

// A sphere's circle of contact (top of light_disk_shadow.h) turned into arcs, each arc giving
// the inner polygon its first point and the outer polygon the meeting point of its ends'
// tangents (at the arc's middle angle, 1 / cos(half the arc) times the radius out).
struct ContactArcs {
    DiskSight& v;
    glm::dvec3 centre, b1, b2;
    double radius;
    double tolerance;  // an arc's gap (its triangle's area, disk radii squared) left unsplit
    ConvexPolygon& inner;
    ConvexPolygon& outer;
    bool ok = true;

    glm::dvec3 at(double phi, double scale) const {
        return centre + (b1 * std::cos(phi) + b2 * std::sin(phi)) * (radius * scale);
    }

    void arc(double phi0, glm::dvec2 q0, double phi1, glm::dvec2 q1, int depth) {
        double half = 0.5 * (phi1 - phi0);
        double mid = phi0 + half;
        glm::dvec3 corner = at(mid, 1.0 / std::cos(half));
        if (!(v.ahead(corner) > 0.0)) {
            ok = false;
            return;
        }
        glm::dvec2 t = v.project(corner);
        glm::dvec2 lo = glm::min(glm::min(q0, q1), t);
        glm::dvec2 hi = glm::max(glm::max(q0, q1), t);
        bool nearDisk = lo.x < SQUARE && lo.y < SQUARE && hi.x > -SQUARE && hi.y > -SQUARE;
        double gap = 0.5 * std::abs(cross2d(t - q0, q1 - q0));
        if (nearDisk && gap > tolerance && depth < MAX_ARC_DEPTH) {
            glm::dvec2 qm = v.project(at(mid, 1.0));
            arc(phi0, q0, mid, qm, depth + 1);
            arc(mid, qm, phi1, q1, depth + 1);
            return;
        }
        inner.push_back(q0);
        outer.push_back(t);
    }
};

// A sphere's shadow bracketed between `inner` and `outer`, cut to the square: 1 built, 0 no
// shadow (its cone lies behind p), -1 where the closed form does not apply.
int sphereShadow(const Sphere& s, DiskSight& v, double tolerance, ConvexPolygon& inner,
                 ConvexPolygon& outer) {
    inner.clear();
    outer.clear();
    glm::dvec3 c(s.centreWs);
    double r = s.radius;
    glm::dvec3 toCentre = c - v.d.p;
    double dist = glm::length(toCentre);
    if (dist - r < -1e-9) {
        inner = outer = diskSquare();  // p inside: it sees nothing
        return 1;
    }
    if (dist - r <= 1e-9) {
        // p on the sphere: the rays into it, n . d < 0 with n its normal at p (a convex solid
        // is not met again by a ray that leaves it).
        horizonShadow(v, -toCentre / dist, inner);
        outer = inner;
        return 1;
    }
    glm::dvec3 axis = toCentre / dist;
    double sinHalf = r / dist;
    double cosToNormal = glm::dot(axis, v.w);
    // The cone's directions lie within asin(r / dist) of its axis: all behind p's depth when
    // the axis is more than 90 degrees plus that from w, all ahead when less than 90 minus it.
    if (cosToNormal <= -sinHalf) return 0;
    if (cosToNormal <= sinHalf + 1e-6) return -1;
    glm::dvec3 b1 = glm::normalize(
        glm::cross(axis, std::abs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)));
    glm::dvec3 b2 = glm::cross(axis, b1);
    ContactArcs arcs{v,
                     c - axis * (r * r / dist),
                     b1,
                     b2,
                     r * std::sqrt(dist * dist - r * r) / dist,
                     tolerance,
                     inner,
                     outer};
    double step = 2.0 * std::numbers::pi / SPHERE_ARCS;
    glm::dvec2 first = v.project(arcs.at(0.0, 1.0));
    glm::dvec2 q0 = first;
    for (int k = 0; k < SPHERE_ARCS && arcs.ok; ++k) {
        double phi1 = (k + 1) * step;
        glm::dvec2 q1 = k + 1 == SPHERE_ARCS ? first : v.project(arcs.at(phi1, 1.0));
        arcs.arc(k * step, q0, phi1, q1, 0);
        q0 = q1;
    }
    if (!arcs.ok || !(v.maxCoord <= MAX_COORD)) return -1;
    double signedArea = 0.0;
    for (size_t i = 0; i < inner.size(); ++i) {
        signedArea += cross2d(inner[i], inner[(i + 1) % inner.size()]);
    }
    if (signedArea < 0.0) {
        std::reverse(inner.begin(), inner.end());
        std::reverse(outer.begin(), outer.end());
    }
    inner = intersectConvex(inner, diskSquare());
    outer = intersectConvex(outer, diskSquare());
    return 1;
}

// The shadows at p: `exact` (the horizon's, the boxes' and rectangles'), and per sphere an inner
// and an outer polygon. False where the closed form does not apply.
struct Shadows {
    std::vector<ConvexPolygon> exact, inner, outer;
};

bool collectShadows(const Scene& scene, DiskSight& v, glm::dvec3 facing, int object,
                    double tolerance, Shadows& s) {
    s.exact.clear();
    s.inner.clear();
    s.outer.clear();
    ConvexPolygon poly, in, out;
    horizonShadow(v, facing, poly);
    if (!poly.empty()) s.exact.push_back(poly);
    bool receives = object < 0 || scene.objects[static_cast<size_t>(object)].receivesShadow;
    for (size_t i = 0; receives && i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        if (!o.castsShadow || static_cast<int>(i) == object) continue;
        if (const Sphere* sphere = std::get_if<Sphere>(&o.shape)) {
            int built = sphereShadow(*sphere, v, tolerance, in, out);
            if (built < 0) return false;
            if (built > 0 && !out.empty()) {
                s.inner.push_back(in);
                s.outer.push_back(out);
            }
            continue;
        }
        polygonShadow(o.shape, v, poly);
        if (!poly.empty()) s.exact.push_back(poly);
    }
    return true;
}

// The covered area between the unions with the spheres' inner and outer polygons: nullopt when
// too many terms.
std::optional<std::pair<DiskCover, DiskCover>> coveredBracket(const Shadows& s) {
    std::vector<ConvexPolygon> set = s.exact;
    set.insert(set.end(), s.inner.begin(), s.inner.end());
    std::optional<DiskCover> lo = unitDiskUnionArea(set, MAX_TERMS);
    if (!lo) return std::nullopt;
    if (s.outer.empty()) return std::pair{*lo, *lo};
    set.resize(s.exact.size());
    set.insert(set.end(), s.outer.begin(), s.outer.end());
    std::optional<DiskCover> hi = unitDiskUnionArea(set, MAX_TERMS);
    if (!hi) return std::nullopt;
    return std::pair{*lo, *hi};
}

}  // namespace

std::optional<LightFraction> diskFractionClosedForm(const Scene& scene, const LightDiskView& disk,
                                                    glm::dvec3 facingWs, int object,
                                                    double target) {
    glm::dvec3 toCentre = disk.centre - disk.p;
    glm::dvec3 w = glm::normalize(glm::cross(disk.e1, disk.e2));
    if (glm::dot(w, toCentre) < 0.0) w = -w;
    DiskSight v(disk, w);
    if (!(v.depth > 0.0) || !(disk.radius > 0.0)) return std::nullopt;
    thread_local Shadows shadows;
    // A sphere's arcs are split until each gap near the disk is at most a 16th of the target's
    // area; where the bracket is still wider than half the target, finer.
    double tolerance = target * std::numbers::pi / 16.0;
    for (int attempt = 0;; ++attempt) {
        v.maxCoord = 0.0;
        v.pointError = 0.0;
        if (!collectShadows(scene, v, facingWs, object, tolerance, shadows)) return std::nullopt;
        if (shadows.exact.empty() && shadows.outer.empty()) return LightFraction{1.0, 0.0};
        auto bracket = coveredBracket(shadows);
        if (!bracket) return std::nullopt;
        auto [lo, hi] = *bracket;
        if (lo.whole) return LightFraction{0.0, 0.0};
        // Rounding: each term's area is a sum of a few dozen operations on coordinates of at
        // most SQUARE (1e-13), and its polygon's corners may each be off by the projection's
        // error (addProjected) or that of a clipped point of a sphere's polygon (its largest
        // coordinate's rounding), which moves the area by at most the perimeter, 8 SQUARE,
        // times that.
        double cornerError = v.pointError + 1e-15 * (1.0 + v.maxCoord);
        double rounding = (lo.terms + hi.terms) * (8.0 * SQUARE * cornerError + 1e-13);
        double gap = (hi.area - lo.area) / (2.0 * std::numbers::pi);
        if (gap > 0.5 * target && attempt < 2) {
            tolerance /= 16.0;
            continue;
        }
        double f = 1.0 - (lo.area + hi.area) / (2.0 * std::numbers::pi);
        return LightFraction{std::clamp(f, 0.0, 1.0),
                             std::max(gap, 0.0) + rounding / std::numbers::pi};
    }
}

}  // namespace pcf
