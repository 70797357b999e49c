#include "render/gl_context.h"

#include <epoxy/gl.h>

#include <cstdio>
#include <stdexcept>

namespace pcf {

namespace {

std::string glString(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s != nullptr ? reinterpret_cast<const char*>(s) : std::string();
}

#ifndef NDEBUG
// Debug builds only: the callback makes the driver validate and report, which costs time.
void GLAPIENTRY printDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                                  const GLchar* message, const void*) {
    // Notifications (buffer placement hints and the like) would drown the real problems.
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    std::fprintf(stderr, "GL debug%s: %s\n", type == GL_DEBUG_TYPE_ERROR ? " error" : "", message);
}
#endif

}  // namespace

glm::ivec2 parseGlVersion(const std::string& version) {
    int major = 0;
    int minor = 0;
    if (std::sscanf(version.c_str(), "%d.%d", &major, &minor) != 2) return {0, 0};
    return {major, minor};
}

void GlContext::initializeCurrent(const std::string& api) {
    mRenderer = glString(GL_RENDERER);
    mVersion = glString(GL_VERSION);
    glm::ivec2 v = parseGlVersion(mVersion);
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    if (v.x * 10 + v.y < 45 || (profile & GL_CONTEXT_CORE_PROFILE_BIT) == 0) {
        throw std::runtime_error(api + ": got OpenGL " + mVersion + " (" + mRenderer +
                                 "), pcfscope needs 4.5 core");
    }
#ifndef NDEBUG
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(printDebugMessage, nullptr);
#endif
}

}  // namespace pcf
