// The covered area of the unit disk against forms derived here independently of the edge sum:
// - beyond a chord at distance u from the centre lies the circular segment
//     acos(u) - u sqrt(1 - u^2);
// - the corner {x >= a, y >= b} (b >= 0, a^2 + b^2 < 1) holds the integral over x in [a, sqrt(1 -
// b^2)]
//   of sqrt(1 - x^2) - b, with the antiderivative F(x) = (x sqrt(1 - x^2) + asin(x)) / 2 of
//   sqrt(1 - x^2);
// - a polygon inside the disk keeps its own area (the shoelace sum), one around it gives pi;
// - any convex polygons against a grid count of the disk's cells (midpoint rule).
#include "measure/light_disk_area.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace pcf {
namespace {

constexpr double PI = std::numbers::pi;

ConvexPolygon box(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

TEST(UnitDiskArea, BeyondAChordIsTheCircularSegment) {
    for (double u : {-0.99, -0.7, -0.3, 0.0, 0.2, 0.5, 0.8, 0.999}) {
        double exact = std::acos(u) - u * std::sqrt(1.0 - u * u);
        EXPECT_NEAR(unitDiskPolygonArea(box(u, -5.0, 5.0, 5.0)), exact, 1e-13) << u;
        // The same half-plane turned by 30 degrees: x cos + y sin >= u.
        double c = std::cos(PI / 6.0), s = std::sin(PI / 6.0);
        ConvexPolygon turned;
        for (glm::dvec2 p : box(u, -5.0, 5.0, 5.0))
            turned.push_back({c * p.x - s * p.y, s * p.x + c * p.y});
        EXPECT_NEAR(unitDiskPolygonArea(turned), exact, 1e-12) << u;
    }
    EXPECT_NEAR(unitDiskPolygonArea(box(1.0, -5.0, 5.0, 5.0)), 0.0, 1e-15);
}

TEST(UnitDiskArea, ACornerIsTheIntegralOfTheCircle) {
    auto F = [](double x) { return 0.5 * (x * std::sqrt(1.0 - x * x) + std::asin(x)); };
    for (glm::dvec2 ab : {glm::dvec2(0.0, 0.0), glm::dvec2(0.3, 0.2), glm::dvec2(-0.6, 0.5),
                          glm::dvec2(0.7, 0.6), glm::dvec2(-0.9, 0.1)}) {
        double top = std::sqrt(1.0 - ab.y * ab.y);
        double exact = F(top) - F(ab.x) - ab.y * (top - ab.x);
        EXPECT_NEAR(unitDiskPolygonArea(box(ab.x, ab.y, 3.0, 3.0)), exact, 1e-13)
            << ab.x << ", " << ab.y;
    }
    EXPECT_NEAR(unitDiskPolygonArea(box(0.0, 0.0, 3.0, 3.0)), PI / 4.0, 1e-14);
}

TEST(UnitDiskArea, InsideKeepsItsAreaAroundGivesPi) {
    ConvexPolygon hexagon;
    for (int k = 0; k < 6; ++k) {
        hexagon.push_back({0.9 * std::cos(k * PI / 3.0) + 0.05, 0.9 * std::sin(k * PI / 3.0)});
    }
    EXPECT_NEAR(unitDiskPolygonArea(hexagon), 1.5 * std::sqrt(3.0) * 0.81, 1e-13);
    EXPECT_FALSE(coversUnitDisk(hexagon));
    ConvexPolygon around = box(-1.5, -1.2, 1.1, 2.0);
    EXPECT_NEAR(unitDiskPolygonArea(around), PI, 1e-13);
    EXPECT_TRUE(coversUnitDisk(around));
    EXPECT_FALSE(coversUnitDisk(box(-1.5, -1.2, 0.99, 2.0)));
    EXPECT_NEAR(unitDiskPolygonArea(box(1.1, 1.1, 3.0, 3.0)), 0.0, 1e-15);  // misses it
}

TEST(UnitDiskArea, IntersectsAndClipsConvexPolygons) {
    ConvexPolygon both = intersectConvex(box(-1.0, -1.0, 1.0, 1.0), box(0.0, 0.5, 2.0, 3.0));
    double area = 0.0;
    for (size_t i = 0; i < both.size(); ++i) {
        glm::dvec2 a = both[i], b = both[(i + 1) % both.size()];
        area += 0.5 * (a.x * b.y - a.y * b.x);
    }
    EXPECT_NEAR(area, 0.5, 1e-15);  // [0, 1] x [0.5, 1], counter-clockwise
    EXPECT_TRUE(intersectConvex(box(0.0, 0.0, 1.0, 1.0), box(2.0, 0.0, 3.0, 1.0)).empty());
}

TEST(UnitDiskArea, UnionsCountOverlapsOnce) {
    // Two half-planes at right angles: three quadrants.
    std::optional<DiskCover> two =
        unitDiskUnionArea({box(0.0, -5.0, 5.0, 5.0), box(-5.0, 0.0, 5.0, 5.0)}, 100);
    ASSERT_TRUE(two);
    EXPECT_NEAR(two->area, 0.75 * PI, 1e-13);
    EXPECT_EQ(two->terms, 3);
    // Three strips, the middle one overlapping both others: the band |x| <= 0.6.
    std::optional<DiskCover> band = unitDiskUnionArea(
        {box(-0.6, -5.0, -0.1, 5.0), box(-0.2, -5.0, 0.2, 5.0), box(0.1, -5.0, 0.6, 5.0)}, 100);
    ASSERT_TRUE(band);
    double u = 0.6;
    double segment = std::acos(u) - u * std::sqrt(1.0 - u * u);
    EXPECT_NEAR(band->area, PI - 2.0 * segment, 1e-13);
    // One polygon around the disk settles it; too many terms give no answer.
    std::optional<DiskCover> whole =
        unitDiskUnionArea({box(0.5, -5.0, 5.0, 5.0), box(-3.0, -3.0, 3.0, 3.0)}, 100);
    ASSERT_TRUE(whole);
    EXPECT_TRUE(whole->whole);
    EXPECT_EQ(whole->area, PI);
    EXPECT_FALSE(unitDiskUnionArea(
        {box(0.0, -5.0, 5.0, 5.0), box(-5.0, 0.0, 5.0, 5.0), box(-0.5, -5.0, 0.5, 5.0)}, 3));
}

// Random convex polygons (hulls of random points), alone and in unions, against the share of
// a fine grid's cell centres that lie in the disk and in some polygon.
bool insideConvex(const ConvexPolygon& p, glm::dvec2 x) {
    for (size_t i = 0; i < p.size(); ++i) {
        glm::dvec2 a = p[i], d = p[(i + 1) % p.size()] - a;
        if (d.x * (x.y - a.y) - d.y * (x.x - a.x) < 0.0) return false;
    }
    return true;
}

ConvexPolygon randomConvex(std::mt19937& rng) {
    std::uniform_real_distribution<double> centre(-1.2, 1.2), size(0.2, 1.5), angle(0.0, 2.0 * PI);
    glm::dvec2 c(centre(rng), centre(rng));
    std::vector<double> angles(5);
    for (double& a : angles) a = angle(rng);
    std::sort(angles.begin(), angles.end());
    ConvexPolygon p;
    double r = size(rng);
    for (double a : angles) p.push_back(c + r * glm::dvec2(std::cos(a), std::sin(a)));
    return p;  // points on a circle in angle order: convex, counter-clockwise
}

TEST(UnitDiskArea, UnionsMatchAGridCount) {
    std::mt19937 rng(7);
    const int n = 1200;
    const double h = 2.0 / n;
    for (int trial = 0; trial < 6; ++trial) {
        std::vector<ConvexPolygon> polys;
        for (int k = 0; k <= trial % 4; ++k) polys.push_back(randomConvex(rng));
        int hits = 0;
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                glm::dvec2 x(-1.0 + (i + 0.5) * h, -1.0 + (j + 0.5) * h);
                if (glm::dot(x, x) > 1.0) continue;
                for (const ConvexPolygon& p : polys) {
                    if (insideConvex(p, x)) {
                        ++hits;
                        break;
                    }
                }
            }
        }
        std::optional<DiskCover> cover = unitDiskUnionArea(polys, 1000);
        ASSERT_TRUE(cover);
        EXPECT_NEAR(cover->area, hits * h * h, 0.01) << "trial " << trial;
    }
}

}  // namespace
}  // namespace pcf
