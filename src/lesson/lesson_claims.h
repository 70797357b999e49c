// lesson_claims.h: what a step's words state about its numbers, written beside the words so that
// a checker can verify them (`pcfscope lesson check FILE`) and the viewer can withhold words that
// a key press has made false. A step lists its claims in its TOML table:
//
//   claims = [
//     "shadowed",                       the picked point: visibility 0
//     "{shadowed_count} = 0",           an expression compared with another
//     "{frac.x} ~ 0.2 +- 0.0005",       near: within the tolerance after +-
//     "{visibility} ~ 1 - {frac.x} +- 1e-4",
//     "failing taps nearer",            every failing read stores a depth nearer the light than
//                                       its ref (depth < ref)
//     "bits 1010",                      every read's bit, in read order
//     "chart: pcf-gather3 faster than pcf-hw3",   an order on the step's chart (bench.csv)
//     "chart: measured on llvmpipe",    any other fact of the step's chart's table
//     "flickers",                       an animating step: the ringed point's visibility jumps
//                                       between two frames of the step's sweep
//   ]
//
// Keywords: `lit` (every read that counts passes, visibility 1), `shadowed` (visibility 0),
// `penumbra` (0 < visibility < 1), `failing taps nearer`, `on the ground` (the picked point lies
// on a plane), `bits B...` (the reads' bits), `flickers` (a step with `animate`: the flicker
// trace's line of the step's method, the point's visibility frame by frame, changes by at least
// FLICKER_JUMP between two consecutive frames: the jagged line of a hard edge crossing the point).
// Expressions: numbers, {placeholders} (any number placeholder of lesson_text.h, with *F factors),
// + - * / and parentheses, compared with = != < <= > >= or ~ (near, with a tolerance: `a ~ b +- t`
// holds when |a - b| <= t). `=` is exact: use it for counts and bits. Chart claims read the CSV the
// step's chart draws: `chart: A faster than B` / `slower than` (the median scene-pass time), `more
// accurate than` / `less accurate than` (the chart's y axis: the edge RMSE against the ray-cast
// truth, or near the contacts on a "PATH#contact" chart); A and B are dot labels or their first
// word, as chart_highlight takes them. Any other `chart: FACT` is one of the facts the chart's data
// answers (charts/chart_facts.h: the renderer it was measured on, the truth it was measured
// against, the Pareto front, where acne and leak lie on the bias axis); `lesson check` names the
// facts it knows when one is not among them.
//
// A step's `keys = ["O", "+"]` names the viewer keys its words are written to survive (a step that
// tells the class to press O): the checker verifies the claims after each of those keys too.
// After any other key the viewer checks the claims on the live trace and, when one fails, shows
// the settings the words were written for instead of the words.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "kernel/trace.h"
#include "lesson/lesson.h"
#include "lesson/lesson_text.h"

namespace pcf {

// The smallest change of visibility between two consecutive frames that `flickers` counts: half
// the range, which a filter's smooth creep (1/32 texel a frame) never makes and nearest's 0 <-> 1
// always does.
constexpr float FLICKER_JUMP = 0.5f;
// The largest change between two consecutive frames that `steady` allows: 1/512, a quarter of
// an 8-bit grey level, the change the stability sweeps count as visible
// (measure/failure_measures.h VISIBLE_CHANGE).
constexpr float STEADY_CHANGE = 1.0f / 512.0f;

// What a claim may read besides the trace and the step's context.
struct ClaimWorld {
    bool onPlane = false;  // the picked point lies on a plane
    // A chart claim: whether A's `metric` ("time" or "rmse") is less than B's on the step's
    // chart, or the reason it cannot be told. Unset: chart claims are not checked (held).
    std::function<std::variant<bool, std::string>(const std::string& a, const std::string& b,
                                                  const std::string& metric)>
        chartLess;
    // Any other chart claim: whether the fact holds on the step's chart; `why` gets the numbers
    // that decided it, or the reason it cannot be told (an unknown fact, a file without the
    // data: then false). Unset: held.
    std::function<bool(const std::string& fact, std::string* why)> chartFact;
    // A motion claim (`flickers`): the step's flicker trace, the pinned point's visibility under
    // the step's method at each frame of its animation (-1: the point on no receiver in that
    // frame), or the reason there is none. Unset: held (the viewer, which plays the frames).
    std::function<std::variant<std::vector<float>, std::string>()> flickerCurve;
};

// The deepest a claim's expression may nest ( and unary -: TOML's own limit on nested arrays and
// tables (toml++ TOML_MAX_NESTED_VALUES), far below where the parser's recursion would overflow
// the stack of any build.
constexpr int MAX_CLAIM_NESTING = 256;

// Parses a claim; std::invalid_argument naming what is wrong (an unknown placeholder, a missing
// operator, a near without +-, a non-finite number, nesting past MAX_CLAIM_NESTING).
std::shared_ptr<const ParsedClaim> parseClaim(std::string_view text);

// What the braces of a comparison claim's placeholders hold ("visibility", "tap[2].margin"), in
// order; empty for a keyword or chart claim. The lesson reader checks their indices against the
// step's reads, as it checks its text's (lesson_text.h checkPlaceholders).
std::vector<std::string> claimPlaceholders(const StepClaim& claim);

// Whether the claim holds for this trace; `why` gets the values that decided it ("{frac.x} =
// 0.2022, not within 0.0005 of 0.2"). Charts claims are held when world.chartLess is unset.
bool claimHolds(const StepClaim& claim, const Trace& trace, const StepContext& ctx,
                const ClaimWorld& world, std::string* why = nullptr);

// The fact a "chart: FACT" claim states (not an order of dots), or "" for any other claim.
std::string chartFactOf(const StepClaim& claim);

// Whether the claim reads the step's chart (an order or a fact; nothing of the trace).
bool isChartClaim(const StepClaim& claim);

// Whether the claim reads the step's animation (`flickers`; nothing of the still frame's trace).
bool isMotionClaim(const StepClaim& claim);

// What a claim says, in plain words that follow "the words say" ("the point is fully
// shadowed", "the light's angle from the surface's normal is above 60"), for a frame that
// withholds words the claim makes false; "" for a claim plain words cannot say briefly (an
// expression of several placeholders, a chart's), whose syntax a class should not read either.
std::string claimInWords(const StepClaim& claim);

}  // namespace pcf
