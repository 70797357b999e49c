// The glyph atlas: metrics for what the inspector writes, rasterised at the exact size asked.
#include "draw/glyph_atlas.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace pcf {
namespace {

// Every glyph bitmap lies inside the atlas image and carries some ink.
void expectInkInsideImage(GlyphAtlas& atlas, const Glyph& g) {
    GlyphAtlas::Image image = atlas.image();
    ASSERT_GE(g.atlasPos.x, 0);
    ASSERT_GE(g.atlasPos.y, 0);
    ASSERT_LE(g.atlasPos.x + g.size.x, image.size.x);
    ASSERT_LE(g.atlasPos.y + g.size.y, image.size.y);
    int ink = 0;
    for (int y = 0; y < g.size.y; ++y) {
        for (int x = 0; x < g.size.x; ++x) {
            ink += image.pixels[static_cast<size_t>(g.atlasPos.y + y) * image.size.x +
                                g.atlasPos.x + x];
        }
    }
    EXPECT_GT(ink, 0) << "codepoint U+" << std::hex << static_cast<uint32_t>(g.codepoint);
}

TEST(GlyphAtlas, HasMetricsForWhatTheInspectorWrites) {
    for (FontFace face : {FontFace::Sans, FontFace::Mono}) {
        GlyphAtlas& atlas = glyphAtlas(face, 20.0f);
        std::u32string chars = U"0123456789=()≤≥×·°Σ√←→↑↓∑é";
        for (char32_t c = U'A'; c <= U'z'; ++c) chars += c;
        for (char32_t c : chars) {
            SCOPED_TRACE(::testing::Message() << "U+" << std::hex << static_cast<uint32_t>(c)
                                              << (face == FontFace::Mono ? " mono" : " sans"));
            EXPECT_TRUE(atlas.hasGlyph(c));
            Glyph g = atlas.glyph(c);
            EXPECT_EQ(g.codepoint, c);
            EXPECT_NE(g.glyphIndex, 0u);
            EXPECT_GT(g.advance, 0.0f);
            EXPECT_GT(g.size.x, 0);
            EXPECT_GT(g.size.y, 0);
            expectInkInsideImage(atlas, g);
        }
    }
}

TEST(GlyphAtlas, SpaceHasAnAdvanceAndNoBitmap) {
    Glyph g = glyphAtlas(FontFace::Sans, 20.0f).glyph(U' ');
    EXPECT_GT(g.advance, 0.0f);
    EXPECT_EQ(g.size, glm::ivec2(0, 0));
}

TEST(GlyphAtlas, MetricsAreWholePixelsAndScaleWithTheSize) {
    FontMetrics m16 = glyphAtlas(FontFace::Sans, 16.0f).metrics();
    FontMetrics m32 = glyphAtlas(FontFace::Sans, 32.0f).metrics();
    for (const FontMetrics& m : {m16, m32}) {
        EXPECT_GT(m.ascender, 0.0f);
        EXPECT_LT(m.descender, 0.0f);
        EXPECT_GE(m.lineHeight, m.ascender - m.descender);
        EXPECT_EQ(m.ascender, std::round(m.ascender));
        EXPECT_EQ(m.lineHeight, std::round(m.lineHeight));
    }
    // DejaVu Sans: line height 1.164 em.
    EXPECT_NEAR(m16.lineHeight, 19.0f, 1.0f);
    EXPECT_NEAR(m32.lineHeight, 37.0f, 1.0f);
}

// Rasterised at the size asked, not scaled from one fixed size: the cap height of 'H' (0.729 em
// in DejaVu Sans) follows the pixel size (hinting moves an edge by at most a pixel and an
// antialiased edge can add a partial row).
TEST(GlyphAtlas, RasterisesAtTheExactPixelSize) {
    for (float size : {9.0f, 12.0f, 16.0f, 23.0f, 32.0f, 48.0f, 96.0f}) {
        GlyphAtlas& atlas = glyphAtlas(FontFace::Sans, size);
        EXPECT_EQ(atlas.pixelSize(), size);
        Glyph h = atlas.glyph(U'H');
        EXPECT_NEAR(h.size.y, 0.729f * size, 1.5f) << size << " px";
        EXPECT_EQ(h.bearing.y, h.size.y) << "'H' sits on the baseline";
    }
}

TEST(GlyphAtlas, IsCachedPerFaceAndSize) {
    EXPECT_EQ(&glyphAtlas(FontFace::Sans, 18.0f), &glyphAtlas(FontFace::Sans, 18.0f));
    EXPECT_NE(&glyphAtlas(FontFace::Sans, 18.0f), &glyphAtlas(FontFace::Sans, 19.0f));
    EXPECT_NE(&glyphAtlas(FontFace::Sans, 18.0f), &glyphAtlas(FontFace::Mono, 18.0f));
    EXPECT_EQ(glyphAtlas(FontFace::Mono, 18.0f).font().family, "DejaVu Sans Mono");
}

TEST(GlyphAtlas, MonoAdvancesAreAllEqual) {
    GlyphAtlas& atlas = glyphAtlas(FontFace::Mono, 17.0f);
    float advance = atlas.glyph(U'0').advance;
    EXPECT_GT(advance, 0.0f);
    for (char32_t c = 32; c < 127; ++c) EXPECT_EQ(atlas.glyph(c).advance, advance) << char(c);
}

TEST(GlyphAtlas, AdvancesAreWholePixels) {
    GlyphAtlas& atlas = glyphAtlas(FontFace::Sans, 15.0f);
    for (char32_t c = 32; c < 127; ++c) {
        float a = atlas.glyph(c).advance;
        EXPECT_EQ(a, std::round(a)) << char(c);
    }
}

TEST(GlyphAtlas, RasterisesOtherCodepointsOnFirstUse) {
    GlyphAtlas& atlas = glyphAtlas(FontFace::Sans, 21.0f);
    size_t count = atlas.glyphCount();
    uint64_t version = atlas.version();
    Glyph omega = atlas.glyph(U'Ω');
    EXPECT_NE(omega.glyphIndex, 0u);
    EXPECT_GT(omega.size.x, 0);
    EXPECT_EQ(atlas.glyphCount(), count + 1);
    EXPECT_GT(atlas.version(), version);
    expectInkInsideImage(atlas, omega);
    // Earlier glyphs keep their place when the atlas grows.
    Glyph a = atlas.glyph(U'a');
    for (char32_t c = 0x0400; c < 0x0500; ++c) atlas.glyph(c);  // all of Cyrillic
    Glyph again = atlas.glyph(U'a');
    EXPECT_EQ(again.atlasPos, a.atlasPos);
    expectInkInsideImage(atlas, again);
}

TEST(GlyphAtlas, MissingCodepointsGetTheMissingGlyphBox) {
    GlyphAtlas& atlas = glyphAtlas(FontFace::Sans, 20.0f);
    char32_t han = 0x4E2D;  // CJK: not in DejaVu
    EXPECT_FALSE(atlas.hasGlyph(han));
    Glyph g = atlas.glyph(han);
    EXPECT_EQ(g.glyphIndex, 0u);
    EXPECT_GT(g.advance, 0.0f);
    EXPECT_GT(g.size.x, 0);
}

TEST(GlyphAtlas, KernsPairsWhenTheFaceHasKerning) {
    GlyphAtlas& atlas = glyphAtlas(FontFace::Sans, 40.0f);
    ASSERT_TRUE(atlas.hasKerning());
    float av = atlas.kerning(atlas.glyph(U'A').glyphIndex, atlas.glyph(U'V').glyphIndex);
    EXPECT_LT(av, 0.0f);
    EXPECT_EQ(av, std::round(av));
    EXPECT_EQ(atlas.kerning(0, atlas.glyph(U'V').glyphIndex), 0.0f);
}

TEST(GlyphAtlas, RejectsSizesOutOfRange) {
    EXPECT_THROW(glyphAtlas(FontFace::Sans, 0.0f), std::invalid_argument);
    EXPECT_THROW(glyphAtlas(FontFace::Sans, -3.0f), std::invalid_argument);
    EXPECT_THROW(glyphAtlas(FontFace::Sans, 0.5f), std::invalid_argument);
    EXPECT_THROW(glyphAtlas(FontFace::Sans, 1000.0f), std::invalid_argument);
    EXPECT_THROW(glyphAtlas(FontFace::Sans, std::nanf("")), std::invalid_argument);
    EXPECT_NO_THROW(glyphAtlas(FontFace::Sans, 1.0f));
}

TEST(GlyphAtlas, PreloadsAsciiLatin1AndTheTeachersSymbols) {
    auto pre = preloadedCodepoints();
    auto has = [&](char32_t c) { return std::find(pre.begin(), pre.end(), c) != pre.end(); };
    for (char32_t c = 32; c < 127; ++c) EXPECT_TRUE(has(c));
    for (char32_t c = 0xA0; c <= 0xFF; ++c) EXPECT_TRUE(has(c));
    for (char32_t c : std::u32string(U"≤≥×·°Σ√←→↑↓∑é")) EXPECT_TRUE(has(c));
    EXPECT_GE(glyphAtlas(FontFace::Sans, 22.0f).glyphCount(), pre.size());
}

}  // namespace
}  // namespace pcf
