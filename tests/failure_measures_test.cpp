// The leak's width (failure_measures.h: leakWidth) on synthetic frames: a band of leaking pixels
// along a contact sets it, a stray pixel far from the caster does not, and the support says how
// many pixels the width stands on.
#include "measure/failure_measures.h"

#include <gtest/gtest.h>

namespace pcf {
namespace {

// A W x H frame whose every pixel is clean umbra, a pixel's distance from the caster its column
// (texels) and half that (world); visibility 0 (no leak) until leak() lights pixels.
struct SyntheticLeak {
    glm::ivec2 size{64, 24};
    std::vector<float> visibility, texels, world;
    std::vector<uint8_t> umbra;
    SyntheticLeak() {
        size_t n = static_cast<size_t>(size.x) * size.y;
        visibility.assign(n, 0.0f);
        umbra.assign(n, 1);
        texels.resize(n);
        world.resize(n);
        for (size_t k = 0; k < n; ++k) {
            texels[k] = static_cast<float>(k % size.x);
            world[k] = 0.5f * texels[k];
        }
    }
    void leak(int x, int y, float v = 0.5f) { visibility[y * size.x + x] = v; }
    // A band along the contact (column 0): columns 0..reach of rows 8..11.
    void band(int reach) {
        for (int y = 8; y < 12; ++y) {
            for (int x = 0; x <= reach; ++x) leak(x, y);
        }
    }
    LeakWidth width() const { return leakWidth(visibility, umbra, texels, world, size); }
};

TEST(LeakWidth, AStrayPixelDoesNotMoveTheWidthAlongASweep) {
    // A synthetic bias sweep: the real leak band grows 2, 4, 6, 9 texels from the contact; at the
    // second step one stray pixel leaks 50 texels out, at the third two strays touch diagonally.
    const int reaches[] = {2, 4, 6, 9};
    for (int step = 0; step < 4; ++step) {
        SyntheticLeak f;
        f.band(reaches[step]);
        int strays = 0;
        if (step == 1) {
            f.leak(50, 2);
            strays = 1;
        }
        if (step == 2) {
            f.leak(55, 20);
            f.leak(56, 21);
            strays = 2;
        }
        LeakWidth w = f.width();
        EXPECT_EQ(w.texels, reaches[step]) << "step " << step;
        EXPECT_EQ(w.world, 0.5 * reaches[step]) << "step " << step;
        EXPECT_EQ(w.support, 4 * (reaches[step] + 1)) << "step " << step;
        EXPECT_EQ(w.stray, strays) << "step " << step;
    }
}

TEST(LeakWidth, RunsShorterThanTheMinimumAreStrayAndDiagonalRunsHoldTogether) {
    SyntheticLeak f;
    // LEAK_MIN_RUN - 1 pixels in a row, 40 texels out: not enough to count.
    for (int x = 40; x < 40 + LEAK_MIN_RUN - 1; ++x) f.leak(x, 3);
    LeakWidth shortRun = f.width();
    EXPECT_EQ(shortRun.texels, 0.0);
    EXPECT_EQ(shortRun.support, 0);
    EXPECT_EQ(shortRun.stray, LEAK_MIN_RUN - 1);
    // A one-pixel diagonal of LEAK_MIN_RUN pixels (8-neighbours): a run that counts.
    for (int i = 0; i < LEAK_MIN_RUN; ++i) f.leak(10 + i, 12 + i);
    LeakWidth diagonal = f.width();
    EXPECT_EQ(diagonal.texels, 10 + LEAK_MIN_RUN - 1);
    EXPECT_EQ(diagonal.support, LEAK_MIN_RUN);
    // Outside the umbra, or at the leak level, a pixel does not leak.
    SyntheticLeak g;
    g.band(5);
    for (int x = 0; x <= 30; ++x) g.umbra[10 * g.size.x + x] = x <= 5 ? 1 : 0;
    for (int x = 6; x <= 30; ++x) g.leak(x, 10);
    for (int x = 6; x <= 30; ++x) g.leak(x, 9, LEAK_LEVEL);
    EXPECT_EQ(g.width().texels, 5.0);
}

// A mask tested on every second pixel (bench's clean masks on a large frame): the band's tested
// pixels are two apart, a run only at that stride.
TEST(LeakWidth, AStridedMaskIsConnectedAtItsStride) {
    SyntheticLeak f;
    f.band(9);
    for (size_t k = 0; k < f.umbra.size(); ++k) {
        int x = static_cast<int>(k % f.size.x), y = static_cast<int>(k / f.size.x);
        f.umbra[k] = x % 2 == 0 && y % 2 == 0;
    }
    // Rows 8 and 10, columns 0, 2, .., 8: ten tested pixels, none next to another.
    LeakWidth plain = leakWidth(f.visibility, f.umbra, f.texels, f.world, f.size);
    EXPECT_EQ(plain.support, 0);
    EXPECT_EQ(plain.stray, 10);
    LeakWidth strided =
        leakWidth(f.visibility, f.umbra, f.texels, f.world, f.size, LEAK_MIN_RUN, 2);
    EXPECT_EQ(strided.support, 10);
    EXPECT_EQ(strided.texels, 8.0);
}

}  // namespace
}  // namespace pcf
