// The overlay canvas on llvmpipe through EGL: exact coverage, painter's order, crisp text,
// determinism and batching. Pixels are read back with rows top-down, like the canvas counts.
#include "draw/canvas.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>

#include "image_read.h"
#include "render/gl_context.h"
#include "render/gl_objects.h"
#include "render/image_io.h"

namespace pcf {
namespace {

using Rgba = glm::u8vec4;

const Colour BLACK{0, 0, 0, 1};
const Colour WHITE{1, 1, 1, 1};
const Colour RED{1, 0, 0, 1};
const Colour GREEN{0, 1, 0, 1};
const Colour BLUE{0, 0, 1, 1};

const Rgba OPAQUE_BLACK{0, 0, 0, 255};

struct Image {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;  // rows top-down

    Rgba at(int x, int y) const {
        size_t k = (static_cast<size_t>(y) * width + x) * 4;
        return {rgba[k], rgba[k + 1], rgba[k + 2], rgba[k + 3]};
    }
    // Sum of the red channel over the image, in pixels of full intensity.
    double redCoverage() const {
        double sum = 0.0;
        for (size_t k = 0; k < rgba.size(); k += 4) sum += rgba[k];
        return sum / 255.0;
    }
};

std::string str(Rgba c) {
    return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) +
           ", " + std::to_string(c.a) + ")";
}

class OverlayCanvas : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    void SetUp() override { sContext->makeCurrent(); }

    // A fresh Canvas draws `draw` into a width x height RGBA8 target cleared to opaque black.
    static Image render(int width, int height, const std::function<void(Canvas&)>& draw,
                        int* drawCalls = nullptr) {
        OffscreenTarget t = createOffscreenTarget(width, height, {GL_RGBA8});
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.framebuffer.id());
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        {
            Canvas canvas;
            canvas.begin({width, height});
            draw(canvas);
            canvas.flush();
            if (drawCalls != nullptr) *drawCalls = canvas.lastFlushDrawCalls();
        }
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        return {width, height,
                readPixelsRgba8(t.framebuffer.id(), GL_COLOR_ATTACHMENT0, width, height)};
    }

    static std::unique_ptr<GlContext> sContext;
};

std::unique_ptr<GlContext> OverlayCanvas::sContext;

// Every pixel is `inside` where mask(x, y) holds and opaque black elsewhere.
void expectExactly(const Image& image, const std::function<bool(int, int)>& mask, Rgba inside) {
    int wrong = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            Rgba want = mask(x, y) ? inside : OPAQUE_BLACK;
            if (image.at(x, y) != want && ++wrong <= 5) {
                ADD_FAILURE() << "pixel (" << x << ", " << y << ") from the top-left is "
                              << str(image.at(x, y)) << ", want " << str(want);
            }
        }
    }
    EXPECT_EQ(wrong, 0);
}

TEST_F(OverlayCanvas, FillRectCoversExactlyItsPixelsFromTheTop) {
    Image image = render(200, 100, [](Canvas& c) { c.fillRect({10, 20, 30, 5}, RED); });
    // Inside, and one pixel outside on each side.
    EXPECT_EQ(image.at(10, 20), Rgba(255, 0, 0, 255));
    EXPECT_EQ(image.at(39, 24), Rgba(255, 0, 0, 255));
    EXPECT_EQ(image.at(9, 22), OPAQUE_BLACK);
    EXPECT_EQ(image.at(40, 22), OPAQUE_BLACK);
    EXPECT_EQ(image.at(25, 19), OPAQUE_BLACK);
    EXPECT_EQ(image.at(25, 25), OPAQUE_BLACK);
    expectExactly(image, [](int x, int y) { return x >= 10 && x < 40 && y >= 20 && y < 25; },
                  {255, 0, 0, 255});
}

TEST_F(OverlayCanvas, FillRectOnA100x100TargetToo) {
    Image image = render(100, 100, [](Canvas& c) { c.fillRect({10, 20, 30, 5}, WHITE); });
    expectExactly(image, [](int x, int y) { return x >= 10 && x < 40 && y >= 20 && y < 25; },
                  {255, 255, 255, 255});
}

TEST_F(OverlayCanvas, TranslucentFillBlendsOver) {
    Image image = render(200, 100, [](Canvas& c) {
        c.fillRect({0, 0, 200, 100}, {0, 0, 1, 1});
        c.fillRect({50, 50, 10, 10}, {1, 0, 0, 0.5f});
    });
    Rgba p = image.at(55, 55);
    EXPECT_NEAR(p.r, 128, 1);
    EXPECT_EQ(p.g, 0);
    EXPECT_NEAR(p.b, 127, 1);
    EXPECT_EQ(p.a, 255);
    EXPECT_EQ(image.at(49, 55), Rgba(0, 0, 255, 255));
}

TEST_F(OverlayCanvas, StrokeRectDrawsTheBorderInsideAndLeavesTheInsideClear) {
    Image image = render(200, 100, [](Canvas& c) { c.strokeRect({20, 10, 60, 40}, 2, WHITE); });
    auto inRect = [](int x, int y, int x0, int y0, int x1, int y1) {
        return x >= x0 && x < x1 && y >= y0 && y < y1;
    };
    EXPECT_EQ(image.at(50, 30), OPAQUE_BLACK);  // the middle
    EXPECT_EQ(image.at(22, 12), OPAQUE_BLACK);  // just inside the border
    EXPECT_EQ(image.at(21, 11), Rgba(255, 255, 255, 255));
    expectExactly(
        image,
        [&](int x, int y) { return inRect(x, y, 20, 10, 80, 50) && !inRect(x, y, 22, 12, 78, 48); },
        {255, 255, 255, 255});
}

TEST_F(OverlayCanvas, TranslucentStrokeCornersAreNotDrawnTwice) {
    Image image = render(200, 100, [](Canvas& c) {
        c.strokeRect({20, 10, 60, 40}, 3, {1, 0, 0, 0.5f});
    });
    EXPECT_EQ(image.at(20, 10), image.at(50, 10));  // corner = middle of the top edge
    EXPECT_EQ(image.at(79, 49), image.at(20, 30));
}

TEST_F(OverlayCanvas, ThickHorizontalLineCoversTheExpectedRows) {
    Image image = render(200, 100, [](Canvas& c) { c.line({10, 50}, {190, 50}, 4, GREEN); });
    expectExactly(image, [](int x, int y) { return x >= 10 && x < 190 && y >= 48 && y < 52; },
                  {0, 255, 0, 255});
}

TEST_F(OverlayCanvas, OnePixelLinesOnPixelCentresFillOneRowOrColumn) {
    Image image = render(200, 100, [](Canvas& c) {
        c.line({0, 10.5f}, {50, 10.5f}, 1, WHITE);
        c.line({100.5f, 90}, {100.5f, 60}, 1, WHITE);
    });
    expectExactly(
        image, [](int x, int y) { return (y == 10 && x < 50) || (x == 100 && y >= 60 && y < 90); },
        {255, 255, 255, 255});
}

TEST_F(OverlayCanvas, SlantedLineCoversItsAreaWithAntialiasedEdges) {
    glm::vec2 a(20, 80);
    glm::vec2 b(180, 20);
    const float width = 3.0f;
    Image image = render(200, 100, [&](Canvas& c) { c.line(a, b, width, RED); });
    EXPECT_EQ(image.at(100, 50), Rgba(255, 0, 0, 255));  // on the line
    EXPECT_EQ(image.at(100, 80), OPAQUE_BLACK);          // far from it
    EXPECT_EQ(image.at(20, 20), OPAQUE_BLACK);
    // Antialiasing keeps the covered area: length x width.
    EXPECT_NEAR(image.redCoverage(), glm::distance(a, b) * width, 0.02 * glm::distance(a, b) * 3);
    // ... and gives partial pixels along the edges.
    int partial = 0;
    for (size_t k = 0; k < image.rgba.size(); k += 4) {
        partial += image.rgba[k] > 0 && image.rgba[k] < 255;
    }
    EXPECT_GT(partial, 100);
}

TEST_F(OverlayCanvas, CircleCoversItsCentreAndNotItsBoundingBoxCorners) {
    const float r = 30.0f;
    Image image = render(200, 100, [&](Canvas& c) { c.circle({100, 50}, r, RED); });
    EXPECT_EQ(image.at(100, 50), Rgba(255, 0, 0, 255));
    EXPECT_EQ(image.at(99, 49), Rgba(255, 0, 0, 255));
    EXPECT_EQ(image.at(127, 50), Rgba(255, 0, 0, 255));  // inside, near the right edge
    for (glm::ivec2 corner :
         {glm::ivec2(70, 20), glm::ivec2(129, 20), glm::ivec2(70, 79), glm::ivec2(129, 79)}) {
        EXPECT_EQ(image.at(corner.x, corner.y), OPAQUE_BLACK) << corner.x << ", " << corner.y;
    }
    EXPECT_EQ(image.at(131, 50), OPAQUE_BLACK);  // just outside
    EXPECT_NEAR(image.redCoverage(), M_PI * r * r, 0.005 * M_PI * r * r);
}

TEST_F(OverlayCanvas, RingLeavesItsCentreClear) {
    const float r = 30.0f;
    const float w = 4.0f;
    Image image = render(200, 100, [&](Canvas& c) { c.ring({100, 50}, r, w, RED); });
    EXPECT_EQ(image.at(100, 50), OPAQUE_BLACK);
    EXPECT_EQ(image.at(115, 50), OPAQUE_BLACK);
    EXPECT_EQ(image.at(129, 50), Rgba(255, 0, 0, 255));  // pixel centre 29.5 from the centre
    EXPECT_EQ(image.at(70, 50), Rgba(255, 0, 0, 255));
    EXPECT_EQ(image.at(135, 50), OPAQUE_BLACK);
    EXPECT_NEAR(image.redCoverage(), 2 * M_PI * r * w, 0.01 * 2 * M_PI * r * w);
}

TEST_F(OverlayCanvas, ArrowDrawsItsShaftAndHeadUpToTheTip) {
    // Width 2: the head is 8 px long and 8 px wide, tip at x = 180.
    Image image = render(200, 100, [](Canvas& c) { c.arrow({20, 50}, {180, 50}, 2, WHITE); });
    const Rgba lit(255, 255, 255, 255);
    // The shaft: rows 49 and 50, exactly.
    EXPECT_EQ(image.at(100, 49), lit);
    EXPECT_EQ(image.at(100, 50), lit);
    EXPECT_EQ(image.at(100, 48), OPAQUE_BLACK);
    EXPECT_EQ(image.at(100, 51), OPAQUE_BLACK);
    EXPECT_EQ(image.at(20, 49), lit);
    EXPECT_EQ(image.at(19, 49), OPAQUE_BLACK);
    // The head: wider than the shaft near its base, only there.
    EXPECT_EQ(image.at(173, 47), lit);
    EXPECT_EQ(image.at(173, 52), lit);
    EXPECT_GT(image.at(177, 49).r, 200);
    EXPECT_EQ(image.at(170, 47), OPAQUE_BLACK);  // before the base
    EXPECT_EQ(image.at(182, 50), OPAQUE_BLACK);  // beyond the tip
    EXPECT_EQ(image.at(173, 44), OPAQUE_BLACK);  // beside the head
}

TEST_F(OverlayCanvas, SlantedArrowHeadIsDrawnAtTheTip) {
    glm::vec2 tip(150, 80);
    Image image = render(200, 100, [&](Canvas& c) { c.arrow({30, 10}, tip, 3, WHITE); });
    // 12 px head: a point 4 px back from the tip along the arrow is inside it.
    glm::vec2 d = glm::normalize(tip - glm::vec2(30, 10));
    glm::vec2 inHead = tip - 4.0f * d;
    EXPECT_EQ(image.at(int(inHead.x), int(inHead.y)), Rgba(255, 255, 255, 255));
    // ... and 4 px to the side of the shaft, 8 px back from the tip: head, not shaft.
    glm::vec2 side = tip - 9.0f * d + 4.0f * glm::vec2(-d.y, d.x);
    EXPECT_GT(image.at(int(side.x), int(side.y)).r, 128);
    glm::vec2 sideOfShaft = tip - 60.0f * d + 4.0f * glm::vec2(-d.y, d.x);
    EXPECT_EQ(image.at(int(sideOfShaft.x), int(sideOfShaft.y)), OPAQUE_BLACK);
}

// Red rect, white text on it, then a blue rect over part of the text: the blue wins where it
// is drawn, and the text shows (over the red) where it is not.
TEST_F(OverlayCanvas, PaintersOrderHoldsAcrossShapesAndText) {
    const TextStyle style{FontFace::Sans, 40.0f, WHITE};
    auto scene = [&](bool withBlue) {
        return [=](Canvas& c) {
            c.fillRect({10, 10, 180, 80}, RED);
            c.text({20, 25}, "888 888", style);
            if (withBlue) c.fillRect({100, 10, 90, 80}, BLUE);
        };
    };
    Image without = render(200, 100, scene(false));
    Image with = render(200, 100, scene(true));
    int textUnderBlue = 0;
    int whiteLeft = 0;
    for (int y = 10; y < 90; ++y) {
        for (int x = 10; x < 190; ++x) {
            if (x >= 100) {
                textUnderBlue += without.at(x, y) == Rgba(255, 255, 255, 255);
                EXPECT_EQ(with.at(x, y), Rgba(0, 0, 255, 255)) << x << ", " << y;
            } else {
                EXPECT_EQ(with.at(x, y), without.at(x, y));
                EXPECT_EQ(with.at(x, y).b, with.at(x, y).g);  // white over red: r, g = b
                whiteLeft += with.at(x, y) == Rgba(255, 255, 255, 255);
            }
        }
    }
    EXPECT_GT(textUnderBlue, 50) << "the blue rect must cover some text";
    EXPECT_GT(whiteLeft, 50) << "the text must show over the red";
}

TEST_F(OverlayCanvas, TextLitPixelsStayInsideTheReturnedRect) {
    Rect box;
    Image image = render(200, 100, [&](Canvas& c) {
        box = c.text({50, 20}, "8", {FontFace::Sans, 40.0f, WHITE});
    });
    EXPECT_EQ(box.x, 50.0f);
    EXPECT_EQ(box.y, 20.0f);
    EXPECT_EQ(box.w, glyphAtlas(FontFace::Sans, 40.0f).glyph(U'8').advance);
    EXPECT_EQ(box.h, glyphAtlas(FontFace::Sans, 40.0f).metrics().lineHeight);
    int inside = 0;
    int outside = 0;
    int full = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            Rgba p = image.at(x, y);
            if (p == OPAQUE_BLACK) continue;
            EXPECT_TRUE(p.r == p.g && p.g == p.b && p.a == 255);  // grey coverage of white
            bool in = box.contains({x + 0.5f, y + 0.5f});
            inside += in;
            outside += !in;
            full += p.r == 255;
        }
    }
    EXPECT_GT(inside, 100);
    EXPECT_EQ(outside, 0);
    // Crisp: a 40 px '8' has many fully covered pixels (a blurred one would have few).
    EXPECT_GT(full, 60);
}

TEST_F(OverlayCanvas, TextAlignPlacesLinesAroundTheAnchor) {
    const TextStyle left{FontFace::Mono, 20.0f, WHITE, TextAlign::Left};
    TextStyle centre = left;
    centre.align = TextAlign::Center;
    TextStyle right = left;
    right.align = TextAlign::Right;
    float w = measureText(FontFace::Mono, 20.0f, "0.75").x;
    Rect l;
    Rect c;
    Rect r;
    render(200, 100, [&](Canvas& canvas) {
        l = canvas.text({100, 10}, "0.75", left);
        c = canvas.text({100, 10}, "0.75", centre);
        r = canvas.text({100, 10}, "0.75", right);
    });
    EXPECT_EQ(l, (Rect{100, 10, w, l.h}));
    EXPECT_EQ(c, (Rect{100 - std::round(w / 2), 10, w, l.h}));
    EXPECT_EQ(r, (Rect{100 - w, 10, w, l.h}));
}

// Each glyph's pixels are its atlas bitmap, byte for byte: white text on black writes the
// coverage itself. No scaling, no filtering, at every size, from fractional positions too.
TEST_F(OverlayCanvas, GlyphsMapOneToOneOntoPixels) {
    for (float size : {9.0f, 13.0f, 16.0f, 23.0f, 40.0f}) {
        SCOPED_TRACE(::testing::Message() << size << " px");
        GlyphAtlas& atlas = glyphAtlas(FontFace::Sans, size);
        const glm::vec2 pos(7.4f, 5.6f);  // rounds to (7, 6)
        Image image = render(120, 80, [&](Canvas& c) {
            c.text(pos, "g@", {FontFace::Sans, size, WHITE});
        });
        TextLayout layout = layoutText(atlas, "g@");
        ASSERT_EQ(layout.glyphs.size(), 2u);
        GlyphAtlas::Image bitmap = atlas.image();
        for (const PlacedGlyph& g : layout.glyphs) {
            int mismatches = 0;
            for (int y = 0; y < g.glyph.size.y; ++y) {
                for (int x = 0; x < g.glyph.size.x; ++x) {
                    uint8_t want =
                        bitmap.pixels[static_cast<size_t>(g.glyph.atlasPos.y + y) * bitmap.size.x +
                                      g.glyph.atlasPos.x + x];
                    Rgba got = image.at(7 + g.topLeft.x + x, 6 + g.topLeft.y + y);
                    mismatches += got != Rgba(want, want, want, 255);
                }
            }
            EXPECT_EQ(mismatches, 0);
        }
    }
}

TEST_F(OverlayCanvas, DifferentStringsGiveDifferentPixels) {
    auto draw = [](const char* s) {
        return [=](Canvas& c) { c.text({10, 10}, s, {FontFace::Mono, 24.0f, WHITE}); };
    };
    Image a = render(200, 100, draw("0.25"));
    Image b = render(200, 100, draw("0.75"));
    EXPECT_NE(a.rgba, b.rgba);
    // Same prefix, same pixels there: "0." occupies the first two advances.
    int prefix = static_cast<int>(2 * glyphAtlas(FontFace::Mono, 24.0f).glyph(U'0').advance);
    for (int y = 0; y < 100; ++y) {
        for (int x = 0; x < 10 + prefix; ++x) ASSERT_EQ(a.at(x, y), b.at(x, y));
    }
}

TEST_F(OverlayCanvas, TextBoxWrapsIntoTheBoxWidth) {
    const char* paragraph =
        "A tap is lit when ref ≤ depth. The weights of the taps sum to 1, so the result is "
        "a visibility in [0, 1].";
    const TextStyle style{FontFace::Sans, 14.0f, WHITE};
    const Rect box{20, 10, 120, 80};
    float used = 0.0f;
    Image image = render(200, 100, [&](Canvas& c) { used = c.textBox(box, paragraph, style); });
    std::vector<std::string> lines = wrapText(FontFace::Sans, 14.0f, paragraph, box.w);
    float lineHeight = fontMetrics(FontFace::Sans, 14.0f).lineHeight;
    EXPECT_GE(lines.size(), 3u);
    EXPECT_EQ(used, lines.size() * lineHeight);
    int lit = 0;
    for (int y = 0; y < 100; ++y) {
        for (int x = 0; x < 200; ++x) {
            if (image.at(x, y) == OPAQUE_BLACK) continue;
            ++lit;
            EXPECT_TRUE(x >= box.x && x < box.right() && y >= box.y && y < box.y + used)
                << x << ", " << y;
        }
    }
    EXPECT_GT(lit, 300);
}

TEST_F(OverlayCanvas, ClipLimitsDrawingToTheClipRect) {
    int drawCalls = 0;
    Image image = render(
        200, 100,
        [](Canvas& c) {
            c.pushClip({50, 25, 100, 50});
            c.pushClip({0, 0, 120, 60});  // nested: the intersection
            c.fillRect({0, 0, 200, 100}, RED);
            c.popClip();
            c.popClip();
            c.fillRect({0, 90, 10, 10}, RED);  // after the clip: anywhere again
        },
        &drawCalls);
    expectExactly(image,
                  [](int x, int y) {
                      return (x >= 50 && x < 120 && y >= 25 && y < 60) || (x < 10 && y >= 90);
                  },
                  {255, 0, 0, 255});
    EXPECT_EQ(drawCalls, 2);
}

// Large opaque rects become scissored clears that run before the flush's draws; they must keep
// the painter's order: one drawn over an earlier shape still covers it, a later shape still
// covers the rect.
TEST_F(OverlayCanvas, LargeOpaqueRectsKeepThePaintersOrder) {
    const Colour green{0.0f, 1.0f, 0.0f, 1.0f};
    Image image = render(200, 100, [&](Canvas& c) {
        c.fillRect({10, 10, 20, 20}, green);   // small: drawn
        c.fillRect({0, 0, 100, 100}, RED);     // over the green: must hide it
        c.fillRect({120, 0, 80, 100}, RED);    // touches nothing before it
        c.fillRect({150, 40, 10, 10}, green);  // over that red: must show
    });
    int wrong = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            bool shown = x >= 150 && x < 160 && y >= 40 && y < 50;
            Rgba want = shown                   ? Rgba(0, 255, 0, 255)
                        : (x < 100 || x >= 120) ? Rgba(255, 0, 0, 255)
                                                : OPAQUE_BLACK;
            if (image.at(x, y) != want) ++wrong;
        }
    }
    EXPECT_EQ(wrong, 0);
}

TEST_F(OverlayCanvas, PopClipWithoutPushThrows) {
    Canvas c;
    c.begin({10, 10});
    EXPECT_THROW(c.popClip(), std::logic_error);
}

TEST_F(OverlayCanvas, FlushBeforeBeginThrowsAndBadSizesAreRejected) {
    Canvas c;
    EXPECT_THROW(c.flush(), std::logic_error);
    EXPECT_THROW(c.begin({0, 10}), std::invalid_argument);
    c.begin({10, 10});
    EXPECT_THROW(c.text({0, 0}, "x", {FontFace::Sans, 0.0f}), std::invalid_argument);
}

// 200 rects and 50 labels in three styles, interleaved: one draw call.
TEST_F(OverlayCanvas, BatchesAFrameIntoFewDrawCalls) {
    int drawCalls = -1;
    Image image = render(
        640, 400,
        [](Canvas& c) {
            const TextStyle styles[3] = {{FontFace::Sans, 14.0f, WHITE},
                                         {FontFace::Mono, 14.0f, {1, 1, 0, 1}},
                                         {FontFace::Sans, 20.0f, {0, 1, 1, 1}}};
            for (int k = 0; k < 200; ++k) {
                c.fillRect(
                    {static_cast<float>(k % 20) * 32, static_cast<float>(k / 20) * 40, 30, 38},
                    {k / 200.0f, 0.2f, 0.4f, 1});
                if (k % 4 == 0) {
                    c.text(
                        {static_cast<float>(k % 20) * 32 + 2, static_cast<float>(k / 20) * 40 + 2},
                        std::to_string(k), styles[(k / 4) % 3]);
                }
            }
        },
        &drawCalls);
    EXPECT_GE(drawCalls, 1);
    EXPECT_LE(drawCalls, 8);
    EXPECT_EQ(drawCalls, 1);
    EXPECT_NE(image.at(5, 5), OPAQUE_BLACK);
}

// A background whose every pixel differs, so that a blend over it shows any change of colour.
void drawGradient(Canvas& c, int width, int height) {
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; x += 8) {
            c.fillRect({static_cast<float>(x), static_cast<float>(y), 8, 1},
                       {x / float(width), y / float(height), 0.5f, 1.0f});
        }
    }
}

// A texel-grid-like picture: translucent edges every 5 pixels, a tinted footprint, holes.
std::shared_ptr<const CanvasImage> gridPicture(glm::ivec2 size) {
    const Colour edge{0.05f, 0.05f, 0.1f, 0.35f};
    const Colour footprintEdge{0.1f, 0.9f, 1.0f, 0.95f};
    const Colour tint{1.0f, 0.85f, 0.2f, 0.18f};
    std::vector<glm::vec4> pixels(static_cast<size_t>(size.x) * size.y, glm::vec4(0.0f));
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            bool inFootprint = x >= 10 && x < 25 && y >= 5 && y < 20;
            bool onEdge = x % 5 == 0 || y % 5 == 0;
            if ((x + y) % 17 == 0) continue;  // a hole: left alone
            Colour c =
                onEdge ? (inFootprint ? footprintEdge : edge) : (inFootprint ? tint : Colour{0});
            pixels[static_cast<size_t>(y) * size.x + x] = c;
        }
    }
    return std::make_shared<const CanvasImage>(size, std::move(pixels));
}

// The scene's texel grid is drawn as one image instead of 1-pixel runs of rects: every pixel
// must come out as the fillRect of its texel's colour gave it, byte for byte, in one quad.
TEST_F(OverlayCanvas, ImageBlendsEachTexelExactlyAsFillRectOfItsColour) {
    const glm::ivec2 at{7, 3};
    std::shared_ptr<const CanvasImage> picture = gridPicture({40, 30});
    size_t imageVertices = 0;
    int imageCalls = -1;
    Image viaImage = render(
        64, 48,
        [&](Canvas& c) {
            drawGradient(c, 64, 48);
            size_t before = c.pendingVertexCount();
            c.image(at, picture);
            imageVertices = c.pendingVertexCount() - before;
        },
        &imageCalls);
    Image viaRects = render(64, 48, [&](Canvas& c) {
        drawGradient(c, 64, 48);
        for (int y = 0; y < picture->size.y; ++y) {
            for (int x = 0; x < picture->size.x; ++x) {
                glm::vec4 col = picture->pixels[static_cast<size_t>(y) * picture->size.x + x];
                if (col.a > 0.0f) {
                    c.fillRect({static_cast<float>(at.x + x), static_cast<float>(at.y + y), 1, 1},
                               col);
                }
            }
        }
    });
    EXPECT_EQ(imageVertices, 6u);
    EXPECT_EQ(imageCalls, 1);  // the image shares the shapes' draw call
    int differ = 0;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            if (viaImage.at(x, y) != viaRects.at(x, y) && ++differ <= 5) {
                ADD_FAILURE() << "pixel (" << x << ", " << y << "): image "
                              << str(viaImage.at(x, y)) << ", rects " << str(viaRects.at(x, y));
            }
        }
    }
    EXPECT_EQ(differ, 0);
    // The picture did draw (its edge colour over the background), and not outside its box.
    Image background = render(64, 48, [](Canvas& c) { drawGradient(c, 64, 48); });
    EXPECT_NE(viaImage.at(at.x + 1, at.y), background.at(at.x + 1, at.y));  // an edge texel
    EXPECT_EQ(viaImage.at(at.x + 40, at.y), background.at(at.x + 40, at.y));
    EXPECT_EQ(viaImage.at(at.x, at.y + 30), background.at(at.x, at.y + 30));
    EXPECT_EQ(viaImage.at(at.x - 1, at.y), background.at(at.x - 1, at.y));
}

// Two different images in one frame, the second partly clipped: each draws its own texels.
TEST_F(OverlayCanvas, TwoImagesInOneFrameEachDrawTheirOwnAndHonourTheClip) {
    auto red = std::make_shared<const CanvasImage>(glm::ivec2(4, 4),
                                                   std::vector<glm::vec4>(16, glm::vec4(RED)));
    auto blue = std::make_shared<const CanvasImage>(glm::ivec2(4, 4),
                                                    std::vector<glm::vec4>(16, glm::vec4(BLUE)));
    Image image = render(16, 8, [&](Canvas& c) {
        c.image({0, 0}, red);
        c.pushClip({8, 0, 2, 8});
        c.image({8, 0}, blue);
        c.popClip();
    });
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 16; ++x) {
            Rgba want = OPAQUE_BLACK;
            if (x < 4 && y < 4) want = Rgba{255, 0, 0, 255};
            if (x >= 8 && x < 10 && y < 4) want = Rgba{0, 0, 255, 255};
            EXPECT_EQ(image.at(x, y), want) << "pixel (" << x << ", " << y << ")";
        }
    }
}

// More atlases than texture units in one draw: the batch splits and every glyph still shows.
TEST_F(OverlayCanvas, ManyFontSizesSplitIntoBatchesAndStillDraw) {
    int drawCalls = -1;
    Image image = render(
        400, 100,
        [](Canvas& c) {
            for (int k = 0; k < 10; ++k) {
                c.text({k * 40.0f, 10.0f}, "H", {FontFace::Sans, 10.0f + k, WHITE});
            }
        },
        &drawCalls);
    EXPECT_EQ(drawCalls, 2);
    for (int k = 0; k < 10; ++k) {
        int lit = 0;
        for (int y = 0; y < 100; ++y) {
            for (int x = k * 40; x < k * 40 + 40; ++x) lit += image.at(x, y).r > 96;
        }
        EXPECT_GT(lit, 10) << "size " << 10 + k;
    }
}

TEST_F(OverlayCanvas, FlushRestoresTheGlStateItChanges) {
    OffscreenTarget t = createOffscreenTarget(64, 64, {GL_RGBA8});
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.framebuffer.id());
    glViewport(1, 2, 3, 4);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    GlTexture callers2d = createTexture2d(GL_RGBA8, 4, 4);
    GlTexture callersArray = createTexture(GL_TEXTURE_2D_ARRAY);
    GlSampler callersSampler = createNearestSampler();
    glBindTextureUnit(0, callers2d.id());
    glBindTextureUnit(1, callersArray.id());
    glBindSampler(0, callersSampler.id());
    glActiveTexture(GL_TEXTURE3);
    Canvas c;
    c.begin({64, 64});
    c.fillRect({0, 0, 8, 8}, RED);
    c.text({0, 10}, "x", {});
    c.flush();
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(viewport[0], 1);
    EXPECT_EQ(viewport[3], 4);
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_FALSE(glIsEnabled(GL_BLEND));
    EXPECT_FALSE(glIsEnabled(GL_SCISSOR_TEST));
    GLint value = 0;
    glGetIntegerv(GL_BLEND_SRC_RGB, &value);
    EXPECT_EQ(value, GL_ONE);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &value);
    EXPECT_EQ(value, GL_TEXTURE3);
    glGetIntegerv(GL_CURRENT_PROGRAM, &value);
    EXPECT_EQ(value, 0);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &value);
    EXPECT_EQ(static_cast<GLuint>(value), callers2d.id());
    glGetIntegerv(GL_SAMPLER_BINDING, &value);
    EXPECT_EQ(static_cast<GLuint>(value), callersSampler.id());
    glActiveTexture(GL_TEXTURE1);
    glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &value);
    EXPECT_EQ(static_cast<GLuint>(value), callersArray.id());
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &value);
    EXPECT_EQ(value, 0);
    // The canvas drew where it was asked, whatever state it found.
    std::vector<uint8_t> pixels = readPixelsRgba8(t.framebuffer.id(), GL_COLOR_ATTACHMENT0, 64, 64);
    EXPECT_EQ(pixels[0], 255);
    EXPECT_EQ(pixels[1], 0);
    glBindTextureUnit(0, 0);
    glBindTextureUnit(1, 0);
    glBindSampler(0, 0);
    glDisable(GL_DEPTH_TEST);
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Everything the inspector draws, used by the determinism test and the demo picture.
void drawDemo(Canvas& c, glm::ivec2 size) {
    const Colour panel{0.10f, 0.11f, 0.14f, 1};
    const Colour grid{0.35f, 0.38f, 0.45f, 1};
    const Colour accent{1.0f, 0.75f, 0.2f, 1};
    c.fillRect({0, 0, float(size.x), float(size.y)}, {0.05f, 0.05f, 0.07f, 1});
    c.fillRect({10, 10, 300, float(size.y) - 20}, panel);
    c.strokeRect({10, 10, 300, float(size.y) - 20}, 1, grid);
    c.text({20, 18}, "PCF inspector · pixel (412, 233)", {FontFace::Sans, 17, WHITE});
    float y = 46.0f;
    y += c.textBox({20, y, 280, 120},
                   "Each tap compares the receiver depth ref with one texel: lit when ref ≤ depth. "
                   "The bilinear weights blend the four bits, so the result moves smoothly as the "
                   "sub-texel position changes. Déjà vu: 3×3 taps · 16 fetches.",
                   {FontFace::Sans, 13, {0.85f, 0.87f, 0.9f, 1}});
    const char* rows[] = {"frac  = (0.375, 0.625)", "ref   = 0.4812", "w     = 0.234 × 1",
                          "Σ w·lit = 0.7500", "√2 ≈ 1.414  ← → ↑ ↓ ∑ ≥ 90°"};
    for (int k = 0; k < 5; ++k) {
        y += c.text({20, y + 10.0f}, rows[k], {FontFace::Mono, 14, accent}).h;
    }
    y += 20.0f;
    for (int k = 0; k < 6; ++k) {
        float px = 9.0f + 3.0f * k;
        y += c.text({20, y}, std::to_string(int(px)) + " px: 0.8 AVA Wo ≤",
                    {FontFace::Sans, px, WHITE})
                 .h;
    }
    // A 4x4 texel neighbourhood with taps.
    const glm::vec2 o(340, 40);
    const float cell = 56.0f;
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            bool lit = (i + 2 * j) % 3 != 0;
            c.fillRect({o.x + i * cell, o.y + j * cell, cell, cell},
                       lit ? Colour{0.85f, 0.85f, 0.8f, 1} : Colour{0.2f, 0.2f, 0.25f, 1});
            c.text({o.x + i * cell + cell / 2, o.y + j * cell + 4}, lit ? "1" : "0",
                   {FontFace::Mono, 14, lit ? BLACK : WHITE, TextAlign::Center});
        }
    }
    for (int k = 0; k <= 4; ++k) {
        c.line({o.x + k * cell, o.y}, {o.x + k * cell, o.y + 4 * cell}, 1, grid);
        c.line({o.x, o.y + k * cell}, {o.x + 4 * cell, o.y + k * cell}, 1, grid);
    }
    glm::vec2 sample = o + glm::vec2(1.375f, 1.625f) * cell;
    c.ring(sample, 10, 2.5f, {1, 0.3f, 0.3f, 1});
    c.circle(sample, 3.5f, {1, 0.3f, 0.3f, 1});
    c.arrow(o + glm::vec2(1.5f, 1.5f) * cell, sample, 2, {0.3f, 0.8f, 1, 1});
    c.arrow({o.x + 4 * cell + 40, o.y + 20}, {o.x + 4 * cell + 8, o.y + 0.5f * cell}, 2.5f, accent);
    c.line({o.x, o.y + 4 * cell + 20}, {o.x + 4 * cell, o.y + 4 * cell + 60}, 3,
           {0.6f, 1, 0.6f, 0.8f});
    c.fillRect({o.x + 2 * cell, o.y + 2 * cell, cell, cell}, {0.2f, 0.5f, 1, 0.35f});
    c.text({o.x, o.y + 4 * cell + 70}, "visibility = 0.75", {FontFace::Mono, 24, WHITE});
}

TEST_F(OverlayCanvas, SameFrameIsByteIdenticalAcrossCanvasesAndContexts) {
    const glm::ivec2 size(640, 400);
    Image first = render(size.x, size.y, [&](Canvas& c) { drawDemo(c, size); });
    Image second = render(size.x, size.y, [&](Canvas& c) { drawDemo(c, size); });
    EXPECT_EQ(first.rgba, second.rgba);
    Image other;
    {
        std::unique_ptr<GlContext> context = createHeadlessContext();
        other = render(size.x, size.y, [&](Canvas& c) { drawDemo(c, size); });
    }
    sContext->makeCurrent();
    EXPECT_EQ(first.rgba, other.rgba);
}

// The demo picture written as a PNG reads back as the very pixels the canvas drew (rows and
// alpha included): what an exported frame shows is what was on screen.
TEST_F(OverlayCanvas, WritesADemoPictureThatReadsBackUnchanged) {
    const glm::ivec2 size(640, 400);
    Image image = render(size.x, size.y, [&](Canvas& c) { drawDemo(c, size); });
    std::string path = ::testing::TempDir() + "overlay_demo.png";
    writePngRgba8(path, size.x, size.y, image.rgba);
    ImageSize written = readImageSize(path);
    EXPECT_EQ(written.width, size.x);
    EXPECT_EQ(written.height, size.y);
    ASSERT_EQ(written.channels, 4);
    std::vector<unsigned char> back = readImageBytes(path, 4);
    ASSERT_EQ(back.size(), image.rgba.size());
    EXPECT_TRUE(std::equal(back.begin(), back.end(), image.rgba.begin()));
    std::printf("overlay demo: %s\n", path.c_str());
}

}  // namespace
}  // namespace pcf
