// inspector_text.cpp: text blocks that fit a box: wrapped, then set in smaller type down to a
// floor, then paged (the step text, the notes, the formula).
#include <limits>

#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

namespace {

// A line of lesson text that starts with two spaces (or a tab) is preformatted: a table row or a
// formula whose columns must stay put. It is drawn in the monospace face with every space kept;
// only a row wider than the box is cut into pieces (at the floor size), never reflowed.
bool preformatted(std::string_view line) {
    return line.starts_with("  ") || line.starts_with("\t");
}

size_t codepoints(std::string_view s) {
    size_t n = 0;
    for (unsigned char ch : s) n += (ch & 0xC0u) != 0x80u;
    return n;
}

// A preformatted row's cells (separated by two or more spaces) and its indent.
std::vector<std::string> tableCellsOf(const std::string& row, size_t& indent) {
    std::vector<std::string> cells;
    indent = row.find_first_not_of(" \t");
    if (indent == std::string::npos) return cells;
    size_t i = indent;
    while (i < row.size()) {
        size_t gap = row.find("  ", i);
        if (gap == std::string::npos) gap = row.size();
        cells.push_back(row.substr(i, gap - i));
        i = row.find_first_not_of(' ', gap);
        if (i == std::string::npos) break;
    }
    return cells;
}

// Lines [first, end) padded column by column, when every one of them has two cells or more.
void alignTableRows(std::vector<std::string>& lines, size_t first, size_t end) {
    std::vector<std::vector<std::string>> rows;
    std::vector<size_t> indents;
    for (size_t r = first; r < end; ++r) {
        size_t indent = 0;
        rows.push_back(tableCellsOf(lines[r], indent));
        indents.push_back(indent);
        if (rows.back().size() < 2) return;
    }
    std::vector<size_t> widths;
    for (const auto& row : rows) {
        if (widths.size() < row.size()) widths.resize(row.size(), 0);
        for (size_t c = 0; c < row.size(); ++c) {
            widths[c] = std::max(widths[c], codepoints(row[c]));
        }
    }
    for (size_t r = 0; r < rows.size(); ++r) {
        std::string out(indents[r], ' ');
        for (size_t c = 0; c < rows[r].size(); ++c) {
            out += rows[r][c];
            if (c + 1 < rows[r].size()) {
                out += std::string(widths[c] - codepoints(rows[r][c]) + 3, ' ');
            }
        }
        lines[first + r] = out;
    }
}

// Consecutive preformatted rows whose cells are separated by two or more spaces form a table:
// each column is padded to its widest cell, so the columns line up in the monospace face even
// when the numbers filled into them differ in length ("1" under "0.6333").
std::string alignTables(std::string_view text) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (true) {
        size_t end = text.find('\n', start);
        lines.emplace_back(text.substr(start, end == std::string_view::npos ? end : end - start));
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    for (size_t k = 0; k < lines.size();) {
        size_t end = k;
        while (end < lines.size() && preformatted(lines[end])) ++end;
        if (end - k >= 2) alignTableRows(lines, k, end);
        k = std::max(end, k + 1);
    }
    std::string out;
    for (size_t k = 0; k < lines.size(); ++k) out += (k ? "\n" : "") + lines[k];
    return out;
}

// Prose lines (one paragraph source, '\n' kept) wrapped to width onto out. Prose with `code
// spans`: a span is set in monospace and kept on one line; one that had to be broken (wider
// than the box) sets tooWide, asking for smaller type first.
void wrapProse(const std::string& prose, FontFace face, float size, float width,
               std::vector<FitLine>& out, bool& tooWide) {
    if (face == FontFace::Mono) {
        for (std::string& l : wrapText(face, size, prose, width))
            out.push_back({std::move(l), false, {}});
        return;
    }
    bool spanSplit = false;
    for (SpanLine& l : wrapSpans(face, size, prose, width, &spanSplit)) {
        std::string plain;
        for (const TextSpan& sp : l) plain += sp.text;
        out.push_back({std::move(plain), false, std::move(l)});
    }
    tooWide |= spanSplit;
}

// A preformatted line (tabs as spaces) onto out, kept whole where it fits; else (tooWide) wrapped
// at its spaces, continuation lines indented further (a table row this wide has no columns to
// keep at this size).
void wrapPreformatted(std::string_view line, float size, float width, std::vector<FitLine>& out,
                      bool& tooWide) {
    std::string row(line);
    for (char& ch : row) {
        if (ch == '\t') ch = ' ';
    }
    float w = measureText(FontFace::Mono, size, row).x;
    if (w <= width) {
        out.push_back({row, true, {}});
        return;
    }
    tooWide = true;
    size_t indent = row.find_first_not_of(' ');
    if (indent == std::string::npos) indent = 0;
    std::string lead(indent, ' ');
    float leadW = measureText(FontFace::Mono, size, lead + "  ").x;
    std::vector<std::string> parts = wrapText(FontFace::Mono, size, row.substr(indent),
                                              std::max(8.0f * size * 0.6f, width - leadW));
    for (size_t k = 0; k < parts.size(); ++k) {
        out.push_back({(k == 0 ? lead : lead + "  ") + parts[k], true, {}});
    }
}

std::vector<FitLine> wrapBlock(std::string_view text, FontFace face, float size, float width,
                               bool& tooWide) {
    std::vector<FitLine> out;
    size_t start = 0;
    std::string prose;  // consecutive prose lines form one paragraph source ('\n' kept)
    int para = 0;
    auto flushProse = [&]() {
        if (prose.empty()) return;
        // Each source line on its own (as wrapping breaks at '\n' anyway), its lines numbered,
        // so that a page break can wrap the rest of one again (pageBreaks).
        size_t from = 0;
        while (true) {
            size_t nl = prose.find('\n', from);
            size_t first = out.size();
            wrapProse(prose.substr(from, nl == std::string::npos ? nl : nl - from), face, size,
                      width, out, tooWide);
            for (size_t k = first; k < out.size(); ++k) out[k].para = para;
            ++para;
            if (nl == std::string::npos) break;
            from = nl + 1;
        }
        prose.clear();
    };
    while (true) {
        size_t end = text.find('\n', start);
        std::string_view line =
            text.substr(start, end == std::string_view::npos ? end : end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (preformatted(line)) {
            flushProse();
            wrapPreformatted(line, size, width, out, tooWide);
        } else if (line.empty()) {
            // A paragraph gap: one empty line.
            flushProse();
            if (!out.empty() && !out.back().text.empty()) out.push_back({"", false, {}});
        } else {
            if (!prose.empty()) prose += '\n';
            prose += std::string(line);
        }
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    flushProse();
    // Leading and trailing empty lines take room and say nothing.
    while (!out.empty() && out.back().text.empty()) out.pop_back();
    while (!out.empty() && out.front().text.empty()) out.erase(out.begin());
    if (out.empty()) out.push_back({"", false, {}});
    return out;
}

// A prose line that ends a sentence: a page that ends there leaves no statement half made (a
// slide that stops at "p = uv * size" says something else than the sentence that goes on with
// "- 0.5").
bool endsSentence(const FitLine& line) {
    if (line.mono) return false;
    std::string_view t = line.text;
    while (!t.empty() && (t.back() == ' ' || t.back() == ')' || t.back() == '"'))
        t.remove_suffix(1);
    return !t.empty() && (t.back() == '.' || t.back() == '?' || t.back() == '!');
}

// Where the last sentence that ends inside a prose line ends (the index after its '.', '?' or
// '!', followed by a space and more words); npos when none does.
size_t lastSentenceEnd(const FitLine& line) {
    if (line.mono) return std::string::npos;
    for (size_t k = line.text.size(); k-- > 1;) {
        char c = line.text[k - 1];
        if (line.text[k] == ' ' && (c == '.' || c == '?' || c == '!') && k + 1 < line.text.size())
            return k;
    }
    return std::string::npos;
}

// The part of a prose line after `cut` (its sentence's end; the space there is dropped) as a
// line of its own; `line` keeps the part before. Spans (code spans in monospace) are cut where
// the text is.
FitLine splitLineAt(FitLine& line, size_t cut) {
    FitLine tail{line.text.substr(cut + 1), false, {}};
    line.text.resize(cut);
    if (line.spans.empty()) return tail;
    SpanLine head;
    size_t at = 0;
    for (TextSpan& sp : line.spans) {
        size_t end = at + sp.text.size();
        if (end <= cut) {
            head.push_back(std::move(sp));
        } else if (at >= cut + 1) {
            tail.spans.push_back(std::move(sp));
        } else {
            if (cut > at) head.push_back({sp.text.substr(0, cut - at), sp.mono});
            size_t from = std::max(at, cut + 1) - at;
            if (from < sp.text.size()) tail.spans.push_back({sp.text.substr(from), sp.mono});
        }
        at = end;
    }
    line.spans = std::move(head);
    return tail;
}

bool isOperatorWord(std::string_view w) {
    return w == "-" || w == "+" || w == "=" || w == "*" || w == "/" || w == "<=" || w == ">=";
}

// A break between lines b - 1 and b that cuts no preformatted block and no formula (a line that
// ends or a line that starts with an operator: "p = uv * size" / "- 0.5").
bool cleanBreak(const std::vector<FitLine>& lines, int b) {
    if (lines[b - 1].mono && lines[b].mono) return false;
    std::string_view before = lines[b - 1].text;
    std::string_view after = lines[b].text;
    size_t lastSpace = before.find_last_of(' ');
    std::string_view lastWord =
        lastSpace == std::string_view::npos ? before : before.substr(lastSpace + 1);
    std::string_view firstWord = after.substr(0, after.find(' '));
    return !isOperatorWord(lastWord) && !isOperatorWord(firstWord);
}

// Where each page starts, for pages of at most `budget` lines. A page ends, in this order of
// preference, at a paragraph gap, at the end of a sentence (a prose line is split there when
// the sentence ends inside it), or between two lines that cut no table and no formula, as long
// as that keeps at least half of the page's budget; else it is cut at the budget. No page starts
// with a gap.
// A prose line as its source again: its code spans in backticks.
std::string sourceOf(const FitLine& line) {
    if (line.spans.empty()) return line.text;
    std::string out;
    for (const TextSpan& sp : line.spans) out += sp.mono ? "`" + sp.text + "`" : sp.text;
    return out;
}

std::vector<int> pageBreaks(std::vector<FitLine>& lines, int budget,
                            const std::function<std::vector<FitLine>(const std::string&)>& wrap) {
    auto gap = [&](int k) { return lines[k].text.empty() && !lines[k].mono; };
    std::vector<int> starts;
    int start = 0;
    while (start < static_cast<int>(lines.size())) {
        starts.push_back(start);
        const int n = static_cast<int>(lines.size());
        int end = start + budget;
        if (end < n) {
            int low = std::max(start + 1, start + budget / 2 + 1);
            int chosen = -1;
            for (int b = end; b >= low && chosen < 0; --b) {
                if (gap(b)) chosen = b;
            }
            for (int b = end; b >= low && chosen < 0; --b) {
                if (endsSentence(lines[b - 1])) {
                    chosen = b;
                } else if (size_t cut = lastSentenceEnd(lines[b - 1]); cut != std::string::npos) {
                    // The next page starts with the next sentence, and the rest of its source
                    // line is wrapped again from there (no short line left at the page's top).
                    int para = lines[b - 1].para;
                    std::string rest = sourceOf(splitLineAt(lines[b - 1], cut));
                    int e = b;
                    while (e < static_cast<int>(lines.size()) && para >= 0 &&
                           lines[e].para == para) {
                        rest += " " + sourceOf(lines[e]);
                        ++e;
                    }
                    std::vector<FitLine> again = wrap(rest);
                    for (FitLine& l : again) l.para = para;
                    lines.erase(lines.begin() + b, lines.begin() + e);
                    lines.insert(lines.begin() + b, again.begin(), again.end());
                    chosen = b;
                }
            }
            for (int b = end; b >= low && chosen < 0; --b) {
                if (cleanBreak(lines, b)) chosen = b;
            }
            if (chosen >= 0) end = chosen;
        }
        start = std::min(end, static_cast<int>(lines.size()));
        while (start < static_cast<int>(lines.size()) && gap(start)) ++start;
    }
    return starts;
}

// ---- Pages that end where a sentence does. ----

// A place a page may start: an offset into the (aligned) text, and how clean a cut it is there
// (0: a paragraph, 1: a line of its own after a sentence or a table, 2: a sentence inside a
// line).
struct PageCut {
    size_t at = 0;
    int quality = 0;
};

// Whether the prose before `end` (exclusive) closes a sentence: '.', '?' or '!' (a closing
// bracket or quote may follow), not an abbreviation's full stop ("e.g.").
bool closesSentence(std::string_view line, size_t end) {
    while (end > 0 && (line[end - 1] == ')' || line[end - 1] == '"')) --end;
    if (end == 0) return false;
    char c = line[end - 1];
    if (c != '.' && c != '?' && c != '!') return false;
    std::string_view before = line.substr(0, end);
    for (std::string_view abbreviation : {"e.g.", "i.e.", "etc.", "vs."}) {
        if (before.ends_with(abbreviation)) return false;
    }
    return true;
}

// Where pages may start: every paragraph; a line after a sentence's end or after a table (a
// table stays with the line that introduces it: "... weigh:" and its rows are one); and every
// sentence inside a prose line (outside code spans).
std::vector<PageCut> pageCuts(std::string_view text) {
    std::vector<PageCut> cuts{{0, 0}};
    bool gap = false, afterTable = false, sentenceDone = false;
    for (size_t start = 0; start <= text.size();) {
        size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.find_first_not_of(" \t") == std::string_view::npos) {
            gap = true;
        } else {
            bool pre = preformatted(line);
            int quality = gap ? 0 : (sentenceDone || (afterTable && !pre)) ? 1 : -1;
            if (start > 0 && quality >= 0) cuts.push_back({start, quality});
            gap = false;
            afterTable = pre;
            sentenceDone = !pre && closesSentence(line, line.size());
            bool code = false;
            for (size_t k = 0; !pre && k + 1 < line.size(); ++k) {
                if (line[k] == '`') code = !code;
                if (!code && line[k + 1] == ' ' && closesSentence(line, k + 1)) {
                    size_t next = line.find_first_not_of(' ', k + 1);
                    if (next != std::string_view::npos) cuts.push_back({start + next, 2});
                }
            }
        }
        if (end == text.size()) break;
        start = end + 1;
    }
    return cuts;
}

// Pages of at most `budget` lines that each start at a cut: the fewest pages; of those, none
// holding a lone sentence where the text has more than one (it goes back to its neighbours), the
// cleanest cuts and the most even pages. The lines of each page are wrapped from its cut, so no
// page opens with the tail of a line. Empty when a sentence alone is longer than a page.
std::vector<std::vector<FitLine>> sentencePages(
    std::string_view text, int budget,
    const std::function<std::vector<FitLine>(std::string_view)>& wrap) {
    std::vector<PageCut> cuts = pageCuts(text);
    const size_t n = cuts.size();
    auto offset = [&](size_t k) { return k < n ? cuts[k].at : text.size(); };
    constexpr double PAGE = 1e6, LONE = 1e4, ROUGH_CUT = 50.0;
    std::vector<double> best(n + 1, std::numeric_limits<double>::infinity());
    std::vector<size_t> from(n + 1, 0);
    best[0] = 0.0;
    for (size_t j = 1; j <= n; ++j) {
        for (size_t i = j; i-- > 0;) {
            if (!std::isfinite(best[i])) continue;
            int lines =
                static_cast<int>(wrap(text.substr(offset(i), offset(j) - offset(i))).size());
            if (lines > budget) break;  // fewer cuts only add lines
            double slack = budget - lines;
            double cost = best[i] + PAGE + (j - i == 1 && n > 1 ? LONE : 0.0) +
                          (j < n ? ROUGH_CUT * cuts[j].quality : 0.0) + slack * slack;
            if (cost < best[j]) best[j] = cost, from[j] = i;
        }
    }
    std::vector<std::vector<FitLine>> pages;
    if (!std::isfinite(best[n])) return pages;
    for (size_t j = n; j > 0; j = from[j]) {
        pages.push_back(wrap(text.substr(offset(from[j]), offset(j) - offset(from[j]))));
    }
    std::reverse(pages.begin(), pages.end());
    return pages;
}

}  // namespace

FittedText fitText(std::string_view text, FontFace face, float start, float floor, float width,
                   float height, bool markLine) {
    FittedText f;
    std::string aligned = alignTables(text);
    text = aligned;
    float size = std::max(start, floor);
    while (true) {
        bool tooWide = false;
        bool atFloor = size <= floor;
        f.lines = wrapBlock(text, face, size, width, tooWide);
        f.size = size;
        f.lineHeight = lineHeightOf(size);
        float needed = static_cast<float>(f.lines.size()) * f.lineHeight;
        // A preformatted row that had to wrap loses its columns: smaller type first, if the
        // floor allows (then the rows wrap at the floor).
        if ((needed <= height && !tooWide) || atFloor) break;
        size = stepDown(size, floor);
        f.stepped = true;
    }
    int fitting = std::max(1, static_cast<int>(std::floor(height / f.lineHeight)));
    if (static_cast<int>(f.lines.size()) <= fitting) {
        f.pageStarts = {0};
    } else {
        // One line of every page is the "more" mark's (unless it goes elsewhere). Prose pages end
        // where a sentence does (sentencePages); a formula, or prose with a sentence longer than
        // a page, where a line cuts no statement in two (pageBreaks).
        int budget = std::max(1, fitting - (markLine ? 1 : 0));
        bool unused = false;
        std::vector<std::vector<FitLine>> pages;
        if (face != FontFace::Mono) {
            pages = sentencePages(text, budget, [&](std::string_view part) {
                bool wide = false;
                return wrapBlock(part, face, f.size, width, wide);
            });
        }
        if (!pages.empty()) {
            f.lines.clear();
            f.pageStarts.clear();
            for (std::vector<FitLine>& page : pages) {
                f.pageStarts.push_back(static_cast<int>(f.lines.size()));
                f.lines.insert(f.lines.end(), page.begin(), page.end());
            }
        } else {
            auto wrap = [&](const std::string& prose) {
                std::vector<FitLine> out;
                wrapProse(prose, face, f.size, width, out, unused);
                return out;
            };
            f.pageStarts = pageBreaks(f.lines, budget, wrap);
        }
    }
    f.pages = static_cast<int>(f.pageStarts.size());
    return f;
}

namespace {

// The lines page `page` draws, [first, last): a gap that ends a page is not drawn (it would only
// push the "more" mark down).
std::pair<size_t, size_t> pageLineRange(const FittedText& f, int page) {
    size_t first = static_cast<size_t>(f.pageStarts[static_cast<size_t>(page)]);
    size_t last = page + 1 < f.pages
                      ? static_cast<size_t>(f.pageStarts[static_cast<size_t>(page) + 1])
                      : f.lines.size();
    while (last > first && f.lines[last - 1].text.empty() && !f.lines[last - 1].mono) --last;
    return {first, last};
}

// One line of a fitted block with its top-left at (x, y): prose in `face`, a preformatted line
// in the monospace face, code spans in their own face. Returns the width it takes.
float planFittedLine(Planner& pl, const FitLine& line, FontFace face, float size,
                     const Colour& colour, float x0, float y) {
    bool mixed = std::any_of(line.spans.begin(), line.spans.end(),
                             [](const TextSpan& sp) { return sp.mono; });
    if (mixed) {
        // Each piece in its own face, one after the other on a shared baseline: the
        // monospace pieces are moved down by the difference of the two ascenders.
        float ascender = fontMetrics(face, size).ascender;
        float x = std::round(x0);
        for (const TextSpan& sp : line.spans) {
            FontFace sf = sp.mono ? FontFace::Mono : face;
            float dy = std::round(ascender - fontMetrics(sf, size).ascender);
            TextStyle st{sf, size, sp.mono ? MONO_TEXT : colour};
            glm::vec2 at{std::round(x), std::round(y) + dy};
            std::string s = sp.text;
            pl.op([=](Canvas& cv) { cv.text(at, s, st); });
            x += measureText(sf, size, s).x;
        }
        return x - std::round(x0);
    }
    if (line.text.empty()) return 0.0f;
    FontFace lf = line.mono ? FontFace::Mono : face;
    TextStyle st{lf, size, line.mono ? MONO_TEXT : colour};
    glm::vec2 at{std::round(x0), std::round(y)};
    std::string s = line.text;
    pl.op([=](Canvas& cv) { cv.text(at, s, st); });
    return measureText(lf, size, s).x;
}

// The "more" mark of a paged block: which page this is of how many, and the key that turns it,
// right-aligned at the area's bottom; `y`: below the page's last line.
void planMoreMark(Planner& pl, const FittedText& f, const Rect& area, int page, float y,
                  const std::string& panel, const std::string& moreHint,
                  const std::optional<MarkPlace>& place) {
    std::string more = moreMarkText(f, page, moreHint);
    float ms = place ? place->size : std::max(10.0f, std::round(f.size * 0.85f));
    Rect r = pl.measure({area.right(), area.bottom() - lineHeightOf(ms)}, more,
                        {FontFace::Sans, ms, ACCENT, TextAlign::Right});
    if (place) {
        r = pl.measure({place->row.right(), place->row.y}, more,
                       {FontFace::Sans, ms, ACCENT, TextAlign::Right});
    } else {
        // The mark has the area's last line to itself (fitText left it free).
        r.y = std::max(r.y, y);
    }
    pl.fill(r.expanded(2), Colour{0.35f, 0.78f, 0.98f, 0.18f});
    glm::vec2 at = r.position();
    pl.op([=](Canvas& cv) { cv.text(at, more, {FontFace::Sans, ms, ACCENT}); });
    pl.box(BoxKind::Mark, r, panel, "more", ms);
    pl.plan.boxes.back().text = more;
}

}  // namespace

std::string moreMarkText(const FittedText& f, int page, const std::string& moreHint) {
    page = std::clamp(page, 0, f.pages - 1);
    // Appended, not a chain of operator+ (GCC 12 warns falsely, -Wrestrict).
    std::string more;
    if (page + 1 < f.pages) {
        more.append("more ").append(moreHint).append(moreHint.empty() ? "" : " ");
    }
    more.append("(").append(std::to_string(page + 1)).append("/");
    more.append(std::to_string(f.pages)).append(")");
    return more;
}

float placeFitted(Planner& pl, const FittedText& f, const Rect& area, int page, FontFace face,
                  const Colour& colour, const std::string& panel, const std::string& role,
                  const std::string& moreHint, const std::optional<MarkPlace>& mark) {
    page = std::clamp(page, 0, f.pages - 1);
    auto [first, last] = pageLineRange(f, page);
    float y = area.y;
    float widest = 0.0f;
    for (size_t k = first; k < last; ++k) {
        widest = std::max(widest, planFittedLine(pl, f.lines[k], face, f.size, colour, area.x, y));
        y += f.lineHeight;
    }
    float used = y - area.y;
    pl.box(BoxKind::Text, {std::round(area.x), std::round(area.y), std::min(widest, area.w), used},
           panel, role, f.size, f.pages > 1);
    for (size_t k = first; k < last; ++k) {
        pl.plan.boxes.back().text.append(k > first ? "\n" : "").append(f.lines[k].text);
    }
    if (f.pages > 1) planMoreMark(pl, f, area, page, y, panel, moreHint, mark);
    return used;
}

}  // namespace pcf::inspector_detail

namespace pcf {

std::string drawnStepText(std::string_view text) {
    std::string aligned = inspector_detail::alignTables(text);
    std::string out;
    size_t start = 0;
    while (true) {
        size_t end = aligned.find('\n', start);
        std::string_view line = std::string_view(aligned).substr(
            start, end == std::string::npos ? std::string::npos : end - start);
        if (inspector_detail::preformatted(line)) {
            out += line;
        } else {
            for (const TextSpan& span : splitCodeSpans(line)) out += span.text;
        }
        if (end == std::string::npos) break;
        out += '\n';
        start = end + 1;
    }
    return out;
}

}  // namespace pcf
