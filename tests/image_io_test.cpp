// PNG and EXR round trips, row order, atomic writes, and the one-line errors of readDepthImage.
#include "render/image_io.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>

#include "exr_header.h"
#include "run_command.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;

class ImageIo : public ::testing::Test {
  protected:
    void SetUp() override {
        mDir = fs::temp_directory_path() /
               ("pcfscope-image-io-" + std::to_string(getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(mDir);
        fs::create_directories(mDir);
    }
    void TearDown() override { fs::remove_all(mDir); }

    std::string path(const std::string& name) const { return (mDir / name).string(); }

    // Every file of the directory: leftovers of a failed write would show here.
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(mDir)) names.push_back(e.path().filename());
        std::sort(names.begin(), names.end());
        return names;
    }

    fs::path mDir;
};

// Writes an image with OIIO directly, in whatever layout a test needs to reject.
void writeRaw(const std::string& file, int w, int h, int channels, OIIO::TypeDesc type,
              const void* data) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(file);
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(w, h, channels, type);
    ASSERT_TRUE(out->open(file, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(type, data)) << out->geterror();
    ASSERT_TRUE(out->close());
}

std::string errorOf(const std::string& file) {
    try {
        readDepthImage(file);
    } catch (const ImageError& e) {
        std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << "not one line: " << what;
        return what;
    }
    ADD_FAILURE() << file << " was accepted";
    return "";
}

TEST_F(ImageIo, PngRoundTripKeepsBytesAndRowOrder) {
    const int w = 3;
    const int h = 2;
    std::vector<uint8_t> rgba(w * h * 4);
    for (size_t k = 0; k < rgba.size(); ++k) rgba[k] = static_cast<uint8_t>(k * 9 + 1);
    std::string file = path("round.png");
    writePngRgba8(file, w, h, rgba);
    EXPECT_TRUE(fileExists(file));
    // Straight alpha in, straight alpha back: the colours must not be touched by alpha.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(file, &config);
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().width, w);
    EXPECT_EQ(in->spec().height, h);
    EXPECT_EQ(in->spec().nchannels, 4);
    std::vector<uint8_t> back(rgba.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, back.data()));
    // The first row given is the first scanline of the file: the top of the picture.
    EXPECT_EQ(back, rgba);
    EXPECT_EQ(listing(), std::vector<std::string>{"round.png"});
}

TEST_F(ImageIo, ExrRoundTripKeepsFloatsChannelsAndRowOrder) {
    const int w = 4;
    const int h = 3;
    std::vector<float> rgb(w * h * 3);
    for (size_t k = 0; k < rgb.size(); ++k) rgb[k] = static_cast<float>(k) * 0.37f - 2.0f;
    std::string file = path("round.exr");
    writeExr(file, w, h, 3, rgb, {"R", "G", "B"});
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(file);
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().nchannels, 3);
    EXPECT_EQ(in->spec().channelnames, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::FLOAT);
    std::vector<float> back(rgb.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, back.data()));
    EXPECT_EQ(back, rgb);
}

TEST_F(ImageIo, DepthImageRoundTripGivesTheSameFloatsAndRows) {
    ShadowMap map(5, 3);
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 5; ++i) map.setDepth(i, j, 0.1f * static_cast<float>(j) + 0.013f * i);
    }
    std::string file = path("depth.exr");
    writeDepthImage(file, map);
    ShadowMap back = readDepthImage(file);
    EXPECT_EQ(back.size(), map.size());
    EXPECT_EQ(back.depths(), map.depths());
    // Row 0 = first scanline: OIIO's own view of the file agrees.
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(file);
    ASSERT_TRUE(in);
    float firstScanline[5];
    ASSERT_TRUE(in->read_scanline(0, 0, OIIO::TypeDesc::FLOAT, firstScanline));
    for (int i = 0; i < 5; ++i) EXPECT_EQ(firstScanline[i], map.depth(i, 0));

    // A one-channel EXR written through the general writer reads the same way.
    std::string plain = path("plain.exr");
    writeExr(plain, 5, 3, 1, map.depths(), {"Y"});
    EXPECT_EQ(readDepthImage(plain).depths(), map.depths());
}

TEST_F(ImageIo, ReadsHalfDepthImages) {
    std::vector<float> values = {0.0f, 0.25f, 0.5f, 1.0f, 0.125f, 0.75f};
    std::string file = path("half.exr");
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(file);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(file, OIIO::ImageSpec(3, 2, 1, OIIO::TypeDesc::HALF)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, values.data()));
    ASSERT_TRUE(out->close());
    ShadowMap map = readDepthImage(file);
    EXPECT_EQ(map.width(), 3);
    EXPECT_EQ(map.height(), 2);
    EXPECT_EQ(map.depths(), values);  // all exact in half
}

TEST_F(ImageIo, RejectsAnRgbImage) {
    std::vector<uint8_t> rgb(4 * 4 * 3, 200);
    std::string file = path("colour.png");
    writeRaw(file, 4, 4, 3, OIIO::TypeDesc::UINT8, rgb.data());
    EXPECT_EQ(errorOf(file), file + ": has 3 channels; a depth map has 1");
}

TEST_F(ImageIo, RejectsAUint8Png) {
    std::vector<uint8_t> grey(4 * 4, 128);
    std::string file = path("grey.png");
    writeRaw(file, 4, 4, 1, OIIO::TypeDesc::UINT8, grey.data());
    EXPECT_EQ(errorOf(file),
              file + ": holds uint8 integers; a depth map holds floats (half or float)");
}

TEST_F(ImageIo, RejectsANanTexel) {
    std::vector<float> depths(4 * 3, 0.5f);
    depths[1 * 4 + 2] = std::numeric_limits<float>::quiet_NaN();  // texel (2, 1)
    std::string file = path("nan.exr");
    writeExr(file, 4, 3, 1, depths, {"Z"});
    EXPECT_EQ(errorOf(file), file + ": texel (2, 1) is NaN");
}

TEST_F(ImageIo, RejectsOutOfRangeDepths) {
    ShadowMap map(2, 2, 0.5f);
    std::vector<float> depths = map.depths();
    depths[3] = 1.5f;
    std::string file = path("far.exr");
    writeExr(file, 2, 2, 1, depths, {"Z"});
    EXPECT_EQ(errorOf(file).rfind(file + ": texel (1, 1) has depth 1.5", 0), 0u);
}

TEST_F(ImageIo, MissingFileSaysItCannotRead) {
    std::string file = path("missing.exr");
    std::string message = errorOf(file);
    EXPECT_EQ(message.rfind(file + ": cannot read image (", 0), 0u) << message;
    EXPECT_EQ(message.back(), ')') << message;
}

TEST_F(ImageIo, FailedWritesLeaveNothingBehind) {
    std::vector<uint8_t> rgba(2 * 2 * 4, 7);
    // The rename fails: a directory holds the name. The half-done temporary must go.
    fs::create_directory(mDir / "taken.png");
    EXPECT_THROW(writePngRgba8(path("taken.png"), 2, 2, rgba), ImageError);
    EXPECT_TRUE(fs::is_directory(mDir / "taken.png"));
    // No writer for the extension.
    EXPECT_THROW(writePngRgba8(path("picture.nosuchformat"), 2, 2, rgba), ImageError);
    // A directory that does not exist.
    EXPECT_THROW(writePngRgba8(path("no/such/dir/x.png"), 2, 2, rgba), ImageError);
    // Too few pixels for the size.
    EXPECT_THROW(writePngRgba8(path("short.png"), 3, 3, rgba), ImageError);
    EXPECT_EQ(listing(), std::vector<std::string>{"taken.png"});
}

TEST_F(ImageIo, WriteReplacesAnExistingFileWhole) {
    std::string file = path("again.exr");
    writeExr(file, 2, 1, 1, std::vector<float>{0.25f, 0.5f}, {"Z"});
    writeExr(file, 3, 1, 1, std::vector<float>{0.75f, 1.0f, 0.0f}, {"Z"});
    EXPECT_EQ(readDepthImage(file).depths(), (std::vector<float>{0.75f, 1.0f, 0.0f}));
    EXPECT_EQ(listing(), std::vector<std::string>{"again.exr"});
}

// A header that claims more than MAX_DEPTH_IMAGE_SIDE is refused from the header: no 1.6 GB
// allocation, no seconds spent (the file is a few hundred bytes; only its header lies).
TEST_F(ImageIo, HugeHeadersAreRefusedBeforeAllocating) {
    std::string file = path("huge.exr");
    writeDepthImage(file, ShadowMap(16, 16, 0.5f));
    ASSERT_TRUE(testutil::makeExrClaimSize(file, 20000));
    auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(errorOf(file),
              file + ": is 20000 x 20000 texels; a depth map is at most 16384 on a side");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

TEST_F(ImageIo, NonRegularFilesAreRefusedWithoutBlocking) {
    ASSERT_EQ(mkfifo(path("fifo.exr").c_str(), 0644), 0);
    EXPECT_EQ(errorOf(path("fifo.exr")),
              path("fifo.exr") + ": cannot read image (not a regular file)");
    EXPECT_EQ(errorOf(mDir.string()), mDir.string() + ": cannot read image (it is a directory)");
}

// No time stamp in an EXR: the same data gives the same bytes, whenever written.
TEST_F(ImageIo, ExrsCarryNoDateTime) {
    writeExr(path("a.exr"), 2, 1, 1, std::vector<float>{0.25f, 0.5f}, {"Z"});
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path("a.exr"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().find_attribute("DateTime"), nullptr);
    EXPECT_EQ(testutil::readAll(mDir / "a.exr").find("DateTime"), std::string::npos);
}

// A link as the output: the image goes to the file it points at, and the link stays.
TEST_F(ImageIo, WritesThroughALink) {
    fs::create_directory(mDir / "real");
    fs::create_symlink("real/target.exr", mDir / "link.exr");
    writeExr(path("link.exr"), 1, 1, 1, std::vector<float>{0.5f}, {"Z"});
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(mDir / "link.exr")));
    EXPECT_EQ(readDepthImage(path("real/target.exr")).depths(), std::vector<float>{0.5f});
    writeTextFile(path("link.exr"), "text");  // text writes too
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(mDir / "link.exr")));
    EXPECT_EQ(testutil::readAll(mDir / "real/target.exr"), "text");
    EXPECT_EQ(listing(), (std::vector<std::string>{"link.exr", "real"}));
}

TEST_F(ImageIo, FileExists) {
    EXPECT_FALSE(fileExists(path("nothing.png")));
    EXPECT_FALSE(fileExists(mDir.string()));  // a directory is not a file
    writePngRgba8(path("something.png"), 1, 1, std::vector<uint8_t>{1, 2, 3, 4});
    EXPECT_TRUE(fileExists(path("something.png")));
}

}  // namespace
}  // namespace pcf
