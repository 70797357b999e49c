// inspector_table.cpp: the texel table. Where the cells are too small at this size for all of a
// texel's numbers (a 4 x 4 of receiver-plane reads at 1024x768 in presentation mode keeps only
// the weights), the page after the cells lists them, one row per texel, so that every number the
// step's words can name is on some frame at the projector's number size (issue 19).
#include <algorithm>

#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

namespace {

const TapRecord* firstTapOf(const Trace& tr, glm::ivec2 texel) {
    for (const TapRecord& t : tr.taps) {
        if (t.texel == texel) return &t;
    }
    return nullptr;
}

// Rows on one page: the line pitch is the numbers' own size (a row set smaller to fit the width
// keeps it, so the count does not depend on the rows' text). Under the title and the header;
// above the line that says where the rest is.
int rowsPerPage(const InspectorLayout& l, const TypeSizes& t, float top) {
    float margin = inspectorMargin(l);
    float lh = lineHeightOf(t.number);
    float room = l.inspector.bottom() - margin - top - lineHeightOf(t.label) * 3.0f - lh;
    return std::max(1, static_cast<int>(room / lh));
}

// The rows as columns padded to their widest cell (monospace), the header first.
std::vector<std::string> alignedRows(const std::vector<std::vector<std::string>>& cells) {
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
            // Numbers right-aligned, the texel left-aligned.
            std::string pad(widths[c] - cell.size(), ' ');
            line += c == 0 ? cell + pad : pad + cell;
            if (c + 1 < row.size()) line += "  ";
        }
        out.push_back(line);
    }
    return out;
}

// The table's text: the header and one row per texel, with or without the depth - ref column.
std::vector<std::string> tableRows(const InspectorModel& m, const std::vector<glm::ivec2>& texels,
                                   bool margins) {
    const Trace& tr = *m.trace;
    std::vector<std::vector<std::string>> cells;
    cells.push_back({"texel", "bit", "ref", "depth", "w"});
    if (margins) cells.back().insert(cells.back().begin() + 4, "d - ref");
    for (glm::ivec2 texel : texels) {
        const TapRecord* tap = firstTapOf(tr, texel);
        if (!tap) continue;
        // As the cell would show it (cellItems): a soft comparison's fraction for its bit.
        bool soft = tap->lit != 0.0f && tap->lit != 1.0f;
        std::string bit = soft ? fixed(tap->lit, 2) : tap->lit >= 0.5f ? "1" : "0";
        std::vector<std::string> row{
            "(" + std::to_string(texel.x) + ", " + std::to_string(texel.y) + ")", bit,
            fixed(tap->ref, 4), fixed(tap->depth, 3), fixed(tr.weights.at(texel), 3)};
        if (margins) row.insert(row.begin() + 4, fixed(tap->depth - tap->ref, 4));
        cells.push_back(std::move(row));
    }
    return alignedRows(cells);
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

int texelTablePages(const InspectorLayout& l, const TypeSizes& t, size_t rows, float top) {
    int per = rowsPerPage(l, t, top);
    return static_cast<int>((rows + static_cast<size_t>(per) - 1) / static_cast<size_t>(per));
}

float planTexelTable(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                     const TypeSizes& t, const std::vector<glm::ivec2>& texels, float top,
                     int page) {
    const Rect& p = l.inspector;
    const std::string panel = "inspector";
    float margin = inspectorMargin(l);
    float width = p.w - 2 * margin;
    // The widest type that holds a row, down to the numbers' floor; without the depth - ref
    // column when even the floor does not.
    auto widest = [](const std::vector<std::string>& rows, float size) {
        float w = 0;
        for (const std::string& r : rows) w = std::max(w, measureText(FontFace::Mono, size, r).x);
        return w;
    };
    std::vector<std::string> rows = tableRows(m, texels, true);
    float size = t.number;
    while (widest(rows, size) > width && size > t.numberFloor) size = stepDown(size, t.numberFloor);
    if (widest(rows, size) > width) rows = tableRows(m, texels, false);
    std::string title = texels.size() == 1 ? "The texel whose cell has no room for its numbers:"
                                           : "The " + std::to_string(texels.size()) +
                                                 " texels whose cells have no room for their "
                                                 "numbers, row by row:";
    title = elideText(FontFace::Sans, t.label, title, width);
    float y = top;
    pl.text({p.x + margin, y}, title, {FontFace::Sans, t.label, TEXT_DIM}, BoxKind::Text, panel,
            "table-title");
    y += lineHeightOf(t.label) * 1.5f;
    float lh = lineHeightOf(t.number);
    pl.text({p.x + margin, y}, rows.front(), {FontFace::Mono, size, ACCENT}, BoxKind::Text, panel,
            "table-header");
    y += lh;
    int per = rowsPerPage(l, t, top);
    size_t first = static_cast<size_t>(page) * static_cast<size_t>(per);
    for (size_t k = first; k < texels.size() && k < first + static_cast<size_t>(per); ++k) {
        pl.text({p.x + margin, y}, rows[k + 1], {FontFace::Mono, size, TEXT}, BoxKind::Number,
                panel, "table-row");
        pl.plan.numberedTexels.push_back(texels[k]);
        y += lh;
    }
    return y;
}

}  // namespace pcf::inspector_detail
