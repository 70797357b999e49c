// pcfscope exercise: questions for a tutorial drawn from a lesson (app/exercise.h), written as a
// worksheet (the question frames, and worksheet.pdf to print them two to an A4 page) and a
// separate answer key (the answer frames, each item's shadow map, answers.json with each item's
// whole trace and the `trace` command that repeats it, and answers.pdf). The same seed gives the
// same files, byte for byte.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/exercise.h"
#include "app/frame_options.h"
#include "app/output_files.h"
#include "app/session.h"
#include "deck/deck.h"
#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "kernel/trace_json.h"
#include "lesson/lesson_pick.h"
#include "render/gl_context.h"
#include "render/image_io.h"

namespace pcf {

namespace {

namespace fs = std::filesystem;

struct ExerciseOptions {
    std::string lesson;
    int count = 8;
    std::uint64_t seed = 1;
    std::string outDir;
    std::string size = "1600x900";
    bool presentation = false;
    bool force = false;
};

std::string itemName(int k) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "item%02d", k);
    return buf;
}

std::string exact(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

// The `pcfscope trace` command that looks the item up again on its map: the filter's and the
// bias's settings that differ from trace's defaults, and the receiver's angle or plane where the
// bias reads them.
std::string traceCommand(const LessonSettings& s, const Trace& tr, const std::string& map,
                         float lightAngle) {
    std::string cmd = "pcfscope trace --map " + map + " --uv " + exact(tr.uv.x) + "," +
                      exact(tr.uv.y) + " --z " + exact(tr.z);
    const MethodInfo& info = methodInfo(s.method);
    ShadowSettings plain;
    for (const ParamInfo& p : allParams()) {
        if (p.group == ParamGroup::Map || p.key == "rotate" || p.key == "light_size") continue;
        if (p.key == "kernel" && !info.usesKernel) continue;
        if (p.key == "radius" && !info.usesRadius) continue;
        bool always = p.key == "method" || p.key == "bias";
        if (!always && settingText(p, s) == settingText(p, plain)) continue;
        cmd += " " + settingFlag(p.key) + " " + settingText(p, s);
    }
    if (s.depthFormat != TexelKind::D32F) {
        cmd += " --depth-format " + std::string(depthFormatName(s.depthFormat));
    }
    if (s.bias == BiasMode::Slope) cmd += " --angle " + exact(lightAngle);
    if (s.bias == BiasMode::ReceiverPlane) {
        cmd += " --dzduv " + exact(tr.dzduv.x) + "," + exact(tr.dzduv.y);
    }
    return cmd + " --json";
}

// The files of one item, relative to the output folder.
struct ItemFiles {
    std::vector<std::string> questions;  // worksheet/itemNN.png, -page2 ...
    std::vector<std::string> answers;    // answers/itemNN.png, -page2 ...
    std::string map;                     // answers/itemNN-map.exr
};

// Writes the frames of the phase on screen, its first page as `stem`.png, the rest -pageN.png;
// each goes on `sheet` (the worksheet's or the answer key's pages). Returns their names.
std::vector<std::string> writePages(Session& session, const fs::path& dir, const std::string& stem,
                                    OutputFiles& outputs, std::vector<DeckFrame>& sheet) {
    std::vector<std::string> names;
    glm::ivec2 size = session.frameSize();
    for (int page = 0; page < session.textPages(); ++page) {
        std::string name = page == 0 ? stem : stem + "-page" + std::to_string(page + 1);
        outputs.add("-o", dir / (name + ".png"));
        session.setTextPage(page);
        session.compose();
        writePngRgba8((dir / (name + ".png")).string(), size.x, size.y, session.readFrame());
        sheet.push_back({(dir / (name + ".png")).string(), session.stepJson(), ""});
        names.push_back((dir.filename() / (name + ".png")).string());
    }
    return names;
}

Json itemJson(const Session& session, int k, const ItemFiles& files) {
    const Trace& tr = *session.trace();
    FilledPredict f = *session.filledPredict();
    const LessonStep& step = session.lesson().steps[static_cast<size_t>(k - 1)];
    float angle = session.point() ? lightAngleDeg(session.scene(), *session.point()) : -1.0f;
    std::string map = fs::path(files.map).filename().string();
    return {{"item", k},
            {"title", step.title},
            {"question", f.ask},
            {"answer", f.answer},
            {"tolerance", EXERCISE_TOLERANCE},
            {"frames", {{"question", files.questions}, {"answer", files.answers}}},
            {"point",
             Json::array({jsonNumber(step.settings.point->x), jsonNumber(step.settings.point->y),
                          jsonNumber(step.settings.point->z)})},
            {"settings", paramsJson(step.settings, ParamSet::All)},
            {"lookup",
             {{"map", map},
              {"uv", Json::array({tr.uv.x, tr.uv.y})},
              {"z", tr.z},
              {"command", traceCommand(step.settings, tr, map, angle)}}},
            {"trace", traceJson(tr)}};
}

// Every file the exercise writes but the pages a frame may add, checked before any is made.
void planExerciseFiles(OutputFiles& outputs, const fs::path& dir, int count) {
    outputs.addDirectory("-o", dir / "worksheet");
    outputs.addDirectory("-o", dir / "answers");
    for (int k = 1; k <= count; ++k) {
        outputs.add("-o", dir / "worksheet" / (itemName(k) + ".png"));
        outputs.add("-o", dir / "answers" / (itemName(k) + ".png"));
        outputs.add("-o", dir / "answers" / (itemName(k) + "-map.exr"));
    }
    outputs.add("-o", dir / "answers" / "answers.json");
    outputs.add("-o", dir / "worksheet.pdf");
    outputs.add("-o", dir / "answers.pdf");
}

int runExercise(const ExerciseOptions& o) {
    glm::ivec2 size = parseSize("--size", o.size, {MIN_SESSION_SIZE});
    std::string path = resolveLesson(o.lesson);
    Lesson lesson = loadLessonChecked(path);
    if (o.count < 1 || o.count > MAX_EXERCISE_ITEMS) {
        throw UsageError("--count must be 1.." + std::to_string(MAX_EXERCISE_ITEMS) + ", got " +
                         std::to_string(o.count));
    }
    fs::path dir =
        o.outDir.empty() ? fs::path("pcfscope-exercise") / lesson.name : fs::path(o.outDir);
    OutputFiles outputs(o.force);
    outputs.addInput("LESSON", path);
    planExerciseFiles(outputs, dir, o.count);
    std::unique_ptr<GlContext> context = createHeadlessContext();
    Lesson items = makeExercise(lesson, o.count, o.seed);
    Session session(size, o.presentation);
    session.setLesson(items);
    Json list = Json::array();
    Deck worksheet{items.title + ": worksheet", {}}, answers{items.title + ": answers", {}};
    for (int k = 1; k <= o.count; ++k) {
        session.goToStep(k - 1);
        session.compose();
        if (!session.trace()) throw std::logic_error("exercise: an item's point has no lookup");
        ItemFiles files;
        files.questions =
            writePages(session, dir / "worksheet", itemName(k), outputs, worksheet.frames);
        session.setRevealed(true);
        session.compose();
        files.answers = writePages(session, dir / "answers", itemName(k), outputs, answers.frames);
        files.map = "answers/" + itemName(k) + "-map.exr";
        writeDepthImage((dir / files.map).string(), session.shadowMap());
        list.push_back(itemJson(session, k, files));
        std::fprintf(stderr, "exercise: %s (%d/%d)\n", itemName(k).c_str(), k, o.count);
    }
    Json key = {
        {"lesson", lesson.name}, {"title", items.title},         {"seed", o.seed},
        {"count", o.count},      {"frame_size", jsonPair(size)}, {"presentation", o.presentation},
        {"items", list}};
    writeTextFile((dir / "answers" / "answers.json").string(), jsonDump(key) + "\n");
    // To print: the questions, then the answers with the words and the trace's table.
    writePdfHandout(worksheet, (dir / "worksheet.pdf").string());
    writePdfHandout(answers, (dir / "answers.pdf").string());
    outputs.commit();
    std::fprintf(stderr, "exercise: %d items into %s (worksheet/, answers/)\n", o.count,
                 dir.string().c_str());
    return 0;
}

}  // namespace

Command addExerciseCommand(CLI::App& app) {
    auto o = std::make_shared<ExerciseOptions>();
    CLI::App* sub = app.add_subcommand(
        "exercise",
        "questions for a tutorial from a lesson: a worksheet of question frames and an answer key");
    addLessonArgument(sub, o->lesson)->required();
    sub->add_option("--count", o->count, "how many questions (1..32, default 8)");
    sub->add_option("--seed", o->seed,
                    "which questions: the same seed, the same files (default 1)");
    sub->add_option("-o,--out", o->outDir,
                    "output directory (default pcfscope-exercise/LESSON): worksheet/ and answers/");
    addFrameSizeOption(sub, o->size, "frame size", "default 1600x900");
    addPresentationFlag(sub, o->presentation);
    sub->add_flag("-f,--force", o->force, "overwrite existing files");
    return {sub, [o] { return runExercise(*o); }};
}

}  // namespace pcf
