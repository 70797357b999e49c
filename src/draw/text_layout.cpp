#include "draw/text_layout.h"

#include <algorithm>
#include <cmath>

namespace pcf {

namespace {

constexpr char32_t REPLACEMENT = 0xFFFD;

// Decodes the codepoint starting at s[i] and moves i past it (one byte for malformed input).
char32_t decodeOne(std::string_view s, size_t& i) {
    auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
    unsigned char lead = byte(i);
    if (lead < 0x80) {
        ++i;
        return lead;
    }
    int length = 0;
    char32_t cp = 0;
    char32_t minimum = 0;
    if ((lead & 0xE0) == 0xC0) {
        length = 2, cp = lead & 0x1F, minimum = 0x80;
    } else if ((lead & 0xF0) == 0xE0) {
        length = 3, cp = lead & 0x0F, minimum = 0x800;
    } else if ((lead & 0xF8) == 0xF0) {
        length = 4, cp = lead & 0x07, minimum = 0x10000;
    } else {
        ++i;
        return REPLACEMENT;
    }
    if (i + length > s.size()) {
        ++i;
        return REPLACEMENT;
    }
    for (int k = 1; k < length; ++k) {
        unsigned char c = byte(i + k);
        if ((c & 0xC0) != 0x80) {
            ++i;
            return REPLACEMENT;
        }
        cp = (cp << 6) | (c & 0x3F);
    }
    if (cp < minimum || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) {
        ++i;
        return REPLACEMENT;
    }
    i += length;
    return cp;
}

// Tabs and other control characters take a space's room rather than a missing-glyph box.
char32_t drawable(char32_t cp) { return cp < 0x20 || cp == 0x7F ? U' ' : cp; }

// Pen advance of one line (no '\n' in it), exactly as layoutText advances.
float lineWidth(GlyphAtlas& atlas, std::string_view utf8) {
    float pen = 0.0f;
    uint32_t previous = 0;
    for (size_t i = 0; i < utf8.size();) {
        char32_t cp = decodeOne(utf8, i);
        if (cp == U'\r') continue;
        Glyph g = atlas.glyph(drawable(cp));
        pen += atlas.kerning(previous, g.glyphIndex) + g.advance;
        previous = g.glyphIndex;
    }
    return pen;
}

// The pen advance of a run of text and the glyphs at its two ends, so that the width of two runs
// joined is known without measuring the joined string again: width(a + b) = a.width +
// kerning(a.last, b.first) + b.width, exactly what lineWidth would return (advances and kerning
// are multiples of 1/64 px, so the sums are exact in float). This keeps wrapping linear in the
// text's length: re-measuring the growing line for every word made a long title quadratic.
struct Run {
    float width = 0.0f;
    uint32_t first = 0;  // glyph index of the first glyph, 0 for an empty run
    uint32_t last = 0;
};

Run measureRun(GlyphAtlas& atlas, std::string_view utf8) {
    Run r;
    uint32_t previous = 0;
    for (size_t i = 0; i < utf8.size();) {
        char32_t cp = decodeOne(utf8, i);
        if (cp == U'\r') continue;
        Glyph g = atlas.glyph(drawable(cp));
        r.width += atlas.kerning(previous, g.glyphIndex) + g.advance;
        if (previous == 0 && r.first == 0) r.first = g.glyphIndex;
        previous = g.glyphIndex;
    }
    r.last = previous;
    return r;
}

Run join(GlyphAtlas& atlas, const Run& a, const Run& b) {
    if (a.first == 0 && a.width == 0.0f) return b;
    if (b.first == 0 && b.width == 0.0f) return a;
    return {a.width + atlas.kerning(a.last, b.first) + b.width, a.first, b.last};
}

// Splits a word too wide for a line between characters; appends all pieces but the last to
// `lines` and returns the last (it may share its line with the next word) with its run.
std::string splitLongWord(GlyphAtlas& atlas, std::string_view word, float maxWidth,
                          std::vector<std::string>& lines, Run& pieceRun) {
    std::string piece;
    pieceRun = {};
    for (size_t i = 0; i < word.size();) {
        size_t start = i;
        decodeOne(word, i);
        std::string_view character = word.substr(start, i - start);
        Run c = measureRun(atlas, character);
        Run candidate = join(atlas, pieceRun, c);
        if (!piece.empty() && candidate.width > maxWidth) {
            lines.push_back(piece);
            piece = std::string(character);
            pieceRun = c;
        } else {
            piece += character;
            pieceRun = candidate;
        }
    }
    return piece;
}

// A word that is a lone operator ("1 - g", "a = b") is kept on one line with its neighbours, so
// a formula in prose does not break at its operator.
bool isOperator(std::string_view word) {
    return word == "-" || word == "+" || word == "=" || word == "*" || word == "/" || word == "x" ||
           word == "<=" || word == ">=" || word == "<" || word == ">";
}

void wrapParagraph(GlyphAtlas& atlas, std::string_view paragraph, float maxWidth,
                   std::vector<std::string>& lines) {
    // Words are split at ASCII spaces and tabs (byte-safe in UTF-8); operators glue their
    // neighbours into one unit.
    std::vector<std::string> units;
    {
        std::vector<std::string_view> words;
        size_t i = 0;
        while (i < paragraph.size()) {
            while (i < paragraph.size() && (paragraph[i] == ' ' || paragraph[i] == '\t')) ++i;
            size_t end = i;
            while (end < paragraph.size() && paragraph[end] != ' ' && paragraph[end] != '\t') {
                ++end;
            }
            if (end == i) break;
            words.push_back(paragraph.substr(i, end - i));
            i = end;
        }
        // An operator takes the word after it, and the word before it when that word stands
        // alone ("1 - g" is one unit; a long sum "a + b + c" still breaks before a "+").
        bool glueNext = false;
        bool lastAlone = false;
        for (std::string_view w : words) {
            bool op = isOperator(w);
            bool glue = !units.empty() && (glueNext || (op && lastAlone));
            lastAlone = !glue;
            if (glue) {
                units.back() += " ";
                units.back() += w;
            } else {
                units.emplace_back(w);
            }
            glueNext = op;
        }
    }
    const Run space = measureRun(atlas, " ");
    std::string line;
    Run lineRun;
    for (const std::string& word : units) {
        Run w = measureRun(atlas, word);
        Run candidate = line.empty() ? w : join(atlas, join(atlas, lineRun, space), w);
        if (candidate.width <= maxWidth) {
            if (!line.empty()) line += ' ';
            line += word;
            lineRun = candidate;
            continue;
        }
        if (!line.empty()) lines.push_back(std::move(line));
        if (w.width <= maxWidth) {
            line = word;
            lineRun = w;
        } else {
            line = splitLongWord(atlas, word, maxWidth, lines, lineRun);
        }
    }
    lines.push_back(std::move(line));
}

}  // namespace

std::u32string decodeUtf8(std::string_view utf8) {
    std::u32string out;
    out.reserve(utf8.size());
    for (size_t i = 0; i < utf8.size();) out.push_back(decodeOne(utf8, i));
    return out;
}

TextLayout layoutText(GlyphAtlas& atlas, std::string_view utf8) {
    TextLayout out;
    out.metrics = atlas.metrics();
    const int lineHeight = static_cast<int>(out.metrics.lineHeight);
    const int ascender = static_cast<int>(out.metrics.ascender);
    float pen = 0.0f;
    int line = 0;
    uint32_t previous = 0;
    for (size_t i = 0; i < utf8.size();) {
        char32_t cp = decodeOne(utf8, i);
        if (cp == U'\n') {
            out.lineWidths.push_back(pen);
            pen = 0.0f;
            previous = 0;
            ++line;
            continue;
        }
        if (cp == U'\r') continue;
        Glyph g = atlas.glyph(drawable(cp));
        pen += atlas.kerning(previous, g.glyphIndex);
        if (g.size.x > 0 && g.size.y > 0) {
            // Whole-pixel pen origin + whole-pixel bearing: the bitmap maps 1:1 to pixels.
            int originX = static_cast<int>(std::lround(pen));
            int baseline = line * lineHeight + ascender;
            out.glyphs.push_back({g, {originX + g.bearing.x, baseline - g.bearing.y}, line});
        }
        pen += g.advance;
        previous = g.glyphIndex;
    }
    out.lineWidths.push_back(pen);
    float widest = *std::max_element(out.lineWidths.begin(), out.lineWidths.end());
    out.size = {widest, static_cast<float>(out.lineWidths.size()) * out.metrics.lineHeight};
    return out;
}

glm::vec2 measureText(FontFace face, float pixelSize, std::string_view utf8) {
    GlyphAtlas& atlas = glyphAtlas(face, pixelSize);
    float widest = 0.0f;
    size_t lines = 0;
    size_t start = 0;
    while (true) {
        size_t end = utf8.find('\n', start);
        widest = std::max(widest, lineWidth(atlas, utf8.substr(start, end - start)));
        ++lines;
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    return {widest, static_cast<float>(lines) * atlas.metrics().lineHeight};
}

FontMetrics fontMetrics(FontFace face, float pixelSize) {
    return glyphAtlas(face, pixelSize).metrics();
}

std::vector<std::string> wrapText(GlyphAtlas& atlas, std::string_view utf8, float maxWidth) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (true) {
        size_t end = utf8.find('\n', start);
        std::string_view paragraph = utf8.substr(start, end - start);
        if (!paragraph.empty() && paragraph.back() == '\r') paragraph.remove_suffix(1);
        wrapParagraph(atlas, paragraph, maxWidth, lines);
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    return lines;
}

std::vector<std::string> wrapText(FontFace face, float pixelSize, std::string_view utf8,
                                  float maxWidth) {
    return wrapText(glyphAtlas(face, pixelSize), utf8, maxWidth);
}

SpanLine splitCodeSpans(std::string_view utf8) {
    SpanLine out;
    auto add = [&](std::string_view text, bool mono) {
        if (!text.empty()) out.push_back({std::string(text), mono});
    };
    size_t prose = 0;  // start of the prose not yet added
    size_t i = 0;
    while (i < utf8.size()) {
        size_t open = utf8.find('`', i);
        if (open == std::string_view::npos) break;
        size_t close = utf8.find('`', open + 1);
        if (close == std::string_view::npos) break;  // no partner: the backtick is text
        add(utf8.substr(prose, open - prose), false);
        add(utf8.substr(open + 1, close - open - 1), true);
        prose = i = close + 1;
    }
    add(utf8.substr(prose), false);
    return out;
}

float spanLineWidth(FontFace face, float pixelSize, const SpanLine& line) {
    float w = 0.0f;
    for (const TextSpan& span : line) {
        w += lineWidth(glyphAtlas(span.mono ? FontFace::Mono : face, pixelSize), span.text);
    }
    return w;
}

namespace {

// A piece of a unit (the text between two breakable spaces) with its measured run.
struct MeasuredSpan {
    std::string text;
    bool mono = false;
    Run run;
};

// A line being filled: the width of its finished spans plus the run of its last (open) span, so
// that appending is exact (kerning inside a face, none across faces) without re-measuring.
struct LineState {
    SpanLine spans;
    float closed = 0.0f;
    Run open;
    bool openMono = false;
    float width() const { return closed + open.width; }
};

struct SpanWrapper {
    GlyphAtlas& prose;
    GlyphAtlas& mono;
    float maxWidth;
    std::vector<SpanLine>& lines;
    bool* spanSplit;
    Run space;

    GlyphAtlas& atlas(bool m) { return m ? mono : prose; }

    // The state after appending a span (text added only when `commit`).
    void append(LineState& st, const MeasuredSpan& sp) {
        if (!st.spans.empty() && st.openMono == sp.mono) {
            st.open = join(atlas(sp.mono), st.open, sp.run);
            st.spans.back().text += sp.text;
            return;
        }
        st.closed += st.open.width;
        st.open = sp.run;
        st.openMono = sp.mono;
        st.spans.push_back({sp.text, sp.mono});
    }
    float widthWith(const LineState& st, const std::vector<MeasuredSpan>& unit, bool gap) {
        float closed = st.closed;
        Run open = st.open;
        bool openMono = st.openMono;
        bool empty = st.spans.empty();
        auto add = [&](const Run& r, bool m) {
            if (!empty && openMono == m) {
                open = join(atlas(m), open, r);
            } else {
                closed += empty ? 0.0f : open.width;
                open = r;
                openMono = m;
            }
            empty = false;
        };
        if (gap && !empty) add(space, false);
        for (const MeasuredSpan& sp : unit) add(sp.run, sp.mono);
        return closed + open.width;
    }
    void finish(LineState& st) {
        if (!st.spans.empty()) lines.push_back(std::move(st.spans));
        st = {};
    }
    // A unit wider than the line alone: split between characters, span by span.
    void splitUnit(LineState& st, const std::vector<MeasuredSpan>& unit) {
        for (const MeasuredSpan& sp : unit) {
            bool broke = false;
            for (size_t i = 0; i < sp.text.size();) {
                size_t start = i;
                decodeOne(sp.text, i);
                MeasuredSpan c{sp.text.substr(start, i - start), sp.mono, {}};
                c.run = measureRun(atlas(sp.mono), c.text);
                if (!st.spans.empty() && widthWith(st, {c}, false) > maxWidth) {
                    finish(st);
                    broke |= start > 0;
                }
                append(st, c);
            }
            if (broke && sp.mono && spanSplit) *spanSplit = true;
        }
    }
    using Unit = std::vector<MeasuredSpan>;

    // Units: the text between breakable spaces (spaces outside code spans); a code span
    // belongs to the unit of the prose it touches. Measured.
    std::vector<Unit> unitsOf(std::string_view text) {
        std::vector<Unit> units;
        bool unitOpen = false;
        auto piece = [&](std::string_view s, bool m) {
            if (s.empty()) return;
            if (!unitOpen) {
                units.emplace_back();
                unitOpen = true;
            }
            auto& u = units.back();
            if (!u.empty() && u.back().mono == m) {
                u.back().text += s;
            } else {
                u.push_back({std::string(s), m, {}});
            }
        };
        for (const TextSpan& span : splitCodeSpans(text)) {
            if (span.mono) {
                piece(span.text, true);
                continue;
            }
            std::string_view p = span.text;
            size_t i = 0;
            while (i < p.size()) {
                if (p[i] == ' ' || p[i] == '\t') {
                    unitOpen = false;
                    ++i;
                    continue;
                }
                size_t end = i;
                while (end < p.size() && p[end] != ' ' && p[end] != '\t') ++end;
                piece(p.substr(i, end - i), false);
                i = end;
            }
        }
        for (auto& u : units) {
            for (MeasuredSpan& sp : u) sp.run = measureRun(atlas(sp.mono), sp.text);
        }
        return units;
    }

    // Operators glue their neighbours as in wrapText: "1 - g" is one unit.
    std::vector<Unit> glueOperators(std::vector<Unit> units) {
        std::vector<bool> operators;  // a unit that is a lone operator word
        for (const Unit& u : units) {
            operators.push_back(u.size() == 1 && !u[0].mono && isOperator(u[0].text));
        }
        std::vector<Unit> glued;
        bool glueNext = false;
        bool lastAlone = false;
        for (size_t k = 0; k < units.size(); ++k) {
            bool op = operators[k];
            bool glue = !glued.empty() && (glueNext || (op && lastAlone));
            lastAlone = !glue;
            if (glue) {
                glued.back().push_back({" ", false, space});
                for (MeasuredSpan& sp : units[k]) glued.back().push_back(std::move(sp));
            } else {
                glued.push_back(std::move(units[k]));
            }
            glueNext = op;
        }
        return glued;
    }

    // One paragraph's lines: its units filled greedily, a unit wider than a line split.
    void paragraph(std::string_view text) {
        std::vector<Unit> glued = glueOperators(unitsOf(text));
        LineState st;
        for (const auto& unit : glued) {
            if (widthWith(st, unit, true) <= maxWidth) {
                if (!st.spans.empty()) append(st, {" ", false, space});
                for (const MeasuredSpan& sp : unit) append(st, sp);
                continue;
            }
            finish(st);
            if (widthWith(st, unit, false) <= maxWidth) {
                for (const MeasuredSpan& sp : unit) append(st, sp);
            } else {
                splitUnit(st, unit);
            }
        }
        // An empty paragraph is an empty line (a paragraph gap), as in wrapText.
        if (st.spans.empty()) {
            lines.emplace_back();
        } else {
            finish(st);
        }
    }
};

}  // namespace

std::vector<SpanLine> wrapSpans(FontFace face, float pixelSize, std::string_view utf8,
                                float maxWidth, bool* spanSplit) {
    std::vector<SpanLine> lines;
    SpanWrapper w{glyphAtlas(face, pixelSize),
                  glyphAtlas(FontFace::Mono, pixelSize),
                  maxWidth,
                  lines,
                  spanSplit,
                  {}};
    w.space = measureRun(w.prose, " ");
    size_t start = 0;
    while (true) {
        size_t end = utf8.find('\n', start);
        std::string_view paragraph = utf8.substr(start, end - start);
        if (!paragraph.empty() && paragraph.back() == '\r') paragraph.remove_suffix(1);
        w.paragraph(paragraph);
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    return lines;
}

std::string elideText(FontFace face, float pixelSize, std::string_view utf8, float maxWidth) {
    GlyphAtlas& atlas = glyphAtlas(face, pixelSize);
    if (lineWidth(atlas, utf8) <= maxWidth) return std::string(utf8);
    // One pass: the prefix grows character by character while prefix + "..." fits (widths
    // joined as runs, so this is linear in the text's length).
    const Run dots = measureRun(atlas, "...");
    Run prefix;
    size_t kept = 0;
    for (size_t i = 0; i < utf8.size();) {
        size_t start = i;
        decodeOne(utf8, i);
        Run c = measureRun(atlas, utf8.substr(start, i - start));
        Run next = join(atlas, prefix, c);
        if (join(atlas, next, dots).width > maxWidth) break;
        prefix = next;
        kept = i;
    }
    std::string out(utf8.substr(0, kept));
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out + "...";
}

}  // namespace pcf
