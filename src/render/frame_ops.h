// frame_ops.h: the framebuffer operations the layers above render/ compose their frames with
// (copying a rendered picture into a frame, clearing panels, binding the frame to draw on,
// waiting for the GPU), so that the OpenGL calls stay in render/ and draw/.
//
// Rectangles are in GL's window coordinates: x from the left, y from the BOTTOM (gl_objects.h,
// "Row order").
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace pcf {

// A GL rectangle: [x0, x1) x [y0, y1), y from the bottom.
struct GlRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Copies the `from` rectangle of colour attachment 0 of framebuffer `from` into the `to`
// rectangle of framebuffer `to`; scaled with linear filtering when `linear`, else nearest (a
// same-size copy, which llvmpipe does as a memory copy).
void blitColour(GLuint from, GlRect fromRect, GLuint to, GlRect toRect, bool linear = false);

// Fills the whole of `framebuffer`'s draw buffer 0 with `colour`, whatever the scissor says.
void clearColour(GLuint framebuffer, glm::vec4 colour);
// Fills the rectangle `rect` of `framebuffer`'s draw buffer 0 with `colour`; the scissor test is
// left as it was found.
void clearColourRect(GLuint framebuffer, GlRect rect, glm::vec4 colour);

// Makes `framebuffer` (0: the window's) the one drawn into and read from.
void bindFramebuffer(GLuint framebuffer);

// Writes w x h RGBA8 pixels, rows in GL order (row 0 = bottom), into level 0 of `texture`.
void uploadRgba8(GLuint texture, int w, int h, const std::vector<uint8_t>& rgba);

// Waits until the GPU has done every command given so far (a timer's end: docs/measurement.md).
void finishGpu();

// Keeps the draw and read framebuffer bindings of its construction and puts them back when it
// goes (a chart drawn offscreen in the middle of a frame).
class FramebufferBindingsKept {
  public:
    FramebufferBindingsKept();
    ~FramebufferBindingsKept();
    FramebufferBindingsKept(const FramebufferBindingsKept&) = delete;
    FramebufferBindingsKept& operator=(const FramebufferBindingsKept&) = delete;

  private:
    GLint mDraw = 0;
    GLint mRead = 0;
};

}  // namespace pcf
