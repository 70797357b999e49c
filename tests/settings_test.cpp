// kernel/settings.h: the settings vocabulary the CLI, lesson files and renderer share.
#include "kernel/settings.h"

#include <gtest/gtest.h>

namespace pcf {
namespace {

TEST(Settings, TentTakesThreeFiveOrSevenAndTheOthersTheRange) {
    for (int n = -1; n <= MAX_KERNEL + 2; ++n) {
        EXPECT_EQ(kernelFits(PCF_TENT, n), n == 3 || n == 5 || n == 7) << n;
        EXPECT_EQ(kernelFits(PCF_GATHER, n), n >= MIN_KERNEL && n <= MAX_KERNEL) << n;
        EXPECT_TRUE(kernelFits(PCF_BILINEAR2X2, n)) << n;  // no kernel: any N is ignored
    }
    EXPECT_EQ(kernelSizesText(PCF_TENT), "3, 5 or 7");
    EXPECT_EQ(kernelSizesText(PCF_NAIVE), "1..8");
}

TEST(Settings, ValidateParamsFollowsTheSameRule) {
    for (int n = MIN_KERNEL; n <= MAX_KERNEL; ++n) {
        bool tentTakes = n == 3 || n == 5 || n == 7;
        EXPECT_EQ(validateParams(makeParams(PCF_TENT, n)).has_value(), !tentTakes) << n;
        EXPECT_FALSE(validateParams(makeParams(PCF_GATHER, n)).has_value()) << n;
    }
    EXPECT_TRUE(validateParams(makeParams(PCF_GATHER, MAX_KERNEL + 1)).has_value());
}

TEST(Settings, KernelKeysStepThroughWhatTheMethodTakes) {
    EXPECT_EQ(stepKernel(PCF_TENT, 3, 1), 5);
    EXPECT_EQ(stepKernel(PCF_TENT, 5, 1), 7);
    EXPECT_EQ(stepKernel(PCF_TENT, 7, 1), 7);
    EXPECT_EQ(stepKernel(PCF_TENT, 5, -1), 3);
    EXPECT_EQ(stepKernel(PCF_TENT, 3, -1), 3);
    EXPECT_EQ(stepKernel(PCF_TENT, 4, 1), 3);  // a size tent cannot take: its smallest
    EXPECT_EQ(stepKernel(PCF_GATHER, 3, 1), 4);
    EXPECT_EQ(stepKernel(PCF_GATHER, MAX_KERNEL, 1), MAX_KERNEL);
    EXPECT_EQ(stepKernel(PCF_GATHER, MIN_KERNEL, -1), MIN_KERNEL);
    EXPECT_EQ(fitKernel(PCF_TENT, 6), 3);
    EXPECT_EQ(fitKernel(PCF_TENT, 5), 5);
    EXPECT_EQ(fitKernel(PCF_GATHER, 6), 6);
}

TEST(Settings, NamesRoundTrip) {
    for (DepthFormat f : {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F}) {
        EXPECT_EQ(depthFormatFromName(depthFormatName(f)), f);
        EXPECT_NE(DEPTH_FORMAT_NAMES.find(depthFormatName(f)), std::string_view::npos);
    }
    EXPECT_EQ(depthFormatFromName("32"), DepthFormat::D32F);
    EXPECT_FALSE(depthFormatFromName("8").has_value());
    EXPECT_EQ(depthFormatFixedPointBits(DepthFormat::D24), 24);
    EXPECT_EQ(depthFormatFixedPointBits(DepthFormat::D32F), 0);
    for (CullMode c : {CullMode::Back, CullMode::Front, CullMode::None}) {
        EXPECT_EQ(cullModeFromName(cullModeName(c)), c);
        EXPECT_NE(CULL_MODE_NAMES.find(cullModeName(c)), std::string_view::npos);
    }
    EXPECT_FALSE(cullModeFromName("both").has_value());
    for (int m = 0; m < PCF_BIAS_COUNT; ++m) {
        BiasMode mode = static_cast<BiasMode>(m);
        EXPECT_EQ(biasModeFromName(biasModeName(mode)), mode);
        EXPECT_EQ(biasModeName(mode), biasName(m));  // one table of names: kernel/bias.h
    }
    EXPECT_FALSE(biasModeFromName("lots").has_value());
}

}  // namespace
}  // namespace pcf
