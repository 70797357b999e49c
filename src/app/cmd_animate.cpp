// pcfscope animate: a lesson step with one quantity swept across the frames (app/animation.h),
// as MP4 (H.264), animated GIF and numbered PNGs, headless. Videos are encoded into a scratch
// folder beside their final names and moved there only when complete, so an error, a full disk
// or Ctrl-C leaves no half video; PNGs are taken back like `export`'s.
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
#include "app/frame_options.h"
#include "app/magnifier.h"
#include "app/output_files.h"
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
    std::string sweep = "light";
    bool snap = false;
    int frames = 120;
    int fps = 12;
    std::string size = "1280x720";
    bool presentation = false;
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

std::vector<std::string> planPngs(OutputFiles& outputs, const AnimateOptions& o,
                                  const std::string& stem) {
    std::vector<std::string> pngs;
    if (o.pngDir.empty()) return pngs;
    outputs.addDirectory("--png", o.pngDir);
    for (int k = 0; k < o.frames; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "-%04d.png", k + 1);
        pngs.push_back((fs::path(o.pngDir) / (stem + name)).string());
        outputs.add("--png", pngs.back());
    }
    return pngs;
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

// The step exists and shows the scene (no sweep moves a chart), and --snap goes with the sweep
// it snaps: options that would change nothing are refused, not ignored.
void checkSweptStep(const AnimateOptions& o, AnimationSweep sweep, const Lesson& lesson) {
    if (o.snap && sweep != AnimationSweep::Light) {
        throw UsageError("--snap is for --sweep light (it snaps the creeping texel grid), not " +
                         o.sweep);
    }
    requireIntRange("--step", o.step, 1, static_cast<int>(lesson.steps.size()));
    if (!lesson.steps[static_cast<size_t>(o.step - 1)].chart.empty()) {
        throw UsageError("lesson step " + std::to_string(o.step) +
                         " shows a chart, which no sweep moves; animate a step that shows the "
                         "scene");
    }
}

int runAnimate(AnimateOptions o) {
    glm::ivec2 size = parseSize("--size", o.size, {MIN_SESSION_SIZE});
    std::optional<AnimationSweep> sweep = animationSweepFromName(o.sweep);
    if (!sweep) {
        throw UsageError("--sweep: unknown sweep '" + o.sweep +
                         "' (known: " + std::string(ANIMATION_SWEEP_NAMES) + ")");
    }
    requireIntRange("--frames", o.frames, 2, 3600);
    requireIntRange("--fps", o.fps, 1, 60);
    std::string path = resolveLesson(o.lesson);
    Lesson lesson = loadLessonChecked(path);
    checkSweptStep(o, *sweep, lesson);
    const LessonSettings& stepSettings = lesson.steps[static_cast<size_t>(o.step - 1)].settings;
    int compare = compareMethodOf(o, stepSettings);
    std::optional<CompareSpec> split = splitSpecOf(o, stepSettings);
    std::optional<ScenePoint> point = pointOption(lesson.scene, o.point);
    if (split) checkSplitSize(o, size, split->parts());
    std::string stem = frameStem(lesson.name, o.step) + "-" + o.sweep;
    if (o.videos.empty() && o.pngDir.empty())
        o.videos.push_back("pcfscope-frames/" + stem + ".mp4");

    announceWork("animate", animateEstimate(o, size), o.force);
    OutputFiles outputs(o.force);
    outputs.addInput("LESSON", path);
    std::vector<std::string> pngs = planPngs(outputs, o, stem);
    std::unique_ptr<GlContext> context = createHeadlessContext();
    std::vector<VideoOut> videos = planVideos(outputs, o, size);

    Session session(size, o.presentation);
    session.loadLesson(path);
    session.goToStep(o.step - 1);
    session.setSceneOnly(o.sceneOnly);
    std::unique_ptr<CompareView> splitView = setUpView(session, o, split, point);
    AnimationOptions ao = animationOptions(o, *sweep, compare);
    Animation animation = splitView ? Animation(session, ao, *splitView) : Animation(session, ao);

    auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < o.frames; ++k) {
        animation.composeFrame(k);
        std::vector<uint8_t> rgba = splitView ? splitView->readFrame() : session.readFrame();
        for (VideoOut& v : videos) v.writer->addFrame(rgba);
        if (!pngs.empty()) writePngRgba8(pngs[static_cast<size_t>(k)], size.x, size.y, rgba);
        progressBar(k + 1, o.frames, secondsSince(start));
    }
    EncodeTimes encoded = finishVideos(videos, outputs);
    double encode = encoded.encode, waited = encoded.waited;
    double seconds = secondsSince(start);
    // The encoders run on their own threads: their share of the time is what the frames waited
    // for them (a full queue, the final flush); their own time overlaps the frames'.
    std::fprintf(stderr,
                 "animate: %d frames of %dx%d in %.2f s (%.1f frames/s; encoding %.2f s beside "
                 "the frames, waited for %.2f s, %.0f %%)\n",
                 o.frames, size.x, size.y, seconds, o.frames / seconds, encode, waited,
                 100.0 * waited / seconds);
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
                    "a frame), sun (90 -> 2 deg), bias (0.0005 -> 0.064), map-size (32 -> 2048)");
    sub->add_flag("--snap", o->snap, "light: the creeping grid snapped to whole texels");
    sub->add_option("--frames", o->frames, "frames (default 120)");
    sub->add_option("--fps", o->fps, "frames per second of the videos (default 12)");
    addFrameSizeOption(sub, o->size, "frame size", "default 1280x720; even for MP4");
    addPresentationFlag(sub, o->presentation);
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
    sub->add_option("--png", o->pngDir, "also write the frames as numbered PNGs into this folder");
    sub->add_flag("-f,--force", o->force,
                  "overwrite existing files; start work larger than the memory estimate says the "
                  "machine holds");
    return {sub, [o] { return runAnimate(*o); }};
}

}  // namespace pcf
