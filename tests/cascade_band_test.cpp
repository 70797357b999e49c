// A `render --raw` folder of cascades with a blend band (--cascade-blend), read back by
// `trace --raw` and `verify`: a pixel in the band is traced with the next cascade's lookup, the
// band's weight and the mix the frame shows, and `verify` bounds every band pixel by the mix of
// both cascades' envelopes, under receiver-plane bias too (whose next cascade is filtered with the
// receiver's plane there, next_dzduv.exr). The folder: long-ground, 4 cascades, receiver-plane
// bias, poisson with its disk turned per texel (each cascade's lookup turns by its own texel).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "kernel/trace_json.h"
#include "render/image_io.h"
#include "run_command.h"

namespace {

using pcf::FloatImage;
using pcf::Json;

constexpr double BAND = 0.3;
constexpr int COUNT = 4;
// What tests/cascade_parity_test.cpp allows between the GPU's band pixel and the CPU's: its
// PARITY_TOLERANCE plus the recomputed next lookup's RECOMPUTED_LOOKUP_SLACK.
constexpr double PARITY = 1e-5 + 3e-5;

// One receiver pixel as render.json and positions.exr place it: its cascade (the first whose far
// view depth lies beyond the pixel's) and the band's weight there, by the band's formula of
// docs/user-guide.md: start = far - B (far - near), w = (d - start) / (far - start) in [0, 1],
// 0 in the last cascade.
struct BandPixel {
    size_t k = 0;
    int layer = 0;
    double weight = 0.0;
};

class BlendBandFolder : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        sDir = testutil::makeTempDir("cascade-band");
        sRaw = (sDir / "raw").string();
        testutil::CommandResult r = testutil::runPcfscope(
            "render --scene long-ground --cascades 4 --shadow-distance 60 --map-size 128 "
            "--size 192x108 --bias receiver-plane --method poisson --radius 2 --rotate "
            "--cascade-blend " +
            std::to_string(BAND) + " --raw " + sRaw);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        sVisibility = pcf::readFloatImage(sRaw + "/visibility.exr");
        FloatImage ls = pcf::readFloatImage(sRaw + "/lightspace.exr");
        FloatImage pos = pcf::readFloatImage(sRaw + "/positions.exr");
        Json j = Json::parse(testutil::readAll(sRaw + "/render.json"));
        const Json& cam = j["map"]["cascade_camera"];
        for (size_t k = 0; k < sVisibility.data.size(); ++k) {
            if (ls.data[4 * k + 3] != 1.0f) continue;
            double depth = 0.0;
            for (size_t c = 0; c < 3; ++c) {
                depth += (pos.data[4 * k + c] - cam["eye"][c].get<double>()) *
                         cam["view_dir"][c].get<double>();
            }
            BandPixel p{k, 0, 0.0};
            while (p.layer < COUNT && depth >= j["map"]["cascades"][p.layer]["far"].get<double>()) {
                ++p.layer;
            }
            if (p.layer + 1 < COUNT) {
                double near = j["map"]["cascades"][p.layer]["near"].get<double>();
                double far = j["map"]["cascades"][p.layer]["far"].get<double>();
                double start = far - BAND * (far - near);
                p.weight = std::clamp((depth - start) / (far - start), 0.0, 1.0);
            }
            sPixels.push_back(p);
        }
    }
    static void TearDownTestSuite() {
        if (!::testing::UnitTest::GetInstance()->failed_test_count()) {
            std::filesystem::remove_all(sDir);
        }
    }
    static std::string pixelArg(size_t k) {
        return std::to_string(k % static_cast<size_t>(sVisibility.width)) + "," +
               std::to_string(k / static_cast<size_t>(sVisibility.width));
    }
    static Json traceJson(size_t k) {
        testutil::CommandResult t =
            testutil::runPcfscope("trace --raw " + sRaw + " --pixel " + pixelArg(k) + " --json");
        EXPECT_EQ(t.exitCode, 0) << t.err;
        return Json::parse(t.out);
    }
    static std::filesystem::path sDir;
    static std::string sRaw;
    static FloatImage sVisibility;
    static std::vector<BandPixel> sPixels;
};
std::filesystem::path BlendBandFolder::sDir;
std::string BlendBandFolder::sRaw;
FloatImage BlendBandFolder::sVisibility;
std::vector<BandPixel> BlendBandFolder::sPixels;

// In the band (away from its ends, where the test's double view depth and the GPU's float one
// could pick different sides) the trace has the next cascade, the formula's weight and, as
// `visibility`, what the frame shows; where the two cascades disagree the mix is not the cascade
// read's own visibility. Before the band, no band.
TEST_F(BlendBandFolder, TraceRawShowsTheBandsSecondLookup) {
    int traced = 0, blendMatters = 0;
    std::vector<bool> layerTraced(COUNT, false);
    for (const BandPixel& p : sPixels) {  // a shadow edge's pixel in each band
        float v = sVisibility.data[p.k];
        if (p.weight < 0.1 || p.weight > 0.9 || v < 0.05f || v > 0.95f ||
            layerTraced[static_cast<size_t>(p.layer)]) {
            continue;
        }
        layerTraced[static_cast<size_t>(p.layer)] = true;
        ++traced;
        Json tr = traceJson(p.k);
        const Json& band = tr["cascade_blend"];
        EXPECT_EQ(tr["layer"], p.layer) << pixelArg(p.k);
        EXPECT_EQ(band["next_layer"], p.layer + 1) << pixelArg(p.k);
        EXPECT_NEAR(band["weight"].get<double>(), p.weight, 1e-4) << pixelArg(p.k);
        EXPECT_NEAR(band["visibility"].get<double>(), v, PARITY) << pixelArg(p.k);
        blendMatters += std::abs(tr["visibility"].get<double>() - v) > 0.01 ? 1 : 0;
        if (traced == 1) {  // the text trace says so before the steps
            testutil::CommandResult text =
                testutil::runPcfscope("trace --raw " + sRaw + " --pixel " + pixelArg(p.k));
            std::string line =
                "blend band: cascade " + std::to_string(p.layer + 1) + " looks the point up too";
            EXPECT_LT(text.out.find(line), text.out.find("1. ")) << text.out.substr(0, 600);
        }
    }
    EXPECT_EQ(traced, COUNT - 1);  // every band but the last cascade's, which has none
    EXPECT_GE(blendMatters, 2);

    // A shadow edge's pixel of cascade 1 before its band.
    const BandPixel* before = nullptr;
    for (const BandPixel& p : sPixels) {
        float v = sVisibility.data[p.k];
        if (p.layer == 1 && p.weight == 0.0 && v > 0.05f && v < 0.95f && !before) before = &p;
    }
    ASSERT_TRUE(before);
    Json tr = traceJson(before->k);
    EXPECT_EQ(tr["cascade_blend"]["next_layer"], -1) << pixelArg(before->k);
    EXPECT_EQ(tr["cascade_blend"]["weight"], 0) << pixelArg(before->k);
    EXPECT_NEAR(tr["visibility"].get<double>(), sVisibility.data[before->k], PARITY);
}

// The folder passes whole; one band pixel moved by half its weight, towards the middle of [0, 1],
// from a value both cascades agree on (fully lit or fully shadowed), lies outside the mix of
// their envelopes, and verify names it. Without next_dzduv.exr verify refuses the folder.
TEST_F(BlendBandFolder, VerifyBoundsABandPixelUnderReceiverPlaneBias) {
    testutil::CommandResult ok = testutil::runPcfscope("verify " + sRaw);
    EXPECT_EQ(ok.exitCode, 0) << ok.out << ok.err;
    EXPECT_NE(ok.out.find("(100.0000 %)"), std::string::npos) << ok.out;

    const BandPixel* pick = nullptr;
    for (const BandPixel& p : sPixels) {
        float v = sVisibility.data[p.k];
        if (p.weight > 0.4 && p.weight < 0.6 && (v == 0.0f || v == 1.0f)) pick = &p;
    }
    ASSERT_TRUE(pick);
    std::string altered = (sDir / "altered").string();
    std::filesystem::copy(sRaw, altered);
    FloatImage vis = sVisibility;
    float half = static_cast<float>(pick->weight / 2.0);
    vis.data[pick->k] = vis.data[pick->k] == 0.0f ? half : 1.0f - half;
    pcf::writeExr(altered + "/visibility.exr", vis.width, vis.height, 1, vis.data, {"Y"});
    testutil::CommandResult bad = testutil::runPcfscope("verify " + altered);
    EXPECT_EQ(bad.exitCode, 1) << bad.out << bad.err;
    std::string where = "pixel (" + std::to_string(pick->k % static_cast<size_t>(vis.width)) +
                        ", " + std::to_string(pick->k / static_cast<size_t>(vis.width)) + ")";
    EXPECT_NE(bad.out.find("worst outlier: " + where), std::string::npos) << bad.out;

    std::filesystem::remove(altered + "/next_dzduv.exr");
    testutil::CommandResult lacking = testutil::runPcfscope("verify " + altered);
    EXPECT_EQ(lacking.exitCode, 2);
    EXPECT_NE(lacking.err.find("(next_dzduv.exr), which the folder lacks"), std::string::npos)
        << lacking.err;
}

}  // namespace
