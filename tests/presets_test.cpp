// The built-in scenes: each parses, has a caster and a receiver, and shows its shadow.
#include "scene/presets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "scene/raycast.h"
#include "scene/scene_file.h"

namespace pcf {
namespace {

constexpr float ASPECT = 16.0f / 9.0f;

TEST(Presets, NamesInOrder) {
    std::vector<std::string_view> names = presetNames();
    std::vector<std::string_view> expected = {"box-on-plane", "sphere-over-plane", "pole",
                                              "post-in-sun",  "post-under-spot",   "grazing",
                                              "stairs",       "stacked-cards",     "long-ground"};
    EXPECT_EQ(names, expected);
    EXPECT_FALSE(presetScene("no-such-scene"));
    EXPECT_FALSE(presetSceneToml("no-such-scene"));
}

TEST(Presets, EachParsesWithCastersAndReceivers) {
    for (std::string_view name : presetNames()) {
        SCOPED_TRACE(std::string(name));
        std::optional<Scene> scene = presetScene(name);
        ASSERT_TRUE(scene);
        EXPECT_EQ(scene->name, name);
        EXPECT_GE(casterCount(*scene), 1);
        EXPECT_GE(receiverCount(*scene), 1);
        EXPECT_GT(scene->camera.nearZ, 0.0f);
        EXPECT_GT(scene->camera.farZ, scene->camera.nearZ);
        // The text is what was parsed.
        Scene again = parseSceneString(*presetSceneToml(name), "again");
        EXPECT_EQ(again.objects.size(), scene->objects.size());
    }
}

// What a 16:9 frame of the preset shows, sampled on a 96 x 54 grid of pixel centres.
struct FrameStats {
    int pixels = 0;
    int castShadow = 0;             // a receiver facing the light, blocked by another object
    std::set<int> shadowedObjects;  // which objects carry cast shadows
    std::set<int> shadowHeights;    // their heights, in centimetres
};

FrameStats frameStats(const Scene& scene) {
    FrameStats st;
    const glm::ivec2 size(96, 54);
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            ++st.pixels;
            auto hit =
                intersect(scene, cameraRay(scene.camera, pixelCentreNdc({x, y}, size), ASPECT));
            if (!hit || !scene.objects[hit->object].receivesShadow) continue;
            LightSample toLight = towardLight(scene.light, hit->posWs);
            glm::vec3 facing = hit->frontFace ? hit->normalWs : -hit->normalWs;
            if (!toLight.insideCone || glm::dot(facing, toLight.dirWs) <= 0.0f) continue;
            if (!occluded(scene, hit->posWs, toLight.dirWs, toLight.distance, hit->object)) {
                continue;
            }
            EXPECT_FALSE(litByLight(scene, *hit));
            ++st.castShadow;
            st.shadowedObjects.insert(hit->object);
            st.shadowHeights.insert(static_cast<int>(std::lround(hit->posWs.y * 100.0f)));
        }
    }
    return st;
}

TEST(Presets, ShadowIsProminentInTheFrame) {
    for (std::string_view name : presetNames()) {
        SCOPED_TRACE(std::string(name));
        Scene scene = *presetScene(name);
        FrameStats st = frameStats(scene);
        // At least 1.5% of the frame is cast shadow (the pole's thin shadow is the least).
        EXPECT_GT(st.castShadow, st.pixels * 3 / 200) << st.castShadow << " of " << st.pixels;
    }
}

TEST(Presets, ShadowMapCoversEveryObject) {
    for (std::string_view name : presetNames()) {
        SCOPED_TRACE(std::string(name));
        Scene scene = *presetScene(name);
        glm::mat4 m = shadowClipFromWorld(scene);
        for (const SceneObject& object : scene.objects) {
            Aabb b = bounds(object.shape);
            for (int k = 0; k < 8; ++k) {
                ShadowCoord sc = shadowCoord(m, b.cornerWs(k));
                EXPECT_GE(sc.uvSm.x, 0.0f);
                EXPECT_LE(sc.uvSm.x, 1.0f);
                EXPECT_GE(sc.uvSm.y, 0.0f);
                EXPECT_LE(sc.uvSm.y, 1.0f);
                EXPECT_GE(sc.depth, 0.0f);
                EXPECT_LE(sc.depth, 1.0f);
            }
        }
    }
}

const SceneObject& objectNamed(const Scene& scene, std::string_view name) {
    for (const SceneObject& o : scene.objects) {
        if (o.name == name) return o;
    }
    throw std::runtime_error("no object " + std::string(name));
}

float lightAngleFromVerticalDeg(const Scene& scene) {
    return glm::degrees(std::acos(-glm::normalize(scene.light.directionWs).y));
}

TEST(Presets, EachShowsWhatItIsFor) {
    Scene box = *presetScene("box-on-plane");
    const Box& crate = std::get<Box>(objectNamed(box, "box").shape);
    EXPECT_FLOAT_EQ(crate.centreWs.y - crate.halfExtents.y, 0.0f);  // resting on the ground

    Scene sphere = *presetScene("sphere-over-plane");
    const Sphere& ball = std::get<Sphere>(objectNamed(sphere, "ball").shape);
    EXPECT_GT(ball.centreWs.y - ball.radius, 0.3f);       // floating
    EXPECT_GT(lightAngleFromVerticalDeg(sphere), 30.0f);  // an elongated ellipse

    Scene pole = *presetScene("pole");
    const Box& p = std::get<Box>(objectNamed(pole, "pole").shape);
    EXPECT_FLOAT_EQ(p.centreWs.y - p.halfExtents.y, 0.0f);  // its foot touches the ground
    EXPECT_GT(p.halfExtents.y, 10.0f * p.halfExtents.x);    // thin and tall
    // The foot itself is in the frame, so the gap peter panning opens can be seen.
    glm::vec4 clip =
        clipFromWorld(pole.camera, ASPECT) * glm::vec4(p.centreWs.x, 0, p.centreWs.z, 1);
    EXPECT_LT(std::abs(clip.x / clip.w), 0.9f);
    EXPECT_LT(std::abs(clip.y / clip.w), 0.9f);

    Scene grazing = *presetScene("grazing");
    float angle = lightAngleFromVerticalDeg(grazing);
    EXPECT_GE(angle, 80.0f);
    EXPECT_LE(angle, 85.0f);

    // Stairs: shadows fall on several receivers at several heights.
    Scene stairs = *presetScene("stairs");
    FrameStats st = frameStats(stairs);
    EXPECT_GE(st.shadowedObjects.size(), 3u);
    EXPECT_GE(st.shadowHeights.size(), 3u);
}

// stacked-cards' gap: the upper card's underside that far above the lower card's top, on the
// light's ray through the lower card's centre (so its shadow stays put); the default is the
// preset's own.
TEST(Presets, StackedCardsGapLiftsTheUpperCardAlongTheLight) {
    ASSERT_EQ(presetParams("stacked-cards").size(), 1u);
    const PresetParam& gap = presetParams("stacked-cards").front();
    EXPECT_EQ(gap.key, "gap");
    EXPECT_TRUE(presetParams("pole").empty());
    for (double g : {gap.min, 0.4, gap.defaultValue, gap.max}) {
        SCOPED_TRACE(g);
        const double values[] = {g};
        Scene scene = *presetScene("stacked-cards", values);
        const Box& lower = std::get<Box>(objectNamed(scene, "lower-card").shape);
        const Box& upper = std::get<Box>(objectNamed(scene, "upper-card").shape);
        float clear =
            (upper.centreWs.y - upper.halfExtents.y) - (lower.centreWs.y + lower.halfExtents.y);
        EXPECT_NEAR(clear, g, 1e-5);
        glm::vec3 along =
            glm::cross(upper.centreWs - lower.centreWs, glm::normalize(scene.light.directionWs));
        EXPECT_LT(glm::length(along), 1e-5f);
        // Two thin squares, the upper one smaller: its edges throw their shadow inside the
        // lower card's.
        EXPECT_EQ(lower.halfExtents.x, lower.halfExtents.z);
        EXPECT_EQ(upper.halfExtents.x, upper.halfExtents.z);
        EXPECT_LT(upper.halfExtents.x, lower.halfExtents.x);
        EXPECT_LT(lower.halfExtents.y, 0.05f * lower.halfExtents.x);
        EXPECT_GT(scene.camera.farZ, scene.camera.nearZ);
    }
    Scene byDefault = *presetScene("stacked-cards");
    const double values[] = {gap.defaultValue};
    EXPECT_EQ(std::get<Box>(objectNamed(byDefault, "upper-card").shape).centreWs,
              std::get<Box>(objectNamed(*presetScene("stacked-cards", values), "upper-card").shape)
                  .centreWs);
    const double outside[] = {gap.max * 2.0};
    EXPECT_THROW(presetScene("stacked-cards", outside), std::invalid_argument);
    EXPECT_THROW(presetScene("stacked-cards", std::span<const double>{}), std::invalid_argument);
}

TEST(Presets, FormatRoundTripsEveryPreset) {
    for (std::string_view name : presetNames()) {
        SCOPED_TRACE(std::string(name));
        Scene scene = *presetScene(name);
        Scene back = parseSceneString(formatSceneToml(scene), "formatted");
        ASSERT_EQ(back.objects.size(), scene.objects.size());
        EXPECT_EQ(back.camera.eyeWs, scene.camera.eyeWs);
        // Light directions are normalised again on the way back: equal to a float's rounding.
        glm::mat4 a = shadowClipFromWorld(back);
        glm::mat4 b = shadowClipFromWorld(scene);
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], 1e-5f);
        }
    }
}

}  // namespace
}  // namespace pcf
