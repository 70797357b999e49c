// light_disk_area.h: how much of a disk convex polygons cover, in closed form. The area-light
// truth (light_visibility.h) turns every caster's shadow on the light's disk into a convex
// polygon (a box's, a rectangle's, the horizon's half-plane) or brackets it between two (a
// sphere's ellipse), in the disk's own coordinates scaled so that the disk is the unit disk about
// the origin; the share of the light a point sees is then 1 - (covered area) / pi.
//
// The area of the unit disk inside a polygon is a sum over the polygon's edges (a, b) of the
// signed area of the disk inside the triangle (0, a, b): the polygon's area as a fan of signed
// triangles from one point (O'Rourke, "Computational Geometry in C", 2nd ed. 1998, section 1.3),
// each triangle cut by the circle. Where the edge runs outside the circle the triangle's part
// in the disk is the circular sector between the directions of its ends, of area theta / 2;
// where it runs inside, the triangle (0, p, q) on its inner piece [p, q], of area
// cross(p, q) / 2, with a sector on each side. This is Green's theorem in polar form, area =
// (1/2) closed integral of r^2 dtheta, along the boundary of (polygon and disk).
//
// The union of several polygons by inclusion and exclusion over their intersections, which are
// convex polygons again (Sutherland and Hodgman, "Reentrant Polygon Clipping", CACM 1974):
//   |D and (P1 or ... or Pk)| = sum over non-empty S of (-1)^(|S| + 1) |D and (Pi, i in S)|
// A subset whose intersection misses the disk ends its branch: every larger subset misses too.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

namespace pcf {

using ConvexPolygon = std::vector<glm::dvec2>;

// The area of the unit disk about the origin inside the simple polygon `polygon` (vertices
// counter-clockwise; convex or not). In [0, pi] up to rounding.
double unitDiskPolygonArea(std::span<const glm::dvec2> polygon);

// The part of the convex polygon `poly` where dot(n, x) <= c, into `out` (counter-clockwise
// stays counter-clockwise; empty when nothing is left).
void clipToHalfPlane(std::span<const glm::dvec2> poly, glm::dvec2 n, double c, ConvexPolygon& out);

// The intersection of two convex counter-clockwise polygons (empty when they do not overlap).
ConvexPolygon intersectConvex(const ConvexPolygon& a, const ConvexPolygon& b);

// Whether the convex counter-clockwise polygon holds the whole unit disk.
bool coversUnitDisk(std::span<const glm::dvec2> polygon);

// The area of the unit disk covered by the union of the convex counter-clockwise polygons, and
// how many intersections it took; nullopt when that would take more than maxTerms. `whole`: one
// polygon holds the whole disk (area exactly pi).
struct DiskCover {
    double area;
    int terms;
    bool whole;
};
std::optional<DiskCover> unitDiskUnionArea(const std::vector<ConvexPolygon>& polygons,
                                           int maxTerms);

}  // namespace pcf
