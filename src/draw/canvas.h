// canvas.h: the 2D drawing layer of the inspector: text, rectangles, lines, circles, rings and
// arrows in plain OpenGL 4.5, batched into a few draw calls per frame.
//
// COORDINATES: pixels of the target, ORIGIN AT THE TOP-LEFT, x to the right, y DOWN (as in every
// UI toolkit, and as readPixelsRgba8 returns rows). Pixel (i, j) is the square
// [i, i + 1) x [j, j + 1); its centre is (i + 0.5, j + 0.5). A shape covers the pixels whose
// centres it contains, so Rect{10, 20, 30, 5} covers exactly columns 10..39 and rows 20..24
// from the top. Colours are RGBA in [0,1] with straight alpha, blended "over" and written as
// they are (no sRGB conversion).
//
// Edges: rectangles, rectangle outlines and axis-aligned lines are drawn without antialiasing,
// so whole-pixel coordinates give pixel-exact results. Circles, rings, slanted lines and arrow
// heads get a 1 px antialiased fringe centred on the true edge (the coverage still integrates to
// the shape's area). Text is placed at whole pixels and drawn 1:1 from the glyph atlas.
//
// Usage, once per frame and target:
//     canvas.begin({width, height});
//     canvas.fillRect({10, 10, 200, 40}, {0, 0, 0, 0.8f});
//     canvas.text({16, 18}, "visibility = 0.75", {FontFace::Mono, 18});
//     canvas.flush();  // draws into the currently bound draw framebuffer
//
// Commands are recorded in painter's order (later draws over earlier) into one vertex stream:
// shapes are coloured triangles, glyphs textured quads, one shader for both. flush() issues one
// draw call per batch; a batch ends only where the clip changes or a draw would need a 9th glyph
// atlas (one atlas per font face and pixel size), so a typical frame is one draw call.
//
// Output depends only on the commands and the target size: no time, no state carried between
// frames, and flush() sets (and afterwards restores) every piece of GL state it relies on. The
// same commands give byte-identical pixels in a GLFW window and in an EGL offscreen target.
//
// GL: a Canvas creates its GL objects at the first flush(), in the context current then; use it
// only with that context and destroy it while that context is current (gl_objects.h).
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <span>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "draw/font.h"
#include "draw/glyph_atlas.h"
#include "draw/rect.h"
#include "draw/text_layout.h"
#include "render/gl_objects.h"

namespace pcf {

enum class TextAlign { Left, Center, Right };

// A picture for Canvas::image: RGBA, straight alpha, floats in [0,1], rows top-down. Floats, so a
// texel holds exactly the colour a fillRect would have drawn (an 8-bit texel would round it).
// Each CanvasImage gets its own id; the canvas keeps its texture while frames draw the same one.
struct CanvasImage {
    CanvasImage(glm::ivec2 size, std::vector<glm::vec4> pixels);
    glm::ivec2 size{0, 0};
    std::vector<glm::vec4> pixels;  // size.x * size.y, row 0 = the top row
    uint64_t id = 0;
};

struct TextStyle {
    FontFace face = FontFace::Sans;
    float pixelSize = 16.0f;  // em size in pixels (the atlas is rasterised at exactly this size)
    Colour colour{1.0f, 1.0f, 1.0f, 1.0f};
    // Where pos.x of text() sits on each line: its left end, its middle, or its right end.
    TextAlign align = TextAlign::Left;
};

class Canvas {
  public:
    // Glyph atlases one draw call can read (texture units 0..7).
    static constexpr int MAX_ATLASES_PER_DRAW = 8;
    // The texture unit of a batch's image (Canvas::image), after the atlases'.
    static constexpr int IMAGE_UNIT = MAX_ATLASES_PER_DRAW;

    Canvas();
    ~Canvas();
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;

    // Starts a frame for a target of targetSize pixels: drops anything not flushed and the clip
    // stack. Throws std::invalid_argument unless both sides are positive.
    void begin(glm::ivec2 targetSize);
    glm::ivec2 targetSize() const { return mTargetSize; }

    // Exactly the pixels of `r` (see the top of this file).
    void fillRect(const Rect& r, const Colour& colour);
    // A border `width` pixels wide INSIDE `r` (its outer edge is r's edge, like CSS's
    // border-box), drawn as four rects that do not overlap, so translucent borders are even.
    void strokeRect(const Rect& r, float width, const Colour& colour);
    // A segment with butt ends (it stops at a and b), `width` pixels across. Horizontal and
    // vertical lines are exactly the rect around them: line({0, 10.5}, {50, 10.5}, 1, c) fills
    // row 10, line({0, 50}, {100, 50}, 4, c) rows 48..51.
    void line(glm::vec2 a, glm::vec2 b, float width, const Colour& colour);
    // A filled disc.
    void circle(glm::vec2 centre, float radius, const Colour& colour);
    // A ring whose band, `width` pixels wide, is centred on the circle of `radius` (SVG's stroke).
    void ring(glm::vec2 centre, float radius, float width, const Colour& colour);
    // A line from `from` with a triangular head whose tip is exactly at `to`. The head is
    // max(8, 4 * width) long and as wide as it is long (shortened on short arrows).
    void arrow(glm::vec2 from, glm::vec2 to, float width, const Colour& colour);
    // A filled convex polygon, either winding, antialiased edges.
    void convexPolygon(std::span<const glm::vec2> points, const Colour& colour);
    // The image 1:1 with its top-left corner at the whole pixel `topLeft`: each pixel blended
    // "over" with its texel's colour exactly as fillRect of that pixel and colour would, and
    // texels of alpha 0 left alone. One quad however busy the picture (the scene's texel grid:
    // thousands of 1-pixel runs as rects). One image per batch: a different one ends the batch.
    void image(glm::ivec2 topLeft, std::shared_ptr<const CanvasImage> img);

    // One line of text per '\n'; pos is the top-left corner of the first line box (rounded to
    // whole pixels), or its top-middle / top-right for TextAlign::Center / Right (per line).
    // Returns the box of the text: line boxes of the face's line height, as wide as the pen
    // advance of the widest line. Throws std::invalid_argument for a pixel size out of
    // [1, 512] and std::runtime_error when no font is found.
    Rect text(glm::vec2 pos, std::string_view utf8, const TextStyle& style);
    // The text word-wrapped to box.w (wrapText), lines from box.y down, aligned within box.
    // Lines that run past box.h are drawn too (pushClip(box) to cut them); returns the height
    // used: lines * line height.
    float textBox(const Rect& box, std::string_view utf8, const TextStyle& style);

    // Restricts later commands to `r` (intersected with the enclosing clip and the target, edges
    // rounded to whole pixels) until the matching popClip(). A clip change ends a batch.
    void pushClip(const Rect& r);
    // Throws std::logic_error without a matching pushClip().
    void popClip();

    // Draws everything recorded since begin() / the last flush into the currently bound draw
    // framebuffer, with glViewport(0, 0, targetSize), then forgets it (the clip stack stays).
    // Restores the GL state it changed. Throws std::logic_error before begin().
    void flush();
    // Draw calls the last flush() issued.
    int lastFlushDrawCalls() const { return mLastFlushDrawCalls; }
    // Scissored clears the last flush() issued in place of large opaque rects (tryClearRect).
    int lastFlushClears() const { return mLastFlushClears; }
    // Vertices recorded and not yet flushed (6 per rect, 6 per glyph...).
    size_t pendingVertexCount() const { return mVertices.size(); }

  private:
    struct Vertex {
        glm::vec2 pos;     // pixels, top-left origin
        glm::vec2 uv;      // atlas texel coordinates (glyphs only)
        glm::vec4 colour;  // straight alpha
        int32_t slot;      // -1 = solid colour, -2 = the batch's image, 0..7 = glyph atlas
    };
    struct Batch {
        size_t first = 0;
        size_t count = 0;
        std::array<const GlyphAtlas*, MAX_ATLASES_PER_DRAW> atlases{};
        int atlasCount = 0;
        std::shared_ptr<const CanvasImage> image;  // read on IMAGE_UNIT by slot -2
        glm::ivec4 clip{0, 0, 0, 0};               // x0, y0, x1, y1 in pixels, top-left origin
    };
    struct AtlasTexture {
        GlTexture texture;
        glm::ivec2 size{0, 0};
        uint64_t version = 0;
    };

    Batch& currentBatch();
    // A batch with the clip of the current one, starting at the next vertex.
    Batch& newBatch();
    int atlasSlot(const GlyphAtlas& atlas);
    void setClip(glm::ivec4 clip);
    void triangle(const Vertex& a, const Vertex& b, const Vertex& c);
    void solidTriangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, const Colour& colour);
    void solidQuad(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d, const Colour& ca,
                   const Colour& cb, const Colour& cc, const Colour& cd);
    // Concentric band between radii r0 and r1 with colours c0 (at r0) and c1 (at r1).
    void band(glm::vec2 centre, float r0, float r1, const Colour& c0, const Colour& c1,
              int segments);
    Rect drawLayout(GlyphAtlas& atlas, const TextLayout& layout, glm::vec2 pos,
                    const TextStyle& style);
    void createGlObjects();
    void uploadAtlas(const GlyphAtlas& atlas);
    void uploadImage(const CanvasImage& img);
    // Uploads the atlases and images the batches draw, and drops the textures of images no
    // batch draws (a new grid is a new image).
    void uploadBatchTextures();

    glm::ivec2 mTargetSize{0, 0};
    // An opaque, pixel-aligned rect that no earlier vertex of this flush touches: flush()
    // clears it (scissored) before drawing, in record order, instead of blending its pixels.
    struct ClearRect {
        glm::ivec4 box;  // x0, y0, x1, y1 in pixels, top-left origin, already clipped
        Colour colour;
    };
    bool tryClearRect(const Rect& r, const Colour& colour);

    std::vector<Vertex> mVertices;
    std::vector<Batch> mBatches;
    std::vector<ClearRect> mClears;
    std::vector<glm::ivec4> mClipStack;
    int mLastFlushDrawCalls = 0;
    int mLastFlushClears = 0;

    GlProgram mProgram;
    GlProgram mSingleAtlasProgram;  // overlay.frag with SINGLE_ATLAS: draws of one atlas
    GlVertexArray mVertexArray;
    GlBuffer mVertexBuffer;
    std::unordered_map<const GlyphAtlas*, AtlasTexture> mAtlasTextures;
    // Images' textures by CanvasImage::id; those the last flush did not draw are dropped.
    std::unordered_map<uint64_t, GlTexture> mImageTextures;
};

}  // namespace pcf
