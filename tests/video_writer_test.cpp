// VideoWriter: frames in, a video FFmpeg reads back with the same size and frame count out; the
// GIF's fixed palette; a failed write is an error, not a silent short file.
#include "video/video_writer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "run_command.h"
#include "video_read.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

// A moving gradient: frame k's pixel (x, y).
std::vector<uint8_t> testFrame(int w, int h, int k) {
    std::vector<uint8_t> rgba(static_cast<size_t>(w) * h * 4);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            uint8_t* p = &rgba[(static_cast<size_t>(y) * w + x) * 4];
            p[0] = static_cast<uint8_t>((x * 4 + k * 16) & 255);
            p[1] = static_cast<uint8_t>(y * 5);
            p[2] = static_cast<uint8_t>(k * 40);
            p[3] = 255;
        }
    }
    return rgba;
}

void writeVideo(const fs::path& path, VideoFormat format, int w, int h, int frames) {
    VideoWriter writer(path, format, w, h, 10);
    for (int k = 0; k < frames; ++k) writer.addFrame(testFrame(w, h, k));
    writer.finish();
    EXPECT_EQ(writer.framesWritten(), frames);
}

TEST(VideoWriter, Mp4IsH264Yuv420pWithEveryFrame) {
    fs::path dir = testutil::makeTempDir("video");
    writeVideo(dir / "a.mp4", VideoFormat::Mp4, 96, 64, 7);
    testutil::expectMp4(testutil::readVideo((dir / "a.mp4").string()), 96, 64, 7);
    fs::remove_all(dir);
}

TEST(VideoWriter, GifHasEveryFrameAndTheSameBytesRunToRun) {
    fs::path dir = testutil::makeTempDir("video");
    writeVideo(dir / "a.gif", VideoFormat::Gif, 75, 41, 5);
    writeVideo(dir / "b.gif", VideoFormat::Gif, 75, 41, 5);
    testutil::expectGif(testutil::readVideo((dir / "a.gif").string()), 75, 41, 5);
    EXPECT_EQ(testutil::readAll(dir / "a.gif"), testutil::readAll(dir / "b.gif"));
    fs::remove_all(dir);
}

TEST(VideoWriter, GifPaletteKeepsItsOwnColoursAtEveryDitherPosition) {
    std::vector<uint32_t> palette = gifPalette();
    ASSERT_EQ(palette.size(), 256u);
    for (int index : {0, 41, 42 * 5 + 6 * 6 + 5, 100}) {
        uint32_t c = palette[static_cast<size_t>(index)];
        for (int y = 0; y < 4; ++y) {
            for (int x = 0; x < 4; ++x) {
                EXPECT_EQ(gifPaletteIndex((c >> 16) & 255, (c >> 8) & 255, c & 255, x, y), index)
                    << "index " << index << " at " << x << "," << y;
            }
        }
    }
    // A grey between two levels is dithered: both neighbours appear across the 4 x 4 cell.
    std::vector<int> seen(256, 0);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) ++seen[gifPaletteIndex(140, 140, 140, x, y)];
    }
    int used = 0;
    for (int n : seen) used += n > 0;
    EXPECT_GE(used, 2);
}

TEST(VideoWriter, OddSizesAreRefusedForMp4) {
    EXPECT_TRUE(videoSizeProblem(VideoFormat::Mp4, 101, 64).has_value());
    EXPECT_FALSE(videoSizeProblem(VideoFormat::Gif, 101, 63).has_value());
    EXPECT_THROW(VideoWriter("/tmp/never.mp4", VideoFormat::Mp4, 101, 64, 10), VideoError);
    EXPECT_FALSE(fs::exists("/tmp/never.mp4"));
}

TEST(VideoWriter, AFullDiskIsAnError) {
    EXPECT_THROW(
        {
            VideoWriter writer("/dev/full", VideoFormat::Gif, 64, 64, 10);
            for (int k = 0; k < 40; ++k) writer.addFrame(testFrame(64, 64, k));
            writer.finish();
        },
        VideoError);
}

}  // namespace
}  // namespace pcf
