// `pcfscope truth`: the ray-cast ground truth as an EXR, rows top-down, and bad input refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "image_read.h"
#include "measure/ground_truth.h"
#include "run_command.h"
#include "scene/presets.h"
#include "scene/scene_file.h"

namespace pcf {
namespace {

class TruthCommand : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("truth"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    std::filesystem::path mDir;
};

TEST_F(TruthCommand, WritesTheVisibilityTopDownAsTheLibraryComputesIt) {
    auto r = testutil::runPcfscope("truth --scene box-on-plane --size 64x36 --spp 3 -o " +
                                   path("gt.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("truth:"), std::string::npos);  // progress on stderr
    ImageSize size = readImageSize(path("gt.exr"));
    EXPECT_EQ(size.width, 64);
    EXPECT_EQ(size.height, 36);
    EXPECT_EQ(size.channels, 2);
    // EXR keeps channels sorted by name: read them by name.
    std::vector<std::string> names = readImageChannelNames(path("gt.exr"));
    ASSERT_EQ(names.size(), 2u);
    size_t vis = std::find(names.begin(), names.end(), "visibility") - names.begin();
    size_t bound = std::find(names.begin(), names.end(), "bound") - names.begin();
    ASSERT_LT(vis, 2u);
    ASSERT_LT(bound, 2u);
    std::vector<float> both = readImageFloats(path("gt.exr"), 2);
    GroundTruthOptions options;
    options.spp = 3;
    GroundTruth truth = computeGroundTruth(*presetScene("box-on-plane"), {64, 36}, options);
    ASSERT_EQ(both.size(), 2 * truth.visibility.size());
    std::vector<float> file(truth.pixelCount());
    int refined = 0;
    for (size_t k = 0; k < truth.pixelCount(); ++k) {
        file[k] = both[2 * k + vis];
        EXPECT_EQ(both[2 * k + bound], truth.bound[k]) << k;
        EXPECT_LE(both[2 * k + bound], DEFAULT_TRUTH_TARGET_BOUND) << k;
        refined += both[2 * k + bound] > 0.0f;
    }
    EXPECT_GT(refined, 0);
    EXPECT_EQ(file, truth.visibility);
    // The largest bound is on stderr; every pixel reached the target, so nothing more is said.
    EXPECT_NE(r.err.find("largest bound"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("did not reach the target"), std::string::npos) << r.err;
    // Top-down: the first scanline is the sky above the ground's far edge (nothing hit: 1), and
    // the frame holds both shadow and light.
    for (int x = 0; x < 64; ++x) EXPECT_EQ(file[x], 1.0f) << x;
    EXPECT_NE(std::find(file.begin(), file.end(), 0.0f), file.end());
}

// A target too fine for 513 scanlines (issue 24 finding 15: a bound of 0.002005 above the 1/512
// asked for, unsaid): the summary says how many pixels stopped short of it.
TEST_F(TruthCommand, SaysWhichPixelsStoppedAboveTheTarget) {
    auto r = testutil::runPcfscope("truth --scene sphere-over-plane --size 48x27 --bound 1e-6 -o " +
                                   path("gt.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<std::string> names = readImageChannelNames(path("gt.exr"));
    size_t bound = std::find(names.begin(), names.end(), "bound") - names.begin();
    ASSERT_LT(bound, 2u);
    std::vector<float> both = readImageFloats(path("gt.exr"), 2);
    long above = 0;
    for (size_t k = bound; k < both.size(); k += 2) above += both[k] > 1e-6f ? 1 : 0;
    ASSERT_GT(above, 0);
    EXPECT_NE(r.err.find("truth: " + std::to_string(above) +
                         " pixels did not reach the target within 513 scanlines"),
              std::string::npos)
        << r.err;
}

// A sphere in another sphere's shadow has a quartic shadow edge, which the truth walks instead
// of cutting exactly: `truth` names the objects that may take one; the presets name none.
TEST_F(TruthCommand, NamesTheObjectsWhoseEdgesAreWalked) {
    std::string scene = path("two-balls.toml");
    std::ofstream(scene) << R"([camera]
eye = [3.0, 3.0, 4.5]
target = [0.0, 0.5, 0.0]
fov = 40.0

[light]
type = "directional"
direction = [0.0, -1.0, 0.0]

[[object]]
type = "plane"
name = "ground"
centre = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [8.0, 8.0]

[[object]]
type = "sphere"
name = "low-ball"
centre = [0.0, 0.5, 0.0]
radius = 0.5

[[object]]
type = "sphere"
name = "high-ball"
centre = [0.0, 2.0, 0.0]
radius = 0.3
)";
    auto r = testutil::runPcfscope("truth --scene-file " + scene + " --size 32x18 -o " +
                                   path("two.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // Each ball may lie in the other's shadow; the ground takes only conic edges.
    EXPECT_NE(r.err.find("truth: low-ball may take shadow edges that are not conics"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("truth: high-ball may take shadow edges"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("ground may take"), std::string::npos) << r.err;
    for (std::string_view preset : presetNames()) {
        auto p = testutil::runPcfscope("truth --scene " + std::string(preset) +
                                       " --size 32x18 -f -o " + path("p.exr"));
        ASSERT_EQ(p.exitCode, 0) << p.err;
        EXPECT_EQ(p.err.find("not conics"), std::string::npos) << preset << ": " << p.err;
    }
}

// A spot light with a radius: the truth integrates over its disk (light_visibility.h), as the
// library computes it; --light-radius is the spot's radius; a sphere reaching behind the disk is
// refused with one line.
TEST_F(TruthCommand, IntegratesASpotLightsDisk) {
    std::string spot = R"([camera]
eye = [2.5, 3.0, 3.5]
target = [0.0, 0.3, 0.0]
fov = 40.0

[light]
type = "spot"
direction = [0.0, -1.0, 0.0]
position = [0.0, 4.0, 0.0]
cone = 50.0
radius = 0.4

[[object]]
type = "plane"
name = "ground"
centre = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [8.0, 8.0]

[[object]]
type = "box"
name = "post"
centre = [0.4, 0.75, 0.0]
half = [0.15, 0.75, 0.15]
)";
    std::string scene = path("spot.toml");
    std::ofstream(scene) << spot;
    auto r = testutil::runPcfscope("truth --scene-file " + scene + " --size 24x14 -o " +
                                   path("spot.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("a spot disk of radius 0.4"), std::string::npos) << r.err;
    std::vector<std::string> names = readImageChannelNames(path("spot.exr"));
    ASSERT_EQ(names.size(), 2u);
    size_t vis = std::find(names.begin(), names.end(), "visibility") - names.begin();
    ASSERT_LT(vis, 2u);
    std::vector<float> both = readImageFloats(path("spot.exr"), 2);
    GroundTruthOptions options;
    options.area = true;
    GroundTruth truth = computeGroundTruth(parseSceneString(spot, "spot"), {24, 14}, options);
    ASSERT_EQ(both.size(), 2 * truth.pixelCount());
    int partial = 0;
    for (size_t k = 0; k < truth.pixelCount(); ++k) {
        EXPECT_EQ(both[2 * k + vis], truth.visibility[k]) << k;
        partial += truth.visibility[k] > 0.01f && truth.visibility[k] < 0.99f ? 1 : 0;
    }
    EXPECT_GT(partial, 0);  // a penumbra
    EXPECT_GT(truth.refinedPixels, partial);

    auto big = testutil::runPcfscope("truth --scene-file " + scene +
                                     " --light-radius 101 --size 24x14 -o " + path("big.exr"));
    EXPECT_EQ(big.exitCode, 2) << big.err;
    EXPECT_EQ(testutil::lineCount(big.err), 1) << big.err;
    EXPECT_NE(big.err.find("--light-radius must be in [0, 100] world units, got 101"),
              std::string::npos)
        << big.err;
    EXPECT_FALSE(std::filesystem::exists(path("big.exr")));

    std::string behind = path("behind.toml");
    std::ofstream(behind) << spot
                          << "\n[[object]]\ntype = \"sphere\"\nname = \"lamp\"\ncentre = [0.0, "
                             "4.0, 0.0]\nradius = 0.1\n";
    auto refused = testutil::runPcfscope("truth --scene-file " + behind + " --size 24x14 -o " +
                                         path("behind.exr"));
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_EQ(testutil::lineCount(refused.err), 1) << refused.err;
    EXPECT_NE(refused.err.find("sphere 'lamp' reaches behind the light's disk"), std::string::npos)
        << refused.err;
    EXPECT_FALSE(std::filesystem::exists(path("behind.exr")));
}

TEST_F(TruthCommand, MaskAddsTheReceiverChannel) {
    auto r = testutil::runPcfscope(
        "truth --scene sphere-over-plane --size 48x27 --spp 2 --mask "
        "-o " +
        path("gt.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<float> file = readImageFloats(path("gt.exr"), 3);
    std::vector<std::string> names = readImageChannelNames(path("gt.exr"));
    auto at = [&](const char* name) {
        return static_cast<size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    ASSERT_LT(at("visibility"), 3u);
    ASSERT_LT(at("bound"), 3u);
    ASSERT_LT(at("mask"), 3u);
    GroundTruthOptions options;
    options.spp = 2;
    GroundTruth truth = computeGroundTruth(*presetScene("sphere-over-plane"), {48, 27}, options);
    int receivers = 0;
    for (size_t k = 0; k < truth.pixelCount(); ++k) {
        EXPECT_EQ(file[3 * k + at("visibility")], truth.visibility[k]);
        EXPECT_EQ(file[3 * k + at("bound")], truth.bound[k]);
        EXPECT_EQ(file[3 * k + at("mask")], truth.receiver[k] ? 1.0f : 0.0f);
        receivers += truth.receiver[k];
    }
    EXPECT_GT(receivers, 48 * 27 / 3);
}

TEST_F(TruthCommand, RefusesToOverwriteWithoutForce) {
    std::string out = path("gt.exr");
    ASSERT_EQ(testutil::runPcfscope("truth --scene pole --size 16x9 --spp 1 -o " + out).exitCode,
              0);
    auto again = testutil::runPcfscope("truth --scene pole --size 32x18 --spp 1 -o " + out);
    EXPECT_EQ(again.exitCode, 2);
    EXPECT_EQ(testutil::lineCount(again.err), 1) << again.err;
    EXPECT_NE(again.err.find("already exists"), std::string::npos) << again.err;
    EXPECT_EQ(readImageSize(out).width, 16);
    auto forced = testutil::runPcfscope("truth --scene pole --size 32x18 --spp 1 -f -o " + out);
    EXPECT_EQ(forced.exitCode, 0) << forced.err;
    EXPECT_EQ(readImageSize(out).width, 32);
}

TEST_F(TruthCommand, BadInputExitsTwoWithOneLineAndWritesNothing) {
    struct Case {
        std::string args;
        std::string expect;
    };
    std::vector<Case> cases = {
        {"", "needs --scene"},
        {"--scene pole --scene-file x.toml", "not both"},
        {"--scene no-such", "unknown scene 'no-such'"},
        {"--scene-file " + path("missing.toml"), "missing.toml"},
        {"--scene pole --spp 0", "--spp 0"},
        {"--scene pole --spp 65", "--spp 65"},
        {"--scene pole --size 0x10", "--size"},
        {"--scene pole --size 10", "--size"},
        {"--scene pole --threads -1", "--threads"},
        {"--scene pole --bound 0", "--bound"},
    };
    for (const Case& c : cases) {
        auto r = testutil::runPcfscope("truth " + c.args + " -o " + path("gt.exr"));
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(path("gt.exr"))) << c.args;
    }
    auto noOut = testutil::runPcfscope("truth --scene pole");
    EXPECT_EQ(noOut.exitCode, 2);
    EXPECT_NE(noOut.err.find("-o"), std::string::npos) << noOut.err;
    EXPECT_TRUE(std::filesystem::is_empty(mDir));
}

}  // namespace
}  // namespace pcf
