// The step text's frame (inspector.h: planFrame): presentation type at projector sizes, text that
// pages with a "more" mark at a sentence's end and keeps its tables whole, the neighbouring steps,
// monospace table rows and code spans, and long titles laid out in linear time.
#include <gtest/gtest.h>

#include "layout_checks.h"

namespace pcf {
namespace {

using namespace testutil;

// lesson_pixels_test checks the lessons' pixel claims in presentation mode's scenes at the
// projector sizes: these.
TEST_F(Layout, PresentationScenesAreTheCheckedSizes) {
    EXPECT_EQ(glm::ivec2(inspectorLayout({1280, 720}, true).scene.size()), glm::ivec2(617, 347));
    EXPECT_EQ(glm::ivec2(inspectorLayout({1024, 768}, true).scene.size()), glm::ivec2(512, 288));
}

// Presentation type is a projector's at the small sizes: 22 px step text, 18 px numbers.
TEST_F(Layout, PresentationTypeIsLargeAtProjectorSizes) {
    for (glm::ivec2 size : {glm::ivec2{1280, 720}, glm::ivec2{1024, 768}}) {
        TypeSizes t = typeSizes(inspectorLayout(size, true));
        EXPECT_GE(t.body, 22.0f);
        EXPECT_GE(t.bodyFloor, 22.0f);
        EXPECT_GE(t.number, 18.0f);
        EXPECT_GE(t.numberFloor, 18.0f);
        TypeSizes normal = typeSizes(inspectorLayout(size, false));
        EXPECT_GT(t.body, normal.body);
        EXPECT_GT(t.number, normal.number);
    }
}

// Text that cannot fit pages, says so with a "more" mark, and every page stays in its panel.
TEST_F(Layout, LongStepTextPagesWithAMoreMarkInsteadOfClipping) {
    InspectorModel m;
    m.title = "Paging";
    m.stepTitles = {"One", "Two"};
    m.trace = syntheticTrace();
    std::string text;
    for (int k = 0; k < 120; ++k) text += "Sentence " + std::to_string(k) + " of a long step. ";
    m.stepText = text;
    InspectorLayout l = inspectorLayout({1280, 720}, true);
    m.presentation = true;
    m.sceneSize = glm::ivec2(l.scene.size());
    FramePlan plan = planFrame(l, m);
    ASSERT_GT(plan.textPages, 1);
    bool more = false;
    for (const LayoutBox& b : plan.boxes) {
        more |= b.role == "more";
        if (b.role == "step-text") {
            EXPECT_TRUE(b.shortened);
            EXPECT_GE(b.fontPx, 22.0f);
        }
    }
    EXPECT_TRUE(more);
    // In the window the mark names the keys that turn the page: on an animation step Space
    // plays, so Right. A written frame (export, animate) names no key: it has none.
    for (bool plays : {false, true}) {
        m.plays = plays;
        for (bool interactive : {false, true}) {
            m.interactive = interactive;
            int marks = 0;
            for (const LayoutBox& b : planFrame(l, m).boxes) {
                if (b.role != "more") continue;
                ++marks;
                EXPECT_EQ(b.text.starts_with("more Space/Right"), interactive && !plays) << b.text;
                EXPECT_EQ(b.text.starts_with("more Right"), interactive && plays) << b.text;
                if (!interactive) {
                    EXPECT_EQ(b.text, "more (1/" + std::to_string(plan.textPages) + ")");
                }
            }
            EXPECT_EQ(marks, 1);
        }
    }
    m.plays = false;
    m.interactive = false;
    // The last page holds the last sentence's words (nothing is dropped between pages).
    m.textPage = plan.textPages - 1;
    FramePlan last = planFrame(l, m);
    EXPECT_TRUE(problems(last, l).empty());
    // A short text is one page, not shortened, no mark.
    m.stepText = "Short.";
    m.textPage = 0;
    FramePlan one = planFrame(l, m);
    EXPECT_EQ(one.textPages, 1);
    for (const LayoutBox& b : one.boxes) {
        EXPECT_NE(b.role, "more");
        if (b.role == "step-text") {
            EXPECT_FALSE(b.shortened);
        }
    }
}

// A page of step text ends where a sentence or a paragraph ends, and a preformatted block (a
// table, a formula) stays on one page: a slide that stopped at "p = uv * size" with "- 0.5" on
// the next (3.6 at 1280x720 presentation) stated another formula than the lesson's.
TEST_F(Layout, PagesEndAtSentencesAndKeepTablesWhole) {
    InspectorModel m;
    m.title = "Paging";
    m.stepTitles = {"One", "Two"};
    m.trace = syntheticTrace();
    m.presentation = true;
    std::string text;
    for (int k = 0; k < 14; ++k) {
        text += "Sentence " + std::to_string(k) +
                " runs on over more than one line of the step panel, so that a page that is cut "
                "at a fixed count of lines ends in its middle. ";
        if (k == 6) text += "The rows:\n  a     b     c\n  1.0   2.0   3.0\n  4.0   5.0   6.0\n";
    }
    m.stepText = text;
    for (glm::ivec2 size : {glm::ivec2{1024, 768}, glm::ivec2{1280, 720}}) {
        InspectorLayout l = inspectorLayout(size, true);
        m.sceneSize = glm::ivec2(l.scene.size());
        m.textPage = 0;
        int pages = planFrame(l, m).textPages;
        ASSERT_GT(pages, 2) << size.x;
        std::string all;
        int tablePage = -1;
        for (int page = 0; page < pages; ++page) {
            m.textPage = page;
            FramePlan plan = planFrame(l, m);
            EXPECT_TRUE(problems(plan, l).empty()) << size.x << " page " << page + 1;
            std::string shown;
            for (const LayoutBox& b : plan.boxes) {
                if (b.role == "step-text") shown = b.text;
            }
            ASSERT_FALSE(shown.empty()) << size.x << " page " << page + 1;
            // At a sentence's end or after the table that ends one; never one sentence alone.
            if (page + 1 < pages) {
                EXPECT_TRUE(endsCleanly(shown)) << size.x << " page " << page + 1 << " ends \""
                                                << shown.substr(shown.size() - 20) << "\"";
            }
            EXPECT_GE(sentencesIn(shown), 2) << size.x << " page " << page + 1 << ": " << shown;
            size_t rows = 0;
            for (const char* row : {"  a ", "  1.0 ", "  4.0 "})
                rows += shown.find(row) != std::string::npos;
            if (rows > 0) {
                EXPECT_EQ(rows, 3u) << size.x << " page " << page + 1 << ": the table is split";
                // With the words that lead into it.
                EXPECT_NE(shown.find("The rows:\n  a "), std::string::npos) << shown;
                tablePage = page;
            }
            for (char c : shown) all += c == '\n' ? ' ' : c;
            all += ' ';
        }
        EXPECT_GE(tablePage, 0) << size.x;
        // Nothing is dropped between pages: every sentence is on one of them.
        for (int k = 0; k < 14; ++k) {
            EXPECT_NE(all.find("Sentence " + std::to_string(k) + " "), std::string::npos) << k;
        }
    }
}

// Presentation mode keeps the step list's neighbours of the current step, at 18 px or more at
// projector sizes: the previous step on the left, the next on the right.
TEST_F(Layout, PresentationShowsTheNeighbouringStepsAtReadableSize) {
    InspectorModel m;
    m.trace = syntheticTrace();
    m.stepTitles = {"First step", "Second step", "Third step"};
    m.stepText = "Short.";
    m.presentation = true;
    for (glm::ivec2 size : {glm::ivec2{1280, 720}, glm::ivec2{1024, 768}}) {
        InspectorLayout l = inspectorLayout(size, true);
        m.sceneSize = glm::ivec2(l.scene.size());
        for (int current : {0, 1, 2}) {
            m.currentStep = current;
            FramePlan plan = planFrame(l, m);
            std::vector<LayoutBox> items;
            for (const LayoutBox& b : plan.boxes) {
                if (b.role == "step-list") items.push_back(b);
            }
            ASSERT_EQ(items.size(), current == 1 ? 2u : 1u) << current;
            for (const LayoutBox& b : items) {
                EXPECT_GE(b.fontPx, 18.0f);
                EXPECT_FALSE(b.shortened);
            }
            if (current == 1) {
                EXPECT_LT(items[0].rect.x, items[1].rect.x);  // previous, next
            }
            EXPECT_TRUE(problems(plan, l).empty());
        }
    }
}

// The plan of a frame of layout `l` whose one step, `title`, says `text` beside the small
// bilinear trace.
FramePlan stepTextPlan(const InspectorLayout& l, const std::string& title,
                       const std::string& text) {
    InspectorModel m;
    m.trace = syntheticTrace();
    m.stepTitles = {title};
    m.stepText = text;
    m.sceneSize = glm::ivec2(l.scene.size());
    return planFrame(l, m);
}

// Preformatted rows (two leading spaces) keep their columns: cells padded to the widest.
TEST_F(Layout, TableRowsKeepTheirColumnsInMonospace) {
    InspectorLayout l = inspectorLayout({1600, 900}, false);
    FramePlan plan =
        stepTextPlan(l, "Table", "Weights:\n  0.1171   1   0.0678\n  1   0.6333   1\nend");
    // Draw into a recording canvas is GL; instead check the rows' widths: equal in monospace.
    // The step-text box is as wide as its widest line; both rows pad to "0.1171   0.6333   ..."
    // so that the width of the block equals the measured row of the widest cells.
    float rowW = measureText(FontFace::Mono, typeSizes(l).body, "  0.1171   0.6333   0.0678").x;
    for (const LayoutBox& b : plan.boxes) {
        if (b.role == "step-text") {
            EXPECT_GE(b.rect.w + 0.5f, rowW);
        }
    }
}

// A `code span` in the step text is set in monospace without its backticks: the one-line block is
// as wide as its prose in Sans plus its span in Mono.
TEST_F(Layout, CodeSpansInStepTextAreMonospaceWithoutBackticks) {
    const std::string text = "Set `origin_shift = 0.25` now.";
    InspectorLayout l = inspectorLayout({1600, 900}, false);
    FramePlan plan = stepTextPlan(l, "Span", text);
    bool found = false;
    for (const LayoutBox& b : plan.boxes) {
        if (b.role != "step-text") continue;
        found = true;
        float px = b.fontPx;
        float expected = measureText(FontFace::Sans, px, "Set ").x +
                         measureText(FontFace::Mono, px, "origin_shift = 0.25").x +
                         measureText(FontFace::Sans, px, " now.").x;
        EXPECT_NEAR(b.rect.w, expected, 1.0f);
        EXPECT_GT(std::fabs(b.rect.w - measureText(FontFace::Sans, px, text).x), 2.0f);
        EXPECT_FALSE(b.shortened);
    }
    EXPECT_TRUE(found);
    EXPECT_TRUE(problems(plan, l).empty());
}

// The step JSON's `text` is the text as drawn: code spans lose their backticks, a lone backtick
// stays, preformatted rows keep theirs and their columns line up as drawn.
TEST(DrawnStepText, DropsCodeSpanBackticksAsTheFrameDraws) {
    EXPECT_EQ(drawnStepText("Set `origin_shift = 0.25` now."), "Set origin_shift = 0.25 now.");
    EXPECT_EQ(drawnStepText("a `b` and `c`\nit's 5` wide"), "a b and c\nit's 5` wide");
    EXPECT_EQ(drawnStepText("Rows:\n  `x`  1\n  `yy`  0.5\nend `z`"),
              "Rows:\n  `x`    1\n  `yy`   0.5\nend z");
    EXPECT_EQ(drawnStepText(""), "");
}

// A title of 200,000 characters is laid out in linear time (it once took minutes: wrapping
// re-measured the growing line for every word).
TEST_F(Layout, LongTitlesLayOutInLinearTime) {
    auto timeFor = [](size_t chars) {
        InspectorModel m;
        std::string title;
        while (title.size() < chars) title += "word ";
        m.title = title;
        m.stepTitles = {title, "short"};
        m.stepText = title;
        m.trace = syntheticTrace();
        InspectorLayout l = inspectorLayout({1280, 720}, false);
        m.sceneSize = glm::ivec2(l.scene.size());
        auto start = std::chrono::steady_clock::now();
        FramePlan plan = planFrame(l, m);
        EXPECT_FALSE(plan.boxes.empty());
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    timeFor(1000);  // atlases warm
    double small = timeFor(50000);
    double large = timeFor(200000);
    std::printf("layout of a 50,000-char title %.3f s, 200,000-char %.3f s\n", small, large);
    EXPECT_LT(large, 5.0);
    // Linear: 4x the text, well under 16x the time (allow noise on a shared machine).
    EXPECT_LT(large, 10.0 * small + 0.2);
}

}  // namespace
}  // namespace pcf
