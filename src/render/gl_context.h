// gl_context.h: one interface over the two ways pcfscope gets an OpenGL 4.5 core context:
// headless through EGL (export, render, tests, CI) and a GLFW window (the viewer).
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <string>

namespace pcf {

// A current-able OpenGL 4.5 core context. Every GL object (gl_objects.h) must be destroyed while
// the context that made it is still alive and current: destroy them before the context.
class GlContext {
  public:
    virtual ~GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    // Makes this context current on the calling thread. The factories leave it current.
    virtual void makeCurrent() = 0;
    // The default framebuffer in pixels (not screen coordinates, so HiDPI windows report their
    // real size); {0, 0} for a headless context, which has no default framebuffer.
    virtual glm::ivec2 framebufferSize() const = 0;
    // Presents the back buffer; nothing when headless.
    virtual void swapBuffers() = 0;
    virtual bool isHeadless() const = 0;

    // GL_RENDERER and GL_VERSION as the driver reported them when the context was made,
    // e.g. "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6".
    std::string description() const { return mRenderer + ", OpenGL " + mVersion; }
    const std::string& renderer() const { return mRenderer; }
    const std::string& version() const { return mVersion; }

  protected:
    GlContext() = default;
    // Called by the subclasses once the new context is current: reads the GL strings, checks
    // that the driver really gave 4.5 core (throws std::runtime_error naming `api` otherwise),
    // and in debug builds routes GL debug messages to stderr.
    void initializeCurrent(const std::string& api);

  private:
    std::string mRenderer;
    std::string mVersion;
};

// A headless context: EGL with no surface at all (EGL_KHR_surfaceless_context), desktop OpenGL
// 4.5 core. Tries the Mesa surfaceless platform, then the first EGL device (NVIDIA headless),
// then the default display. Render into framebuffer objects. Throws std::runtime_error with one
// line saying what failed. Several may be created and destroyed in one process.
std::unique_ptr<GlContext> createHeadlessContext();

// A window with an OpenGL 4.5 core context (GLFW). Throws std::runtime_error when there is no
// display. The viewer, which needs the GLFWwindow*, uses GlfwWindowContext::create
// (glfw_window_context.h) instead; this is the same thing behind the plain interface.
std::unique_ptr<GlContext> createWindowContext(int width, int height, const std::string& title,
                                               bool visible);

// Parses "4.5 (Core Profile) Mesa 22.3.6" or "4.6.0 NVIDIA 550.54" into {4, 5} / {4, 6};
// {0, 0} when the string does not start with a version.
glm::ivec2 parseGlVersion(const std::string& version);

}  // namespace pcf
