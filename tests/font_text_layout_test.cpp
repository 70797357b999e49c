// Text layout: UTF-8, measuring, whole-pixel placement and word wrap.
#include <gtest/gtest.h>

#include <string>

#include "overlay/text_layout.h"

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

}  // namespace
}  // namespace pcf
