#include "render/frame_ops.h"

namespace pcf {

void blitColour(GLuint from, GlRect fromRect, GLuint to, GlRect toRect, bool linear) {
    glNamedFramebufferReadBuffer(from, GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(from, to, fromRect.x0, fromRect.y0, fromRect.x1, fromRect.y1, toRect.x0,
                           toRect.y0, toRect.x1, toRect.y1, GL_COLOR_BUFFER_BIT,
                           linear ? GL_LINEAR : GL_NEAREST);
}

void clearColour(GLuint framebuffer, glm::vec4 colour) {
    GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
    if (scissor) glDisable(GL_SCISSOR_TEST);
    glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, &colour.x);
    if (scissor) glEnable(GL_SCISSOR_TEST);
}

void clearColourRect(GLuint framebuffer, GlRect rect, glm::vec4 colour) {
    GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
    GLint box[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_SCISSOR_BOX, box);
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x0, rect.y0, rect.x1 - rect.x0, rect.y1 - rect.y0);
    glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, &colour.x);
    glScissor(box[0], box[1], box[2], box[3]);
    if (!scissor) glDisable(GL_SCISSOR_TEST);
}

void bindFramebuffer(GLuint framebuffer) { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer); }

void uploadRgba8(GLuint texture, int w, int h, const std::vector<uint8_t>& rgba) {
    glTextureSubImage2D(texture, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
}

void finishGpu() { glFinish(); }

FramebufferBindingsKept::FramebufferBindingsKept() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &mDraw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &mRead);
}

FramebufferBindingsKept::~FramebufferBindingsKept() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(mDraw));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(mRead));
}

}  // namespace pcf
