// pcfscope export: one annotated PNG per lesson step, plus the step's trace as JSON beside it,
// headless (EGL). The frames are the viewer's frames: the same Session composes both.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/animation.h"
#include "app/cli_util.h"
#include "app/commands.h"
#include "app/compare_view.h"
#include "app/export.h"
#include "app/frame_files.h"
#include "app/frame_options.h"
#include "app/live_keys.h"
#include "app/magnifier.h"
#include "app/render_options.h"
#include "app/session.h"
#include "base/memory_budget.h"
#include "base/work_estimate.h"
#include "deck/deck.h"
#include "render/gl_context.h"
#include "render/image_io.h"
#include "video/video_writer.h"

namespace pcf {

namespace {

struct ExportOptions {
    std::string lesson;
    std::string outDir;
    std::string size = "1600x900";
    std::string steps;
    std::string keys;
    bool presentation = false;
    std::string compare;
    bool magnify = false;
    bool force = false;
    std::vector<std::string> decks;  // --deck html, --deck pdf
    std::string handout;             // --handout pdf
};

// The frame size a handout's frames have (deck/deck.h: two to an A4 page, the words beneath).
constexpr glm::ivec2 HANDOUT_FRAME{1600, 900};

// --deck and --handout: the files beside the frames, DIR/LESSON.html, .pdf, -handout.pdf.
void planDecks(OutputFiles& outputs, ExportPlan& plan, const ExportOptions& o,
               const std::string& lessonName, glm::ivec2 size) {
    std::filesystem::path base = std::filesystem::path(plan.dir) / lessonName;
    for (const std::string& d : o.decks) {
        std::string& path = d == "html" ? plan.htmlDeck : plan.pdfDeck;
        path = base.string() + "." + d;
        outputs.add("--deck", path);
    }
    if (o.handout.empty()) return;
    if (size != HANDOUT_FRAME || o.presentation) {
        throw UsageError(
            "--handout is made of the 1600x900 frames (two to an A4 page, the words "
            "beneath): drop --size and --presentation");
    }
    plan.handout = base.string() + "-handout.pdf";
    outputs.add("--handout", plan.handout);
}

// "2-4" or "3" -> 1-based inclusive range, checked against the lesson's step count.
glm::ivec2 parseSteps(const std::string& text, int count) {
    if (text.empty()) return {1, count};
    size_t dash = text.find('-');
    glm::ivec2 r;
    try {
        size_t used = 0;
        r.x = std::stoi(text.substr(0, dash), &used);
        if (used != (dash == std::string::npos ? text.size() : dash))
            throw std::invalid_argument("");
        r.y = r.x;
        if (dash != std::string::npos) {
            r.y = std::stoi(text.substr(dash + 1), &used);
            if (used != text.size() - dash - 1) throw std::invalid_argument("");
        }
    } catch (const std::exception&) {
        throw UsageError("--steps expects A-B or A, got '" + text + "'");
    }
    if (r.x < 1 || r.y > count || r.x > r.y) {
        throw UsageError("--steps " + text + " is out of range (the lesson has steps 1.." +
                         std::to_string(count) + ")");
    }
    return r;
}

// --keys: what changes every step the same way (settings keys, X, clicks); the keys that move
// between steps or pages are refused, since export writes every step and page (--steps chooses).
std::vector<ScriptedInput> exportKeys(const std::string& text) {
    std::vector<ScriptedInput> keys = parseScriptedInput(text);
    std::istringstream tokens(text);
    for (const ScriptedInput& k : keys) {
        std::string token;
        tokens >> token;
        if (k.click || isLiveKey(k.key)) continue;
        throw UsageError("export --keys: '" + token +
                         "' does not change a setting or the marks (export writes every step "
                         "and page; --steps chooses them)");
    }
    return keys;
}

// The frames: a step's page at least (a step split into pages writes more; those are known only
// once rendered), each composed and written as PNG. Peak memory measured with /usr/bin/time:
// 225 MB and 25 bytes a pixel (1280x720 to 2560x1440); 40 leaves room for a step's pages.
WorkEstimate exportEstimate(glm::ivec2 size, glm::ivec2 steps) {
    double pixels = static_cast<double>(size.x) * size.y;
    int frames = steps.y - steps.x + 1;
    WorkEstimate w;
    w.what = "at least " + std::to_string(frames) + " frames of " + std::to_string(size.x) + "x" +
             std::to_string(size.y);
    w.frameNs = pixels * frames * RENDER_NS_PER_PIXEL_FRAME;
    w.fixedSeconds = 1.0;
    w.bytes = memoryEstimate(240 * MIB, 40, size.x, size.y);
    return w;
}

int runExport(const ExportOptions& o) {
    glm::ivec2 size = parseSize("--size", o.size, {MIN_SESSION_SIZE});
    std::string path = resolveLesson(o.lesson);
    Lesson lesson = loadLessonChecked(path);  // checked before anything is made
    glm::ivec2 steps = parseSteps(o.steps, static_cast<int>(lesson.steps.size()));
    std::vector<ScriptedInput> keys = exportKeys(o.keys);
    std::string dir = o.outDir.empty() ? "pcfscope-frames/" + lesson.name : o.outDir;
    announceWork("export", exportEstimate(size, steps), o.force);
    OutputFiles outputs(o.force);
    outputs.addInput("LESSON", path);
    for (const LessonStep& step : lesson.steps) outputs.addInput("chart", step.chart);
    ExportPlan plan = planExport(outputs, dir, lesson, steps);
    plan.keys = keys;
    plan.magnify = o.magnify;
    planExtras(outputs, plan, lesson, {size, o.presentation}, o.compare);
    planDecks(outputs, plan, o, lesson.name, size);
    exportFrames(lesson, plan, size, o.presentation, true, &outputs);
    outputs.commit();
    return 0;
}

}  // namespace

std::string frameStem(const std::string& lessonName, int step) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "-step%02d", step);
    return lessonName + buf;
}

ExportPlan planExport(OutputFiles& outputs, const std::string& dir, const Lesson& lesson,
                      glm::ivec2 steps) {
    const std::string& lessonName = lesson.name;
    ExportPlan plan;
    plan.dir = dir;
    plan.steps = steps;
    outputs.addDirectory("-o", dir);
    for (int s = steps.x; s <= steps.y; ++s) {
        std::string stem = (std::filesystem::path(dir) / frameStem(lessonName, s)).string();
        outputs.add("-o", stem + ".png");
        outputs.add("-o", stem + ".json");
        // A predict step's answer: STEM-reveal.png (+ .json) after its question's frames.
        if (lesson.steps[static_cast<size_t>(s - 1)].predict) {
            outputs.add("-o", stem + "-reveal.png");
            outputs.add("-o", stem + "-reveal.json");
        }
        plan.stems.push_back(stem);
    }
    // A step's extra pages are only known once it is rendered, but page files already in the
    // folder (STEM-pageN.png/.json from an earlier export) are known now: refused here, before
    // any frame is rendered, as the step files are (with --force they are overwritten as well).
    std::error_code ec;
    std::vector<std::filesystem::path> stale;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        std::string name = entry.path().filename().string();
        for (int s = steps.x; s <= steps.y; ++s) {
            std::string stem = frameStem(lessonName, s);
            if (name.starts_with(stem + "-page") || name.starts_with(stem + "-reveal-page")) {
                stale.push_back(entry.path());
            }
        }
    }
    std::sort(stale.begin(), stale.end());
    for (const std::filesystem::path& page : stale) outputs.add("-o", page);
    return plan;
}

namespace {

// The MP4s of the planned steps that are animations; sets plan.videos.
void planStepVideos(OutputFiles& outputs, ExportPlan& plan, const Lesson& lesson, glm::ivec2 size) {
    plan.videos = true;
    for (int s = plan.steps.x; s <= plan.steps.y; ++s) {
        if (!lesson.steps[static_cast<size_t>(s - 1)].animate) continue;
        if (auto problem = videoSizeProblem(VideoFormat::Mp4, size.x, size.y)) {
            throw UsageError("--size: step " + std::to_string(s) +
                             " is an animation, written as MP4: " + *problem);
        }
        outputs.add("-o", plan.stems[static_cast<size_t>(s - plan.steps.x)] + ".mp4");
    }
}

// plan.compares: `all` for every step, else each step's own `compare`, each checked on the step's
// settings and the frame's size.
void planStepCompares(OutputFiles& outputs, ExportPlan& plan, const Lesson& lesson,
                      const ExtrasFrame& frame, const CompareSpec& all) {
    plan.compares.clear();
    for (int s = plan.steps.x; s <= plan.steps.y; ++s) {
        const LessonStep& step = lesson.steps[static_cast<size_t>(s - 1)];
        CompareSpec spec = all.empty() ? step.compare : all;
        try {
            for (int i = 0; i < spec.parts(); ++i) comparePart(step.settings, spec, i);
        } catch (const std::invalid_argument& e) {
            throw UsageError("--" + std::string(e.what()) + " (at step " + std::to_string(s) + ")");
        }
        if (!spec.empty()) {
            // Said with the step it is about: one step's compare refused a whole export.
            if (auto problem =
                    compareFrameProblem(frame.size, spec.parts(), frame.presentation, false)) {
                std::string whose = all.empty() ? "step " + std::to_string(s) + "'s compare (" +
                                                      compareSpecText(spec) + ")"
                                                : "--compare at step " + std::to_string(s);
                throw UsageError("--size " + std::to_string(frame.size.x) + "x" +
                                 std::to_string(frame.size.y) + ": " + whose + ": " + *problem +
                                 " (a larger --size, or --steps without that step)");
            }
            const std::string& stem = plan.stems[static_cast<size_t>(s - plan.steps.x)];
            outputs.add("--compare", stem + "-compare.png");
            outputs.add("--compare", stem + "-compare.json");
        }
        plan.compares.push_back(std::move(spec));
    }
}

}  // namespace

void planExtras(OutputFiles& outputs, ExportPlan& plan, const Lesson& lesson,
                const ExtrasFrame& frame, const std::string& compare) {
    planStepVideos(outputs, plan, lesson, frame.size);

    CompareSpec all;
    if (!compare.empty()) {
        try {
            all = parseCompareSpec(compare);
        } catch (const std::invalid_argument& e) {
            throw UsageError("--" + std::string(e.what()));
        }
    }
    planStepCompares(outputs, plan, lesson, frame, all);
}

namespace {

// A step that is an animation (`animate = {...}`) as an MP4 at `path`: its frames as the viewer
// plays them (app/animation.h), with the flicker trace; the session is put back afterwards.
// Returns the frames written.
int writeStepVideo(Session& session, const std::string& path) {
    const LessonStep& step = session.lesson().steps[static_cast<size_t>(session.step())];
    AnimationOptions ao = stepAnimationOptions(step);
    glm::ivec2 size = session.frameSize();
    VideoWriter writer(path, VideoFormat::Mp4, size.x, size.y, step.animate->fps);
    session.setTextPage(0);
    Animation animation(session, ao);
    for (int k = 0; k < ao.frames; ++k) {
        animation.composeFrame(k);
        writer.addFrame(session.readFrame());
    }
    animation.restore();
    writer.finish();
    return ao.frames;
}

// The keys on a step just gone to, each on a composed frame as in the viewer (a click lands where
// the frame drew the scene). The marks start shown on every step, so X hides them on each.
void applyKeys(Session& session, const std::vector<ScriptedInput>& keys) {
    session.setMarkers(true);
    for (const ScriptedInput& k : keys) {
        session.compose();
        if (k.click)
            session.clickFrame(*k.click);
        else
            pressLiveKey(session, k.key);
    }
}

// The step's split view beside its frame (STEM-compare.png + .json), following `session`: the
// deck's frame.
DeckFrame writeCompare(const Session& session, const CompareSpec& spec, const std::string& stem,
                       glm::ivec2 size, bool presentation) {
    CompareView view(size, presentation, spec);
    view.follow(session);
    view.compose();
    writePngRgba8(stem + "-compare.png", size.x, size.y, view.readFrame());
    writeTextFile(stem + "-compare.json", view.json() + "\n");
    return {stem + "-compare.png", view.json(), ""};
}

// Every frame an export writes, in order: the deck's frames (deck/deck.h). The PNG and JSON go
// to the writer's thread (frame_files.h: PNG encoding is a third of an export's CPU time).
struct FrameLog {
    FrameFiles& files;
    std::vector<DeckFrame> written;

    void write(const std::string& stem, glm::ivec2 size, std::vector<uint8_t> rgba,
               std::string json) {
        written.push_back({stem + ".png", json, ""});
        files.add(stem + ".png", size, std::move(rgba), stem + ".json", std::move(json));
    }
};

// The rest of a step's text, when it pages at this size: one more frame per page, STEM-pageN
// (added to `outputs`; none without it). The step's first page is written. Returns the frames.
int writeLaterPages(Session& session, FrameLog& writer, const std::string& stem,
                    OutputFiles* outputs, bool progress) {
    int written = 0;
    glm::ivec2 size = session.frameSize();
    for (int page = 1; outputs && page < session.textPages(); ++page) {
        std::string more = stem + "-page" + std::to_string(page + 1);
        outputs->add("-o", more + ".png");
        outputs->add("-o", more + ".json");
        session.setTextPage(page);
        session.compose();
        writer.write(more, size, session.readFrame(), session.stepJson() + "\n");
        if (progress)
            std::fprintf(stderr, "export: %s (page %d)\n", (more + ".png").c_str(), page + 1);
        ++written;
    }
    return written;
}

}  // namespace

namespace {

// One export: the session, what it has written and its counts.
struct ExportRun {
    const ExportPlan& plan;
    Session& session;
    FrameLog& writer;
    OutputFiles* outputs;
    bool progress;
    int extraFrames = 0;
    int videoFrames = 0;  // the frames of the steps' MP4s
};

// Step `s`, gone to and composed: its frames (its pages; a predict step's question's, then its
// answer's), its split view and its video, each on the deck in that order.
void exportStep(ExportRun& run, int s) {
    Session& session = run.session;
    glm::ivec2 size = session.frameSize();
    const std::string& stem = run.plan.stems[static_cast<size_t>(s - run.plan.steps.x)];
    size_t index = static_cast<size_t>(s - run.plan.steps.x);
    size_t first = run.writer.written.size();
    run.writer.write(stem, size, session.readFrame(), session.stepJson() + "\n");
    if (run.progress) {
        std::fprintf(stderr, "export: %s (%d/%d)\n", (stem + ".png").c_str(),
                     s - run.plan.steps.x + 1, run.plan.steps.y - run.plan.steps.x + 1);
    }
    run.extraFrames += writeLaterPages(session, run.writer, stem, run.outputs, run.progress);
    if (session.predictStep()) {
        session.setRevealed(true);
        session.compose();
        run.writer.write(stem + "-reveal", size, session.readFrame(), session.stepJson() + "\n");
        if (run.progress) std::fprintf(stderr, "export: %s\n", (stem + "-reveal.png").c_str());
        run.extraFrames +=
            1 + writeLaterPages(session, run.writer, stem + "-reveal", run.outputs, run.progress);
    }
    if (index < run.plan.compares.size() && !run.plan.compares[index].empty()) {
        run.writer.written.push_back(
            writeCompare(session, run.plan.compares[index], stem, size, session.presentation()));
        ++run.extraFrames;
    }
    if (run.plan.videos && session.lesson().steps[static_cast<size_t>(s - 1)].animate) {
        run.videoFrames += writeStepVideo(session, stem + ".mp4");
        run.writer.written[first].video = stem + ".mp4";
        if (run.progress) std::fprintf(stderr, "export: %s\n", (stem + ".mp4").c_str());
    }
}

// The decks and the handout the plan asks for, from the frames written.
void writeDecks(const ExportPlan& plan, const std::string& title,
                const std::vector<DeckFrame>& frames) {
    Deck deck{title, frames};
    if (!plan.htmlDeck.empty()) writeHtmlDeck(deck, plan.htmlDeck);
    if (!plan.pdfDeck.empty()) writePdfDeck(deck, plan.pdfDeck);
    if (!plan.handout.empty()) writePdfHandout(deck, plan.handout);
}

}  // namespace

void exportFrames(const Lesson& lesson, const ExportPlan& plan, glm::ivec2 size, bool presentation,
                  bool progress, OutputFiles* outputs) {
    std::unique_ptr<GlContext> context = createHeadlessContext();
    Session session(size, presentation);
    session.setLesson(lesson);
    auto start = std::chrono::steady_clock::now();
    // A frame's PNG and JSON are written on a thread of their own while the next frame renders
    // (frame_files.h).
    FrameFiles files(1);
    FrameLog writer{files, {}};
    ExportRun run{plan, session, writer, outputs, progress};
    const Camera wide = session.scene().camera;
    for (int s = plan.steps.x; s <= plan.steps.y; ++s) {
        // Each step's point is found in the lesson's own view, then magnified.
        if (plan.magnify) session.setCamera(wide);
        session.goToStep(s - 1);
        if (plan.magnify) magnifySession(session, wide);
        applyKeys(session, plan.keys);
        session.compose();
        exportStep(run, s);
    }
    files.finish();
    writeDecks(plan, session.lesson().title, writer.written);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int frames = plan.steps.y - plan.steps.x + 1 + run.extraFrames + run.videoFrames;
    // Kept before announced: an interrupt after the line below must not take back the frames
    // it names.
    if (outputs) outputs->commit();
    if (progress) {
        // The videos' share is named only when the lesson has animation steps.
        std::string inVideos = run.videoFrames > 0
                                   ? " (" + std::to_string(run.videoFrames) + " of them in videos)"
                                   : "";
        std::fprintf(stderr, "export: %d frames of %dx%d%s in %.2f s (%.1f frames/s) into %s\n",
                     frames, size.x, size.y, inVideos.c_str(), seconds, frames / seconds,
                     plan.dir.c_str());
    }
}

Command addExportCommand(CLI::App& app) {
    auto o = std::make_shared<ExportOptions>();
    CLI::App* sub = app.add_subcommand(
        "export", "write a lesson's annotated frames (PNG + JSON trace per step), no display");
    addLessonArgument(sub, o->lesson)->required();
    sub->add_option("-o,--out", o->outDir, "output directory (default pcfscope-frames/LESSON)");
    addFrameSizeOption(sub, o->size, "frame size", "default 1600x900, the viewer's");
    sub->add_option("--steps", o->steps, "steps to write, A-B or A (default all)");
    sub->add_option("--keys", o->keys,
                    "on every step: the viewer's settings keys, x and click:X,Y (\"v v t\")");
    addPresentationFlag(sub, o->presentation);
    sub->add_option("--compare", o->compare,
                    "also a split view of every step, STEM-compare.png: KEY=V1,V2[,V3] "
                    "(bias=none,constant,slope); without it a step's own `compare` is written");
    addMagnifyFlag(sub, o->magnify);
    sub->add_option("--deck", o->decks,
                    "also the frames as one deck, DIR/LESSON.html (self-contained: arrow keys, "
                    "notes N, trace T) or DIR/LESSON.pdf (a page per frame); may be given twice")
        ->check(CLI::IsMember({"html", "pdf"}));
    sub->add_option("--handout", o->handout,
                    "also DIR/LESSON-handout.pdf: A4, the 1600x900 frames two to a page with the "
                    "words and the trace's table beneath")
        ->check(CLI::IsMember({"pdf"}));
    sub->add_flag("-f,--force", o->force,
                  "overwrite existing frames; start work larger than the memory estimate says "
                  "the machine holds");
    return {sub, [o] { return runExport(*o); }};
}

}  // namespace pcf
