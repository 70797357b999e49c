// inspector_table.cpp: the texel table. Where the cells are too small at this size for all of a
// texel's numbers (a 4 x 4 of receiver-plane reads at 1024x768 in presentation mode keeps only
// the weights), the page after the cells lists them, one row per texel, so that every number the
// step's words can name is on some frame at the projector's number size (issue 19).
#include <algorithm>
#include <climits>
#include <functional>
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
        const HiddenNumbers& hide = m.hidden;
        std::vector<std::string> row;
        if (form.pairTexel) {
            row = {"(" + std::to_string(texel.x) + ", " + std::to_string(texel.y) + ")"};
        } else {
            row = {std::to_string(texel.x), std::to_string(texel.y)};
        }
        row.push_back(hiddenOr(hide.bits, "", bit));
        if (form.refColumn) row.push_back(hiddenOr(hide.refs, "", fixed(tap->ref, 4)));
        row.push_back(hiddenOr(hide.depths, "", fixed(tap->depth, hide.bits ? 4 : 3)));
        // depth - ref: its sign is the bit.
        bool marginHidden = hide.bits || hide.refs || hide.depths;
        if (form.margin) row.push_back(hiddenOr(marginHidden, "", fixed(tap->depth - tap->ref, 4)));
        row.push_back(hiddenOr(hide.weights, "", weightText(tr.weights.at(texel))));
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

// One quantity of the grid form: its name in the grid's corner and its text for a texel's first
// read.
struct GridQuantity {
    std::string name;
    std::function<std::string(const TapRecord&, glm::ivec2)> text;
};

// The grid form's quantities: ref (where the reads compare with refs of their own), depth,
// d - ref (where it fits the width) and w. A question's hidden numbers (app/predict.h) as "?", as
// the rows form draws them; with the bits hidden the depths keep a fourth decimal, and depth - ref
// (its sign is the bit) goes.
std::vector<GridQuantity> gridQuantities(const Trace& tr, const HiddenNumbers& hide, bool refGrid,
                                         bool marginGrid) {
    std::vector<GridQuantity> quantities;
    bool marginHidden = hide.bits || hide.refs || hide.depths;
    if (refGrid)
        quantities.push_back({"ref", [hide](const TapRecord& t, glm::ivec2) {
                                  return hiddenOr(hide.refs, "", fixed(t.ref, 4));
                              }});
    quantities.push_back({"depth", [hide](const TapRecord& t, glm::ivec2) {
                              return hiddenOr(hide.depths, "", fixed(t.depth, hide.bits ? 4 : 3));
                          }});
    if (marginGrid)
        quantities.push_back({"d - ref", [marginHidden](const TapRecord& t, glm::ivec2) {
                                  return hiddenOr(marginHidden, "", fixed(t.depth - t.ref, 4));
                              }});
    const Trace* trace = &tr;
    quantities.push_back({"w", [hide, trace](const TapRecord&, glm::ivec2 x) {
                              return hiddenOr(hide.weights, "", weightText(trace->weights.at(x)));
                          }});
    return quantities;
}

// A grid's cells: its name and the columns i across the top, then per row j its label and each
// texel's text ("-" for a texel not read).
std::vector<std::vector<std::string>> gridCells(const Trace& tr, const GridQuantity& q,
                                                glm::ivec2 lo, glm::ivec2 size) {
    std::vector<std::vector<std::string>> cells;
    cells.push_back({q.name});
    for (int i = 0; i < size.x; ++i) cells.back().push_back(std::to_string(lo.x + i));
    for (int j = 0; j < size.y; ++j) {
        cells.push_back({std::to_string(lo.y + j)});
        for (int i = 0; i < size.x; ++i) {
            const TapRecord* tap = firstTapAt(tr, lo + glm::ivec2(i, j));
            cells.back().push_back(tap ? q.text(*tap, lo + glm::ivec2(i, j)) : "-");
        }
    }
    return cells;
}

// The grids as lines, their columns lined up under each other across all the grids: the labels
// left-aligned to the widest, the numbers one space apart, right-aligned under their texel's i.
std::vector<std::vector<std::string>> alignedGrids(
    const std::vector<std::vector<std::vector<std::string>>>& cells) {
    size_t label = 0, number = 0;
    for (const auto& grid : cells) {
        for (const auto& row : grid) {
            label = std::max(label, row.front().size());
            for (size_t c = 1; c < row.size(); ++c) number = std::max(number, row[c].size());
        }
    }
    std::vector<std::vector<std::string>> grids;
    for (const auto& grid : cells) {
        grids.emplace_back();
        for (const auto& row : grid) {
            std::string line = row.front() + std::string(label - row.front().size(), ' ');
            for (size_t c = 1; c < row.size(); ++c) {
                line += std::string(number + 1 - row[c].size(), ' ') + row[c];
            }
            grids.back().push_back(line);
        }
    }
    return grids;
}

// The grid form: each quantity of the texels (gridQuantities) as a grid laid out as the cells
// sit (row j down, column i across), its name in the corner. A 7x7 tent's 64 texels take two
// grids of nine lines instead of 64 rows. Empty when the texels do not fill their bounding box.
std::vector<std::vector<std::string>> texelGrids(const Trace& tr, const HiddenNumbers& hide,
                                                 const std::vector<glm::ivec2>& texels,
                                                 bool refGrid, bool marginGrid) {
    glm::ivec2 lo(INT32_MAX), hi(INT32_MIN);
    for (glm::ivec2 x : texels) lo = glm::min(lo, x), hi = glm::max(hi, x);
    glm::ivec2 size = hi - lo + 1;
    if (texels.empty() || static_cast<size_t>(size.x) * size.y != texels.size()) return {};
    // Every grid's cells first, so that the columns of all the grids line up under each other.
    std::vector<std::vector<std::vector<std::string>>> cells;
    for (const GridQuantity& q : gridQuantities(tr, hide, refGrid, marginGrid)) {
        cells.push_back(gridCells(tr, q, lo, size));
    }
    return alignedGrids(cells);
}

// The table as a page draws it: the title wrapped to the panel (never cut short: it says what
// the rows are and, without a ref column, the ref), then the rows (the header first) or the
// grids, at the widest type that holds them.
struct TexelTable {
    FittedText title;
    std::vector<std::string> rows;                // the rows form: the header first
    std::vector<std::vector<std::string>> grids;  // the grid form: each grid's lines
    float size = 0.0f;
    // What a page stacks: rows (one line each, under the header every page repeats) or grids.
    size_t units() const { return grids.empty() ? rows.size() - 1 : grids.size(); }
    int unitLines(size_t k) const { return grids.empty() ? 1 : static_cast<int>(grids[k].size()); }
};

float widestOf(const std::vector<std::string>& rows, float size) {
    float w = 0;
    for (const std::string& r : rows) w = std::max(w, measureText(FontFace::Mono, size, r).x);
    return w;
}

FittedText tableTitle(const InspectorModel& m, const TypeSizes& t,
                      const std::vector<glm::ivec2>& texels, bool grids, float width) {
    const Trace& tr = *m.trace;
    std::optional<float> ref = commonRef(tr);
    // (A question on the fetch counts does not count them here either.)
    std::string count = m.hidden.counts ? "" : std::to_string(texels.size()) + " ";
    std::string title = texels.size() == 1 && !m.hidden.counts
                            ? "The texel whose cell has no room for its numbers"
                        : grids ? "The numbers of the " + count +
                                      "texels whose cells have no room for them, as the "
                                      "cells sit (bits: in the cells)"
                                : "The " + count +
                                      "texels whose cells have no room for their "
                                      "numbers, row by row";
    // pcss: the texels only its blocker search read weigh 0 (the search counts blockers; the
    // filter's taps weigh the visibility). Without a word their w 0.000 reads as a tap that does
    // not count.
    bool searchOnly = methodInfo(tr.params.method).searchesBlockers &&
                      std::any_of(texels.begin(), texels.end(),
                                  [&](glm::ivec2 x) { return tr.weights.at(x) == 0.0f; });
    if (searchOnly) title += " (`w 0.000`: read by the blocker search only)";
    // (The ref as a code span: monospace like the rows, and never broken across lines.)
    title += ref ? "; `ref " + hiddenOr(m.hidden.refs, "", fixed(*ref, 4)) + "` for all:" : ":";
    return fitText(title, FontFace::Sans, t.label, t.label, width, 1e6f);
}

TexelTable texelTableOf(const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t,
                        const std::vector<glm::ivec2>& texels, bool grids) {
    float width = l.inspector.w - 2 * inspectorMargin(l);
    std::optional<float> ref = commonRef(*m.trace);
    TexelTable out;
    auto fit = [&](const std::vector<std::string>& lines) {
        out.size = t.number;
        while (widestOf(lines, out.size) > width && out.size > t.numberFloor) {
            out.size = stepDown(out.size, t.numberFloor);
        }
        return widestOf(lines, out.size) <= width;
    };
    if (grids) {
        // With d - ref where it fits, else without: the grids' lines are as wide as a grid of
        // their widest quantity.
        for (bool margin : {true, false}) {
            out.grids = texelGrids(*m.trace, m.hidden, texels, !ref, margin);
            std::vector<std::string> all;
            for (const auto& g : out.grids) all.insert(all.end(), g.begin(), g.end());
            if (!out.grids.empty() && fit(all)) break;
            out.grids.clear();
        }
    } else {
        // The first spelling whose rows fit at the numbers' size or smaller, down to their floor.
        TableForm forms[] = {{true, !ref, true}, {false, !ref, true}, {false, !ref, false}};
        for (const TableForm& form : forms) {
            out.rows = tableRows(m, texels, form);
            if (fit(out.rows)) break;
        }
    }
    out.title = tableTitle(m, t, texels, !out.grids.empty(), width);
    return out;
}

// The height of the title and the gap under it.
float titleHeight(const TexelTable& table, const TypeSizes& t) {
    return static_cast<float>(table.title.lines.size()) * table.title.lineHeight +
           lineHeightOf(t.label) * 0.5f;
}

// Lines on one page: the line pitch is the numbers' own size (a row set smaller to fit the width
// keeps it, so the count does not depend on the rows' text). Under the title (and the rows'
// header); above the line that says where the rest is, when `note`.
int linesPerPage(const InspectorLayout& l, const TypeSizes& t, const TexelTable& table, float top,
                 bool note) {
    float margin = inspectorMargin(l);
    float lh = lineHeightOf(t.number);
    float room = l.inspector.bottom() - margin - top - titleHeight(table, t);
    if (table.grids.empty()) room -= lh;
    if (note) room -= lineHeightOf(t.label) * 1.5f;
    return std::max(1, static_cast<int>(room / lh));
}

// The first unit (row or grid) of each page, filling each page before the next.
std::vector<size_t> fillPages(const TexelTable& table, int per, int last) {
    std::vector<size_t> starts{0};
    int used = 0;
    for (size_t k = 0; k < table.units(); ++k) {
        int lines = table.unitLines(k);
        if (used > 0 && used + lines > per) {
            starts.push_back(k);
            used = 0;
        }
        used += lines;
    }
    // The last page without the note holds a little more: a unit that spilled onto a page of
    // its own goes back when it fits there.
    if (starts.size() > 1) {
        int tail = 0;
        for (size_t k = starts[starts.size() - 2]; k < table.units(); ++k) {
            tail += table.unitLines(k);
        }
        if (tail <= last) starts.pop_back();
    }
    return starts;
}

// Rows shared out evenly over the fewest pages that hold them (64 rows at 21 a page: 16 on each
// of 4, not 21, 21, 21, 1); every page but the last keeps the room for the line that says where
// the rest is, the last one only when more pages follow it (noteAfter: the formula's). Grids
// fill each page in turn.
std::vector<size_t> evenPages(const TexelTable& table, int per, int last) {
    if (!table.grids.empty()) return fillPages(table, per, last);
    size_t rows = table.units();
    size_t pages = 1;
    for (size_t left = rows; left > static_cast<size_t>(last); left -= per) ++pages;
    // The first rows % pages pages take one row more. (Where that is more than a page with the
    // note holds, the last page, without it, takes the rest.)
    size_t each = rows / pages, extra = rows % pages;
    bool even = each + (extra > 0 ? 1 : 0) <= static_cast<size_t>(per);
    std::vector<size_t> starts{0};
    for (size_t k = 0; k + 1 < pages; ++k) {
        starts.push_back(starts.back() + (even ? each + (k < extra ? 1 : 0) : per));
    }
    return starts;
}

// The y under page `page`'s last line.
float pageBottom(const InspectorLayout& l, const TypeSizes& t, const TexelTable& table, float top,
                 const std::vector<size_t>& starts, size_t page) {
    (void)l;
    size_t end = page + 1 < starts.size() ? starts[page + 1] : table.units();
    int lines = table.grids.empty() ? 1 : 0;  // the rows' header
    for (size_t k = starts[page]; k < end; ++k) lines += table.unitLines(k);
    return top + titleHeight(table, t) + static_cast<float>(lines) * lineHeightOf(t.number);
}

// The paging of one form of the table: the fewest parts (its pages, and the formula's when it
// follows on pages of its own).
TablePaging pagingOf(const InspectorLayout& l, const TypeSizes& t, const TexelTable& table,
                     float top, const FormulaAfter& formula) {
    TablePaging out;
    out.grids = !table.grids.empty();
    int per = linesPerPage(l, t, table, top, true);
    int bare = linesPerPage(l, t, table, top, false);
    if (formula.pages > 0) {
        // The formula whole under the last page's lines, the pages filled to make room for it.
        out.starts = fillPages(table, per, bare);
        float y = pageBottom(l, t, table, top, out.starts, out.starts.size() - 1);
        if (formula.fitsFrom(y + t.label * 0.5f)) {
            out.formulaBelow = true;
            out.formulaTop = y + t.label * 0.5f;
            out.parts = static_cast<int>(out.starts.size());
            return out;
        }
    }
    out.starts = evenPages(table, per, formula.pages > 0 ? per : bare);
    out.parts = static_cast<int>(out.starts.size()) + formula.pages;
    return out;
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

TablePaging texelTablePaging(const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t,
                             const std::vector<glm::ivec2>& texels,
                             const std::vector<glm::ivec2>& bitTexels, float top,
                             const FormulaAfter& formula) {
    TablePaging best = pagingOf(l, t, texelTableOf(l, m, t, texels, false), top, formula);
    // The grids leave the bits to the cells: only where every texel's cell shows its bit.
    bool bits = std::all_of(texels.begin(), texels.end(), [&](glm::ivec2 x) {
        return std::find(bitTexels.begin(), bitTexels.end(), x) != bitTexels.end();
    });
    TexelTable grids = texelTableOf(l, m, t, texels, true);
    if (bits && !grids.grids.empty()) {
        TablePaging g = pagingOf(l, t, grids, top, formula);
        if (g.parts < best.parts) best = g;
    }
    return best;
}

float planTexelTable(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                     const TypeSizes& t, const std::vector<glm::ivec2>& texels, float top,
                     const TablePaging& paging, int page) {
    const Rect& p = l.inspector;
    const std::string panel = "inspector";
    float margin = inspectorMargin(l);
    float width = p.w - 2 * margin;
    TexelTable table = texelTableOf(l, m, t, texels, paging.grids);
    float y = top;
    placeFitted(pl, table.title, {p.x + margin, y, width, p.bottom() - margin - y}, 0,
                FontFace::Sans, TEXT_DIM, panel, "table-title", "");
    y += titleHeight(table, t);
    float lh = lineHeightOf(t.number);
    auto line = [&](const std::string& text, const Colour& c, BoxKind kind, const char* role) {
        pl.text({p.x + margin, y}, text, {FontFace::Mono, table.size, c}, kind, panel, role);
        y += lh;
    };
    size_t at = std::min(static_cast<size_t>(std::max(0, page)), paging.starts.size() - 1);
    size_t end = at + 1 < paging.starts.size() ? paging.starts[at + 1] : table.units();
    if (table.grids.empty()) {
        line(table.rows.front(), ACCENT, BoxKind::Text, "table-header");
        for (size_t k = paging.starts[at]; k < end; ++k) {
            line(table.rows[k + 1], TEXT, BoxKind::Number, "table-row");
            pl.plan.numberedTexels.push_back(texels[k]);
        }
        return y;
    }
    for (size_t k = paging.starts[at]; k < end; ++k) {
        line(table.grids[k].front(), ACCENT, BoxKind::Text, "grid-header");
        for (size_t r = 1; r < table.grids[k].size(); ++r) {
            line(table.grids[k][r], TEXT, BoxKind::Number, "grid-row");
        }
    }
    // A texel's numbers are whole on the page that draws its last grid.
    if (end == table.units()) {
        pl.plan.numberedTexels.insert(pl.plan.numberedTexels.end(), texels.begin(), texels.end());
    }
    return y;
}

}  // namespace pcf::inspector_detail
