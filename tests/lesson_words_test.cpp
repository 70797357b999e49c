// The words a step types where a placeholder or a claim belongs (lesson/lesson_words.h), read
// against a lookup whose numbers are known: the example map's bilinear2x2 lookup with bits 1 0 in
// both rows at fx 0.399, visibility 0.601 (the penumbra), 2 of its 4 reads lit.
#include "lesson/lesson_words.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kernel/trace.h"

namespace pcf {
namespace {

Trace penumbraTrace() {
    // p.x = uv.x * 8 - 0.5 = 3.399: fx 0.399 over texels 3 (lit) and 4 (shadowed).
    return traceLookup(exampleShadowMap(), vec2(3.899f / 8.0f, 0.3875f), 0.5f, 0.5f,
                       makeParams(PCF_BILINEAR2X2, 3));
}

std::vector<WordProblem> problemsOf(const std::string& text) {
    return typedWordProblems(text, penumbraTrace(), StepContext{});
}

TEST(LessonWords, TheLookupIsTheOneTheTestsReadAgainst) {
    Trace tr = penumbraTrace();
    EXPECT_NEAR(tr.visibility, 0.601f, 1e-5f);
    ASSERT_EQ(tr.taps.size(), 4u);
    int lit = 0;
    for (const TapRecord& t : tr.taps) lit += t.lit >= 0.5f;
    EXPECT_EQ(lit, 2);
}

TEST(LessonWords, AStateAndANumberTheStepContradictsAreBothRefused) {
    std::string text = "Here the point is fully lit, visibility 1.";
    std::vector<WordProblem> p = problemsOf(text);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0].offset, text.find("fully lit"));
    EXPECT_NE(p[0].problem.find("\"fully lit\" is false here"), std::string::npos) << p[0].problem;
    // The claim to use instead: the state that holds.
    EXPECT_NE(p[0].problem.find("\"penumbra\""), std::string::npos) << p[0].problem;
    EXPECT_EQ(p[1].offset, text.find("visibility 1"));
    EXPECT_NE(p[1].problem.find("the step's visibility is 0.601"), std::string::npos)
        << p[1].problem;
    EXPECT_NE(p[1].problem.find("{visibility}"), std::string::npos) << p[1].problem;
}

TEST(LessonWords, ANumberTypedForAQuantityNamesItsPlaceholder) {
    for (const char* text :
         {"The answer is 0.601.", "so visibility = 0.601 here", "{lit_count} / {taps} = 0.601"}) {
        std::vector<WordProblem> p = problemsOf(text);
        ASSERT_EQ(p.size(), 1u) << text;
        EXPECT_EQ(p[0].offset, std::string(text).find(text[0] == 's' ? "visibility" : "0.601"))
            << text;
        // (1 - fx is 0.601 too: both are named.)
        EXPECT_NE(p[0].problem.find("{visibility}"), std::string::npos) << p[0].problem;
    }
    // fx to its last digit, and 1 - visibility.
    std::vector<WordProblem> fx = problemsOf("The fraction is 0.399 and the shadow 0.399.");
    ASSERT_EQ(fx.size(), 2u);
    EXPECT_NE(fx[0].problem.find("{frac.x}"), std::string::npos) << fx[0].problem;
    EXPECT_NE(fx[1].problem.find("{1-visibility}"), std::string::npos) << fx[1].problem;
    // Counts in "N of M": the reads that pass, and the reads.
    std::vector<WordProblem> counts = problemsOf("2 of the 4 reads pass.");
    ASSERT_EQ(counts.size(), 2u);
    EXPECT_NE(counts[0].problem.find("{lit_count}"), std::string::npos) << counts[0].problem;
    EXPECT_NE(counts[1].problem.find("{taps}"), std::string::npos) << counts[1].problem;
}

TEST(LessonWords, WordsThatStateNothingOfTheStepPass) {
    for (const char* text :
         {"visibility {visibility}: in the penumbra",  // true, with its placeholder
          "{lit_count} of {taps} are lit: {visibility}.", "this pixel is half in shadow.",
          "The worked example gives `1 - 0.399 = 0.601`.",  // a code span
          "the post's \"0.601\" is an amount of shadow",    // quoted
          "1 - 0.399 = 0.601, as the article says",         // arithmetic on typed numbers
          "p = uv * size - 0.601",                          // a formula's constant
          "it can answer 0, 0.25, 0.601, 0.75 or 1",        // a list of values
          "a visibility near 0.7 reads as grey",            // not the step's to 4 decimals
          "Texels that are lit pass the test; shadowed ones fail."}) {
        EXPECT_TRUE(problemsOf(text).empty()) << text << ": " << problemsOf(text).front().problem;
    }
}

TEST(LessonWords, APointsStateIsReadAsItsClaim) {
    for (const char* text : {"The point is lit.", "it stays in shadow", "this pixel is shadowed",
                             "visibility {visibility}: fully in shadow"}) {
        std::vector<WordProblem> p = problemsOf(text);
        ASSERT_EQ(p.size(), 1u) << text;
        EXPECT_NE(p[0].problem.find("in the penumbra"), std::string::npos) << p[0].problem;
    }
    EXPECT_TRUE(problemsOf("the point is in the penumbra").empty());
    EXPECT_TRUE(problemsOf("the point is partly lit").empty());
}

}  // namespace
}  // namespace pcf
