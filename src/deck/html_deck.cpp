// html_deck.cpp: the HTML deck, one self-contained file: every frame a <section> holding its PNG
// (and an animation step's MP4) as a data: URI, the step's words as speaker notes and the trace's
// table as text; a small script turns the slides with the arrow keys, Space, PageUp/PageDown,
// Home/End and clicks, plays a slide's video while it is shown, and toggles the notes (N) and the
// table (T). No network: nothing in it points outside the file.
#include <fstream>
#include <sstream>

#include "deck/deck.h"
#include "render/image_io.h"

namespace pcf {

namespace {

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ImageError(path + ": cannot read the frame for the deck");
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

std::string base64(const std::string& bytes) {
    static const char* ALPHABET =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                     (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                     static_cast<unsigned char>(bytes[i + 2]);
        for (int k = 3; k >= 0; --k) out += ALPHABET[(v >> (6 * k)) & 63];
    }
    if (i < bytes.size()) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        out += ALPHABET[(v >> 18) & 63];
        out += ALPHABET[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? ALPHABET[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

std::string escaped(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

const char* STYLE = R"(<style>
html, body { margin: 0; height: 100%; background: #111318; color: #e8eaf0;
  font-family: "DejaVu Sans", sans-serif; }
section { display: none; height: 100vh; flex-direction: column; align-items: center;
  justify-content: center; }
section.current { display: flex; }
section img, section video { max-width: 100vw; max-height: 100vh; object-fit: contain; }
body.notes section img, body.notes section video { max-height: 62vh; }
aside.notes, div.trace { display: none; max-width: 96vw; overflow: auto; font-size: 15px; }
body.notes aside.notes { display: block; white-space: pre-wrap; padding: 0.5em 1em; }
body.table div.trace { display: block; position: fixed; right: 0; top: 0; max-height: 100vh;
  background: rgba(17, 19, 24, 0.94); padding: 0.5em 1em; }
div.trace table { border-collapse: collapse; font-family: "DejaVu Sans Mono", monospace; }
div.trace td, div.trace th { padding: 0 0.6em; text-align: right; }
</style>
)";

// Turns the slides; plays the shown slide's video from its start and pauses the others.
// deckReady and deckState() let a test (or a remote) read where the deck is.
const char* SCRIPT = R"(<script>
(function () {
  var slides = document.querySelectorAll('section');
  var title = document.title;
  var at = 0;
  function show(k) {
    at = Math.max(0, Math.min(slides.length - 1, k));
    for (var i = 0; i < slides.length; ++i) {
      var on = i === at;
      slides[i].classList.toggle('current', on);
      var v = slides[i].querySelector('video');
      if (!v) continue;
      if (on) { v.currentTime = 0; var p = v.play(); if (p && p.catch) p.catch(function () {}); }
      else v.pause();
    }
    document.title = (at + 1) + '/' + slides.length + ' ' + title;
    if (history.replaceState) history.replaceState(null, '', '#' + (at + 1));
  }
  document.addEventListener('keydown', function (e) {
    var k = e.key;
    if (k === 'ArrowRight' || k === ' ' || k === 'PageDown' || k === 'ArrowDown') show(at + 1);
    else if (k === 'ArrowLeft' || k === 'PageUp' || k === 'ArrowUp' || k === 'Backspace') show(at - 1);
    else if (k === 'Home') show(0);
    else if (k === 'End') show(slides.length - 1);
    else if (k === 'n' || k === 'N') document.body.classList.toggle('notes');
    else if (k === 't' || k === 'T') document.body.classList.toggle('table');
    else return;
    e.preventDefault();
  });
  document.addEventListener('click', function (e) {
    show(e.clientX < window.innerWidth / 3 ? at - 1 : at + 1);
  });
  window.deckState = function () {
    var v = slides[at].querySelector('video');
    return { slide: at + 1, slides: slides.length, id: slides[at].id,
             video: v ? { time: v.currentTime, paused: v.paused, ready: v.readyState } : null };
  };
  var start = parseInt((location.hash || '#1').slice(1), 10);
  show(isNaN(start) ? 0 : start - 1);
  window.deckReady = true;
})();
</script>
)";

// The slide's trace table as an HTML table, under its summary line.
std::string tableHtml(const SlideText& t) {
    if (t.rows.empty()) return "";
    std::ostringstream out;
    out << "<div class=\"trace\"><p>" << escaped(t.summary) << "</p><table><tr>";
    for (const std::string& h : t.header) out << "<th>" << escaped(h) << "</th>";
    out << "</tr>";
    for (const auto& row : t.rows) {
        out << "<tr>";
        for (const std::string& c : row) out << "<td>" << escaped(c) << "</td>";
        out << "</tr>";
    }
    out << "</table></div>";
    return out.str();
}

// The speaker notes: the step, a question's ask and choices or a reveal's answer, the words.
std::string notesText(const SlideText& t) {
    std::string notes = "Step " + std::to_string(t.step) + ": " + t.stepTitle;
    if (t.textPages > 1) {
        notes +=
            " (page " + std::to_string(t.textPage) + " of " + std::to_string(t.textPages) + ")";
    }
    if (t.phase == "question") notes += "\nQuestion (the next slide answers it):";
    if (!t.answer.empty()) notes += "\n" + t.answer;
    notes += "\n" + t.words;
    for (size_t k = 0; k < t.choices.size(); ++k) {
        notes += std::string("\n  ") + static_cast<char>('A' + k) + "  " + t.choices[k];
    }
    return notes;
}

}  // namespace

void writeHtmlDeck(const Deck& deck, const std::string& path) {
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>"
         << escaped(deck.title) << "</title>\n"
         << STYLE << "</head>\n<body>\n";
    for (size_t k = 0; k < deck.frames.size(); ++k) {
        const DeckFrame& f = deck.frames[k];
        SlideText t = slideText(f.json);
        std::string alt = "Step " + std::to_string(t.step) + ": " + t.stepTitle +
                          (t.phase.empty() ? "" : " (" + t.phase + ")");
        html << "<section id=\"slide" << (k + 1) << "\" data-step=\"" << t.step
             << "\" data-phase=\"" << t.phase << "\">\n";
        std::string png = "data:image/png;base64," + base64(readBytes(f.png));
        if (!f.video.empty()) {
            html << "<video muted loop playsinline preload=\"auto\" poster=\"" << png
                 << "\" src=\"data:video/mp4;base64," << base64(readBytes(f.video)) << "\" title=\""
                 << escaped(alt) << "\"></video>\n";
        } else {
            html << "<img alt=\"" << escaped(alt) << "\" src=\"" << png << "\">\n";
        }
        html << "<aside class=\"notes\">" << escaped(notesText(t)) << "</aside>\n"
             << tableHtml(t) << "\n</section>\n";
    }
    html << SCRIPT << "</body></html>\n";
    writeTextFile(path, html.str());
}

}  // namespace pcf
