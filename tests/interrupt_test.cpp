// Ctrl-C (SIGINT) and SIGTERM in the middle of a command leave no half output: what the command
// had written is removed, as on an error, and the exit code is 128 + the signal (130, 143).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "run_command.h"

extern char** environ;

namespace pcf {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

class Interrupt : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("interrupt"); }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }

    // Starts pcfscope with `args`, stderr into mDir/stderr.txt; returns its pid.
    pid_t start(std::vector<std::string> args) {
        args.insert(args.begin(), PCFSCOPE_EXE);
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        std::string err = (mDir / "stderr.txt").string();
        posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                         0644);
        posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
        pid_t pid = -1;
        EXPECT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
        posix_spawn_file_actions_destroy(&actions);
        return pid;
    }

    // Waits up to `limit` for `file` to exist while the process runs; false if it never did.
    static bool waitFor(const fs::path& file, pid_t pid, std::chrono::seconds limit) {
        auto until = std::chrono::steady_clock::now() + limit;
        while (std::chrono::steady_clock::now() < until) {
            if (fs::exists(file)) return true;
            int status = 0;
            if (waitpid(pid, &status, WNOHANG) == pid) return false;  // ended first
            std::this_thread::sleep_for(2ms);
        }
        return false;
    }

    // Waits up to `limit` for stderr to say `text` while the process runs.
    bool waitForStderr(const std::string& text, pid_t pid, std::chrono::seconds limit) const {
        auto until = std::chrono::steady_clock::now() + limit;
        while (std::chrono::steady_clock::now() < until) {
            if (stderrText().find(text) != std::string::npos) return true;
            int status = 0;
            if (waitpid(pid, &status, WNOHANG) == pid) return false;
            std::this_thread::sleep_for(2ms);
        }
        return false;
    }

    static int exitCodeOf(pid_t pid) {
        int status = 0;
        EXPECT_EQ(waitpid(pid, &status, 0), pid);
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    std::string stderrText() const { return testutil::readAll(mDir / "stderr.txt"); }

    fs::path mDir;
};

// The case: after the first of lesson 11's six frames, SIGINT. Everything goes: the
// frames, the JSON sidecars and the folder export made.
TEST_F(Interrupt, SigintAfterTheFirstExportFrameLeavesNothing) {
    fs::path out = mDir / "frames";
    pid_t pid = start({"export", "11", "-o", out.string(), "--size", "1280x720"});
    ASSERT_TRUE(waitFor(out / "11-speed-and-accuracy-step01.json", pid, 120s)) << stderrText();
    ASSERT_EQ(kill(pid, SIGINT), 0);
    EXPECT_EQ(exitCodeOf(pid), 130) << stderrText();
    EXPECT_FALSE(fs::exists(out)) << "export left its folder";
    std::string err = stderrText();
    EXPECT_NE(err.find("pcfscope: interrupted (SIGINT); removed the files this command had "
                       "written\n"),
              std::string::npos)
        << err;
}

// Issue 24, finding 11: SIGINT right after export's success line took back every frame the
// line had just announced. The frames are kept before the line is printed.
TEST_F(Interrupt, SigintAfterTheExportSummaryKeepsTheFrames) {
    fs::path out = mDir / "frames";
    pid_t pid = start({"export", "5", "--steps", "1-2", "-o", out.string(), "--size", "640x360"});
    ASSERT_TRUE(waitForStderr(" frames of 640x360 in ", pid, 120s)) << stderrText();
    kill(pid, SIGINT);  // it may have ended already: that is fine too
    int code = exitCodeOf(pid);
    EXPECT_TRUE(code == 0 || code == 130) << code << stderrText();
    for (const char* step : {"01", "02"}) {
        EXPECT_TRUE(fs::exists(out / ("05-gather-weights-step" + std::string(step) + ".png")))
            << step << ": " << stderrText();
        EXPECT_TRUE(fs::exists(out / ("05-gather-weights-step" + std::string(step) + ".json")));
    }
}

// SIGTERM during the ground truth, before anything was written: the folder made for -o goes,
// a folder that was there stays.
TEST_F(Interrupt, SigtermDuringTruthRemovesTheFoldersItMade) {
    fs::path out = mDir / "made" / "truth.exr";
    pid_t pid = start({"truth", "--scene", "box-on-plane", "--size", "640x360", "--spp", "32",
                       "--threads", "1", "-o", out.string()});
    // The folder for -o is made when the output is checked, before the work starts.
    ASSERT_TRUE(waitFor(mDir / "made", pid, 60s)) << stderrText();
    std::this_thread::sleep_for(200ms);
    ASSERT_EQ(kill(pid, SIGTERM), 0);
    EXPECT_EQ(exitCodeOf(pid), 143) << stderrText();
    EXPECT_FALSE(fs::exists(mDir / "made"));
    EXPECT_TRUE(fs::exists(mDir));
    EXPECT_NE(stderrText().find("pcfscope: interrupted (SIGTERM)"), std::string::npos)
        << stderrText();
}

// Only what the command made goes: a file of the user's in the same folder stays.
TEST_F(Interrupt, ExistingFilesAreNotTouched) {
    fs::path out = mDir / "truth.exr";
    { std::ofstream(mDir / "keep.txt") << "mine"; }
    pid_t pid = start({"truth", "--scene", "box-on-plane", "--size", "640x360", "--spp", "32",
                       "--threads", "1", "-o", out.string()});
    ASSERT_TRUE(waitForStderr("truth: box-on-plane", pid, 60s)) << stderrText();
    ASSERT_EQ(kill(pid, SIGINT), 0);
    EXPECT_EQ(exitCodeOf(pid), 130) << stderrText();
    EXPECT_FALSE(fs::exists(out));
    EXPECT_EQ(testutil::readAll(mDir / "keep.txt"), "mine");
}

// bench stages everything in a scratch folder inside -o and moves it into place at the end,
// under the write gate: SIGINT after the first run's difference image went to the scratch
// folder leaves neither the scratch folder nor the -o folder bench made.
TEST_F(Interrupt, SigintDuringBenchLeavesNothing) {
    fs::path out = mDir / "bench";
    pid_t pid = start({"bench", "--quick", "--methods", "nearest,pcf-gather", "--repeats", "200",
                       "-o", out.string()});
    ASSERT_TRUE(waitForStderr("bench: timing round 2/200", pid, 120s)) << stderrText();
    ASSERT_EQ(kill(pid, SIGINT), 0);
    EXPECT_EQ(exitCodeOf(pid), 130) << stderrText();
    EXPECT_FALSE(fs::exists(out)) << "bench left its folder";
    EXPECT_NE(stderrText().find("pcfscope: interrupted (SIGINT); removed the files"),
              std::string::npos)
        << stderrText();
}

// SIGTERM while bench measures its runs, into a folder the user made: the folder stays, empty
// (no scratch folder, no file), and a file of the user's in it is untouched.
TEST_F(Interrupt, SigtermDuringBenchKeepsTheUsersFolder) {
    fs::path out = mDir / "mine";
    fs::create_directories(out);
    { std::ofstream(out / "notes.txt") << "mine"; }
    pid_t pid = start({"bench", "--quick", "--methods", "nearest", "--map-sizes",
                       "64,96,128,160,192,224,256", "-o", out.string()});
    ASSERT_TRUE(waitForStderr("bench: 2/7 ", pid, 120s)) << stderrText();
    ASSERT_EQ(kill(pid, SIGTERM), 0);
    EXPECT_EQ(exitCodeOf(pid), 143) << stderrText();
    std::vector<std::string> left;
    for (const auto& e : fs::recursive_directory_iterator(out)) {
        left.push_back(fs::relative(e.path(), out).string());
    }
    EXPECT_EQ(left, std::vector<std::string>{"notes.txt"});
    EXPECT_EQ(testutil::readAll(out / "notes.txt"), "mine");
}

}  // namespace
}  // namespace pcf
