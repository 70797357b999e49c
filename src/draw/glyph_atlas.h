// glyph_atlas.h: glyphs rasterised by FreeType at one exact pixel size, packed into one
// single-channel image that the canvas uploads as a GL_R8 texture.
//
// Crisp text at every size comes from three rules kept together here and in text_layout.h:
//   - each (face, pixel size) has its own atlas, rasterised at that size (never a scaled atlas);
//   - glyph bitmaps sit at whole-pixel offsets from a whole-pixel pen origin (bearing below);
//   - the canvas reads the atlas with texelFetch, one texel per screen pixel (no filtering).
//
// The atlas is CPU-only (no GL): measuring and wrapping text need no context, and one atlas
// serves every context and Canvas of the process; each Canvas keeps its own texture copy.
// Atlas image rows are top-down: row 0 is the top of the image, and a glyph's bitmap row 0 (its
// top) is image row atlasPos.y. The canvas uploads memory row r as texel row r and fetches with
// the same integers, so no flip is involved anywhere.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <mutex>
#include <span>
#include <unordered_map>
#include <vector>

#include "draw/font.h"

namespace pcf {

struct Glyph {
    char32_t codepoint = 0;
    uint32_t glyphIndex = 0;    // FreeType's index in the face (0 = the face's "missing" glyph)
    float advance = 0.0f;       // pixels the pen moves right after this glyph (whole pixels with
                                // hinting)
    glm::ivec2 bearing{0, 0};   // pen origin on the baseline -> bitmap's top-left corner, pixels:
                                // x to the right, y UP (FreeType's bitmap_left, bitmap_top)
    glm::ivec2 size{0, 0};      // bitmap width, height in pixels (0 x 0 for a space)
    glm::ivec2 atlasPos{0, 0};  // bitmap's top-left texel in the atlas image
};

// Vertical metrics of one (face, pixel size), whole pixels.
struct FontMetrics {
    float ascender = 0.0f;    // baseline -> top of the line box (positive)
    float descender = 0.0f;   // baseline -> bottom of the line box (negative)
    float lineHeight = 0.0f;  // baseline to baseline; >= ascender - descender
};

// The codepoints every atlas rasterises up front: ASCII 32..126, Latin-1 160..255 (é, °, ×, ·,
// ±, ²...) and the symbols the lessons use (≤ ≥ ≠ ≈ − Σ ∑ √ ← ↑ → ↓ … • Δ α σ π ∞). Others
// are rasterised on first use.
std::span<const char32_t> preloadedCodepoints();

class GlyphAtlas {
  public:
    // Opens the font and rasterises preloadedCodepoints() at `pixelSize` (the em size in
    // pixels, in [MIN_PIXEL_SIZE, MAX_PIXEL_SIZE]). Throws std::runtime_error when FreeType cannot
    // open the file and std::invalid_argument for a bad size.
    GlyphAtlas(const FontFile& font, float pixelSize);
    ~GlyphAtlas();
    GlyphAtlas(const GlyphAtlas&) = delete;
    GlyphAtlas& operator=(const GlyphAtlas&) = delete;

    static constexpr float MIN_PIXEL_SIZE = 1.0f;
    static constexpr float MAX_PIXEL_SIZE = 512.0f;

    float pixelSize() const { return mPixelSize; }
    const FontMetrics& metrics() const { return mMetrics; }
    const FontFile& font() const { return mFont; }

    // The glyph of `codepoint`, rasterised now when it was not yet. A codepoint the face lacks
    // gets the face's missing-glyph box (glyphIndex 0), which shows the gap honestly.
    // Thread-safe, like every member below.
    Glyph glyph(char32_t codepoint);
    // Whether the face has its own glyph for `codepoint`.
    bool hasGlyph(char32_t codepoint) const;
    // Horizontal kerning between two glyph indices in pixels (grid-fitted: whole pixels); 0 when
    // the face has no kerning table.
    float kerning(uint32_t leftGlyphIndex, uint32_t rightGlyphIndex) const;
    bool hasKerning() const { return mHasKerning; }

    // Grows whenever a glyph is added: a Canvas re-uploads its texture when this changes.
    uint64_t version() const;
    // The atlas image: size.x * size.y bytes of coverage (0..255), rows top-down.
    struct Image {
        glm::ivec2 size{0, 0};
        std::vector<uint8_t> pixels;
        uint64_t version = 0;
    };
    Image image() const;
    size_t glyphCount() const;

  private:
    struct FreeType;
    Glyph rasterise(char32_t codepoint);   // mMutex held
    glm::ivec2 allocate(glm::ivec2 size);  // mMutex held; grows the image as needed

    FontFile mFont;
    float mPixelSize;
    FontMetrics mMetrics;
    bool mHasKerning = false;
    std::unique_ptr<FreeType> mFt;

    mutable std::mutex mMutex;
    std::unordered_map<char32_t, Glyph> mGlyphs;
    glm::ivec2 mImageSize{0, 0};
    std::vector<uint8_t> mPixels;
    glm::ivec2 mShelfPos{0, 0};  // where the next glyph goes on the current shelf
    int mShelfHeight = 0;
    uint64_t mVersion = 0;
};

// The process-wide atlas of (face, pixelSize), made on first use and kept until exit.
// Pixel sizes are told apart to 1/64 px (FreeType's 26.6 units). Thread-safe.
// Throws as findFontFile(face) and the GlyphAtlas constructor.
GlyphAtlas& glyphAtlas(FontFace face, float pixelSize);

}  // namespace pcf
