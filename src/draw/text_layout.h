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

#include "draw/glyph_atlas.h"

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
// breaks before a "+". Linear in the text's length (widths of joined runs are added, not
// re-measured).
std::vector<std::string> wrapText(FontFace face, float pixelSize, std::string_view utf8,
                                  float maxWidth);
std::vector<std::string> wrapText(GlyphAtlas& atlas, std::string_view utf8, float maxWidth);

// A run of text in one face: prose (the block's own face) or a `code span` (monospace).
struct TextSpan {
    std::string text;
    bool mono = false;
    bool operator==(const TextSpan&) const = default;
};
using SpanLine = std::vector<TextSpan>;

// Splits one line of prose at its `code spans`: the text between a pair of backticks becomes a
// monospace span with every space kept and the backticks dropped; a backtick with no partner on
// the line stays as text. Adjacent pieces alternate between prose and code; empty pieces are left
// out ("``" is nothing).
SpanLine splitCodeSpans(std::string_view utf8);

// wrapText for prose with `code spans`: prose words are measured in `face`, each code span in the
// monospace face and kept whole on one line, glued to the prose it touches without a space
// ("(`snap = true`," is one unit). Lines carry no leading or trailing prose spaces; within a line
// same-face neighbours are merged, so spanLineWidth is the width the canvas draws. A unit wider
// than maxWidth alone is split between characters (then *spanSplit, when given, is set if that
// broke a code span), so the width promise still holds. Linear in the text's length.
std::vector<SpanLine> wrapSpans(FontFace face, float pixelSize, std::string_view utf8,
                                float maxWidth, bool* spanSplit = nullptr);

// The width of a wrapped line: each span measured in its face (prose in `face`), no kerning
// across a change of face (the canvas draws each span on its own).
float spanLineWidth(FontFace face, float pixelSize, const SpanLine& line);

// One line of at most maxWidth: the text itself when it fits, else as much of it as fits
// followed by "...".
std::string elideText(FontFace face, float pixelSize, std::string_view utf8, float maxWidth);

}  // namespace pcf
