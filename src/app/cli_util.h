// cli_util.h: parsing of the command line's small values, with one-line errors.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "base/usage_error.h"
#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"

namespace pcf {

// "a,b,a" -> {"a", "b"}: the comma-separated items, each once, in order; throws UsageError naming
// the option on an empty item.
std::vector<std::string> splitList(const std::string& option, const std::string& text);

// "3,5,3" -> {3, 5}: splitList's items as integers (within +-1e6; the caller checks ranges);
// throws UsageError naming the option on an item that is not one.
std::vector<int> parseIntList(const std::string& option, const std::string& text);

// "0.25,0.5" -> (0.25, 0.5); throws UsageError naming the option on anything else, NaN included.
glm::vec2 parseVec2(const std::string& option, const std::string& text);
// A size option's range: each side from `min` up to `maxSide`. The help and the error state
// it with the same text(), "320x180 up to 8192x8192".
struct SizeRange {
    glm::ivec2 min{1};
    int maxSide = MAX_FRAME_SIDE;
    std::string text() const;
};
// The charts' smallest size: their axes, labels and legend need 64 px a side.
constexpr SizeRange CHART_SIZE_RANGE{glm::ivec2(64), MAX_FRAME_SIDE};
// "1280x720" -> (1280, 720); throws UsageError naming the option and the range.
glm::ivec2 parseSize(const std::string& option, const std::string& text, SizeRange range = {});
// A size option's help: "WHAT WxH, RANGE" and the note (a default) in parentheses if any.
std::string sizeHelp(const std::string& what, SizeRange range, const std::string& note = "");
// "12,34" -> (12, 34).
glm::ivec2 parseIvec2(const std::string& option, const std::string& text);
// Throws UsageError unless lo <= v <= hi and v is finite.
void requireRange(const std::string& option, float v, float lo, float hi);
// Throws UsageError ("--spp 0 is out of range (1..64)") unless lo <= v <= hi.
void requireIntRange(const std::string& option, int v, int lo, int hi);

// A progress line on stderr ("\ranimate [###...] 12/120", redrawn in place, its newline not yet
// written) is open: an error said meanwhile must start a line of its own. The command that draws
// the line says when it opens and closes; endProgressLine ends it, if open, with a newline.
void setProgressLineOpen(bool open);
void endProgressLine();

// A problem the kernel (or an analysis sweep) states in its words, said in the command line's:
// the setting named as its flag, "slope_max" -> "--slope-max" ("tent takes --kernel 3, 5 or 7,
// not 4"). The one place the CLI turns setting names into flags.
std::string cliWords(const ParamProblem& problem);
// checkParams (kernel/methods.h) and checkSettingRanges (kernel/settings.h) in cliWords; nullopt
// when the parameters are valid.
std::optional<std::string> cliParamsProblem(const PcfParams& prm);
std::optional<std::string> cliRangeProblem(const ShadowSettings& s);

}  // namespace pcf
