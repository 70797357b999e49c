// The status line (app/step_words.h: settingsSummary), built from its table of parts over the
// parameter table: what it says for the default state, and that each bias parameter is on it
// exactly under the bias modes that read it (kernel/bias.h), each filter parameter under the
// methods that take it.
#include <gtest/gtest.h>

#include <string>

#include "app/step_words.h"
#include "kernel/methods.h"
#include "kernel/settings.h"

namespace pcf {
namespace {

TEST(StatusLine, TheDefaultStateInTheLinesWords) {
    EXPECT_EQ(settingsSummary(LessonSettings{}),
              "pcf-gather N=3   bias constant 0.002   cull back   map 1024 32f");
}

TEST(StatusLine, NamesTheMethodsOwnParametersAndNotesHw8AndTheGridLast) {
    LessonSettings s;
    s.method = PCF_POISSON;
    s.radius = 2.5f;
    s.rotate = true;
    EXPECT_EQ(settingsSummary(s).substr(0, 22), "poisson R=2.5 rotated ");
    s.method = PCF_NAIVE;
    s.kernel = 5;
    s.weights = PCF_WEIGHTS_GAUSSIAN;
    s.precision = PCF_PRECISION_HW8;
    s.originShift = 0.25f;
    s.snap = true;
    std::string line = settingsSummary(s);
    EXPECT_EQ(line.substr(0, 22), "pcf-naive N=5 gaussian") << line;
    EXPECT_EQ(line.find(" R="), std::string::npos) << line;
    EXPECT_TRUE(line.ends_with("   grid +0.25 texel snapped   hw8")) << line;
}

// Changing a bias parameter changes the line exactly when the mode reads it (bias.h: every mode
// but none subtracts the constant; slope reads slope_bias and slope_max, normal normal_offset,
// soft soft_scale, receiver-plane rpdb_max).
TEST(StatusLine, ShowsEachBiasParameterUnderTheModesThatReadIt) {
    struct Case {
        float ShadowSettings::*field;
        const char* key;
    };
    const Case params[] = {{&ShadowSettings::constantBias, "constant_bias"},
                           {&ShadowSettings::slopeBias, "slope_bias"},
                           {&ShadowSettings::slopeMax, "slope_max"},
                           {&ShadowSettings::normalOffset, "normal_offset"},
                           {&ShadowSettings::softScale, "soft_scale"},
                           {&ShadowSettings::rpdbMax, "rpdb_max"}};
    auto reads = [](BiasMode m, const std::string& key) {
        if (key == "constant_bias") return m != BiasMode::None;
        if (key == "slope_bias" || key == "slope_max") return m == BiasMode::Slope;
        if (key == "normal_offset") return m == BiasMode::Normal;
        if (key == "soft_scale") return m == BiasMode::Soft;
        return m == BiasMode::ReceiverPlane;
    };
    for (BiasMode m : {BiasMode::None, BiasMode::Constant, BiasMode::Slope, BiasMode::Normal,
                       BiasMode::ReceiverPlane, BiasMode::Soft, BiasMode::Interpolated}) {
        LessonSettings s;
        s.bias = m;
        std::string before = settingsSummary(s);
        EXPECT_NE(before.find("   bias " + std::string(biasModeName(m))), std::string::npos)
            << before;
        for (const Case& c : params) {
            LessonSettings t = s;
            t.*c.field = s.*c.field * 0.5f;
            EXPECT_EQ(settingsSummary(t) != before, reads(m, c.key))
                << biasModeName(m) << " " << c.key << ": " << settingsSummary(t);
        }
    }
}

}  // namespace
}  // namespace pcf
