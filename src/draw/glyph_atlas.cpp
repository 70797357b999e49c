#include "draw/glyph_atlas.h"

#include <ft2build.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include FT_FREETYPE_H

namespace pcf {

namespace {

// ASCII 32..126 and Latin-1 160..255 (é, °, ±, ², ·, ×, ÷, µ ...), then the teacher's symbols:
// ≤ ≥ ≠ ≈ − Σ ∑ √ ← ↑ → ↓ … • Δ α σ π ∞
constexpr char32_t SYMBOLS[] = {0x2264, 0x2265, 0x2260, 0x2248, 0x2212, 0x03A3, 0x2211,
                                0x221A, 0x2190, 0x2191, 0x2192, 0x2193, 0x2026, 0x2022,
                                0x0394, 0x03B1, 0x03C3, 0x03C0, 0x221E};

constexpr size_t PRELOADED_COUNT = (126 - 32 + 1) + (255 - 160 + 1) + std::size(SYMBOLS);

constexpr std::array<char32_t, PRELOADED_COUNT> makePreloaded() {
    std::array<char32_t, PRELOADED_COUNT> all{};
    size_t k = 0;
    for (char32_t c = 32; c <= 126; ++c) all[k++] = c;
    for (char32_t c = 160; c <= 255; ++c) all[k++] = c;
    for (char32_t c : SYMBOLS) all[k++] = c;
    return all;
}

constexpr std::array<char32_t, PRELOADED_COUNT> PRELOADED = makePreloaded();

// Glyphs are packed with this many empty texels between them, so the atlas reads well when
// written out as an image (texelFetch never reads across anyway).
constexpr int PADDING = 1;
constexpr int MAX_IMAGE_HEIGHT = 16384;

int nextPowerOfTwo(int v) {
    int p = 1;
    while (p < v) p *= 2;
    return p;
}

std::string freetypeError(const char* what, const FontFile& font, FT_Error error) {
    const char* message = FT_Error_String(error);
    return std::string("FreeType: ") + what + " " + font.path + " failed (" +
           (message != nullptr ? message : "error " + std::to_string(error)) + ")";
}

}  // namespace

std::span<const char32_t> preloadedCodepoints() { return PRELOADED; }

// One FT_Library per atlas: FreeType objects are not thread-safe across a library, and an atlas
// is small next to what this saves in locking.
struct GlyphAtlas::FreeType {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    ~FreeType() {
        if (face != nullptr) FT_Done_Face(face);
        if (library != nullptr) FT_Done_FreeType(library);
    }
};

GlyphAtlas::GlyphAtlas(const FontFile& font, float pixelSize)
    : mFont(font), mPixelSize(pixelSize), mFt(std::make_unique<FreeType>()) {
    if (!(pixelSize >= MIN_PIXEL_SIZE && pixelSize <= MAX_PIXEL_SIZE)) {
        throw std::invalid_argument("glyph atlas: pixel size must be in [1, " +
                                    std::to_string(static_cast<int>(MAX_PIXEL_SIZE)) + "], got " +
                                    std::to_string(pixelSize));
    }
    if (FT_Error e = FT_Init_FreeType(&mFt->library)) {
        throw std::runtime_error(freetypeError("initialising for", font, e));
    }
    if (FT_Error e = FT_New_Face(mFt->library, font.path.c_str(), font.index, &mFt->face)) {
        throw std::runtime_error(freetypeError("opening", font, e));
    }
    FT_Select_Charmap(mFt->face, FT_ENCODING_UNICODE);
    // 26.6 fixed point at 72 dpi: one point is one pixel, so this is the em size in pixels.
    FT_F26Dot6 size26 = std::lround(pixelSize * 64.0f);
    mPixelSize = static_cast<float>(size26) / 64.0f;
    if (FT_Error e = FT_Set_Char_Size(mFt->face, 0, size26, 72, 72)) {
        throw std::runtime_error(freetypeError("sizing", font, e));
    }
    const FT_Size_Metrics& m = mFt->face->size->metrics;
    mMetrics.ascender = std::ceil(static_cast<float>(m.ascender) / 64.0f);
    mMetrics.descender = std::floor(static_cast<float>(m.descender) / 64.0f);
    mMetrics.lineHeight = std::max(std::round(static_cast<float>(m.height) / 64.0f),
                                   mMetrics.ascender - mMetrics.descender);
    mHasKerning = FT_HAS_KERNING(mFt->face);

    // Wide enough that the preloaded set packs into a roughly square image; the height grows.
    int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<float>(std::size(PRELOADED)))));
    int cell = static_cast<int>(std::ceil(mPixelSize * 0.75f)) + 2 * PADDING;
    mImageSize = {std::clamp(nextPowerOfTwo(cols * cell), 128, 4096), 32};
    mPixels.assign(static_cast<size_t>(mImageSize.x) * mImageSize.y, 0);
    mShelfPos = {PADDING, PADDING};

    std::lock_guard lock(mMutex);
    for (char32_t c : PRELOADED) mGlyphs.emplace(c, rasterise(c));
}

GlyphAtlas::~GlyphAtlas() = default;

glm::ivec2 GlyphAtlas::allocate(glm::ivec2 size) {
    if (size.x <= 0 || size.y <= 0) return {0, 0};
    if (size.x + 2 * PADDING > mImageSize.x) {
        throw std::runtime_error("glyph atlas: a " + std::to_string(size.x) +
                                 " px wide glyph does not fit a " + std::to_string(mImageSize.x) +
                                 " px atlas");
    }
    if (mShelfPos.x + size.x + PADDING > mImageSize.x) {
        mShelfPos = {PADDING, mShelfPos.y + mShelfHeight + PADDING};
        mShelfHeight = 0;
    }
    int needed = mShelfPos.y + size.y + PADDING;
    if (needed > mImageSize.y) {
        int height = mImageSize.y;
        while (height < needed) height *= 2;
        if (height > MAX_IMAGE_HEIGHT) {
            throw std::runtime_error("glyph atlas of " + mFont.path + " at " +
                                     std::to_string(mPixelSize) + " px is full");
        }
        // Rows are top-down and the width stays, so growing only appends rows.
        mImageSize.y = height;
        mPixels.resize(static_cast<size_t>(mImageSize.x) * mImageSize.y, 0);
    }
    glm::ivec2 pos = mShelfPos;
    mShelfPos.x += size.x + PADDING;
    mShelfHeight = std::max(mShelfHeight, size.y);
    return pos;
}

Glyph GlyphAtlas::rasterise(char32_t codepoint) {
    FT_Face face = mFt->face;
    Glyph g;
    g.codepoint = codepoint;
    g.glyphIndex = FT_Get_Char_Index(face, codepoint);
    // Light hinting snaps outlines vertically only: stems and bars (the '=' of a formula, the
    // top of an '8') land on whole pixel rows, while shapes keep their designed widths.
    FT_Int32 flags = FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT | FT_LOAD_NO_BITMAP;
    if (FT_Load_Glyph(face, g.glyphIndex, flags) != 0) {
        g.glyphIndex = 0;
        if (FT_Load_Glyph(face, 0, flags) != 0) {
            g.advance = std::round(mPixelSize * 0.5f);
            return g;
        }
    }
    FT_GlyphSlot slot = face->glyph;
    const FT_Bitmap& bitmap = slot->bitmap;
    g.advance = static_cast<float>(slot->advance.x) / 64.0f;
    g.bearing = {slot->bitmap_left, slot->bitmap_top};
    g.size = {static_cast<int>(bitmap.width), static_cast<int>(bitmap.rows)};
    if (bitmap.pixel_mode != FT_PIXEL_MODE_GRAY) g.size = {0, 0};
    g.atlasPos = allocate(g.size);
    for (int row = 0; row < g.size.y; ++row) {
        // pitch < 0 means the rows are stored bottom-up.
        const uint8_t* src =
            bitmap.pitch >= 0
                ? bitmap.buffer + static_cast<ptrdiff_t>(row) * bitmap.pitch
                : bitmap.buffer + static_cast<ptrdiff_t>(g.size.y - 1 - row) * -bitmap.pitch;
        uint8_t* dst =
            mPixels.data() + static_cast<size_t>(g.atlasPos.y + row) * mImageSize.x + g.atlasPos.x;
        std::memcpy(dst, src, static_cast<size_t>(g.size.x));
    }
    ++mVersion;
    return g;
}

Glyph GlyphAtlas::glyph(char32_t codepoint) {
    std::lock_guard lock(mMutex);
    auto it = mGlyphs.find(codepoint);
    if (it != mGlyphs.end()) return it->second;
    return mGlyphs.emplace(codepoint, rasterise(codepoint)).first->second;
}

bool GlyphAtlas::hasGlyph(char32_t codepoint) const {
    std::lock_guard lock(mMutex);
    return FT_Get_Char_Index(mFt->face, codepoint) != 0;
}

float GlyphAtlas::kerning(uint32_t leftGlyphIndex, uint32_t rightGlyphIndex) const {
    if (!mHasKerning || leftGlyphIndex == 0 || rightGlyphIndex == 0) return 0.0f;
    std::lock_guard lock(mMutex);
    FT_Vector delta{0, 0};
    // FT_KERNING_DEFAULT: scaled and grid-fitted, so pen origins stay on whole pixels.
    if (FT_Get_Kerning(mFt->face, leftGlyphIndex, rightGlyphIndex, FT_KERNING_DEFAULT, &delta)) {
        return 0.0f;
    }
    return static_cast<float>(delta.x) / 64.0f;
}

uint64_t GlyphAtlas::version() const {
    std::lock_guard lock(mMutex);
    return mVersion;
}

GlyphAtlas::Image GlyphAtlas::image() const {
    std::lock_guard lock(mMutex);
    return Image{mImageSize, mPixels, mVersion};
}

size_t GlyphAtlas::glyphCount() const {
    std::lock_guard lock(mMutex);
    return mGlyphs.size();
}

GlyphAtlas& glyphAtlas(FontFace face, float pixelSize) {
    static std::mutex mutex;
    static std::map<std::pair<int, long>, std::unique_ptr<GlyphAtlas>> atlases;
    long size26 = std::isfinite(pixelSize) ? std::lround(pixelSize * 64.0f) : -1;
    std::lock_guard lock(mutex);
    std::unique_ptr<GlyphAtlas>& slot = atlases[{static_cast<int>(face), size26}];
    if (!slot) {
        try {
            slot = std::make_unique<GlyphAtlas>(findFontFile(face), pixelSize);
        } catch (...) {
            atlases.erase({static_cast<int>(face), size26});
            throw;
        }
    }
    return *slot;
}

}  // namespace pcf
