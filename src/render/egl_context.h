// egl_context.h: the headless OpenGL 4.5 core context (EGL, no surface), made by
// createHeadlessContext() (gl_context.h).
#pragma once

#include <epoxy/egl.h>

#include <string>

#include "render/gl_context.h"

namespace pcf {

class EglContext final : public GlContext {
  public:
    // Takes ownership of a context already made current on `display` (and of one reference to
    // the initialised display); `platform` names where the display came from ("surfaceless",
    // "device", "default"). Throws std::runtime_error when the context is not 4.5 core.
    EglContext(EGLDisplay display, EGLContext context, std::string platform);
    ~EglContext() override;

    void makeCurrent() override;
    glm::ivec2 framebufferSize() const override { return {0, 0}; }
    void swapBuffers() override {}
    bool isHeadless() const override { return true; }

    const std::string& platform() const { return mPlatform; }

  private:
    void destroy();

    EGLDisplay mDisplay;
    EGLContext mContext;
    std::string mPlatform;
};

}  // namespace pcf
