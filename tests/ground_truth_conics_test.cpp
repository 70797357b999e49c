// The pieces of ground_truth_conics.h that do not need a scene: polynomial roots (simple and
// double), a conic's cuts along a row, and the rows where the cuts of conics change.
#include "measure/ground_truth_conics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace pcf {
namespace {

std::vector<double> sorted(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v;
}

// (t - 0.2)(t - 0.5)(t - 0.7)(t - 0.9), expanded.
TEST(GroundTruthConics, QuarticRootsAreFoundToRounding) {
    double p[5] = {0.0, 0.0, 0.0, 0.0, 1.0};
    p[3] = -(0.2 + 0.5 + 0.7 + 0.9);
    p[2] = 0.2 * 0.5 + 0.2 * 0.7 + 0.2 * 0.9 + 0.5 * 0.7 + 0.5 * 0.9 + 0.7 * 0.9;
    p[1] = -(0.2 * 0.5 * 0.7 + 0.2 * 0.5 * 0.9 + 0.2 * 0.7 * 0.9 + 0.5 * 0.7 * 0.9);
    p[0] = 0.2 * 0.5 * 0.7 * 0.9;
    std::vector<double> roots;
    polynomialRoots(p, 4, 0.0, 1.0, roots);
    roots = sorted(roots);
    ASSERT_EQ(roots.size(), 4u);
    const double expected[4] = {0.2, 0.5, 0.7, 0.9};
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(roots[k], expected[k], 1e-12);
    // Only those inside the interval asked for.
    roots.clear();
    polynomialRoots(p, 4, 0.3, 0.8, roots);
    roots = sorted(roots);
    ASSERT_EQ(roots.size(), 2u);
    EXPECT_NEAR(roots[0], 0.5, 1e-12);
    EXPECT_NEAR(roots[1], 0.7, 1e-12);
}

// (t - 0.3)^2 (t - 0.8): with `touching` the double root is reported, however rounding leaves
// its sign (it may not change sign at all); ((t - 0.3)^2 + 0.01)(t - 0.8) has the same
// extremum near 0.3 but no root there, and only 0.8 is reported.
TEST(GroundTruthConics, DoubleRootsAreFoundWithTouching) {
    double p[4] = {-0.3 * 0.3 * 0.8, 0.09 + 2.0 * 0.3 * 0.8, -(0.6 + 0.8), 1.0};
    std::vector<double> roots;
    polynomialRoots(p, 3, 0.0, 1.0, roots, true, 1e-12);
    ASSERT_FALSE(roots.empty());
    for (double t : roots) EXPECT_TRUE(std::abs(t - 0.3) < 1e-6 || std::abs(t - 0.8) < 1e-12) << t;
    EXPECT_NEAR(sorted(roots).front(), 0.3, 1e-6);
    EXPECT_NEAR(sorted(roots).back(), 0.8, 1e-12);
    double q[4] = {p[0] - 0.01 * 0.8, p[1] + 0.01, p[2], p[3]};
    roots.clear();
    polynomialRoots(q, 3, 0.0, 1.0, roots, true, 1e-12);
    ASSERT_EQ(roots.size(), 1u);
    EXPECT_NEAR(roots[0], 0.8, 1e-12);
}

// The circle (x - 0.5)^2 + (v - 0.5)^2 = 0.01: x^2 + v^2 - x - v + 0.49.
const Conic CIRCLE{1.0, 0.0, 1.0, -1.0, -1.0, 0.49, false};

TEST(GroundTruthConics, RowCutsAreTheRootsAndTheVertex) {
    std::vector<double> xs;
    scanlineCuts(CIRCLE, 0.5, xs);
    xs = sorted(xs);
    ASSERT_EQ(xs.size(), 3u);
    EXPECT_NEAR(xs[0], 0.4, 1e-12);
    EXPECT_NEAR(xs[1], 0.5, 1e-12);  // the vertex, between the two roots
    EXPECT_NEAR(xs[2], 0.6, 1e-12);
    // A row that misses the circle still gets its vertex: a sliver thinner than rounding can
    // lose its pair of roots, not the cut between them.
    xs.clear();
    scanlineCuts(CIRCLE, 0.95, xs);
    ASSERT_EQ(xs.size(), 1u);
    EXPECT_NEAR(xs[0], 0.5, 1e-12);
}

TEST(GroundTruthConics, CriticalRowsAreTangentsSidesAndCrossings) {
    // The circle's rows of tangency, 0.4 and 0.6.
    std::vector<double> vs;
    criticalRows({CIRCLE}, vs);
    vs = sorted(vs);
    ASSERT_EQ(vs.size(), 2u);
    EXPECT_NEAR(vs[0], 0.4, 1e-9);
    EXPECT_NEAR(vs[1], 0.6, 1e-9);
    // The lines x = 0.2 + 0.5 v and x = 0.9 - 0.5 v cross at v = 0.7; the second leaves through
    // the side x = 1 nowhere in [0,1], the first through no side either.
    Conic a{0.0, 0.0, 0.0, 1.0, -0.5, -0.2, true};
    Conic b{0.0, 0.0, 0.0, 1.0, 0.5, -0.9, true};
    vs.clear();
    criticalRows({a, b}, vs);
    ASSERT_EQ(vs.size(), 1u);
    EXPECT_NEAR(vs[0], 0.7, 1e-12);
    // x = 1.2 - v crosses the side x = 1 at v = 0.2.
    Conic c{0.0, 0.0, 0.0, 1.0, 1.0, -1.2, true};
    vs.clear();
    criticalRows({c}, vs);
    ASSERT_EQ(vs.size(), 1u);
    EXPECT_NEAR(vs[0], 0.2, 1e-12);
    // The circle and the line x = 0.5 cross at its top and bottom, v = 0.4 and 0.6, which are
    // also its tangent rows; the line x = 0.55 crosses it at 0.5 -+ sqrt(0.0075).
    Conic d{0.0, 0.0, 0.0, 1.0, 0.0, -0.55, true};
    vs.clear();
    criticalRows({CIRCLE, d}, vs);
    vs = sorted(vs);
    ASSERT_EQ(vs.size(), 4u);
    EXPECT_NEAR(vs[0], 0.4, 1e-9);
    EXPECT_NEAR(vs[1], 0.5 - std::sqrt(0.0075), 1e-12);
    EXPECT_NEAR(vs[2], 0.5 + std::sqrt(0.0075), 1e-12);
    EXPECT_NEAR(vs[3], 0.6, 1e-9);
}

}  // namespace
}  // namespace pcf
