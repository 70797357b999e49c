// deck.h: a lesson's exported frames as one file to teach from or hand out (docs/teaching.md,
// "The handout"): an HTML deck (one self-contained file, one <section> per frame, every image,
// video and script inside it as data), a PDF deck (one page per frame, the frame's pixels at the
// frame's size) and an A4 handout (the frames two to a page, the step's words and the trace's table
// as text beneath). Each is made from the frames `export` wrote, PNG and JSON sidecar, so a deck
// shows exactly what the frames show.
#pragma once

#include <string>
#include <vector>

namespace pcf {

// One frame of the deck, in the order they are shown.
struct DeckFrame {
    std::string png;    // the frame's PNG file
    std::string json;   // its JSON sidecar's text (app/session.h: stepJson)
    std::string video;  // the step's MP4 when the step is an animation (its first frame); ""
};

struct Deck {
    std::string title;  // the lesson's
    std::vector<DeckFrame> frames;
};

// What a frame says besides its pixels, read from its sidecar: which step, its words as the
// notes, a question's ask and choices or a reveal's answer, and the trace as a table of the
// texels read, the numbers the question hides written "?".
struct SlideText {
    int step = 0;
    std::string stepTitle;
    std::string phase;  // "question", "reveal" or "" (a step that asks nothing)
    std::string words;  // the step's words (a question's: its ask)
    std::vector<std::string> choices;
    std::string answer;  // a reveal's
    int textPage = 1;
    int textPages = 1;
    std::string summary;                         // "pcf-gather N=3  uv (...)  ref ...  ..."
    std::vector<std::string> header;             // the table's columns
    std::vector<std::vector<std::string>> rows;  // one per texel read, in read order
};
// Throws std::runtime_error for a sidecar that is not one export writes.
SlideText slideText(const std::string& json);

// The files. Each is written whole or not at all (render/image_io.h: writeTextFile); throws
// ImageError for a frame that cannot be read or a file that cannot be written.
void writeHtmlDeck(const Deck& deck, const std::string& path);
void writePdfDeck(const Deck& deck, const std::string& path);
void writePdfHandout(const Deck& deck, const std::string& path);

// The handout's type sizes, points: every word of it at least HANDOUT_MIN_PT.
constexpr double HANDOUT_MIN_PT = 10.0;

}  // namespace pcf
