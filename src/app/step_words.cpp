#include "app/step_words.h"

#include <cmath>
#include <sstream>

#include "app/cli_util.h"
#include "kernel/methods.h"
#include "kernel/trace_explain.h"
#include "lesson/lesson_keys.h"
#include "lesson/lesson_pick.h"

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
    // The sun as the keys moved it from the scene's (U, T), in degrees.
    if (s.sunTilt != 0.0f)
        line << "   sun " << (s.sunTilt > 0.0f ? "+" : "") << formatNumber(s.sunTilt) << " deg";
    if (s.sunTurn != 0.0f) line << "   sun turned " << formatNumber(s.sunTurn) << " deg";
    return line.str();
}

std::vector<std::string> changedSettings(const LessonSettings& step, const LessonSettings& live,
                                         const Light& sceneLight) {
    std::vector<std::string> changed;
    for (const ParamInfo& p : allParams()) {
        std::string now = settingText(p, live);
        if (now != settingText(p, step)) changed.push_back(std::string(p.key) + " " + now);
    }
    if (live.originShift != step.originShift) {
        changed.push_back("origin_shift " + formatNumber(live.originShift));
    }
    if (live.snap != step.snap) changed.push_back(live.snap ? "snap true" : "snap false");
    if (live.sunTilt != step.sunTilt) {
        float up = lightElevationDeg(lessonLight(sceneLight, live));
        changed.push_back("sun " + formatNumber(std::round(up * 10.0f) / 10.0f) + " deg up");
    }
    if (live.sunTurn != step.sunTurn) {
        changed.push_back("sun turned " + formatNumber(live.sunTurn - step.sunTurn) + " deg");
    }
    return changed;
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
