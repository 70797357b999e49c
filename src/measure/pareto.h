// pareto.h: the points of a speed/accuracy plot that no other point beats on both counts.
#pragma once

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace pcf {

// Indices of the points (x = cost, y = error; lower is better on both) that are not dominated.
// q dominates p when q.x <= p.x and q.y <= p.y + yTolerance, and q is strictly better on one
// count (q.x < p.x, or q.y < p.y - yTolerance): errors within yTolerance of each other are a
// tie, so a run that is slower by a hair of float rounding in its error is not on the front
// (bilinear2x2 and hw2x2 compute one filter two ways). Points that tie on both counts all stay.
// Sorted by x ascending (then y): the order the front is drawn in, x rising and y falling.
std::vector<size_t> paretoFront(std::span<const glm::dvec2> points, double yTolerance = 0.0);

}  // namespace pcf
