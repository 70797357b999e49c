#include "render/glfw_window_context.h"

#include <epoxy/gl.h>

#include <mutex>
#include <stdexcept>

#include "render/driver_pin.h"

// After epoxy: GLFW must not pull in a GL header of its own.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace pcf {

namespace {

// glfwInit and glfwTerminate are process-wide: initialise with the first window, terminate
// with the last, so that windows can come and go (tests open several in turn).
std::mutex gGlfwMutex;
int gGlfwWindows = 0;
std::string gGlfwError;

void recordGlfwError(int, const char* description) { gGlfwError = description; }

std::string takeGlfwError() {
    std::string e = gGlfwError.empty() ? "unknown error" : gGlfwError;
    gGlfwError.clear();
    return e;
}

void acquireGlfw() {
    std::lock_guard lock(gGlfwMutex);
    if (gGlfwWindows == 0) {
        glfwSetErrorCallback(recordGlfwError);
        if (glfwInit() != GLFW_TRUE) {
            throw std::runtime_error(
                "no display: set DISPLAY or use pcfscope export (GLFW: " + takeGlfwError() + ")");
        }
    }
    ++gGlfwWindows;
}

void releaseGlfw() {
    std::lock_guard lock(gGlfwMutex);
    if (--gGlfwWindows == 0) glfwTerminate();
}

}  // namespace

std::unique_ptr<GlfwWindowContext> GlfwWindowContext::create(int width, int height,
                                                             const std::string& title,
                                                             bool visible) {
    // Sanitizer builds keep libGL and the driver mapped past glfwTerminate (render/driver_pin.h).
    std::set<std::string> before = mappedLibraries();
    acquireGlfw();
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    // HiDPI: the window grows with the monitor's content scale, and on macOS the framebuffer
    // gets the full Retina resolution; framebufferSize() reports pixels either way.
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    glfwWindowHint(GLFW_COCOA_RETINA_FRAMEBUFFER, GLFW_TRUE);
#ifndef NDEBUG
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
#endif
    GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window == nullptr) {
        std::string reason = takeGlfwError();
        releaseGlfw();
        throw std::runtime_error(
            "no display: set DISPLAY or use pcfscope export (GLFW: cannot open an OpenGL 4.5 "
            "core window: " +
            reason + ")");
    }
    glfwMakeContextCurrent(window);
    pinLibrariesLoadedSince(before);
    // The constructor owns the window (and the GLFW reference) from here on.
    std::unique_ptr<GlfwWindowContext> out(new GlfwWindowContext(window));
    out->initializeCurrent("GLFW");
    return out;
}

GlfwWindowContext::GlfwWindowContext(GLFWwindow* window) : mWindow(window) {}

GlfwWindowContext::~GlfwWindowContext() {
    if (glfwGetCurrentContext() == mWindow) glfwMakeContextCurrent(nullptr);
    glfwDestroyWindow(mWindow);
    releaseGlfw();
}

void GlfwWindowContext::makeCurrent() { glfwMakeContextCurrent(mWindow); }

glm::ivec2 GlfwWindowContext::framebufferSize() const {
    glm::ivec2 size(0, 0);
    glfwGetFramebufferSize(mWindow, &size.x, &size.y);
    return size;
}

void GlfwWindowContext::swapBuffers() { glfwSwapBuffers(mWindow); }

std::unique_ptr<GlContext> createWindowContext(int width, int height, const std::string& title,
                                               bool visible) {
    return GlfwWindowContext::create(width, height, title, visible);
}

}  // namespace pcf
