// light_visibility.h: how much of a light with a size (light.h: a sun's disk of directions) a
// surface point sees, the fraction that a soft shadow's penumbra is made of.
//
// The light is a disk: for a directional light the directions toward -L tilted by up to half
// the angular diameter, taken as the points of a flat disk of radius tan(diameter / 2) one unit
// from the point, across L, with uniform measure over that disk (the light's gnomonic image: a
// straight occluder edge cuts it along a straight chord, so a half-covered sun is exactly a
// circular segment). The visible fraction at p is
//   f(p) = (1 / (pi R^2)) * integral over the disk of [the light point is above p's horizon and
//          the segment from p toward it meets no caster]
// It is computed in closed form where the casters allow (light_disk_shadow.h: each caster's
// shadow on the disk a convex polygon or, for a sphere, an ellipse bracketed between two, and the
// covered area light_disk_area.h's), with the bound that form states (rounding only, or a
// sphere's bracket). Elsewhere the disk is sliced (lightVisibleFractionBySlices below).
//
// The slicing: per chord of the disk (height b, a in [-w, w], w = sqrt(R^2 - b^2)) the blocked
// part is found exactly: each caster cut by the plane through p and the chord is a convex slice
// (a box: a polygon, a rectangle: a segment, a sphere: a disk), and the rays from p through it
// meet the chord in one interval; the horizon n . (light point - p) <= 0 is a half-line. The
// chords' blocked lengths are merged and the integral over b = R sin(theta) (which takes the square
// root out of the chord ends) is an adaptive trapezoid rule with the step-halving error
// estimate of ground_truth.h, so f comes with a bound. It is done twice, with chords one way
// and across: a sliver of the disk parallel to the chords and thinner than their spacing
// escapes one but not the other; the mean is kept, with half their difference added to the
// bound. Assumed, and not checked: no blocker's image (or visible part) smaller than the
// chords' spacing both ways.
//
// A spot light's disk (light.h: radius, centred on positionWs, facing along directionWs) is the
// same computation at a finite distance: the disk is where it is, with uniform measure over its
// area (f is the share of the light's area p sees, not weighted by the angles to it), and a
// caster counts only up to the light: the plane through p and a chord meets the disk's plane
// along the chord's line, so a box's slice is clipped there (Sutherland and Hodgman, 1974); a
// sphere may not reach behind the disk (checkSpotDiskCasters). The spot's cone is its centre's:
// a point outside it sees nothing of the light.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace pcf {

struct LightFraction {
    double visible;  // f(p) in [0,1]
    double bound;    // |visible - exact| <= bound (the integration's estimate, see above)
};

// The visible fraction of the scene's light (with its size) at surface point posWs of object
// `object` (-1: none; it is then shadowed by every caster), whose normal toward the side the
// camera sees is facingWs (unit). Every caster but `object` itself counts, as in litByLight; a
// non-receiver sees the whole light above its horizon. `target`: the bound aimed for.
// A directional light with an angular diameter or a spot light with a radius (hasSize), whose
// scene passes checkSpotDiskCasters; throws std::invalid_argument for a light without a size.
LightFraction lightVisibleFraction(const Scene& scene, glm::dvec3 posWs, glm::dvec3 facingWs,
                                   int object, double target);

// The same by slicing the disk into chords for every point (what lightVisibleFraction falls back
// to where the closed form does not apply): the older computation, to compare the closed form
// against.
LightFraction lightVisibleFractionBySlices(const Scene& scene, glm::dvec3 posWs,
                                           glm::dvec3 facingWs, int object, double target);

// Throws std::invalid_argument naming the sphere when a spot light's scene has a casting sphere
// that reaches behind the light's disk (its slice would need clipping at the disk, which is not
// done); nothing for other lights.
void checkSpotDiskCasters(const Scene& scene);

}  // namespace pcf
