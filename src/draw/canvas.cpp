#include "draw/canvas.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>

#include "render/shader_loader.h"

namespace pcf {

namespace {

// Antialiased edges: a fringe this wide, centred on the true edge, ramps alpha from full to 0.
constexpr float FRINGE = 1.0f;
// Circles are polygons whose sides stray at most this far (pixels) from the true circle.
constexpr float MAX_ARC_ERROR = 0.1f;
constexpr int MIN_SEGMENTS = 12;
constexpr int MAX_SEGMENTS = 512;

int circleSegments(float radius) {
    if (radius <= MAX_ARC_ERROR * 2.0f) return MIN_SEGMENTS;
    // Sagitta of a side spanning 2*pi/n: r * (1 - cos(pi / n)) <= MAX_ARC_ERROR.
    double n = std::numbers::pi / std::acos(1.0 - MAX_ARC_ERROR / radius);
    return std::clamp(static_cast<int>(std::ceil(n)), MIN_SEGMENTS, MAX_SEGMENTS);
}

// Unit vectors of n equal steps around the circle, in double so that every platform and build
// gives the same floats for the same n.
glm::vec2 direction(int k, int n) {
    double angle = 2.0 * std::numbers::pi * k / n;
    return {static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle))};
}

Colour transparent(const Colour& c) { return {c.r, c.g, c.b, 0.0f}; }

// Everything flush() changes, saved on construction and put back on destruction, so the canvas
// can be drawn between the renderer's passes without either disturbing the other.
class GlStateGuard {
  public:
    GlStateGuard() {
        glGetIntegerv(GL_VIEWPORT, mViewport);
        glGetIntegerv(GL_SCISSOR_BOX, mScissorBox);
        glGetIntegerv(GL_CURRENT_PROGRAM, &mProgram);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &mVertexArray);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &mActiveTexture);
        glGetIntegerv(GL_BLEND_SRC_RGB, &mBlendSrcRgb);
        glGetIntegerv(GL_BLEND_DST_RGB, &mBlendDstRgb);
        glGetIntegerv(GL_BLEND_SRC_ALPHA, &mBlendSrcAlpha);
        glGetIntegerv(GL_BLEND_DST_ALPHA, &mBlendDstAlpha);
        glGetIntegerv(GL_BLEND_EQUATION_RGB, &mBlendEquationRgb);
        glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &mBlendEquationAlpha);
        glGetBooleanv(GL_COLOR_WRITEMASK, mColourMask);
        glGetIntegerv(GL_POLYGON_MODE, mPolygonMode);
        for (int unit = 0; unit < UNITS; ++unit) {
            glActiveTexture(GL_TEXTURE0 + unit);
            glGetIntegerv(GL_TEXTURE_BINDING_2D, &mTextures[unit]);
            glGetIntegerv(GL_SAMPLER_BINDING, &mSamplers[unit]);
        }
        for (size_t k = 0; k < std::size(CAPS); ++k) mEnabled[k] = glIsEnabled(CAPS[k]);
    }
    ~GlStateGuard() {
        glViewport(mViewport[0], mViewport[1], mViewport[2], mViewport[3]);
        glScissor(mScissorBox[0], mScissorBox[1], mScissorBox[2], mScissorBox[3]);
        glUseProgram(static_cast<GLuint>(mProgram));
        glBindVertexArray(static_cast<GLuint>(mVertexArray));
        for (int unit = 0; unit < UNITS; ++unit) {
            // glBindTexture, not glBindTextureUnit: binding 0 with the latter would also unbind
            // the unit's other targets (a cube map, an array) that flush() never touched.
            glActiveTexture(GL_TEXTURE0 + unit);
            glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(mTextures[unit]));
            glBindSampler(unit, static_cast<GLuint>(mSamplers[unit]));
        }
        glActiveTexture(static_cast<GLenum>(mActiveTexture));
        glBlendFuncSeparate(mBlendSrcRgb, mBlendDstRgb, mBlendSrcAlpha, mBlendDstAlpha);
        glBlendEquationSeparate(mBlendEquationRgb, mBlendEquationAlpha);
        glColorMask(mColourMask[0], mColourMask[1], mColourMask[2], mColourMask[3]);
        glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(mPolygonMode[0]));
        for (size_t k = 0; k < std::size(CAPS); ++k) {
            if (mEnabled[k]) {
                glEnable(CAPS[k]);
            } else {
                glDisable(CAPS[k]);
            }
        }
    }
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

    // Switches that would change the overlay's pixels: depth/stencil/culling would drop
    // fragments, sRGB writes and dithering would change the bytes between targets.
    static constexpr GLenum CAPS[] = {GL_BLEND,         GL_SCISSOR_TEST,
                                      GL_DEPTH_TEST,    GL_STENCIL_TEST,
                                      GL_CULL_FACE,     GL_FRAMEBUFFER_SRGB,
                                      GL_DITHER,        GL_RASTERIZER_DISCARD,
                                      GL_MULTISAMPLE,   GL_SAMPLE_ALPHA_TO_COVERAGE,
                                      GL_COLOR_LOGIC_OP};

  private:
    GLint mViewport[4]{};
    GLint mScissorBox[4]{};
    GLint mProgram = 0;
    GLint mVertexArray = 0;
    GLint mActiveTexture = GL_TEXTURE0;
    GLint mBlendSrcRgb = GL_ONE;
    GLint mBlendDstRgb = GL_ZERO;
    GLint mBlendSrcAlpha = GL_ONE;
    GLint mBlendDstAlpha = GL_ZERO;
    GLint mBlendEquationRgb = GL_FUNC_ADD;
    GLint mBlendEquationAlpha = GL_FUNC_ADD;
    GLboolean mColourMask[4]{GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    GLint mPolygonMode[2]{GL_FILL, GL_FILL};
    // The atlases' units and the image's.
    static constexpr int UNITS = Canvas::IMAGE_UNIT + 1;
    GLint mTextures[UNITS]{};
    GLint mSamplers[UNITS]{};
    GLboolean mEnabled[std::size(CAPS)]{};
};

// Unpack state set for tightly packed rows read from client memory, and put back afterwards.
class UnpackGuard {
  public:
    UnpackGuard() {
        glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &mUnpackBuffer);
        glGetIntegerv(GL_UNPACK_ALIGNMENT, &mAlignment);
        glGetIntegerv(GL_UNPACK_ROW_LENGTH, &mRowLength);
        glGetIntegerv(GL_UNPACK_SKIP_ROWS, &mSkipRows);
        glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &mSkipPixels);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    }
    ~UnpackGuard() {
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(mUnpackBuffer));
        glPixelStorei(GL_UNPACK_ALIGNMENT, mAlignment);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, mRowLength);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, mSkipRows);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, mSkipPixels);
    }
    UnpackGuard(const UnpackGuard&) = delete;
    UnpackGuard& operator=(const UnpackGuard&) = delete;

  private:
    GLint mUnpackBuffer = 0;
    GLint mAlignment = 4;
    GLint mRowLength = 0;
    GLint mSkipRows = 0;
    GLint mSkipPixels = 0;
};

}  // namespace

CanvasImage::CanvasImage(glm::ivec2 size_, std::vector<glm::vec4> pixels_)
    : size(size_), pixels(std::move(pixels_)) {
    static std::atomic<uint64_t> next{1};
    if (size.x < 0 || size.y < 0 || pixels.size() != static_cast<size_t>(size.x) * size.y) {
        throw std::invalid_argument("CanvasImage: " + std::to_string(pixels.size()) +
                                    " pixels for " + std::to_string(size.x) + " x " +
                                    std::to_string(size.y));
    }
    id = next++;
}

Canvas::Canvas() = default;
Canvas::~Canvas() = default;

void Canvas::begin(glm::ivec2 targetSize) {
    if (targetSize.x <= 0 || targetSize.y <= 0) {
        throw std::invalid_argument("Canvas::begin: target size must be positive, got " +
                                    std::to_string(targetSize.x) + " x " +
                                    std::to_string(targetSize.y));
    }
    mTargetSize = targetSize;
    mVertices.clear();
    mBatches.clear();
    mClipStack.clear();
    mClears.clear();
}

Canvas::Batch& Canvas::currentBatch() {
    if (mBatches.empty()) {
        Batch b;
        b.first = mVertices.size();
        b.clip =
            mClipStack.empty() ? glm::ivec4(0, 0, mTargetSize.x, mTargetSize.y) : mClipStack.back();
        mBatches.push_back(b);
    }
    return mBatches.back();
}

Canvas::Batch& Canvas::newBatch() {
    Batch next;
    next.first = mVertices.size();
    next.clip = currentBatch().clip;
    mBatches.push_back(next);
    return mBatches.back();
}

int Canvas::atlasSlot(const GlyphAtlas& atlas) {
    Batch* b = &currentBatch();
    for (int k = 0; k < b->atlasCount; ++k) {
        if (b->atlases[k] == &atlas) return k;
    }
    if (b->atlasCount == MAX_ATLASES_PER_DRAW) b = &newBatch();
    b->atlases[b->atlasCount] = &atlas;
    return b->atlasCount++;
}

void Canvas::setClip(glm::ivec4 clip) {
    Batch& b = currentBatch();
    if (b.clip == clip) return;
    if (b.count == 0) {
        b.clip = clip;
        return;
    }
    Batch next;
    next.first = mVertices.size();
    next.clip = clip;
    mBatches.push_back(next);
}

void Canvas::pushClip(const Rect& r) {
    glm::ivec4 outer =
        mClipStack.empty() ? glm::ivec4(0, 0, mTargetSize.x, mTargetSize.y) : mClipStack.back();
    glm::ivec4 clip(static_cast<int>(std::lround(r.x)), static_cast<int>(std::lround(r.y)),
                    static_cast<int>(std::lround(r.right())),
                    static_cast<int>(std::lround(r.bottom())));
    clip = {std::max(clip.x, outer.x), std::max(clip.y, outer.y), std::min(clip.z, outer.z),
            std::min(clip.w, outer.w)};
    clip.z = std::max(clip.z, clip.x);
    clip.w = std::max(clip.w, clip.y);
    mClipStack.push_back(clip);
    setClip(clip);
}

void Canvas::popClip() {
    if (mClipStack.empty()) throw std::logic_error("Canvas::popClip without pushClip");
    mClipStack.pop_back();
    setClip(mClipStack.empty() ? glm::ivec4(0, 0, mTargetSize.x, mTargetSize.y)
                               : mClipStack.back());
}

void Canvas::triangle(const Vertex& a, const Vertex& b, const Vertex& c) {
    Batch& batch = currentBatch();
    mVertices.push_back(a);
    mVertices.push_back(b);
    mVertices.push_back(c);
    batch.count += 3;
}

void Canvas::solidTriangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, const Colour& colour) {
    triangle({a, {}, colour, -1}, {b, {}, colour, -1}, {c, {}, colour, -1});
}

void Canvas::solidQuad(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d, const Colour& ca,
                       const Colour& cb, const Colour& cc, const Colour& cd) {
    Vertex va{a, {}, ca, -1};
    Vertex vc{c, {}, cc, -1};
    triangle(va, {b, {}, cb, -1}, vc);
    triangle(va, vc, {d, {}, cd, -1});
}

// Large opaque rects (the neighbourhood's cells) cost llvmpipe a blended fragment each. One whose
// edges sit on whole pixels covers exactly the pixels a scissored clear does, and with alpha 1
// the blend writes the colour itself, so the clear gives the same bytes. It may run first only
// if nothing recorded before it in this flush overlaps it (bounding boxes, one pixel of margin).
bool Canvas::tryClearRect(const Rect& r, const Colour& colour) {
    constexpr float MIN_CLEAR_AREA = 4096.0f;
    if (colour.a != 1.0f) return false;
    glm::vec4 edges(r.x, r.y, r.right(), r.bottom());
    if (edges != glm::floor(edges)) return false;
    glm::ivec4 box(edges);
    glm::ivec4 clip =
        mClipStack.empty() ? glm::ivec4(0, 0, mTargetSize.x, mTargetSize.y) : mClipStack.back();
    box = {std::max(box.x, clip.x), std::max(box.y, clip.y), std::min(box.z, clip.z),
           std::min(box.w, clip.w)};
    if (box.z <= box.x || box.w <= box.y) return true;  // clipped away: nothing to draw
    if (static_cast<float>(box.z - box.x) * static_cast<float>(box.w - box.y) < MIN_CLEAR_AREA) {
        return false;
    }
    glm::vec2 lo = glm::vec2(box.x, box.y) - 1.0f;
    glm::vec2 hi = glm::vec2(box.z, box.w) + 1.0f;
    for (size_t i = 0; i + 2 < mVertices.size(); i += 3) {
        glm::vec2 a = mVertices[i].pos, b = mVertices[i + 1].pos, c = mVertices[i + 2].pos;
        glm::vec2 tmin = glm::min(a, glm::min(b, c));
        glm::vec2 tmax = glm::max(a, glm::max(b, c));
        if (tmin.x < hi.x && tmax.x > lo.x && tmin.y < hi.y && tmax.y > lo.y) return false;
    }
    mClears.push_back({box, colour});
    return true;
}

void Canvas::fillRect(const Rect& r, const Colour& colour) {
    if (r.empty()) return;
    if (tryClearRect(r, colour)) return;
    glm::vec2 p0(r.x, r.y);
    glm::vec2 p1(r.right(), r.bottom());
    solidQuad(p0, {p1.x, p0.y}, p1, {p0.x, p1.y}, colour, colour, colour, colour);
}

void Canvas::strokeRect(const Rect& r, float width, const Colour& colour) {
    if (r.empty() || !(width > 0.0f)) return;
    if (2.0f * width >= r.w || 2.0f * width >= r.h) {
        fillRect(r, colour);
        return;
    }
    fillRect({r.x, r.y, r.w, width}, colour);
    fillRect({r.x, r.bottom() - width, r.w, width}, colour);
    fillRect({r.x, r.y + width, width, r.h - 2.0f * width}, colour);
    fillRect({r.right() - width, r.y + width, width, r.h - 2.0f * width}, colour);
}

void Canvas::line(glm::vec2 a, glm::vec2 b, float width, const Colour& colour) {
    if (!(width > 0.0f) || a == b) return;
    float half = 0.5f * width;
    // Axis-aligned: the exact rect (grids and tick marks stay pixel-exact).
    if (a.y == b.y) {
        fillRect({std::min(a.x, b.x), a.y - half, std::abs(b.x - a.x), width}, colour);
        return;
    }
    if (a.x == b.x) {
        fillRect({a.x - half, std::min(a.y, b.y), width, std::abs(b.y - a.y)}, colour);
        return;
    }
    // Thinner than the fringe: a 1 px line at the matching opacity covers the same amount.
    Colour c = colour;
    if (width < FRINGE) {
        c.a *= width;
        half = 0.5f * FRINGE;
    }
    glm::vec2 d = glm::normalize(b - a);
    glm::vec2 n(-d.y * half, d.x * half);
    const glm::vec2 quad[4] = {a + n, b + n, b - n, a - n};
    convexPolygon(quad, c);
}

void Canvas::convexPolygon(std::span<const glm::vec2> input, const Colour& colour) {
    // Repeated points have no edge direction; drop them (the first and last too).
    std::vector<glm::vec2> p;
    p.reserve(input.size());
    for (glm::vec2 q : input) {
        if (p.empty() || glm::distance(p.back(), q) > 1e-4f) p.push_back(q);
    }
    while (p.size() > 1 && glm::distance(p.front(), p.back()) <= 1e-4f) p.pop_back();
    const size_t n = p.size();
    if (n < 3) return;

    // Shoelace: the sign of the area tells the winding, hence which normal points outwards.
    float area = 0.0f;
    for (size_t i = 0; i < n; ++i) {
        const glm::vec2& u = p[i];
        const glm::vec2& v = p[(i + 1) % n];
        area += u.x * v.y - v.x * u.y;
    }
    if (area == 0.0f) return;
    float outwards = area > 0.0f ? 1.0f : -1.0f;
    std::vector<glm::vec2> edgeNormal(n);
    for (size_t i = 0; i < n; ++i) {
        glm::vec2 d = glm::normalize(p[(i + 1) % n] - p[i]);
        edgeNormal[i] = outwards * glm::vec2(d.y, -d.x);
    }
    // After ImGui's AddConvexPolyFilled: each corner moves along the mean of its two edge
    // normals, scaled by 1/|mean|^2 so both edges move by the same distance (the miter), with the
    // scale capped so sharp corners do not spike.
    std::vector<glm::vec2> inner(n);
    std::vector<glm::vec2> outer(n);
    for (size_t i = 0; i < n; ++i) {
        glm::vec2 m = 0.5f * (edgeNormal[(i + n - 1) % n] + edgeNormal[i]);
        float d2 = glm::dot(m, m);
        if (d2 > 1e-6f) m *= std::min(1.0f / d2, 100.0f);
        inner[i] = p[i] - 0.5f * FRINGE * m;
        outer[i] = p[i] + 0.5f * FRINGE * m;
    }
    for (size_t i = 1; i + 1 < n; ++i) solidTriangle(inner[0], inner[i], inner[i + 1], colour);
    Colour clear = transparent(colour);
    for (size_t i = 0; i < n; ++i) {
        size_t j = (i + 1) % n;
        solidQuad(inner[i], inner[j], outer[j], outer[i], colour, colour, clear, clear);
    }
}

void Canvas::circle(glm::vec2 centre, float radius, const Colour& colour) {
    if (!(radius > 0.0f)) return;
    int segments = circleSegments(radius);
    std::vector<glm::vec2> points(static_cast<size_t>(segments));
    for (int k = 0; k < segments; ++k) points[k] = centre + radius * direction(k, segments);
    convexPolygon(points, colour);
}

void Canvas::band(glm::vec2 centre, float r0, float r1, const Colour& c0, const Colour& c1,
                  int segments) {
    if (!(r1 > r0)) return;
    for (int k = 0; k < segments; ++k) {
        glm::vec2 d0 = direction(k, segments);
        glm::vec2 d1 = direction(k + 1 == segments ? 0 : k + 1, segments);
        solidQuad(centre + r0 * d0, centre + r1 * d0, centre + r1 * d1, centre + r0 * d1, c0, c1,
                  c1, c0);
    }
}

void Canvas::ring(glm::vec2 centre, float radius, float width, const Colour& colour) {
    if (!(radius > 0.0f) || !(width > 0.0f)) return;
    float half = 0.5f * width;
    if (radius - half <= 0.0f) {
        circle(centre, radius + half, colour);  // no hole left
        return;
    }
    Colour c = colour;
    // Full-opacity core between the two fringes; a band thinner than the fringes keeps a
    // zero-width core at its centre line and the matching opacity.
    float coreIn = radius - half + 0.5f * FRINGE;
    float coreOut = radius + half - 0.5f * FRINGE;
    if (coreIn > coreOut) {
        coreIn = coreOut = radius;
        c.a *= width / FRINGE;
    }
    float fringeIn = std::max(0.0f, radius - half - 0.5f * FRINGE);
    float fringeOut = radius + half + 0.5f * FRINGE;
    int segments = circleSegments(fringeOut);
    Colour clear = transparent(c);
    band(centre, fringeIn, coreIn, clear, c, segments);
    band(centre, coreIn, coreOut, c, c, segments);
    band(centre, coreOut, fringeOut, c, clear, segments);
}

void Canvas::arrow(glm::vec2 from, glm::vec2 to, float width, const Colour& colour) {
    if (!(width > 0.0f) || from == to) return;
    float length = glm::distance(from, to);
    glm::vec2 d = (to - from) / length;
    glm::vec2 n(-d.y, d.x);
    float headLength = std::min(length, std::max(8.0f, 4.0f * width));
    glm::vec2 base = to - headLength * d;
    // The shaft runs halfway into the head, so no seam shows between their antialiased edges.
    glm::vec2 shaftEnd = to - 0.5f * headLength * d;
    if (glm::distance(from, shaftEnd) > 0.0f && glm::dot(shaftEnd - from, d) > 0.0f) {
        // Keep the axis-aligned fast path exact: snap the end to the shaft's own axis.
        if (from.y == to.y) shaftEnd.y = from.y;
        if (from.x == to.x) shaftEnd.x = from.x;
        line(from, shaftEnd, width, colour);
    }
    const glm::vec2 head[3] = {to, base + 0.5f * headLength * n, base - 0.5f * headLength * n};
    convexPolygon(head, colour);
}

void Canvas::image(glm::ivec2 topLeft, std::shared_ptr<const CanvasImage> img) {
    if (!img || img->size.x <= 0 || img->size.y <= 0) return;
    Batch* b = &currentBatch();
    if (b->image && b->image->id != img->id) b = &newBatch();
    b->image = img;
    // Texel coordinates advance one texel per pixel from the top-left corner, as glyphs do:
    // floor(uv) at a pixel centre is that pixel's texel (row 0 = the image's top row).
    glm::vec2 p0(topLeft);
    glm::vec2 p1 = p0 + glm::vec2(img->size);
    glm::vec2 t1(img->size);
    Colour none{0.0f};
    Vertex v00{p0, {0.0f, 0.0f}, none, -2};
    Vertex v11{p1, t1, none, -2};
    triangle(v00, {{p1.x, p0.y}, {t1.x, 0.0f}, none, -2}, v11);
    triangle(v00, v11, {{p0.x, p1.y}, {0.0f, t1.y}, none, -2});
}

Rect Canvas::drawLayout(GlyphAtlas& atlas, const TextLayout& layout, glm::vec2 pos,
                        const TextStyle& style) {
    glm::ivec2 origin(static_cast<int>(std::lround(pos.x)), static_cast<int>(std::lround(pos.y)));
    std::vector<int> lineOffset(layout.lineWidths.size(), 0);
    float left = 0.0f;
    float right = 0.0f;
    for (size_t k = 0; k < lineOffset.size(); ++k) {
        float w = layout.lineWidths[k];
        // Offsets are whole pixels, so centred and right-aligned glyphs stay on the pixel grid.
        if (style.align == TextAlign::Center) {
            lineOffset[k] = -static_cast<int>(std::lround(0.5f * w));
        } else if (style.align == TextAlign::Right) {
            lineOffset[k] = -static_cast<int>(std::lround(w));
        }
        float offset = static_cast<float>(lineOffset[k]);
        left = k == 0 ? offset : std::min(left, offset);
        right = k == 0 ? offset + w : std::max(right, offset + w);
    }
    if (!layout.glyphs.empty()) {
        int slot = atlasSlot(atlas);
        for (const PlacedGlyph& g : layout.glyphs) {
            glm::vec2 p0(origin.x + lineOffset[g.line] + g.topLeft.x, origin.y + g.topLeft.y);
            glm::vec2 p1 = p0 + glm::vec2(g.glyph.size);
            glm::vec2 t0(g.glyph.atlasPos);
            glm::vec2 t1 = t0 + glm::vec2(g.glyph.size);
            Vertex v00{p0, t0, style.colour, slot};
            Vertex v11{p1, t1, style.colour, slot};
            triangle(v00, {{p1.x, p0.y}, {t1.x, t0.y}, style.colour, slot}, v11);
            triangle(v00, v11, {{p0.x, p1.y}, {t0.x, t1.y}, style.colour, slot});
        }
    }
    return {origin.x + left, static_cast<float>(origin.y), right - left, layout.size.y};
}

Rect Canvas::text(glm::vec2 pos, std::string_view utf8, const TextStyle& style) {
    GlyphAtlas& atlas = glyphAtlas(style.face, style.pixelSize);
    return drawLayout(atlas, layoutText(atlas, utf8), pos, style);
}

float Canvas::textBox(const Rect& box, std::string_view utf8, const TextStyle& style) {
    GlyphAtlas& atlas = glyphAtlas(style.face, style.pixelSize);
    std::vector<std::string> lines = wrapText(atlas, utf8, box.w);
    float lineHeight = atlas.metrics().lineHeight;
    float x = style.align == TextAlign::Left     ? box.x
              : style.align == TextAlign::Center ? box.x + 0.5f * box.w
                                                 : box.right();
    for (size_t k = 0; k < lines.size(); ++k) {
        drawLayout(atlas, layoutText(atlas, lines[k]),
                   {x, box.y + static_cast<float>(k) * lineHeight}, style);
    }
    return static_cast<float>(lines.size()) * lineHeight;
}

void Canvas::createGlObjects() {
    mProgram = buildProgram({{GL_VERTEX_SHADER, {"overlay.vert"}, "", {}},
                             {GL_FRAGMENT_SHADER, {"overlay.frag"}, "", {}}});
    mSingleAtlasProgram =
        buildProgram({{GL_VERTEX_SHADER, {"overlay.vert"}, "", {}},
                      {GL_FRAGMENT_SHADER, {"overlay.frag"}, "#define SINGLE_ATLAS 1\n", {}}});
    mVertexBuffer = createBuffer();
    mVertexArray = createVertexArray();
    GLuint vao = mVertexArray.id();
    glVertexArrayVertexBuffer(vao, 0, mVertexBuffer.id(), 0, sizeof(Vertex));
    auto floats = [&](GLuint location, GLint components, size_t offset) {
        glEnableVertexArrayAttrib(vao, location);
        glVertexArrayAttribFormat(vao, location, components, GL_FLOAT, GL_FALSE,
                                  static_cast<GLuint>(offset));
        glVertexArrayAttribBinding(vao, location, 0);
    };
    floats(0, 2, offsetof(Vertex, pos));
    floats(1, 2, offsetof(Vertex, uv));
    floats(2, 4, offsetof(Vertex, colour));
    glEnableVertexArrayAttrib(vao, 3);
    glVertexArrayAttribIFormat(vao, 3, 1, GL_INT, static_cast<GLuint>(offsetof(Vertex, slot)));
    glVertexArrayAttribBinding(vao, 3, 0);
}

void Canvas::uploadAtlas(const GlyphAtlas& atlas) {
    AtlasTexture& t = mAtlasTextures[&atlas];
    if (t.texture && t.version == atlas.version()) return;
    GlyphAtlas::Image image = atlas.image();
    if (!t.texture || t.size != image.size) {
        t.texture = createTexture2d(GL_R8, image.size.x, image.size.y);
        t.size = image.size;
    }
    // Rows of one byte each: alignment 1, and no unpack buffer or row length of someone else's.
    UnpackGuard unpack;
    // Image row r becomes texel row r: the shader fetches with the image's own coordinates.
    glTextureSubImage2D(t.texture.id(), 0, 0, 0, image.size.x, image.size.y, GL_RED,
                        GL_UNSIGNED_BYTE, image.pixels.data());
    t.version = image.version;
}

void Canvas::uploadImage(const CanvasImage& img) {
    if (mImageTextures.count(img.id)) return;
    GlTexture t = createTexture2d(GL_RGBA32F, img.size.x, img.size.y);
    UnpackGuard unpack;
    // Row r of the image becomes texel row r (as the atlases): fetched by the quad's own uv.
    glTextureSubImage2D(t.id(), 0, 0, 0, img.size.x, img.size.y, GL_RGBA, GL_FLOAT,
                        img.pixels.data());
    mImageTextures.emplace(img.id, std::move(t));
}

void Canvas::uploadBatchTextures() {
    std::vector<uint64_t> drawnImages;
    for (const Batch& b : mBatches) {
        for (int k = 0; k < b.atlasCount; ++k) uploadAtlas(*b.atlases[k]);
        if (b.image) {
            uploadImage(*b.image);
            drawnImages.push_back(b.image->id);
        }
    }
    // Textures of images this flush does not draw are dropped (a new grid is a new image).
    std::erase_if(mImageTextures, [&](const auto& kv) {
        return std::find(drawnImages.begin(), drawnImages.end(), kv.first) == drawnImages.end();
    });
}

namespace {

// The GL state the canvas draws with (the caller's GlStateGuard restores it): only blending and
// the scissor on, over the whole target.
void setOverlayDrawState(glm::ivec2 targetSize) {
    for (GLenum cap : GlStateGuard::CAPS) glDisable(cap);
    glEnable(GL_BLEND);
    glEnable(GL_SCISSOR_TEST);
    // Straight-alpha "over": colour = src * a + dst * (1 - a); alpha accumulates coverage, so an
    // overlay drawn into a transparent target still has the right opacity.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glViewport(0, 0, targetSize.x, targetSize.y);
}

}  // namespace

void Canvas::flush() {
    if (mTargetSize.x <= 0 || mTargetSize.y <= 0) {
        throw std::logic_error("Canvas::flush before Canvas::begin");
    }
    mLastFlushDrawCalls = 0;
    mLastFlushClears = 0;
    if (mVertices.empty() && mClears.empty()) {
        mBatches.clear();
        return;
    }
    if (!mProgram) createGlObjects();
    uploadBatchTextures();
    glNamedBufferData(mVertexBuffer.id(),
                      static_cast<GLsizeiptr>(mVertices.size() * sizeof(Vertex)), mVertices.data(),
                      GL_STREAM_DRAW);

    GlStateGuard guard;
    setOverlayDrawState(mTargetSize);
    for (const GlProgram* p : {&mProgram, &mSingleAtlasProgram}) {
        glProgramUniform2f(p->id(), 0, static_cast<float>(mTargetSize.x),
                           static_cast<float>(mTargetSize.y));
    }
    GLuint bound = 0;
    glBindVertexArray(mVertexArray.id());
    for (const ClearRect& c : mClears) {
        // Scissor boxes count rows from the bottom.
        glScissor(c.box.x, mTargetSize.y - c.box.w, c.box.z - c.box.x, c.box.w - c.box.y);
        glClearBufferfv(GL_COLOR, 0, &c.colour.x);
        ++mLastFlushClears;
    }
    mClears.clear();
    for (const Batch& b : mBatches) {
        if (b.count == 0) continue;
        if (b.clip.z <= b.clip.x || b.clip.w <= b.clip.y) continue;  // clipped away entirely
        // A draw with at most one atlas reads slot 0 only: the single-fetch variant.
        GLuint program = b.atlasCount <= 1 ? mSingleAtlasProgram.id() : mProgram.id();
        if (program != bound) {
            glUseProgram(program);
            bound = program;
        }
        for (int k = 0; k < b.atlasCount; ++k) {
            glBindTextureUnit(k, mAtlasTextures.at(b.atlases[k]).texture.id());
            // A sampler object left bound by someone else could make the texture incomplete.
            glBindSampler(k, 0);
        }
        if (b.image) {
            glBindTextureUnit(IMAGE_UNIT, mImageTextures.at(b.image->id).id());
            glBindSampler(IMAGE_UNIT, 0);
        }
        // Scissor boxes count rows from the bottom.
        glScissor(b.clip.x, mTargetSize.y - b.clip.w, b.clip.z - b.clip.x, b.clip.w - b.clip.y);
        glDrawArrays(GL_TRIANGLES, static_cast<GLint>(b.first), static_cast<GLsizei>(b.count));
        ++mLastFlushDrawCalls;
    }
    mVertices.clear();
    mBatches.clear();
}

}  // namespace pcf
