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
    {"constant_bias", " "},
    {"slope_bias", " +"},
    {"slope_max", "tan<="},
    {"normal_offset", " k="},
    {"soft_scale", " x"},
    {"rpdb_max", " dz<="},
    {"cull", "   cull "},
    {"map_size", "   map "},
    {"depth_format", " "},
    {"origin_shift", "   grid +", gridMoved, "", false, gridText},
    {"precision", "   ", nullptr, "exact"},
    {"sun_tilt", "   sun ", sunTilted, "", false, sunTiltText},
    {"sun_turn", "   sun turned ", sunTurned, "", false, sunTurnText},
    {"shading", "   shading ", nullptr, "lit"},
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
        const ParamInfo* p = part.text ? nullptr : findParam(part.key);
        // A bias parameter shows under the modes it acts under (the table's biasModes).
        if (p && p->biasModes != 0 && !paramActsUnder(*p, s.bias)) continue;
        std::string value = statusValue(part, s);
        if (value == part.quiet) continue;
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
        // What the frame draws (the shading) is in the line's settings whenever it is not the
        // default, and changes nothing the words say.
        if (p.group == ParamGroup::View) continue;
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

bool sameForTheWords(LessonSettings a, const LessonSettings& b) {
    const MethodInfo& info = methodInfo(a.method);
    if (a.method == b.method && !info.usesKernel) a.kernel = b.kernel;
    if (a.method == b.method && !info.usesRadius) a.radius = b.radius;
    a.point = b.point;
    a.shading = b.shading;
    return a == b;
}

std::string_view wordsShownName(WordsShown shown) {
    switch (shown) {
        case WordsShown::Step:
            return "step";
        case WordsShown::Noted:
            return "noted";
        case WordsShown::Caption:
            return "caption";
    }
    return "?";
}

std::vector<const StepClaim*> failingClaims(const WordsInput& in) {
    std::vector<const StepClaim*> failing;
    for (const StepClaim& claim : in.step.claims) {
        if (isChartClaim(claim) || claimHolds(claim, in.trace, in.ctx, in.world)) continue;
        failing.push_back(&claim);
    }
    return failing;
}

std::string pointNowWords(const Trace& trace, const ShadowSettings& s) {
    const MethodInfo& info = methodInfo(s.method);
    std::string method(info.name);
    if (info.usesKernel) method += " " + std::to_string(s.kernel) + "x" + std::to_string(s.kernel);
    int lit = 0;
    for (const TapRecord& tap : trace.taps) lit += tap.lit >= 0.5f ? 1 : 0;
    const char* state = trace.visibility >= 1.0f   ? "fully lit"
                        : trace.visibility <= 0.0f ? "fully shadowed"
                                                   : "in penumbra, partly lit";
    return "Under " + method + " the ringed point is " + state + ": visibility " +
           formatNumber(trace.visibility) + ", " + std::to_string(lit) + " of " +
           std::to_string(trace.taps.size()) + " reads pass.";
}

namespace {

// "Written for pcf-gather N=3, bias constant 0.005; now ...": the two states, in the status
// line's words.
std::string writtenFor(const LessonSettings& step, const LessonSettings& live) {
    auto compact = [](std::string t) {
        for (size_t at; (at = t.find("   ")) != std::string::npos;) t.replace(at, 3, ", ");
        return t;
    };
    return "Written for " + compact(settingsSummary(step)) + "; now " +
           compact(settingsSummary(live)) + ".";
}

// Why the words are not shown, in plain words: what the first failing claim that plain words
// can say says, or that numbers they state do not hold.
std::string whyWithheld(const std::vector<const StepClaim*>& failing, const char* where) {
    std::string head = std::string("This step's words are not shown ") + where + ": ";
    for (const StepClaim* claim : failing) {
        std::string words = claimInWords(*claim);
        if (!words.empty()) return head + "they say " + words + ", which is not so here.";
    }
    return head + "numbers they state do not hold here.";
}

// The state the words were written for, or one its `keys` invite: no note needed.
bool wordsState(const WordsInput& in) {
    return sameForTheWords(in.live, in.step.settings) ||
           reachableByKeys(in.step.settings, in.live, in.step.keys);
}

}  // namespace

FrameWords wordsForLiveState(const WordsInput& in) {
    if (sameForTheWords(in.live, in.step.settings)) return {in.text, WordsShown::Step};
    std::string written = writtenFor(in.step.settings, in.live);
    std::string restore = in.interactive ? " Step away and back to restore the step." : "";
    std::vector<const StepClaim*> failing = failingClaims(in);
    if (!failing.empty()) {
        return {"(" + written + " " + whyWithheld(failing, "in this state") + restore + ")\n\n" +
                    pointNowWords(in.trace, in.ctx.settings) + " The live lookup: uv = (" +
                    fillText("{uv.x}, {uv.y}), ref = {ref}, frac = ({frac.x}, {frac.y}).", in.trace,
                             in.ctx),
                WordsShown::Caption};
    }
    // A state the words invite (the step's `keys`, "press O") needs no note: its claims hold.
    if (wordsState(in)) return {in.text, WordsShown::Step};
    return {"(" + written + " The numbers are live." + restore + ")\n\n" + in.text,
            WordsShown::Noted};
}

FrameWords wordsForMovingFrame(const WordsInput& in, const std::string& swept) {
    std::vector<const StepClaim*> failing = failingClaims(in);
    if (!failing.empty()) {
        return {swept + " " + pointNowWords(in.trace, in.ctx.settings) + "\n\n" +
                    whyWithheld(failing, "on this frame"),
                WordsShown::Caption};
    }
    if (wordsState(in)) return {in.text, WordsShown::Step};
    return {"(" + writtenFor(in.step.settings, in.live) + ")\n\n" + in.text, WordsShown::Noted};
}

}  // namespace pcf
