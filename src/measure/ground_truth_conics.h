// ground_truth_conics.h: where the hard-light truth's answer can change inside a pixel, found
// exactly instead of by walking a scanline at a fixed step (which misses a sliver narrower than
// the step, and an edge that runs along the scanline).
//
// Inside pixel (X, Y) the camera ray through the window point (X + x, Y + v), x and v in [0,1],
// has the direction D(x, v) = D0 + x Dx + v Dv (not normalised: the NDC position is linear in
// the window position, and the truth's rays are normalize(D)). Which object a ray meets, and
// whether the light reaches the point it meets, can only change where D satisfies one of these
// conditions, each either a linear form m . D = 0 or a quadratic form D^T Q D = 0 (E the eye):
//   the ray through a line (a box's or a rectangle's edge; where two planes cut each other):
//     m = (a - E) x (b - E) for a line through a, b
//   the ray tangent to a sphere (c, r), its silhouette: |W x D|^2 = r^2 |D|^2, W = E - c
//   for the hit on a plane (n . P = k) a condition on the point P: with w = n . D and
//     h = k - n . E, w P = w E + h D is linear in D, so a condition that is linear or quadratic
//     in P is a form in D after multiplying by w or w^2:
//       on another plane (m . P = l):             (m . E - l) n . D + h m . D
//       on a sphere (c, r) (the circle where it cuts the plane): |w (E - c) + h D|^2 = r^2 w^2
//       on a sphere's shadow cylinder (directional light L): the same with the part across L
//       on a cone from the spot light (its rim, a sphere caster's shadow cone): with M = w (P - l),
//         (M . a)^2 = cos^2(gamma) |M|^2
//   for the hit on a sphere, a condition that is a plane (the terminator's plane through c
//   across L, or (P - c) . (l - c) = r^2 for a spot; a box edge's shadow plane; another plane
//   or a sphere's radical plane): the ray meets the circle where the plane cuts the sphere,
//   the "on a sphere" form above with the roles of plane and sphere swapped.
// So in a pixel every such edge lies on a conic (degree 2 in x and v together):
//   q(x, v) = a x^2 + b x v + c v^2 + d x + e v + f = 0,
// a superset of the edges (whole lines and circles, not just the parts that are edges). Along
// the scanline v the state is constant between the roots of the conics, so the scanline's lit
// and on lengths are exact up to rounding (ground_truth.cpp reads each piece at its middle). In
// v, the set of roots changes its order or count only at a conic's tangent to the scanline
// direction (disc(v) = 0), where a conic crosses the pixel's left or right side, and where two
// conics cross (a root of their resultant in x, a polynomial of degree <= 4 in v): between those
// rows every piece of the state is swept by smooth curves, so a lit or unlit region of the
// pixel cannot begin and end between two scanlines of the integral.
//
// Not conics (the intersection of a sphere with a cylinder or a cone is a quartic curve): a
// sphere receiving another sphere's shadow, and a spot light's rim on a sphere. For those
// objects exact() is false and the truth walks the scanline as before (ground_truth.h says what
// that assumes).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"

namespace pcf {

// q(x, v) = a x^2 + b x v + c v^2 + d x + e v + f, scaled so that its largest coefficient is 1.
struct Conic {
    double a, b, c, d, e, f;
    bool linear;  // a = b = c = 0: a line
};

// A condition on the ray direction D: m . D (linear) or D^T Q D.
struct EdgeForm {
    glm::dmat3 q;
    glm::dvec3 m;
    bool linear;
};

class EdgeConics {
  public:
    EdgeConics(const Scene& scene, const glm::dvec3& eye);

    // Whether every edge of `object`'s answer lies on its forms (see the top of this file).
    bool exact(int object) const { return mExact[static_cast<size_t>(object)]; }

    // The conics of `object` in the pixel whose rays are D0 + x Dx + v Dv, those that meet the
    // pixel's square: where the object seen changes (lit = false), or also where its lit state
    // does (lit = true). Replaces `out`.
    void pixelConics(int object, bool lit, const glm::dvec3& d0, const glm::dvec3& dx,
                     const glm::dvec3& dv, std::vector<Conic>& out) const;

  private:
    std::vector<std::vector<EdgeForm>> mOutline;  // per object: which object is seen
    std::vector<std::vector<EdgeForm>> mLit;      // per object: its lit state
    std::vector<bool> mExact;
};

// Appends the x in (0,1) where the conic meets scanline v, and the x where it comes nearest to
// touching the scanline (its vertex along x): a sliver between two close roots is then split
// even where rounding loses the pair.
void scanlineCuts(const Conic& conic, double v, std::vector<double>& xs);

// Appends the v in (0,1) where the cuts of the conics may change order or count (see the top of
// this file): tangents to the scanline direction, crossings of the pixel's sides x = 0 and
// x = 1, and crossings of two conics.
void criticalRows(const std::vector<Conic>& conics, std::vector<double>& vs);

// The real roots in [lo, hi] of the polynomial sum p[k] t^k of degree <= 4 (p has 5
// coefficients), appended in increasing order; with `touching`, also its local extrema there
// where it is within `touchTolerance` of 0 (double roots, which do not change sign).
void polynomialRoots(const double* p, int degree, double lo, double hi, std::vector<double>& out,
                     bool touching = false, double touchTolerance = 0.0);

}  // namespace pcf
