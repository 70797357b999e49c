// The ray-cast ground truth against closed forms: under a directional light a sphere's shadow on
// a plane is exactly an ellipse and a box's exactly a convex polygon (the hull of its projected
// corners). The camera looks straight down at the ground, so a pixel's footprint there is an
// exact axis-aligned rectangle, and the exact shadowed fraction of each pixel can be computed
// from the closed form alone, without the ray caster.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "analysis/error_metrics.h"
#include "analysis/ground_truth.h"
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

// The exact shadow of a sphere on the ground plane: the ground point p is shadowed when the
// ray from p toward the light (-d) passes within r of the centre c, on the light's side:
//   w = c - p, L = -d / |d|:  |w|^2 - (w.L)^2 < r^2  and  w.L > 0
// The boundary is an ellipse with semi-axes r and r / cos(angle of d from the normal).
bool inSphereShadow(glm::dvec2 xz, glm::dvec3 centre, double r, glm::dvec3 d) {
    glm::dvec3 w = centre - glm::dvec3(xz.x, 0.0, xz.y);
    glm::dvec3 toLight = -glm::normalize(d);
    double along = glm::dot(w, toLight);
    return along > 0.0 && glm::dot(w, w) - along * along < r * r;
}

// The box's 8 corners projected along d onto y = 0; their convex hull (Andrew's monotone
// chain), counter-clockwise in (x, z).
std::vector<glm::dvec2> boxShadowPolygon(const Box& box, glm::dvec3 d) {
    std::vector<glm::dvec2> pts;
    for (int k = 0; k < 8; ++k) {
        glm::vec3 local((k & 1 ? 1.0f : -1.0f) * box.halfExtents.x,
                        (k & 2 ? 1.0f : -1.0f) * box.halfExtents.y,
                        (k & 4 ? 1.0f : -1.0f) * box.halfExtents.z);
        glm::dvec3 v(boxWorldFromLocal(box, local));
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

bool inConvexPolygon(glm::dvec2 p, const std::vector<glm::dvec2>& poly) {
    for (size_t k = 0; k < poly.size(); ++k) {
        glm::dvec2 a = poly[k];
        glm::dvec2 b = poly[(k + 1) % poly.size()];
        if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < 0.0) return false;
    }
    return true;
}

// Where the camera ray through ndc meets the ground (y = 0), and which object it meets first.
struct GroundPoint {
    glm::dvec2 xz;
    int object;
};
GroundPoint groundPoint(const Scene& scene, glm::vec2 ndc, float aspect) {
    Ray ray = cameraRay(scene.camera, ndc, aspect);
    glm::dvec3 o(ray.originWs);
    glm::dvec3 d(ray.dirWs);
    glm::dvec3 p = o + d * (-o.y / d.y);
    std::optional<Hit> hit = intersect(scene, ray);
    return {{p.x, p.z}, hit ? hit->object : -1};
}

struct ClosedFormCheck {
    int inside = 0;             // footprint entirely in the exact shadow
    int outside = 0;            // footprint clear of it (with a margin)
    int straddling = 0;         // the exact edge crosses the footprint
    double meanAbsError = 0.0;  // over the straddling pixels
};

// Compares the truth with the closed form `shadowed` pixel by pixel (see the file comment).
ClosedFormCheck checkAgainstClosedForm(const Scene& scene, glm::ivec2 size, int spp,
                                       const std::function<bool(glm::dvec2)>& shadowed) {
    GroundTruthOptions options;
    options.spp = spp;
    GroundTruth truth = computeGroundTruth(scene, size, options);
    float aspect = static_cast<float>(size.x) / size.y;
    const int FINE = 128;  // the "exact" fraction: FINE x FINE points per footprint
    // Per axis a jittered K x K sampler is off by at most one cell row / column along the
    // edge: |truth - exact| <= 2 / K, plus the fine grid's own 2 / FINE.
    const double bound = 2.0 / spp + 2.0 / FINE;
    ClosedFormCheck c;
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            float v = truth.visibility[truth.index(x, size.y - 1 - y)];
            glm::vec2 lo = glm::vec2(x, y) / glm::vec2(size) * 2.0f - 1.0f;
            glm::vec2 hi = glm::vec2(x + 1, y + 1) / glm::vec2(size) * 2.0f - 1.0f;
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
            auto shadowFraction = [&](double margin) {
                glm::dvec2 m = (b - a) * margin;
                glm::dvec2 lo2 = a - m;
                glm::dvec2 ext = (b - a) + 2.0 * m;
                int n = 0;
                for (int j = 0; j < FINE; ++j) {
                    for (int i = 0; i < FINE; ++i) {
                        glm::dvec2 p = lo2 + ext * glm::dvec2((i + 0.5) / FINE, (j + 0.5) / FINE);
                        n += shadowed(p) ? 1 : 0;
                    }
                }
                return static_cast<double>(n) / (FINE * FINE);
            };
            bool allCornersIn = true;
            for (const GroundPoint& g : corners) allCornersIn = allCornersIn && shadowed(g.xz);
            if (allCornersIn) {  // convex shadow: the whole footprint is inside
                ++c.inside;
                EXPECT_EQ(v, 0.0f) << "pixel " << x << ", " << y << " is fully in shadow";
                continue;
            }
            if (shadowFraction(0.1) == 0.0) {
                ++c.outside;
                EXPECT_EQ(v, 1.0f) << "pixel " << x << ", " << y << " is fully lit";
                continue;
            }
            ++c.straddling;
            double exact = 1.0 - shadowFraction(0.0);
            EXPECT_NEAR(v, exact, bound) << "pixel " << x << ", " << y;
            c.meanAbsError += std::fabs(v - exact);
            if (exact > bound && exact < 1.0 - bound) {
                EXPECT_GT(v, 0.0f) << "pixel " << x << ", " << y << " straddles the edge";
                EXPECT_LT(v, 1.0f) << "pixel " << x << ", " << y << " straddles the edge";
            }
        }
    }
    if (c.straddling > 0) c.meanAbsError /= c.straddling;
    return c;
}

TEST(GroundTruth, SphereShadowOnAPlaneIsTheExactEllipse) {
    Scene scene = sphereScene();
    const Sphere& sphere = std::get<Sphere>(scene.objects[1].shape);
    glm::dvec3 d(scene.light.directionWs);
    auto shadowed = [&](glm::dvec2 p) {
        return inSphereShadow(p, glm::dvec3(sphere.centreWs), sphere.radius, d);
    };
    for (int spp : {4, 8}) {
        ClosedFormCheck c = checkAgainstClosedForm(scene, {96, 96}, spp, shadowed);
        // The ellipse (semi-axes 0.6 and 0.6 * sqrt(5) = 1.34) covers ~1300 of the 9216 pixels
        // of 0.036 units; its ~6.5 units of perimeter cross ~200.
        EXPECT_GT(c.inside, 1000) << spp;
        EXPECT_GT(c.outside, 6000) << spp;
        EXPECT_GT(c.straddling, 150) << spp;
        // The bound is the worst case; on average the jitter does far better.
        EXPECT_LT(c.meanAbsError, 0.5 / spp) << spp;
    }
}

TEST(GroundTruth, BoxShadowOnAPlaneIsTheExactPolygon) {
    Scene scene = boxScene();
    const Box& box = std::get<Box>(scene.objects[1].shape);
    std::vector<glm::dvec2> polygon = boxShadowPolygon(box, glm::dvec3(scene.light.directionWs));
    ASSERT_GE(polygon.size(), 4u);
    auto shadowed = [&](glm::dvec2 p) { return inConvexPolygon(p, polygon); };
    ClosedFormCheck c = checkAgainstClosedForm(scene, {96, 96}, 8, shadowed);
    EXPECT_GT(c.inside, 1000);
    EXPECT_GT(c.outside, 4000);
    EXPECT_GT(c.straddling, 150);
    EXPECT_LT(c.meanAbsError, 0.5 / 8);
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
