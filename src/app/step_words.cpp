#include "app/step_words.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <variant>

#include "app/cli_util.h"
#include "kernel/methods.h"
#include "kernel/trace_explain.h"
#include "lesson/lesson_keys.h"
#include "lesson/lesson_pick.h"
#include "overlay/inspector.h"

namespace pcf {

namespace {

// The status line, part by part in its order: a parameter of the table (kernel/settings.h
// PARAMS: its value as the table writes it, numbers as the trace prints them) or a lesson's own
// setting (`text`), the words before it, and when it shows: the settings use it (a kernel size
// under a method that has one, a bias mode's own parameters) and its value is not `quiet` (box
// weights and exact precision go without saying). `bare`: the words alone (" rotated").
struct StatusPart {
    std::string_view key;
    std::string_view before;
    bool (*shows)(const LessonSettings& s) = nullptr;  // nullptr: always
    std::string_view quiet = "";
    bool bare = false;
    std::string (*text)(const LessonSettings& s) = nullptr;  // the value, when not a parameter
};

bool usesKernel(const LessonSettings& s) { return methodInfo(s.method).usesKernel; }
bool usesRadius(const LessonSettings& s) { return methodInfo(s.method).usesRadius; }
bool anyBias(const LessonSettings& s) { return s.bias != BiasMode::None; }
template <BiasMode MODE>
bool biasIs(const LessonSettings& s) {
    return s.bias == MODE;
}
bool gridMoved(const LessonSettings& s) { return s.originShift != 0.0f || s.snap; }
std::string gridText(const LessonSettings& s) {
    return formatNumber(s.originShift) + " texel" + (s.snap ? " snapped" : "");
}

// The sun as the keys moved it from the scene's (U, T), in degrees.
bool sunTilted(const LessonSettings& s) { return s.sunTilt != 0.0f; }
std::string sunTiltText(const LessonSettings& s) {
    return (s.sunTilt > 0.0f ? "+" : "") + formatNumber(s.sunTilt) + " deg";
}
bool sunTurned(const LessonSettings& s) { return s.sunTurn != 0.0f; }
std::string sunTurnText(const LessonSettings& s) { return formatNumber(s.sunTurn) + " deg"; }

const StatusPart STATUS_PARTS[] = {
    {"method", ""},
    {"kernel", " N=", usesKernel},
    {"weights", " ", nullptr, "box"},
    {"radius", " R=", usesRadius},
    {"rotate", " rotated", usesRadius, "false", true},
    {"bias", "   bias "},
    {"constant_bias", " ", anyBias},
    {"slope_bias", " +", biasIs<BiasMode::Slope>},
    {"slope_max", "tan<=", biasIs<BiasMode::Slope>},
    {"normal_offset", " k=", biasIs<BiasMode::Normal>},
    {"soft_scale", " x", biasIs<BiasMode::Soft>},
    {"rpdb_max", " dz<=", biasIs<BiasMode::ReceiverPlane>},
    {"cull", "   cull "},
    {"map_size", "   map "},
    {"depth_format", " "},
    {"origin_shift", "   grid +", gridMoved, "", false, gridText},
    {"precision", "   ", nullptr, "exact"},
    {"sun_tilt", "   sun ", sunTilted, "", false, sunTiltText},
    {"sun_turn", "   sun turned ", sunTurned, "", false, sunTurnText},
};

std::string statusValue(const StatusPart& part, const LessonSettings& s) {
    if (part.text) return part.text(s);
    const ParamInfo* p = findParam(part.key);
    if (!p) throw std::logic_error("status line: no parameter '" + std::string(part.key) + "'");
    if (const auto* field = std::get_if<float ShadowSettings::*>(&p->field)) {
        return formatNumber(s.*(*field));
    }
    return settingText(*p, s);
}

}  // namespace

std::string settingsSummary(const LessonSettings& s, bool hideBiasAmounts) {
    std::string line;
    for (const StatusPart& part : STATUS_PARTS) {
        if (part.shows && !part.shows(s)) continue;
        std::string value = statusValue(part, s);
        if (value == part.quiet) continue;
        const ParamInfo* p = part.text ? nullptr : findParam(part.key);
        bool amount = p && p->group == ParamGroup::Bias && part.key != "bias";
        if (hideBiasAmounts && amount) value = HIDDEN_NUMBER;
        line += std::string(part.before) + (part.bare ? "" : value);
    }
    return line;
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
