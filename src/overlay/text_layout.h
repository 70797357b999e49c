// text_layout.h: where each glyph of a string goes, how big a string is, and how a paragraph
// wraps into lines of a given width. No GL: the canvas draws what layoutText places.
//
// Coordinates are pixels with the origin at the TOP-LEFT of the first line's box, y down (the
// canvas's convention). Line k's box spans y in [k * lineHeight, (k + 1) * lineHeight); its
// baseline is at k * lineHeight + ascender. '\n' starts a new line.
//
// Every glyph's bitmap lands on whole pixels: the pen advances in (hinted, whole-pixel) advances
// plus kerning, and each pen position is rounded before the bearing is added. This, with a
// whole-pixel text origin, is what keeps text crisp (see glyph_atlas.h).
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "overlay/glyph_atlas.h"

namespace pcf {

// UTF-8 -> codepoints. Malformed bytes (stray continuation, overlong or truncated sequence,
// surrogate, > U+10FFFF) each become U+FFFD, so any input can be drawn.
std::u32string decodeUtf8(std::string_view utf8);

struct PlacedGlyph {
    Glyph glyph;
    glm::ivec2 topLeft{0, 0};  // bitmap's top-left pixel, relative to the layout origin
    int line = 0;
};

struct TextLayout {
    std::vector<PlacedGlyph> glyphs;  // drawable glyphs only (spaces take no quad)
    std::vector<float> lineWidths;    // pen advance of each line, pixels
    glm::vec2 size{0.0f, 0.0f};       // widest line x (lines * lineHeight); an empty string is
                                      // one empty line: (0, lineHeight)
    FontMetrics metrics;
};

TextLayout layoutText(GlyphAtlas& atlas, std::string_view utf8);

// The size layoutText gives: (width of the widest line, lines * line height), pixels.
glm::vec2 measureText(FontFace face, float pixelSize, std::string_view utf8);
FontMetrics fontMetrics(FontFace face, float pixelSize);

// Greedy word wrap for paragraphs of explanation: breaks at spaces so that each line measures
// <= maxWidth; '\n' forces a break (an empty line stays, as a paragraph gap); runs of spaces
// between words collapse to one. A word wider than maxWidth alone is split between characters,
// so the width promise holds for every line (one character always goes on a line, even when
// it alone is wider). Lines carry no leading or trailing spaces. A lone operator word ("-", "+",
// "=", "*", "/", "x", "<=", ...) stays on the line of the word after it, and of the word before
// it when that word is not already part of such a group: "1 - g" never breaks, and a long sum
// breaks before a "+". Linear in the text's length (widths of joined runs are added, not re-measured).
std::vector<std::string> wrapText(FontFace face, float pixelSize, std::string_view utf8,
                                  float maxWidth);
std::vector<std::string> wrapText(GlyphAtlas& atlas, std::string_view utf8, float maxWidth);

// One line of at most maxWidth: the text itself when it fits, else as much of it as fits
// followed by "...".
std::string elideText(FontFace face, float pixelSize, std::string_view utf8, float maxWidth);

}  // namespace pcf
