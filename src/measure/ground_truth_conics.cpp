#include "measure/ground_truth_conics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <variant>

#include "measure/ground_truth_edges.h"

namespace pcf {

namespace {

// A surface an object's points lie on: a plane n . P = k (a rectangle, a box face) or a sphere.
struct Surface {
    bool sphere;
    glm::dvec3 n;  // plane: normal; sphere: centre
    double k;      // plane: offset; sphere: radius
};

std::vector<Surface> surfacesOf(const Primitive& shape) {
    if (const Sphere* s = std::get_if<Sphere>(&shape)) {
        return {{true, glm::dvec3(s->centreWs), static_cast<double>(s->radius)}};
    }
    if (const Plane* p = std::get_if<Plane>(&shape)) {
        glm::dvec3 n(p->normalWs);
        return {{false, n, glm::dot(n, glm::dvec3(p->centreWs))}};
    }
    const Box& b = std::get<Box>(shape);
    BoxAxes ax = boxAxes(b);
    glm::dvec3 centre(b.centreWs);
    std::vector<Surface> faces;
    const glm::dvec3 axes[3] = {ax.xWs, glm::dvec3(0.0, 1.0, 0.0), ax.zWs};
    for (int i = 0; i < 3; ++i) {
        double mid = glm::dot(axes[i], centre);
        double half = b.halfExtents[i];
        faces.push_back({false, axes[i], mid + half});
        faces.push_back({false, axes[i], mid - half});
    }
    return faces;
}

EdgeForm linearForm(const glm::dvec3& m) { return {glm::dmat3(0.0), m, true}; }
EdgeForm quadraticForm(const glm::dmat3& q) { return {q, glm::dvec3(0.0), false}; }

// w (P - x) for the hit P on the plane n . P = k, as a matrix applied to D (w = n . D):
// w (E - x) + h D with h = k - n . E.
glm::dmat3 planeHitFrom(const glm::dvec3& eye, const glm::dvec3& n, double k, const glm::dvec3& x) {
    return glm::outerProduct(eye - x, n) + glm::dmat3(k - glm::dot(n, eye));
}

// The ray meets the circle where the plane n . P = k cuts the sphere (c, r): none when they
// do not meet.
void addCircle(const glm::dvec3& eye, const glm::dvec3& n, double k, const glm::dvec3& c, double r,
               std::vector<EdgeForm>& out) {
    double len = glm::length(n);
    if (!(len > 0.0) || std::abs(glm::dot(n, c) - k) / len > r) return;
    glm::dmat3 m = planeHitFrom(eye, n, k, c);
    out.push_back(quadraticForm(glm::transpose(m) * m - r * r * glm::outerProduct(n, n)));
}

// The ray meets the curve where surfaces s and t cut each other (a line, a circle).
void addCut(const glm::dvec3& eye, const Surface& s, const Surface& t, std::vector<EdgeForm>& out) {
    if (!s.sphere && !t.sphere) {
        // (m . E - l) n . D + h m . D: none for parallel planes (coincident ones cut nowhere
        // that the ray caster can tell apart).
        if (glm::length(glm::cross(s.n, t.n)) <= 1e-12 * glm::length(s.n) * glm::length(t.n)) {
            return;
        }
        double h = s.k - glm::dot(s.n, eye);
        out.push_back(linearForm((glm::dot(t.n, eye) - t.k) * s.n + h * t.n));
    } else if (s.sphere && t.sphere) {
        // Their radical plane: 2 (c2 - c1) . P = |c2|^2 - |c1|^2 + r1^2 - r2^2.
        glm::dvec3 m = 2.0 * (t.n - s.n);
        if (glm::length(m) == 0.0) return;
        double k = glm::dot(t.n, t.n) - glm::dot(s.n, s.n) + s.k * s.k - t.k * t.k;
        addCircle(eye, m, k, s.n, s.k, out);
    } else if (s.sphere) {
        addCircle(eye, t.n, t.k, s.n, s.k, out);
    } else {
        addCircle(eye, s.n, s.k, t.n, t.k, out);
    }
}

// Which object is seen can change at the outline of any object.
void addOutline(const glm::dvec3& eye, const Primitive& shape, std::vector<EdgeForm>& out) {
    if (const Sphere* s = std::get_if<Sphere>(&shape)) {
        glm::dvec3 w = eye - glm::dvec3(s->centreWs);
        double r = s->radius;
        // |W x D|^2 - r^2 |D|^2 = D^T ((|W|^2 - r^2) I - W W^T) D.
        out.push_back(quadraticForm(glm::dmat3(glm::dot(w, w) - r * r) - glm::outerProduct(w, w)));
        return;
    }
    for (const auto& edge : primitiveEdges(shape)) {
        out.push_back(linearForm(glm::cross(edge[0] - eye, edge[1] - eye)));
    }
}

// On a plane surface s: the hit inside a cone with apex l, unit axis a, half-angle cos^2 c2
// (both nappes: a superset).
void addConeOnPlane(const glm::dvec3& eye, const Surface& s, const glm::dvec3& l,
                    const glm::dvec3& a, double c2, std::vector<EdgeForm>& out) {
    glm::dmat3 m = planeHitFrom(eye, s.n, s.k, l);
    glm::dmat3 inner = glm::outerProduct(a, a) - glm::dmat3(c2);
    out.push_back(quadraticForm(glm::transpose(m) * inner * m));
}

// The shadow edges that a caster throws on surface s (false: not conics there).
bool addShadow(const glm::dvec3& eye, const Light& light, const Surface& s, const Primitive& caster,
               std::vector<EdgeForm>& out) {
    bool directional = light.type == LightType::Directional;
    glm::dvec3 travel = glm::normalize(glm::dvec3(light.directionWs));
    glm::dvec3 l(light.positionWs);
    if (const Sphere* k = std::get_if<Sphere>(&caster)) {
        if (s.sphere) return false;  // a cylinder or cone on a sphere: a quartic
        glm::dvec3 c(k->centreWs);
        double r = k->radius;
        if (directional) {
            // |(I - L L^T) w (P - c)|^2 = r^2 w^2: the shadow cylinder's side.
            glm::dmat3 m = planeHitFrom(eye, s.n, s.k, c);
            glm::dmat3 across = glm::dmat3(1.0) - glm::outerProduct(travel, travel);
            out.push_back(quadraticForm(glm::transpose(m) * across * m -
                                        r * r * glm::outerProduct(s.n, s.n)));
            return true;
        }
        double dist = glm::length(c - l);
        if (dist <= r) return true;  // the light inside the caster: everything is in its shadow
        addConeOnPlane(eye, s, l, (c - l) / dist, 1.0 - (r * r) / (dist * dist), out);
        return true;
    }
    // A box or a rectangle: the planes its edges sweep along the light (a superset of the
    // shadow's outline).
    for (const auto& edge : primitiveEdges(caster)) {
        glm::dvec3 m = directional ? glm::cross(edge[1] - edge[0], travel)
                                   : glm::cross(edge[0] - l, edge[1] - l);
        if (glm::length(m) <= 1e-12 * glm::length(edge[1] - edge[0])) continue;
        Surface plane{false, m, glm::dot(m, edge[0])};
        addCut(eye, s, plane, out);
    }
    return true;
}

// The edges of the lit state on surface s of an object (false: not all conics).
bool addLitEdges(const glm::dvec3& eye, const Scene& scene, size_t object, const Surface& s,
                 std::vector<EdgeForm>& out) {
    const Light& light = scene.light;
    bool directional = light.type == LightType::Directional;
    glm::dvec3 travel = glm::normalize(glm::dvec3(light.directionWs));
    glm::dvec3 l(light.positionWs);
    bool exact = true;
    if (s.sphere) {
        // The terminator: the plane through c across L, or (P - c) . (l - c) = r^2 for a spot.
        Surface plane = directional ? Surface{false, travel, glm::dot(travel, s.n)}
                                    : Surface{false, l - s.n, s.k * s.k + glm::dot(l - s.n, s.n)};
        addCut(eye, s, plane, out);
    }
    if (!directional) {
        // The spot's rim: inside when the angle to the axis is <= coneDeg.
        if (s.sphere) {
            exact = false;
        } else {
            double cosCone = std::cos(glm::radians(static_cast<double>(light.coneDeg)));
            addConeOnPlane(eye, s, l, travel, cosCone * cosCone, out);
        }
    }
    if (!scene.objects[object].receivesShadow) return exact;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (i == object || !scene.objects[i].castsShadow) continue;
        exact = addShadow(eye, light, s, scene.objects[i].shape, out) && exact;
    }
    return exact;
}

}  // namespace

EdgeConics::EdgeConics(const Scene& scene, const glm::dvec3& eye) {
    size_t n = scene.objects.size();
    mOutline.resize(n);
    mLit.resize(n);
    mExact.assign(n, true);
    for (size_t o = 0; o < n; ++o) {
        std::vector<Surface> own = surfacesOf(scene.objects[o].shape);
        for (size_t i = 0; i < n; ++i) {
            addOutline(eye, scene.objects[i].shape, mOutline[o]);
            if (i == o) continue;
            // Where another object cuts this one, which of the two is in front changes; its
            // surface also splits its shadow prism into the part upstream and downstream of it.
            for (const Surface& s : own) {
                for (const Surface& t : surfacesOf(scene.objects[i].shape)) {
                    addCut(eye, s, t, mOutline[o]);
                }
            }
        }
        bool exact = true;
        for (const Surface& s : own) exact = addLitEdges(eye, scene, o, s, mLit[o]) && exact;
        mExact[o] = exact;
    }
}

namespace {

// The pixel's conic of a form: D = D0 + x Dx + v Dv substituted, scaled to a largest
// coefficient of 1; false when the form vanishes on the pixel's rays.
bool conicOf(const EdgeForm& form, const glm::dvec3& d0, const glm::dvec3& dx, const glm::dvec3& dv,
             Conic& out) {
    if (form.linear) {
        out = {0.0, 0.0, 0.0, glm::dot(form.m, dx), glm::dot(form.m, dv), glm::dot(form.m, d0),
               true};
    } else {
        glm::dvec3 q0 = form.q * d0;
        glm::dvec3 qx = form.q * dx;
        glm::dvec3 qv = form.q * dv;
        out = {glm::dot(dx, qx),
               2.0 * glm::dot(dx, qv),
               glm::dot(dv, qv),
               2.0 * glm::dot(d0, qx),
               2.0 * glm::dot(d0, qv),
               glm::dot(d0, q0),
               false};
    }
    double scale = std::max({std::abs(out.a), std::abs(out.b), std::abs(out.c), std::abs(out.d),
                             std::abs(out.e), std::abs(out.f)});
    if (!(scale > 0.0) || !std::isfinite(scale)) return false;
    out = {out.a / scale, out.b / scale, out.c / scale, out.d / scale,
           out.e / scale, out.f / scale, out.linear};
    return true;
}

// Roots of a t^2 + b t + c in [lo, hi], appended; a discriminant negative by rounding only
// counts as a double root.
void quadraticRoots(double a, double b, double c, double lo, double hi, std::vector<double>& out) {
    auto keep = [&](double t) {
        if (t >= lo && t <= hi) out.push_back(t);
    };
    if (a == 0.0) {
        if (b != 0.0) keep(-c / b);
        return;
    }
    double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) {
        if (disc < -1e-13 * (b * b + std::abs(4.0 * a * c))) return;
        disc = 0.0;
    }
    double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    if (q == 0.0) {
        keep(0.0);
        return;
    }
    keep(q / a);
    keep(c / q);
}

// The coefficients in x of q(x, v) at row v: a x^2 + (b v + d) x + (c v^2 + e v + f).
struct RowPoly {
    double a2, a1, a0;
};
RowPoly atRow(const Conic& q, double v) { return {q.a, q.b * v + q.d, (q.c * v + q.e) * v + q.f}; }

// Whether the conic meets the pixel's closed square: a root on a side, or (a closed curve
// inside) a tangent to the scanline direction inside.
bool meetsSquare(const Conic& q) {
    constexpr double LO = -1e-9;
    constexpr double HI = 1.0 + 1e-9;
    std::vector<double> roots;
    for (double v : {0.0, 1.0}) {
        RowPoly r = atRow(q, v);
        quadraticRoots(r.a2, r.a1, r.a0, LO, HI, roots);
    }
    quadraticRoots(q.c, q.e, q.f, LO, HI, roots);                    // x = 0
    quadraticRoots(q.c, q.b + q.e, q.a + q.d + q.f, LO, HI, roots);  // x = 1
    if (!roots.empty()) return true;
    if (q.a == 0.0) return false;  // unbounded in x along every row: it would cross a side
    std::vector<double> tangents;
    quadraticRoots(q.b * q.b - 4.0 * q.a * q.c, 2.0 * q.b * q.d - 4.0 * q.a * q.e,
                   q.d * q.d - 4.0 * q.a * q.f, LO, HI, tangents);
    for (double v : tangents) {
        double x = -(q.b * v + q.d) / (2.0 * q.a);
        if (x >= LO && x <= HI) return true;
    }
    return false;
}

}  // namespace

void EdgeConics::pixelConics(int object, bool lit, const glm::dvec3& d0, const glm::dvec3& dx,
                             const glm::dvec3& dv, std::vector<Conic>& out) const {
    out.clear();
    auto add = [&](const std::vector<EdgeForm>& forms) {
        for (const EdgeForm& form : forms) {
            Conic q;
            if (conicOf(form, d0, dx, dv, q) && meetsSquare(q)) out.push_back(q);
        }
    };
    add(mOutline[static_cast<size_t>(object)]);
    if (lit) add(mLit[static_cast<size_t>(object)]);
}

void scanlineCuts(const Conic& q, double v, std::vector<double>& xs) {
    RowPoly r = atRow(q, v);
    size_t before = xs.size();
    quadraticRoots(r.a2, r.a1, r.a0, 0.0, 1.0, xs);
    if (r.a2 != 0.0) {
        double vertex = -r.a1 / (2.0 * r.a2);
        if (vertex > 0.0 && vertex < 1.0) xs.push_back(vertex);
    }
    // Ends of the pixel are cuts already.
    xs.erase(std::remove_if(xs.begin() + static_cast<long>(before), xs.end(),
                            [](double x) { return !(x > 0.0 && x < 1.0); }),
             xs.end());
}

namespace {

using Poly = std::array<double, 5>;  // sum p[k] v^k, degree <= 4

double evaluate(const double* p, int degree, double t) {
    double y = 0.0;
    for (int k = degree; k >= 0; --k) y = y * t + p[k];
    return y;
}

Poly times(const Poly& p, const Poly& q) {
    Poly r{};
    for (size_t i = 0; i < 5; ++i) {
        for (size_t j = 0; i + j < 5; ++j) r[i + j] += p[i] * q[j];
    }
    return r;
}

Poly minus(const Poly& p, const Poly& q) {
    Poly r{};
    for (size_t i = 0; i < 5; ++i) r[i] = p[i] - q[i];
    return r;
}

Poly plus(const Poly& p, const Poly& q) {
    Poly r{};
    for (size_t i = 0; i < 5; ++i) r[i] = p[i] + q[i];
    return r;
}

// The conic's coefficients in x as polynomials in v: a2 x^2 + a1 x + a0.
struct InX {
    Poly a2, a1, a0;
};
InX inX(const Conic& q) { return {{q.a, 0, 0, 0, 0}, {q.d, q.b, 0, 0, 0}, {q.f, q.e, q.c, 0, 0}}; }

// The resultant in x of two conics, a polynomial in v that vanishes at every v where they share
// a point (Sylvester's determinant: for p2 x^2 + p1 x + p0 and q2 x^2 + q1 x + q0 it is
// (p2 q0 - q2 p0)^2 - (p2 q1 - q2 p1)(p1 q0 - q1 p0); for p against a line q1 x + q0 it is
// p2 q0^2 - p1 q1 q0 + p0 q1^2; for two lines p1 q0 - q1 p0).
Poly resultant(const Conic& p, const Conic& q) {
    InX s = inX(p);
    InX t = inX(q);
    if (p.a != 0.0 && q.a != 0.0) {
        Poly ac = minus(times(s.a2, t.a0), times(t.a2, s.a0));
        Poly ab = minus(times(s.a2, t.a1), times(t.a2, s.a1));
        Poly bc = minus(times(s.a1, t.a0), times(t.a1, s.a0));
        return minus(times(ac, ac), times(ab, bc));
    }
    if (p.a == 0.0 && q.a == 0.0) return minus(times(s.a1, t.a0), times(t.a1, s.a0));
    if (p.a == 0.0) std::swap(s, t);
    return plus(minus(times(s.a2, times(t.a0, t.a0)), times(times(s.a1, t.a1), t.a0)),
                times(s.a0, times(t.a1, t.a1)));
}

// Whether the conic has a point on row v with x in [-margin, 1 + margin].
bool onRowNearPixel(const Conic& q, double v, double margin) {
    RowPoly r = atRow(q, v);
    std::vector<double> xs;
    quadraticRoots(r.a2, r.a1, r.a0, -margin, 1.0 + margin, xs);
    return !xs.empty();
}

// The roots in [0,1] of a polynomial in v scaled to a largest coefficient of 1 (none when it is
// 0 throughout: the same curve twice), double roots included.
void rootsInPixel(Poly p, std::vector<double>& out) {
    double scale = 0.0;
    for (double c : p) scale = std::max(scale, std::abs(c));
    if (!(scale > 1e-14)) return;
    for (double& c : p) c /= scale;
    polynomialRoots(p.data(), 4, 0.0, 1.0, out, true, 1e-11);
}

}  // namespace

void polynomialRoots(const double* p, int degree, double lo, double hi, std::vector<double>& out,
                     bool touching, double touchTolerance) {
    while (degree > 0 && p[degree] == 0.0) --degree;
    if (degree <= 0) return;
    if (degree == 1) {
        double t = -p[0] / p[1];
        if (t >= lo && t <= hi) out.push_back(t);
        return;
    }
    // Between consecutive roots of the derivative the polynomial is monotone: at most one root,
    // found by bisection where the sign changes.
    double dp[4];
    for (int k = 1; k <= degree; ++k) dp[k - 1] = k * p[k];
    std::vector<double> ends{lo};
    polynomialRoots(dp, degree - 1, lo, hi, ends);
    ends.push_back(hi);
    std::sort(ends.begin(), ends.end());
    for (size_t i = 0; i + 1 < ends.size(); ++i) {
        double a = ends[i];
        double b = ends[i + 1];
        double fa = evaluate(p, degree, a);
        double fb = evaluate(p, degree, b);
        if (fa == 0.0) out.push_back(a);
        if (i > 0 && touching && fa != 0.0 && std::abs(fa) <= touchTolerance) out.push_back(a);
        if (!((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0))) continue;
        for (int step = 0; step < 200 && b - a > 1e-15 * std::max(1.0, std::abs(a)); ++step) {
            double m = 0.5 * (a + b);
            double fm = evaluate(p, degree, m);
            if (fm == 0.0) {
                a = b = m;
                break;
            }
            ((fm < 0.0) == (fa < 0.0) ? a : b) = m;
        }
        out.push_back(0.5 * (a + b));
    }
    if (evaluate(p, degree, hi) == 0.0) out.push_back(hi);
}

void criticalRows(const std::vector<Conic>& conics, std::vector<double>& vs) {
    constexpr double MARGIN = 1e-6;
    std::vector<double> found;
    for (const Conic& q : conics) {
        // Through the sides x = 0 and x = 1.
        quadraticRoots(q.c, q.e, q.f, 0.0, 1.0, found);
        quadraticRoots(q.c, q.b + q.e, q.a + q.d + q.f, 0.0, 1.0, found);
        if (q.a != 0.0) {
            // Tangent to the row direction inside the pixel: disc(v) = 0, at x = -(b v + d) / 2a.
            std::vector<double> tangents;
            Poly disc{q.d * q.d - 4.0 * q.a * q.f, 2.0 * q.b * q.d - 4.0 * q.a * q.e,
                      q.b * q.b - 4.0 * q.a * q.c, 0.0, 0.0};
            rootsInPixel(disc, tangents);
            for (double v : tangents) {
                double x = -(q.b * v + q.d) / (2.0 * q.a);
                if (x >= -MARGIN && x <= 1.0 + MARGIN) found.push_back(v);
            }
        } else if (q.b != 0.0 || q.d != 0.0) {
            // x = -(c v^2 + e v + f) / (b v + d) runs off to infinity where b v + d = 0.
            if (q.b != 0.0) found.push_back(-q.d / q.b);
        } else {
            quadraticRoots(q.c, q.e, q.f, 0.0, 1.0, found);  // rows along the curve
        }
    }
    // Crossings of two conics inside the pixel (or near it: a superset).
    for (size_t i = 0; i < conics.size(); ++i) {
        for (size_t j = i + 1; j < conics.size(); ++j) {
            std::vector<double> roots;
            rootsInPixel(resultant(conics[i], conics[j]), roots);
            for (double v : roots) {
                if (onRowNearPixel(conics[i], v, MARGIN) && onRowNearPixel(conics[j], v, MARGIN)) {
                    found.push_back(v);
                }
            }
        }
    }
    for (double v : found) {
        if (v > 0.0 && v < 1.0) vs.push_back(v);
    }
}

}  // namespace pcf
