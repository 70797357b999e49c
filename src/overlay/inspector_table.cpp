// inspector_table.cpp: the texel table. Where the cells are too small at this size for all of a
// texel's numbers (a 4 x 4 of receiver-plane reads at 1024x768 in presentation mode keeps only
// the weights), the page after the cells lists them, one row per texel, so that every number the
// step's words can name is on some frame at the projector's number size (issue 19).
#include <algorithm>
#include <optional>

#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

namespace {

// The rows as columns padded to their widest cell (monospace), the header first.
std::vector<std::string> alignedRows(const std::vector<std::vector<std::string>>& cells,
                                     size_t leftColumns) {
    std::vector<size_t> widths;
    for (const auto& row : cells) {
        widths.resize(std::max(widths.size(), row.size()), 0);
        for (size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
    }
    std::vector<std::string> out;
    for (const auto& row : cells) {
        std::string line;
        for (size_t c = 0; c < row.size(); ++c) {
            std::string cell = row[c];
            // Numbers right-aligned, a texel "(i, j)" left-aligned.
            std::string pad(widths[c] - cell.size(), ' ');
            line += c < leftColumns ? cell + pad : pad + cell;
            if (c + 1 < row.size()) line += "  ";
        }
        out.push_back(line);
    }
    return out;
}

// How the table's columns are spelled: the texel as "(i, j)" or as two columns i and j (two
// characters narrower, the names the cells' index labels use); the ref column only where the taps
// compare with refs of their own (receiver-plane bias), else the one ref is in the title; the
// depth - ref column, dropped only where nothing else makes the row fit.
struct TableForm {
    bool pairTexel = true;
    bool refColumn = true;
    bool margin = true;
};

// The table's text: the header and one row per texel.
std::vector<std::string> tableRows(const InspectorModel& m, const std::vector<glm::ivec2>& texels,
                                   TableForm form) {
    const Trace& tr = *m.trace;
    std::vector<std::vector<std::string>> cells;
    std::vector<std::string> header;
    if (form.pairTexel) {
        header = {"texel"};
    } else {
        header = {"i", "j"};
    }
    header.push_back("bit");
    if (form.refColumn) header.push_back("ref");
    header.push_back("depth");
    if (form.margin) header.push_back("d - ref");
    header.push_back("w");
    cells.push_back(header);
    for (glm::ivec2 texel : texels) {
        const TapRecord* tap = firstTapAt(tr, texel);
        if (!tap) continue;
        // As the cell would show it (cellItems): a soft comparison's fraction for its bit.
        bool soft = tap->lit != 0.0f && tap->lit != 1.0f;
        std::string bit = soft ? fixed(tap->lit, 2) : tap->lit >= 0.5f ? "1" : "0";
        std::vector<std::string> row;
        if (form.pairTexel) {
            row = {"(" + std::to_string(texel.x) + ", " + std::to_string(texel.y) + ")"};
        } else {
            row = {std::to_string(texel.x), std::to_string(texel.y)};
        }
        row.push_back(bit);
        if (form.refColumn) row.push_back(fixed(tap->ref, 4));
        row.push_back(fixed(tap->depth, 3));
        if (form.margin) row.push_back(fixed(tap->depth - tap->ref, 4));
        row.push_back(weightText(tr.weights.at(texel)));
        cells.push_back(std::move(row));
    }
    return alignedRows(cells, form.pairTexel ? 1 : 0);
}

// The one ref every read was compared with; none under a per-tap bias (receiver-plane).
std::optional<float> commonRef(const Trace& tr) {
    if (tr.taps.empty()) return std::nullopt;
    for (const TapRecord& t : tr.taps) {
        if (t.ref != tr.taps.front().ref) return std::nullopt;
    }
    return tr.taps.front().ref;
}

// The table as a page draws it: the title wrapped to the panel (never cut short: it says what
// the rows are and, without a ref column, the ref), the rows at the widest type that holds them.
struct TexelTable {
    FittedText title;
    std::vector<std::string> rows;  // the header first
    float size = 0.0f;
};

TexelTable texelTableOf(const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t,
                        const std::vector<glm::ivec2>& texels) {
    float width = l.inspector.w - 2 * inspectorMargin(l);
    auto widest = [](const std::vector<std::string>& rows, float size) {
        float w = 0;
        for (const std::string& r : rows) w = std::max(w, measureText(FontFace::Mono, size, r).x);
        return w;
    };
    std::optional<float> ref = commonRef(*m.trace);
    TexelTable out;
    // The first spelling whose rows fit at the numbers' size or smaller, down to their floor.
    TableForm forms[] = {{true, !ref, true}, {false, !ref, true}, {false, !ref, false}};
    for (const TableForm& form : forms) {
        out.rows = tableRows(m, texels, form);
        out.size = t.number;
        while (widest(out.rows, out.size) > width && out.size > t.numberFloor) {
            out.size = stepDown(out.size, t.numberFloor);
        }
        if (widest(out.rows, out.size) <= width) break;
    }
    std::string title = texels.size() == 1 ? "The texel whose cell has no room for its numbers"
                                           : "The " + std::to_string(texels.size()) +
                                                 " texels whose cells have no room for their "
                                                 "numbers, row by row";
    // pcss: the texels only its blocker search read weigh 0 (the search counts blockers; the
    // filter's taps weigh the visibility). Without a word their w 0.000 reads as a tap that does
    // not count.
    const Trace& tr = *m.trace;
    bool searchOnly = methodInfo(tr.params.method).searchesBlockers &&
                      std::any_of(texels.begin(), texels.end(),
                                  [&](glm::ivec2 x) { return tr.weights.at(x) == 0.0f; });
    if (searchOnly) title += " (`w 0.000`: read by the blocker search only)";
    // (The ref as a code span: monospace like the rows, and never broken across lines.)
    title += ref ? "; `ref " + fixed(*ref, 4) + "` for all:" : ":";
    out.title = fitText(title, FontFace::Sans, t.label, t.label, width, 1e6f);
    return out;
}

// The height of the title and the gap under it.
float titleHeight(const TexelTable& table, const TypeSizes& t) {
    return static_cast<float>(table.title.lines.size()) * table.title.lineHeight +
           lineHeightOf(t.label) * 0.5f;
}

// Rows on one page: the line pitch is the numbers' own size (a row set smaller to fit the width
// keeps it, so the count does not depend on the rows' text). Under the title and the header;
// above the line that says where the rest is, when `note`.
int rowsPerPage(const InspectorLayout& l, const TypeSizes& t, const TexelTable& table, float top,
                bool note) {
    float margin = inspectorMargin(l);
    float lh = lineHeightOf(t.number);
    float room = l.inspector.bottom() - margin - top - titleHeight(table, t) - lh;
    if (note) room -= lineHeightOf(t.label) * 1.5f;
    return std::max(1, static_cast<int>(room / lh));
}

// The first row of each page. Every page but the last keeps the room for the line that says
// where the rest is; the last one only when more pages follow it (noteAfter: the formula's), so
// that a 25th row does not get a slide to itself. The rows are shared out evenly over the
// fewest pages that hold them (64 rows at 21 a page: 16 on each of 4, not 21, 21, 21, 1).
std::vector<size_t> tablePageStarts(const InspectorLayout& l, const TypeSizes& t,
                                    const TexelTable& table, float top, size_t rows,
                                    bool noteAfter) {
    size_t per = static_cast<size_t>(rowsPerPage(l, t, table, top, true));
    size_t last = static_cast<size_t>(rowsPerPage(l, t, table, top, noteAfter));
    size_t pages = 1;
    for (size_t left = rows; left > last; left -= per) ++pages;
    // The first rows % pages pages take one row more. (Where that is more than a page with the
    // note holds, the last page, without it, takes the rest.)
    size_t each = rows / pages, extra = rows % pages;
    bool even = each + (extra > 0 ? 1 : 0) <= per;
    std::vector<size_t> starts{0};
    for (size_t k = 0; k + 1 < pages; ++k) {
        starts.push_back(starts.back() + (even ? each + (k < extra ? 1 : 0) : per));
    }
    return starts;
}

}  // namespace

std::vector<glm::ivec2> texelsWithoutNumbers(const Trace& tr, const FramePlan& cells) {
    std::vector<glm::ivec2> out;
    for (const TapRecord& t : tr.taps) {
        bool shown = std::find(cells.numberedTexels.begin(), cells.numberedTexels.end(), t.texel) !=
                     cells.numberedTexels.end();
        if (!shown && std::find(out.begin(), out.end(), t.texel) == out.end())
            out.push_back(t.texel);
    }
    // Row by row, as the cells sit: a texel the words name is found where the grid has it.
    std::sort(out.begin(), out.end(),
              [](glm::ivec2 a, glm::ivec2 b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
    return out;
}

int texelTablePages(const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t,
                    const std::vector<glm::ivec2>& texels, float top, bool noteAfter) {
    TexelTable table = texelTableOf(l, m, t, texels);
    return static_cast<int>(tablePageStarts(l, t, table, top, texels.size(), noteAfter).size());
}

float planTexelTable(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                     const TypeSizes& t, const std::vector<glm::ivec2>& texels, float top, int page,
                     bool noteAfter) {
    const Rect& p = l.inspector;
    const std::string panel = "inspector";
    float margin = inspectorMargin(l);
    float width = p.w - 2 * margin;
    TexelTable table = texelTableOf(l, m, t, texels);
    float y = top;
    placeFitted(pl, table.title, {p.x + margin, y, width, p.bottom() - margin - y}, 0,
                FontFace::Sans, TEXT_DIM, panel, "table-title", "");
    y += titleHeight(table, t);
    float lh = lineHeightOf(t.number);
    pl.text({p.x + margin, y}, table.rows.front(), {FontFace::Mono, table.size, ACCENT},
            BoxKind::Text, panel, "table-header");
    y += lh;
    std::vector<size_t> starts = tablePageStarts(l, t, table, top, texels.size(), noteAfter);
    size_t at = std::min(static_cast<size_t>(std::max(0, page)), starts.size() - 1);
    size_t end = at + 1 < starts.size() ? starts[at + 1] : texels.size();
    for (size_t k = starts[at]; k < end; ++k) {
        pl.text({p.x + margin, y}, table.rows[k + 1], {FontFace::Mono, table.size, TEXT},
                BoxKind::Number, panel, "table-row");
        pl.plan.numberedTexels.push_back(texels[k]);
        y += lh;
    }
    return y;
}

}  // namespace pcf::inspector_detail
