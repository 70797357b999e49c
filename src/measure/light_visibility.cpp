#include "measure/light_visibility.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "measure/ground_truth_edges.h"
#include "measure/light_disk_shadow.h"
#include "scene/light.h"

namespace pcf {

namespace {

constexpr double INF = std::numeric_limits<double>::infinity();
constexpr double PI = std::numbers::pi;

struct Interval {
    double lo, hi;
};

// The plane through p and one chord of the light disk, p at the origin: x along the chord, y
// toward it; the chord is the line y = d, its point a (the disk's own coordinate) at x = x0 + a.
// finite: the disk is a spot's, at its place: the chord's line is where this plane meets the
// disk's, and what lies beyond it (y > d) is behind the light.
struct ChordPlane {
    glm::dvec3 p, u, v, n;
    double d, x0;
    bool finite;
    glm::dvec2 at(const glm::dvec3& q) const { return {glm::dot(q - p, u), glm::dot(q - p, v)}; }
};

// The part of a convex polygon (or segment, or point) with y <= d: one half-plane of
// Sutherland and Hodgman, "Reentrant Polygon Clipping" (CACM, 1974).
std::vector<glm::dvec2> clipBelow(const std::vector<glm::dvec2>& poly, double d) {
    std::vector<glm::dvec2> out;
    size_t n = poly.size();
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec2& a = poly[i];
        const glm::dvec2& b = poly[(i + 1) % n];
        if (a.y <= d) out.push_back(a);
        if ((a.y <= d) != (b.y <= d)) out.push_back(a + (b - a) * ((d - a.y) / (b.y - a.y)));
    }
    return out;
}

// The chord's points reached by the rays from p at angles [phiLo, phiHi] (from +x, in the
// plane): the rays toward the chord have angles in (0, pi), and the ray at angle phi meets it
// at x = d cot(phi), falling as phi grows.
std::optional<Interval> chordInterval(double phiLo, double phiHi, const ChordPlane& c) {
    for (double shift : {-2.0 * PI, 0.0, 2.0 * PI}) {
        double lo = std::max(phiLo + shift, 0.0);
        double hi = std::min(phiHi + shift, PI);
        if (!(lo < hi)) continue;
        double xLo = hi >= PI ? -INF : c.d * std::cos(hi) / std::sin(hi);
        double xHi = lo <= 0.0 ? INF : c.d * std::cos(lo) / std::sin(lo);
        return Interval{xLo - c.x0, xHi - c.x0};
    }
    return std::nullopt;
}

// A sphere's slice is a disk (centre q, radius s): the rays from p through it span the angle
// atan2(q) +- asin(s / |q|); p inside it sees nothing past it.
std::optional<Interval> sphereInterval(const Sphere& sphere, const ChordPlane& c) {
    glm::dvec3 centre(sphere.centreWs);
    double off = glm::dot(centre - c.p, c.n);
    double r = sphere.radius;
    double s2 = r * r - off * off;
    if (s2 <= 0.0) return std::nullopt;
    glm::dvec2 q = c.at(centre);
    double dist = glm::length(q);
    double s = std::sqrt(s2);
    if (dist <= s) return Interval{-INF, INF};
    double phi = std::atan2(q.y, q.x);
    double half = std::asin(s / dist);
    return chordInterval(phi - half, phi + half, c);
}

// A box's or a rectangle's slice: the points where its edges cross the plane, a convex polygon
// (or a segment); the rays through it span the angles of its vertices.
std::optional<Interval> polygonInterval(const Primitive& shape, const ChordPlane& c) {
    std::vector<glm::dvec2> pts;
    for (const auto& e : primitiveEdges(shape)) {
        double sa = glm::dot(e[0] - c.p, c.n);
        double sb = glm::dot(e[1] - c.p, c.n);
        if ((sa > 0.0 && sb > 0.0) || (sa < 0.0 && sb < 0.0)) continue;
        if (sa == sb) {  // the edge lies in the plane
            pts.push_back(c.at(e[0]));
            pts.push_back(c.at(e[1]));
            continue;
        }
        double t = sa / (sa - sb);
        pts.push_back(c.at(e[0] + (e[1] - e[0]) * t));
    }
    if (pts.empty()) return std::nullopt;
    std::vector<glm::dvec2> hull = convexHull2d(std::move(pts));
    if (c.finite) {
        hull = clipBelow(hull, c.d);
        if (hull.empty()) return std::nullopt;
    }
    if (hull.size() >= 3) {
        bool inside = true;
        for (size_t i = 0; i < hull.size(); ++i) {
            const glm::dvec2& a = hull[i];
            const glm::dvec2& b = hull[(i + 1) % hull.size()];
            inside = inside && (b.x - a.x) * (-a.y) - (b.y - a.y) * (-a.x) > 0.0;
        }
        if (inside) return Interval{-INF, INF};
    }
    glm::dvec2 mean(0.0);
    for (const glm::dvec2& h : hull) mean += h;
    mean /= static_cast<double>(hull.size());
    if (glm::length(mean) == 0.0) return Interval{-INF, INF};
    double ref = std::atan2(mean.y, mean.x);
    double lo = INF, hi = -INF;
    for (const glm::dvec2& h : hull) {
        // The angle of each vertex from the mean's direction, in (-pi, pi].
        double delta = std::atan2(mean.x * h.y - mean.y * h.x, glm::dot(mean, h));
        lo = std::min(lo, delta);
        hi = std::max(hi, delta);
    }
    return chordInterval(ref + lo, ref + hi, c);
}

// The chord's blocked length: casters' intervals and the horizon, merged, within [-w, w].
double chordVisible(const Scene& scene, const ChordPlane& c, glm::dvec3 e1, glm::dvec3 facing,
                    int object, double w) {
    std::vector<Interval> blocked;
    // The horizon: the light point ahead of p's tangent plane, n . ((x0 + a) u + d v) > 0.
    double k = glm::dot(facing, c.u * c.x0 + c.v * c.d);
    double slope = glm::dot(facing, e1);
    if (std::abs(slope) < 1e-300) {
        if (k <= 0.0) return 0.0;
    } else if (slope > 0.0) {
        blocked.push_back({-INF, -k / slope});
    } else {
        blocked.push_back({-k / slope, INF});
    }
    bool receives = object < 0 || scene.objects[static_cast<size_t>(object)].receivesShadow;
    for (size_t i = 0; receives && i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        if (!o.castsShadow || static_cast<int>(i) == object) continue;
        std::optional<Interval> iv = std::holds_alternative<Sphere>(o.shape)
                                         ? sphereInterval(std::get<Sphere>(o.shape), c)
                                         : polygonInterval(o.shape, c);
        if (iv) blocked.push_back(*iv);
    }
    std::sort(blocked.begin(), blocked.end(),
              [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
    double covered = 0.0;
    double end = -w;
    for (const Interval& iv : blocked) {
        double lo = std::max(iv.lo, end);
        double hi = std::min(iv.hi, w);
        if (hi > lo) {
            covered += hi - lo;
            end = hi;
        }
    }
    return std::max(0.0, 2.0 * w - covered);
}

constexpr int MAX_CHORDS = 257;

struct DiskIntegral {
    double visible;  // the fraction
    double bound;
};

// The visible and the blocked length of one chord, each times its share of the disk.
struct ChordValue {
    double v, b;
};

// A panel [a, b] of theta with the chord values at its ends and middle: the visible (v) and the
// blocked (b2) length by the trapezoid rule on its two halves, and the error of each and of
// their sum, estimated as twice the difference from the rule on the whole panel.
struct ChordPanel {
    double a, b;
    ChordValue ga, gm, gb;
    double v, b2, errV, errB, errT;
};

ChordPanel makeChordPanel(double a, double b, ChordValue ga, ChordValue gm, ChordValue gb) {
    double h = b - a;
    auto fine = [&](double ChordValue::*m) { return 0.25 * h * (ga.*m + 2.0 * gm.*m + gb.*m); };
    auto coarse = [&](double ChordValue::*m) { return 0.5 * h * (ga.*m + gb.*m); };
    double v = fine(&ChordValue::v), bl = fine(&ChordValue::b);
    double dv = v - coarse(&ChordValue::v), db = bl - coarse(&ChordValue::b);
    return ChordPanel{
        a, b, ga, gm, gb, v, bl, 2.0 * std::abs(dv), 2.0 * std::abs(db), 2.0 * std::abs(dv + db)};
}

// f by chords along `along`, stacked along `across` (both unit, in the disk's plane), of the
// disk of `radius` about `centre`, from `firstPanels` panels in theta. The visible and the blocked
// length are integrated by the same rule and f = V / (V + B): a point that sees all of the disk (B
// = 0 on every chord) or none of it gets exactly 1 or 0. Its error is at most min(e_V, e_B) / (V +
// B) plus f's share of the rule's error on the chord lengths, which are smooth (cos^2).
DiskIntegral integrateDisk(const Scene& scene, glm::dvec3 posWs, glm::dvec3 facingWs, int object,
                           double target, glm::dvec3 centre, bool finite, glm::dvec3 along,
                           glm::dvec3 across, double radius, int firstPanels) {
    // The chord at height R sin(theta), weighted by its share R cos(theta) dtheta.
    auto g = [&](double theta) {
        double h = radius * std::sin(theta);
        double w = radius * std::cos(theta);
        glm::dvec3 toChord = centre + across * h - posWs;
        double x0 = glm::dot(toChord, along);
        glm::dvec3 perp = toChord - along * x0;
        double d = glm::length(perp);
        glm::dvec3 v = perp / d;
        ChordPlane c{posWs, along, v, glm::cross(along, v), d, x0, finite};
        double visible = chordVisible(scene, c, along, facingWs, object, w);
        return ChordValue{visible * w, (2.0 * w - visible) * w};
    };
    std::vector<ChordPanel> panels;
    double step = PI / firstPanels;
    ChordValue gPrev = g(-0.5 * PI);
    for (int k = 0; k < firstPanels; ++k) {
        double a = -0.5 * PI + k * step;
        ChordValue gEnd = g(a + step);
        panels.push_back(makeChordPanel(a, a + step, gPrev, g(a + 0.5 * step), gEnd));
        gPrev = gEnd;
    }
    int chords = 2 * firstPanels + 1;
    for (;;) {
        double v = 0.0, bl = 0.0, errV = 0.0, errB = 0.0, errT = 0.0;
        size_t worst = 0;
        for (size_t k = 0; k < panels.size(); ++k) {
            v += panels[k].v;
            bl += panels[k].b2;
            errV += panels[k].errV;
            errB += panels[k].errB;
            errT += panels[k].errT;
            if (panels[k].errV + panels[k].errB > panels[worst].errV + panels[worst].errB) {
                worst = k;
            }
        }
        double total = v + bl;
        double f = total > 0.0 ? v / total : 1.0;
        double bound =
            total > 0.0 ? (std::min(errV + f * errT, errB + (1.0 - f) * errT)) / total : 1.0;
        if (bound <= target || chords + 2 > std::max(MAX_CHORDS, 4 * firstPanels + 1)) {
            return {std::clamp(f, 0.0, 1.0), bound};
        }
        ChordPanel p = panels[worst];
        double m = 0.5 * (p.a + p.b);
        ChordValue q1 = g(0.5 * (p.a + m));
        ChordValue q3 = g(0.5 * (m + p.b));
        chords += 2;
        panels[worst] = makeChordPanel(p.a, m, p.ga, q1, p.gm);
        panels.push_back(makeChordPanel(m, p.b, p.gm, q3, p.gb));
    }
}

// Two unit vectors across `axis` (unit), and across each other.
std::pair<glm::dvec3, glm::dvec3> acrossAxis(glm::dvec3 axis) {
    glm::dvec3 helper = std::abs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    glm::dvec3 e1 = glm::normalize(glm::cross(axis, helper));
    return {e1, glm::cross(axis, e1)};
}

}  // namespace

void checkSpotDiskCasters(const Scene& scene) {
    const Light& light = scene.light;
    if (light.type != LightType::Spot) return;
    glm::dvec3 axis = glm::normalize(glm::dvec3(light.directionWs));
    for (const SceneObject& o : scene.objects) {
        const Sphere* s = std::get_if<Sphere>(&o.shape);
        if (!o.castsShadow || s == nullptr) continue;
        double ahead = glm::dot(glm::dvec3(s->centreWs) - glm::dvec3(light.positionWs), axis);
        if (ahead < static_cast<double>(s->radius)) {
            throw std::invalid_argument(
                "the area-light truth of a spot light with a radius: sphere '" + o.name +
                "' reaches behind the light's disk");
        }
    }
}

namespace {

// The light's disk seen from posWs, or nullopt for a spot's point outside its cone (which sees
// nothing of the light). Throws for a light without a size.
std::optional<LightDiskView> diskFor(const Light& light, glm::dvec3 posWs) {
    if (!hasSize(light)) {
        throw std::invalid_argument("lightVisibleFraction: needs a light with a size");
    }
    if (light.type == LightType::Directional) {
        glm::dvec3 travel = glm::normalize(glm::dvec3(light.directionWs));
        auto [e1, e2] = acrossAxis(travel);
        // The gnomonic disk one unit toward the light.
        return LightDiskView{
            posWs,
            posWs - travel,
            e1,
            e2,
            std::tan(0.5 * glm::radians(static_cast<double>(light.angularDiameterDeg))),
            false};
    }
    // The spot's cone is its centre's: a point outside it gets no light at all.
    if (!towardLight(light, glm::vec3(posWs)).insideCone) return std::nullopt;
    glm::dvec3 axis = glm::normalize(glm::dvec3(light.directionWs));
    auto [e1, e2] = acrossAxis(axis);
    return LightDiskView{posWs, glm::dvec3(light.positionWs),      e1,
                         e2,    static_cast<double>(light.radius), true};
}

// Chords one way and across: a sliver of the disk thinner than the chords' spacing and parallel
// to them escapes one integral but not the other, so they are compared: the mean, with half
// their difference added to the worse bound. More first panels while that is above the target.
LightFraction slicedFraction(const Scene& scene, const LightDiskView& disk, glm::dvec3 facingWs,
                             int object, double target) {
    DiskIntegral a{}, b{};
    for (int first : {8, 32, 128}) {
        a = integrateDisk(scene, disk.p, facingWs, object, target, disk.centre, disk.finite,
                          disk.e1, disk.e2, disk.radius, first);
        b = integrateDisk(scene, disk.p, facingWs, object, target, disk.centre, disk.finite,
                          disk.e2, -disk.e1, disk.radius, first);
        double bound = 0.5 * std::abs(a.visible - b.visible) + std::max(a.bound, b.bound);
        if (bound <= target || first == 128) {
            return {0.5 * (a.visible + b.visible), bound};
        }
    }
    return {0.5 * (a.visible + b.visible), 1.0};
}

}  // namespace

LightFraction lightVisibleFraction(const Scene& scene, glm::dvec3 posWs, glm::dvec3 facingWs,
                                   int object, double target) {
    std::optional<LightDiskView> disk = diskFor(scene.light, posWs);
    if (!disk) return {0.0, 0.0};
    if (std::optional<LightFraction> f =
            diskFractionClosedForm(scene, *disk, facingWs, object, target)) {
        return *f;
    }
    return slicedFraction(scene, *disk, facingWs, object, target);
}

LightFraction lightVisibleFractionBySlices(const Scene& scene, glm::dvec3 posWs,
                                           glm::dvec3 facingWs, int object, double target) {
    std::optional<LightDiskView> disk = diskFor(scene.light, posWs);
    if (!disk) return {0.0, 0.0};
    return slicedFraction(scene, *disk, facingWs, object, target);
}

}  // namespace pcf
