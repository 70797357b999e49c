// The area-light truth against closed forms. The sun is a disk (light_visibility.h: radius
// R = tan(diameter / 2) in the plane one unit toward the light, uniform over it), so:
// - a straight occluder edge seen from a point cuts the disk along a straight chord: the part
//   beyond a chord at distance d from the centre is the circular segment
//     s(u) = (acos(u) - u sqrt(1 - u^2)) / pi,  u = d / R  (s = 0 for u >= 1, 1 for u <= -1)
//   and over a band of ground points the integral of s is closed too:
//     integral of s(u) du = (u acos(u) - sqrt(1 - u^2) + (1 - u^2)^(3/2) / 3) / pi
// - a sphere straight toward the light's centre from the point is a disk of radius tan(beta)
//   (beta = asin(r / distance)) centred on the sun's: an annular eclipse, visible
//   1 - tan^2(beta) / R^2, or nothing when tan(beta) >= R.
#include "measure/light_visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <thread>

#include "measure/ground_truth.h"
#include "scene/camera.h"
#include "scene/presets.h"
#include "scene/raycast.h"
#include "scene/scene_file.h"

namespace pcf {
namespace {

constexpr double PI = std::numbers::pi;

double segment(double u) {
    if (u >= 1.0) return 0.0;
    if (u <= -1.0) return 1.0;
    return (std::acos(u) - u * std::sqrt(1.0 - u * u)) / PI;
}

double segmentIntegral(double u) {
    u = std::clamp(u, -1.0, 1.0);
    double w = std::sqrt(1.0 - u * u);
    return (u * std::acos(u) - w + w * w * w / 3.0) / PI;
}

// A pixel spanning ground x in [xa, xb] whose points see the disk cut by the edge at
// u = x / scale: its visible fraction, 1 - the mean of segment(u) over the pixel.
double pixelExact(double xa, double xb, double scale) {
    return 1.0 - scale * (segmentIntegral(xb / scale) - segmentIntegral(xa / scale)) / (xb - xa);
}

// The light straight down with angular diameter `diameter`; a ground plane; a slab covering
// x < 0 between heights H and H + 1 (its edge along z at x = 0); a camera straight down at
// (cx, 20, 0) with a 2 degree field of view.
constexpr double H = 2.0;
Scene edgeScene(double diameter, double cx) {
    std::string toml = "[camera]\neye = [" + std::to_string(cx) + ", 20.0, 0.0]\ntarget = [" +
                       std::to_string(cx) +
                       ", 0.0, 0.0]\nup = [0.0, 0.0, -1.0]\nfov = 2.0\n"
                       "[light]\ntype = \"directional\"\ndirection = [0.0, -1.0, 0.0]\n"
                       "angular_diameter = " +
                       std::to_string(diameter) +
                       "\n[[object]]\ntype = \"plane\"\nname = \"ground\"\ncentre = [0.0, 0.0, "
                       "0.0]\nnormal = [0.0, 1.0, 0.0]\nsize = [200.0, 200.0]\n"
                       "[[object]]\ntype = \"box\"\nname = \"slab\"\ncentre = [-50.0, " +
                       std::to_string(H + 0.5) + ", 0.0]\nhalf = [50.0, 0.5, 50.0]\n";
    return parseSceneString(toml, "edge-test");
}

double radiusOf(double diameterDeg) { return std::tan(0.5 * diameterDeg * PI / 180.0); }

// Seen from ground point (x, 0, 0), x > 0, the slab's top edge (height H + 1) cuts the disk at
// d = x / (H + 1); from x < 0 (under the slab) the bottom edge at d = -x / H leaves a segment.
double edgeExact(double x, double r) {
    return x >= 0.0 ? 1.0 - segment(x / ((H + 1.0) * r)) : segment(-x / (H * r));
}

TEST(LightVisibility, ASunCutByAStraightEdgeIsACircularSegment) {
    const double diameter = 4.0;
    Scene scene = edgeScene(diameter, 0.0);
    double r = radiusOf(diameter);
    int checked = 0;
    for (double t : {-0.95, -0.6, -0.2, 0.0, 0.1, 0.45, 0.8, 0.99}) {
        for (double side : {-1.0, 1.0}) {
            double x = side * t * (side > 0 ? (H + 1.0) : H) * r;
            LightFraction f =
                lightVisibleFraction(scene, {x, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1.0 / 2048.0);
            double exact = edgeExact(x, r);
            EXPECT_LE(std::abs(f.visible - exact), f.bound + 1e-9) << "x " << x;
            EXPECT_LE(f.bound, 1.0 / 2048.0) << "x " << x;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 16);
    // Half the sun at the edge's foot, by symmetry of the chord through the centre.
    EXPECT_NEAR(lightVisibleFraction(scene, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1e-4).visible, 0.5,
                1e-4);
}

Scene sphereScene(double diameter, double radius, double height) {
    std::string toml =
        "[camera]\neye = [3.0, 3.0, 3.0]\ntarget = [0.0, 0.0, 0.0]\n"
        "[light]\ntype = \"directional\"\ndirection = [0.0, -1.0, 0.0]\n"
        "angular_diameter = " +
        std::to_string(diameter) +
        "\n[[object]]\ntype = \"plane\"\ncentre = [0.0, 0.0, 0.0]\n"
        "normal = [0.0, 1.0, 0.0]\nsize = [20.0, 20.0]\n"
        "[[object]]\ntype = \"sphere\"\ncentre = [0.0, " +
        std::to_string(height) + ", 0.0]\nradius = " + std::to_string(radius) + "\n";
    return parseSceneString(toml, "sphere-test");
}

TEST(LightVisibility, ASphereBeforeTheSunIsAnAnnularEclipse) {
    const double diameter = 4.0;
    const double height = 2.0;
    double r = radiusOf(diameter);
    for (double given : {0.01, 0.03, 0.05}) {
        Scene scene = sphereScene(diameter, given, height);
        double sphereRadius = std::get<Sphere>(scene.objects[1].shape).radius;  // as stored
        double tb = std::tan(std::asin(sphereRadius / height));
        double exact = tb >= r ? 0.0 : 1.0 - tb * tb / (r * r);
        LightFraction f =
            lightVisibleFraction(scene, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1.0 / 2048.0);
        EXPECT_LE(std::abs(f.visible - exact), f.bound + 1e-12) << sphereRadius;
        // The ellipse (here a circle) bracketed to within half the target.
        EXPECT_LE(f.bound, 0.5 / 2048.0) << sphereRadius;
    }
}

// The closed form (light_disk_shadow.h) against the slicing it replaces, point by point over the
// presets' penumbrae: |closed - sliced| <= both bounds. Points are the camera's hits on a grid of
// the frame, those in the penumbra (0 < f < 1) and a few outside it.
struct FractionCheck {
    int penumbra = 0;
    int compared = 0;
    double worstClosedBound = 0.0;
};

FractionCheck compareWithSlices(const Scene& scene, int wanted) {
    const glm::ivec2 grid(160, 90);
    const float aspect = 16.0f / 9.0f;
    const double target = 1.0 / 2048.0;
    FractionCheck check;
    int stride = 0;
    for (int y = 0; y < grid.y; ++y) {
        for (int x = 0; x < grid.x; ++x) {
            Ray ray = cameraRay(scene.camera, pixelCentreNdc({x, y}, grid), aspect);
            std::optional<Hit> hit = intersect(scene, ray);
            if (!hit) continue;
            glm::dvec3 pos(hit->posWs);
            glm::dvec3 facing(hit->frontFace ? hit->normalWs : -hit->normalWs);
            LightFraction closed = lightVisibleFraction(scene, pos, facing, hit->object, target);
            bool partial = closed.visible > 0.0 && closed.visible < 1.0;
            // Every penumbra point until `wanted`, and one in 97 of the others.
            if (!(partial ? check.penumbra < wanted : ++stride % 97 == 0)) continue;
            LightFraction sliced =
                lightVisibleFractionBySlices(scene, pos, facing, hit->object, target);
            EXPECT_LE(std::abs(closed.visible - sliced.visible), closed.bound + sliced.bound)
                << scene.name << " pixel " << x << ", " << y << " closed " << closed.visible
                << " sliced " << sliced.visible;
            check.penumbra += partial ? 1 : 0;
            ++check.compared;
            check.worstClosedBound = std::max(check.worstClosedBound, closed.bound);
        }
    }
    return check;
}

TEST(LightVisibility, TheClosedFormAgreesWithTheSlicesOnThePresets) {
    // name, light size (degrees, or a spot's radius; 0: the preset's own)
    const std::pair<const char*, float> presets[] = {
        {"post-in-sun", 0.0f}, {"post-under-spot", 0.0f},  {"box-on-plane", 1.0f}, {"stairs", 1.5f},
        {"pole", 2.0f},        {"sphere-over-plane", 2.0f}};
    for (auto [name, size] : presets) {
        Scene scene = *presetScene(name);
        if (size > 0.0f) scene.light.angularDiameterDeg = size;
        FractionCheck check = compareWithSlices(scene, 40);
        EXPECT_GE(check.penumbra, 20) << name;
        EXPECT_GE(check.compared, check.penumbra + 5) << name;
        // Boxes and rectangles are exact up to rounding; a sphere's ellipse is bracketed.
        bool sphere = std::string(name) == "sphere-over-plane";
        EXPECT_LE(check.worstClosedBound, sphere ? 0.5 / 2048.0 : 1e-8) << name;
    }
}

// An off-axis sphere under a sun: its shadow on the disk is an ellipse, bracketed between two
// polygons; the bracket's middle agrees with the slicing, and its gap is stated in the bound.
// (Every point here sees part of the sphere's image on the disk: the image's angular radius
// 0.025 plus the disk's tan(2 deg) exceeds each point's offset over 2 units of height.)
TEST(LightVisibility, ASphereOffTheAxisIsBracketed) {
    const double diameter = 4.0;
    Scene scene = sphereScene(diameter, 0.05, 2.0);
    for (double x : {-0.1, -0.07, -0.05, -0.03, 0.0, 0.02, 0.04, 0.06, 0.09}) {
        LightFraction closed =
            lightVisibleFraction(scene, {x, 0.0, 0.02}, {0.0, 1.0, 0.0}, 0, 1.0 / 2048.0);
        LightFraction sliced =
            lightVisibleFractionBySlices(scene, {x, 0.0, 0.02}, {0.0, 1.0, 0.0}, 0, 1.0 / 2048.0);
        EXPECT_LE(std::abs(closed.visible - sliced.visible), closed.bound + sliced.bound) << x;
        EXPECT_LE(closed.bound, 0.5 / 2048.0) << x;
        EXPECT_GT(closed.bound, 0.0) << x;  // the bracket's gap, never claimed away
    }
}

TEST(LightVisibility, UmbraSeesNothingAndFarPointsSeeAll) {
    Scene scene = sphereScene(0.53, 0.5, 1.5);
    LightFraction deep =
        lightVisibleFraction(scene, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1.0 / 2048.0);
    EXPECT_EQ(deep.visible, 0.0);
    LightFraction far =
        lightVisibleFraction(scene, {2.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1.0 / 2048.0);
    EXPECT_EQ(far.visible, 1.0);
    // The sphere's own top faces the whole sun, its side sees half of it (the horizon through
    // the disk's centre), its underside none.
    EXPECT_EQ(lightVisibleFraction(scene, {0.0, 2.0, 0.0}, {0.0, 1.0, 0.0}, 1, 1e-4).visible, 1.0);
    EXPECT_NEAR(lightVisibleFraction(scene, {0.5, 1.5, 0.0}, {1.0, 0.0, 0.0}, 1, 1e-4).visible, 0.5,
                1e-4);
    EXPECT_EQ(lightVisibleFraction(scene, {0.0, 1.0, 0.0}, {0.0, -1.0, 0.0}, 1, 1e-4).visible, 0.0);
}

// The whole area truth on a frame: the camera looks straight down, so a ground pixel covers
// world x in [xa, xb] exactly (x linear in the window x), and its exact value is the mean of the
// closed form over that band (the integral of s above).
TEST(AreaGroundTruth, PixelsAcrossAStraightEdgesPenumbraMatchTheClosedForm) {
    const double diameter = 4.0;
    const double cx = 0.12;
    Scene scene = edgeScene(diameter, cx);
    double r = radiusOf(diameter);
    glm::ivec2 size(32, 18);
    GroundTruthOptions options;
    options.area = true;
    GroundTruth truth = computeGroundTruth(scene, size, options);
    double halfWidth = 20.0 * std::tan(1.0 * PI / 180.0) * size.x / size.y;
    auto worldX = [&](double windowX) { return cx + halfWidth * (2.0 * windowX / size.x - 1.0); };
    int penumbra = 0, checked = 0;
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            double xa = worldX(x), xb = worldX(x + 1);
            if (xa <= 1e-3) continue;  // the slab and its side face, not the ground
            double scale = (H + 1.0) * r;
            double exact = pixelExact(xa, xb, scale);
            size_t k = truth.index(x, y);
            EXPECT_LE(std::abs(truth.visibility[k] - exact), truth.bound[k] + 1e-6)
                << "pixel " << x << ", " << y << " exact " << exact;
            EXPECT_LE(truth.bound[k], options.targetBound);
            penumbra += exact < 0.999 ? 1 : 0;
            ++checked;
        }
    }
    EXPECT_GE(penumbra, 2 * size.y);  // the penumbra is pixels wide
    EXPECT_GE(checked, 18 * size.y);
}

TEST(AreaGroundTruth, IsTheSameForAnyThreadCount) {
    Scene scene = sphereScene(2.0, 0.4, 1.0);
    GroundTruthOptions options;
    options.area = true;
    glm::ivec2 size(32, 18);
    options.threads = 1;
    GroundTruth one = computeGroundTruth(scene, size, options);
    options.threads = 2;
    GroundTruth two = computeGroundTruth(scene, size, options);
    options.threads = 0;
    GroundTruth all = computeGroundTruth(scene, size, options);
    EXPECT_GT(one.refinedPixels, 10);
    EXPECT_EQ(one.visibility, two.visibility);
    EXPECT_EQ(one.bound, two.bound);
    EXPECT_EQ(one.visibility, all.visibility);
    EXPECT_EQ(one.bound, all.bound);
}

// A spot light's disk (light.h: radius R, at positionWs, facing along directionWs) at height
// L straight above the origin, over the slab of edgeScene. From ground point (x, 0, 0) the ray
// toward disk point (xd, L, z) passes height h at x + (xd - x) h / L, so the slab's edge at
// height h (the top, H + 1, for x >= 0; the bottom, H, under the slab) hides exactly the disk's
// part xd < c, c = x (1 - L / h): the part left is the circular segment beyond the chord at c,
// s(c / R), and along x it integrates in closed form as the sun's does.
// (The visible share of the disk's AREA: light_visibility.h weighs every point of it alike.)
constexpr double SPOT_HEIGHT = 6.0;
Scene spotEdgeScene(double radius, double cx) {
    std::string toml =
        "[camera]\neye = [" + std::to_string(cx) + ", 20.0, 0.0]\ntarget = [" + std::to_string(cx) +
        ", 0.0, 0.0]\nup = [0.0, 0.0, -1.0]\nfov = 2.0\n"
        "[light]\ntype = \"spot\"\ndirection = [0.0, -1.0, 0.0]\n"
        "position = [0.0, " +
        std::to_string(SPOT_HEIGHT) + ", 0.0]\ncone = 60.0\nradius = " + std::to_string(radius) +
        "\n[[object]]\ntype = \"plane\"\nname = \"ground\"\ncentre = [0.0, 0.0, "
        "0.0]\nnormal = [0.0, 1.0, 0.0]\nsize = [200.0, 200.0]\n"
        "[[object]]\ntype = \"box\"\nname = \"slab\"\ncentre = [-50.0, " +
        std::to_string(H + 0.5) + ", 0.0]\nhalf = [50.0, 0.5, 50.0]\n";
    return parseSceneString(toml, "spot-edge-test");
}

// c / x: where the slab's edge cuts the disk, per unit of x (see spotEdgeScene).
double spotChordPerX(double x) { return 1.0 - SPOT_HEIGHT / (x >= 0.0 ? H + 1.0 : H); }

TEST(LightVisibility, ASpotDiskCutByAStraightEdgeIsACircularSegment) {
    Scene scene = spotEdgeScene(0.3, 0.0);
    double radius = scene.light.radius;  // the scene's float, which the closed form meets exactly
    int checked = 0, partial = 0;
    for (double x : {-0.2, -0.14, -0.1, -0.05, -0.01, 0.0, 0.02, 0.1, 0.2, 0.29, 0.35}) {
        double exact = segment(x * spotChordPerX(x) / radius);
        // The closed form (light_disk_shadow.h): exact up to rounding.
        LightFraction f =
            lightVisibleFraction(scene, {x, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1.0 / 2048.0);
        EXPECT_LE(std::abs(f.visible - exact), f.bound + 1e-12) << "x " << x;
        EXPECT_LE(f.bound, 1e-8) << "x " << x;
        // The slicing it falls back to, within its own bound.
        LightFraction sliced =
            lightVisibleFractionBySlices(scene, {x, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1.0 / 2048.0);
        EXPECT_LE(std::abs(sliced.visible - exact), sliced.bound + 1e-9) << "x " << x;
        EXPECT_LE(sliced.bound, 1.0 / 2048.0) << "x " << x;
        partial += exact > 0.01 && exact < 0.99 ? 1 : 0;
        ++checked;
    }
    EXPECT_EQ(checked, 11);
    EXPECT_GE(partial, 7);  // most of them in the penumbra
    // Half the disk at the edge's foot; all of it past the penumbra, none deep under the slab.
    EXPECT_NEAR(lightVisibleFraction(scene, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1e-4).visible, 0.5,
                1e-4);
    EXPECT_EQ(lightVisibleFraction(scene, {0.5, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1e-4).visible, 1.0);
    EXPECT_EQ(lightVisibleFraction(scene, {-0.5, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1e-4).visible, 0.0);
    // Outside the spot's cone (60 degrees: x > L tan 60) nothing of the light arrives.
    EXPECT_EQ(lightVisibleFraction(scene, {11.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1e-4).visible, 0.0);
}

// A sphere of radius r centred on the spot's axis at height h, seen from the origin: a cone of
// half-angle beta = asin(r / h) that meets the disk's plane (height L) in a circle of radius
// L tan(beta) about the disk's centre: an annular eclipse, 1 - (L tan(beta))^2 / R^2 visible.
TEST(LightVisibility, ASphereUnderTheSpotIsAnAnnularEclipse) {
    const double radius = 0.5;
    const double height = 3.0;
    for (double sphereRadius : {0.05, 0.15, 0.24, 0.3}) {
        std::string toml =
            "[camera]\neye = [3.0, 3.0, 3.0]\ntarget = [0.0, 0.0, 0.0]\n"
            "[light]\ntype = \"spot\"\ndirection = [0.0, -1.0, 0.0]\nposition = [0.0, " +
            std::to_string(SPOT_HEIGHT) +
            ", 0.0]\ncone = 45.0\nradius = " + std::to_string(radius) +
            "\n[[object]]\ntype = \"plane\"\ncentre = [0.0, 0.0, 0.0]\n"
            "normal = [0.0, 1.0, 0.0]\nsize = [20.0, 20.0]\n"
            "[[object]]\ntype = \"sphere\"\ncentre = [0.0, " +
            std::to_string(height) + ", 0.0]\nradius = " + std::to_string(sphereRadius) + "\n";
        Scene scene = parseSceneString(toml, "spot-sphere-test");
        double seen = SPOT_HEIGHT * std::tan(std::asin(sphereRadius / height));
        double exact = seen >= radius ? 0.0 : 1.0 - seen * seen / (radius * radius);
        LightFraction f =
            lightVisibleFraction(scene, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1.0 / 2048.0);
        EXPECT_LE(std::abs(f.visible - exact), f.bound + 1e-9) << sphereRadius;
    }
}

// A box that rises past the spot's disk beside it blocks nothing of it: only the part of a
// caster between the point and the light counts (the slice clipped at the disk's plane). Seen
// from the origin the pole's part above the light (x in [2, 3], up to height 100) lies in the
// directions of the disk's points, its part below the disk does not.
TEST(LightVisibility, ACasterBehindTheSpotDiskDoesNotBlock) {
    std::string toml =
        "[camera]\neye = [3.0, 3.0, 3.0]\ntarget = [0.0, 0.0, 0.0]\n"
        "[light]\ntype = \"spot\"\ndirection = [0.0, -1.0, 0.0]\nposition = [0.0, " +
        std::to_string(SPOT_HEIGHT) +
        ", 0.0]\ncone = 45.0\nradius = 0.5\n"
        "[[object]]\ntype = \"plane\"\ncentre = [0.0, 0.0, 0.0]\n"
        "normal = [0.0, 1.0, 0.0]\nsize = [20.0, 20.0]\n"
        "[[object]]\ntype = \"box\"\nname = \"pole\"\ncentre = [2.5, 50.0, 0.0]\n"
        "half = [0.5, 50.0, 0.5]\n";
    Scene scene = parseSceneString(toml, "spot-behind-test");
    EXPECT_EQ(lightVisibleFraction(scene, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0, 1e-4).visible, 1.0);
    // A sphere reaching behind the disk is refused rather than integrated wrongly.
    std::string sphere = toml +
                         "[[object]]\ntype = \"sphere\"\nname = \"high\"\ncentre = [-3.0, "
                         "6.1, 0.0]\nradius = 0.2\n";
    Scene high = parseSceneString(sphere, "spot-behind-test");
    EXPECT_THROW(checkSpotDiskCasters(high), std::invalid_argument);
    EXPECT_NO_THROW(checkSpotDiskCasters(scene));
    GroundTruthOptions options;
    options.area = true;
    EXPECT_THROW(computeGroundTruth(high, {8, 6}, options), std::invalid_argument);
}

// The whole frame under the spot's disk, as the sun's above: each ground pixel covers world x
// in [xa, xb], and its exact value is the mean of s(k x / R) over it, k = spotChordPerX.
TEST(AreaGroundTruth, PixelsUnderASpotDiskMatchTheClosedForm) {
    const double radius = 0.3;
    const double cx = 0.12;
    Scene scene = spotEdgeScene(radius, cx);
    glm::ivec2 size(32, 18);
    GroundTruthOptions options;
    options.area = true;
    GroundTruth truth = computeGroundTruth(scene, size, options);
    double halfWidth = 20.0 * std::tan(1.0 * PI / 180.0) * size.x / size.y;
    auto worldX = [&](double windowX) { return cx + halfWidth * (2.0 * windowX / size.x - 1.0); };
    int penumbra = 0, checked = 0;
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            double xa = worldX(x), xb = worldX(x + 1);
            if (xa <= 1e-3) continue;  // the slab and its side face, not the ground
            // x > 0: k < 0, and s(u) = 1 - s(-u) turns it into the sun's form.
            double scale = -radius / spotChordPerX(xa);
            double exact = pixelExact(xa, xb, scale);
            size_t k = truth.index(x, y);
            EXPECT_LE(std::abs(truth.visibility[k] - exact), truth.bound[k] + 1e-6)
                << "pixel " << x << ", " << y << " exact " << exact;
            EXPECT_LE(truth.bound[k], options.targetBound);
            penumbra += exact < 0.999 ? 1 : 0;
            ++checked;
        }
    }
    EXPECT_GE(penumbra, 4 * size.y);  // the penumbra is pixels wide
    EXPECT_GE(checked, 18 * size.y);
}

TEST(AreaGroundTruth, RefusesALightWithoutASize) {
    Scene scene = sphereScene(0.0, 0.4, 1.0);
    GroundTruthOptions options;
    options.area = true;
    EXPECT_THROW(computeGroundTruth(scene, {16, 9}, options), std::invalid_argument);
}

}  // namespace
}  // namespace pcf
