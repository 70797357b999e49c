// Text layout: UTF-8, measuring, whole-pixel placement and word wrap.
#include "draw/text_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace pcf {
namespace {

const char* PARAGRAPH =
    "Percentage closer filtering compares the receiver depth with every texel of the "
    "neighbourhood first, and only then filters the results: averaging depths first would "
    "blur the occluder, not the shadow. Each tap gives 0 or 1; the weights blend them.";

TEST(TextLayout, DecodesUtf8) {
    EXPECT_EQ(decodeUtf8("a≤é→Σ"), std::u32string(U"a≤é→Σ"));
    EXPECT_EQ(decodeUtf8(""), std::u32string());
    EXPECT_EQ(decodeUtf8("\xF0\x9F\x98\x80"), std::u32string(U"\U0001F600"));
}

TEST(TextLayout, MalformedUtf8BecomesReplacementCharacters) {
    EXPECT_EQ(decodeUtf8("a\x80z"), std::u32string(U"a\uFFFDz"));          // stray continuation
    EXPECT_EQ(decodeUtf8("a\xE2\x89"), std::u32string(U"a\uFFFD\uFFFD"));  // truncated
    EXPECT_EQ(decodeUtf8("\xC0\xAF"), std::u32string(U"\uFFFD\uFFFD"));    // overlong '/'
    EXPECT_EQ(decodeUtf8("\xED\xA0\x80"), std::u32string(U"\uFFFD\uFFFD\uFFFD"));  // surrogate
    EXPECT_EQ(decodeUtf8("\xFF"), std::u32string(U"\uFFFD"));
}

TEST(TextLayout, MeasureGrowsWithThePixelSize) {
    glm::vec2 small = measureText(FontFace::Mono, 16.0f, "0.8");
    glm::vec2 large = measureText(FontFace::Mono, 32.0f, "0.8");
    EXPECT_GT(small.x, 0.0f);
    EXPECT_GT(large.x, small.x);
    EXPECT_NEAR(large.x / small.x, 2.0f, 0.15f);
    EXPECT_NEAR(large.y / small.y, 2.0f, 0.15f);
    glm::vec2 sansSmall = measureText(FontFace::Sans, 16.0f, "0.8");
    glm::vec2 sansLarge = measureText(FontFace::Sans, 32.0f, "0.8");
    EXPECT_GT(sansLarge.x, sansSmall.x);
    EXPECT_NEAR(sansLarge.x / sansSmall.x, 2.0f, 0.2f);
}

TEST(TextLayout, MeasureIsTheSumOfAdvancesAndLines) {
    GlyphAtlas& mono = glyphAtlas(FontFace::Mono, 20.0f);
    float advance = mono.glyph(U'0').advance;
    float lineHeight = mono.metrics().lineHeight;
    EXPECT_EQ(measureText(FontFace::Mono, 20.0f, "0.25"), glm::vec2(4 * advance, lineHeight));
    EXPECT_EQ(measureText(FontFace::Mono, 20.0f, "ab\nabcde\nc"),
              glm::vec2(5 * advance, 3 * lineHeight));
    EXPECT_EQ(measureText(FontFace::Mono, 20.0f, ""), glm::vec2(0, lineHeight));
    EXPECT_EQ(fontMetrics(FontFace::Mono, 20.0f).lineHeight, lineHeight);
}

TEST(TextLayout, LayoutAgreesWithMeasure) {
    for (const char* s : {"visibility = 0.75", "w ≤ 1\nΣw = 1", "AVATAR", ""}) {
        GlyphAtlas& atlas = glyphAtlas(FontFace::Sans, 19.0f);
        EXPECT_EQ(layoutText(atlas, s).size, measureText(FontFace::Sans, 19.0f, s)) << s;
    }
}

TEST(TextLayout, PlacesGlyphsLeftToRightOnTheirBaseline) {
    GlyphAtlas& atlas = glyphAtlas(FontFace::Sans, 24.0f);
    TextLayout l = layoutText(atlas, "HH\nH");
    ASSERT_EQ(l.glyphs.size(), 3u);
    ASSERT_EQ(l.lineWidths.size(), 2u);
    const FontMetrics& m = l.metrics;
    // 'H' sits on the baseline: its bitmap bottom is the baseline.
    EXPECT_EQ(l.glyphs[0].topLeft.y + l.glyphs[0].glyph.size.y, static_cast<int>(m.ascender));
    EXPECT_EQ(l.glyphs[1].topLeft.y, l.glyphs[0].topLeft.y);
    EXPECT_EQ(l.glyphs[1].topLeft.x - l.glyphs[0].topLeft.x,
              static_cast<int>(atlas.glyph(U'H').advance));
    EXPECT_EQ(l.glyphs[2].line, 1);
    EXPECT_EQ(l.glyphs[2].topLeft.y - l.glyphs[0].topLeft.y, static_cast<int>(m.lineHeight));
    EXPECT_EQ(l.glyphs[2].topLeft.x, l.glyphs[0].topLeft.x);
}

TEST(TextLayout, KerningTightensPairs) {
    GlyphAtlas& atlas = glyphAtlas(FontFace::Sans, 40.0f);
    float a = atlas.glyph(U'A').advance;
    float v = atlas.glyph(U'V').advance;
    EXPECT_LT(measureText(FontFace::Sans, 40.0f, "AV").x, a + v);
}

TEST(TextLayout, WrapSplitsAtSpacesWithinTheWidth) {
    const float width = 300.0f;
    std::vector<std::string> lines = wrapText(FontFace::Sans, 16.0f, PARAGRAPH, width);
    ASSERT_GE(lines.size(), 3u);
    std::string joined;
    for (const std::string& line : lines) {
        EXPECT_LE(measureText(FontFace::Sans, 16.0f, line).x, width) << line;
        EXPECT_FALSE(line.empty());
        EXPECT_NE(line.front(), ' ');
        EXPECT_NE(line.back(), ' ');
        joined += (joined.empty() ? "" : " ") + line;
    }
    // Breaks only at spaces: the lines joined by spaces are the paragraph.
    EXPECT_EQ(joined, PARAGRAPH);
    // Greedy: no line could have taken the next line's first word.
    for (size_t k = 0; k + 1 < lines.size(); ++k) {
        std::string next = lines[k + 1].substr(0, lines[k + 1].find(' '));
        EXPECT_GT(measureText(FontFace::Sans, 16.0f, lines[k] + " " + next).x, width);
    }
}

TEST(TextLayout, ElideKeepsWhatFitsAndMarksTheCut) {
    const std::string title = "2. Lerp by the sub-texel position";
    float full = measureText(FontFace::Sans, 24.0f, title).x;
    EXPECT_EQ(elideText(FontFace::Sans, 24.0f, title, full + 1.0f), title);
    std::string cut = elideText(FontFace::Sans, 24.0f, title, full * 0.6f);
    EXPECT_LE(measureText(FontFace::Sans, 24.0f, cut).x, full * 0.6f) << cut;
    ASSERT_GT(cut.size(), 3u);
    EXPECT_EQ(cut.substr(cut.size() - 3), "...");
    EXPECT_EQ(title.rfind(cut.substr(0, cut.size() - 3), 0), 0u) << cut;  // a prefix
    // Multi-byte characters are dropped whole.
    std::string symbols = elideText(FontFace::Sans, 24.0f, "≤≤≤≤≤≤≤≤≤≤≤≤", 80.0f);
    EXPECT_EQ(decodeUtf8(symbols).find(U'\uFFFD'), std::u32string::npos) << symbols;
}

TEST(TextLayout, WrapKeepsHardBreaksAndParagraphGaps) {
    std::vector<std::string> lines =
        wrapText(FontFace::Sans, 16.0f, "first  line\n\nsecond\tparagraph", 1000.0f);
    EXPECT_EQ(lines, (std::vector<std::string>{"first line", "", "second paragraph"}));
}

TEST(TextLayout, WrapSplitsAWordWiderThanTheLine) {
    const float width = 60.0f;
    std::vector<std::string> lines =
        wrapText(FontFace::Mono, 16.0f, "ok 0123456789012345678901234567 ≤≤≤≤≤≤≤≤≤≤", width);
    ASSERT_GE(lines.size(), 4u);
    EXPECT_EQ(lines[0], "ok");
    std::string digits;
    for (const std::string& line : lines) {
        EXPECT_LE(measureText(FontFace::Mono, 16.0f, line).x, width) << line;
        if (line.find("≤") == std::string::npos && line != "ok") digits += line;
    }
    EXPECT_EQ(digits, "0123456789012345678901234567");
    // Multi-byte characters are never cut in half.
    for (const std::string& line : lines) {
        EXPECT_EQ(decodeUtf8(line).find(U'\uFFFD'), std::u32string::npos) << line;
    }
}

TEST(TextLayout, WrapOfEmptyTextIsOneEmptyLine) {
    EXPECT_EQ(wrapText(FontFace::Sans, 16.0f, "", 100.0f), std::vector<std::string>{""});
}

// `code spans` in prose: the backticks go, the text between them is a monospace span with its
// spaces kept; a backtick with no partner is text.
TEST(TextLayout, CodeSpansDropTheirBackticksAndKeepTheirSpaces) {
    SpanLine spans = splitCodeSpans("set `origin_shift  =  0.25` now");
    ASSERT_EQ(spans.size(), 3u);
    EXPECT_EQ(spans[0].text, "set ");
    EXPECT_FALSE(spans[0].mono);
    EXPECT_EQ(spans[1].text, "origin_shift  =  0.25");
    EXPECT_TRUE(spans[1].mono);
    EXPECT_EQ(spans[2].text, " now");
    EXPECT_FALSE(spans[2].mono);
    SpanLine odd = splitCodeSpans("a `b` c ` d");
    ASSERT_EQ(odd.size(), 3u);
    EXPECT_EQ(odd[2].text, " c ` d");
    EXPECT_FALSE(odd[2].mono);
    // Wrapped, the span keeps both double spaces (prose runs of spaces still collapse).
    std::vector<SpanLine> lines =
        wrapSpans(FontFace::Sans, 16.0f, "set   `origin_shift  =  0.25`   now", 1000.0f);
    ASSERT_EQ(lines.size(), 1u);
    ASSERT_EQ(lines[0].size(), 3u);
    EXPECT_EQ(lines[0][0].text, "set ");
    EXPECT_EQ(lines[0][1].text, "origin_shift  =  0.25");
    EXPECT_TRUE(lines[0][1].mono);
    EXPECT_EQ(lines[0][2].text, " now");
}

// A span is measured in the monospace face: the line's width is the prose in Sans plus the span in
// Mono, and a width that holds that sum (but not one pixel less) keeps it on one line.
TEST(TextLayout, CodeSpansAreMeasuredInMonospace) {
    const float px = 18.0f;
    const std::string text = "Press `origin_shift = 0.25` now";
    float sans =
        measureText(FontFace::Sans, px, "Press ").x + measureText(FontFace::Sans, px, " now").x;
    float mono = measureText(FontFace::Mono, px, "origin_shift = 0.25").x;
    EXPECT_NE(mono, measureText(FontFace::Sans, px, "origin_shift = 0.25").x);
    std::vector<SpanLine> one = wrapSpans(FontFace::Sans, px, text, sans + mono);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_FLOAT_EQ(spanLineWidth(FontFace::Sans, px, one[0]), sans + mono);
    std::vector<SpanLine> two = wrapSpans(FontFace::Sans, px, text, sans + mono - 1.0f);
    ASSERT_EQ(two.size(), 2u);
    // The break is at the space after the span, not inside it.
    ASSERT_EQ(two[0].size(), 2u);
    EXPECT_EQ(two[0][1].text, "origin_shift = 0.25");
    EXPECT_EQ(two[1], (SpanLine{{"now", false}}));
}

// Whatever the width, a span is never broken across lines (while it fits a line alone), every
// line keeps the width promise, and no backtick is left in the text.
TEST(TextLayout, WrapNeverBreaksACodeSpan) {
    const float px = 16.0f;
    const std::string text =
        "Now the grid has moved: `origin_shift = 0.25` slides it a quarter texel, and "
        "(`snap = true`, the S key) snaps it back; `pcfscope stability` measures both.";
    const std::vector<std::string> codes = {"origin_shift = 0.25", "snap = true",
                                            "pcfscope stability"};
    float widest = 0.0f;
    for (const std::string& c : codes)
        widest = std::max(widest, measureText(FontFace::Mono, px, c).x);
    for (float width = widest + 12.0f; width < 900.0f; width += 7.0f) {
        bool split = false;
        std::vector<SpanLine> lines = wrapSpans(FontFace::Sans, px, text, width, &split);
        EXPECT_FALSE(split) << width;
        std::vector<std::string> seen;
        std::string joined;
        for (const SpanLine& line : lines) {
            EXPECT_LE(spanLineWidth(FontFace::Sans, px, line), width);
            for (const TextSpan& sp : line) {
                EXPECT_EQ(sp.text.find('`'), std::string::npos) << sp.text;
                if (sp.mono) seen.push_back(sp.text);
                joined += sp.text;
            }
            joined += ' ';
        }
        EXPECT_EQ(seen, codes) << width;
        EXPECT_NE(joined.find("(snap = true,"), std::string::npos) << joined;
    }
    // A span wider than the whole line is split (said so), and the width promise still holds.
    bool split = false;
    std::vector<SpanLine> narrow = wrapSpans(FontFace::Sans, px, text, 60.0f, &split);
    EXPECT_TRUE(split);
    for (const SpanLine& line : narrow) EXPECT_LE(spanLineWidth(FontFace::Sans, px, line), 60.0f);
}

}  // namespace
}  // namespace pcf
