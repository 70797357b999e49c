// The area-light truth over whole pixels (ground_truth_area.h): every pixel reaches its target
// (no pixel left at the scanline cap, contacts included), and each pixel agrees with the same
// pixel computed with every point's share of the disk sliced into chords (the computation the
// closed form replaced) within the two bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "measure/ground_truth.h"
#include "scene/presets.h"

namespace pcf {
namespace {

Scene presetWithLight(const char* name, float size) {
    Scene scene = *presetScene(name);
    if (size > 0.0f) scene.light.angularDiameterDeg = size;
    return scene;
}

// box-on-plane under a 0.5 degree sun at 320x180: the box's foot and edges, where a scanline's
// run of one face ends on the ground (a caster touching the point) or a sliver of the box lies
// in the pixel; (124, 49) stopped at the 513-scanline cap with a bound of 0.031.
TEST(AreaGroundTruth, EveryPixelOfBoxOnPlaneReachesTheTarget) {
    Scene scene = presetWithLight("box-on-plane", 0.5f);
    GroundTruthOptions options;
    options.area = true;
    glm::ivec2 size(320, 180);
    GroundTruth truth = computeGroundTruth(scene, size, options);
    EXPECT_GT(truth.refinedPixels, 1000);
    EXPECT_LE(truth.maxBound, options.targetBound);
    for (glm::ivec2 pixel : {glm::ivec2(124, 49), glm::ivec2(110, 91), glm::ivec2(116, 104)}) {
        GroundTruthPixel p = groundTruthAt(scene, size, pixel, options);
        EXPECT_TRUE(p.refined) << pixel.x << ", " << pixel.y;
        EXPECT_LE(p.bound, options.targetBound) << pixel.x << ", " << pixel.y;
        EXPECT_EQ(p.visibility, truth.visibility[truth.index(pixel.x, pixel.y)]);
    }
}

TEST(AreaGroundTruth, EveryPixelOfPostInSunReachesTheTarget) {
    Scene scene = presetWithLight("post-in-sun", 0.0f);
    GroundTruthOptions options;
    options.area = true;
    GroundTruth truth = computeGroundTruth(scene, {480, 270}, options);
    EXPECT_GT(truth.refinedPixels, 3000);
    EXPECT_LE(truth.maxBound, options.targetBound);
}

// Up to `count` refined pixels of the frame with a value strictly between 0 and 1, spread over
// it (every k-th in row order).
std::vector<glm::ivec2> penumbraPixels(const GroundTruth& truth, size_t count) {
    std::vector<glm::ivec2> all;
    for (int y = 0; y < truth.size.y; ++y) {
        for (int x = 0; x < truth.size.x; ++x) {
            float v = truth.visibility[truth.index(x, y)];
            if (truth.receiver[truth.index(x, y)] != 0 && v > 0.02f && v < 0.98f) {
                all.push_back({x, y});
            }
        }
    }
    std::vector<glm::ivec2> out;
    for (size_t k = 0; k < count && !all.empty(); ++k) out.push_back(all[k * all.size() / count]);
    return out;
}

TEST(AreaGroundTruth, PixelsAgreeWithTheSlicedDisk) {
    const std::pair<const char*, float> presets[] = {{"post-in-sun", 0.0f},
                                                     {"post-under-spot", 0.0f},
                                                     {"box-on-plane", 1.0f},
                                                     {"stairs", 1.5f},
                                                     {"sphere-over-plane", 2.0f}};
    glm::ivec2 size(160, 90);
    for (auto [name, light] : presets) {
        Scene scene = presetWithLight(name, light);
        GroundTruthOptions options;
        options.area = true;
        GroundTruth truth = computeGroundTruth(scene, size, options);
        std::vector<glm::ivec2> pixels = penumbraPixels(truth, 5);
        EXPECT_EQ(pixels.size(), 5u) << name;
        GroundTruthOptions sliced = options;
        sliced.areaBySlices = true;
        for (glm::ivec2 pixel : pixels) {
            size_t k = truth.index(pixel.x, pixel.y);
            GroundTruthPixel old = groundTruthAt(scene, size, pixel, sliced);
            EXPECT_LE(std::abs(truth.visibility[k] - old.visibility),
                      truth.bound[k] + old.bound + 1e-6f)
                << name << " pixel " << pixel.x << ", " << pixel.y << ": " << truth.visibility[k]
                << " +- " << truth.bound[k] << ", sliced " << old.visibility << " +- " << old.bound;
            EXPECT_LE(truth.bound[k], options.targetBound) << name;
        }
    }
}

}  // namespace
}  // namespace pcf
