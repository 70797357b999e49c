// pcfscope animate: a lesson step with one quantity swept across the frames (app/animation.h),
// as MP4 (H.264), animated GIF and numbered PNGs (each with its frame's JSON, as `export` writes
// it), headless, at the presentation floors unless --no-presentation. Videos are encoded into a
// scratch folder beside their final names and moved there only when complete, so an error, a
// full disk or Ctrl-C leaves no half video; PNGs are taken back like `export`'s.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/animation.h"
#include "app/cli_util.h"
#include "app/commands.h"
#include "app/compare_view.h"
#include "app/export.h"
#include "app/frame_files.h"
#include "app/frame_options.h"
#include "app/magnifier.h"
#include "app/output_files.h"
#include "app/render_options.h"
#include "app/session.h"
#include "base/memory_budget.h"
#include "base/work_estimate.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "render/gl_context.h"
#include "render/image_io.h"
#include "video/video_writer.h"

namespace pcf {

namespace {

namespace fs = std::filesystem;

struct AnimateOptions {
    std::string lesson;
    int step = 1;
    std::string sweep;  // empty: the step's own `animate`, else light
    bool snap = false;
    int frames = 120;
    int fps = 12;
    std::string size = "1280x720";
    bool presentation = true;  // the projector's floors: 22 px step text, 18 px numbers
    SettingOptions view;       // --shading: what the frames draw (ParamGroup::View)
    CLI::App* sub = nullptr;   // to ask which options were given
    bool sceneOnly = false;
    bool noTrace = false;
    bool magnify = false;
    std::string point;
    std::string compare = "auto";
    int compareKernel = 3;
    CLI::Option* compareKernelOption = nullptr;  // given or not
    std::vector<std::string> videos;
    std::string pngDir;
    bool force = false;
};

// --point X,Y,Z: the scene point the animation watches instead of the step's, on a surface the
// camera sees (lesson_pick.h: seenPoint, as a lesson's `point`).
std::optional<ScenePoint> pointOption(const Scene& scene, const std::string& text) {
    if (text.empty()) return std::nullopt;
    glm::vec3 p(0.0f);
    char tail = 0;
    if (std::sscanf(text.c_str(), "%f,%f,%f%c", &p.x, &p.y, &p.z, &tail) != 3 ||
        !std::isfinite(p.x + p.y + p.z)) {
        throw UsageError("--point expects X,Y,Z (world units), got '" + text + "'");
    }
    std::optional<ScenePoint> seen = seenPoint(scene, p);
    if (!seen) {
        throw UsageError("--point " + text + " is not on a surface the camera sees (within " +
                         "0.001; a click in `pcfscope view` prints a point)");
    }
    return seen;
}

// "--compare bias=none,constant,slope": a split view (compare_view.h), not a second curve.
bool isSplitCompare(const std::string& compare) { return compare.find('=') != std::string::npos; }

// The split view's spec, each part checked on the step's settings; UsageError in the option's
// words.
std::optional<CompareSpec> splitSpecOf(const AnimateOptions& o, const LessonSettings& step) {
    if (!isSplitCompare(o.compare)) return std::nullopt;
    try {
        CompareSpec spec = parseCompareSpec(o.compare);
        for (int i = 0; i < spec.parts(); ++i) comparePart(step, spec, i);
        return spec;
    } catch (const std::invalid_argument& e) {
        throw UsageError("--" + std::string(e.what()));
    }
}

// --compare-kernel given for a comparison that has no kernel (none, a split view, nearest) would
// change nothing: refused, not ignored.
int withCompareKernel(const AnimateOptions& o, int method) {
    if (o.compareKernelOption->count() == 0 || (method >= 0 && methodInfo(method).usesKernel)) {
        return method;
    }
    throw UsageError("--compare-kernel is for a comparison method with a kernel; " +
                     (method < 0 ? "--compare " + o.compare + " draws no second curve"
                                 : std::string(methodInfo(method).name) + " has none"));
}

// The comparison curve's method: a method id, or -1 for none. auto: defaultCompareMethod.
int compareMethodOf(const AnimateOptions& o, const LessonSettings& step) {
    if (o.compare == "none" || isSplitCompare(o.compare)) return withCompareKernel(o, -1);
    if (o.compare == "auto") return withCompareKernel(o, defaultCompareMethod(step.method));
    std::optional<int> m = methodFromName(o.compare);
    if (!m) {
        throw UsageError("--compare: unknown method '" + o.compare + "' (known: auto, none, " +
                         methodNameList() + ")");
    }
    if (!kernelFits(*m, o.compareKernel)) {
        throw UsageError("--compare-kernel " + std::to_string(o.compareKernel) + ": " + o.compare +
                         " takes " + kernelSizesText(*m));
    }
    return withCompareKernel(o, *m);
}

struct VideoOut {
    fs::path final;
    VideoFormat format;
    std::unique_ptr<StagingDir> staging;
    std::unique_ptr<VideoWriter> writer;
};

void progressBar(int done, int total, double seconds) {
    constexpr int WIDTH = 30;
    int filled = done * WIDTH / total;
    std::string bar(static_cast<size_t>(filled), '#');
    bar.append(static_cast<size_t>(WIDTH - filled), '.');
    std::fprintf(stderr, "\ranimate [%s] %d/%d  %.1f frames/s", bar.c_str(), done, total,
                 seconds > 0.0 ? done / seconds : 0.0);
    if (done == total) std::fprintf(stderr, "\n");
    setProgressLineOpen(done != total);  // an error meanwhile starts a line of its own
}

// Checks every output before any work and opens the videos under their scratch names.
std::vector<VideoOut> planVideos(OutputFiles& outputs, const AnimateOptions& o, glm::ivec2 size) {
    std::vector<VideoOut> videos;
    for (const std::string& v : o.videos) {
        std::optional<VideoFormat> format = videoFormatFromPath(v);
        if (!format) throw UsageError("-o " + v + ": a video ends in .mp4 or .gif");
        if (auto problem = videoSizeProblem(*format, size.x, size.y)) {
            throw UsageError("--size " + o.size + ": " + *problem);
        }
        videos.push_back({fs::path(v), *format, nullptr, nullptr});
    }
    outputs.addEach("-o", {o.videos.begin(), o.videos.end()});
    for (VideoOut& v : videos) {
        fs::path dir = v.final.parent_path().empty() ? fs::path(".") : v.final.parent_path();
        // Known to the interrupt cleanup, which removes the scratch folder made in it below.
        outputs.addDirectory("-o", dir);
        v.staging = std::make_unique<StagingDir>(dir, "animate");
        v.writer = std::make_unique<VideoWriter>(v.staging->path() / v.final.filename(), v.format,
                                                 size.x, size.y, o.fps);
    }
    return videos;
}

// The frames' stems in the --png folder (STEM-0001 ...), each a .png and a .json.
std::vector<std::string> planPngs(OutputFiles& outputs, const AnimateOptions& o,
                                  const std::string& stem) {
    std::vector<std::string> stems;
    if (o.pngDir.empty()) return stems;
    outputs.addDirectory("--png", o.pngDir);
    for (int k = 0; k < o.frames; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "-%04d", k + 1);
        stems.push_back((fs::path(o.pngDir) / (stem + name)).string());
        outputs.add("--png", stems.back() + ".png");
        outputs.add("--png", stems.back() + ".json");
    }
    return stems;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void checkSplitSize(const AnimateOptions& o, glm::ivec2 size, int parts) {
    if (auto problem = compareFrameProblem(size, parts, o.presentation, !o.noTrace)) {
        throw UsageError("--size " + o.size + ": " + *problem);
    }
}

// The session at the step, watching `point`, magnified when asked; with a split view (returned)
// it is the scene alone at a part's size: the sweep moves it as the parts see it.
std::unique_ptr<CompareView> setUpView(Session& session, const AnimateOptions& o,
                                       const std::optional<CompareSpec>& split,
                                       const std::optional<ScenePoint>& point) {
    std::unique_ptr<CompareView> view;
    if (split) {
        view = std::make_unique<CompareView>(session.frameSize(), o.presentation, *split);
        view->setTraceBand(!o.noTrace);
        session.setSceneOnly(true);
        session.setFrameSize(view->partSceneSize());
    }
    if (point) session.pinPoint(*point);
    if (o.magnify) magnifySession(session, session.scene().camera);
    return view;
}

AnimationOptions animationOptions(const AnimateOptions& o, AnimationSweep sweep, int compare) {
    AnimationOptions ao;
    ao.sweep = sweep;
    ao.frames = o.frames;
    ao.snap = o.snap;
    ao.flicker = !o.noTrace;
    ao.compareMethod = compare;
    ao.compareKernel = o.compareKernel;
    return ao;
}

bool given(const AnimateOptions& o, const char* option) {
    return o.sub != nullptr && o.sub->count(option) > 0;
}

// Without --sweep a step that is an animation plays its own `animate` (its sweep, range, frames,
// snap and rate; --frames and --fps still choose), any other step the light sweep. nullopt: the
// options' own sweep.
std::optional<AnimationOptions> stepsOwnSweep(AnimateOptions& o, const LessonStep& step,
                                              int compare) {
    if (!o.sweep.empty() || !step.animate) {
        if (o.sweep.empty()) o.sweep = "light";
        return std::nullopt;
    }
    AnimationOptions ao = stepAnimationOptions(step);
    o.sweep = std::string(animationSweepName(ao.sweep));
    if (given(o, "--frames")) ao.frames = o.frames;
    o.frames = ao.frames;
    if (!given(o, "--fps")) o.fps = step.animate->fps;
    if (given(o, "--snap")) ao.snap = o.snap;
    ao.flicker = !o.noTrace;
    ao.compareMethod = compare;
    ao.compareKernel = o.compareKernel;
    return ao;
}

// The encoders' own time and what the frames waited for them, seconds.
struct EncodeTimes {
    double encode = 0.0;
    double waited = 0.0;
};

// Finishes every encoder and moves each video to its final name (with the other outputs).
EncodeTimes finishVideos(std::vector<VideoOut>& videos, OutputFiles& outputs) {
    std::vector<std::pair<fs::path, fs::path>> moves;
    EncodeTimes t;
    for (VideoOut& v : videos) {
        v.writer->finish();
        t.encode += v.writer->encodeSeconds();
        t.waited += v.writer->waitSeconds();
        moves.emplace_back(v.staging->path() / v.final.filename(), v.final);
    }
    outputs.commitMoves(moves);
    return t;
}

// Each frame composed, read back and encoded; memory measured with /usr/bin/time (peak RSS): a
// GIF or PNGs 125 MB and 50 bytes a pixel (1280x720 to 2560x1440), an MP4 130 bytes a pixel
// more once libx264's look-ahead holds its frames (320 MB at 1280x720 from 40 frames on).
WorkEstimate animateEstimate(const AnimateOptions& o, glm::ivec2 size) {
    bool mp4 = std::any_of(o.videos.begin(), o.videos.end(), [](const std::string& v) {
        return videoFormatFromPath(v) == VideoFormat::Mp4;
    });
    double pixels = static_cast<double>(size.x) * size.y;
    WorkEstimate w;
    w.what = std::to_string(o.frames) + " frames of " + std::to_string(size.x) + "x" +
             std::to_string(size.y);
    w.frameNs = pixels * o.frames * RENDER_NS_PER_PIXEL_FRAME;
    w.fixedSeconds = 2.0;
    w.bytes = memoryEstimate(160 * MIB, mp4 ? 190 : 60, size.x, size.y);
    return w;
}

// The step shows the scene (no sweep moves a chart), and --snap goes with the sweep it snaps:
// options that would change nothing are refused, not ignored.
void checkSweptStep(const AnimateOptions& o, AnimationSweep sweep, const LessonStep& step) {
    if (o.snap && sweep != AnimationSweep::Light) {
        throw UsageError("--snap is for --sweep light (it snaps the creeping texel grid), not " +
                         o.sweep);
    }
    if (!step.chart.empty()) {
        throw UsageError("lesson step " + std::to_string(o.step) +
                         " shows a chart, which no sweep moves; animate a step that shows the "
                         "scene");
    }
}

// What runAnimate makes, every option checked before anything is made.
struct AnimatePlan {
    std::string path;
    Lesson lesson;
    glm::ivec2 size{0, 0};
    std::optional<CompareSpec> split;
    std::optional<ScenePoint> point;
    AnimationOptions animation;
    std::string stem;
};

AnimatePlan planAnimate(AnimateOptions& o) {
    AnimatePlan p;
    p.size = parseSize("--size", o.size, {MIN_SESSION_SIZE});
    if (!o.sweep.empty() && !animationSweepFromName(o.sweep)) {
        throw UsageError("--sweep: unknown sweep '" + o.sweep +
                         "' (known: " + std::string(ANIMATION_SWEEP_NAMES) + ")");
    }
    requireIntRange("--frames", o.frames, 2, 3600);
    requireIntRange("--fps", o.fps, 1, 60);
    p.path = resolveLesson(o.lesson);
    p.lesson = loadLessonChecked(p.path);
    requireIntRange("--step", o.step, 1, static_cast<int>(p.lesson.steps.size()));
    const LessonStep& step = p.lesson.steps[static_cast<size_t>(o.step - 1)];
    int compare = compareMethodOf(o, step.settings);
    std::optional<AnimationOptions> own = stepsOwnSweep(o, step, compare);
    p.animation = own ? *own : animationOptions(o, *animationSweepFromName(o.sweep), compare);
    checkSweptStep(o, p.animation.sweep, step);
    p.split = splitSpecOf(o, step.settings);
    p.point = pointOption(p.lesson.scene, o.point);
    if (p.split) checkSplitSize(o, p.size, p.split->parts());
    p.stem = frameStem(p.lesson.name, o.step) + "-" + o.sweep;
    if (o.videos.empty() && o.pngDir.empty())
        o.videos.push_back("pcfscope-frames/" + p.stem + ".mp4");
    return p;
}

// The frame the session (or the split view) composed, as JSON: `export`'s sidecar.
std::string frameJson(const Session& session, const CompareView* split) {
    return (split ? split->json() : session.stepJson()) + "\n";
}

int runAnimate(AnimateOptions o) {
    AnimatePlan plan = planAnimate(o);
    glm::ivec2 size = plan.size;
    announceWork("animate", animateEstimate(o, size), o.force);
    OutputFiles outputs(o.force);
    outputs.addInput("LESSON", plan.path);
    std::vector<std::string> pngs = planPngs(outputs, o, plan.stem);
    std::unique_ptr<GlContext> context = createHeadlessContext();
    std::vector<VideoOut> videos = planVideos(outputs, o, size);

    Session session(size, o.presentation);
    session.setLesson(plan.lesson);
    session.goToStep(o.step - 1);
    LessonSettings shown = session.settings();
    o.view.applyTo(shown, true);  // --shading, over the step's
    session.setSettings(shown);
    session.setSceneOnly(o.sceneOnly);
    std::unique_ptr<CompareView> splitView = setUpView(session, o, plan.split, plan.point);
    const AnimationOptions& ao = plan.animation;
    Animation animation = splitView ? Animation(session, ao, *splitView) : Animation(session, ao);

    // The PNGs and their JSON on a thread of their own (frame_files.h), as the videos are.
    FrameFiles pngWriter(2);
    auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < o.frames; ++k) {
        animation.composeFrame(k);
        std::vector<uint8_t> rgba = splitView ? splitView->readFrame() : session.readFrame();
        for (VideoOut& v : videos) v.writer->addFrame(rgba);
        if (!pngs.empty()) {
            const std::string& stem = pngs[static_cast<size_t>(k)];
            pngWriter.add(stem + ".png", size, std::move(rgba), stem + ".json",
                          frameJson(session, splitView.get()));
        }
        progressBar(k + 1, o.frames, secondsSince(start));
    }
    pngWriter.finish();
    EncodeTimes encoded = finishVideos(videos, outputs);  // commits every output
    double seconds = secondsSince(start);
    // The encoders and the PNG writer run on their own threads: their share of the time is what
    // the frames waited for them (a full queue, the final flush); their own time overlaps the
    // frames'.
    double waited = encoded.waited + pngWriter.waitSeconds();
    std::fprintf(stderr,
                 "animate: %d frames of %dx%d in %.2f s (%.1f frames/s; encoding and writing "
                 "%.2f s beside the frames, waited for %.2f s, %.0f %%)\n",
                 o.frames, size.x, size.y, seconds, o.frames / seconds,
                 encoded.encode + pngWriter.writeSeconds(), waited, 100.0 * waited / seconds);
    for (const VideoOut& v : videos) std::printf("%s\n", v.final.string().c_str());
    if (!o.pngDir.empty()) std::printf("%s\n", o.pngDir.c_str());
    return 0;
}

}  // namespace

Command addAnimateCommand(CLI::App& app) {
    auto o = std::make_shared<AnimateOptions>();
    CLI::App* sub = app.add_subcommand(
        "animate", "a lesson step with one quantity swept: MP4, GIF and numbered PNGs, no display");
    addLessonArgument(sub, o->lesson)->required();
    sub->add_option("--step", o->step, "the lesson step animated (default 1)");
    sub->add_option("--sweep", o->sweep,
                    "what moves: light (texel grid creeping 1/32 texel a frame), camera (1/6 pixel "
                    "a frame), sun (90 -> 2 deg), bias (0.0005 -> 0.064), map-size (32 -> 2048), "
                    "turn (the camera turned 0 -> 45 deg about the point); default: the step's "
                    "own `animate`, else light");
    sub->add_flag("--snap", o->snap, "light: the creeping grid snapped to whole texels");
    sub->add_option("--frames", o->frames, "frames (default 120, or the step's own `animate`'s)");
    sub->add_option("--fps", o->fps, "frames per second of the videos (default 12)");
    addFrameSizeOption(sub, o->size, "frame size", "default 1280x720; even for MP4");
    sub->add_flag("--presentation,!--no-presentation", o->presentation,
                  "presentation mode, the default: 22 px step text, 18 px numbers, thick lines, "
                  "for a projector; --no-presentation: the handout's smaller type");
    ShadowSettings defaults;
    o->view.addTo(sub, {ParamGroup::View}, defaults);
    o->sub = sub;
    sub->add_flag("--scene-only", o->sceneOnly, "the scene alone, without the inspector");
    sub->add_flag("--no-trace", o->noTrace, "no flicker trace");
    sub->add_option("--point", o->point,
                    "X,Y,Z: the scene point watched (ringed, traced) instead of the step's");
    addMagnifyFlag(sub, o->magnify);
    sub->add_option(
        "--compare", o->compare,
        "the flicker trace's second method (default auto: nearest, or pcf-gather 3 when the step's "
        "method is nearest; none: no second curve); or KEY=V1,V2[,V3] (bias=none,constant,slope): "
        "a split view of 2 or 3 parts, one curve each");
    o->compareKernelOption =
        sub->add_option("--compare-kernel", o->compareKernel, "its kernel size (default 3)");
    sub->add_option(
        "-o,--out", o->videos,
        "video files, .mp4 and/or .gif (default pcfscope-frames/LESSON-stepNN-SWEEP.mp4)");
    sub->add_option("--png", o->pngDir,
                    "also write the frames as numbered PNGs into this folder, each with its "
                    "frame's JSON (trace, layout, the text drawn) as `export` writes it");
    sub->add_flag("-f,--force", o->force,
                  "overwrite existing files; start work larger than the memory estimate says the "
                  "machine holds");
    return {sub, [o] { return runAnimate(*o); }};
}

}  // namespace pcf
