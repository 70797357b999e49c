#include "app/viewer.h"

#include <epoxy/gl.h>
// After epoxy, without GLFW pulling in its own GL header.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "app/cli_util.h"
#include "app/export.h"
#include "app/output_files.h"
#include "app/render_options.h"
#include "app/session.h"
#include "app/step_player.h"
#include "app/viewer_answer.h"
#include "app/viewer_split.h"
#include "kernel/bias.h"
#include "kernel/methods.h"
#include "render/frame_ops.h"
#include "render/glfw_window_context.h"
#include "render/image_io.h"

namespace pcf {

namespace {

// A free name for frames exported with E: DIR/LESSON-stepNN.png, then -take2, -take3 ... (never
// overwriting; a bare "-2" after the step number read as a range of steps).
std::string freeStem(const std::string& dir, const std::string& base) {
    std::error_code ec;
    std::string stem = (std::filesystem::path(dir) / base).string();
    auto taken = [&](const std::string& p) {  // a dangling link is taken too
        return std::filesystem::symlink_status(p, ec).type() !=
               std::filesystem::file_type::not_found;
    };
    for (int k = 2; taken(stem + ".png") || taken(stem + ".json"); ++k) {
        stem = (std::filesystem::path(dir) / (base + "-take" + std::to_string(k))).string();
    }
    return stem;
}

class Viewer {
  public:
    // `lesson`: o.lesson as runViewer loaded and checked it.
    Viewer(const ViewerOptions& o, GlfwWindowContext& window, Lesson lesson)
        : mWindow(window), mSession(window.framebufferSize(), o.presentation) {
        mLessons = builtInLessons();
        mSession.setLesson(std::move(lesson));
        mSession.setInteractive(true);  // the window's frames name its keys
        auto it = std::find(mLessons.begin(), mLessons.end(), o.lesson);
        mLessonIndex = it == mLessons.end() ? -1 : static_cast<int>(it - mLessons.begin());
        mPlayer.afterChange();
        mSession.setTypedAnswers(true);
    }

    Session& session() { return mSession; }
    bool quit() const { return mQuit; }

    void press(KeyPress k) {
        bool shift = (k.mods & GLFW_MOD_SHIFT) != 0;
        // A question's typed answer (its choices' letters before C's split view), R and the
        // exercise mode (viewer_answer.h).
        if (mAnswers.press(mSession, k)) {
            mSplit.follow(mSession);
            return;
        }
        if (mSplit.press(mSession, k.key)) return;
        // An animation step's own keys (step_player.h) first; around the others the player
        // puts the step's state back and shows its frame on the new one.
        if (mPlayer.press(k)) return;
        bool change = isLiveKey(k) || changesStep(k.key, shift);
        if (change) mPlayer.beforeChange();
        bool handled = pressNavigation(k.key, shift) || pressLiveKey(mSession, k);
        if (change) mPlayer.afterChange();
        if (!handled) pressView(k.key);
        mSplit.follow(mSession);
    }

    // The keys of pressNavigation that go to another step or lesson.
    static bool changesStep(int key, bool shift) {
        switch (key) {
            case GLFW_KEY_SPACE:
            case GLFW_KEY_BACKSPACE:
            case GLFW_KEY_HOME:
            case GLFW_KEY_END:
            case GLFW_KEY_L:
                return true;
            case GLFW_KEY_RIGHT:
            case GLFW_KEY_LEFT:
                return !shift;
            default:
                return false;
        }
    }

    // An animation step playing: its next frame when due; the seconds until the one after.
    std::optional<double> tick() {
        using namespace std::chrono;
        return mPlayer.tick(duration<double>(steady_clock::now().time_since_epoch()).count());
    }

    // The split view (C) and the magnifier (Z): viewer_split.h.
    ViewerSplit& split() { return mSplit; }

    void click(glm::dvec2 cursor) {
        // Cursor in screen coordinates; the frame is in framebuffer pixels (HiDPI).
        int ww = 0, wh = 0;
        glfwGetWindowSize(mWindow.window(), &ww, &wh);
        glm::ivec2 fb = mWindow.framebufferSize();
        if (ww <= 0 || wh <= 0) return;
        clickFrame(glm::vec2(cursor.x * fb.x / ww, cursor.y * fb.y / wh));
    }

    // A click at a frame pixel (a scripted `click:X,Y` too).
    void clickFrame(glm::vec2 p) {
        // A chart step's chart covers the scene: a click on it picks nothing.
        if (!mSession.clickFrame(p)) return;
        mSplit.follow(mSession);
        // The scene point the click pinned, as a lesson's `point` key takes it (lesson.h).
        if (const std::optional<ScenePoint>& q = mSession.point()) {
            std::printf("pixel (%d, %d): %s\n", mSession.pixel().x, mSession.pixel().y,
                        pointKeyText(q->posWs).c_str());
            std::fflush(stdout);
        }
    }

    // E: the frame as PNG + JSON into pcfscope-frames/. A failure is reported and the class
    // goes on; nothing half-written stays.
    void exportFrame() {
        std::string dir = "pcfscope-frames";
        std::string base = frameStem(mSession.lesson().name, mSession.step() + 1);
        if (mSession.predictStep() && mSession.revealed()) base += "-reveal";
        if (mSession.textPage() > 0) base += "-page" + std::to_string(mSession.textPage() + 1);
        std::string stem = freeStem(dir, base);
        try {
            OutputFiles outputs(false);
            outputs.add("E", stem + ".png");
            outputs.add("E", stem + ".json");
            // Written as `export` writes it: without the window's key hints.
            mSession.setInteractive(false);
            mSession.compose();
            glm::ivec2 size = mSession.frameSize();
            std::vector<uint8_t> rgba = mSession.readFrame();
            std::string json = mSession.stepJson() + "\n";
            mSession.setInteractive(true);
            writePngRgba8(stem + ".png", size.x, size.y, rgba);
            writeTextFile(stem + ".json", json);
            outputs.commit();
            std::fprintf(stderr, "view: exported %s.png\n", stem.c_str());
        } catch (const std::exception& e) {
            mSession.setInteractive(true);
            std::fprintf(stderr, "view: export failed: %s\n", e.what());
        }
    }

  private:
    // The keys that move through the steps, the pixels and the lessons, and Esc. Returns
    // whether `key` is one of them.
    bool pressNavigation(int key, bool shift) {
        glm::ivec2 px = mSession.pixel();
        switch (key) {
            case GLFW_KEY_ESCAPE:
                mQuit = true;
                return true;
            case GLFW_KEY_SPACE:
                forward();
                return true;
            case GLFW_KEY_RIGHT:
                if (shift)
                    mSession.setPixel(px + glm::ivec2(1, 0));
                else
                    forward();
                return true;
            case GLFW_KEY_LEFT:
                if (shift)
                    mSession.setPixel(px - glm::ivec2(1, 0));
                else
                    back();
                return true;
            case GLFW_KEY_BACKSPACE:
                back();
                return true;
            case GLFW_KEY_UP:
                mSession.setPixel(px - glm::ivec2(0, 1));
                return true;
            case GLFW_KEY_DOWN:
                mSession.setPixel(px + glm::ivec2(0, 1));
                return true;
            case GLFW_KEY_HOME:
                mSession.goToStep(0);
                return true;
            case GLFW_KEY_END:
                mSession.goToStep(mSession.stepCount() - 1);
                return true;
            case GLFW_KEY_L:
                nextLesson(shift ? -1 : 1);
                return true;
            default:
                return false;
        }
    }

    // The keys that toggle what the frame shows, export it, or go full screen.
    void pressView(int key) {
        switch (key) {
            case GLFW_KEY_G:
                mSession.setGrid(!mSession.grid());
                break;
            case GLFW_KEY_A:
                mSession.setHeatmap(!mSession.heatmap());
                break;
            case GLFW_KEY_E:
                exportFrame();
                break;
            case GLFW_KEY_P:
                mSession.setPresentation(!mSession.presentation());
                break;
            case GLFW_KEY_H:
                mSession.setHelp(!mSession.help());
                break;
            case GLFW_KEY_F:
                toggleFullscreen();
                break;
            default:
                break;
        }
    }

    // Space/Right: the next page of a step's text that pages, then the next step.
    void forward() {
        if (!mSession.nextPage()) mSession.goToStep(mSession.step() + 1);
    }
    void back() {
        if (mSession.previousPage()) return;
        int before = mSession.step();
        mSession.goToStep(before - 1);
    }

    void nextLesson(int delta) {
        if (mLessons.empty()) return;
        int n = static_cast<int>(mLessons.size());
        mLessonIndex = ((mLessonIndex < 0 ? 0 : mLessonIndex) + delta + n) % n;
        mSession.loadLesson(mLessons[static_cast<size_t>(mLessonIndex)]);
    }

    void toggleFullscreen() {
        GLFWwindow* w = mWindow.window();
        if (glfwGetWindowMonitor(w)) {
            glfwSetWindowMonitor(w, nullptr, mSaved.x, mSaved.y, mSaved.z, mSaved.w, 0);
            return;
        }
        GLFWmonitor* monitor = glfwGetPrimaryMonitor();
        if (!monitor) return;
        const GLFWvidmode* mode = glfwGetVideoMode(monitor);
        glfwGetWindowPos(w, &mSaved.x, &mSaved.y);
        glfwGetWindowSize(w, &mSaved.z, &mSaved.w);
        glfwSetWindowMonitor(w, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
    }

    GlfwWindowContext& mWindow;
    Session mSession;
    StepPlayer mPlayer{mSession};
    ViewerSplit mSplit;
    ViewerAnswers mAnswers;
    std::vector<std::string> mLessons;
    int mLessonIndex = -1;
    bool mQuit = false;
    glm::ivec4 mSaved{100, 100, 1600, 900};
};

Viewer* viewerOf(GLFWwindow* window) {
    return static_cast<Viewer*>(glfwGetWindowUserPointer(window));
}

void onKey(GLFWwindow* window, int key, int, int action, int mods) {
    Viewer* viewer = viewerOf(window);
    if (viewer && (action == GLFW_PRESS || action == GLFW_REPEAT)) viewer->press({key, mods});
}

void onMouseButton(GLFWwindow* window, int button, int action, int) {
    Viewer* viewer = viewerOf(window);
    if (!viewer || button != GLFW_MOUSE_BUTTON_LEFT || action != GLFW_PRESS) return;
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    viewer->click({x, y});
}

// Routes the window's keys and clicks to a viewer for as long as this lives. GLFW callbacks are
// plain functions; the viewer rides in the window's user pointer, which the destructor clears
// on every way out (return or exception).
class InputBinding {
  public:
    InputBinding(GLFWwindow* window, Viewer& viewer) : mWindow(window) {
        glfwSetWindowUserPointer(window, &viewer);
        glfwSetKeyCallback(window, onKey);
        glfwSetMouseButtonCallback(window, onMouseButton);
    }
    ~InputBinding() {
        glfwSetKeyCallback(mWindow, nullptr);
        glfwSetMouseButtonCallback(mWindow, nullptr);
        glfwSetWindowUserPointer(mWindow, nullptr);
    }
    InputBinding(const InputBinding&) = delete;
    InputBinding& operator=(const InputBinding&) = delete;

  private:
    GLFWwindow* mWindow;
};

// A frame for the window: composed straight into its back buffer (Session::composeInto says why
// not through the offscreen frame), at the window's size.
void composeToWindow(Session& session, GlfwWindowContext& window) {
    session.setFrameSize(window.framebufferSize());
    session.composeInto(0);
}

}  // namespace

namespace {

// --bench-frames: frame time as the class sees it: compose into the window (scene, trace,
// inspector), present (the swap),
// finish. Once with the scene rendered again every frame (a key changed the method), once with
// only the pixel moving (the scene is reused). Prints the medians.
void benchFrames(Session& session, GlfwWindowContext& window, int frames) {
    using Clock = std::chrono::steady_clock;
    auto ms = [](Clock::time_point a, Clock::time_point b) {
        return std::chrono::duration<double, std::milli>(b - a).count();
    };
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    struct Times {
        double frame, compose, present;
    };
    auto timeFrames = [&](bool rerender) {
        std::vector<double> frame, compose, shown;
        for (int k = 0; k < frames; ++k) {
            if (rerender)
                session.invalidateScene();
            else
                session.setPixel(session.pixel() + glm::ivec2(k % 2 ? -1 : 1, 0));
            auto start = Clock::now();
            composeToWindow(session, window);
            finishGpu();
            auto composed = Clock::now();
            window.swapBuffers();
            finishGpu();
            auto end = Clock::now();
            frame.push_back(ms(start, end));
            compose.push_back(ms(start, composed));
            shown.push_back(ms(composed, end));
        }
        return Times{median(frame), median(compose), median(shown)};
    };
    composeToWindow(session, window);  // warm-up: programs compiled, map rendered
    Times full = timeFrames(true);
    Times pick = timeFrames(false);
    glm::ivec2 size = session.frameSize();
    std::printf(
        "view: %dx%d, %s, %d frames each, medians (glFinish + steady_clock):\n"
        "  scene re-rendered: frame %.1f ms (compose %.1f + present %.1f)\n"
        "  pixel moved:       frame %.1f ms (compose %.1f + present %.1f)\n",
        size.x, size.y, std::string(methodInfo(session.settings().method).name).c_str(), frames,
        full.frame, full.compose, full.present, pick.frame, pick.compose, pick.present);
}

// --screenshot: the frame after the keys, written to `path` (staged in `outputs`).
void writeScreenshot(Viewer& viewer, GlfwWindowContext& window, const std::string& path,
                     OutputFiles& outputs) {
    Session& session = viewer.session();
    // Keys such as F change the window: let it settle, then compose at its size.
    for (int k = 0; k < 10; ++k) {
        glfwPollEvents();
        if (window.framebufferSize() != session.frameSize()) break;
        glfwWaitEventsTimeout(0.02);
    }
    glfwPollEvents();
    session.setFrameSize(window.framebufferSize());
    glm::ivec2 size = session.frameSize();
    writePngRgba8(path, size.x, size.y, viewer.split().readFrame(session));
    outputs.commit();
    viewer.split().composeInto(session, 0, size);
    window.swapBuffers();
}

// The class: a frame whenever something happens (or every 0.25 s), until Esc or the window
// closes.
void runInteractive(Viewer& viewer, GlfwWindowContext& window) {
    Session& session = viewer.session();
    while (!glfwWindowShouldClose(window.window()) && !viewer.quit()) {
        auto start = std::chrono::steady_clock::now();
        viewer.split().composeInto(session, 0, window.framebufferSize());
        finishGpu();
        double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        window.swapBuffers();
        session.setFrameTimeMs(ms);
        std::optional<double> due = viewer.tick();
        glfwWaitEventsTimeout(due ? std::min(*due, 0.25) : 0.25);
        if (due) viewer.tick();
    }
}

}  // namespace

int runViewer(const ViewerOptions& o) {
    std::vector<ScriptedInput> keys = parseScriptedInput(o.keys);
    OutputFiles outputs(o.force);
    Lesson lesson = loadLessonChecked(o.lesson);  // bad lessons fail before a window opens
    // The screenshot may not be what the view reads (a link to the lesson or a chart), --force
    // or not: every other writer refuses that too.
    outputs.addInput("LESSON", o.lesson);
    for (const LessonStep& step : lesson.steps) outputs.addInput("chart", step.chart);
    if (!o.screenshot.empty()) {
        requireExtension("--screenshot", o.screenshot, ".png");
        outputs.add("--screenshot", o.screenshot);
    }

    std::unique_ptr<GlfwWindowContext> window =
        GlfwWindowContext::create(o.windowSize.x, o.windowSize.y, "pcfscope", true);
    Viewer viewer(o, *window, std::move(lesson));
    InputBinding input(window->window(), viewer);
    for (const ScriptedInput& k : keys) {
        // As on screen, where every key lands on a composed frame: the step's pages are known,
        // so Right turns to a step's page 2 before it moves on.
        viewer.session().compose();
        if (k.click)
            viewer.clickFrame(*k.click);
        else
            viewer.press(k.key);
    }

    if (o.benchFrames > 0) {
        benchFrames(viewer.session(), *window, o.benchFrames);
    } else if (!o.screenshot.empty()) {
        writeScreenshot(viewer, *window, o.screenshot, outputs);
    } else {
        runInteractive(viewer, *window);
    }
    return 0;
}

}  // namespace pcf
