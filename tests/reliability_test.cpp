// Issue 24, "nothing lost, nothing trusted blindly": every image and JSON input goes through one
// checked path (regular files only, size caps, EXR header attribute sizes); every write is
// checked (a file size limit gives one line, exit 2 and nothing under a final name); one
// writer per output folder; verify recomputes ref and checks the depth format.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/output_files.h"
#include "exr_header.h"
#include "kernel/sigma_limits.h"
#include "render/image_io.h"
#include "run_command.h"
#include "virtual_display.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;
using testutil::lineCount;
using testutil::readAll;
using testutil::runPcfscope;

class Reliability : public ::testing::Test {
  protected:
    // One `render --raw` folder for the verify cases, rendered once; each test copies it.
    static void SetUpTestSuite() {
        sRaw = testutil::makeTempDir("reliability-raw");
        auto r = runPcfscope("render --scene box-on-plane --size 96x54 --map-size 64 --raw " +
                             (sRaw / "raw").string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    static void TearDownTestSuite() { fs::remove_all(sRaw); }
    void SetUp() override { mDir = testutil::makeTempDir("reliability"); }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    // A fresh copy of the raw folder, as mDir/raw.
    std::string rawCopy() const {
        fs::copy(sRaw / "raw", mDir / "raw", fs::copy_options::recursive);
        return path("raw");
    }
    std::vector<std::string> leftovers() const {
        std::vector<std::string> names;
        for (const auto& e : fs::recursive_directory_iterator(mDir)) {
            names.push_back(fs::relative(e.path(), mDir).string());
        }
        return names;
    }
    // Exit 2 with one line holding `expect`, never an internal error.
    static void expectOneLine(const testutil::CommandResult& r, const std::string& expect) {
        EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(expect), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    }
    void setJson(const std::string& raw, const std::string& key, const std::string& value) {
        std::string json = readAll(raw + "/render.json");
        size_t at = json.find("\"" + key + "\":");
        ASSERT_NE(at, std::string::npos) << json;
        size_t start = at + key.size() + 3;
        size_t end = json.find_first_of(",}", start);
        json.replace(start, end - start, value);
        std::ofstream(raw + "/render.json", std::ios::trunc) << json;
    }

    static fs::path sRaw;
    fs::path mDir;
};

fs::path Reliability::sRaw;

// Finding 1: verify read its EXRs without the side cap `--map` had; a 65536^2 claim was
// "internal error: std::bad_alloc", exit 1 (verify's "outside the envelope").
TEST_F(Reliability, VerifyRefusesAHugeImageHeaderBeforeAllocating) {
    std::string raw = rawCopy();
    ASSERT_TRUE(testutil::makeExrClaimSize(raw + "/lightspace.exr", 65536));
    expectOneLine(runPcfscope("verify " + raw),
                  "lightspace.exr: is 65536 x 65536 pixels; an image is at most 16384 on a side");
}

// Finding 2: a FIFO as render.json hung verify; a link to /dev/zero read 2.2 GB.
TEST_F(Reliability, VerifyRefusesFifosAndDevicesWithoutBlocking) {
    std::string raw = rawCopy();
    fs::remove(raw + "/render.json");
    ASSERT_EQ(mkfifo((raw + "/render.json").c_str(), 0644), 0);
    // `timeout`: a hang is a failure here, not a stuck test.
    expectOneLine(runPcfscope("verify " + raw, "timeout 60"),
                  "render.json: not a regular file (a FIFO, device or socket)");
    fs::remove(raw + "/render.json");
    fs::create_symlink("/dev/zero", raw + "/render.json");
    expectOneLine(runPcfscope("verify " + raw, "timeout 60"), "render.json: not a regular file");
    fs::remove(raw + "/render.json");
    fs::copy_file(sRaw / "raw" / "render.json", raw + "/render.json");
    fs::remove(raw + "/visibility.exr");
    ASSERT_EQ(mkfifo((raw + "/visibility.exr").c_str(), 0644), 0);
    expectOneLine(runPcfscope("verify " + raw, "timeout 60"),
                  "visibility.exr: cannot read image (not a regular file)");
}

// Finding 10: a 584-byte EXR whose header attribute claims 1.77 GB made OpenEXR allocate it.
// Refused from the header walk, with the attribute named.
TEST_F(Reliability, AnExrAttributeLargerThanTheFileIsRefused) {
    std::string file = path("lie.exr");
    std::string bytes("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    bytes += std::string("comments\0string\0", 16);
    int32_t size = 1770000000;
    bytes.append(reinterpret_cast<const char*>(&size), 4);
    bytes += "just a few bytes";
    std::ofstream(file, std::ios::binary) << bytes;
    expectOneLine(
        runPcfscope("trace --map " + file + " --uv 0.5,0.5 --z 0.5 --method nearest"),
        "lie.exr: cannot read image (header attribute 'comments' claims 1770000000 bytes; the "
        "file has 16 after it)");
    EXPECT_THROW(readFloatImage(file), ImageError);
}

// Finding 16: ref was read back, not recomputed, so a relabelled bias passed; a 32F map
// labelled 16-bit passed too.
TEST_F(Reliability, VerifyRecomputesRefAndChecksTheDepthFormat) {
    std::string raw = rawCopy();
    auto good = runPcfscope("verify " + raw);
    EXPECT_EQ(good.exitCode, 0) << good.out << good.err;
    EXPECT_NE(good.out.find("recomputed from position, normal and bias: as rendered"),
              std::string::npos)
        << good.out;

    setJson(raw, "bias", "\"none\"");
    setJson(raw, "constant_bias", "0");
    expectOneLine(runPcfscope("verify " + raw), "render.json does not describe these images");

    fs::copy_file(sRaw / "raw" / "render.json", raw + "/render.json",
                  fs::copy_options::overwrite_existing);
    setJson(raw, "constant_bias", "0.02");
    expectOneLine(runPcfscope("verify " + raw), "render.json does not describe these images");

    fs::copy_file(sRaw / "raw" / "render.json", raw + "/render.json",
                  fs::copy_options::overwrite_existing);
    setJson(raw, "depth_format", "\"16\"");
    expectOneLine(runPcfscope("verify " + raw), "not a 16-bit depth value");

    // The map as a value ("map"): its texel kind and size are the images'.
    fs::copy_file(sRaw / "raw" / "render.json", raw + "/render.json",
                  fs::copy_options::overwrite_existing);
    setJson(raw, "texels", "\"16\"");
    expectOneLine(runPcfscope("verify " + raw),
                  "\"map\" holds texels 16, but pcf-gather reads depth_format 32f");
    fs::copy_file(sRaw / "raw" / "render.json", raw + "/render.json",
                  fs::copy_options::overwrite_existing);
    setJson(raw, "size", "[32");
    expectOneLine(runPcfscope("verify " + raw),
                  "\"map\" is 32x64 in 1 layer(s), but shadowmap.exr is 64x64");
    fs::copy_file(sRaw / "raw" / "render.json", raw + "/render.json",
                  fs::copy_options::overwrite_existing);
    setJson(raw, "texel_ws", "\"wide\"");
    expectOneLine(runPcfscope("verify " + raw), "a map layer needs shadow_clip_from_world");
}

// Finding 4: the heat map was drawn only when --map-size was one of the aliasing sweep's
// sizes, so any other size failed at the very end, after every sweep.
TEST_F(Reliability, StabilityDrawsTheHeatMapAtAnyMapSize) {
    auto r = runPcfscope("stability --quick --sweep aliasing --size 160x90 --map-size 200 -o " +
                         path("out"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::is_regular_file(path("out/aliasing_heatmap.png")));
    EXPECT_NE(readAll(path("out/stability.csv")).find(",map_size,200,"), std::string::npos)
        << readAll(path("out/stability.csv"));
}

// Findings 3 and 12: past `ulimit -f` the process died of SIGXFSZ (exit 153, temporary files
// and the scratch folder left), and OIIO's PNG writer did not report a failed write. Now the
// write fails (EFBIG): one line, exit 2, and nothing under mDir, the folder included.
TEST_F(Reliability, AFileSizeLimitFailsTheCommandAndLeavesNothing) {
    const std::string limit = "ulimit -f 4 && ";  // 4 KiB: the CSV fits, the heat map does not
    const std::string stability =
        "stability --quick --sweep aliasing --size 480x270 --map-size 200 -o " + path("out");
    // stability reports progress on stderr as it goes; the error is its last line, and the only
    // one from pcfscope itself.
    auto r = runPcfscope(stability, limit);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(r.err.find("pcfscope: "), r.err.rfind("pcfscope: ")) << r.err;
    EXPECT_NE(r.err.find("cannot write image (File too large)\n", r.err.rfind("pcfscope: ")),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(leftovers().empty()) << leftovers().front();
    expectOneLine(runPcfscope("render --scene box-on-plane --size 320x180 -o " + path("a.png") +
                                  " --raw " + path("raw"),
                              limit),
                  "File too large");
    EXPECT_TRUE(leftovers().empty()) << leftovers().front();
}

// A full disk (ENOSPC, not the size limit above): every command that writes files fails in one
// line naming it, exits 2 and leaves nothing, whether the disk fills on the first file or later.
// tests/full_disk_shim.cpp makes the disk "full" under mDir after a number of bytes.
TEST_F(Reliability, AFullDiskFailsEveryWriterAndLeavesNothing) {
    const std::vector<std::string> writers = {
        "render --scene box-on-plane --size 96x54 -o OUT/a.png --raw OUT/raw",
        "truth --scene box-on-plane --size 48x27 -o OUT/t.exr",
        "export 3 --size 320x180 --steps 1-2 -o OUT/frames",
        "stability --quick --sweep aliasing --size 160x90 --map-size 64 -o OUT/s",
        "bench --quick --size 64x36 --methods nearest --map-sizes 64 -o OUT/b",
        "animate 13 --step 3 --frames 3 --size 320x180 -o OUT/v.mp4",
    };
    // 0: the first write fails; 1000: part of a first file gets through (each output is larger).
    for (const char* bytes : {"0", "1000"}) {
        for (std::string cmd : writers) {
            fs::path out = mDir / "out";
            fs::create_directory(out);
            for (size_t at; (at = cmd.find("OUT")) != std::string::npos;)
                cmd.replace(at, 3, out.string());
            std::string env =
                "PCF_FULL_DISK_DIR=" + out.string() + " PCF_FULL_DISK_BYTES=" + bytes +
                " LD_PRELOAD=" + PCFSCOPE_FULL_DISK_SHIM + " ASAN_OPTIONS=verify_asan_link_order=0";
            auto r = runPcfscope(cmd, env);
            EXPECT_EQ(r.exitCode, 2) << bytes << ": " << cmd << "\n" << r.err;
            // Progress lines may come first; the error is the last line, and the only one of
            // pcfscope's own.
            EXPECT_EQ(r.err.find("pcfscope: "), r.err.rfind("pcfscope: ")) << cmd << r.err;
            EXPECT_NE(r.err.find("No space left on device", r.err.rfind("pcfscope: ")),
                      std::string::npos)
                << bytes << ": " << cmd << "\n"
                << r.err;
            // The file named is the one asked for, not its copy in a scratch folder.
            EXPECT_EQ(r.err.find(".pcfscope-"), std::string::npos) << cmd << "\n" << r.err;
            EXPECT_TRUE(leftovers() == std::vector<std::string>{"out"})
                << bytes << ": " << cmd << " left " << leftovers().back();
            fs::remove_all(out);
        }
    }
}

// animate draws its progress on one line, redrawn in place: an error in the middle (here the disk
// fills at the third PNG) starts a line of its own instead of running on after "2/3".
TEST_F(Reliability, AnErrorDuringAnimateIsALineOfItsOwn) {
    fs::path out = mDir / "out";
    fs::create_directory(out);
    // Two 320x180 frames' PNGs (about 27 KB each) fit, the third does not.
    std::string env = "PCF_FULL_DISK_DIR=" + out.string() +
                      " PCF_FULL_DISK_BYTES=60000 LD_PRELOAD=" + PCFSCOPE_FULL_DISK_SHIM +
                      " ASAN_OPTIONS=verify_asan_link_order=0";
    auto r = runPcfscope(
        "animate 13 --step 3 --frames 3 --size 320x180 --png " + (out / "p").string(), env);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    size_t error = r.err.find("pcfscope: ");
    ASSERT_NE(error, std::string::npos) << r.err;
    ASSERT_GT(error, 0u) << "no progress before the error: " << r.err;
    EXPECT_EQ(r.err[error - 1], '\n') << r.err;
    EXPECT_NE(r.err.find("No space left on device", error), std::string::npos) << r.err;
}

// Standard output is checked like a file: a full one is an error, not a success.
TEST_F(Reliability, AFullStandardOutputIsAnError) {
    std::string cmd = std::string(PCFSCOPE_EXE) +
                      " trace --example --method nearest --json >/dev/full 2>" + path("err");
    int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2);
    std::string err = readAll(path("err"));
    EXPECT_EQ(lineCount(err), 1) << err;
    EXPECT_NE(err.find("cannot write to standard output (No space left on device)"),
              std::string::npos)
        << err;
}

// Finding 5: two writers into one folder both ran; the loser removed the winner's frames. The
// folder is locked by the first; the second is refused before it claims or writes anything.
TEST_F(Reliability, ASecondWriterIntoTheSameFolderIsRefusedUpFront) {
    fs::create_directory(path("same"));
    {
        OutputFiles holder(false);
        holder.addDirectory("-o", path("same"));
        // The same process may add more outputs there (the viewer's screenshots do).
        OutputFiles nested(false);
        EXPECT_NO_THROW(nested.add("-o", path("same/x.png")));
        auto r =
            runPcfscope("render --scene box-on-plane --size 64x36 -o " + path("same/shadow.png"));
        expectOneLine(r, "another pcfscope is writing into " + path("same"));
        auto e = runPcfscope("export 5 --steps 1 -o " + path("same"));
        expectOneLine(e, "another pcfscope is writing into " + path("same"));
        EXPECT_EQ(leftovers(), std::vector<std::string>{"same"});
    }
    // Released with the set: the next writer goes ahead.
    auto r = runPcfscope("render --scene box-on-plane --size 64x36 -o " + path("same/shadow.png"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::is_regular_file(path("same/shadow.png")));
}

// Finding 6: stale page files were found only after every frame was rendered (13 lines).
TEST_F(Reliability, ExportRefusesStalePageFilesBeforeRendering) {
    fs::create_directory(path("frames"));
    std::ofstream(path("frames/05-gather-weights-step01-page2.png")) << "stale";
    auto r = runPcfscope("export 5 --steps 1-2 -o " + path("frames"));
    expectOneLine(r, "frames/05-gather-weights-step01-page2.png already exists");
    EXPECT_EQ(r.err.find("export: "), std::string::npos) << r.err;
    EXPECT_EQ(readAll(path("frames/05-gather-weights-step01-page2.png")), "stale");
    EXPECT_EQ(leftovers().size(), 2u);
}

// Finding 7: `view --screenshot LINK -f` overwrote the lesson the link points at.
TEST_F(Reliability, AScreenshotMayNotOverwriteItsLesson) {
    fs::copy_file(std::string(PCFSCOPE_SOURCE_DIR) + "/lessons/01-hard-shadows.toml",
                  path("lesson.toml"));
    std::string before = readAll(path("lesson.toml"));
    fs::create_symlink(path("lesson.toml"), path("shot.png"));
    testutil::VirtualDisplay x;
    ASSERT_FALSE(x.display().empty()) << "Xvfb did not start";
    expectOneLine(
        runPcfscope("view " + path("lesson.toml") + " --screenshot " + path("shot.png") + " -f",
                    "DISPLAY=" + x.display()),
        "is the file LESSON " + path("lesson.toml") + " reads");
    EXPECT_EQ(readAll(path("lesson.toml")), before);
}

// Finding 8: a sigma below about 1e-19 underflowed every weight: 0 / 0, visibility null.
TEST_F(Reliability, ASigmaTooSmallForFloatsIsRefused) {
    expectOneLine(runPcfscope("trace --example --weights gaussian --sigma 1e-30 --method "
                              "pcf-naive --json"),
                  "sigma");
    // The smallest accepted sigma still weighs an even kernel's nearest taps (0.5 texels off).
    auto r = runPcfscope("trace --example --weights gaussian --sigma " + std::to_string(MIN_SIGMA) +
                         " --method pcf-naive --kernel 2 --json");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("null"), std::string::npos) << r.out;
}

// Finding 9: a chart step rendered below the charts' 64 px, and a sphere of radius 1e301 (a
// float infinity: no camera planes), both ended in "internal error", exit 1.
TEST_F(Reliability, TooSmallChartsAndTooLargeScenesAreBadInput) {
    expectOneLine(runPcfscope("render --lesson 11 --size 63x63 -o " + path("c.png")),
                  "--size 63x63: lesson step 1 shows a chart, which needs at least 64 x 64");
    std::ofstream(path("big.toml")) << "[camera]\neye = [0, 2, 8]\ntarget = [0, 0, 0]\n"
                                       "[light]\ntype = \"directional\"\n"
                                       "direction = [0, -1, 0]\n[[object]]\ntype = \"sphere\"\n"
                                       "centre = [0, 1, 0]\nradius = 1e301\n";
    expectOneLine(runPcfscope("render --scene-file " + path("big.toml") + " -o " + path("b.png")),
                  "big.toml:10: sphere radius must be within +-1e+06, got 1e+301");
    EXPECT_EQ(leftovers(), std::vector<std::string>{"big.toml"});
}

// Finding 14: the largest sizes had no memory estimate (bench reached 9.8 GiB and ran on).
// Under an address-space limit the estimate exceeds what is available, and the work is
// refused in one line before it starts, with nothing made.
TEST_F(Reliability, WorkLargerThanTheMemoryIsRefusedUpFront) {
    const std::string limit = "ulimit -v 1500000 && ";  // 1.5 GB of address space
    for (const std::string& args :
         {"render --scene box-on-plane --size 8192x8192 -o " + path("a.png"),
          "truth --scene box-on-plane --size 8192x8192 -o " + path("t.exr"),
          "bench --quick --size 8192x8192 -o " + path("b"),
          "stability --quick --size 8192x8192 -o " + path("s"),
          "animate 13 --step 3 --size 8192x8192 --frames 3600 -o " + path("v.mp4"),
          "export 3 --size 8192x8192 -o " + path("e")}) {
        expectOneLine(runPcfscope(args, limit), "8192x8192: needs about ");
        EXPECT_TRUE(leftovers().empty()) << args << ": left " << leftovers().front();
    }
    // The refusal names the work and the way on: -f starts it anyway, saying so.
    auto animate = runPcfscope(
        "animate 13 --step 3 --size 8192x8192 --frames 3600 -o " + path("v.mp4"), limit);
    EXPECT_NE(animate.err.find("pcfscope: 3600 frames of 8192x8192: needs about "),
              std::string::npos)
        << animate.err;
    EXPECT_NE(animate.err.find("or -f to start it anyway"), std::string::npos) << animate.err;
    auto forced =
        runPcfscope("animate 13 --step 3 --size 8192x8192 --frames 3600 -f -o " + path("v.mp4"),
                    limit + "timeout 5");
    EXPECT_NE(forced.err.find("animate: 3600 frames of 8192x8192: about "), std::string::npos)
        << forced.err;
    EXPECT_NE(forced.err.find("available: forced"), std::string::npos) << forced.err;
    EXPECT_TRUE(leftovers().empty()) << "left " << leftovers().front();
}

// A long job says how long before it starts: animate's 3600 frames at 1280x720 are minutes of
// work (about 100 ns a pixel a frame on llvmpipe), which it states, then begins.
TEST_F(Reliability, ALongJobStatesItsEstimateBeforeItStarts) {
    auto r = runPcfscope("animate 13 --step 3 --size 1280x720 --frames 3600 -o " + path("v.gif"),
                         "timeout 5");
    std::string first = r.err.substr(0, r.err.find('\n'));
    EXPECT_EQ(first.rfind("animate: 3600 frames of 1280x720: about ", 0), 0u) << r.err;
    EXPECT_NE(first.find(" min and 0."), std::string::npos) << first;  // minutes, under a GiB
    EXPECT_NE(first.find("GiB of memory (an estimate"), std::string::npos) << first;
    EXPECT_TRUE(leftovers().empty()) << "left " << leftovers().front();
}

}  // namespace
}  // namespace pcf
