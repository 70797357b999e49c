// light_disk_shadow.h: the share of a light's disk that a point sees, in closed form: each
// caster's shadow on the disk is the central projection from the point onto the disk's plane, a
// convex set, and the covered area is light_disk_area.h's.
//
// Seen from p, with w the disk's unit normal toward it from p and z(v) = (v - p) . w the depth of
// a point v, the disk lies in the plane z = L (L = (centre - p) . w > 0) and the ray from p
// through v meets that plane at p + (v - p) L / z(v). A point of the disk is hidden when the
// segment from p to it (the whole ray for a sun) meets a caster, so a convex caster C hides
// exactly the projection of C's part with 0 < z (<= L for a spot's disk), a convex set:
// - a box or a rectangle: only its part inside K, the pyramid from p over a square about the
//   disk (the disk's part of the plane, and a margin), matters, and that part is a convex
//   polytope whose corners are the caster's corners inside K, its edges' crossings of K's faces,
//   and where K's edges (the rays from p through the square's corners; for a spot's disk also
//   the square's sides) enter and leave the caster. The hull of their projections, each inside
//   the square, is the shadow there. Every point of K but p lies ahead (z > 0), so nothing is
//   projected from near p's depth; p itself (a caster touching p: a box on the ground at its
//   foot) is left out, and with it any corner within about 1e-6 scene units of p, whose
//   direction from p is not known to 1e-6 disk radii (the corners beyond it still give the
//   caster's wedge); the others' projection error goes into the bound;
// - a sphere (c, r): the cone of the rays from p that meet it, axis (c - p) / |c - p|, its
//   half-angle asin(r / |c - p|), touches the sphere along a circle (centre c - (c - p) r^2 /
//   |c - p|^2, radius r sqrt(|c - p|^2 - r^2) / |c - p|). When the whole cone lies ahead (z > 0)
//   the projection of that circle is an ellipse, bracketed between the projections of an
//   inscribed and a circumscribed polygon of the circle (a projection keeps lines straight and
//   tangents tangent, so the first lies inside the ellipse and the second holds it); their arcs
//   are halved where they come near the disk until each gap is small (p inside the sphere sees
//   nothing; p on it, within 1e-9, is hidden from the rays into it, a half-plane);
// - the horizon: the disk's points q with n . (q - p) <= 0 (n the facing normal), a half-plane.
// The covered area is then bracketed between the union with the spheres' inner polygons and
// with their outer ones: the fraction is their mean, the bound half their difference plus the
// rounding of the sums (boxes and rectangles alone: exact up to rounding).
//
// Where this does not apply lightVisibleFraction (light_visibility.h) slices the disk instead:
// a sphere's cone that reaches p's depth (z <= 0) without lying wholly
// behind it, an ellipse point beyond 1e7 disk radii (a cone nearly grazing that depth), or more
// than 4096 intersections in the union.
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "measure/light_visibility.h"
#include "scene/scene.h"

namespace pcf {

// The light's disk seen from a receiver point.
struct LightDiskView {
    glm::dvec3 p;       // the receiver point
    glm::dvec3 centre;  // the disk's centre
    glm::dvec3 e1, e2;  // unit, across the disk's normal and each other
    double radius;
    bool finite;  // a spot's disk at its place: only casters between p and it count
};

// The visible fraction at p (light_visibility.h defines it: every caster but `object`, none for
// a non-receiver, the horizon of the facing normal facingWs) in closed form, aiming for a bound
// of at most `target`; nullopt where the closed form does not apply (above).
std::optional<LightFraction> diskFractionClosedForm(const Scene& scene, const LightDiskView& disk,
                                                    glm::dvec3 facingWs, int object, double target);

}  // namespace pcf
