// The GLFW window context, under a virtual X server when no display is set: it opens, renders
// into its default framebuffer, and reads back what it drew.
#include <epoxy/gl.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

// After epoxy: GLFW must not pull in a GL header of its own.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "render/gl_objects.h"
#include "render/glfw_window_context.h"
#include "virtual_display.h"

namespace pcf {
namespace {

class GlfwWindow : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        const char* display = std::getenv("DISPLAY");
        if (display != nullptr && *display != '\0') {
            sDisplay = display;
            return;
        }
        sServer = new testutil::VirtualDisplay();
        sDisplay = sServer->display();
    }
    static void TearDownTestSuite() {
        delete sServer;
        sServer = nullptr;
    }
    void SetUp() override {
        ASSERT_FALSE(sDisplay.empty()) << "no DISPLAY and Xvfb did not start";
        setenv("DISPLAY", sDisplay.c_str(), 1);
    }

    static testutil::VirtualDisplay* sServer;
    static std::string sDisplay;
};

testutil::VirtualDisplay* GlfwWindow::sServer = nullptr;
std::string GlfwWindow::sDisplay;

TEST_F(GlfwWindow, OpensA45CoreWindowThatRendersAndReadsBack) {
    std::unique_ptr<GlfwWindowContext> context =
        GlfwWindowContext::create(64, 48, "pcfscope test", true);
    ASSERT_NE(context->window(), nullptr);
    EXPECT_FALSE(context->isHeadless());
    glm::ivec2 size = context->framebufferSize();
    // Xvfb has no HiDPI scaling: pixels = screen coordinates.
    EXPECT_EQ(size, glm::ivec2(64, 48));
    glm::ivec2 version = parseGlVersion(context->version());
    EXPECT_GE(version.x * 10 + version.y, 45) << context->description();
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_NE(profile & GL_CONTEXT_CORE_PROFILE_BIT, 0);

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, size.x, size.y);
    glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    // The top 10 rows in another colour: the window's readback must be top-down as well.
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, size.y - 10, size.x, 10);
    glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    std::vector<uint8_t> px = readPixelsRgba8(0, GL_BACK, size.x, size.y);
    ASSERT_EQ(px.size(), static_cast<size_t>(size.x * size.y * 4));
    for (int row = 0; row < size.y; ++row) {
        bool top = row < 10;
        for (int x = 0; x < size.x; ++x) {
            const uint8_t* p = &px[(static_cast<size_t>(row) * size.x + x) * 4];
            ASSERT_EQ(p[0], top ? 255 : 51) << "row " << row << " x " << x;
            ASSERT_EQ(p[1], top ? 0 : 102) << "row " << row << " x " << x;
            ASSERT_EQ(p[2], top ? 0 : 153) << "row " << row << " x " << x;
        }
    }
    context->swapBuffers();
    glfwPollEvents();
}

TEST_F(GlfwWindow, WindowsComeAndGoThroughThePlainInterface) {
    for (int k = 0; k < 2; ++k) {
        std::unique_ptr<GlContext> context = createWindowContext(32, 32, "again", false);
        context->makeCurrent();
        EXPECT_FALSE(context->isHeadless());
        // Offscreen rendering works in a window's context as in a headless one.
        OffscreenTarget t = createOffscreenTarget(4, 4, {GL_RGBA8});
        const float green[4] = {0.0f, 1.0f, 0.0f, 1.0f};
        glClearNamedFramebufferfv(t.framebuffer.id(), GL_COLOR, 0, green);
        std::vector<uint8_t> px = readPixelsRgba8(t.framebuffer.id(), GL_COLOR_ATTACHMENT0, 4, 4);
        for (size_t i = 0; i < px.size(); i += 4) EXPECT_EQ(px[i + 1], 255);
    }
}

TEST_F(GlfwWindow, NoDisplayGivesAClearMessage) {
    // A display number nobody serves.
    setenv("DISPLAY", ":987654", 1);
    try {
        createWindowContext(32, 32, "nowhere", false);
        FAIL() << "a window opened on a display that does not exist";
    } catch (const std::runtime_error& e) {
        std::string what = e.what();
        EXPECT_EQ(what.rfind("no display: set DISPLAY or use pcfscope export", 0), 0u) << what;
    }
}

}  // namespace
}  // namespace pcf
