#include "overlay/inspector.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kernel/methods.h"
#include "kernel/trace_explain.h"

namespace pcf {

namespace {

// Colours (straight alpha).
constexpr Colour PANEL{0.10f, 0.11f, 0.14f, 1.0f};
constexpr Colour PANEL_LIGHT{0.16f, 0.17f, 0.21f, 1.0f};
constexpr Colour TEXT{0.92f, 0.93f, 0.95f, 1.0f};
constexpr Colour TEXT_DIM{0.66f, 0.69f, 0.76f, 1.0f};
constexpr Colour MONO_TEXT{0.80f, 0.92f, 1.0f, 1.0f};
constexpr Colour ACCENT{0.35f, 0.78f, 0.98f, 1.0f};
constexpr Colour POINT{0.95f, 0.20f, 0.45f, 1.0f};
constexpr Colour GATHER{0.30f, 0.90f, 0.50f, 1.0f};
constexpr Colour HW_RING{0.10f, 0.10f, 0.10f, 0.95f};
constexpr Colour PADDING{0.30f, 0.31f, 0.35f, 1.0f};
constexpr Colour CLAMPED{1.0f, 0.6f, 0.1f, 1.0f};  // a texel read clamped to the edge
constexpr Colour DARK_TEXT{0.08f, 0.08f, 0.10f, 1.0f};
constexpr Colour STATUS{0.03f, 0.03f, 0.04f, 1.0f};
constexpr Colour WEIGHT_BAR{0.95f, 0.35f, 0.25f, 0.9f};
constexpr Colour HIGHLIGHT{1.0f, 0.62f, 0.10f, 1.0f};
constexpr Colour FOOTPRINT_TINT{0.2f, 0.85f, 1.0f, 0.18f};

// A texel narrower than this on screen makes the grid's lines a moire that reads as acne: the
// grid is hidden then (the footprint tint stays).
constexpr float GRID_MIN_TEXEL_PX = 4.0f;

std::string fixed(float v, int decimals) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, static_cast<double>(v));
    return buf;
}

float lineHeightOf(float size) {
    return std::max(fontMetrics(FontFace::Sans, size).lineHeight,
                    fontMetrics(FontFace::Mono, size).lineHeight);
}

// The next smaller size on the way down to a floor.
float stepDown(float size, float floor) {
    float next = std::round(size * 0.92f);
    if (next >= size) next = size - 1.0f;
    return std::max(floor, next);
}

bool overlaps(const Rect& a, const Rect& b) { return !a.intersect(b).empty(); }

bool inside(const Rect& inner, const Rect& outer) {
    return inner.x >= outer.x - 0.01f && inner.y >= outer.y - 0.01f &&
           inner.right() <= outer.right() + 0.01f && inner.bottom() <= outer.bottom() + 0.01f;
}

// Records boxes and the draw commands that go with them.
struct Planner {
    FramePlan& plan;
    bool onTop = false;

    void op(std::function<void(Canvas&)> f) {
        (onTop ? plan.top : plan.base).push_back(std::move(f));
    }
    void box(BoxKind kind, const Rect& r, const std::string& panel, const std::string& role,
             float font = 0.0f, bool shortened = false) {
        plan.boxes.push_back({kind, r, panel, role, font, shortened});
    }
    void fill(const Rect& r, const Colour& c) {
        op([=](Canvas& cv) { cv.fillRect(r, c); });
    }
    // Text at a whole-pixel position; returns its measured box (what Canvas::text will cover).
    Rect measure(glm::vec2 pos, const std::string& s, const TextStyle& st) const {
        glm::vec2 size = measureText(st.face, st.pixelSize, s);
        float x = std::round(pos.x);
        if (st.align == TextAlign::Center) x = std::round(pos.x - size.x * 0.5f);
        if (st.align == TextAlign::Right) x = std::round(pos.x - size.x);
        return {x, std::round(pos.y), size.x, size.y};
    }
    Rect text(glm::vec2 pos, const std::string& s, const TextStyle& st, BoxKind kind,
              const std::string& panel, const std::string& role, bool shortened = false) {
        Rect r = measure(pos, s, st);
        TextStyle left = st;
        left.align = TextAlign::Left;
        glm::vec2 at = r.position();
        op([=](Canvas& cv) { cv.text(at, s, left); });
        box(kind, r, panel, role, st.pixelSize, shortened);
        return r;
    }
};

// ---- Text blocks that fit: wrap, then smaller type down to a floor, then pages. ----

struct FitLine {
    std::string text;
    bool mono = false;  // a preformatted line: monospace, spaces kept, never rewrapped
};

struct FittedText {
    float size = 0.0f;
    float lineHeight = 0.0f;
    std::vector<FitLine> lines;
    int linesPerPage = 0;
    int pages = 1;
    bool stepped = false;  // drawn below its starting size
};

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
    auto cellsOf = [](const std::string& row, size_t& indent) {
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
    };
    for (size_t k = 0; k < lines.size();) {
        size_t end = k;
        while (end < lines.size() && preformatted(lines[end])) ++end;
        if (end - k >= 2) {
            std::vector<std::vector<std::string>> rows;
            std::vector<size_t> indents;
            bool table = true;
            for (size_t r = k; r < end; ++r) {
                size_t indent = 0;
                rows.push_back(cellsOf(lines[r], indent));
                indents.push_back(indent);
                if (rows.back().size() < 2) table = false;
            }
            if (table) {
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
                    lines[k + r] = out;
                }
            }
        }
        k = std::max(end, k + 1);
    }
    std::string out;
    for (size_t k = 0; k < lines.size(); ++k) out += (k ? "\n" : "") + lines[k];
    return out;
}

std::vector<FitLine> wrapBlock(std::string_view text, FontFace face, float size, float width,
                               bool& tooWide) {
    std::vector<FitLine> out;
    size_t start = 0;
    std::string prose;  // consecutive prose lines form one paragraph source ('\n' kept)
    auto flushProse = [&]() {
        if (prose.empty()) return;
        for (std::string& l : wrapText(face, size, prose, width))
            out.push_back({std::move(l), false});
        prose.clear();
    };
    while (true) {
        size_t end = text.find('\n', start);
        std::string_view line =
            text.substr(start, end == std::string_view::npos ? end : end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (preformatted(line)) {
            flushProse();
            std::string row(line);
            for (char& ch : row) {
                if (ch == '\t') ch = ' ';
            }
            float w = measureText(FontFace::Mono, size, row).x;
            if (w > width) {
                // Too wide for the box: wrapped at its spaces, continuation lines indented
                // further (a table row this wide has no columns to keep at this size).
                tooWide = true;
                size_t indent = row.find_first_not_of(' ');
                if (indent == std::string::npos) indent = 0;
                std::string lead(indent, ' ');
                float leadW = measureText(FontFace::Mono, size, lead + "  ").x;
                std::vector<std::string> parts =
                    wrapText(FontFace::Mono, size, row.substr(indent),
                             std::max(8.0f * size * 0.6f, width - leadW));
                for (size_t k = 0; k < parts.size(); ++k) {
                    out.push_back({(k == 0 ? lead : lead + "  ") + parts[k], true});
                }
                if (end == std::string_view::npos) break;
                start = end + 1;
                continue;
            }
            out.push_back({row, true});
        } else {
            if (line.empty()) {
                // A paragraph gap: one empty line.
                flushProse();
                if (!out.empty() && !out.back().text.empty()) out.push_back({"", false});
            } else {
                if (!prose.empty()) prose += '\n';
                prose += std::string(line);
            }
        }
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    flushProse();
    // Leading and trailing empty lines take room and say nothing.
    while (!out.empty() && out.back().text.empty()) out.pop_back();
    while (!out.empty() && out.front().text.empty()) out.erase(out.begin());
    if (out.empty()) out.push_back({"", false});
    return out;
}

FittedText fitText(std::string_view text, FontFace face, float start, float floor, float width,
                   float height) {
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
        f.linesPerPage = static_cast<int>(f.lines.size());
        f.pages = 1;
    } else {
        // One line of every page is the "more" mark's.
        f.linesPerPage = std::max(1, fitting - 1);
        f.pages = (static_cast<int>(f.lines.size()) + f.linesPerPage - 1) / f.linesPerPage;
    }
    return f;
}

// Draws page `page` of a fitted block at the top-left of `area`, with the "more" mark on the
// last line of the area when there are more pages. Returns the height used.
float placeFitted(Planner& pl, const FittedText& f, const Rect& area, int page, FontFace face,
                  const Colour& colour, const std::string& panel, const std::string& role,
                  const std::string& moreHint) {
    page = std::clamp(page, 0, f.pages - 1);
    size_t first = static_cast<size_t>(page * f.linesPerPage);
    size_t last = std::min(f.lines.size(), first + static_cast<size_t>(f.linesPerPage));
    float y = area.y;
    float widest = 0.0f;
    for (size_t k = first; k < last; ++k) {
        const FitLine& line = f.lines[k];
        if (!line.text.empty()) {
            FontFace lf = line.mono ? FontFace::Mono : face;
            TextStyle st{lf, f.size, line.mono ? MONO_TEXT : colour};
            glm::vec2 at{std::round(area.x), std::round(y)};
            std::string s = line.text;
            pl.op([=](Canvas& cv) { cv.text(at, s, st); });
            widest = std::max(widest, measureText(lf, f.size, s).x);
        }
        y += f.lineHeight;
    }
    float used = y - area.y;
    pl.box(BoxKind::Text, {std::round(area.x), std::round(area.y), std::min(widest, area.w), used},
           panel, role, f.size, f.pages > 1);
    if (f.pages > 1) {
        std::string more =
            page + 1 < f.pages
                ? "more " + moreHint + " (" + std::to_string(page + 1) + "/" +
                      std::to_string(f.pages) + ")"
                : "(" + std::to_string(page + 1) + "/" + std::to_string(f.pages) + ")";
        float ms = std::max(10.0f, std::round(f.size * 0.85f));
        Rect r = pl.measure({area.right(), area.bottom() - lineHeightOf(ms)}, more,
                            {FontFace::Sans, ms, ACCENT, TextAlign::Right});
        // The mark has the area's last line to itself (linesPerPage left it free).
        r.y = std::max(r.y, y);
        pl.fill(r.expanded(2), Colour{0.35f, 0.78f, 0.98f, 0.18f});
        glm::vec2 at = r.position();
        pl.op([=](Canvas& cv) { cv.text(at, more, {FontFace::Sans, ms, ACCENT}); });
        pl.box(BoxKind::Mark, r, panel, "more", ms);
    }
    return used;
}

// ---- The scene: picked pixel, its label, the texel grid on the receiver. ----

void planScene(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t) {
    glm::vec2 origin = l.scene.position();
    glm::vec2 centre = origin + glm::vec2(m.pixel) + 0.5f;
    float lineWidth = l.presentation ? 3.0f : 2.0f;
    Rect scene = l.scene;
    pl.op([=](Canvas& c) { c.pushClip(scene); });
    glm::ivec2 region = m.lightSpaceSize;
    if (m.trace && m.lightSpace && region.x > 0 &&
        m.lightSpace->size() == static_cast<size_t>(region.x) * region.y * 4) {
        const std::vector<float>& ls = *m.lightSpace;
        glm::vec2 mapSize(m.trace->mapSize);
        int radius = gridRadius(m.sceneSize);
        auto texelAt = [&](int x, int y, glm::ivec2& out) {
            if (x < 0 || y < 0 || x >= m.sceneSize.x || y >= m.sceneSize.y) return false;
            glm::ivec2 r = glm::ivec2(x, y) - m.lightSpaceOrigin;
            if (r.x < 0 || r.y < 0 || r.x >= region.x || r.y >= region.y) return false;
            size_t k = (static_cast<size_t>(r.y) * region.x + r.x) * 4;
            if (ls[k + 3] != 1.0f) return false;
            out = glm::ivec2(glm::floor(glm::vec2(ls[k], ls[k + 1]) * mapSize));
            return true;
        };
        // How many screen pixels a texel spans here: pixels per texel change along the row and
        // the column through the picked pixel (the smaller of the two).
        auto spanAlong = [&](glm::ivec2 dir) {
            int valid = 0, changes = 0;
            glm::ivec2 prev{0}, cur{0};
            bool havePrev = false;
            for (int k = -radius; k <= radius; ++k) {
                glm::ivec2 q = m.pixel + dir * k;
                if (!texelAt(q.x, q.y, cur)) {
                    havePrev = false;
                    continue;
                }
                ++valid;
                if (havePrev && cur != prev) ++changes;
                prev = cur;
                havePrev = true;
            }
            return valid == 0 ? 0.0f : static_cast<float>(valid) / static_cast<float>(changes + 1);
        };
        float texelPx = std::min(spanAlong({1, 0}), spanAlong({0, 1}));
        bool drawEdges = m.grid && texelPx >= GRID_MIN_TEXEL_PX;
        pl.plan.gridShown = drawEdges;
        Neighbourhood n = neighbourhoodOf(*m.trace);
        enum Kind { NONE, FOOTPRINT_EDGE, EDGE, FOOTPRINT };
        const Colour colours[] = {Colour{0.0f}, Colour{0.1f, 0.9f, 1.0f, 0.95f},
                                  Colour{0.05f, 0.05f, 0.1f, 0.35f}, FOOTPRINT_TINT};
        // Per row, runs of pixels of one kind become one rect.
        std::vector<std::pair<Rect, Colour>> runs;
        for (int y = m.pixel.y - radius; y <= m.pixel.y + radius; ++y) {
            Kind runKind = NONE;
            int runStart = 0;
            for (int x = m.pixel.x - radius; x <= m.pixel.x + radius + 1; ++x) {
                Kind kind = NONE;
                glm::ivec2 tx, left, up;
                if (x <= m.pixel.x + radius && texelAt(x, y, tx)) {
                    bool inFootprint = tx.x >= n.origin.x && tx.y >= n.origin.y &&
                                       tx.x < n.origin.x + n.size.x && tx.y < n.origin.y + n.size.y;
                    bool edge = drawEdges && ((texelAt(x - 1, y, left) && left != tx) ||
                                              (texelAt(x, y - 1, up) && up != tx));
                    kind = edge ? (inFootprint ? FOOTPRINT_EDGE : EDGE)
                                : (inFootprint ? FOOTPRINT : NONE);
                }
                if (kind != runKind) {
                    if (runKind != NONE) {
                        runs.push_back({{origin.x + runStart, origin.y + y,
                                         static_cast<float>(x - runStart), 1.0f},
                                        colours[runKind]});
                    }
                    runKind = kind;
                    runStart = x;
                }
            }
        }
        pl.op([runs = std::move(runs)](Canvas& c) {
            for (const auto& [r, col] : runs) c.fillRect(r, col);
        });
    }
    float ringR = std::max(7.0f, 9.0f * l.scale);
    pl.op([=](Canvas& c) {
        c.ring(centre, ringR, lineWidth, Colour{0, 0, 0, 0.8f});
        c.ring(centre, ringR, lineWidth * 0.5f, POINT);
        c.fillRect({centre.x - 0.5f, centre.y - 0.5f, 1.0f, 1.0f}, POINT);
        c.popClip();
    });
    Rect ring{centre.x - ringR - lineWidth, centre.y - ringR - lineWidth, 2 * (ringR + lineWidth),
              2 * (ringR + lineWidth)};
    pl.box(BoxKind::Mark, ring.intersect(l.scene), "scene", "picked-pixel");
    std::string label = "pixel (" + std::to_string(m.pixel.x) + ", " + std::to_string(m.pixel.y) +
                        ")" + (m.trace ? "" : ": no shadow receiver here");
    TextStyle st{FontFace::Sans, t.label, TEXT};
    // Beside the ring, in the first corner where the whole label stays in the scene.
    Rect size = pl.measure({0, 0}, label, st);
    float gap = ringR + lineWidth + 4.0f;
    const glm::vec2 candidates[] = {{centre.x + gap, centre.y + gap * 0.3f},
                                    {centre.x - gap - size.w, centre.y + gap * 0.3f},
                                    {centre.x + gap, centre.y - gap * 0.3f - size.h},
                                    {centre.x - gap - size.w, centre.y - gap * 0.3f - size.h}};
    Rect scenePad = l.scene.expanded(-4.0f);
    glm::vec2 at = candidates[0];
    bool placed = false;
    for (glm::vec2 c : candidates) {
        Rect r{std::round(c.x), std::round(c.y), size.w, size.h};
        if (inside(r, scenePad)) {
            at = r.position();
            placed = true;
            break;
        }
    }
    if (!placed) {
        at.x = std::clamp(at.x, scenePad.x, std::max(scenePad.x, scenePad.right() - size.w));
        at.y = std::clamp(at.y, scenePad.y, std::max(scenePad.y, scenePad.bottom() - size.h));
    }
    bool fits = size.w <= scenePad.w;
    std::string shown = fits ? label : elideText(FontFace::Sans, t.label, label, scenePad.w);
    Rect r = pl.measure(at, shown, st);
    pl.fill(r.expanded(3).intersect(l.scene), Colour{0, 0, 0, 0.6f});
    pl.text(at, shown, st, BoxKind::Label, "scene", "pixel-label", !fits);
}

// ---- The inspector: header, the cells, the legend, the formula. ----

struct Header {
    std::string title;
    std::string result;
    std::vector<std::string> counts;  // wrapped
    bool resultOnOwnLine = false;
    float height = 0.0f;
};

Header headerOf(const InspectorLayout& l, const Trace& tr, const TypeSizes& t, float width) {
    Header h;
    const MethodInfo& info = methodInfo(tr.params.method);
    h.title = std::string(info.name);
    if (info.usesKernel) h.title += "  N = " + std::to_string(tr.params.kernel);
    if (info.usesRadius) h.title += "  R = " + formatNumber(tr.params.radius);
    h.result = "visibility = " + formatNumber(tr.visibility);
    float tw = measureText(FontFace::Mono, t.head, h.title).x;
    float rw = measureText(FontFace::Mono, t.head, h.result).x;
    h.resultOnOwnLine = tw + rw + t.head > width;
    auto plural = [](int n, const char* one, const char* many) {
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    std::string counts = plural(tr.counts.texels, "texel read", "texel reads");
    if (tr.counts.gathers) counts += ", " + plural(tr.counts.gathers, "gather", "gathers");
    if (tr.counts.hwTaps)
        counts += ", " + plural(tr.counts.hwTaps, "hardware tap", "hardware taps");
    counts += "\nuv (" + fixed(tr.uv.x, 4) + ", " + fixed(tr.uv.y, 4) + ")  ref " +
              fixed(tr.ref, 4) + "  bias " + std::string(biasName(tr.bias.mode));
    // Two lines when one does not hold them, and each wraps again if need be.
    std::string oneLine = counts;
    std::replace(oneLine.begin(), oneLine.end(), '\n', ' ');
    oneLine.insert(oneLine.find(" uv ("), "  ");
    if (measureText(FontFace::Mono, t.number, oneLine).x <= width) {
        h.counts = {oneLine};
    } else {
        h.counts = wrapText(FontFace::Mono, t.number, counts, width);
    }
    float headLh = lineHeightOf(t.head);
    h.height = headLh * (h.resultOnOwnLine ? 2.0f : 1.0f) + 4.0f +
               lineHeightOf(t.number) * static_cast<float>(h.counts.size());
    (void)l;
    return h;
}

float marginOf(const InspectorLayout& l) { return std::max(8.0f, std::round(18.0f * l.scale)); }

// The cell geometry the inspector uses for a trace; shared by the plan and neighbourhoodArea.
struct Grid {
    Neighbourhood full;
    Neighbourhood view;
    Rect area;  // the cells
    float cell = 0.0f;
    float number = 0.0f;  // the cells' number size
    float bit = 0.0f;
    float pad = 0.0f;  // inset of the numbers from the cell's edge (gather outlines live there)
    float bar = 0.0f;  // weight bar height
    Rect laneTop, laneLeft, laneRight, laneBottom;
    float bottom = 0.0f;  // below the bottom lane
};

float lineOf(const InspectorLayout& l) {
    return l.presentation ? 3.0f : std::max(1.0f, std::round(l.scale));
}

// highlight: the fetch (0-based) the step talks about; a windowed view keeps its texels in view.
Grid gridOf(const InspectorLayout& l, const Trace& tr, const TypeSizes& t, int highlight = -1) {
    Grid g;
    const Rect& p = l.inspector;
    float margin = marginOf(l);
    float width = p.w - 2 * margin;
    Header h = headerOf(l, tr, t, width);
    float top = p.y + margin + h.height + t.label * 0.5f;
    g.full = neighbourhoodOf(tr);
    float line = lineOf(l);
    // The cell's border band: the gather outline (inset `line`, `line + 1` wide), then 2 px.
    g.pad = 2.0f * line + 3.0f;
    auto cellFor = [&](float number) {
        float bit = std::round(number * 1.5f);
        float blockW = measureText(FontFace::Mono, number, "d 0.000").x;
        float blockH = lineHeightOf(bit) + 2.0f * lineHeightOf(number);
        float bar = std::max(3.0f, number * 0.25f);
        // Room for the block and, beside it, for the marks a cell may hold.
        return std::max(blockW + 2.0f * g.pad, blockH + bar + 2.0f * g.pad) * 1.08f;
    };
    int lastRow = std::max(std::abs(g.full.origin.y), std::abs(g.full.origin.y + g.full.size.y));
    float labelW = measureText(FontFace::Mono, t.label, "j=-" + std::to_string(lastRow)).x + 8.0f;
    float laneH = lineHeightOf(t.label) + 12.0f;
    float fyW = measureText(FontFace::Mono, t.label, "fy 0.00").x + 16.0f;
    // The grid takes at most this share of the panel's height: the legend and the formula need
    // the rest.
    float maxH = p.bottom() - margin - top - laneH * 2.0f -
                 std::max(4.0f * lineHeightOf(t.number), 0.22f * p.h);
    float side = std::max(40.0f, std::min(width - labelW - fyW, maxH));
    int cellsFull = std::max(g.full.size.x, g.full.size.y);
    // Whole neighbourhood at the largest number size that fits, down to the floor; else a window
    // of it at the starting size.
    float number = t.number;
    while (cellFor(number) * cellsFull > side && number > t.numberFloor) {
        number = stepDown(number, t.numberFloor);
    }
    int cells = cellsFull;
    if (cellFor(number) * cellsFull > side) {
        number = t.number;
        cells = std::clamp(static_cast<int>(side / cellFor(number)), 2, cellsFull);
    }
    g.number = number;
    g.bit = std::round(number * 1.5f);
    g.bar = std::max(3.0f, number * 0.25f);
    g.view = g.full;
    if (cells < cellsFull) {
        glm::vec2 pt = tr.uv * glm::vec2(tr.mapSize);
        for (int a = 0; a < 2; ++a) {
            int k = std::min(cells, g.full.size[a]);
            int lo = g.full.origin[a];
            int hi = g.full.origin[a] + g.full.size[a] - k;
            int want = static_cast<int>(std::floor(pt[a])) - (k - 1) / 2;
            // Keep the base 2 x 2 in view.
            want = std::min(want, tr.pos.base[a]);
            want = std::max(want, tr.pos.base[a] + 2 - k);
            if (highlight >= 0 && highlight < static_cast<int>(tr.fetches.size())) {
                // The 2 x 2 the highlighted fetch reads (one texel for a point read).
                const FetchRecord& f = tr.fetches[static_cast<size_t>(highlight)];
                float q = f.uv[a] * static_cast<float>(tr.mapSize[a]);
                bool point = f.kind == PCF_FETCH_POINT;
                int first = static_cast<int>(std::floor(point ? q : q - 0.5f));
                int last = point ? first : first + 1;
                want = std::min(want, first);
                want = std::max(want, last + 1 - k);
            }
            g.view.origin[a] = std::clamp(want, lo, std::max(lo, hi));
            g.view.size[a] = k;
        }
    }
    int viewCells = std::max(g.view.size.x, g.view.size.y);
    g.cell = std::floor(side / static_cast<float>(viewCells));
    // Big cells (few texels) get bigger numbers, as long as the block still fits beside marks.
    float grown = std::min(std::round(g.cell * 0.12f), std::round(t.number * 1.8f));
    while (grown > g.number && cellFor(grown) > g.cell) grown -= 1.0f;
    if (grown > g.number) {
        g.number = grown;
        g.bit = std::round(grown * 1.5f);
        g.bar = std::max(3.0f, grown * 0.25f);
    }
    float gridW = g.cell * g.view.size.x;
    float gridH = g.cell * g.view.size.y;
    float x0 = std::round(p.x + margin + labelW);
    float y0 = std::round(top + laneH);
    g.area = {x0, y0, gridW, gridH};
    g.laneTop = {x0, y0 - laneH, gridW, laneH};
    g.laneLeft = {p.x + margin, y0, labelW, gridH};
    g.laneRight = {x0 + gridW, y0, fyW, gridH};
    g.laneBottom = {x0, y0 + gridH, gridW, laneH};
    g.bottom = y0 + gridH + laneH;
    return g;
}

const TapRecord* firstTapAt(const Trace& tr, glm::ivec2 texel) {
    for (const TapRecord& tp : tr.taps) {
        if (tp.texel == texel) return &tp;
    }
    return nullptr;
}

glm::vec2 viewPoint(const Grid& g, glm::vec2 texelPos) {
    return {g.area.x + (texelPos.x - static_cast<float>(g.view.origin.x)) * g.cell,
            g.area.y + (texelPos.y - static_cast<float>(g.view.origin.y)) * g.cell};
}

struct LegendNeeds {
    bool highlight = false, weightBar = false, dots = false, rings = false, gathers = false,
         fraction = false, baseCentre = false, padding = false, footprint = false;
    bool clamped = false;  // a texel read clamped to the edge (any finite uv)
};

void planCells(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const Grid& g,
               const TypeSizes& t, LegendNeeds& legend, int& hiddenCells) {
    const Trace& tr = *m.trace;
    const std::string panel = "inspector";
    float line = lineOf(l);
    glm::vec2 size(tr.mapSize);
    Rect area = g.area;
    // Marks first: they sit where the math puts them; the numbers then find room beside them.
    std::vector<Rect> marks;
    auto mark = [&](const Rect& r, const std::string& role) {
        Rect clipped = r.intersect(area);
        if (clipped.empty()) return;
        marks.push_back(clipped);
        pl.box(BoxKind::Mark, clipped, panel, role);
    };
    float maxWeight = 0.0f;
    for (float w : tr.weights.values) maxWeight = std::max(maxWeight, w);
    // Cells, fills and weight bars.
    for (int j = 0; j < g.view.size.y; ++j) {
        for (int i = 0; i < g.view.size.x; ++i) {
            glm::ivec2 texel = g.view.origin + glm::ivec2(i, j);
            Rect r = texelCellRect(g.view, area, texel);
            const TapRecord* tap = firstTapAt(tr, texel);
            float weight = tr.weights.at(texel);
            Colour fill = !tap ? PADDING : tap->lit >= 0.5f ? LIT_COLOUR : SHADOWED_COLOUR;
            if (tap && weight == 0.0f) fill = glm::mix(fill, PADDING, 0.55f);
            if (!tap) legend.padding = true;
            pl.fill(r, fill);
            // A tap whose texel lay outside the map, read clamped to the edge: an orange frame
            // in the cell's border band, where no number goes.
            bool clamped = std::any_of(tr.taps.begin(), tr.taps.end(), [&](const TapRecord& t) {
                return t.texel == texel && t.clamped;
            });
            if (clamped) {
                legend.clamped = true;
                Rect frame = r.expanded(-line);
                pl.op([frame, line](Canvas& c) { c.strokeRect(frame, line, CLAMPED); });
            }
            if (tap && maxWeight > 0.0f && weight > 0.0f) {
                float band = 2.0f * line + 1.0f;
                Rect bar{r.x + band, r.bottom() - g.bar - band,
                         (r.w - 2 * band) * weight / maxWeight, g.bar};
                pl.fill(bar, WEIGHT_BAR);
                mark(bar, "weight-bar");
                legend.weightBar = true;
            }
        }
    }
    // Grid lines (cell borders: the numbers stay g.pad inside them).
    {
        std::vector<std::pair<glm::vec2, glm::vec2>> lines;
        for (int i = 0; i <= g.view.size.x; ++i) {
            float x = area.x + i * g.cell;
            lines.push_back({{x, area.y}, {x, area.bottom()}});
        }
        for (int j = 0; j <= g.view.size.y; ++j) {
            float y = area.y + j * g.cell;
            lines.push_back({{area.x, y}, {area.right(), y}});
        }
        pl.op([lines, line](Canvas& c) {
            for (const auto& [a, b] : lines) c.line(a, b, line, Colour{0, 0, 0, 0.9f});
        });
    }
    // Texel indices in the lanes above and to the left.
    for (int i = 0; i < g.view.size.x; ++i) {
        pl.text({area.x + (i + 0.5f) * g.cell, g.laneTop.y + 4.0f},
                "i=" + std::to_string(g.view.origin.x + i),
                {FontFace::Mono, t.label, TEXT_DIM, TextAlign::Center}, BoxKind::Label, panel,
                "texel-index");
    }
    for (int j = 0; j < g.view.size.y; ++j) {
        pl.text({g.laneLeft.right() - 6.0f,
                 area.y + (j + 0.5f) * g.cell - lineHeightOf(t.label) * 0.5f},
                "j=" + std::to_string(g.view.origin.y + j),
                {FontFace::Mono, t.label, TEXT_DIM, TextAlign::Right}, BoxKind::Label, panel,
                "texel-index");
    }
    // The fetches: gathers as outlines in the cells' border band, hardware taps as small rings,
    // lookups and point reads as dots, each at the uv the instruction sampled.
    std::vector<std::function<void(Canvas&)>> markOps;
    float dotR = std::max(3.0f, std::round(g.cell * 0.04f));
    for (size_t fi = 0; fi < tr.fetches.size(); ++fi) {
        const FetchRecord& fr = tr.fetches[fi];
        glm::vec2 at = viewPoint(g, fr.uv * size);
        bool highlit = static_cast<int>(fi) == m.highlightFetch;
        if (highlit) legend.highlight = true;
        if (fr.kind == PCF_FETCH_GATHER) {
            glm::ivec2 corner(glm::floor(fr.uv * size - 0.5f));
            Rect a = texelCellRect(g.view, area, corner);
            Rect b = texelCellRect(g.view, area, corner + glm::ivec2(1));
            Rect block = Rect{a.x, a.y, b.right() - a.x, b.bottom() - a.y}.expanded(-line);
            float w = line + 1.0f + (highlit ? 2.0f : 0.0f);
            Colour gatherColour = highlit ? HIGHLIGHT : GATHER;
            // Four edges, each inside the border band of its cells, clipped to the view.
            Rect edges[] = {{block.x, block.y, block.w, w},
                            {block.x, block.bottom() - w, block.w, w},
                            {block.x, block.y, w, block.h},
                            {block.right() - w, block.y, w, block.h}};
            for (const Rect& e : edges) {
                Rect ce = e.intersect(area);
                if (ce.empty()) continue;
                markOps.push_back([=](Canvas& c) { c.fillRect(ce, gatherColour); });
                mark(ce, "gather-outline");
            }
            legend.gathers = true;
        } else if (fr.kind == PCF_FETCH_HW) {
            float rr = std::max(5.0f, std::round(g.cell * 0.07f));
            if (!area.contains(at)) continue;
            markOps.push_back([=](Canvas& c) {
                c.ring(at, rr, highlit ? line + 2.0f : line, highlit ? HIGHLIGHT : HW_RING);
                c.circle(at, std::max(2.0f, rr * 0.4f), ACCENT);
            });
            mark({at.x - rr - line, at.y - rr - line, 2 * (rr + line), 2 * (rr + line)}, "hw-tap");
            legend.rings = true;
        } else if (tr.params.method == PCF_POISSON || tr.params.method == PCF_NAIVE ||
                   tr.params.method == PCF_HW) {
            if (!area.contains(at)) continue;
            markOps.push_back([=](Canvas& c) {
                if (highlit) c.circle(at, dotR + 2.0f, HIGHLIGHT);
                c.circle(at, dotR, ACCENT);
            });
            mark({at.x - dotR - 1, at.y - dotR - 1, 2 * dotR + 2, 2 * dotR + 2}, "lookup");
            legend.dots = true;
        }
    }
    // The lookup point and its base texel's centre.
    glm::vec2 pTex = tr.uv * size;
    glm::vec2 point = viewPoint(g, pTex);
    glm::vec2 baseCentre = viewPoint(g, glm::vec2(tr.pos.base) + 0.5f);
    float pr = std::max(4.0f, std::round(g.cell * 0.05f));
    bool showFrac = tr.params.method != PCF_NEAREST && tr.params.method != PCF_POISSON;
    if (area.contains(point)) {
        markOps.push_back([=](Canvas& c) {
            c.circle(point, pr + 1.5f, Colour{0, 0, 0, 0.9f});
            c.circle(point, pr, POINT);
        });
        mark({point.x - pr - 2, point.y - pr - 2, 2 * pr + 4, 2 * pr + 4}, "lookup-point");
    }
    // The base texel's centre is not marked in the cell (its bit sits there): the fx and fy
    // brackets in the lanes start at its column and row.
    // Numbers: each cell's block goes where no mark is.
    Colour inkLit = DARK_TEXT;
    for (int j = 0; j < g.view.size.y; ++j) {
        for (int i = 0; i < g.view.size.x; ++i) {
            glm::ivec2 texel = g.view.origin + glm::ivec2(i, j);
            Rect r = texelCellRect(g.view, area, texel);
            const TapRecord* tap = firstTapAt(tr, texel);
            bool inMap =
                texel.x >= 0 && texel.y >= 0 && texel.x < tr.mapSize.x && texel.y < tr.mapSize.y;
            Colour ink = tap && tap->lit >= 0.5f ? inkLit : TEXT;
            struct Item {
                std::string text;
                float size;
                std::string role;
            };
            std::vector<Item> all;
            // The bit; a soft comparison's fraction (bias soft) in its place.
            bool soft = tap && tap->lit != 0.0f && tap->lit != 1.0f;
            if (tap) {
                all.push_back(
                    {soft ? fixed(tap->lit, 2) : tap->lit >= 0.5f ? "1" : "0", g.bit, "cell-bit"});
            }
            // The tap's own ref where the bias gave it one (receiver plane), under its bit.
            bool ownRef = tap && tap->ref != tr.ref;
            if (ownRef) all.push_back({"r " + fixed(tap->ref, 4), g.number, "cell-ref"});
            bool hasDepth = inMap;
            if (inMap) {
                float depth = m.map ? m.map->depth(texel.x, texel.y) : (tap ? tap->depth : 0.0f);
                all.push_back({"d " + fixed(depth, 3), g.number, "cell-depth"});
            }
            if (tap)
                all.push_back({"w " + fixed(tr.weights.at(texel), 3), g.number, "cell-weight"});
            // Variants from whole to nothing: all, without depth, weight alone.
            std::vector<std::vector<Item>> variants{all};
            if (tap && hasDepth) {
                std::vector<Item> noDepth;
                for (const Item& it : all) {
                    if (it.role != "cell-depth") noDepth.push_back(it);
                }
                variants.push_back(noDepth);
            }
            if (tap) variants.push_back({all.back()});
            variants.push_back({});
            Rect inner = r.expanded(-g.pad);
            inner.h -= g.bar + 1.0f;
            std::vector<Rect> cellMarks;
            for (const Rect& mk : marks) {
                if (overlaps(mk, r)) cellMarks.push_back(mk.expanded(2.0f));
            }
            bool placed = false;
            for (size_t v = 0; v < variants.size() && !placed; ++v) {
                const std::vector<Item>& items = variants[v];
                if (items.empty()) {
                    if (!all.empty()) ++hiddenCells;
                    placed = true;
                    break;
                }
                float bw = 0, bh = 0;
                for (const Item& it : items) {
                    bw = std::max(bw, measureText(FontFace::Mono, it.size, it.text).x);
                    bh += lineHeightOf(it.size);
                }
                if (bw > inner.w || bh > inner.h) continue;
                float cx = inner.x + (inner.w - bw) * 0.5f, cy = inner.y + (inner.h - bh) * 0.5f;
                float rx = inner.right() - bw, by = inner.bottom() - bh;
                const glm::vec2 spots[] = {{cx, cy},      {cx, inner.y}, {cx, by},
                                           {inner.x, cy}, {rx, cy},      {inner.x, inner.y},
                                           {rx, inner.y}, {inner.x, by}, {rx, by}};
                for (glm::vec2 s : spots) {
                    Rect blk{std::round(s.x), std::round(s.y), bw, bh};
                    bool free = std::none_of(cellMarks.begin(), cellMarks.end(),
                                             [&](const Rect& mk) { return overlaps(mk, blk); });
                    if (!free) continue;
                    float y = blk.y;
                    for (const Item& it : items) {
                        pl.text({blk.x + bw * 0.5f, y}, it.text,
                                {FontFace::Mono, it.size, ink, TextAlign::Center}, BoxKind::Number,
                                panel, it.role);
                        y += lineHeightOf(it.size);
                    }
                    placed = true;
                    break;
                }
            }
        }
    }
    for (auto& f : markOps) pl.op(std::move(f));
    // fx and fy in the lanes under and beside the cells: a bracket from the base texel's centre
    // to the lookup point, with its value.
    if (showFrac) {
        legend.fraction = true;
        float x0 = std::clamp(baseCentre.x, area.x, area.right());
        float x1 = std::clamp(point.x, area.x, area.right());
        float y0 = std::clamp(baseCentre.y, area.y, area.bottom());
        float y1 = std::clamp(point.y, area.y, area.bottom());
        float lw = std::max(2.0f, line);
        float ly = g.laneBottom.y + 4.0f;
        float lx = g.laneRight.x + 5.0f;
        float tick = 6.0f;
        Rect hb{std::min(x0, x1) - lw, ly, std::abs(x1 - x0) + 2 * lw, tick};
        Rect vb{lx, std::min(y0, y1) - lw, tick, std::abs(y1 - y0) + 2 * lw};
        pl.op([=](Canvas& c) {
            c.line({x0, ly + tick * 0.5f}, {x1, ly + tick * 0.5f}, lw, POINT);
            c.line({x0, ly}, {x0, ly + tick}, lw, POINT);
            c.line({x1, ly}, {x1, ly + tick}, lw, POINT);
            c.line({lx + tick * 0.5f, y0}, {lx + tick * 0.5f, y1}, lw, POINT);
            c.line({lx, y0}, {lx + tick, y0}, lw, POINT);
            c.line({lx, y1}, {lx + tick, y1}, lw, POINT);
        });
        pl.box(BoxKind::Mark, hb, panel, "fx-bracket");
        pl.box(BoxKind::Mark, vb, panel, "fy-bracket");
        std::string fx = "fx " + fixed(tr.pos.frac.x, 2);
        std::string fy = "fy " + fixed(tr.pos.frac.y, 2);
        TextStyle fst{FontFace::Mono, t.label, POINT, TextAlign::Left};
        Rect fxs = pl.measure({0, 0}, fx, fst);
        float fxX = std::clamp((x0 + x1) * 0.5f - fxs.w * 0.5f, g.laneBottom.x,
                               g.laneBottom.right() - fxs.w);
        pl.text({fxX, ly + tick + 1.0f}, fx, fst, BoxKind::Label, panel, "fx");
        float fyY = std::clamp((y0 + y1) * 0.5f - fxs.h * 0.5f, g.laneRight.y,
                               g.laneRight.bottom() - fxs.h);
        pl.text({lx + tick + 3.0f, fyY}, fy, fst, BoxKind::Label, panel, "fy");
    }
}

std::string formulaText(const Trace& tr) {
    std::string out;
    for (size_t k = 0; k < tr.steps.size(); ++k) {
        const TraceStep& s = tr.steps[k];
        bool last = k + 1 == tr.steps.size();
        if (last || s.kind == TraceStepKind::Lerp) {
            if (!out.empty()) out += "\n";
            out += s.text;
        }
    }
    return out;
}

void planInspector(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                   const TypeSizes& t) {
    const Rect& p = l.inspector;
    const std::string panel = "inspector";
    float margin = marginOf(l);
    float width = p.w - 2 * margin;
    float y = p.y + margin;
    if (!m.trace) {
        pl.text({p.x + margin, y}, "Inspector", {FontFace::Sans, t.head, TEXT}, BoxKind::Text,
                panel, "heading");
        y += lineHeightOf(t.head) * 1.5f;
        FittedText f = fitText(
            "No shadow receiver under the picked pixel. Click a point on the "
            "ground or on an object to see its shadow lookup.",
            FontFace::Sans, t.body, t.bodyFloor, width, p.bottom() - margin - y);
        placeFitted(pl, f, {p.x + margin, y, width, p.bottom() - margin - y}, 0, FontFace::Sans,
                    TEXT_DIM, panel, "no-trace", "");
        return;
    }
    const Trace& tr = *m.trace;
    Header h = headerOf(l, tr, t, width);
    pl.text({p.x + margin, y}, h.title, {FontFace::Mono, t.head, ACCENT}, BoxKind::Text, panel,
            "method");
    if (h.resultOnOwnLine) {
        y += lineHeightOf(t.head);
        pl.text({p.x + margin, y}, h.result, {FontFace::Mono, t.head, TEXT}, BoxKind::Number, panel,
                "visibility");
    } else {
        pl.text({p.right() - margin, y}, h.result, {FontFace::Mono, t.head, TEXT, TextAlign::Right},
                BoxKind::Number, panel, "visibility");
    }
    y += lineHeightOf(t.head) + 4.0f;
    for (const std::string& c : h.counts) {
        pl.text({p.x + margin, y}, c, {FontFace::Mono, t.number, TEXT_DIM}, BoxKind::Number, panel,
                "counts");
        y += lineHeightOf(t.number);
    }
    Grid g = gridOf(l, tr, t, m.highlightFetch);
    LegendNeeds need;
    int hidden = 0;
    planCells(pl, l, m, g, t, need, hidden);
    y = g.bottom + 2.0f;
    // What the cells leave out, said in words.
    std::vector<std::string> notes;
    if (g.view.size != g.full.size) {
        notes.push_back("showing " + std::to_string(g.view.size.x) + " x " +
                        std::to_string(g.view.size.y) + " of the " + std::to_string(g.full.size.x) +
                        " x " + std::to_string(g.full.size.y) +
                        " texels, around the lookup (pcfscope trace lists all)");
    }
    if (hidden > 0) {
        notes.push_back("numbers of " + std::to_string(hidden) +
                        (hidden == 1 ? " cell" : " cells") +
                        " left out where marks fill the cell: see pcfscope trace");
    }
    for (const std::string& note : notes) {
        FittedText f =
            fitText(note, FontFace::Sans, t.label, t.labelFloor, width, 3 * lineHeightOf(t.label));
        y += placeFitted(pl, f, {p.x + margin, y, width, 3 * lineHeightOf(t.label)}, 0,
                         FontFace::Sans, TEXT_DIM, panel, "view-note", "");
    }
    y += 4.0f;
    // The legend: a swatch and a word for every kind of mark this frame draws, flowing onto
    // more lines when the panel is narrow.
    struct Entry {
        Colour colour;
        std::string text;
        int shape;  // 0 square, 1 dot, 2 ring, 3 outline, 4 bar
    };
    std::vector<Entry> entries{{LIT_COLOUR, "lit: ref <= depth", 0},
                               {SHADOWED_COLOUR, "shadowed", 0}};
    if (need.padding) entries.push_back({PADDING, "not read", 0});
    if (need.clamped) entries.push_back({CLAMPED, "read clamped to the edge", 3});
    if (need.weightBar) entries.push_back({WEIGHT_BAR, "weight bar", 4});
    entries.push_back({POINT, "lookup point", 1});
    if (need.fraction) entries.push_back({POINT, "fx, fy: lookup point - base texel centre", 4});
    if (need.dots) entries.push_back({ACCENT, "each lookup", 1});
    if (need.rings) entries.push_back({ACCENT, "hardware tap", 2});
    if (need.gathers) entries.push_back({GATHER, "one gather (2 x 2)", 3});
    if (need.highlight) entries.push_back({HIGHLIGHT, "the fetch the text talks about", 3});
    if (m.showScene)
        entries.push_back({Colour{0.2f, 0.85f, 1.0f, 1.0f}, "texels read, on the scene", 0});
    float lg = t.label;
    float lh = lineHeightOf(lg);
    float x = p.x + margin;
    for (const Entry& e : entries) {
        float tw = measureText(FontFace::Sans, lg, e.text).x;
        float w = lg * 1.4f + tw;
        if (x > p.x + margin && x + w > p.right() - margin) {
            x = p.x + margin;
            y += lh;
        }
        Rect sw{x, y + (lh - lg) * 0.5f, lg, lg};
        Colour col = e.colour;
        int shape = e.shape;
        pl.op([=](Canvas& c) {
            glm::vec2 cc = sw.centre();
            switch (shape) {
                case 1:
                    c.circle(cc, lg * 0.35f + 1.5f, Colour{1, 1, 1, 0.9f});
                    c.circle(cc, lg * 0.35f, col);
                    break;
                case 2:
                    c.ring(cc, lg * 0.38f, 2.0f, HW_RING);
                    c.circle(cc, lg * 0.16f, col);
                    break;
                case 3:
                    c.strokeRect(sw, 3.0f, col);
                    break;
                case 4:
                    c.fillRect({sw.x, sw.y + sw.h * 0.6f, sw.w, sw.h * 0.3f}, col);
                    break;
                default:
                    c.fillRect(sw, col);
                    break;
            }
        });
        pl.box(BoxKind::Mark, sw, panel, "legend-swatch");
        std::string text = e.text;
        if (tw > p.right() - margin - (x + lg * 1.4f)) {
            text = elideText(FontFace::Sans, lg, e.text, p.right() - margin - (x + lg * 1.4f));
        }
        pl.text({x + lg * 1.4f, y}, text, {FontFace::Sans, lg, TEXT_DIM}, BoxKind::Text, panel,
                "legend", text != e.text);
        x += w + lg * 1.4f;
    }
    y += lh + lg * 0.6f;
    // The formula with its numbers, from the kernel's own explanation; the short form when the
    // whole would not fit.
    Rect formula{p.x + margin, y, width, p.bottom() - margin - y};
    if (formula.h < lineHeightOf(t.labelFloor)) return;
    FittedText f =
        fitText(formulaText(tr), FontFace::Mono, t.number, t.numberFloor, width, formula.h);
    bool shortened = false;
    if (f.pages > 1) {
        std::string shortForm =
            "visibility = sum(weight * bit) over the " + std::to_string(tr.taps.size()) +
            " taps = " + formatNumber(tr.visibility) + "\n(every term: pcfscope trace)";
        f = fitText(shortForm, FontFace::Mono, t.number, t.numberFloor, width, formula.h);
        shortened = true;
    }
    float used = placeFitted(pl, f, formula, 0, FontFace::Mono, TEXT, panel, "formula", "");
    if (shortened) pl.plan.boxes.back().shortened = true;
    (void)used;
}

// ---- The steps panel: lesson title, step list, the step's text (paged), the thumbnail. ----

void planSteps(Planner& pl, const InspectorLayout& l, const InspectorModel& m, const TypeSizes& t) {
    const Rect& p = l.steps;
    const std::string panel = "steps";
    float margin = std::max(8.0f, std::round(14.0f * l.scale));
    float width = p.w - 2 * margin;
    float y = p.y + margin * 0.7f;
    int n = static_cast<int>(m.stepTitles.size());
    Rect text;
    if (l.presentation) {
        // One header: where we are and what this step is about; the list would steal the room
        // the large text needs.
        std::string head = "Step " + std::to_string(m.currentStep + 1) + " of " +
                           std::to_string(n) + ": " +
                           (m.currentStep < n ? m.stepTitles[m.currentStep] : std::string());
        std::vector<std::string> lines = wrapText(FontFace::Sans, t.body, head, width);
        bool cut = lines.size() > 2;
        if (cut) {
            std::string rest;
            for (size_t k = 1; k < lines.size(); ++k) rest += (k > 1 ? " " : "") + lines[k];
            lines.resize(2);
            lines[1] = elideText(FontFace::Sans, t.body, rest, width);
        }
        for (const std::string& line : lines) {
            pl.text({p.x + margin, y}, line, {FontFace::Sans, t.body, ACCENT}, BoxKind::Text, panel,
                    "step-title", cut);
            y += lineHeightOf(t.body);
        }
        y += t.body * 0.4f;
        text = {p.x + margin, y, width, p.bottom() - margin * 0.7f - y};
    } else {
        // The lesson's title, one line.
        std::string title = elideText(FontFace::Sans, t.head, m.title, width);
        pl.text({p.x + margin, y}, title, {FontFace::Sans, t.head, TEXT}, BoxKind::Text, panel,
                "lesson-title", title != m.title);
        y += lineHeightOf(t.head) + t.head * 0.3f;
        float bottom = p.bottom() - margin * 0.7f;
        float thumbLeft = l.thumbnail.empty() ? p.right() - margin : l.thumbnail.x - margin;
        float listW = std::round(width * 0.28f);
        float itemLh = lineHeightOf(t.item);
        // Titles wrap in the list's column; when the wrapped list would run out of the panel,
        // each keeps one line (elided); when even that is too long, the list shows the steps
        // around the current one.
        std::vector<std::vector<std::string>> labels;
        float needed = 0.0f;
        for (int k = 0; k < n; ++k) {
            labels.push_back(wrapText(FontFace::Sans, t.item,
                                      std::to_string(k + 1) + ". " + m.stepTitles[k],
                                      listW - 8.0f));
            needed += static_cast<float>(labels.back().size()) * itemLh + 4.0f;
        }
        std::vector<bool> cut(static_cast<size_t>(n), false);
        if (y + needed > bottom) {
            for (int k = 0; k < n; ++k) {
                std::string full = std::to_string(k + 1) + ". " + m.stepTitles[k];
                labels[k] = {elideText(FontFace::Sans, t.item, full, listW - 8.0f)};
                cut[k] = labels[k][0] != full;
            }
        }
        int visible = std::max(1, static_cast<int>((bottom - y) / (itemLh + 4.0f)));
        int first = 0;
        if (n > visible && y + needed > bottom) {
            first = std::clamp(m.currentStep - visible / 2, 0, n - visible);
        }
        int last = std::min(n, first + visible);
        for (int k = first; k < last; ++k) {
            bool current = k == m.currentStep;
            float h = static_cast<float>(labels[k].size()) * itemLh + 2.0f;
            if (y + h > bottom + 0.5f) break;
            Rect row{p.x + margin, y - 1.0f, listW, h};
            if (current) pl.fill(row, Colour{0.35f, 0.78f, 0.98f, 0.25f});
            for (size_t li = 0; li < labels[k].size(); ++li) {
                bool more = (k == first && first > 0) || (k == last - 1 && last < n);
                pl.text({p.x + margin + 4.0f, y + static_cast<float>(li) * itemLh}, labels[k][li],
                        {FontFace::Sans, t.item, current ? TEXT : TEXT_DIM}, BoxKind::Text, panel,
                        "step-list", cut[k] || more);
            }
            y += h + 2.0f;
        }
        float top = p.y + margin * 0.7f + lineHeightOf(t.head) + t.head * 0.3f;
        float tx = p.x + margin + listW + margin;
        text = {tx, top, thumbLeft - tx, bottom - top};
    }
    FittedText f = fitText(m.stepText, FontFace::Sans, t.body, t.bodyFloor, text.w, text.h);
    pl.plan.textPages = f.pages;
    placeFitted(pl, f, text, m.textPage, FontFace::Sans, TEXT, panel, "step-text", "Space/Right");
}

void planThumbnail(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                   const TypeSizes& t) {
    if (!m.map || m.map->width() <= 0 || l.thumbnail.empty()) return;
    const ShadowMap& map = *m.map;
    Rect box = l.thumbnail;
    pl.op([=](Canvas& c) { c.strokeRect(box.expanded(2), 2.0f, Colour{0, 0, 0, 1}); });
    if (m.trace) {
        Neighbourhood n = neighbourhoodOf(*m.trace);
        float sx = box.w / static_cast<float>(map.width());
        float sy = box.h / static_cast<float>(map.height());
        Rect nb{box.x + n.origin.x * sx, box.y + n.origin.y * sy, n.size.x * sx, n.size.y * sy};
        nb = nb.expanded(std::max(0.0f, 3.0f - std::min(nb.w, nb.h) * 0.5f));
        float w = l.presentation ? 3.0f : 2.0f;
        pl.op([=](Canvas& c) { c.strokeRect(nb, w, POINT); });
    }
    // The longest caption that is no wider than the thumbnail (the step text ends beside it).
    std::string dims = std::to_string(map.width()) + " x " + std::to_string(map.height());
    std::string caption = dims;
    for (std::string c : {"shadow map " + dims, "map " + dims}) {
        if (measureText(FontFace::Sans, t.label, c).x <= box.w) {
            caption = c;
            break;
        }
    }
    pl.text({box.centre().x, box.bottom() + 4.0f}, caption,
            {FontFace::Sans, t.label, TEXT_DIM, TextAlign::Center}, BoxKind::Label, "steps",
            "thumbnail-caption");
}

void planStatus(Planner& pl, const InspectorLayout& l, const InspectorModel& m,
                const TypeSizes& t) {
    const Rect& s = l.status;
    float pad = std::max(6.0f, 10.0f * l.scale);
    std::string keys = "H: keys";
    float kw = measureText(FontFace::Sans, t.status, keys).x;
    float room = s.w - 3 * pad - kw;
    float size = t.status;
    while (size > t.labelFloor && measureText(FontFace::Mono, size, m.status).x > room) {
        size = stepDown(size, t.labelFloor);
    }
    std::string status = elideText(FontFace::Mono, size, m.status, room);
    float y = s.y + (s.h - lineHeightOf(size)) * 0.5f;
    pl.text({s.x + pad, y}, status, {FontFace::Mono, size, TEXT}, BoxKind::Text, "status", "status",
            status != m.status);
    float ky = s.y + (s.h - lineHeightOf(t.status)) * 0.5f;
    pl.text({s.right() - pad, ky}, keys, {FontFace::Sans, t.status, TEXT_DIM, TextAlign::Right},
            BoxKind::Text, "status", "keys-hint");
}

void planHelp(Planner& pl, const InspectorLayout& l, const TypeSizes& t) {
    float fs = t.body;
    const auto& keys = viewerKeys();
    float keyW = 0.0f, whatW = 0.0f;
    for (const auto& [key, what] : keys) {
        keyW = std::max(keyW, measureText(FontFace::Mono, fs, key).x);
        whatW = std::max(whatW, measureText(FontFace::Sans, fs, what).x);
    }
    float lh = lineHeightOf(fs);
    float w = std::min(static_cast<float>(l.frameSize.x) - 8.0f, keyW + whatW + fs * 4.0f);
    float h = std::min(static_cast<float>(l.frameSize.y) - 8.0f,
                       (static_cast<float>(keys.size()) + 2.5f) * lh + fs);
    Rect box{std::round((l.frameSize.x - w) * 0.5f), std::round((l.frameSize.y - h) * 0.5f), w, h};
    pl.fill(box, Colour{0.02f, 0.03f, 0.05f, 0.94f});
    pl.op([=](Canvas& c) { c.strokeRect(box, 2.0f, ACCENT); });
    float y = box.y + fs * 0.6f;
    pl.op([=](Canvas& c) { c.text({box.x + fs, y}, "Keys", {FontFace::Sans, fs, ACCENT}); });
    y += lh * 1.4f;
    for (const auto& [key, what] : keys) {
        if (y + lh > box.bottom()) break;
        std::string k = key, wt = what;
        float yy = y;
        pl.op([=](Canvas& c) {
            c.text({box.x + fs, yy}, k, {FontFace::Mono, fs, TEXT});
            c.text({box.x + fs * 2.0f + keyW, yy}, wt, {FontFace::Sans, fs, TEXT_DIM});
        });
        y += lh;
    }
}

}  // namespace

const char* boxKindName(BoxKind kind) {
    switch (kind) {
        case BoxKind::Panel:
            return "panel";
        case BoxKind::Text:
            return "text";
        case BoxKind::Number:
            return "number";
        case BoxKind::Label:
            return "label";
        case BoxKind::Mark:
            return "mark";
    }
    return "text";
}

TypeSizes typeSizes(const InspectorLayout& l) {
    TypeSizes t;
    float s = l.scale;
    if (l.presentation) {
        // A projector at 1024 x 768 or 1280 x 720 still gets 22 px text and 18 px numbers.
        t.bodyFloor = 22;
        t.itemFloor = 22;
        t.numberFloor = 18;
        t.labelFloor = 16;
        t.body = std::max(t.bodyFloor, std::round(17.0f * s * 1.35f));
        t.item = t.body;
        t.head = std::max(24.0f, std::round(20.0f * s * 1.35f));
        t.number = std::max(t.numberFloor, std::round(13.0f * s * 1.35f));
        t.label = std::max(t.labelFloor, std::round(12.0f * s * 1.35f));
        t.status = std::max(16.0f, std::round(13.0f * s * 1.35f));
    } else {
        t.bodyFloor = 12;
        t.itemFloor = 12;
        t.numberFloor = 12;
        t.labelFloor = 11;
        t.body = std::max(13.0f, std::round(15.0f * s));
        t.item = std::max(t.itemFloor, std::round(13.0f * s));
        t.head = std::max(16.0f, std::round(20.0f * s));
        t.number = std::max(t.numberFloor, std::round(14.0f * s));
        t.label = std::max(t.labelFloor, std::round(12.0f * s));
        t.status = std::max(12.0f, std::round(14.0f * s));
    }
    return t;
}

Rect thumbnailRect(const InspectorLayout& l, bool) { return l.thumbnail; }

std::vector<uint8_t> thumbnailImage(const ShadowMap& map, int side) {
    // Nearest texel per thumbnail pixel, depth as grey (near the light = dark). Rows top-down
    // with texel row 0 at the top, like the neighbourhood view.
    std::vector<uint8_t> rgba(static_cast<size_t>(side) * side * 4);
    for (int y = 0; y < side; ++y) {
        int j = std::min(map.height() - 1, y * map.height() / side);
        for (int x = 0; x < side; ++x) {
            int i = std::min(map.width() - 1, x * map.width() / side);
            float g = 0.15f + 0.8f * std::clamp(map.depth(i, j), 0.0f, 1.0f);
            uint8_t v = static_cast<uint8_t>(std::lround(g * 255.0f));
            size_t k = (static_cast<size_t>(y) * side + x) * 4;
            rgba[k] = v;
            rgba[k + 1] = v;
            rgba[k + 2] = static_cast<uint8_t>(std::min(255L, std::lround(g * 1.05f * 255.0f)));
            rgba[k + 3] = 255;
        }
    }
    return rgba;
}

InspectorLayout inspectorLayout(glm::ivec2 frameSize, bool presentation) {
    InspectorLayout l;
    l.frameSize = frameSize;
    l.presentation = presentation;
    float w = static_cast<float>(frameSize.x);
    float h = static_cast<float>(frameSize.y);
    l.scale = std::max(0.5f, std::min(w / 1600.0f, h / 900.0f));
    TypeSizes t = typeSizes(l);
    float statusH = std::round(std::max(28.0f * l.scale, lineHeightOf(t.status) + 8.0f));
    float bodyH = h - statusH;
    // Presentation gives the scene less room so that the step text and the cells can be large.
    // Tall frames too: the inspector's cells are as large as its width allows.
    float sceneShare = presentation || h > 0.75f * w ? 0.5f : 0.6f;
    float sceneW = std::round(w * sceneShare);
    float sceneH = std::round(sceneW * 9.0f / 16.0f);
    float maxSceneH = std::round(bodyH * (presentation ? 0.5f : 0.62f));
    if (sceneH > maxSceneH) {
        sceneH = maxSceneH;
        sceneW = std::round(sceneH * 16.0f / 9.0f);
    }
    l.status = {0.0f, h - statusH, w, statusH};
    if (w > 2.2f * h) {
        // Very wide frames: the scene at the full height on the left, then the step panel, then
        // the inspector, side by side (under the scene would leave a sliver).
        sceneH = bodyH;
        sceneW = std::round(sceneH * 16.0f / 9.0f);
        if (sceneW > w * 0.45f) {
            sceneW = std::round(w * 0.45f);
            sceneH = std::round(sceneW * 9.0f / 16.0f);
        }
        float rest = w - sceneW;
        float stepsW = std::round(rest * 0.45f);
        l.scene = {0.0f, 0.0f, sceneW, sceneH};
        l.steps = {sceneW, 0.0f, stepsW, bodyH};
        l.inspector = {sceneW + stepsW, 0.0f, w - sceneW - stepsW, bodyH};
        if (sceneH < bodyH) {
            // The space under the scene is the step panel's.
            l.steps = {0.0f, sceneH, sceneW + stepsW, bodyH - sceneH};
            l.inspector = {sceneW + stepsW, 0.0f, w - sceneW - stepsW, bodyH};
        }
    } else {
        l.scene = {0.0f, 0.0f, sceneW, sceneH};
        l.steps = {0.0f, sceneH, sceneW, bodyH - sceneH};
        l.inspector = {sceneW, 0.0f, w - sceneW, bodyH};
    }
    if (!presentation) {
        // The map's thumbnail, square, at the steps panel's right, under the lesson title.
        float margin = std::max(8.0f, std::round(14.0f * l.scale));
        float top = l.steps.y + margin * 0.7f + lineHeightOf(t.head) + t.head * 0.3f;
        float caption = lineHeightOf(t.label) + 6.0f;
        float side = std::floor(
            std::min(l.steps.bottom() - top - margin * 0.7f - caption, l.steps.w * 0.2f));
        if (side >= 48.0f) {
            l.thumbnail = {std::round(l.steps.right() - margin - side), std::round(top), side,
                           side};
        }
    }
    return l;
}

Neighbourhood neighbourhoodView(const InspectorLayout& l, const Trace& tr) {
    return gridOf(l, tr, typeSizes(l)).view;
}

Rect neighbourhoodArea(const InspectorLayout& l, const Trace& tr, bool) {
    return gridOf(l, tr, typeSizes(l)).area;
}

Neighbourhood neighbourhoodOf(const Trace& tr) {
    glm::ivec2 lo = tr.pos.base;
    glm::ivec2 hi = tr.pos.base + glm::ivec2(1);
    if (!tr.weights.values.empty()) {
        lo = glm::min(lo, tr.weights.origin);
        hi = glm::max(hi, tr.weights.origin + tr.weights.size - glm::ivec2(1));
    }
    glm::ivec2 point(glm::floor(tr.uv * glm::vec2(tr.mapSize)));
    lo = glm::min(lo, point);
    hi = glm::max(hi, point);
    return {lo, hi - lo + glm::ivec2(1)};
}

Rect texelCellRect(const Neighbourhood& n, const Rect& area, glm::ivec2 texel) {
    // The area is exactly as wide as the view's columns.
    float cell = area.w / static_cast<float>(std::max(1, n.size.x));
    return {area.x + static_cast<float>(texel.x - n.origin.x) * cell,
            area.y + static_cast<float>(texel.y - n.origin.y) * cell, cell, cell};
}

const std::vector<std::pair<std::string, std::string>>& viewerKeys() {
    static const std::vector<std::pair<std::string, std::string>> keys = {
        {"click", "pick a pixel"},
        {"Up / Down", "move the pixel one row"},
        {"Shift+arrows", "move the pixel one pixel"},
        {"Space, Right", "next page of the text, then next step"},
        {"Left, Backspace", "previous step"},
        {"Home / End", "first / last step"},
        {"M / Shift+M", "next / previous method"},
        {"[ / ]", "smaller / larger kernel"},
        {"- / +", "smaller / larger shadow map"},
        {"B / Shift+B", "next / previous bias mode"},
        {"Q", "texture unit: exact / hw8"},
        {"G", "texel grid on the scene on / off"},
        {"L / Shift+L", "next / previous lesson"},
        {"E", "export this frame (PNG + JSON)"},
        {"P", "presentation mode"},
        {"H", "this help"},
        {"F", "fullscreen"},
        {"Esc", "quit"},
    };
    return keys;
}

FramePlan planFrame(const InspectorLayout& l, const InspectorModel& m) {
    FramePlan plan;
    Planner pl{plan};
    TypeSizes t = typeSizes(l);
    pl.box(BoxKind::Panel, l.scene, "scene", "scene");
    pl.box(BoxKind::Panel, l.steps, "steps", "steps");
    pl.box(BoxKind::Panel, l.inspector, "inspector", "inspector");
    pl.box(BoxKind::Panel, l.status, "status", "status");
    if (m.showScene) planScene(pl, l, m, t);
    Rect steps = l.steps;
    pl.op([=](Canvas& c) { c.pushClip(steps); });
    planSteps(pl, l, m, t);
    pl.op([](Canvas& c) { c.popClip(); });
    Rect insp = l.inspector;
    pl.op([=](Canvas& c) { c.pushClip(insp); });
    planInspector(pl, l, m, t);
    pl.op([](Canvas& c) { c.popClip(); });
    planStatus(pl, l, m, t);
    pl.onTop = true;
    planThumbnail(pl, l, m, t);
    if (m.help) planHelp(pl, l, t);
    return plan;
}

void drawPlan(Canvas& canvas, const std::vector<std::function<void(Canvas&)>>& ops) {
    for (const auto& op : ops) op(canvas);
}

std::string layoutJson(const std::vector<LayoutBox>& boxes) {
    std::string out = "[";
    char buf[160];
    for (size_t k = 0; k < boxes.size(); ++k) {
        const LayoutBox& b = boxes[k];
        std::snprintf(buf, sizeof buf, "\"rect\":[%g,%g,%g,%g]", static_cast<double>(b.rect.x),
                      static_cast<double>(b.rect.y), static_cast<double>(b.rect.w),
                      static_cast<double>(b.rect.h));
        out += std::string(k ? "," : "") + "{\"kind\":\"" + boxKindName(b.kind) +
               "\",\"panel\":\"" + b.panel + "\",\"role\":\"" + b.role + "\"," + buf;
        if (b.kind == BoxKind::Text || b.kind == BoxKind::Number || b.kind == BoxKind::Label ||
            b.fontPx > 0.0f) {
            std::snprintf(buf, sizeof buf, ",\"font_px\":%g,\"shortened\":%s",
                          static_cast<double>(b.fontPx), b.shortened ? "true" : "false");
            out += buf;
        }
        out += "}";
    }
    return out + "]";
}

void drawInspector(Canvas& c, const InspectorLayout& l, const InspectorModel& m) {
    drawPlan(c, planFrame(l, m).base);
}

void clearInspectorPanels(GLuint framebuffer, const InspectorLayout& l) {
    // Scissored clears: on llvmpipe a clear is a memset, while a panel-sized quad would run the
    // overlay's fragment shader over a million pixels.
    auto clearRect = [&](const Rect& r, const Colour& colour) {
        int frameH = l.frameSize.y;
        glScissor(static_cast<GLint>(r.x), frameH - static_cast<GLint>(r.bottom()),
                  static_cast<GLsizei>(r.w), static_cast<GLsizei>(r.h));
        glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, &colour.x);
    };
    GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
    glEnable(GL_SCISSOR_TEST);
    clearRect(l.inspector, PANEL);
    clearRect(l.steps, PANEL_LIGHT);
    clearRect(l.status, STATUS);
    if (!scissor) glDisable(GL_SCISSOR_TEST);
}

void drawInspectorTop(Canvas& c, const InspectorLayout& l, const InspectorModel& m) {
    drawPlan(c, planFrame(l, m).top);
}

}  // namespace pcf
