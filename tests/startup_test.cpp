// What pcfscope loads before it starts: OpenImageIO (260 shared objects with its dependencies)
// and FFmpeg (130) only when a command reads or writes an image or a video
// (render/image_codec.h, video/av_library.h). The dynamic loader says what it opened
// (LD_DEBUG=files); the time it saves is measured by scripts/startup-cost, not here.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_command.h"

namespace {

// The shared objects the loader opened for `args`, as its LD_DEBUG=files lines name them.
std::string loaded(const std::string& args) {
    testutil::CommandResult r = testutil::runPcfscope(args, "LD_DEBUG=files");
    EXPECT_EQ(r.exitCode, 0) << args << ": " << r.err.substr(r.err.size() - 2000);
    return r.err;
}

// Whether a "file=..." line of the log names `library` (by soname, or by path when dlopen was
// given one).
bool opened(const std::string& log, const std::string& library) {
    for (size_t at = log.find("file="); at != std::string::npos; at = log.find("file=", at + 1)) {
        std::string line = log.substr(at, log.find('\n', at) - at);
        size_t name = line.find(library);
        if (name != std::string::npos && (line[name - 1] == '=' || line[name - 1] == '/')) {
            return true;
        }
    }
    return false;
}

TEST(Startup, CommandsWithoutImagesLoadNeitherOpenImageIoNorFfmpeg) {
    for (const std::string& args :
         {std::string("methods"), std::string("--help"),
          "lesson check " + std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/03-bilinear-lerp.toml"}) {
        std::string log = loaded(args);
        EXPECT_TRUE(opened(log, "libstdc++")) << args << ": no loader log";
        EXPECT_FALSE(opened(log, "libOpenImageIO")) << args;
        EXPECT_FALSE(opened(log, "libpcfscope_oiio")) << args;
        EXPECT_FALSE(opened(log, "libavcodec")) << args;
        EXPECT_FALSE(opened(log, "libavformat")) << args;
    }
}

TEST(Startup, AnImageLoadsTheCodecModuleWhenWritten) {
    std::filesystem::path dir = testutil::makeTempDir("startup");
    std::string png = (dir / "frame.png").string();
    std::string log = loaded("render --scene box-on-plane --size 64x36 -o " + png);
    EXPECT_TRUE(opened(log, "libpcfscope_oiio")) << log.substr(0, 2000);
    EXPECT_TRUE(opened(log, "libOpenImageIO")) << log.substr(0, 2000);
    // What it wrote is a PNG: the signature's first bytes.
    std::string bytes = testutil::readAll(png);
    ASSERT_GE(bytes.size(), 8u);
    EXPECT_EQ(bytes.substr(1, 3), "PNG");
    std::filesystem::remove_all(dir);
}

TEST(Startup, AVideoLoadsFfmpegWhenWritten) {
    std::filesystem::path dir = testutil::makeTempDir("startup");
    std::string gif = (dir / "clip.gif").string();
    std::string log = loaded("animate 1 --frames 2 --size 320x180 -o " + gif);
    EXPECT_TRUE(opened(log, "libavcodec")) << log.substr(0, 2000);
    EXPECT_EQ(testutil::readAll(gif).substr(0, 3), "GIF");
    std::filesystem::remove_all(dir);
}

}  // namespace
