// Output safety across the commands: an output that cannot be written is refused before any
// work, with one line and exit code 2, and nothing is left behind: no file, no folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <shared_mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "app/output_files.h"
#include "render/image_io.h"
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
    // Refused with one line holding `expect` (exit 2), the folder's contents as they were.
    void expectRefusedKeeping(const std::string& args, const std::string& expect) {
        std::vector<std::string> before = leftovers();
        std::sort(before.begin(), before.end());
        auto r = runPcfscope(args, "cd " + mDir.string() + " && env");
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << args << "\n" << r.err;
        EXPECT_NE(r.err.find(expect), std::string::npos) << args << "\n" << r.err;
        std::vector<std::string> after = leftovers();
        std::sort(after.begin(), after.end());
        EXPECT_EQ(after, before) << args;
    }
    fs::path mDir;
};

const std::string RENDER = "render --scene box-on-plane --size 160x90 ";

// The PNG is fine, the raw folder is not: neither is written, and the folders made on the way to
// the PNG are taken back.
TEST_F(OutputSafetyTest, RenderWritesAllOutputsOrNone) {
    expectRefused(RENDER + "-o new/deeper/frame.png --raw /proc/pcfscope-raw",
                  "--raw /proc/pcfscope-raw: cannot create folder");
    expectRefused(RENDER + "-o /proc/pcfscope.png",
                  "-o /proc/pcfscope.png: cannot write into /proc");
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
    for (const char* name :
         {"shadowmap.exr", "lightspace.exr", "visibility.exr", "positions.exr"}) {
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

// -f never lets an output overwrite what the command reads, by its own name or another (a link).
TEST_F(OutputSafetyTest, AnOutputMayNotBeAnInputEvenWithForce) {
    fs::copy_file(PCFSCOPE_SOURCE_DIR "/tests/fuzz/corpus/scene/wall.toml", mDir / "s.png");
    fs::copy_file(PCFSCOPE_SOURCE_DIR "/tests/fuzz/corpus/scene/wall.toml", mDir / "s.exr");
    fs::create_symlink("s.png", mDir / "link.png");
    const std::string scene = testutil::readAll(mDir / "s.png");
    const std::string args = "render --size 160x90 --scene-file s.png -f -o ";
    expectRefusedKeeping(args + "s.png", "-o s.png is the file --scene-file s.png reads");
    expectRefusedKeeping(args + "link.png", "-o link.png is the file --scene-file s.png reads");
    expectRefusedKeeping("truth --size 16x9 --spp 2 --scene-file s.exr -f -o s.exr",
                         "-o s.exr is the file --scene-file s.exr reads");
    // bench's outputs are fixed names in -o: a scene file named like one of them is refused too.
    fs::create_directory(mDir / "b");
    fs::copy_file(PCFSCOPE_SOURCE_DIR "/tests/fuzz/corpus/scene/wall.toml", mDir / "b/bench.md");
    expectRefusedKeeping("bench --quick --methods nearest --scene-file b/bench.md -f -o b",
                         "-o b/bench.md is the file --scene-file b/bench.md reads");
    EXPECT_EQ(testutil::readAll(mDir / "b/bench.md"), scene);
    EXPECT_EQ(testutil::readAll(mDir / "s.png"), scene);
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(mDir / "link.png")));
}

// An output that is a link is written through: the file it points at gets the image, the link
// stays a link (the user made it).
TEST_F(OutputSafetyTest, ASymlinkedOutputIsWrittenThrough) {
    fs::create_directory(mDir / "store");
    std::ofstream(mDir / "store/real.png") << "old";
    fs::create_symlink("store/real.png", mDir / "link.png");
    auto r = runPcfscope(RENDER + "-f -o " + path("link.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(mDir / "link.png")));
    EXPECT_EQ(testutil::readAll(mDir / "store/real.png").substr(0, 4), "\x89PNG");
    // Nothing else appeared: no temporary file left beside the link or the target.
    EXPECT_EQ(leftovers().size(), 3u);  // link.png, store, store/real.png
}

// Every output is the same bytes on every run: EXRs carry no time stamp (OpenImageIO's
// DateTime), PNGs none either. A second apart, so a stamp would differ.
TEST_F(OutputSafetyTest, EveryOutputIsByteIdenticalRunToRun) {
    const std::string truth = "truth --scene pole --size 32x18 --spp 2 -o ";
    for (const char* run : {"1", "2"}) {
        if (std::string(run) == "2") std::this_thread::sleep_for(std::chrono::milliseconds(1100));
        auto r = runPcfscope(RENDER + "-o " + path(std::string("f") + run + ".png") + " --raw " +
                             path(std::string("raw") + run));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        auto t = runPcfscope(truth + path(std::string("t") + run + ".exr"));
        ASSERT_EQ(t.exitCode, 0) << t.err;
    }
    std::vector<std::pair<std::string, std::string>> pairs = {{"f1.png", "f2.png"},
                                                              {"t1.exr", "t2.exr"}};
    for (const char* name :
         {"shadowmap.exr", "lightspace.exr", "visibility.exr", "positions.exr"}) {
        pairs.push_back({std::string("raw1/") + name, std::string("raw2/") + name});
    }
    for (const auto& [a, b] : pairs) {
        std::string bytes = testutil::readAll(mDir / a);
        EXPECT_FALSE(bytes.empty()) << a;
        EXPECT_EQ(bytes, testutil::readAll(mDir / b)) << a << " and " << b << " differ";
        EXPECT_EQ(bytes.find("DateTime"), std::string::npos) << a << " carries a time stamp";
    }
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

// bench's last step (OutputFiles::commitStaged): the staged files move into place and the set is
// committed under the writers' gate, so the interrupt cleanup, which takes the gate first, finds
// either nothing moved or everything kept.
TEST_F(OutputSafetyTest, StagedFilesMoveIntoPlaceUnderTheWriteGate) {
    fs::path out = mDir / "out";
    {
        OutputFiles outputs(false);
        outputs.addDirectory("-o", out);
        outputs.add("-o", out / "a.txt");
        outputs.add("-o", out / "sub/b.txt");
        StagingDir staging(out, "test", "sub");
        std::ofstream(staging.path() / "a.txt") << "a";
        std::ofstream(staging.path() / "sub/b.txt") << "b";
        std::atomic<bool> done{false};
        std::thread committer;
        {
            std::unique_lock gate(outputWriteGate());  // as the interrupt cleanup holds it
            committer = std::thread([&] {
                outputs.commitStaged(staging.path(), out, {"a.txt", "sub/b.txt"});
                done = true;
            });
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
            EXPECT_FALSE(done) << "commitStaged did not wait for the gate";
            EXPECT_FALSE(fs::exists(out / "a.txt"));
        }
        committer.join();
        EXPECT_TRUE(done);
    }
    // Committed: the set's end keeps the files; the staging folder is gone.
    EXPECT_EQ(testutil::readAll(out / "a.txt"), "a");
    EXPECT_EQ(testutil::readAll(out / "sub/b.txt"), "b");
    std::vector<std::string> left = leftovers();
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, (std::vector<std::string>{"out", "out/a.txt", "out/sub", "out/sub/b.txt"}));
}

// A move that fails half way throws, and the set, not committed, takes back what was moved.
TEST_F(OutputSafetyTest, AFailedStagedMoveTakesEverythingBack) {
    fs::path out = mDir / "out";
    {
        OutputFiles outputs(false);
        outputs.addDirectory("-o", out);
        outputs.add("-o", out / "a.txt");
        outputs.add("-o", out / "missing.txt");
        StagingDir staging(out, "test");
        std::ofstream(staging.path() / "a.txt") << "a";
        EXPECT_THROW(outputs.commitStaged(staging.path(), out, {"a.txt", "missing.txt"}),
                     fs::filesystem_error);
        EXPECT_TRUE(fs::exists(out / "a.txt"));  // moved before the failure
    }
    EXPECT_TRUE(leftovers().empty()) << leftovers().front();
}

// One command, one path, one use: a file given twice (animate rendered every frame of
// `-o a.mp4 a.mp4`, then failed naming its scratch copy) or a path given as a file and as a
// folder (`-o X --png X` said "X is a directory" of the folder it had just made) is refused
// before anything is rendered or made.
TEST_F(OutputSafetyTest, APathGivenTwiceIsRefusedUpFront) {
    const std::string animate = "animate 13 --step 3 --frames 3 --size 320x180 ";
    expectRefused(animate + "-o a.mp4 a.mp4", "-o a.mp4 is given twice");
    expectRefused(animate + "-o a.gif -o ./a.gif", "-o ./a.gif is given twice");
    expectRefused(animate + "-o v.gif --png v.gif",
                  "-o v.gif and --png v.gif are the same path, as a file and as a folder");
    // Two videos in one folder are two files.
    auto two = runPcfscope(animate + "-o " + path("a.gif") + " " + path("b.gif"));
    EXPECT_EQ(two.exitCode, 0) << two.err;
    // A command's own second look at an output is the same output: export -f over an earlier
    // export finds the page files first in the folder, then writes them.
    for (const char* force : {"", "-f "}) {
        auto again =
            runPcfscope("export 1 --size 320x180 " + std::string(force) + "-o " + path("frames"));
        EXPECT_EQ(again.exitCode, 0) << again.err;
    }
}

// Every command writes through an output that is a link, with -f: the staged outputs (animate's
// videos, bench's and stability's files, moved into place at the end) as the direct writers
// (render, truth, export) do. animate replaced the link with its video.
TEST_F(OutputSafetyTest, AStagedOutputIsWrittenThroughALinkToo) {
    fs::create_directory(mDir / "store");
    std::ofstream(mDir / "store/real.gif") << "old";
    fs::create_symlink("store/real.gif", mDir / "link.gif");
    auto r = runPcfscope("animate 13 --step 3 --frames 2 --size 320x180 -f -o " + path("link.gif"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(mDir / "link.gif")));
    EXPECT_EQ(testutil::readAll(mDir / "store/real.gif").substr(0, 3), "GIF");
    EXPECT_EQ(leftovers().size(), 3u);  // link.gif, store, store/real.gif
}

}  // namespace
}  // namespace pcf
