// The command line as a user runs it: `pcfscope methods` and `pcfscope trace`.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include "json_lite.h"
#include "kernel/methods.h"
#include "kernel/trace.h"
#include "render/image_io.h"
#include "run_command.h"

namespace pcf {
namespace {

using testutil::runPcfscope;

class CliTest : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("cli"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    std::filesystem::path mDir;
};

TEST_F(CliTest, MethodsListsTheNineIdsWithFetchCounts) {
    auto r = runPcfscope("methods");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const MethodInfo& m : allMethods()) {
        std::string row = "\n";
        row += m.name;
        row += ' ';
        EXPECT_NE(r.out.find(row), std::string::npos) << m.name;
    }
    EXPECT_NE(r.out.find("36 texels"), std::string::npos) << r.out;  // pcf-naive 3x3
    EXPECT_NE(r.out.find("16 texels in 4 gathers"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("16 texels in 4 hw taps"), std::string::npos) << r.out;  // tent 3
}

TEST_F(CliTest, TraceExamplePrintsTheStepsAStudentFollows) {
    auto r = runPcfscope("trace --example --method bilinear2x2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("p = uv * size - 0.5"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("frac = p - base = (0.2, 0.6)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("lerp(1, 0, 0.2) = 0.8"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("visibility = 0.8"), std::string::npos) << r.out;
}

TEST_F(CliTest, TraceJsonOfAWrittenMapMatchesTheKernel) {
    // A 13 x 9 map of random depths, written as EXR; row 0 must stay row 0.
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    ShadowMap map(13, 9);
    for (int j = 0; j < 9; ++j) {
        for (int i = 0; i < 13; ++i) map.setDepth(i, j, u(rng));
    }
    writeDepthImage(path("map.exr"), map);
    struct Case {
        const char* method;
        int kernel;
    };
    for (Case c : {Case{"nearest", 1}, Case{"bilinear2x2", 1}, Case{"pcf-naive", 3},
                   Case{"pcf-gather", 4}, Case{"tent", 5}, Case{"poisson", 1}}) {
        vec2 uv(0.3141f, 0.7182f);
        float z = 0.55f;
        auto r = runPcfscope("trace --map " + path("map.exr") +
                             " --uv 0.3141,0.7182 --z 0.55 --method " + c.method + " --kernel " +
                             std::to_string(c.kernel) + " --json");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(testutil::lineCount(r.out), 1);
        jsonlite::Value j = jsonlite::parse(r.out);
        PcfParams prm = makeParams(*methodFromName(c.method), c.kernel);
        Trace tr = traceLookup(map, uv, z, z, prm);
        EXPECT_EQ(j["method"].string, c.method);
        EXPECT_FLOAT_EQ(static_cast<float>(j["visibility"].number), tr.visibility) << c.method;
        ASSERT_EQ(j["taps"].size(), tr.taps.size());
        for (size_t k = 0; k < tr.taps.size(); ++k) {
            const jsonlite::Value& t = j["taps"][k];
            EXPECT_EQ(t["texel"][0].number, tr.taps[k].texel.x);
            EXPECT_EQ(t["texel"][1].number, tr.taps[k].texel.y);
            EXPECT_FLOAT_EQ(static_cast<float>(t["depth"].number),
                            map.depth(tr.taps[k].texel.x, tr.taps[k].texel.y));
            EXPECT_EQ(t["lit"].number, tr.taps[k].lit);
            EXPECT_FLOAT_EQ(static_cast<float>(t["weight"].number), tr.taps[k].weight);
        }
    }
}

// Issue 10: any finite uv; outside the map the taps clamp to the edge, as on the GPU.
TEST_F(CliTest, TraceTakesAnyFiniteUvAndMarksClampedTaps) {
    auto r = runPcfscope("trace --example --method pcf-naive --uv 1.02,0.6 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"clamped\":true"), std::string::npos);
    auto far = runPcfscope("trace --example --method hw2x2 --uv -1e30,0.6 --precision hw8");
    EXPECT_EQ(far.exitCode, 0) << far.err;
    EXPECT_NE(far.out.find("clamped to the edge"), std::string::npos) << far.out;
}

TEST_F(CliTest, BadInputExitsTwoWithOneLine) {
    ShadowMap good(4, 4, 0.5f);
    writeDepthImage(path("good.exr"), good);
    // A three-channel float image.
    std::vector<float> rgb(4 * 4 * 3, 0.5f);
    writeExr(path("rgb.exr"), 4, 4, 3, rgb, {"R", "G", "B"});
    // A one-channel 8-bit image.
    {
        auto out = OIIO::ImageOutput::create(path("gray.png"));
        OIIO::ImageSpec spec(4, 4, 1, OIIO::TypeDesc::UINT8);
        ASSERT_TRUE(out && out->open(path("gray.png"), spec));
        std::vector<uint8_t> px(16, 128);
        out->write_image(OIIO::TypeDesc::UINT8, px.data());
        out->close();
    }
    ShadowMap nan(4, 4, 0.5f);
    nan.setDepth(1, 2, std::numeric_limits<float>::quiet_NaN());
    std::vector<float> nanData(nan.depths().begin(), nan.depths().end());
    writeExr(path("nan.exr"), 4, 4, 1, nanData, {"Z"});

    const std::string at = " --uv 0.5,0.5 --z 0.5";
    struct Case {
        std::string args;
        std::string expect;  // a piece of the one-line message
    };
    std::vector<Case> cases = {
        {"trace --map " + path("missing.exr") + at, "missing.exr"},
        {"trace --map " + path("rgb.exr") + at, "has 3 channels"},
        {"trace --map " + path("gray.png") + at, "uint8"},
        {"trace --map " + path("nan.exr") + at, "texel (1, 2) is NaN"},
        {"trace --map " + path("good.exr") + at + " --method pcf-naive --kernel 9",
         "--kernel must be 1..8, got 9"},
        {"trace --map " + path("good.exr") + at + " --method pcf-naive --kernel 0",
         "--kernel must be 1..8, got 0"},
        {"trace --map " + path("good.exr") + at + " --method tent --kernel 4", "tent takes"},
        {"trace --map " + path("good.exr") + at + " --method fancy", "unknown method 'fancy'"},
        {"trace --map " + path("good.exr") + " --uv 0.5 --z 0.5", "--uv expects"},
        {"trace --map " + path("good.exr") + " --uv nan,0.5 --z 0.5", "--uv expects"},
        {"trace --map " + path("good.exr") + " --uv 0.5,0.5 --z nan", "--z"},
        {"trace --map " + path("good.exr") + " --uv 0.5,inf --z 0.5", "--uv expects"},
        {"trace --example --precision hw9", "unknown --precision 'hw9'"},
        {"trace --example --method tent --weights binomial", "applies to pcf-naive"},
        {"trace --map " + path("good.exr"), "needs --uv"},
        {"trace --uv 0.5,0.5 --z 0.5", "exactly one of --map"},
        {"trace --example --kernel x", "kernel"},
        {"trace --example --z nan", "--z nan is out of range"},
        {"trace --example --z 1.5", "--z 1.5 is out of range"},
        // Options the method does not use are still checked: a typo should not pass unseen.
        {"trace --example --method poisson --kernel 99", "--kernel must be 1..8, got 99"},
        {"trace --example --method nearest --radius -5",
         "--radius must be in (0, 64] texels, got -5"},
        {"frobnicate", "frobnicate"},
    };
    for (const Case& c : cases) {
        auto r = runPcfscope(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
        EXPECT_EQ(testutil::lineCount(r.err), 1) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_TRUE(r.out.empty()) << c.args << "\n" << r.out;
    }
}

// trace parses the options it shares with render through the same code (app/render_options.h):
// the same bad value gets the same line from both.
TEST_F(CliTest, TraceAndRenderSayTheSameAboutTheSharedOptions) {
    for (const char* bad :
         {"--method tent --kernel 4", "--method box2x2 --weights binomial", "--precision hw9",
          "--depth-format 8", "--bias slope --slope-max 2", "--method hw2x2 --bias soft"}) {
        auto trace = runPcfscope(std::string("trace --example ") + bad);
        auto render =
            runPcfscope(std::string("render --scene pole ") + bad + " -o " + path("r.png"));
        EXPECT_EQ(trace.exitCode, 2) << bad << "\n" << trace.err;
        EXPECT_EQ(render.exitCode, 2) << bad << "\n" << render.err;
        EXPECT_EQ(testutil::lineCount(trace.err), 1) << bad << "\n" << trace.err;
        EXPECT_EQ(trace.err, render.err) << bad;
    }
    EXPECT_FALSE(std::filesystem::exists(path("r.png")));
}

}  // namespace
}  // namespace pcf
