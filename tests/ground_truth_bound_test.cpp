// The ground truth's bound is a bound: on the sphere-over-plane preset (a sphere above a ground
// plane under a directional light) every pixel's truth lies within its stated bound of the
// exact coverage, including at the sphere's terminator where it grazes the silhouette (thin
// slivers that the first pass's samples and their neighbours' all miss) and at the pixels the
// held-out campaign of issue 24 (finding 15) found outside their bound.
//
// The exact coverage is computed here without the truth's search: along a scanline the camera
// ray's direction is linear in the window x, d(x) = A + B x (not normalised), so every place
// where the answer can change is a root of a polynomial of degree <= 2 in x:
//   silhouette of the sphere (centre c, radius r, f = c - eye): |d|^2 (|f|^2 - r^2) = (f.d)^2
//   terminator (where the ray meets the plane through c across L on the sphere):
//     w = (eye - c)(d.L) + ((c - eye).L) d,  |w|^2 = r^2 (d.L)^2
//   sphere's shadow on the ground (n, p0): the ground point minus c, times n.d, is
//     G = (eye - c)(n.d) + (n.(p0 - eye)) d; its part across L has length r |n.d|
//   the ground's edges and horizon: linear.
// Between consecutive roots the state is constant; it is read at the middle with the exact ray
// caster. The scanline integral is the midpoint rule over REF_SCANLINES rows (lit and on are
// continuous in v; its error is below REF_ERROR at a tangent point, h^1.5 = 9e-5).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "measure/ground_truth.h"
#include "scene/presets.h"
#include "scene/raycast.h"
#include "scene/scene_file.h"

namespace pcf {
namespace {

constexpr int REF_SCANLINES = 512;
constexpr double REF_ERROR = 1e-4;

struct Exact {
    double visibility;
    bool hit;
};

// Real roots of a x^2 + b x + c in (lo, hi), appended to `out`.
void addRoots(double a, double b, double c, double lo, double hi, std::vector<double>& out) {
    auto keep = [&](double x) {
        if (x > lo && x < hi) out.push_back(x);
    };
    double scale = std::max({std::abs(a), std::abs(b), std::abs(c)});
    if (scale == 0.0) return;
    if (std::abs(a) <= 1e-14 * scale) {
        if (b != 0.0) keep(-c / b);
        return;
    }
    double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return;
    double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    keep(q / a);
    if (q != 0.0) keep(c / q);
}

// |P + Q x|^2 - k2 (s + t x)^2 = 0 for x in (lo, hi).
void addNormRoots(glm::dvec3 p, glm::dvec3 q, double k2, double s, double t, double lo, double hi,
                  std::vector<double>& out) {
    addRoots(glm::dot(q, q) - k2 * t * t, 2.0 * (glm::dot(p, q) - k2 * s * t),
             glm::dot(p, p) - k2 * s * s, lo, hi, out);
}

class ExactCoverage {
  public:
    ExactCoverage(const Scene& scene, glm::ivec2 size) : mScene(scene), mSize(size) {
        const Camera& cam = scene.camera;
        mEye = glm::dvec3(cam.eyeWs);
        mF = glm::normalize(glm::dvec3(cam.targetWs) - mEye);
        mS = glm::normalize(glm::cross(mF, glm::dvec3(cam.upWs)));
        mU = glm::cross(mS, mF);
        mTan = std::tan(0.5 * glm::radians(static_cast<double>(cam.fovYDeg)));
        mAspect = static_cast<double>(size.x) / size.y;
        mGround = std::get<Plane>(scene.objects[0].shape);
        mSphere = std::get<Sphere>(scene.objects[1].shape);
        mL = glm::normalize(glm::dvec3(scene.light.directionWs));
    }

    // d(x) = A + B x at window height y (GL, pixels).
    void line(double y, glm::dvec3& a, glm::dvec3& b) const {
        double ndcY = y / mSize.y * 2.0 - 1.0;
        b = mS * (2.0 / mSize.x * mAspect * mTan);
        a = mF - mS * (mAspect * mTan) + mU * (ndcY * mTan);
    }

    int stateAt(double x, double y, int object) const {
        glm::dvec3 a, b;
        line(y, a, b);
        Ray ray{glm::vec3(mEye), glm::vec3(glm::normalize(a + b * x))};
        std::optional<Hit> hit = intersect(mScene, ray);
        if (!hit || hit->object != object) return 2;
        return litByLight(mScene, *hit) ? 1 : 0;
    }

    // Every x in (lo, hi) at height y where the state may change; with `labels`, also which
    // curve each is a root of (in the same order as the sorted x).
    std::vector<double> changes(double y, double lo, double hi,
                                std::vector<int>* labels = nullptr) const {
        glm::dvec3 a, b;
        line(y, a, b);
        std::vector<double> xs;
        std::vector<int> curve;
        int group = 0;
        auto tag = [&] { curve.resize(xs.size(), group++); };
        glm::dvec3 c(mSphere.centreWs);
        double r = mSphere.radius;
        glm::dvec3 f = c - mEye;
        // Silhouette: |d|^2 (|f|^2 - r^2) - (f.d)^2 = 0 (the ray's distance from c is r).
        {
            double fa = glm::dot(f, a), fb = glm::dot(f, b);
            double k = glm::dot(f, f) - r * r;
            addRoots(glm::dot(b, b) * k - fb * fb, 2.0 * (glm::dot(a, b) * k - fa * fb),
                     glm::dot(a, a) * k - fa * fa, lo, hi, xs);
            tag();
        }
        // Terminator.
        double cl = glm::dot(c - mEye, mL);
        addNormRoots((mEye - c) * glm::dot(a, mL) + cl * a, (mEye - c) * glm::dot(b, mL) + cl * b,
                     r * r, glm::dot(a, mL), glm::dot(b, mL), lo, hi, xs);
        tag();
        // The sphere's shadow on the ground: G across L has length r |n.d|.
        glm::dvec3 n(mGround.normalWs);
        glm::dvec3 p0(mGround.centreWs);
        double h = glm::dot(n, p0 - mEye);
        auto across = [&](glm::dvec3 v) { return v - mL * glm::dot(v, mL); };
        addNormRoots(across((mEye - c) * glm::dot(n, a) + h * a),
                     across((mEye - c) * glm::dot(n, b) + h * b), r * r, glm::dot(n, a),
                     glm::dot(n, b), lo, hi, xs);
        tag();
        // The ground's horizon and its four edges: (hit - p0) . e = +-|e|^2, times n.d.
        addRoots(0.0, glm::dot(n, b), glm::dot(n, a), lo, hi, xs);
        tag();
        for (glm::dvec3 e : {glm::dvec3(mGround.halfUWs), glm::dvec3(mGround.halfVWs)}) {
            for (double sign : {-1.0, 1.0}) {
                auto g = [&](glm::dvec3 d) {
                    return glm::dot((mEye - p0) * glm::dot(n, d) + h * d, e) -
                           sign * glm::dot(e, e) * glm::dot(n, d);
                };
                addRoots(0.0, g(b), g(a), lo, hi, xs);  // g is linear in d
                tag();
            }
        }
        std::vector<std::pair<double, int>> sorted;
        for (size_t i = 0; i < xs.size(); ++i) sorted.emplace_back(xs[i], curve[i]);
        std::sort(sorted.begin(), sorted.end());
        for (size_t i = 0; i < xs.size(); ++i) {
            xs[i] = sorted[i].first;
            if (labels) labels->push_back(sorted[i].second);
        }
        return xs;
    }

    // The exact visibility of a pixel (top-down row): lit over on-object length of the pixel
    // square, on the object at its centre.
    Exact at(glm::ivec2 pixelTopDown) const {
        double x0 = pixelTopDown.x;
        double yGl = mSize.y - 1 - pixelTopDown.y;
        glm::dvec3 a, b;
        line(yGl + 0.5, a, b);
        Ray centre{glm::vec3(mEye), glm::vec3(glm::normalize(a + b * (x0 + 0.5)))};
        std::optional<Hit> hit = intersect(mScene, centre);
        if (!hit) return {1.0, false};
        double lit = 0.0, on = 0.0;
        for (int k = 0; k < REF_SCANLINES; ++k) {
            double y = yGl + (k + 0.5) / REF_SCANLINES;
            std::vector<double> xs = changes(y, x0, x0 + 1.0);
            xs.insert(xs.begin(), x0);
            xs.push_back(x0 + 1.0);
            for (size_t i = 0; i + 1 < xs.size(); ++i) {
                double len = xs[i + 1] - xs[i];
                int st = stateAt(0.5 * (xs[i] + xs[i + 1]), y, hit->object);
                if (st != 2) on += len;
                if (st == 1) lit += len;
            }
        }
        return {on > 0.0 ? lit / on : 1.0, true};
    }

    // The exact visibility of a pixel (top-down row) to about 1e-10: the rows where a row's
    // signature (which curves its roots lie on, in order, and the state of each piece) changes
    // are found on GRID_ROWS rows and by bisection between two whose signatures differ; between
    // those rows lit(v) and on(v) are smooth but at the ends (a square root where a curve is
    // tangent to the row, a kink where two cross), which the tanh-sinh rule of Takahasi and Mori
    // ("Double exponential formulas for numerical integration", 1974) integrates to double
    // precision: t = tanh(pi/2 sinh(tau)), weight pi/2 cosh(tau) / cosh^2(pi/2 sinh(tau)),
    // tau = k h for |tau| <= 3, h = 1/16.
    Exact precise(glm::ivec2 pixelTopDown) const {
        double x0 = pixelTopDown.x;
        double yGl = mSize.y - 1 - pixelTopDown.y;
        glm::dvec3 a, b;
        line(yGl + 0.5, a, b);
        Ray centre{glm::vec3(mEye), glm::vec3(glm::normalize(a + b * (x0 + 0.5)))};
        std::optional<Hit> hit = intersect(mScene, centre);
        if (!hit) return {1.0, false};
        auto rowAt = [&](double v) { return row(x0, yGl + v, hit->object); };
        std::vector<double> ends{0.0, 1.0};
        Row low = rowAt(0.0);
        for (int k = 1; k <= GRID_ROWS; ++k) {
            double v = static_cast<double>(k) / GRID_ROWS;
            Row high = rowAt(v);
            split(rowAt, v - 1.0 / GRID_ROWS, low, v, high, ends);
            low = high;
        }
        std::sort(ends.begin(), ends.end());
        double lit = 0.0, on = 0.0;
        constexpr double H = 1.0 / 16.0;
        for (size_t i = 0; i + 1 < ends.size(); ++i) {
            double mid = 0.5 * (ends[i] + ends[i + 1]);
            double half = 0.5 * (ends[i + 1] - ends[i]);
            for (int k = -48; k <= 48; ++k) {
                double u = 0.5 * M_PI * std::sinh(k * H);
                double w = H * half * 0.5 * M_PI * std::cosh(k * H) / (std::cosh(u) * std::cosh(u));
                Row r = rowAt(mid + half * std::tanh(u));
                lit += w * r.lit;
                on += w * r.on;
            }
        }
        return {on > 0.0 ? lit / on : 1.0, true};
    }

    // Whether the pixel may hold an edge, from the roots on 8 of its scanlines and its centre's
    // neighbourhood: the sweep's pixels.
    bool nearEdge(glm::ivec2 pixelTopDown) const {
        double x0 = pixelTopDown.x;
        double yGl = mSize.y - 1 - pixelTopDown.y;
        for (int k = 0; k <= 8; ++k) {
            if (!changes(yGl + k / 8.0, x0 - 1.0, x0 + 2.0).empty()) return true;
        }
        return false;
    }

  private:
    static constexpr int GRID_ROWS = 64;

    struct Row {
        double lit = 0.0;
        double on = 0.0;
        std::vector<int> curves;  // the curve of each root, left to right
        std::vector<int> states;  // the state of each piece
        bool same(const Row& o) const { return curves == o.curves && states == o.states; }
    };

    Row row(double x0, double y, int object) const {
        Row r;
        std::vector<double> xs = changes(y, x0, x0 + 1.0, &r.curves);
        xs.insert(xs.begin(), x0);
        xs.push_back(x0 + 1.0);
        for (size_t i = 0; i + 1 < xs.size(); ++i) {
            double len = xs[i + 1] - xs[i];
            int st = stateAt(0.5 * (xs[i] + xs[i + 1]), y, object);
            r.states.push_back(st);
            if (st != 2) r.on += len;
            if (st == 1) r.lit += len;
        }
        return r;
    }

    // Every row in (va, vb) where the signature changes, to 1e-13, into `ends`.
    template <typename RowAt>
    void split(const RowAt& rowAt, double va, const Row& ra, double vb, const Row& rb,
               std::vector<double>& ends) const {
        if (ra.same(rb)) return;
        double m = 0.5 * (va + vb);
        if (vb - va < 1e-13) {
            ends.push_back(m);
            return;
        }
        Row rm = rowAt(m);
        split(rowAt, va, ra, m, rm, ends);
        split(rowAt, m, rm, vb, rb, ends);
    }

    const Scene& mScene;
    glm::ivec2 mSize;
    glm::dvec3 mEye, mF, mS, mU, mL;
    double mTan, mAspect;
    Plane mGround;
    Sphere mSphere;
};

Scene sphereOverPlane() {
    std::optional<Scene> scene = presetScene("sphere-over-plane");
    EXPECT_TRUE(scene.has_value());
    return *scene;
}

// The light from almost behind the camera, 9.3 degrees off the direction from the eye to the
// sphere: the eye (5 units away) sees a cap of acos(r / 5) = 84.3 degrees around that direction,
// so 9.3 + 84.3 - 90 = 3.5 degrees of the dark side show as a crescent along the silhouette, at
// most r (1 - cos 3.5) = 0.001 units wide, a tenth of a pixel at 640x360. The ground does not
// receive shadows, so every pixel around the crescent is lit: nothing the samples see differs.
Scene crescentScene() {
    return parseSceneString(R"([camera]
eye = [0.806, 2.857, 4.572]
target = [0.0, 1.0, 0.0]
fov = 40.0
[light]
type = "directional"
direction = [0.0, -0.4, -1.0]
[[object]]
type = "plane"
centre = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [12.0, 12.0]
receives_shadow = false
[[object]]
type = "sphere"
centre = [0.0, 1.0, 0.0]
radius = 0.5
)",
                            "crescent");
}

// Finding 15 of issue 24: at the sphere's terminator, pixels read truth 1 with bound 0 where the
// exact coverage was 0.9166: a sliver of the sphere's dark side along its silhouette that the
// first pass's samples missed, in the pixel and in all 8 neighbours (so no rule on samples
// refined it). Here such pixels are found the same way (the first pass alone: target 0), shown
// to exist, and each must now be refined: the geometric test finds them.
TEST(GroundTruthBound, HoldsAtTheTerminatorSliversTheSamplesMiss) {
    Scene scene = crescentScene();
    glm::ivec2 size(640, 360);
    GroundTruthOptions firstOnly;
    firstOnly.targetBound = 0.0f;  // the first pass: bound 1 on mixed pixels, 0 elsewhere
    GroundTruth first = computeGroundTruth(scene, size, firstOnly);
    ExactCoverage exact(scene, size);
    auto uniformAround = [&](int x, int y) {
        float v = first.visibility[first.index(x, y)];
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                size_t k = first.index(std::clamp(x + dx, 0, size.x - 1),
                                       std::clamp(y + dy, 0, size.y - 1));
                if (first.bound[k] != 0.0f || first.visibility[k] != v) return false;
            }
        }
        return true;
    };
    int missed = 0;
    for (int y = 1; y + 1 < size.y; ++y) {
        for (int x = 1; x + 1 < size.x; ++x) {
            if (!uniformAround(x, y) || !exact.nearEdge({x, y})) continue;
            Exact e = exact.at({x, y});
            float sampled = first.visibility[first.index(x, y)];
            if (!e.hit || std::abs(e.visibility - sampled) <= 1e-3) continue;
            ++missed;  // the samples say uniform, the geometry says otherwise
            // Refined now, so no longer the first pass's 0 or 1 with bound 0, and within its
            // bound of the exact value (the crescent is far narrower than the 1/16 px the walk
            // of old stepped by).
            GroundTruthPixel t = groundTruthAt(scene, size, {x, y});
            EXPECT_TRUE(t.refined) << x << ", " << y;
            Exact precise = exact.precise({x, y});
            EXPECT_LE(std::abs(t.visibility - precise.visibility), t.bound + 2e-7)
                << x << ", " << y << ": truth " << t.visibility << " bound " << t.bound << " exact "
                << precise.visibility;
        }
    }
    EXPECT_GE(missed, 20);  // the case is there to be caught
}

// groundTruthAt is computeGroundTruth's pixel, bit for bit.
TEST(GroundTruthBound, OnePixelIsTheFramesPixel) {
    Scene scene = sphereOverPlane();
    glm::ivec2 size(320, 180);
    GroundTruth frame = computeGroundTruth(scene, size);
    int refined = 0;
    for (glm::ivec2 p : {glm::ivec2(167, 103), glm::ivec2(150, 90), glm::ivec2(10, 170),
                         glm::ivec2(200, 60), glm::ivec2(140, 112)}) {
        GroundTruthPixel t = groundTruthAt(scene, size, p);
        size_t k = frame.index(p.x, p.y);
        EXPECT_EQ(t.visibility, frame.visibility[k]) << p.x << ", " << p.y;
        EXPECT_EQ(t.bound, frame.bound[k]) << p.x << ", " << p.y;
        EXPECT_EQ(t.receiver, frame.receiver[k] != 0);
        refined += t.refined ? 1 : 0;
    }
    EXPECT_GE(refined, 1);
}

// Every pixel near a silhouette, the terminator or the shadow's edge (every 3rd of them, to stay
// within seconds) is inside its bound, at two sizes.
TEST(GroundTruthBound, NoPixelOutsideItsBoundNearEdges) {
    for (auto [scene, size] : {std::pair(sphereOverPlane(), glm::ivec2(320, 180)),
                               std::pair(sphereOverPlane(), glm::ivec2(640, 360))}) {
        GroundTruth frame = computeGroundTruth(scene, size);
        ExactCoverage exact(scene, size);
        int checked = 0, outside = 0, candidates = 0;
        for (int y = 0; y < size.y; ++y) {
            for (int x = 0; x < size.x; ++x) {
                if (!exact.nearEdge({x, y}) || candidates++ % 3 != 0) continue;
                Exact e = exact.at({x, y});
                if (!e.hit) continue;
                size_t k = frame.index(x, y);
                ++checked;
                if (std::abs(frame.visibility[k] - e.visibility) > frame.bound[k] + REF_ERROR) {
                    ++outside;
                    ADD_FAILURE() << size.x << "x" << size.y << " (" << x << ", " << y
                                  << "): truth " << frame.visibility[k] << " bound "
                                  << frame.bound[k] << " exact " << e.visibility;
                }
            }
        }
        EXPECT_GT(checked, 100) << size.x;
        EXPECT_EQ(outside, 0) << size.x;
    }
}

// Finding 15 of issue 24: pixels whose truth lay outside its bound. The campaign's pixels (its
// frames at 320x180, 640x360 and 1280x720; the terminator at (585, 260..261) of 1280x720, and
// at half those coordinates at 640x360) and those the walk of 1/16 px got wrong on this preset
// (a lit sliver 0.01 to 0.03 px wide between two walk points, on every scanline of the pixel:
// (113, 56) of 320x180 read 0.0211 with bound 0.0019 where the exact value is 0.0277), each
// with the 5 x 5 pixels around it: every truth within its bound of the exact value computed
// here (precise(): closed-form rows, tanh-sinh over v), every bound at most the target.
TEST(GroundTruthBound, CampaignPixelsAreWithinTheirBoundOfTheClosedForm) {
    Scene scene = sphereOverPlane();
    struct Case {
        glm::ivec2 size;
        std::vector<glm::ivec2> pixels;
    };
    const Case cases[] = {
        {{320, 180}, {{167, 103}, {113, 56}}},
        {{640, 360}, {{292, 130}, {321, 75}, {226, 112}}},
        {{1280, 720}, {{585, 261}, {656, 165}, {453, 226}, {717, 587}, {691, 591}}},
    };
    int checked = 0, refined = 0;
    for (const Case& c : cases) {
        ExactCoverage exact(scene, c.size);
        for (glm::ivec2 centre : c.pixels) {
            for (int dy = -2; dy <= 2; ++dy) {
                for (int dx = -2; dx <= 2; ++dx) {
                    glm::ivec2 p = centre + glm::ivec2(dx, dy);
                    Exact e = exact.precise(p);
                    if (!e.hit) continue;
                    GroundTruthPixel t = groundTruthAt(scene, c.size, p);
                    ++checked;
                    refined += t.refined ? 1 : 0;
                    // 2e-7: the float the visibility and the bound are stored in.
                    EXPECT_LE(std::abs(t.visibility - e.visibility), t.bound + 2e-7)
                        << c.size.x << " (" << p.x << ", " << p.y << "): truth " << t.visibility
                        << " bound " << t.bound << " exact " << e.visibility;
                    EXPECT_LE(t.bound, DEFAULT_TRUTH_TARGET_BOUND) << p.x << ", " << p.y;
                    // The reference against the plain midpoint rule over 512 rows.
                    EXPECT_NEAR(e.visibility, exact.at(p).visibility, REF_ERROR);
                }
            }
        }
    }
    EXPECT_EQ(checked, 10 * 25);
    EXPECT_GE(refined, 100);
}

// A few hundred pixels near an edge, drawn at random (a fixed seed) from the same three frames:
// 300 with an edge inside, and those without one drawn on the way.
TEST(GroundTruthBound, RandomEdgePixelsAreWithinTheirBoundOfTheClosedForm) {
    Scene scene = sphereOverPlane();
    std::mt19937 random(24015);
    int checked = 0;
    for (glm::ivec2 size : {glm::ivec2(320, 180), glm::ivec2(640, 360), glm::ivec2(1280, 720)}) {
        ExactCoverage exact(scene, size);
        std::uniform_int_distribution<int> px(0, size.x - 1);
        std::uniform_int_distribution<int> py(0, size.y - 1);
        // Until 100 of them hold an edge (0 < exact < 1); every pixel drawn on the way counts.
        for (int edge = 0; edge < 100;) {
            glm::ivec2 p(px(random), py(random));
            if (!exact.nearEdge(p)) continue;
            Exact e = exact.precise(p);
            if (!e.hit) continue;
            GroundTruthPixel t = groundTruthAt(scene, size, p);
            ++checked;
            edge += e.visibility > 1e-6 && e.visibility < 1.0 - 1e-6 ? 1 : 0;
            EXPECT_LE(std::abs(t.visibility - e.visibility), t.bound + 2e-7)
                << size.x << " (" << p.x << ", " << p.y << "): truth " << t.visibility << " bound "
                << t.bound << " exact " << e.visibility;
            EXPECT_LE(t.bound, DEFAULT_TRUTH_TARGET_BOUND) << p.x << ", " << p.y;
        }
    }
    EXPECT_GE(checked, 300);
}

}  // namespace
}  // namespace pcf
