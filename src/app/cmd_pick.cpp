// pcfscope pick LESSON --step S --pixel X,Y: the scene point a click at frame pixel (X, Y) of the
// step's frame would pin, printed as the viewer prints it ("pixel (x, y): point = [...]"), ready
// to paste into a lesson as its `point`. No window: the step is set up as the viewer sets it up
// (its camera, its magnifier close-up, an animation step on its first frame) and the click goes
// through the same Session::clickFrame.
#include <cstdio>
#include <memory>
#include <string>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/frame_options.h"
#include "app/session.h"
#include "app/step_player.h"
#include "render/gl_context.h"

namespace pcf {

namespace {

struct PickOptions {
    std::string lesson;
    int step = 1;
    std::string pixel;
    std::string size = "1600x900";
    bool presentation = false;
};

int runPick(const PickOptions& o) {
    glm::ivec2 size = parseSize("--size", o.size, {MIN_SESSION_SIZE});
    glm::ivec2 pixel = parseIvec2("--pixel", o.pixel);
    std::string path = resolveLesson(o.lesson);
    Lesson lesson = loadLessonChecked(path);
    int steps = static_cast<int>(lesson.steps.size());
    requireIntRange("--step", o.step, 1, steps);
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y) {
        throw UsageError("--pixel " + o.pixel + " is outside the " + std::to_string(size.x) + "x" +
                         std::to_string(size.y) + " frame");
    }
    std::unique_ptr<GlContext> context = createHeadlessContext();
    Session session(size, o.presentation);
    session.setLesson(lesson);
    StepPlayer player(session);
    session.goToStep(o.step - 1);
    player.afterChange();  // as the viewer arrives on a step: an animation on its first frame
    // A click lands on the pixel's centre, as the viewer's scripted click:X,Y does.
    if (!session.clickFrame(glm::vec2(pixel) + 0.5f)) {
        Rect scene = session.stepLayout().scene;
        throw UsageError(
            session.sceneShown()
                ? "--pixel " + o.pixel + " is not on the scene (step " + std::to_string(o.step) +
                      "'s scene spans x " + std::to_string(static_cast<int>(scene.x)) + ".." +
                      std::to_string(static_cast<int>(scene.right()) - 1) + ", y " +
                      std::to_string(static_cast<int>(scene.y)) + ".." +
                      std::to_string(static_cast<int>(scene.bottom()) - 1) + " at this size)"
                : "step " + std::to_string(o.step) + " shows a chart: a click picks nothing there");
    }
    const std::optional<ScenePoint>& point = session.point();
    if (!point) {
        throw UsageError("--pixel " + o.pixel + ": no surface under it (the sky)");
    }
    std::printf("pixel (%d, %d): %s\n", session.pixel().x, session.pixel().y,
                pointKeyText(point->posWs).c_str());
    return 0;
}

}  // namespace

Command addPickCommand(CLI::App& app) {
    auto o = std::make_shared<PickOptions>();
    CLI::App* sub = app.add_subcommand(
        "pick", "the scene point a click on a step's frame pins, as a lesson's point = [x, y, z]");
    addLessonArgument(sub, o->lesson)->required();
    sub->add_option("--step", o->step, "the step (1-based), default 1");
    sub->add_option("--pixel", o->pixel, "X,Y: the frame pixel clicked, from the top left")
        ->required();
    addFrameSizeOption(sub, o->size, "frame size", "default 1600x900, the viewer's");
    addPresentationFlag(sub, o->presentation);
    return {sub, [o] { return runPick(*o); }};
}

}  // namespace pcf
