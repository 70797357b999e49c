// gl_objects.h: RAII for OpenGL objects (one owner each: movable, not copyable) and the few
// helpers that make and read back offscreen targets.
//
// Row order, because it is easy to get wrong and every image written depends on it:
//   - GL counts rows bottom-up: texel row 0 / window row 0 is the BOTTOM of the picture.
//   - readPixelsRgba8 / readPixelsFloat return rows TOP-DOWN (first row = top of the picture),
//     ready for writePngRgba8 / writeExr (image_io.h).
//   - readDepthTexture returns rows in GL order (row 0 = GL texel row 0), which is the row order
//     of ShadowMap (docs/methods.md, "Conventions": row 0 = first scanline = GL texel row 0).
#pragma once

#include <epoxy/gl.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pcf {

class ShadowMap;

// One owned GL name. Deleter::destroy(GLuint) gives it back. The context that made the object
// must be current when it is destroyed.
template <class Deleter>
class GlObject {
  public:
    GlObject() = default;
    explicit GlObject(GLuint id) : mId(id) {}
    ~GlObject() { reset(); }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    GlObject(GlObject&& other) noexcept : mId(std::exchange(other.mId, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) {
            reset();
            mId = std::exchange(other.mId, 0);
        }
        return *this;
    }

    GLuint id() const { return mId; }
    explicit operator bool() const { return mId != 0; }
    void reset() {
        if (mId != 0) Deleter::destroy(mId);
        mId = 0;
    }

  private:
    GLuint mId = 0;
};

namespace detail {
struct TextureDeleter {
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct SamplerDeleter {
    static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};
struct BufferDeleter {
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct VertexArrayDeleter {
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct FramebufferDeleter {
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct ProgramDeleter {
    static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct ShaderDeleter {
    static void destroy(GLuint id) { glDeleteShader(id); }
};
struct QueryDeleter {
    static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};
}  // namespace detail

using GlTexture = GlObject<detail::TextureDeleter>;
using GlSampler = GlObject<detail::SamplerDeleter>;
using GlBuffer = GlObject<detail::BufferDeleter>;
using GlVertexArray = GlObject<detail::VertexArrayDeleter>;
using GlFramebuffer = GlObject<detail::FramebufferDeleter>;
using GlProgram = GlObject<detail::ProgramDeleter>;
using GlShader = GlObject<detail::ShaderDeleter>;
using GlQuery = GlObject<detail::QueryDeleter>;

// Fresh names (DSA: glCreate*, so the objects exist before their first bind).
GlTexture createTexture(GLenum target);
GlSampler createSampler();
GlBuffer createBuffer();
GlVertexArray createVertexArray();
GlFramebuffer createFramebuffer();
GlQuery createQuery(GLenum target);

// An immutable single-level 2D texture of `internalFormat` (GL_RGBA8, GL_R32F,
// GL_DEPTH_COMPONENT32F...), contents undefined, nearest filtering, clamped to the edge.
GlTexture createTexture2d(GLenum internalFormat, int width, int height);

// A depth map as a texture of its texel kind (glTexelFormat: GL_DEPTH_COMPONENT16, 24 or 32F;
// GL rounds the floats of a fixed-point kind to its integers): depth(i, j) lands in GL texel
// (i, j), so ShadowMap row 0 is GL texel row 0 (no flip). A moments map likewise, as RG or RGBA
// 16F or 32F (its kind's glTexelFormat).
GlTexture createDepthTexture(const ShadowMap& map);

// The sampler behind pcf_prelude.h's uPcfCompare: hardware depth comparison (GL_LEQUAL),
// GL_LINEAR (so one tap is the bilinear 2x2 of docs/methods.md, "Conventions"), clamped to the
// edge.
GlSampler createCompareSampler();
// Plain nearest-texel reads, clamped to the edge: the kernel reads the map through it.
GlSampler createNearestSampler();

// A framebuffer with its own textures: colour attachment k is colors[k] (GL_COLOR_ATTACHMENT0
// + k, draw buffer k), depth is a depth texture or empty.
struct OffscreenTarget {
    GlFramebuffer framebuffer;
    std::vector<GlTexture> colors;
    GlTexture depth;
    int width = 0;
    int height = 0;
};

// colorFormats: one internal format per colour attachment, in order (may be empty: a depth-only
// target such as the shadow pass); depthFormat: GL_DEPTH_COMPONENT16/24/32F or GL_NONE.
// Throws std::runtime_error naming the status when the framebuffer is not complete.
OffscreenTarget createOffscreenTarget(int width, int height,
                                      const std::vector<GLenum>& colorFormats,
                                      GLenum depthFormat = GL_NONE);

// Throws std::runtime_error("framebuffer WHAT is incomplete: GL_FRAMEBUFFER_...") unless the
// framebuffer (0 = the default one) is complete.
void checkFramebufferComplete(GLuint framebuffer, const std::string& what);
// "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT" and friends; the number in hex when unknown.
std::string framebufferStatusName(GLenum status);

// The width x height pixels at the lower-left corner of `attachment` of `framebuffer`, as RGBA8,
// rows TOP-DOWN (first row = top of the picture). framebuffer 0 is the window's: pass GL_BACK
// or GL_FRONT; otherwise pass GL_COLOR_ATTACHMENT0 + k. Leaves GL state as it found it.
std::vector<uint8_t> readPixelsRgba8(GLuint framebuffer, GLenum attachment, int width, int height);

// The same as floats, `channels` (1..4: R, RG, RGB, RGBA) per pixel, rows TOP-DOWN.
std::vector<float> readPixelsFloat(GLuint framebuffer, GLenum attachment, int width, int height,
                                   int channels);

// Every texel of level 0 of a depth texture of any depth format (GL_DEPTH_COMPONENT16/24/32F),
// as floats in [0,1], rows in GL ORDER (element j * width + i = GL texel (i, j); row 0 = GL texel
// row 0 = the bottom of the picture): exactly ShadowMap's layout.
std::vector<float> readDepthTexture(GLuint texture, int width, int height);

// Reverses the order of `rows` rows of `rowLength` elements in place: GL order <-> top-down.
template <class T>
void flipRows(std::vector<T>& data, size_t rowLength, size_t rows) {
    if (rows < 2) return;
    for (size_t top = 0, bottom = rows - 1; top < bottom; ++top, --bottom) {
        std::swap_ranges(data.begin() + top * rowLength, data.begin() + (top + 1) * rowLength,
                         data.begin() + bottom * rowLength);
    }
}

}  // namespace pcf
