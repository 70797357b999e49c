// settings.h: the vocabulary of pcfscope's settings in one place with no GL: what the command
// line, lesson files, scene files and the renderer all parse and check through. Methods, their
// kernel sizes, weights and precision are in methods.h, bias modes in bias.h; both come with
// this header. Here: the depth formats, culling, the bias modes as an enum, the map-size range
// and the kernel-size rule (tent's 3, 5 or 7), with names <-> enums.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "kernel/bias.h"
#include "kernel/methods.h"

namespace pcf {

enum class DepthFormat { D16, D24, D32F };
// The bias modes, in the kernel's order (the value is PCF_BIAS_NONE ..: kernel/bias.h).
enum class BiasMode { None, Constant, Slope, Normal, ReceiverPlane, Soft, Interpolated };
enum class CullMode { Back, Front, None };

// The shadow map is N x N texels, N in this range.
constexpr int MIN_MAP_SIZE = 4;
constexpr int MAX_MAP_SIZE = 4096;
// The largest frame side (window, export, chart) in pixels.
constexpr int MAX_FRAME_SIDE = 8192;

// Whether `method` can take kernel size n: MIN_KERNEL..MAX_KERNEL, and for tent 3, 5 or 7 (its
// 4, 9 or 16 hardware taps). Methods without a kernel take any n (they ignore it).
bool kernelFits(int method, int n);
// The kernel sizes `method` takes, in words: "1..8", or "3, 5 or 7" for tent.
std::string kernelSizesText(int method);
// The next kernel size `method` takes after n, going up (direction 1) or down (-1), staying
// at the end of the range; a size the method cannot take becomes its smallest.
int stepKernel(int method, int n, int direction);
// n if the method takes it, else its smallest size (a method change keeps N when it can).
int fitKernel(int method, int n);

std::string_view depthFormatName(DepthFormat format);                   // "16", "24", "32f"
std::optional<DepthFormat> depthFormatFromName(std::string_view name);  // also "32", "32F"
int depthFormatFixedPointBits(DepthFormat format);                      // 16, 24, or 0 for 32F
constexpr std::string_view DEPTH_FORMAT_NAMES = "16, 24, 32f";

// "none", "constant", "slope", ...: the names of kernel/bias.h, the one table of them.
std::string_view biasModeName(BiasMode mode);
std::optional<BiasMode> biasModeFromName(std::string_view name);

std::string_view cullModeName(CullMode mode);  // "back", "front", "none"
std::optional<CullMode> cullModeFromName(std::string_view name);
constexpr std::string_view CULL_MODE_NAMES = "back, front, none";

}  // namespace pcf
