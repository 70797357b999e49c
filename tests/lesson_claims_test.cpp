// lesson_claims.h: claims parse, compute with placeholders and hold or fail on a trace, saying
// why; bad claims are refused with the reason.
#include "lesson/lesson_claims.h"

#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "base/input_error.h"
#include "kernel/methods.h"
#include "kernel/shadow_map.h"
#include "lesson/lesson.h"

namespace pcf {
namespace {

Trace bilinearTrace() {
    return traceLookup(exampleShadowMap(), vec2(0.4625f, 0.3875f), 0.5f, 0.5f,
                       makeParams(PCF_BILINEAR2X2, 1));
}

bool holds(const std::string& text, const Trace& t, std::string* why = nullptr,
           bool onPlane = false) {
    StepClaim c{text, 1, parseClaim(text)};
    ClaimWorld world;
    world.onPlane = onPlane;
    return claimHolds(c, t, StepContext{}, world, why);
}

std::string bitsOf(const Trace& t) {
    std::string bits;
    for (const TapRecord& tap : t.taps) bits += tap.lit >= 0.5f ? '1' : '0';
    return bits;
}

TEST(LessonClaims, ComparisonsComputeWithPlaceholders) {
    Trace t = bilinearTrace();
    ASSERT_EQ(t.taps.size(), 4u);
    EXPECT_TRUE(holds("{taps} = 4", t));
    std::string why;
    EXPECT_FALSE(holds("{taps} = 5", t, &why));
    EXPECT_EQ(why, "not 4 = 5");
    // * before +, parentheses first, unary minus.
    EXPECT_TRUE(holds("2 + 3 * {taps} = 14", t));
    EXPECT_TRUE(holds("(2 + 3) * {taps} = 20", t));
    EXPECT_TRUE(holds("-{taps} < 0", t));
    EXPECT_TRUE(holds("{taps*0.5} = 2", t));
    EXPECT_TRUE(holds("{lit_count} + {shadowed_count} = {taps}", t));
    EXPECT_TRUE(holds("{taps} != 3", t));
    EXPECT_TRUE(holds("{taps} >= 4", t));
    EXPECT_FALSE(holds("{taps} > 4", t));
    EXPECT_TRUE(holds("{taps} <= 4", t));
    // Near: within the tolerance, and not beyond it.
    float fx = t.pos.frac.x;
    EXPECT_TRUE(holds("{frac.x} ~ " + std::to_string(fx + 0.0004f) + " +- 0.0005", t));
    EXPECT_FALSE(holds("{frac.x} ~ " + std::to_string(fx + 0.001f) + " +- 0.0005", t));
    // An index past the trace's reads has no value: the claim fails.
    EXPECT_FALSE(holds("{tap[9].depth} < 2", t, &why));
    EXPECT_NE(why.find("no value"), std::string::npos);
}

TEST(LessonClaims, KeywordsReadTheTrace) {
    Trace t = bilinearTrace();
    EXPECT_EQ(holds("lit", t), t.visibility == 1.0f);
    EXPECT_EQ(holds("shadowed", t), t.visibility == 0.0f);
    EXPECT_EQ(holds("penumbra", t), t.visibility > 0.0f && t.visibility < 1.0f);
    EXPECT_TRUE(holds("bits " + bitsOf(t), t));
    std::string flipped = bitsOf(t);
    flipped[0] = flipped[0] == '1' ? '0' : '1';
    EXPECT_FALSE(holds("bits " + flipped, t));
    EXPECT_TRUE(holds("on the ground", t, nullptr, true));
    EXPECT_FALSE(holds("on the ground", t, nullptr, false));
    // Failing reads are those whose depth is below their ref; a made-up one that is not fails.
    EXPECT_TRUE(holds("failing taps nearer", t));
    Trace odd = t;
    odd.taps[0].lit = 0.0f;
    odd.taps[0].depth = odd.taps[0].ref + 0.5f;
    EXPECT_FALSE(holds("failing taps nearer", odd));
}

TEST(LessonClaims, ChartClaimsAskTheChart) {
    Trace t = bilinearTrace();
    StepClaim c{"chart: gather3 faster than hw3", 1, parseClaim("chart: gather3 faster than hw3")};
    EXPECT_TRUE(isChartClaim(c));
    ClaimWorld world;
    std::string asked;
    world.chartLess = [&](const std::string& a, const std::string& b, const std::string& metric) {
        asked = a + "<" + b + " " + metric;
        return std::variant<bool, std::string>(false);
    };
    EXPECT_FALSE(claimHolds(c, t, StepContext{}, world));
    EXPECT_EQ(asked, "gather3<hw3 time");
    // "slower than" asks the other way round; accuracy reads the RMSE.
    StepClaim s{"", 1, parseClaim("chart: tent3 less accurate than naive3")};
    claimHolds(s, t, StepContext{}, world);
    EXPECT_EQ(asked, "naive3<tent3 rmse");
    // Any other statement is a fact the chart's table answers (charts/chart_facts.h), with
    // the numbers that decided it; unset, it holds (the viewer does not read charts).
    StepClaim f{"", 1, parseClaim("chart: pcf-gather 5x5: acne falls as the bias grows")};
    EXPECT_TRUE(isChartClaim(f));
    EXPECT_EQ(chartFactOf(f), "pcf-gather 5x5: acne falls as the bias grows");
    EXPECT_EQ(chartFactOf(c), "");  // an order is not a fact
    EXPECT_TRUE(claimHolds(f, t, StepContext{}, world));
    world.chartFact = [&](const std::string& fact, std::string* why) {
        asked = fact;
        *why = "acne 90% at bias 0.0005, 90% at bias 0.064";
        return false;
    };
    std::string why;
    EXPECT_FALSE(claimHolds(f, t, StepContext{}, world, &why));
    EXPECT_EQ(asked, "pcf-gather 5x5: acne falls as the bias grows");
    EXPECT_EQ(why, "acne 90% at bias 0.0005, 90% at bias 0.064");
}

// `flickers` reads the step's flicker trace, not the trace of the still frame: it holds when the
// curve jumps by FLICKER_JUMP or more between two consecutive frames (nearest's 0 <-> 1), not for
// a filter's creep of small steps, a flat line, or a frame whose point is on no receiver.
TEST(LessonClaims, FlickersReadsTheStepsFlickerTrace) {
    Trace t = bilinearTrace();
    StepClaim c{"flickers", 1, parseClaim("flickers")};
    EXPECT_TRUE(isMotionClaim(c));
    EXPECT_FALSE(isChartClaim(c));
    EXPECT_FALSE(isMotionClaim(StepClaim{"lit", 1, parseClaim("lit")}));
    ClaimWorld world;
    EXPECT_TRUE(claimHolds(c, t, StepContext{}, world));  // unset: the viewer plays the frames
    std::vector<float> curve;
    world.flickerCurve = [&]() { return std::variant<std::vector<float>, std::string>(curve); };
    std::string why;
    curve = {1.0f, 1.0f, 1.0f, 0.0f, 0.0f};  // a hard edge crosses the point at frame 3
    EXPECT_TRUE(claimHolds(c, t, StepContext{}, world, &why));
    EXPECT_NE(why.find("largest change between two frames 1 (frame 2 to 3) over 5 frames"),
              std::string::npos)
        << why;
    curve = {0.25f, 0.28125f, 0.3125f, 0.34375f, 0.375f, 0.25f + FLICKER_JUMP - 0.001f};  // creep
    EXPECT_FALSE(claimHolds(c, t, StepContext{}, world, &why));
    curve = {0.25f, 0.25f + FLICKER_JUMP};  // exactly the jump
    EXPECT_TRUE(claimHolds(c, t, StepContext{}, world));
    curve = {1.0f, 1.0f, 1.0f};  // flat: the point never flickers
    EXPECT_FALSE(claimHolds(c, t, StepContext{}, world, &why));
    EXPECT_NE(why.find("largest change between two frames 0 over 3 frames"), std::string::npos)
        << why;
    curve = {1.0f, -1.0f, 0.0f};  // off every receiver in frame 1
    EXPECT_FALSE(claimHolds(c, t, StepContext{}, world, &why));
    EXPECT_EQ(why, "frame 1: the point is on no receiver");
    world.flickerCurve = []() {
        return std::variant<std::vector<float>, std::string>(std::string("no sweep"));
    };
    EXPECT_FALSE(claimHolds(c, t, StepContext{}, world, &why));
    EXPECT_EQ(why, "no sweep");
}

// `steady` reads the same curve: it holds when no two consecutive frames differ by STEADY_CHANGE
// (1/512) or more, and not where the point is off every receiver.
TEST(LessonClaims, SteadyReadsTheStepsFlickerTrace) {
    Trace t = bilinearTrace();
    StepClaim c{"steady", 1, parseClaim("steady")};
    EXPECT_TRUE(isMotionClaim(c));
    ClaimWorld world;
    std::vector<float> curve;
    world.flickerCurve = [&]() { return std::variant<std::vector<float>, std::string>(curve); };
    std::string why;
    curve = {0.375f, 0.375f, 0.375f};
    EXPECT_TRUE(claimHolds(c, t, StepContext{}, world, &why));
    EXPECT_NE(why.find("largest change between two frames 0 over 3 frames"), std::string::npos)
        << why;
    curve = {0.375f, 0.375f + 0.5f * STEADY_CHANGE, 0.375f};  // under a quarter grey level
    EXPECT_TRUE(claimHolds(c, t, StepContext{}, world));
    curve = {0.375f, 0.375f, 0.375f + STEADY_CHANGE};  // a creep of 1/512 is a change
    EXPECT_FALSE(claimHolds(c, t, StepContext{}, world, &why));
    curve = {0.0f, 1.0f, 0.0f};
    EXPECT_FALSE(claimHolds(c, t, StepContext{}, world));
    curve = {0.5f, -1.0f, 0.5f};
    EXPECT_FALSE(claimHolds(c, t, StepContext{}, world, &why));
    EXPECT_EQ(why, "frame 1: the point is on no receiver");
}

TEST(LessonClaims, BadClaimsAreRefusedWithTheReason) {
    auto problem = [](const std::string& text) {
        try {
            parseClaim(text);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(problem("{taps} is 4").find("no comparison"), std::string::npos);
    EXPECT_NE(problem("{frac.z} = 1").find("unknown placeholder {frac.z}"), std::string::npos);
    EXPECT_NE(problem("{method} = 1").find("a word, not a number"), std::string::npos);
    EXPECT_NE(problem("{frac.x} ~ 0.2").find("+-"), std::string::npos);
    EXPECT_NE(problem("({taps} = 4").find("no )"), std::string::npos);
    EXPECT_NE(problem("taps = 4").find("braces"), std::string::npos);
    EXPECT_NE(problem("bits 10a1").find("bits"), std::string::npos);
    EXPECT_NE(problem("chart:  ").find("says nothing"), std::string::npos);
    // Numbers are finite: "inf" and "nan" read as doubles, but no claim means them.
    EXPECT_NE(problem("{visibility} ~ 1 +- inf").find("finite number >= 0"), std::string::npos);
    EXPECT_NE(problem("{visibility} ~ 1 +- nan").find("finite number >= 0"), std::string::npos);
    EXPECT_NE(problem("{visibility} < inf").find("'inf' is not a finite number"),
              std::string::npos);
    EXPECT_NE(problem("{visibility} != nan").find("'nan' is not a finite number"),
              std::string::npos);
}

// Parentheses and unary minus nest on the parser's stack: past MAX_CLAIM_NESTING levels the
// claim is refused, however deep (60,000 levels overflowed the stack).
TEST(LessonClaims, DeepNestingIsRefusedNotOverflowed) {
    auto nested = [](int n, bool parens) {
        if (!parens) return std::string(static_cast<size_t>(n), '-') + "1 = 1";
        return std::string(static_cast<size_t>(n), '(') + "1" +
               std::string(static_cast<size_t>(n), ')') + " = 1";
    };
    for (bool parens : {true, false}) {
        // At the limit the claim parses and computes (256 minuses cancel).
        EXPECT_TRUE(holds(nested(MAX_CLAIM_NESTING, parens), bilinearTrace()));
        for (int n : {MAX_CLAIM_NESTING + 1, 60000}) {
            try {
                parseClaim(nested(n, parens));
                ADD_FAILURE() << n << " levels parsed";
            } catch (const std::invalid_argument& e) {
                EXPECT_EQ(std::string(e.what()), "nested deeper than 256 levels of ( and unary -");
            }
        }
    }
}

// A claim's placeholders index the step's reads, weights and compare parts as its text's do: an
// index past them is refused when the lesson is read, at the claim's line.
TEST(LessonClaims, IndicesPastTheStepsReadsAreRefusedWhenRead) {
    auto error = [](const std::string& claims, const std::string& text = "x") {
        std::string lesson =
            "title = \"t\"\nscene = \"box-on-plane\"\n[settings]\n"
            "method = \"box2x2\"\n[[step]]\ntitle = \"s\"\nclaims = [" +
            claims + "]\ntext = \"" + text + "\"\n";
        try {
            parseLessonString(lesson, "claims.toml");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error("\"{weight[1,1]} > 0\""), "");
    EXPECT_EQ(error("\"{weight[99999,99999]} = 0\""),
              "claims.toml:7: step 1 claim \"{weight[99999,99999]} = 0\": weight[99999,99999] "
              "is past the 2 x 2 weights this step's method merges (I is 0..1, J is 0..1)");
    EXPECT_EQ(error("\"{part[0].visibility} = 1\""),
              "claims.toml:7: step 1 claim \"{part[0].visibility} = 1\": part[0] is past the 0 "
              "parts of this step's compare");
    EXPECT_EQ(error("\"{tap[4].depth} < 1\""),
              "claims.toml:7: step 1 claim \"{tap[4].depth} < 1\": tap[4] is past the 4 reads "
              "this step's method makes (K is 0..3)");
    // The text's weights are held to the same.
    EXPECT_EQ(error("\"lit\"", "w = {weight[2,0]}"),
              "claims.toml:8: step 1 text: weight[2,0] is past the 2 x 2 weights this step's "
              "method merges (I is 0..1, J is 0..1)");
}

}  // namespace
}  // namespace pcf
