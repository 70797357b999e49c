// glfw_window_context.h: the windowed OpenGL 4.5 core context of the viewer (GLFW).
#pragma once

#include <memory>
#include <string>

#include "render/gl_context.h"

struct GLFWwindow;

namespace pcf {

class GlfwWindowContext final : public GlContext {
  public:
    // Opens a window (hidden unless `visible`) of width x height screen coordinates with a 4.5
    // core context, and leaves the context current. Throws std::runtime_error
    // ("no display: set DISPLAY or use pcfscope export (GLFW: ...)") when there is no display.
    static std::unique_ptr<GlfwWindowContext> create(int width, int height,
                                                     const std::string& title, bool visible);
    ~GlfwWindowContext() override;

    void makeCurrent() override;
    // In pixels: on HiDPI screens larger than the size in screen coordinates.
    glm::ivec2 framebufferSize() const override;
    void swapBuffers() override;
    bool isHeadless() const override { return false; }

    // For the viewer's input callbacks and event loop. Owned by this context.
    GLFWwindow* window() const { return mWindow; }

  private:
    explicit GlfwWindowContext(GLFWwindow* window);

    GLFWwindow* mWindow;
};

}  // namespace pcf
