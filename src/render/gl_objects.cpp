#include "render/gl_objects.h"

#include <cstdio>
#include <stdexcept>

#include "kernel/shadow_map.h"
#include "render/render_settings.h"

namespace pcf {

namespace {

// Readbacks must not depend on, nor disturb, the caller's pack state: a pixel pack buffer
// bound, a row length or an alignment left set by someone else would scramble the rows.
class PackStateGuard {
  public:
    PackStateGuard() {
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &mReadFramebuffer);
        glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &mPackBuffer);
        glGetIntegerv(GL_PACK_ALIGNMENT, &mAlignment);
        glGetIntegerv(GL_PACK_ROW_LENGTH, &mRowLength);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    }
    ~PackStateGuard() {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(mReadFramebuffer));
        glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(mPackBuffer));
        glPixelStorei(GL_PACK_ALIGNMENT, mAlignment);
        glPixelStorei(GL_PACK_ROW_LENGTH, mRowLength);
    }
    PackStateGuard(const PackStateGuard&) = delete;
    PackStateGuard& operator=(const PackStateGuard&) = delete;

  private:
    GLint mReadFramebuffer = 0;
    GLint mPackBuffer = 0;
    GLint mAlignment = 4;
    GLint mRowLength = 0;
};

// Errors left by earlier calls would be blamed on the readback that checks glGetError next.
void clearGlErrors() {
    for (int k = 0; k < 16 && glGetError() != GL_NO_ERROR; ++k) {
    }
}

void checkSize(int width, int height, const char* what) {
    if (width <= 0 || height <= 0) {
        throw std::invalid_argument(std::string(what) + ": size must be positive, got " +
                                    std::to_string(width) + " x " + std::to_string(height));
    }
}

// Reads into `out` in GL order (row 0 = bottom), then flips to top-down.
template <class T>
std::vector<T> readPixelsTopDown(GLuint framebuffer, GLenum attachment, int width, int height,
                                 int channels, GLenum format, GLenum type) {
    PackStateGuard guard;
    clearGlErrors();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    // Per-framebuffer state: setting it on our target does not change what others read.
    glReadBuffer(attachment);
    size_t rowLength = static_cast<size_t>(width) * channels;
    std::vector<T> out(rowLength * height);
    glReadnPixels(0, 0, width, height, format, type, static_cast<GLsizei>(out.size() * sizeof(T)),
                  out.data());
    GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04X", error);
        throw std::runtime_error(std::string("GL: reading pixels failed with error ") + code);
    }
    flipRows(out, rowLength, static_cast<size_t>(height));
    return out;
}

}  // namespace

GlTexture createTexture(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return GlTexture(id);
}

GlSampler createSampler() {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    return GlSampler(id);
}

GlBuffer createBuffer() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return GlBuffer(id);
}

GlVertexArray createVertexArray() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return GlVertexArray(id);
}

GlFramebuffer createFramebuffer() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return GlFramebuffer(id);
}

GlQuery createQuery(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return GlQuery(id);
}

GlTexture createTexture2d(GLenum internalFormat, int width, int height) {
    checkSize(width, height, "texture");
    GlTexture t = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, internalFormat, width, height);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

GlTexture createDepthTexture(const ShadowMap& map) {
    if (map.layers() != 1) {
        throw std::invalid_argument("createDepthTexture: the map is not one layer");
    }
    // A moments map: its 2 or 4 floats per texel as RG or RGBA (16F targets round them).
    static const GLenum MOMENT_FORMATS[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    int channels = map.spec().texel().channels;
    GLenum format = map.spec().texel().depth ? GL_DEPTH_COMPONENT : MOMENT_FORMATS[channels - 1];
    GlTexture t = createTexture2d(glTexelFormat(map.spec().texels), map.width(), map.height());
    GLint unpackBuffer = 0;
    GLint alignment = 4;
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpackBuffer);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // GL takes the first row given as texel row 0, which is ShadowMap's row 0: no flip.
    glTextureSubImage2D(t.id(), 0, 0, 0, map.width(), map.height(), format, GL_FLOAT,
                        map.depths().data());
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpackBuffer));
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
    return t;
}

GlSampler createCompareSampler() {
    GlSampler s = createSampler();
    glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    return s;
}

GlSampler createNearestSampler() {
    GlSampler s = createSampler();
    glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return s;
}

std::string framebufferStatusName(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_COMPLETE:
            return "GL_FRAMEBUFFER_COMPLETE";
        case GL_FRAMEBUFFER_UNDEFINED:
            return "GL_FRAMEBUFFER_UNDEFINED";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
        case GL_FRAMEBUFFER_UNSUPPORTED:
            return "GL_FRAMEBUFFER_UNSUPPORTED";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
            return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
            return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
        default: {
            char code[16];
            std::snprintf(code, sizeof code, "0x%04X", status);
            return code;
        }
    }
}

void checkFramebufferComplete(GLuint framebuffer, const std::string& what) {
    GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error("framebuffer " + what +
                                 " is incomplete: " + framebufferStatusName(status));
    }
}

OffscreenTarget createOffscreenTarget(int width, int height,
                                      const std::vector<GLenum>& colorFormats, GLenum depthFormat) {
    checkSize(width, height, "offscreen target");
    OffscreenTarget t;
    t.width = width;
    t.height = height;
    t.framebuffer = createFramebuffer();
    std::vector<GLenum> drawBuffers;
    for (size_t k = 0; k < colorFormats.size(); ++k) {
        GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k);
        t.colors.push_back(createTexture2d(colorFormats[k], width, height));
        glNamedFramebufferTexture(t.framebuffer.id(), attachment, t.colors.back().id(), 0);
        drawBuffers.push_back(attachment);
    }
    if (depthFormat != GL_NONE) {
        t.depth = createTexture2d(depthFormat, width, height);
        glNamedFramebufferTexture(t.framebuffer.id(), GL_DEPTH_ATTACHMENT, t.depth.id(), 0);
    }
    if (drawBuffers.empty()) {
        // A depth-only target (the shadow pass): no colour to draw to or read from.
        glNamedFramebufferDrawBuffer(t.framebuffer.id(), GL_NONE);
        glNamedFramebufferReadBuffer(t.framebuffer.id(), GL_NONE);
    } else {
        glNamedFramebufferDrawBuffers(t.framebuffer.id(), static_cast<GLsizei>(drawBuffers.size()),
                                      drawBuffers.data());
    }
    std::string what = std::to_string(width) + " x " + std::to_string(height) + " with " +
                       std::to_string(colorFormats.size()) + " colour attachment(s)" +
                       (depthFormat != GL_NONE ? " and depth" : "");
    checkFramebufferComplete(t.framebuffer.id(), what);
    return t;
}

std::vector<uint8_t> readPixelsRgba8(GLuint framebuffer, GLenum attachment, int width, int height) {
    checkSize(width, height, "readPixelsRgba8");
    return readPixelsTopDown<uint8_t>(framebuffer, attachment, width, height, 4, GL_RGBA,
                                      GL_UNSIGNED_BYTE);
}

std::vector<float> readPixelsFloat(GLuint framebuffer, GLenum attachment, int width, int height,
                                   int channels) {
    checkSize(width, height, "readPixelsFloat");
    static const GLenum FORMATS[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    if (channels < 1 || channels > 4) {
        throw std::invalid_argument("readPixelsFloat: channels must be 1..4, got " +
                                    std::to_string(channels));
    }
    return readPixelsTopDown<float>(framebuffer, attachment, width, height, channels,
                                    FORMATS[channels - 1], GL_FLOAT);
}

std::vector<float> readDepthTexture(GLuint texture, int width, int height) {
    checkSize(width, height, "readDepthTexture");
    PackStateGuard guard;
    std::vector<float> out(static_cast<size_t>(width) * height);
    clearGlErrors();
    // GL_DEPTH_COMPONENT + GL_FLOAT converts 16- and 24-bit normalised depths to [0,1] floats,
    // so one path serves every depth format. glGetTextureImage writes texel row 0 first.
    glGetTextureImage(texture, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      static_cast<GLsizei>(out.size() * sizeof(float)), out.data());
    GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04X", error);
        throw std::runtime_error(std::string("GL: glGetTextureImage of a depth texture failed "
                                             "(wrong size or not a depth texture?), error ") +
                                 code);
    }
    return out;
}

}  // namespace pcf
