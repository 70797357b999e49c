#include "measure/ground_truth_area.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

#include "measure/light_visibility.h"

namespace pcf {

namespace {

// Light-fraction evaluations per run of an area light's scanline, at most.
constexpr int MAX_AREA_EVALUATIONS = 33;

// The surface a piece of a scanline lies on, in double: a plane n . P = k (a box's face, with
// its outward normal, or a rectangle's plane) or a sphere (centre n, radius k); `face` tells a
// box's six apart; side: +1 where the camera sees its outside, -1 its inside.
struct PieceSurface {
    int face;
    bool sphere;
    glm::dvec3 n;
    double k;
    double side;
};

PieceSurface surfaceOf(const Primitive& shape, const Hit& hit) {
    double side = hit.frontFace ? 1.0 : -1.0;
    if (const Sphere* s = std::get_if<Sphere>(&shape)) {
        return {0, true, glm::dvec3(s->centreWs), static_cast<double>(s->radius), side};
    }
    if (const Plane* p = std::get_if<Plane>(&shape)) {
        glm::dvec3 n = glm::normalize(glm::dvec3(p->normalWs));
        return {0, false, n, glm::dot(n, glm::dvec3(p->centreWs)), side};
    }
    // A box's face: the axis the hit's normal lies along, and its sign.
    const Box& b = std::get<Box>(shape);
    BoxAxes ax = boxAxes(b);
    const glm::dvec3 axes[3] = {ax.xWs, glm::dvec3(0.0, 1.0, 0.0), ax.zWs};
    glm::dvec3 normal(hit.normalWs);
    int best = 0;
    for (int i = 1; i < 3; ++i) {
        if (std::abs(glm::dot(normal, axes[i])) > std::abs(glm::dot(normal, axes[best]))) best = i;
    }
    double sign = glm::dot(normal, axes[best]) >= 0.0 ? 1.0 : -1.0;
    glm::dvec3 n = axes[best] * sign;
    double k = glm::dot(n, glm::dvec3(b.centreWs)) + static_cast<double>(b.halfExtents[best]);
    return {2 * best + (sign > 0.0 ? 0 : 1), false, n, k, side};
}

struct SurfacePoint {
    glm::dvec3 pos;
    glm::dvec3 facing;  // the unit normal on the side the camera sees
};

// Where the ray eye + t dir (dir not normalised) meets the surface: a plane anywhere along it;
// a sphere at the nearer root seen from outside, the farther from inside, and where the ray
// misses it by rounding (at the silhouette) at the ray's closest point, put on the sphere.
SurfacePoint meetSurface(const PieceSurface& s, const glm::dvec3& eye, const glm::dvec3& dir) {
    if (!s.sphere) {
        double t = (s.k - glm::dot(s.n, eye)) / glm::dot(s.n, dir);
        return {eye + dir * t, s.n * s.side};
    }
    glm::dvec3 oc = eye - s.n;
    double a = glm::dot(dir, dir);
    double b = glm::dot(oc, dir);
    double c = glm::dot(oc, oc) - s.k * s.k;
    double disc = b * b - a * c;
    double root = disc > 0.0 ? std::sqrt(disc) : 0.0;
    double t = (-b - s.side * root) / a;
    glm::dvec3 radial = glm::normalize(eye + dir * t - s.n);
    return {s.n + radial * s.k, radial * s.side};
}

// A run of the scanline on one surface: [a, b] in the pixel's x.
struct SurfaceRun {
    double a, b;
    PieceSurface surface;
};

// The integral of f along one run of scanline y (window row), into lit and litErr: the adaptive
// trapezoid rule of ground_truth_area.h.
void integrateRun(const AreaLine& line, const SurfaceRun& run, double y, Scanline& out) {
    struct RunPanel {
        double a, b, fa, fm, fb, fine, err;
    };
    double worstF = 0.0;
    auto at = [&](double x) {
        glm::dvec3 dir = line.rays.rawAt({static_cast<double>(line.pixel.x) + x, y});
        SurfacePoint p = meetSurface(run.surface, line.rays.eyeD, dir);
        LightFraction here =
            line.bySlices
                ? lightVisibleFractionBySlices(line.scene, p.pos, p.facing, line.object,
                                               line.fTarget)
                : lightVisibleFraction(line.scene, p.pos, p.facing, line.object, line.fTarget);
        worstF = std::max(worstF, here.bound);
        return here.visible;
    };
    auto make = [](double a, double b, double fa, double fm, double fb) {
        double h = b - a;
        double fine = 0.25 * h * (fa + 2.0 * fm + fb);
        return RunPanel{a, b, fa, fm, fb, fine, 2.0 * std::abs(fine - 0.5 * h * (fa + fb))};
    };
    double x0 = run.a, x1 = run.b;
    double xm = 0.5 * (x0 + x1);
    double f0 = at(x0), fm = at(xm), f1 = at(x1);
    thread_local std::vector<RunPanel> panels;
    panels.assign(
        {make(x0, xm, f0, at(0.5 * (x0 + xm)), fm), make(xm, x1, fm, at(0.5 * (xm + x1)), f1)});
    for (int evaluations = 5;; evaluations += 2) {
        double sum = 0.0, err = 0.0;
        size_t worst = 0;
        for (size_t k = 0; k < panels.size(); ++k) {
            sum += panels[k].fine;
            err += panels[k].err;
            if (panels[k].err > panels[worst].err) worst = k;
        }
        if (err <= line.xTarget * (x1 - x0) || evaluations + 2 > MAX_AREA_EVALUATIONS) {
            out.lit += sum;
            out.litErr += err + worstF * (x1 - x0);
            return;
        }
        RunPanel p = panels[worst];
        double m = 0.5 * (p.a + p.b);
        panels[worst] = make(p.a, m, p.fa, at(0.5 * (p.a + m)), p.fm);
        panels.push_back(make(m, p.b, p.fm, at(0.5 * (m + p.b)), p.fb));
    }
}

}  // namespace

Scanline AreaLine::operator()(double v) const {
    double y = static_cast<double>(pixel.y) + v;
    thread_local std::vector<double> xs;
    xs.assign(1, 0.0);
    for (const Conic& q : *outline) scanlineCuts(q, v, xs);
    xs.push_back(1.0);
    std::sort(xs.begin(), xs.end());
    const Primitive& shape = scene.objects[static_cast<size_t>(object)].shape;
    Scanline line;
    thread_local std::vector<SurfaceRun> runs;
    runs.clear();
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
        double length = xs[i + 1] - xs[i];
        if (!(length > 0.0)) continue;
        double x = static_cast<double>(pixel.x) + 0.5 * (xs[i] + xs[i + 1]);
        std::optional<Hit> hit = intersect(scene, rays.at({x, y}));
        if (!hit || hit->object != object) continue;
        line.on += length;
        if (length < UNSURE_PX) {
            line.onErr += length;
            line.litErr += length;
        }
        PieceSurface s = surfaceOf(shape, *hit);
        if (!runs.empty() && runs.back().b == xs[i] && runs.back().surface.face == s.face &&
            runs.back().surface.side == s.side) {
            runs.back().b = xs[i + 1];
        } else {
            runs.push_back({xs[i], xs[i + 1], s});
        }
    }
    for (const SurfaceRun& run : runs) integrateRun(*this, run, y, line);
    return line;
}

}  // namespace pcf
