#include "measure/pareto.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace pcf {

std::vector<size_t> paretoFront(std::span<const glm::dvec2> points, double yTolerance) {
    // Sweep by x ascending (ties by y): a group of points sharing one x is on the front when
    // its best y beats every y seen at a smaller x by more than the tolerance; within the
    // group, the points within the tolerance of its best stay. O(n log n).
    std::vector<size_t> order(points.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (points[a].x != points[b].x) return points[a].x < points[b].x;
        if (points[a].y != points[b].y) return points[a].y < points[b].y;
        return a < b;
    });
    std::vector<size_t> front;
    double bestY = std::numeric_limits<double>::infinity();  // smallest y at a smaller x
    for (size_t k = 0; k < order.size();) {
        size_t end = k;
        while (end < order.size() && points[order[end]].x == points[order[k]].x) ++end;
        double groupY = points[order[k]].y;
        if (groupY < bestY - yTolerance) {
            for (size_t g = k; g < end && points[order[g]].y <= groupY + yTolerance; ++g) {
                front.push_back(order[g]);
            }
        }
        bestY = std::min(bestY, groupY);
        k = end;
    }
    return front;
}

}  // namespace pcf
