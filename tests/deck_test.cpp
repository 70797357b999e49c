// Decks and handouts (deck/deck.h, `export --deck html|pdf`, `--handout pdf`): the PDF deck has
// a page per PNG frame and each page, rendered at the frame's size by poppler, is the frame; the
// HTML deck holds one <section> per frame, points nowhere outside itself, and its images decode to
// the frames' pixels; in a real browser (headless Chromium) the arrow keys step through every
// slide and an animation step's video plays; the handout is A4 with no word under 10 pt.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "headless_browser.h"
#include "image_read.h"
#include "json_lite.h"
#include "run_command.h"

namespace pcf {
namespace {

namespace fs = std::filesystem;
using testutil::readAll;
using testutil::runPcfscope;

// The PNG frames of an export folder in the order export writes them: each step's frame, its
// pages, a predict step's answer and its pages (file names sort that way but for -reveal).
std::vector<fs::path> framesOf(const fs::path& dir) {
    std::vector<fs::path> pngs;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.path().extension() == ".png") pngs.push_back(e.path());
    }
    auto key = [](const fs::path& p) {
        std::string stem = p.stem().string();
        size_t step = stem.find("-step");
        std::string head = stem.substr(0, step + 7);  // "...-stepNN"
        bool reveal = stem.find("-reveal") != std::string::npos;
        size_t page = stem.find("-page");
        int n = page == std::string::npos ? 1 : std::stoi(stem.substr(page + 5));
        return std::make_tuple(head, reveal, n);
    };
    std::sort(pngs.begin(), pngs.end(),
              [&](const fs::path& a, const fs::path& b) { return key(a) < key(b); });
    return pngs;
}

std::vector<float> pixels(const fs::path& path, int channels) {
    return readImageFloats(path.string(), channels);
}

std::string base64Decode(const std::string& s) {
    std::string out;
    int val = 0, bits = -8;
    for (char c : s) {
        int d = c >= 'A' && c <= 'Z'   ? c - 'A'
                : c >= 'a' && c <= 'z' ? c - 'a' + 26
                : c >= '0' && c <= '9' ? c - '0' + 52
                : c == '+'             ? 62
                : c == '/'             ? 63
                                       : -1;
        if (d < 0) break;
        val = (val << 6) + d;
        bits += 6;
        if (bits >= 0) {
            out.push_back(static_cast<char>((val >> bits) & 0xFF));
            bits -= 8;
        }
    }
    return out;
}

int shell(const std::string& cmd) { return std::system((cmd + " 2>/dev/null").c_str()); }

class DeckTest : public ::testing::Test {
  protected:
    void SetUp() override { mDir = testutil::makeTempDir("deck"); }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(mDir);
    }
    fs::path mDir;
};

TEST_F(DeckTest, ThePdfDeckIsAPagePerFrameEachTheFramesPixels) {
    fs::path out = mDir / "frames";
    auto r = runPcfscope("export 3 --size 1280x720 --presentation --deck pdf -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<fs::path> frames = framesOf(out);
    ASSERT_GE(frames.size(), 8u);  // 6 steps, two of them questions with their answers
    fs::path pdf = out / "03-bilinear-lerp.pdf";
    ASSERT_EQ(shell("pdfinfo " + pdf.string() + " > " + (mDir / "info.txt").string()), 0);
    std::string info = readAll(mDir / "info.txt");
    std::smatch pages;
    ASSERT_TRUE(std::regex_search(info, pages, std::regex(R"(Pages:\s+(\d+))")));
    EXPECT_EQ(std::stoul(pages[1]), frames.size());
    // Rendered at the frame's size by poppler's cairo back end. (pdftoppm's own back end blends
    // every image drawn at less than four times its size with its neighbours, even at exactly its
    // own size: a half-pixel blur, about 4/255 on these frames, whatever the PDF holds.)
    ASSERT_EQ(shell("pdftocairo -r 72 -png " + pdf.string() + " " + (mDir / "page").string()), 0);
    for (size_t k = 0; k < frames.size(); ++k) {
        SCOPED_TRACE(frames[k].filename().string());
        // pdftoppm pads the page numbers to the digits of the last.
        char name[32];
        int digits = static_cast<int>(std::to_string(frames.size()).size());
        std::snprintf(name, sizeof name, "page-%0*zu.png", digits, k + 1);
        ImageSize size = readImageSize((mDir / name).string());
        ASSERT_EQ(size.width, 1280);
        ASSERT_EQ(size.height, 720);
        int w = size.width, h = size.height, pc = size.channels;
        std::vector<float> page = pixels(mDir / name, pc);
        std::vector<float> png = pixels(frames[k], 4);
        double sum = 0.0;
        for (size_t p = 0; p < static_cast<size_t>(w) * h; ++p) {
            for (int c = 0; c < 3; ++c) sum += std::abs(page[p * pc + c] - png[p * 4 + c]);
        }
        EXPECT_LT(sum / (static_cast<double>(w) * h * 3), 2.0 / 255.0);
    }
}

TEST_F(DeckTest, TheHtmlDeckIsSelfContainedASlidePerFrameOfTheFramesPixels) {
    fs::path out = mDir / "frames";
    auto r = runPcfscope("export 2 --size 1024x768 --presentation --deck html -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<fs::path> frames = framesOf(out);
    std::string html = readAll(out / "02-box-average.html");
    // (Searched by hand: std::regex recurses per character and a frame is a megabyte.)
    std::string lower = html;
    std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
    EXPECT_EQ(lower.find("http:"), std::string::npos);
    EXPECT_EQ(lower.find("https:"), std::string::npos);
    // Every address in it is data: nothing to fetch, not even from beside the file.
    int addresses = 0;
    for (const std::string attr : {"src=\"", "href=\"", "poster=\""}) {
        for (size_t at = 0; (at = html.find(attr, at)) != std::string::npos; ++at, ++addresses) {
            EXPECT_EQ(html.compare(at + attr.size(), 5, "data:"), 0) << html.substr(at, 60);
        }
    }
    EXPECT_GE(addresses, static_cast<int>(frames.size()));
    size_t sections = 0;
    for (size_t at = 0; (at = html.find("<section ", at)) != std::string::npos; ++at) ++sections;
    EXPECT_EQ(sections, frames.size());
    const std::string tag = "data:image/png;base64,";
    size_t k = 0;
    for (size_t at = 0; (at = html.find(tag, at)) != std::string::npos; ++k) {
        ASSERT_LT(k, frames.size());
        SCOPED_TRACE(frames[k].filename().string());
        at += tag.size();
        size_t end = html.find('"', at);
        fs::path decoded = mDir / ("slide" + std::to_string(k) + ".png");
        std::ofstream(decoded, std::ios::binary) << base64Decode(html.substr(at, end - at));
        EXPECT_EQ(pixels(decoded, 4), pixels(frames[k], 4));
        at = end;
    }
    EXPECT_EQ(k, frames.size());
    // The words as notes, the trace as a table: a question's hides its bits and its answer.
    EXPECT_NE(html.find("<aside class=\"notes\">Step 2: Only five answers"), std::string::npos);
    EXPECT_NE(html.find("<th>bit</th>"), std::string::npos);
    EXPECT_NE(html.find("visibility ?"), std::string::npos);
}

// A short lesson of its own (a question and an animation) at a small size: quick, and not moved
// by edits to the built-in lessons.
const char* SHORT_LESSON = R"(title = "Deck in a browser"
scene = "box-on-plane"
[settings]
method = "bilinear2x2"
map_size = 128
bias = "constant"
constant_bias = 0.02
point = [0.978394, 0, -0.4338]
[[step]]
title = "A lookup"
text = "Visibility {visibility}."
predict = { ask = "What visibility?", answer = "{visibility}", tolerance = 0.1 }
[[step]]
title = "The sun goes down"
text = "The sun sinks."
animate = { sweep = "sun", from = 40, to = 20, frames = 12, fps = 6 }
)";

TEST_F(DeckTest, ABrowserStepsThroughEverySlideWithTheArrowKeysAndPlaysTheVideo) {
    fs::path lesson = mDir / "short.toml";
    std::ofstream(lesson) << SHORT_LESSON;
    fs::path out = mDir / "frames";
    auto r =
        runPcfscope("export " + lesson.string() + " --size 640x360 --deck html -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    size_t slides = framesOf(out).size();
    ASSERT_GE(slides, 3u);  // the question, its answer, the animation step
    testutil::HeadlessBrowser browser("file://" + (out / "short.html").string(), mDir / "profile");
    ASSERT_TRUE(browser.waitFor("window.deckReady === true", 30));
    auto state = [&] { return browser.evaluate("deckState()"); };
    EXPECT_EQ(state()["slide"], 1);
    EXPECT_EQ(state()["slides"], static_cast<int>(slides));
    bool played = false;
    for (size_t k = 2; k <= slides; ++k) {
        browser.press("ArrowRight", 39);
        ASSERT_EQ(state()["slide"], static_cast<int>(k));
        if (!state()["video"].is_null()) {
            played = browser.waitFor(
                "deckState().video.time > 0.3 && !deckState().video.paused && "
                "deckState().video.ready >= 2",
                20);
        }
    }
    EXPECT_TRUE(played) << "the animation step's video did not play";
    browser.press("ArrowRight", 39);  // past the end: stays on the last
    EXPECT_EQ(state()["slide"], static_cast<int>(slides));
    for (size_t k = slides - 1; k >= 1; --k) {
        browser.press("ArrowLeft", 37);
        EXPECT_EQ(state()["slide"], static_cast<int>(k));
    }
    EXPECT_EQ(state()["id"], "slide1");
}

TEST_F(DeckTest, TheHandoutIsA4WithTheWordsAndTablesAtTenPointOrMore) {
    fs::path out = mDir / "frames";
    auto r = runPcfscope("export 2 --handout pdf -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    fs::path pdf = out / "02-box-average-handout.pdf";
    ASSERT_EQ(shell("pdfinfo " + pdf.string() + " > " + (mDir / "info.txt").string()), 0);
    std::string info = readAll(mDir / "info.txt");
    EXPECT_NE(info.find("(A4)"), std::string::npos) << info;
    ASSERT_EQ(shell("pdftotext -bbox " + pdf.string() + " " + (mDir / "words.html").string()), 0);
    std::string words = readAll(mDir / "words.html");
    EXPECT_NE(words.find(">Filter<"), std::string::npos);  // step 1's title
    EXPECT_NE(words.find(">weight<"), std::string::npos);  // a trace table's column
    std::regex word(R"re(yMin="([\d.]+)" xMax="[\d.]+" yMax="([\d.]+)")re");
    int count = 0;
    for (std::sregex_iterator it(words.begin(), words.end(), word), end; it != end; ++it) {
        double height = std::stod((*it)[2]) - std::stod((*it)[1]);
        EXPECT_GE(height, 10.0) << "a word set smaller than 10 pt";
        ++count;
    }
    EXPECT_GT(count, 100);
    // Only the 1600x900 frames make a handout.
    auto bad = runPcfscope("export 2 --handout pdf --size 1280x720 -o " + (mDir / "b").string());
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--handout is made of the 1600x900 frames"), std::string::npos);
}

}  // namespace
}  // namespace pcf
