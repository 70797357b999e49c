// pcfscope view [LESSON]: the window.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/export.h"
#include "app/frame_options.h"
#include "app/session.h"
#include "app/viewer.h"
#include "render/render_settings.h"

namespace pcf {

namespace {

struct ViewCommandOptions {
    std::string lesson = "1";
    std::string size = "1600x900";
    std::string keys;
    std::string screenshot;
    bool presentation = false;
    bool force = false;
    int benchFrames = 0;
    CLI::Option* benchFramesOption = nullptr;  // given or not
};

int runView(const ViewCommandOptions& o) {
    ViewerOptions v;
    v.lesson = resolveLesson(o.lesson);
    v.windowSize = parseSize("--size", o.size, {MIN_SESSION_SIZE});
    v.keys = o.keys;
    v.screenshot = o.screenshot;
    v.presentation = o.presentation;
    v.force = o.force;
    v.benchFrames = o.benchFrames;
    // Given, it times at least one frame: 0 opened the window as if it had not been given.
    if (o.benchFramesOption->count() > 0) {
        requireIntRange("--bench-frames", o.benchFrames, 1, 10000);
    }
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland)) {
        throw UsageError("view needs a display (DISPLAY is not set); use `pcfscope export " +
                         o.lesson + "` to write the frames instead");
    }
    try {
        return runViewer(v);
    } catch (const std::runtime_error& e) {
        std::string what = e.what();
        if (what.rfind("no display", 0) == 0) throw UsageError(what);
        throw;
    }
}

}  // namespace

int runMainJob() {
    std::vector<std::string> lessons = builtInLessons();
    if (lessons.empty()) throw UsageError(std::string("no lessons found in ") + lessonDirectory());
    const char* display = std::getenv("DISPLAY");
    if (display && *display) {
        ViewerOptions v;
        v.lesson = lessons.front();
        try {
            return runViewer(v);
        } catch (const std::runtime_error& e) {
            std::fprintf(stderr, "pcfscope: %s; exporting instead\n", e.what());
        }
    }
    // No display: export lesson 1 into a folder of its own, never over an earlier one.
    Lesson lesson = loadLessonChecked(lessons.front());
    std::string dir = "pcfscope-frames/" + lesson.name;
    std::error_code ec;
    for (int k = 2; std::filesystem::exists(dir, ec); ++k) {
        dir = "pcfscope-frames/" + lesson.name + "-" + std::to_string(k);
    }
    glm::ivec2 steps(1, static_cast<int>(lesson.steps.size()));
    OutputFiles outputs(false);
    ExportPlan plan = planExport(outputs, dir, lesson, steps);
    exportFrames(lesson, plan, {1600, 900}, false, true, &outputs);
    outputs.commit();
    std::printf("No display: lesson '%s' exported as %d frames into %s/\n", lesson.title.c_str(),
                steps.y, dir.c_str());
    return 0;
}

Command addViewCommand(CLI::App& app) {
    auto o = std::make_shared<ViewCommandOptions>();
    CLI::App* sub =
        app.add_subcommand("view", "the lesson in a window: pick a scene point, step through");
    addLessonArgument(sub, o->lesson);
    addFrameSizeOption(sub, o->size, "window size", "default 1600x900");
    sub->add_option("--keys", o->keys,
                    "replay keys first: GLFW names and click:X,Y (frame pixels), space-separated");
    sub->add_option("--screenshot", o->screenshot, "write the frame after --keys to PNG, quit");
    addPresentationFlag(sub, o->presentation);
    sub->add_flag("-f,--force", o->force, "let --screenshot overwrite an existing file");
    o->benchFramesOption = sub->add_option(
        "--bench-frames", o->benchFrames,
        "time this many frames (1..10000, after --keys), print the median frame time, quit");
    // The keys, from the table the help overlay (H) draws (overlay/inspector_keys.cpp).
    std::string keys = "\nKeys in the window:\n";
    for (const auto& [key, what] : viewerKeys()) {
        keys += "  " + key + std::string(key.size() < 18 ? 18 - key.size() : 1, ' ') + what + "\n";
    }
    sub->footer(keys);
    return {sub, [o] { return runView(*o); }};
}

}  // namespace pcf
