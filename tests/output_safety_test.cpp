// Output safety across the commands: an output that cannot be written is refused before any
// work, with one line and exit code 2, and nothing is left behind: no file, no folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_command.h"
#include "virtual_display.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;
using testutil::runPcfscope;

class OutputSafetyTest : public ::testing::Test {
protected:
    void SetUp() override { mDir = testutil::makeTempDir("outputs"); }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    // Everything under the test folder, for "nothing was left" checks.
    std::vector<std::string> leftovers() const {
        std::vector<std::string> names;
        for (const auto& e : fs::recursive_directory_iterator(mDir)) {
            names.push_back(fs::relative(e.path(), mDir).string());
        }
        return names;
    }
    void expectRefused(const std::string& args, const std::string& expect,
                       const std::string& env = "") {
        auto r = runPcfscope(args, "cd " + mDir.string() + " && " + (env.empty() ? "env" : env));
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << args << "\n" << r.err;
        EXPECT_NE(r.err.find(expect), std::string::npos) << args << "\n" << r.err;
        EXPECT_EQ(r.err.find("internal error"), std::string::npos) << args << "\n" << r.err;
        EXPECT_TRUE(leftovers().empty()) << args << ": left " << leftovers().front();
    }
    fs::path mDir;
};

const std::string RENDER = "render --scene box-on-plane --size 160x90 ";

// The PNG is fine, the raw folder is not: neither is written, and the folders made on the way to
// the PNG are taken back.
TEST_F(OutputSafetyTest, RenderWritesAllOutputsOrNone) {
    expectRefused(RENDER + "-o new/deeper/frame.png --raw /proc/pcfscope-raw",
                  "--raw /proc/pcfscope-raw: cannot create folder");
    expectRefused(RENDER + "-o /proc/pcfscope.png", "-o /proc/pcfscope.png: cannot write into /proc");
    expectRefused(RENDER + "-o /dev/null/frame.png", "/dev/null is not a directory");
    expectRefused(RENDER + "-o frame.tif", "must end in .png");
    fs::create_directory(mDir / "dir.png");
    auto r = runPcfscope(RENDER + "-o " + path("dir.png"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
    fs::remove(mDir / "dir.png");

    // And when everything can be written, everything is, folders included (a trailing slash
    // names the same folder).
    auto ok = runPcfscope(RENDER + "-o " + path("a/b/frame.png") + " --raw " + path("raw/x/"));
    ASSERT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_TRUE(fs::is_regular_file(mDir / "a/b/frame.png"));
    for (const char* name : {"shadowmap.exr", "lightspace.exr", "visibility.exr", "positions.exr"}) {
        EXPECT_TRUE(fs::is_regular_file(mDir / "raw/x" / name)) << name;
    }
}

// A link the user made is theirs even when it points nowhere: refused, and still there.
TEST_F(OutputSafetyTest, DanglingLinkIsNotTakenForAFreeName) {
    fs::create_symlink("/nonexistent/pcfscope-target.png", mDir / "link.png");
    auto r = runPcfscope(RENDER + "-o " + path("link.png") + " --raw /proc/pcfscope-raw");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    auto again = runPcfscope(RENDER + "-o " + path("link.png"));
    EXPECT_EQ(again.exitCode, 2) << again.err;
    EXPECT_NE(again.err.find("already exists"), std::string::npos) << again.err;
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(mDir / "link.png")));
    fs::remove(mDir / "link.png");
}

TEST_F(OutputSafetyTest, TruthNeedsAWritableExr) {
    expectRefused("truth --scene pole --size 16x9 -o truth.png", "must end in .exr");
    expectRefused("truth --scene pole --size 16x9 -o /proc/truth.exr", "cannot write into /proc");
    std::ofstream(mDir / "mine.exr") << "the user's";
    auto r = runPcfscope("truth --scene pole --size 16x9 -o " + path("mine.exr"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("already exists"), std::string::npos) << r.err;
    EXPECT_EQ(testutil::readAll(mDir / "mine.exr"), "the user's");
}

TEST_F(OutputSafetyTest, ExportAndBenchRefuseUnwritableFolders) {
    expectRefused("export 1 --steps 1 -o /proc/pcfscope-frames", "cannot create folder");
    expectRefused("export 1 --steps 1 --size 100x100 -o frames", "--size 100x100 is out of range");
    expectRefused("bench --quick --methods nearest -o /proc/pcfscope-bench",
                  "cannot create folder");
    auto ok = runPcfscope("export 1 --steps 1 --size 320x180 -o " + path("new/frames/"));
    ASSERT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_TRUE(fs::is_regular_file(mDir / "new/frames/01-hard-shadows-step01.png"));
    fs::remove_all(mDir / "new");

    std::ofstream(mDir / "file") << "x";
    auto r = runPcfscope("export 1 --steps 1 -o " + path("file"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("is not a directory"), std::string::npos) << r.err;
}

// A screenshot that cannot be written is refused before the replayed keys run: the E key's
// export must not happen either.
TEST_F(OutputSafetyTest, ViewChecksTheScreenshotBeforeReplayingKeys) {
    expectRefused("view 1 --size 10x10", "--size 10x10 is out of range");
    testutil::VirtualDisplay x;
    ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
    expectRefused("view 1 --keys e --screenshot /proc/pcfscope/v.png", "cannot create folder",
                  "DISPLAY=" + x.display());
    expectRefused("view 1 --keys e --screenshot v.jpg", "must end in .png",
                  "DISPLAY=" + x.display());
}

}  // namespace
}  // namespace pcf
