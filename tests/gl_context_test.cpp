// The headless EGL context: OpenGL 4.5 core on llvmpipe (CI) or a GPU, several per process.
#include "render/gl_context.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "render/egl_context.h"
#include "render/gl_objects.h"

namespace pcf {
namespace {

// Clears a small offscreen target and reads it back: proves the context really renders.
void expectClearReadsBack(float r, float g, float b) {
    OffscreenTarget t = createOffscreenTarget(4, 3, {GL_RGBA32F});
    glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.id());
    glClearColor(r, g, b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    std::vector<float> px = readPixelsFloat(t.framebuffer.id(), GL_COLOR_ATTACHMENT0, 4, 3, 4);
    ASSERT_EQ(px.size(), 4u * 3u * 4u);
    for (size_t k = 0; k < px.size(); k += 4) {
        EXPECT_EQ(px[k + 0], r);
        EXPECT_EQ(px[k + 1], g);
        EXPECT_EQ(px[k + 2], b);
        EXPECT_EQ(px[k + 3], 1.0f);
    }
}

TEST(GlContext, HeadlessContextIsOpenGl45Core) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    ASSERT_NE(context, nullptr);
    EXPECT_TRUE(context->isHeadless());
    EXPECT_EQ(context->framebufferSize(), glm::ivec2(0, 0));

    GLint major = 0;
    GLint minor = 0;
    GLint profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_GE(major * 10 + minor, 45);
    EXPECT_NE(profile & GL_CONTEXT_CORE_PROFILE_BIT, 0);
    EXPECT_EQ(profile & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT, 0);

    EXPECT_FALSE(context->renderer().empty());
    EXPECT_EQ(context->renderer(), reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    EXPECT_EQ(context->version(), reinterpret_cast<const char*>(glGetString(GL_VERSION)));
    EXPECT_NE(context->description().find(context->renderer()), std::string::npos);
    EXPECT_NE(context->description().find(context->version()), std::string::npos);
    glm::ivec2 v = parseGlVersion(context->version());
    EXPECT_GE(v.x * 10 + v.y, 45);

    // The platform that worked, for the log: surfaceless on Mesa, device on NVIDIA headless.
    auto* egl = dynamic_cast<EglContext*>(context.get());
    ASSERT_NE(egl, nullptr);
    std::printf("headless context: %s via EGL %s\n", context->description().c_str(),
                egl->platform().c_str());
    expectClearReadsBack(0.25f, 0.5f, 0.75f);
}

TEST(GlContext, SequentialContextsInOneProcess) {
    for (int k = 0; k < 3; ++k) {
        std::unique_ptr<GlContext> context = createHeadlessContext();
        context->makeCurrent();
        expectClearReadsBack(0.125f * static_cast<float>(k), 0.5f, 1.0f);
    }
}

TEST(GlContext, TwoContextsAliveAtOnce) {
    std::unique_ptr<GlContext> a = createHeadlessContext();
    std::unique_ptr<GlContext> b = createHeadlessContext();
    a->makeCurrent();
    expectClearReadsBack(1.0f, 0.0f, 0.0f);
    b->makeCurrent();
    expectClearReadsBack(0.0f, 1.0f, 0.0f);
    // Destroying the first must not take the shared EGL display from the second.
    a.reset();
    b->makeCurrent();
    expectClearReadsBack(0.0f, 0.0f, 1.0f);
}

TEST(GlContext, ParsesVersionStrings) {
    EXPECT_EQ(parseGlVersion("4.5 (Core Profile) Mesa 22.3.6"), glm::ivec2(4, 5));
    EXPECT_EQ(parseGlVersion("4.6.0 NVIDIA 550.54.14"), glm::ivec2(4, 6));
    EXPECT_EQ(parseGlVersion("OpenGL ES 3.2 Mesa"), glm::ivec2(0, 0));
    EXPECT_EQ(parseGlVersion(""), glm::ivec2(0, 0));
}

}  // namespace
}  // namespace pcf
