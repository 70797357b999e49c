// `pcfscope render --lesson L --step S` renders the step's scene as the viewer and export show
// it, including the lesson keys that move the shadow map's texel grid (origin_shift, snap), which
// are not render settings but the map's fit (app/session.h: lessonShadowFit).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "image_read.h"
#include "run_command.h"

namespace {

using Pixels = std::vector<unsigned char>;

// The top-left w x h of an RGBA image `width` wide (the scene's place in an exported frame).
Pixels crop(const Pixels& rgba, int width, int w, int h) {
    Pixels out;
    out.reserve(static_cast<size_t>(w) * h * 4);
    for (int y = 0; y < h; ++y) {
        auto row = rgba.begin() + static_cast<std::ptrdiff_t>((static_cast<size_t>(y) * width) * 4);
        out.insert(out.end(), row, row + static_cast<std::ptrdiff_t>(w) * 4);
    }
    return out;
}

// Pixels (not bytes) where a and b differ.
std::vector<bool> differs(const Pixels& a, const Pixels& b) {
    std::vector<bool> d(a.size() / 4, false);
    for (size_t k = 0; k < a.size() && k < b.size(); ++k) d[k / 4] = d[k / 4] || a[k] != b[k];
    return d;
}

size_t count(const std::vector<bool>& v) {
    size_t n = 0;
    for (bool b : v) n += b ? 1 : 0;
    return n;
}

class RenderLesson : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("render-lesson"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    Pixels render(int step) {
        std::string png = (mDir / ("step" + std::to_string(step) + ".png")).string();
        testutil::CommandResult r = testutil::runPcfscope(
            "render --lesson 13 --step " + std::to_string(step) + " --size 960x540 -o " + png);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return readImageBytes(png, 4);
    }
    std::filesystem::path mDir;
};

// Lesson 13: step 2 is nearest on the plain fit, step 4 the same with origin_shift = 0.25, and
// step 5 that slide snapped back to whole texels (the map of step 2 moved by whole texels).
TEST_F(RenderLesson, AppliesTheStepsTexelGridAsExportDoes) {
    Pixels plain = render(2);
    Pixels shifted = render(4);
    ASSERT_EQ(plain.size(), 960u * 540u * 4u);
    ASSERT_EQ(shifted.size(), plain.size());
    std::vector<bool> slid = differs(plain, shifted);
    // The quarter-texel slide moves the stair-stepped shadow edges, seen through the magnifier
    // (`magnify`: a texel 540 / 16 = 34 pixels high, its quarter about 8): many pixels, not all.
    EXPECT_GT(count(slid), slid.size() / 50);
    EXPECT_LT(count(slid), slid.size() / 4);

    // The exported frames at 1600x900 show the scene in their top-left 960x540, under the
    // overlay's marks, which are the same in both steps (same pixel, same view).
    std::string dir = (mDir / "export").string();
    testutil::CommandResult r = testutil::runPcfscope("export 13 --steps 2-4 -o " + dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto exported = [&](int step) {
        std::string png = dir + "/13-shimmer-and-snapping-step0" + std::to_string(step) + ".png";
        return crop(readImageBytes(png, 4), 1600, 960, 540);
    };
    std::vector<bool> marks2 = differs(plain, exported(2));
    std::vector<bool> marks4 = differs(shifted, exported(4));
    // Where the render and the export disagree is the overlay only: the ring, the label and the
    // texel grid with the tinted texels read, drawn within gridRadius (540 / 7 = 77 pixels) of
    // the picked pixel, the same in both steps but for that grid (which slides with the map's
    // grid). Lesson 13's point is at (479, 270) of a 960x540 scene: the magnifier centres it. A
    // render of step 4 on the plain fit would disagree along every slid shadow edge too.
    EXPECT_LT(count(marks4), marks4.size() / 30);
    size_t farFromPixel = 0;
    for (size_t k = 0; k < marks2.size(); ++k) {
        int x = static_cast<int>(k % 960), y = static_cast<int>(k / 960);
        bool near = std::abs(x - 479) <= 78 && std::abs(y - 270) <= 78;
        farFromPixel += marks2[k] != marks4[k] && !near ? 1 : 0;
    }
    EXPECT_EQ(farFromPixel, 0u);
    size_t slidOutsideMarks = 0;
    for (size_t k = 0; k < slid.size(); ++k) slidOutsideMarks += slid[k] && !marks4[k] ? 1 : 0;
    EXPECT_GT(slidOutsideMarks, 100u);
}

}  // namespace
