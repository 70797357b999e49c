// ground_truth_edges.h: where the ground truth's answer may change, decided from the analytic
// geometry instead of from samples, so that no edge can slip between samples however thin the
// sliver it cuts (a terminator grazing a silhouette, a shadow's tip).
//
// A bundle of camera rays (a pixel, a piece of a scanline) is enclosed in a circular cone: the
// eye, a unit axis and a half-angle. On an object, every point those rays can meet lies in a
// ball (centre m, radius rho): the rays run for t in [t0, t1] (the object's nearest and farthest
// front hit over the cone), and
//   |t d - tc a|^2 = t^2 + tc^2 - 2 t tc cos(angle(d, a)) <= t^2 + tc^2 - 2 t tc cos(alpha)
// with tc = (t0 + t1) / 2, largest at t0 or t1. Every edge of the lit state is the zero set of
// a function g with a known Lipschitz constant K (|g(p) - g(q)| <= K |p - q|):
//   terminator of a sphere, directional:  (p - c) . toLight                              K = 1
//   terminator of a sphere, spot:         (p - c) . (l - c) - r^2 (facing times r on it) K = |l -
//   c| shadow of a sphere, directional:      distance(p, the line c + s L) - r             K = 1
//                                         and |p - c| - r (the lit cap upstream)          K = 1
//   shadow of a box or rectangle, directional: signed distance of p's projection along L to
//     the convex hull of the projected corners (K = 1) and the distance to its surface (K = 1)
//   spot cone rim and spot shadows: angles seen from the light, K = 1 / (|m - l| - rho) in
//     radians per unit (the angular radius of the ball is asin(rho / |m - l|)).
// If |g(m)| > K rho for every such g, no edge meets the ball: the lit state is one and the same
// on the object throughout the cone (the ball is connected). Where a test would need more than
// this (a spot light's box or rectangle shadow, a ray near parallel to a plane) it answers "may
// change": refining more is the safe side.
//
// Which object a ray meets changes only across an outline (a sphere's silhouette circle, the
// projection of a box's or rectangle's edges) or where two surfaces cut each other; the
// refinement cuts its scanlines there too (ground_truth_conics.h: they move the on-object
// length).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"

namespace pcf {

// The camera rays from `eye` whose direction is within `halfAngle` radians of the unit `axis`.
struct RayCone {
    glm::dvec3 eye;
    glm::dvec3 axis;
    double halfAngle;
};

// Every world point a ray of the cone can meet on one object: a ball.
struct Footprint {
    glm::dvec3 centre;
    double radius;
    bool bounded;  // false: the rays run off to (near) infinity on it, no ball
};

class EdgeFinder {
  public:
    explicit EdgeFinder(const Scene& scene);

    // Whether the lit state (litByLight) of the points of `object` met by the cone's rays may
    // differ: false means every ray of the cone that meets the object meets it equally lit.
    bool litMayChange(const RayCone& cone, int object) const;

    // For a directional light with a size (tanHalf = tan of half its angular diameter): 1 when
    // every point of `object` in the cone sees the whole light disk, 0 when none sees any of
    // it, -1 when that is not certain (a penumbra may be there). A ray from a point of the ball
    // toward the disk strays from the line toward the disk's centre by at most t tanHalf after
    // an axial distance t, so the hard tests above hold with the ball grown by (t_max + rho)
    // tanHalf, t_max the caster's farthest axial reach; a point downstream of a caster, deep
    // enough in its prism that no such ray leaves it before passing the caster, sees none
    // (the prism minus the caster has an upstream and a downstream part, and a path from one
    // to the other within the prism crosses the caster). The horizon: a sphere's normal n sees
    // the whole disk when n . toLight > sin(half), none when < -sin(half).
    // For a spot light with a radius R (tanHalf unused): 1 or -1 (areaSpotState), never 0.
    int areaState(const RayCone& cone, int object, double tanHalf) const;

    // The ball around `object`'s points met by the cone (see the top of this file).
    Footprint footprint(const RayCone& cone, int object) const;

  private:
    struct Caster {
        int object;
        std::vector<glm::dvec2> hull;  // directional light: the projection along L, convex hull
    };
    const Scene& mScene;
    glm::dvec3 mTravel;           // unit, the way the light travels
    glm::dvec3 mBasisU, mBasisV;  // the plane across L that casters are projected onto
    std::vector<Caster> mCasters;

    bool shadowEdgeNear(const Footprint& f, const Caster& caster) const;
    bool spotShadowEdgeNear(const Footprint& f, const Caster& caster) const;
    double across(const Footprint& f, const Caster& caster) const;
    int areaHorizon(const RayCone& cone, const Footprint& f, int object, double sinHalf) const;
    // A spot's disk (centre L, radius R, axis a): 1 when every point of the ball (centre c,
    // radius rho) lies in the spot's cone, sees all of the disk above its tangent plane (a
    // plane or one box face, normal n toward the eye: n . (L - c) - R sqrt(1 - (n . a)^2) -
    // rho > 0) and no caster's bounding ball comes within max(rho, R) of the segment from c to
    // L (a point (1 - t) x + t y of a segment from the ball to the disk lies within (1 - t) rho
    // + t R of (1 - t) c + t L); else -1: the umbra is not told apart, it is integrated.
    int areaSpotState(const RayCone& cone, int object) const;
};

// The edges of a box (12) or a rectangle (4) as pairs of corners; none for a sphere.
std::vector<std::array<glm::dvec3, 2>> primitiveEdges(const Primitive& shape);

// The convex hull of 2D points, counter-clockwise, collinear points dropped (Andrew's monotone
// chain: Andrew, "Another efficient algorithm for convex hulls in two dimensions", 1979).
std::vector<glm::dvec2> convexHull2d(std::vector<glm::dvec2> points);

// The cone around the rays through window points p0..p(n-1) (GL window coordinates, pixels) of
// a frame: the axis through their mean, the half-angle to the farthest. `rays` gives a unit
// direction per window point.
template <typename RayAt>
RayCone coneThrough(const glm::dvec3& eye, const RayAt& rays, const glm::dvec2* points, int n) {
    glm::dvec2 mean(0.0);
    for (int k = 0; k < n; ++k) mean += points[k];
    glm::dvec3 axis = rays(mean / static_cast<double>(n));
    double cosMin = 1.0;
    for (int k = 0; k < n; ++k) cosMin = std::min(cosMin, glm::dot(axis, rays(points[k])));
    // acos of a rounded cosine: widen by 1e-9 rad so rounding never shrinks the cone.
    return {eye, axis, std::acos(std::clamp(cosMin, -1.0, 1.0)) + 1e-9};
}

}  // namespace pcf
