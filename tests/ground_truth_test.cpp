// The ray-cast ground truth against closed forms: under a directional light a sphere's shadow on
// a plane is exactly an ellipse and a box's exactly a convex polygon (the hull of its projected
// corners). The camera looks straight down at the ground, so a pixel's footprint there is an
// exact axis-aligned rectangle (the ground is parallel to the image plane: window to ground is a
// uniform scale), and the exact shadowed fraction of each pixel is the area of the shadow
// polygon clipped to that rectangle over the rectangle's area, without the ray caster. Every
// pixel's truth must lie within its own stated bound of that.
#include "measure/ground_truth.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "measure/error_metrics.h"
#include "render/gl_context.h"
#include "render/scene_renderer.h"
#include "scene/camera.h"
#include "scene/presets.h"
#include "scene/raycast.h"
#include "scene/scene_file.h"

namespace pcf {
namespace {

// Looks straight down from 20 units at (cx, cz); 10 degrees of field of view cover 3.5 units
// of ground, and the occluders stay out of the frame.
std::string topDownCamera(float cx, float cz) {
    return "[camera]\neye = [" + std::to_string(cx) + ", 20.0, " + std::to_string(cz) +
           "]\ntarget = [" + std::to_string(cx) + ", 0.0, " + std::to_string(cz) +
           "]\nup = [0.0, 0.0, -1.0]\nfov = 10.0\n";
}

const char* GROUND = R"(
[[object]]
type = "plane"
name = "ground"
centre = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [20.0, 20.0]
)";

// Light direction (2, -1, 0): a sphere at height 1.2 throws its shadow centre to x = 2.4.
Scene sphereScene() {
    std::string toml = topDownCamera(2.4f, 0.0f) +
                       "[light]\ntype = \"directional\"\ndirection = [2.0, -1.0, 0.0]\n" + GROUND +
                       "[[object]]\ntype = \"sphere\"\ncentre = [0.0, 1.2, 0.0]\nradius = 0.6\n";
    return parseSceneString(toml, "sphere-test");
}

// A floating box turned 30 degrees; light (2, -1, 0.5) throws its shadow around (3, 0, 0.75).
Scene boxScene() {
    std::string toml = topDownCamera(3.0f, 0.75f) +
                       "[light]\ntype = \"directional\"\ndirection = [2.0, -1.0, 0.5]\n" + GROUND +
                       "[[object]]\ntype = \"box\"\ncentre = [0.0, 1.5, 0.0]\n"
                       "half = [0.4, 0.3, 0.5]\nrotate_y = 30.0\n";
    return parseSceneString(toml, "box-test");
}

// The exact shadow of a sphere on the ground plane: the ground points whose ray toward the light
// passes within r of the centre, i.e. the cylinder of radius r around the centre along the light
// direction d, cut by y = 0. Its boundary, the circle c + r (cos t e1 + sin t e2) (e1, e2 unit,
// perpendicular to d and each other) moved along d onto y = 0, is an ellipse; n points of it
// give an inscribed polygon whose area is short of the ellipse's by a relative
// 1 - sin(2 pi / n) / (2 pi / n) = 4e-7 for n = 4096 (far below the 1/512 bounds checked).
std::vector<glm::dvec2> sphereShadowPolygon(glm::dvec3 centre, double r, glm::dvec3 d,
                                            int n = 4096) {
    d = glm::normalize(d);
    glm::dvec3 e1 = glm::normalize(glm::cross(d, glm::dvec3(0.0, 0.0, 1.0)));
    glm::dvec3 e2 = glm::cross(d, e1);
    std::vector<glm::dvec2> poly;
    for (int k = 0; k < n; ++k) {
        double t = 2.0 * M_PI * k / n;
        glm::dvec3 q = centre + r * (std::cos(t) * e1 + std::sin(t) * e2);
        q -= d * (q.y / d.y);
        poly.emplace_back(q.x, q.z);
    }
    // Counter-clockwise in (x, z), as the clipping below expects.
    double area2 = 0.0;
    for (int k = 0; k < n; ++k) {
        glm::dvec2 a = poly[k];
        glm::dvec2 b = poly[(k + 1) % n];
        area2 += a.x * b.y - a.y * b.x;
    }
    if (area2 < 0.0) std::reverse(poly.begin(), poly.end());
    return poly;
}

// The box's 8 corners projected along d onto y = 0; their convex hull (Andrew's monotone
// chain), counter-clockwise in (x, z).
std::vector<glm::dvec2> boxShadowPolygon(const Box& box, glm::dvec3 d) {
    std::vector<glm::dvec2> pts;
    for (int k = 0; k < 8; ++k) {
        // In double (boxWorldFromLocal rounds to float: 2e-7 units, 5e-6 of a pixel here).
        BoxAxes ax = boxAxes(box);
        glm::dvec3 v = glm::dvec3(box.centreWs) +
                       ax.xWs * ((k & 1 ? 1.0 : -1.0) * box.halfExtents.x) +
                       glm::dvec3(0.0, (k & 2 ? 1.0 : -1.0) * box.halfExtents.y, 0.0) +
                       ax.zWs * ((k & 4 ? 1.0 : -1.0) * box.halfExtents.z);
        glm::dvec3 q = v - d * (v.y / d.y);
        pts.emplace_back(q.x, q.z);
    }
    std::sort(pts.begin(), pts.end(),
              [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto cross = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::dvec2> hull(2 * pts.size());
    size_t n = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        while (n >= 2 && cross(hull[n - 2], hull[n - 1], pts[i]) <= 0) --n;
        hull[n++] = pts[i];
    }
    for (size_t i = pts.size() - 1, lower = n + 1; i-- > 0;) {
        while (n >= lower && cross(hull[n - 2], hull[n - 1], pts[i]) <= 0) --n;
        hull[n++] = pts[i];
    }
    hull.resize(n - 1);
    return hull;
}

// The area of a convex polygon clipped to the rectangle [lo, hi] (Sutherland-Hodgman against
// the rectangle's four sides, then the shoelace formula).
double clippedArea(const std::vector<glm::dvec2>& poly, glm::dvec2 lo, glm::dvec2 hi) {
    std::vector<glm::dvec2> cur = poly;
    for (int side = 0; side < 4 && !cur.empty(); ++side) {
        int axis = side % 2;
        bool keepAbove = side < 2;
        double edge = keepAbove ? lo[axis] : hi[axis];
        auto inside = [&](glm::dvec2 p) { return keepAbove ? p[axis] >= edge : p[axis] <= edge; };
        std::vector<glm::dvec2> next;
        for (size_t k = 0; k < cur.size(); ++k) {
            glm::dvec2 a = cur[k];
            glm::dvec2 b = cur[(k + 1) % cur.size()];
            if (inside(a)) next.push_back(a);
            if (inside(a) != inside(b)) {
                double t = (edge - a[axis]) / (b[axis] - a[axis]);
                next.push_back(a + (b - a) * t);
            }
        }
        cur = std::move(next);
    }
    double area2 = 0.0;
    for (size_t k = 0; k < cur.size(); ++k) {
        glm::dvec2 a = cur[k];
        glm::dvec2 b = cur[(k + 1) % cur.size()];
        area2 += a.x * b.y - a.y * b.x;
    }
    return 0.5 * std::fabs(area2);
}

// Where the camera ray through ndc meets the ground (y = 0), and which object it meets first.
struct GroundPoint {
    glm::dvec2 xz;
    int object;
};
// In double throughout (cameraRay's formula without its rounding to float, which would move a
// footprint's side by ~1e-6 units, 3e-5 of a pixel here, more than the truth's rounding).
GroundPoint groundPoint(const Scene& scene, glm::dvec2 ndc, double aspect) {
    const Camera& cam = scene.camera;
    glm::dvec3 o(cam.eyeWs);
    glm::dvec3 f = glm::normalize(glm::dvec3(cam.targetWs) - o);
    glm::dvec3 s = glm::normalize(glm::cross(f, glm::dvec3(cam.upWs)));
    glm::dvec3 u = glm::cross(s, f);
    double t = std::tan(0.5 * glm::radians(static_cast<double>(cam.fovYDeg)));
    glm::dvec3 d = f + s * (ndc.x * aspect * t) + u * (ndc.y * t);
    glm::dvec3 p = o + d * (-o.y / d.y);
    std::optional<Hit> hit = intersect(scene, Ray{cam.eyeWs, glm::vec3(glm::normalize(d))});
    return {{p.x, p.z}, hit ? hit->object : -1};
}

struct ClosedFormCheck {
    int inside = 0;             // footprint entirely in the exact shadow
    int outside = 0;            // footprint clear of it
    int straddling = 0;         // the exact edge crosses the footprint
    double meanAbsError = 0.0;  // over the straddling pixels
    double maxError = 0.0;      // over all pixels
    float maxBound = 0.0f;      // the largest bound the truth states
};

// Compares the truth with the exact shadowed area of `shadow` pixel by pixel (see the file
// comment): every pixel within its own stated bound.
ClosedFormCheck checkAgainstClosedForm(const Scene& scene, glm::ivec2 size, int spp,
                                       const std::vector<glm::dvec2>& shadow) {
    GroundTruthOptions options;
    options.spp = spp;
    GroundTruth truth = computeGroundTruth(scene, size, options);
    double aspect = static_cast<double>(size.x) / size.y;
    ClosedFormCheck c;
    c.maxBound = truth.maxBound;
    EXPECT_EQ(truth.bound.size(), truth.pixelCount());
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            size_t k = truth.index(x, size.y - 1 - y);
            float v = truth.visibility[k];
            float bound = truth.bound[k];
            glm::dvec2 lo = glm::dvec2(x, y) / glm::dvec2(size) * 2.0 - 1.0;
            glm::dvec2 hi = glm::dvec2(x + 1, y + 1) / glm::dvec2(size) * 2.0 - 1.0;
            GroundPoint corners[4] = {
                groundPoint(scene, lo, aspect), groundPoint(scene, {hi.x, lo.y}, aspect),
                groundPoint(scene, {lo.x, hi.y}, aspect), groundPoint(scene, hi, aspect)};
            for (const GroundPoint& g : corners) {
                if (g.object != 0) {
                    ADD_FAILURE() << "pixel " << x << ", " << y << " does not see the ground";
                    return c;
                }
            }
            // The ground footprint: a rectangle (the camera looks straight down).
            glm::dvec2 a = glm::min(glm::min(corners[0].xz, corners[1].xz),
                                    glm::min(corners[2].xz, corners[3].xz));
            glm::dvec2 b = glm::max(glm::max(corners[0].xz, corners[1].xz),
                                    glm::max(corners[2].xz, corners[3].xz));
            double footprint = (b.x - a.x) * (b.y - a.y);
            double shadowed = clippedArea(shadow, a, b) / footprint;
            double exact = 1.0 - shadowed;
            double error = std::fabs(v - exact);
            c.maxError = std::max(c.maxError, error);
            // 1e-6: the float the visibility is stored in, and the polygon's 4e-7.
            EXPECT_LE(error, bound + 1e-6) << "pixel " << x << ", " << y << ": truth " << v
                                           << ", exact " << exact << ", bound " << bound;
            if (shadowed >= 1.0 - 1e-9) {
                ++c.inside;
            } else if (shadowed <= 1e-9) {
                ++c.outside;
            } else {
                ++c.straddling;
                c.meanAbsError += error;
            }
        }
    }
    if (c.straddling > 0) c.meanAbsError /= c.straddling;
    return c;
}

TEST(GroundTruth, SphereShadowOnAPlaneIsTheExactEllipseWithinTheBound) {
    Scene scene = sphereScene();
    const Sphere& sphere = std::get<Sphere>(scene.objects[1].shape);
    std::vector<glm::dvec2> ellipse = sphereShadowPolygon(
        glm::dvec3(sphere.centreWs), sphere.radius, glm::dvec3(scene.light.directionWs));
    // spp 1: one first-pass sample per pixel, so finding the edge rests on the neighbour rule.
    for (int spp : {1, 2, 4}) {
        ClosedFormCheck c = checkAgainstClosedForm(scene, {96, 96}, spp, ellipse);
        // The ellipse (semi-axes 0.6 and 0.6 * sqrt(5) = 1.34) covers ~1300 of the 9216 pixels
        // of 0.036 units; its ~6.5 units of perimeter cross ~200.
        EXPECT_GT(c.inside, 1000) << spp;
        EXPECT_GT(c.outside, 6000) << spp;
        EXPECT_GT(c.straddling, 150) << spp;
        EXPECT_LE(c.maxBound, DEFAULT_TRUTH_TARGET_BOUND) << spp;
        EXPECT_LT(c.maxError, DEFAULT_TRUTH_TARGET_BOUND) << spp;
        // The 8 x 8 jittered samples of old were off by 0.004 on average in the edge band.
        EXPECT_LT(c.meanAbsError, 2e-4) << spp;
    }
}

TEST(GroundTruth, BoxShadowOnAPlaneIsTheExactPolygonWithinTheBound) {
    Scene scene = boxScene();
    const Box& box = std::get<Box>(scene.objects[1].shape);
    std::vector<glm::dvec2> polygon = boxShadowPolygon(box, glm::dvec3(scene.light.directionWs));
    ASSERT_GE(polygon.size(), 4u);
    for (int spp : {1, 2}) {
        ClosedFormCheck c = checkAgainstClosedForm(scene, {96, 96}, spp, polygon);
        EXPECT_GT(c.inside, 1000) << spp;
        EXPECT_GT(c.outside, 4000) << spp;
        EXPECT_GT(c.straddling, 150) << spp;
        EXPECT_LE(c.maxBound, DEFAULT_TRUTH_TARGET_BOUND) << spp;
        EXPECT_LT(c.meanAbsError, 2e-4) << spp;
    }
}

// With the refinement off the bound makes no claim where the first pass's samples disagree, and
// the refinement beats the jittered first pass against the same closed form.
TEST(GroundTruth, RefinementIsWhatBringsTheBound) {
    Scene scene = boxScene();
    GroundTruthOptions off;
    off.spp = 4;
    off.targetBound = 0.0f;
    GroundTruth coarse = computeGroundTruth(scene, {64, 64}, off);
    EXPECT_EQ(coarse.refinedPixels, 0);
    EXPECT_EQ(coarse.maxBound, 1.0f);
    GroundTruthOptions on;
    on.spp = 4;
    GroundTruth fine = computeGroundTruth(scene, {64, 64}, on);
    EXPECT_GT(fine.refinedPixels, 100);
    EXPECT_LE(fine.maxBound, DEFAULT_TRUTH_TARGET_BOUND);
    // A looser target stops sooner but still holds its own bound.
    GroundTruthOptions loose = on;
    loose.targetBound = 0.05f;
    GroundTruth rough = computeGroundTruth(scene, {64, 64}, loose);
    EXPECT_LE(rough.maxBound, 0.05f);
    int differ = 0;
    for (size_t k = 0; k < fine.pixelCount(); ++k) {
        EXPECT_NEAR(rough.visibility[k], fine.visibility[k], rough.bound[k] + fine.bound[k] + 1e-6)
            << k;
        differ += coarse.visibility[k] != fine.visibility[k];
    }
    EXPECT_GT(differ, 100);
}

TEST(GroundTruth, FacesAwayFromTheLightAreZeroAndMarked) {
    Scene scene = *presetScene("box-on-plane");
    GroundTruthOptions options;
    options.spp = 4;
    glm::ivec2 size{160, 90};
    GroundTruth truth = computeGroundTruth(scene, size, options);
    int away = 0;
    int dark = 0;
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            size_t k = truth.index(x, y);
            if (!truth.receiver[k] || truth.facesLight[k]) continue;
            ++away;
            if (truth.visibility[k] == 0.0f) {
                ++dark;
                continue;
            }
            // Only where some samples reach a lit face of the same box: next to a pixel whose
            // centre faces the light.
            bool besideLitFace = false;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    int nx = std::clamp(x + dx, 0, size.x - 1);
                    int ny = std::clamp(y + dy, 0, size.y - 1);
                    besideLitFace = besideLitFace || truth.facesLight[truth.index(nx, ny)];
                }
            }
            EXPECT_TRUE(besideLitFace) << "pixel " << x << ", " << y;
        }
    }
    // The box's two faces on the camera side are turned away from the sun.
    EXPECT_GT(away, 200);
    EXPECT_GT(dark, away * 9 / 10);
}

TEST(GroundTruth, IsTheSameForAnyThreadCountAndRun) {
    Scene scene = *presetScene("sphere-over-plane");
    GroundTruthOptions one;
    one.spp = 3;
    one.threads = 1;
    GroundTruthOptions many = one;
    many.threads = 5;
    int progressCalls = 0;
    many.progress = [&](int done, int rows) {
        EXPECT_LE(done, rows);
        ++progressCalls;
    };
    GroundTruth a = computeGroundTruth(scene, {120, 70}, one);
    GroundTruth b = computeGroundTruth(scene, {120, 70}, many);
    EXPECT_EQ(a.visibility, b.visibility);
    EXPECT_EQ(a.receiver, b.receiver);
    EXPECT_EQ(a.facesLight, b.facesLight);
    EXPECT_EQ(a.bound, b.bound);
    EXPECT_GE(progressCalls, 1);
}

TEST(GroundTruth, SamplesStayInTheirCells) {
    for (int spp : {1, 3, 8}) {
        for (int j = 0; j < spp; ++j) {
            for (int i = 0; i < spp; ++i) {
                glm::vec2 s = stratifiedSample({17, 4}, i, j, spp);
                EXPECT_GE(s.x, static_cast<float>(i) / spp);
                EXPECT_LT(s.x, static_cast<float>(i + 1) / spp);
                EXPECT_GE(s.y, static_cast<float>(j) / spp);
                EXPECT_LT(s.y, static_cast<float>(j + 1) / spp);
            }
        }
    }
    // Different pixels get different jitter.
    EXPECT_NE(stratifiedSample({0, 0}, 0, 0, 4), stratifiedSample({1, 0}, 0, 0, 4));
}

TEST(GroundTruth, RefusesBadArguments) {
    Scene scene = *presetScene("box-on-plane");
    GroundTruthOptions bad;
    bad.spp = 0;
    EXPECT_THROW(computeGroundTruth(scene, {10, 10}, bad), std::invalid_argument);
    EXPECT_THROW(computeGroundTruth(scene, {0, 10}), std::invalid_argument);
    GroundTruthOptions nan;
    nan.targetBound = std::nanf("");
    EXPECT_THROW(computeGroundTruth(scene, {10, 10}, nan), std::invalid_argument);
}

// The truth's receiver mask is the renderer's (its light-space alpha) but for a few silhouette
// pixels, where the tessellated mesh and the analytic surface part ways.
TEST(GroundTruth, ReceiverMaskAgreesWithTheRenderer) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    for (const char* name : {"box-on-plane", "sphere-over-plane", "stairs"}) {
        Scene scene = *presetScene(name);
        RenderSettings s;
        s.frameSize = {320, 180};
        SceneRenderer renderer(scene);
        renderer.render(s);
        std::vector<uint8_t> rendered = receiverMaskFromLightSpace(renderer.readLightSpace());
        GroundTruthOptions options;
        options.spp = 1;
        GroundTruth truth = computeGroundTruth(scene, s.frameSize, options);
        int receivers = 0;
        int differ = 0;
        for (size_t k = 0; k < rendered.size(); ++k) {
            receivers += truth.receiver[k];
            differ += truth.receiver[k] != rendered[k];
        }
        EXPECT_GT(receivers, 320 * 180 / 4) << name;
        EXPECT_LT(differ, 320 * 180 / 200) << name;
    }
}

}  // namespace
}  // namespace pcf
