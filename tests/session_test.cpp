// Session::composeInto: the viewer draws its window's back buffer directly (no copy of the
// offscreen frame). That buffer holds whatever the last frame left there, so the composed frame
// must cover every pixel and equal, byte for byte, the offscreen frame export writes.
#include "app/session.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>

#include "render/gl_context.h"
#include "render/gl_objects.h"
#include "render/glfw_window_context.h"
#include "virtual_display.h"

namespace pcf {
namespace {

class SessionCompose : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> SessionCompose::sContext;

// The frame composed into a target first filled with `stale`, read back top-down.
std::vector<uint8_t> composedOver(Session& session, const OffscreenTarget& target,
                                  const glm::vec4& stale) {
    glDisable(GL_SCISSOR_TEST);
    glClearNamedFramebufferfv(target.framebuffer.id(), GL_COLOR, 0, &stale.x);
    session.composeInto(target.framebuffer.id());
    return readPixelsRgba8(target.framebuffer.id(), GL_COLOR_ATTACHMENT0, target.width,
                           target.height);
}

size_t differingBytes(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    size_t n = 0;
    for (size_t k = 0; k < a.size() && k < b.size(); ++k) n += a[k] != b[k] ? 1 : 0;
    return n + (a.size() > b.size() ? a.size() - b.size() : b.size() - a.size());
}

TEST_F(SessionCompose, IntoAnotherTargetEqualsTheOffscreenFrameWhateverItHeld) {
    const glm::ivec2 size(960, 540);
    Session session(size, false);
    session.loadLesson(resolveLesson("1"));
    OffscreenTarget window = createOffscreenTarget(size.x, size.y, {GL_RGBA8});
    for (int move = 0; move < 3; ++move) {
        // A moved pixel (the scene reused) as the viewer draws it, then from scratch.
        session.setPixel(session.pixel() + glm::ivec2(move == 1 ? 7 : -3, move));
        std::vector<uint8_t> magenta = composedOver(session, window, {1, 0, 1, 1});
        std::vector<uint8_t> green = composedOver(session, window, {0, 1, 0, 0});
        session.compose();
        std::vector<uint8_t> frame = session.readFrame();
        ASSERT_EQ(frame.size(), static_cast<size_t>(size.x) * size.y * 4);
        EXPECT_EQ(differingBytes(magenta, frame), 0u) << "move " << move;
        EXPECT_EQ(differingBytes(green, frame), 0u) << "move " << move;
    }
    // The pixel's move shows: the frames are of the pixel, not a cached one.
    session.setPixel(session.pixel() + glm::ivec2(40, 20));
    std::vector<uint8_t> before = session.readFrame();
    std::vector<uint8_t> moved = composedOver(session, window, {1, 0, 1, 1});
    EXPECT_GT(differingBytes(before, moved), 1000u);
}

// The viewer's own path: the frame composed into a window's back buffer (rows top-down in memory,
// another pixel format) reads back as the frame export writes, up to blending's rounding. The test
// starts its own Xvfb.
TEST(SessionWindow, ComposedIntoTheWindowMatchesTheExportedFrame) {
    testutil::VirtualDisplay server;
    ASSERT_FALSE(server.display().empty()) << "Xvfb did not start (is xvfb installed?)";
    ASSERT_EQ(setenv("DISPLAY", server.display().c_str(), 1), 0);
    {
        std::unique_ptr<GlfwWindowContext> window =
            GlfwWindowContext::create(640, 360, "session test", true);
        glm::ivec2 size = window->framebufferSize();
        ASSERT_EQ(size, glm::ivec2(640, 360));
        Session session(size, false);
        session.loadLesson(resolveLesson("5"));
        for (int move = 0; move < 2; ++move) {
            session.setPixel(session.pixel() + glm::ivec2(5, -2));
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glDrawBuffer(GL_BACK);
            glReadBuffer(GL_BACK);
            glDisable(GL_SCISSOR_TEST);
            glClearColor(1, 0, 1, 1);  // what a stale back buffer might hold
            glClear(GL_COLOR_BUFFER_BIT);
            session.composeInto(0);
            glFinish();
            std::vector<uint8_t> shown = readPixelsRgba8(0, GL_BACK, size.x, size.y);
            session.compose();
            std::vector<uint8_t> exported = session.readFrame();
            ASSERT_EQ(shown.size(), exported.size());
            // llvmpipe blends into the window's BGRA with its own rounding: a few antialiased
            // pixels come out 1 apart (2 of 230 400 here); nothing else may differ.
            size_t pixels = 0;
            int largest = 0;
            for (size_t k = 0; k < shown.size(); k += 4) {
                int d = 0;
                for (size_t c = 0; c < 4; ++c) {
                    d = std::max(d, std::abs(int(shown[k + c]) - int(exported[k + c])));
                }
                pixels += d > 0 ? 1 : 0;
                largest = std::max(largest, d);
            }
            EXPECT_LE(largest, 1) << "move " << move;
            EXPECT_LE(pixels, 20u) << "move " << move;
        }
    }
    unsetenv("DISPLAY");
}

}  // namespace
}  // namespace pcf
