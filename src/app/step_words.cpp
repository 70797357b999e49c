#include "app/step_words.h"

#include <sstream>

#include "app/cli_util.h"
#include "kernel/methods.h"
#include "kernel/trace_explain.h"
#include "lesson/lesson_keys.h"

namespace pcf {

std::string settingsSummary(const LessonSettings& s) {
    const MethodInfo& info = methodInfo(s.method);
    // A stream: GCC 12 warns falsely (-Wrestrict) on chains of string operator+.
    std::ostringstream line;
    line << info.name;
    if (info.usesKernel) line << " N=" << s.kernel;
    if (s.weights != PCF_WEIGHTS_BOX) line << " " << weightsName(s.weights);
    if (info.usesRadius) line << " R=" << formatNumber(s.radius) << (s.rotate ? " rotated" : "");
    line << "   bias " << biasModeName(s.bias);
    if (s.bias != BiasMode::None) line << " " << formatNumber(s.constantBias);
    if (s.bias == BiasMode::Slope) {
        line << " +" << formatNumber(s.slopeBias) << "tan<=" << formatNumber(s.slopeMax);
    }
    if (s.bias == BiasMode::Normal) line << " k=" << formatNumber(s.normalOffset);
    if (s.bias == BiasMode::Soft) line << " x" << formatNumber(s.softScale);
    if (s.bias == BiasMode::ReceiverPlane) line << " dz<=" << formatNumber(s.rpdbMax);
    line << "   cull " << cullModeName(s.cull) << "   map " << s.mapSize << " "
         << depthFormatName(s.depthFormat);
    if (s.originShift != 0.0f || s.snap) {
        line << "   grid +" << formatNumber(s.originShift) << " texel"
             << (s.snap ? " snapped" : "");
    }
    if (s.precision == PCF_PRECISION_HW8) line << "   hw8";
    return line.str();
}

std::string wordsForLiveState(const LessonStep& step, const LessonSettings& live,
                              const std::string& text, const Trace& trace, const StepContext& ctx,
                              const ClaimWorld& world) {
    if (live == step.settings) return text;
    auto compact = [](std::string t) {
        for (size_t at; (at = t.find("   ")) != std::string::npos;) t.replace(at, 3, ", ");
        return t;
    };
    std::string written = "Written for " + compact(settingsSummary(step.settings)) + "; now " +
                          compact(settingsSummary(live)) + ".";
    for (const StepClaim& claim : step.claims) {
        if (isChartClaim(claim) || claimHolds(claim, trace, ctx, world)) continue;
        return "(" + written + " This step's words do not hold now (\"" + claim.text +
               "\" is false here), so they are not shown; step away and back to restore the "
               "step.)\n\nThe live lookup: uv = (" +
               fillText(
                   "{uv.x}, {uv.y}), ref = {ref}, frac = ({frac.x}, {frac.y}), "
                   "{lit_count} of {taps} reads pass, visibility = {visibility}.",
                   trace, ctx);
    }
    // A state the words invite (the step's `keys`, "press O") needs no note: its claims hold.
    if (reachableByKeys(step.settings, live, step.keys)) return text;
    return "(" + written + " The numbers are live; step away and back to restore the step.)\n\n" +
           text;
}

}  // namespace pcf
