// The overlay draws the same bytes in a GLFW window as in an EGL offscreen target: an exported
// frame is the window's frame. The test starts its own Xvfb (scripts/deps installs it), so it
// needs no display from its environment and never draws on the user's.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "draw/canvas.h"
#include "render/gl_context.h"
#include "render/gl_objects.h"
#include "virtual_display.h"

namespace pcf {
namespace {

void drawFrame(Canvas& c, glm::ivec2 size) {
    c.fillRect({0, 0, float(size.x), float(size.y)}, {0.08f, 0.09f, 0.12f, 1});
    c.fillRect({10, 10, 150, 60}, {0.8f, 0.2f, 0.2f, 1});
    c.strokeRect({10, 10, 150, 60}, 2, {1, 1, 1, 1});
    c.text({18, 18}, "visibility = 0.75", {FontFace::Mono, 16, {1, 1, 1, 1}});
    c.textBox({18, 40, 140, 40}, "lit when ref ≤ depth, Σw = 1", {FontFace::Sans, 12});
    c.circle({220, 50}, 25, {0.3f, 0.8f, 1, 1});
    c.ring({220, 50}, 35, 3, {1, 0.75f, 0.2f, 0.8f});
    c.arrow({20, 150}, {280, 110}, 2.5f, {0.6f, 1, 0.6f, 1});
    c.line({20, 180}, {300, 180}, 1, {1, 1, 1, 0.5f});
    c.fillRect({100, 90, 80, 80}, {0.2f, 0.4f, 1, 0.4f});
}

std::vector<uint8_t> renderOffscreen(glm::ivec2 size) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    OffscreenTarget t = createOffscreenTarget(size.x, size.y, {GL_RGBA8});
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t.framebuffer.id());
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    {
        Canvas canvas;
        canvas.begin(size);
        drawFrame(canvas, size);
        canvas.flush();
    }
    return readPixelsRgba8(t.framebuffer.id(), GL_COLOR_ATTACHMENT0, size.x, size.y);
}

TEST(OverlayWindow, WindowFrameIsByteIdenticalToTheOffscreenFrame) {
    testutil::VirtualDisplay server;
    ASSERT_FALSE(server.display().empty()) << "Xvfb did not start (is xvfb installed?)";
    ASSERT_EQ(setenv("DISPLAY", server.display().c_str(), 1), 0);
    std::vector<uint8_t> windowPixels;
    glm::ivec2 size(0, 0);
    {
        std::unique_ptr<GlContext> window = createWindowContext(320, 200, "overlay test", true);
        size = window->framebufferSize();
        ASSERT_EQ(size, glm::ivec2(320, 200));
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDrawBuffer(GL_BACK);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        Canvas canvas;
        canvas.begin(size);
        drawFrame(canvas, size);
        canvas.flush();
        EXPECT_EQ(canvas.lastFlushDrawCalls(), 1);
        glFinish();
        windowPixels = readPixelsRgba8(0, GL_BACK, size.x, size.y);
    }
    unsetenv("DISPLAY");
    std::vector<uint8_t> offscreenPixels = renderOffscreen(size);
    ASSERT_EQ(windowPixels.size(), offscreenPixels.size());
    // Alpha: a window without an alpha channel reads back 255, as the opaque offscreen frame.
    size_t different = 0;
    for (size_t k = 0; k < windowPixels.size(); ++k)
        different += windowPixels[k] != offscreenPixels[k];
    EXPECT_EQ(different, 0u);
    // And the frame is not trivially empty.
    EXPECT_NE(windowPixels[(50 * 320 + 220) * 4 + 2], 0);
}

}  // namespace
}  // namespace pcf
