// shaders/shared/pcf_shading.h: the camera pass's gamma encoding, the same source the fragment
// shader runs, bounded against the pow it stands for over the whole range scene.frag feeds it;
// and the `shading` setting: `visibility` draws each receiver as the kernel's visibility alone.
#include "kernel/shading.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "kernel/pcf.h"
#include "render/gl_context.h"
#include "render/scene_renderer.h"
#include "scene/presets.h"

namespace {

// scene.frag's light factor: ambient 0.25 plus 0.75 of the sun, so x in [0.25, 1].
constexpr double LIGHT_MIN = 0.25;
constexpr int SAMPLES = 200000;

TEST(GammaEncode, StaysWithinItsStatedBoundOfPowOverTheLightRange) {
    double worst = 0.0;
    for (int i = 0; i <= SAMPLES; ++i) {
        float x = static_cast<float>(LIGHT_MIN + (1.0 - LIGHT_MIN) * i / SAMPLES);
        double exact = std::pow(static_cast<double>(x), 1.0 / 2.2);
        worst = std::max(worst, std::abs(pcf::pcfGammaEncode(x) - exact));
    }
    EXPECT_LT(worst, 6e-6);  // the bound pcf_shading.h states
}

TEST(GammaEncode, IsIncreasingSoBrighterLightNeverReadsDarker) {
    float previous = pcf::pcfGammaEncode(static_cast<float>(LIGHT_MIN));
    for (int i = 1; i <= SAMPLES; ++i) {
        float x = static_cast<float>(LIGHT_MIN + (1.0 - LIGHT_MIN) * i / SAMPLES);
        float g = pcf::pcfGammaEncode(x);
        ASSERT_GE(g, previous) << "at x = " << x;
        previous = g;
    }
}

TEST(GammaEncode, EndsOfTheRangeRoundToThePowsEightBitValues) {
    // Full sun is white and ambient alone is pow(0.25, 1/2.2) = 0.5325: in an 8-bit frame both
    // ends land on the same byte as the exact power.
    for (float x : {0.25f, 0.5f, 1.0f}) {
        long exact = std::lround(255.0 * std::pow(static_cast<double>(x), 1.0 / 2.2));
        EXPECT_EQ(std::lround(255.0 * pcf::pcfGammaEncode(x)), exact) << "x = " << x;
    }
}

}  // namespace

namespace pcf {
namespace {

// `--shading visibility` (lesson key `shading`, viewer key N): every receiver pixel is the grey
// level of the visibility the CPU kernel computes for that pixel's own lookup (its u, v and ref
// as the camera pass wrote them), 255 v to within the byte's rounding, with no N.L and no
// albedo; off the receivers (the sky) nothing changes. Under the grazing light, lit, the same
// ground is a few grey levels of a dark picture.
TEST(Shading, VisibilityDrawsEachReceiverAsTheKernelsVisibility) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    Scene scene = *presetScene("grazing");
    SceneRenderer renderer(scene);
    for (int method : {PCF_NEAREST, PCF_GATHER}) {
        RenderSettings s;
        s.method = method;
        s.kernel = 3;
        s.mapSize = 256;
        s.bias = BiasMode::None;  // acne: 0 and 1 under nearest, the values between filtered
        s.frameSize = {320, 180};
        renderer.render(s);
        std::vector<uint8_t> lit = renderer.readColour();
        s.shading = Shading::Visibility;
        renderer.render(s);
        std::vector<uint8_t> shown = renderer.readColour();
        std::vector<float> ls = renderer.readLightSpace();
        ShadowMap map = renderer.readShadowMap();
        int receivers = 0, dark = 0, bright = 0, between = 0, litDiffers = 0;
        float worst = 0.0f;
        for (size_t k = 0; k < ls.size() / 4; ++k) {
            const uint8_t* px = &shown[4 * k];
            if (ls[4 * k + 3] != 1.0f) {
                EXPECT_TRUE(std::equal(px, px + 4, &lit[4 * k]))
                    << "off the receivers, pixel " << k;
                continue;
            }
            ++receivers;
            float v = filterVisibility(map, glm::vec2(ls[4 * k], ls[4 * k + 1]), ls[4 * k + 2],
                                       s.pcfParams());
            worst = std::max(worst, std::fabs(px[0] - 255.0f * v));
            EXPECT_TRUE(px[0] == px[1] && px[1] == px[2]) << "grey, pixel " << k;
            dark += px[0] == 0;
            bright += px[0] == 255;
            between += px[0] > 0 && px[0] < 255;
            litDiffers += lit[4 * k] != px[0];
        }
        SCOPED_TRACE(std::string(methodInfo(method).name));
        EXPECT_LE(worst, 0.51f) << "255 v, rounded";
        EXPECT_GT(receivers, 20000);
        if (method == PCF_NEAREST) {
            EXPECT_GT(dark, receivers / 20) << "acne and shadow, black";
            EXPECT_GT(bright, receivers / 20) << "lit ground, white";
            EXPECT_EQ(between, 0) << "nearest's visibility is 0 or 1";
        } else {
            EXPECT_GT(between, receivers / 2) << "acne under a filter: the values between";
        }
        EXPECT_GT(litDiffers, receivers * 9 / 10) << "lit, the picture is another";
    }
}

}  // namespace
}  // namespace pcf
