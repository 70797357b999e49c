// pcss's inspector pages read from a room (issue 32): lessons 16 and 17's pcss steps, composed as
// `export` composes them at 1024x768 and 1280x720 presentation, 1600x900 and 1920x1080. The
// blocker search is its 16 taps, one disc each, drawn dark where the tap found a blocker (the
// frame's pixels are checked against the trace's bits) with its depth beside it at the numbers'
// size; the penumbra's figure is similar triangles in the proportions of the trace's d_b and
// d_r, its words cite Fernando's paper and give the trace's numbers; the filter's 16 taps are
// lit or shadowed as the trace says; every kind of disc is named in the legend.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/session.h"
#include "kernel/pcf.h"
#include "kernel/trace_explain.h"
#include "overlay/inspector.h"
#include "render/gl_context.h"

namespace pcf {
namespace {

class PcssPages : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> PcssPages::sContext;

std::string threeDecimals(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", static_cast<double>(v));
    return buf;
}

std::vector<LayoutBox> withRole(const std::vector<LayoutBox>& boxes, const std::string& role) {
    std::vector<LayoutBox> out;
    for (const LayoutBox& b : boxes) {
        if (b.role == role) out.push_back(b);
    }
    return out;
}

bool legendNames(const std::vector<LayoutBox>& boxes, const std::string& text) {
    return std::any_of(boxes.begin(), boxes.end(),
                       [&](const LayoutBox& b) { return b.role == "legend" && b.text == text; });
}

std::string pageText(const std::vector<LayoutBox>& boxes, const std::string& role) {
    std::string out;
    for (const LayoutBox& b : withRole(boxes, role)) out += b.text + " ";
    std::replace(out.begin(), out.end(), '\n', ' ');
    return out;
}

// Whether the frame's pixel at p is nearer the shadowed cells' colour than the lit ones'.
bool darkAt(const std::vector<uint8_t>& rgba, int width, glm::vec2 p) {
    size_t k = (static_cast<size_t>(p.y) * width + static_cast<size_t>(p.x)) * 4;
    glm::vec3 c(rgba[k] / 255.0f, rgba[k + 1] / 255.0f, rgba[k + 2] / 255.0f);
    auto dist = [&](const Colour& x) { return glm::length(c - glm::vec3(x)); };
    return dist(SHADOWED_COLOUR) < dist(LIT_COLOUR);
}

// One disk page: a disc per tap of [first, first + 16), dark exactly where the tap failed its
// comparison (a blocker, or a shadowed filter tap), each with its depth beside it.
void checkDisk(const std::vector<LayoutBox>& boxes, const std::vector<uint8_t>& rgba, int width,
               const Trace& tr, size_t first, const std::string& kind, float numberFloor,
               const std::string& where) {
    std::vector<LayoutBox> marks = withRole(boxes, kind + "-tap");
    std::vector<LayoutBox> depths = withRole(boxes, kind + "-depth");
    ASSERT_EQ(marks.size(), 16u) << where;
    ASSERT_EQ(depths.size(), 16u) << where;
    int dark = 0;
    for (size_t q = 0; q < 16; ++q) {
        const TapRecord& tap = tr.taps[first + q];
        glm::vec2 c = marks[q].rect.centre();
        bool isDark = darkAt(rgba, width, c);
        dark += isDark;
        EXPECT_EQ(isDark, tap.lit < 0.5f) << where << ": " << kind << " tap " << q;
        // Its depth, at the numbers' size, beside it (within a line and a half).
        std::string depth = threeDecimals(tap.depth);
        bool beside = std::any_of(depths.begin(), depths.end(), [&](const LayoutBox& d) {
            glm::vec2 near = glm::clamp(c, d.rect.position(), d.rect.position() + d.rect.size());
            return d.text == depth && glm::length(near - c) <= marks[q].rect.w + 1.5f * d.rect.h;
        });
        EXPECT_TRUE(beside) << where << ": " << kind << " tap " << q << " has no " << depth
                            << " beside it";
    }
    for (const LayoutBox& d : depths) EXPECT_GE(d.fontPx, numberFloor) << where;
    if (kind == "search") {
        EXPECT_EQ(dark, tr.pcss.blockers) << where;
    } else {
        EXPECT_EQ(16 - dark, static_cast<int>(std::lround(16 * tr.visibility))) << where;
    }
}

// The penumbra's page: the triangles in the trace's proportions, the words with its numbers.
void checkPenumbra(const std::vector<LayoutBox>& boxes, const Trace& tr, const std::string& where) {
    auto one = [&](const std::string& role) {
        std::vector<LayoutBox> b = withRole(boxes, role);
        EXPECT_EQ(b.size(), 1u) << where << ": " << role;
        return b.empty() ? Rect{} : b.front().rect;
    };
    Rect light = one("penumbra-light-bar"), blocker = one("penumbra-blocker");
    Rect receiver = one("penumbra-receiver"), band = one("penumbra-band");
    float yL = light.centre().y, yB = blocker.centre().y, yR = receiver.centre().y;
    // Similar triangles: the penumbra is to the blocker-receiver gap as the light is to the
    // light-blocker gap.
    EXPECT_NEAR(band.w / (yR - yB), light.w / (yB - yL), 0.02f * light.w / (yB - yL)) << where;
    bool spot = tr.params.depthNear > 0.0f;
    float dr = spot ? pcfPcssLinearDepth(tr.ref, tr.params.depthNear, tr.params.depthFar) : tr.ref;
    float share = tr.pcss.blockerDepth / dr;
    if (share > 0.08f && share < 0.95f) {
        EXPECT_NEAR((yB - yL) / (yR - yL), share, 0.01f) << where;
    }
    std::string words = pageText(boxes, "penumbra-words");
    for (const std::string& s :
         {std::string("Fernando"), std::string("Percentage-Closer Soft Shadows"),
          std::string("2005"), formatNumber(tr.pcss.blockerDepth), formatNumber(dr),
          formatNumber(tr.pcss.penumbra), formatNumber(tr.pcss.filterRadius),
          std::string("w = (d_r - d_b) * w_light / d_b")}) {
        EXPECT_NE(words.find(s), std::string::npos) << where << ": no \"" << s << "\" in " << words;
    }
    for (const char* role : {"penumbra-light", "penumbra-db", "penumbra-dr", "penumbra-w"}) {
        EXPECT_EQ(withRole(boxes, role).size(), 1u) << where << ": " << role;
    }
}

TEST_F(PcssPages, SearchPenumbraAndFilterReadFromARoom) {
    struct Size {
        glm::ivec2 frame;
        bool presentation;
    };
    const Size sizes[] = {
        {{1024, 768}, true}, {{1280, 720}, true}, {{1600, 900}, false}, {{1920, 1080}, false}};
    int searched = 0, widths = 0, filtered = 0, opensOnWidth = 0;
    for (const Size& size : sizes) {
        Session session(size.frame, size.presentation);
        for (const char* lesson : {"16-contact-hardening", "17-pcss-under-a-spot"}) {
            session.loadLesson(std::string(PCFSCOPE_SOURCE_DIR "/lessons/") + lesson + ".toml");
            for (int k = 0; k < session.stepCount(); ++k) {
                session.goToStep(k);
                session.setTextPage(0);
                session.compose();
                const std::optional<Trace>& tr = session.trace();
                if (!tr || tr->pcss.searchRadius <= 0.0f || session.stepLayout().inspector.empty())
                    continue;
                std::string where = std::string(lesson) + " step " + std::to_string(k + 1) +
                                    " at " + std::to_string(size.frame.x) + "x" +
                                    std::to_string(size.frame.y);
                if (size.presentation && size.frame.x == 1024) {
                    EXPECT_LE(session.textPages(), 3) << where;
                }
                float floor = typeSizes(session.stepLayout()).numberFloor;
                bool firstIsWidth = !withRole(session.boxes(), "penumbra-band").empty();
                opensOnWidth += firstIsWidth;
                for (int page = 0; page < session.textPages(); ++page) {
                    session.setTextPage(page);
                    session.compose();
                    const std::vector<LayoutBox>& b = session.boxes();
                    std::vector<uint8_t> rgba = session.readFrame();
                    std::string at = where + " page " + std::to_string(page + 1);
                    if (!withRole(b, "search-tap").empty()) {
                        ++searched;
                        checkDisk(b, rgba, size.frame.x, *tr, 0, "search", floor, at);
                        EXPECT_TRUE(legendNames(b, "blocker: depth < ref")) << at;
                        EXPECT_TRUE(legendNames(b, "not a blocker")) << at;
                        std::string result = pageText(b, "pcss-result");
                        EXPECT_NE(result.find(std::to_string(tr->pcss.blockers) + " of the 16"),
                                  std::string::npos)
                            << at << ": " << result;
                    }
                    if (!withRole(b, "filter-tap").empty()) {
                        ++filtered;
                        checkDisk(b, rgba, size.frame.x, *tr, PCF_PCSS_TAPS, "filter", floor, at);
                        EXPECT_TRUE(legendNames(b, "lit: ref <= depth")) << at;
                        EXPECT_TRUE(legendNames(b, "shadowed")) << at;
                    }
                    if (!withRole(b, "penumbra-band").empty()) {
                        ++widths;
                        checkPenumbra(b, *tr, at);
                    }
                }
            }
        }
    }
    // Lessons 16 and 17: 5 pcss steps with an inspector at every size, 2 more in normal mode
    // (16.5-6 and 17.4-5's charts leave it beside them); 16.3, 16.4 and 17.3 open on the width.
    std::printf("%d search pages, %d width pages, %d filter pages; %d steps open on the width\n",
                searched, widths, filtered, opensOnWidth);
    EXPECT_GE(searched, 20);
    EXPECT_EQ(widths, searched);
    EXPECT_EQ(filtered, searched);
    EXPECT_GE(opensOnWidth, 12);
}

}  // namespace
}  // namespace pcf
