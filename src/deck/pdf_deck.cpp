// pdf_deck.cpp: the PDF deck (one page per frame, the page the frame's size in points, the frame
// painted on it pixel for pixel) and the A4 handout (the frames two to a page, each with the
// step's words and the trace's table as text beneath, every word at HANDOUT_MIN_PT or more).
// Both through cairo's PDF surface; the file is made in memory and written whole.
#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "deck/deck.h"
#include "render/image_io.h"

namespace pcf {

namespace {

// The PDF's bytes as cairo writes them.
cairo_status_t appendBytes(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

struct SurfaceFree {
    void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextFree {
    void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceFree>;
using Context = std::unique_ptr<cairo_t, ContextFree>;

Surface readPng(const std::string& path) {
    Surface s(cairo_image_surface_create_from_png(path.c_str()));
    if (cairo_surface_status(s.get()) != CAIRO_STATUS_SUCCESS) {
        throw ImageError(path + ": cannot read the frame for the deck (" +
                         cairo_status_to_string(cairo_surface_status(s.get())) + ")");
    }
    return s;
}

// A PDF being made: its surface writing into `bytes`, with the deck's title. The creation date
// is not written, so that the same frames make the same file.
struct PdfFile {
    std::string bytes;
    Surface surface;
    Context cr;
    PdfFile(const std::string& title, double w, double h) {
        surface.reset(cairo_pdf_surface_create_for_stream(appendBytes, &bytes, w, h));
        cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE, title.c_str());
        cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "pcfscope");
        // No date: cairo dates a file unless told a date, and an empty one is none.
        cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATE_DATE, "");
        cr.reset(cairo_create(surface.get()));
    }
    void finish(const std::string& path) {
        cr.reset();
        cairo_surface_finish(surface.get());
        cairo_status_t status = cairo_surface_status(surface.get());
        if (status != CAIRO_STATUS_SUCCESS) {
            throw ImageError(path + ": cannot make the PDF (" + cairo_status_to_string(status) +
                             ")");
        }
        writeTextFile(path, bytes);
    }
};

}  // namespace

void writePdfDeck(const Deck& deck, const std::string& path) {
    if (deck.frames.empty()) throw ImageError(path + ": a deck needs at least one frame");
    PdfFile pdf(deck.title, 1.0, 1.0);
    for (const DeckFrame& f : deck.frames) {
        Surface img = readPng(f.png);
        int w = cairo_image_surface_get_width(img.get());
        int h = cairo_image_surface_get_height(img.get());
        // One point per frame pixel: rendered at 72 dpi the page is the frame, its pixels
        // stored losslessly and marked not to be interpolated.
        cairo_pdf_surface_set_size(pdf.surface.get(), w, h);
        cairo_set_source_surface(pdf.cr.get(), img.get(), 0, 0);
        cairo_pattern_set_filter(cairo_get_source(pdf.cr.get()), CAIRO_FILTER_NEAREST);
        cairo_paint(pdf.cr.get());
        cairo_show_page(pdf.cr.get());
    }
    pdf.finish(path);
}

// ---- The handout. ----

namespace {

constexpr double A4_W = 595.276, A4_H = 841.890;  // points
constexpr double MARGIN = 36.0;
constexpr double BODY_PT = 10.5;  // the words
constexpr double TABLE_PT = 10.0;
constexpr double HEAD_PT = 12.0;
constexpr double LEADING = 1.22;
constexpr double FRAME_W = 360.0;  // points: 1600 pixels at 320 dpi, sharp in print
constexpr int FRAMES_PER_PAGE = 2;

static_assert(TABLE_PT >= HANDOUT_MIN_PT && BODY_PT >= HANDOUT_MIN_PT);

// A line of the handout's text: its words, face and size.
struct Line {
    std::string text;
    bool mono = false;
    bool bold = false;
    double pt = BODY_PT;
};

void setFont(cairo_t* cr, const Line& l) {
    cairo_select_font_face(cr, l.mono ? "DejaVu Sans Mono" : "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                           l.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, l.pt);
}

double widthOf(cairo_t* cr, const Line& l) {
    setFont(cr, l);
    cairo_text_extents_t e;
    cairo_text_extents(cr, l.text.c_str(), &e);
    return e.x_advance;
}

// A paragraph wrapped into lines no wider than `width` (words are not split; a word longer than
// the line gets a line of its own).
void wrapInto(cairo_t* cr, const std::string& para, Line style, double width,
              std::vector<Line>& out) {
    std::string line;
    size_t i = 0;
    while (i <= para.size()) {
        size_t sp = para.find(' ', i);
        if (sp == std::string::npos) sp = para.size();
        std::string word = para.substr(i, sp - i);
        Line trial = style;
        trial.text = line.empty() ? word : line + " " + word;
        if (!line.empty() && widthOf(cr, trial) > width) {
            style.text = line;
            out.push_back(style);
            line = word;
        } else {
            line = trial.text;
        }
        i = sp + 1;
    }
    style.text = line;
    out.push_back(style);
}

void tableLines(cairo_t* cr, const SlideText& t, double width, std::vector<Line>& out);

// The text under a frame: the step and its words (a question's ask and choices, a reveal's answer
// first), then the trace's table, its rows in as many columns as the width holds.
std::vector<Line> frameLines(cairo_t* cr, const SlideText& t, double width) {
    std::vector<Line> out;
    std::string head = "Step " + std::to_string(t.step) + ": " + t.stepTitle;
    if (t.phase == "question") head += " (question)";
    if (t.phase == "reveal") head += " (answer)";
    // A later page of the step: its words and table are under its first page already.
    if (t.textPage > 1) head += ", continued (page " + std::to_string(t.textPage) + ")";
    wrapInto(cr, head, {"", false, true, HEAD_PT}, width, out);
    if (t.textPage > 1) return out;
    std::string words = (t.answer.empty() ? "" : t.answer + "\n") + t.words;
    for (size_t k = 0; k < t.choices.size(); ++k) {
        words += std::string("\n") + static_cast<char>('A' + k) + "  " + t.choices[k];
    }
    size_t start = 0;
    while (start <= words.size()) {
        size_t end = words.find('\n', start);
        if (end == std::string::npos) end = words.size();
        std::string para = words.substr(start, end - start);
        bool pre = para.starts_with("  ");
        if (pre) {
            out.push_back({para, true, false, TABLE_PT});
        } else {
            wrapInto(cr, para, {"", false, false, BODY_PT}, width, out);
        }
        start = end + 1;
    }
    // A question's table is its answer's, with the numbers hidden: the answer's frame prints it.
    if (t.rows.empty() || t.phase == "question") return out;
    tableLines(cr, t, width, out);
    return out;
}

// The trace's table under a frame's words: its summary, then its rows in as many columns as the
// width holds.
void tableLines(cairo_t* cr, const SlideText& t, double width, std::vector<Line>& out) {
    out.push_back({"", false, false, BODY_PT});
    wrapInto(cr, t.summary, {"", true, false, TABLE_PT}, width, out);
    // Columns of "texel depth [ref] bit weight" cells, as many side by side as fit; the ref
    // column only where the reads compare with refs of their own (the summary has the one ref).
    bool oneRef = std::all_of(t.rows.begin(), t.rows.end(),
                              [&](const auto& r) { return r[2] == t.rows.front()[2]; });
    auto cell = [&](const std::vector<std::string>& r) {
        std::string texel = r[0];
        texel.erase(std::remove_if(texel.begin(), texel.end(),
                                   [](char c) { return c == '(' || c == ')' || c == ' '; }),
                    texel.end());
        char buf[128];
        if (oneRef) {
            std::snprintf(buf, sizeof buf, "%-7s %6s %3s %6s", texel.c_str(), r[1].c_str(),
                          r[3].c_str(), r[4].c_str());
        } else {
            std::snprintf(buf, sizeof buf, "%-7s %6s %6s %3s %6s", texel.c_str(), r[1].c_str(),
                          r[2].c_str(), r[3].c_str(), r[4].c_str());
        }
        return std::string(buf);
    };
    std::string header = cell(t.header);
    double cw = widthOf(cr, {header + "   ", true, false, TABLE_PT});
    size_t columns = std::max<size_t>(1, static_cast<size_t>(width / cw));
    size_t perColumn = (t.rows.size() + columns - 1) / columns;
    columns = (t.rows.size() + perColumn - 1) / perColumn;
    std::string heads;
    for (size_t c = 0; c < columns; ++c) heads += (c ? "   " : "") + header;
    out.push_back({heads, true, true, TABLE_PT});
    for (size_t r = 0; r < perColumn; ++r) {
        std::string line;
        for (size_t c = 0; c < columns && c * perColumn + r < t.rows.size(); ++c) {
            line += (c ? "   " : "") + cell(t.rows[c * perColumn + r]);
        }
        out.push_back({line, true, false, TABLE_PT});
    }
}

double lineHeight(const Line& l) { return l.pt * LEADING; }

// The inspector's boxes of a frame, by role: what a page of a step shows besides its words.
std::multiset<std::string> inspectorRoles(const std::string& json) {
    std::multiset<std::string> roles;
    nlohmann::json j = nlohmann::json::parse(json);
    if (!j.contains("layout")) return roles;
    for (const auto& box : j["layout"]) {
        if (box.value("panel", "") == "inspector") roles.insert(box.value("role", ""));
    }
    return roles;
}

// The frames a handout prints: a later page of a step that only carries on its words (the same
// inspector as the page before) is left out, since the words are printed whole under the step's
// first page.
std::vector<DeckFrame> handoutFrames(const Deck& deck) {
    std::vector<DeckFrame> out;
    std::multiset<std::string> before;
    for (const DeckFrame& f : deck.frames) {
        SlideText t = slideText(f.json);
        std::multiset<std::string> roles = inspectorRoles(f.json);
        if (t.textPage <= 1 || roles != before) out.push_back(f);
        before = roles;
    }
    return out;
}

}  // namespace

void writePdfHandout(const Deck& deck, const std::string& path) {
    if (deck.frames.empty()) throw ImageError(path + ": a handout needs at least one frame");
    PdfFile pdf(deck.title, A4_W, A4_H);
    cairo_t* cr = pdf.cr.get();
    double width = A4_W - 2 * MARGIN;
    double y = MARGIN;
    int onPage = 0;
    bool pageUsed = false;
    auto newPage = [&]() {
        cairo_show_page(cr);
        y = MARGIN;
        onPage = 0;
        pageUsed = false;
    };
    for (const DeckFrame& f : handoutFrames(deck)) {
        SlideText t = slideText(f.json);
        Surface img = readPng(f.png);
        double iw = cairo_image_surface_get_width(img.get());
        double ih = cairo_image_surface_get_height(img.get());
        double scale = std::min(width, FRAME_W) / iw;
        std::vector<Line> lines = frameLines(cr, t, width);
        // A frame and its words stay on one page where a page holds them (a longer block starts
        // a page and runs on); two frames to a page at most.
        double need = ih * scale + 6;
        for (const Line& l : lines) need += lineHeight(l);
        if (pageUsed && (onPage >= FRAMES_PER_PAGE || y + need > A4_H - MARGIN)) newPage();
        cairo_save(cr);
        cairo_translate(cr, MARGIN + (width - iw * scale) * 0.5, y);
        cairo_scale(cr, scale, scale);
        cairo_set_source_surface(cr, img.get(), 0, 0);
        cairo_paint(cr);
        cairo_restore(cr);
        y += ih * scale + 6;
        cairo_set_source_rgb(cr, 0.08, 0.08, 0.1);
        for (const Line& l : lines) {
            if (y + lineHeight(l) > A4_H - MARGIN) newPage();
            setFont(cr, l);
            cairo_move_to(cr, MARGIN, y + l.pt);
            cairo_show_text(cr, l.text.c_str());
            y += lineHeight(l);
        }
        y += BODY_PT;
        ++onPage;
        pageUsed = true;
    }
    pdf.finish(path);
}

}  // namespace pcf
