#include "render/egl_context.h"

#include <epoxy/egl.h>

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "render/driver_pin.h"

namespace pcf {

namespace {

// EGL displays are per-process singletons: two contexts on the surfaceless platform share one
// EGLDisplay, and eglTerminate would pull it from under the other. So the display is
// initialised by the first context that uses it and terminated with the last.
std::mutex gDisplayMutex;
std::map<EGLDisplay, int> gDisplayUsers;

bool initializeDisplay(EGLDisplay display) {
    std::lock_guard lock(gDisplayMutex);
    EGLint major = 0;
    EGLint minor = 0;
    if (eglInitialize(display, &major, &minor) != EGL_TRUE) return false;
    ++gDisplayUsers[display];
    return true;
}

void releaseDisplay(EGLDisplay display) {
    std::lock_guard lock(gDisplayMutex);
    auto it = gDisplayUsers.find(display);
    if (it == gDisplayUsers.end()) return;
    if (--it->second == 0) {
        gDisplayUsers.erase(it);
        eglTerminate(display);
    }
}

bool hasExtension(const char* list, std::string_view name) {
    if (list == nullptr) return false;
    std::string_view all(list);
    size_t pos = 0;
    while ((pos = all.find(name, pos)) != std::string_view::npos) {
        size_t end = pos + name.size();
        bool startOk = pos == 0 || all[pos - 1] == ' ';
        bool endOk = end == all.size() || all[end] == ' ';
        if (startOk && endOk) return true;
        pos = end;
    }
    return false;
}

struct Candidate {
    const char* platform;
    EGLDisplay display;
};

// The displays to try, best first. Client extensions are queried on EGL_NO_DISPLAY.
std::vector<Candidate> candidateDisplays() {
    std::vector<Candidate> out;
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    bool platformBase = hasExtension(clientExtensions, "EGL_EXT_platform_base");
    // Mesa: no window system at all, which is what a headless server has.
    if (platformBase && hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY) out.push_back({"surfaceless", d});
    }
    // NVIDIA's headless path: a display on the first GPU device.
    if (platformBase && hasExtension(clientExtensions, "EGL_EXT_platform_device") &&
        hasExtension(clientExtensions, "EGL_EXT_device_enumeration")) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (eglQueryDevicesEXT(8, devices, &count) == EGL_TRUE && count > 0) {
            EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
            if (d != EGL_NO_DISPLAY) out.push_back({"device", d});
        }
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d != EGL_NO_DISPLAY) out.push_back({"default", d});
    return out;
}

// A 4.5 core context on `display`, current with no surface; nullopt (display released) when
// this display cannot give one.
std::optional<EGLContext> tryCreateContext(EGLDisplay display) {
    if (!initializeDisplay(display)) return std::nullopt;
    auto fail = [&]() -> std::optional<EGLContext> {
        releaseDisplay(display);
        return std::nullopt;
    };
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context")) return fail();
    if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) return fail();

    // No surface is ever made, so any config that renders desktop GL will do; without
    // EGL_KHR_no_config_context one still has to be named.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(extensions, "EGL_KHR_no_config_context")) {
        const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
                                        EGL_NONE};
        EGLint count = 0;
        if (eglChooseConfig(display, configAttribs, &config, 1, &count) != EGL_TRUE || count < 1) {
            return fail();
        }
    }
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     4,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
#ifndef NDEBUG
                                     EGL_CONTEXT_OPENGL_DEBUG,
                                     EGL_TRUE,
#endif
                                     EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) return fail();
    if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
        eglDestroyContext(display, context);
        return fail();
    }
    return context;
}

}  // namespace

EglContext::EglContext(EGLDisplay display, EGLContext context, std::string platform)
    : mDisplay(display), mContext(context), mPlatform(std::move(platform)) {
    try {
        initializeCurrent("EGL (" + mPlatform + ")");
    } catch (...) {
        // The destructor does not run for a constructor that throws.
        destroy();
        throw;
    }
}

EglContext::~EglContext() { destroy(); }

void EglContext::destroy() {
    if (eglGetCurrentContext() == mContext) {
        eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(mDisplay, mContext);
    releaseDisplay(mDisplay);
}

void EglContext::makeCurrent() {
    if (eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, mContext) != EGL_TRUE) {
        throw std::runtime_error("EGL: cannot make the headless context current");
    }
}

std::unique_ptr<GlContext> createHeadlessContext() {
    // Sanitizer builds keep the driver mapped until exit (render/driver_pin.h).
    std::set<std::string> before = mappedLibraries();
    std::string tried;
    for (const Candidate& c : candidateDisplays()) {
        tried += (tried.empty() ? "" : ", ") + std::string(c.platform);
        std::optional<EGLContext> context = tryCreateContext(c.display);
        if (!context) continue;
        pinLibrariesLoadedSince(before);
        return std::make_unique<EglContext>(c.display, *context, c.platform);
    }
    if (tried.empty()) tried = "none found";
    throw std::runtime_error("EGL: no display supports OpenGL 4.5 core (tried " + tried + ")");
}

}  // namespace pcf
