// pcfscope render: one frame, headless (EGL); --raw writes the intermediate buffers as EXR.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/output_files.h"
#include "app/render_options.h"
#include "app/session.h"
#include "kernel/methods.h"
#include "kernel/trace_json.h"
#include "render/gl_context.h"
#include "render/image_io.h"
#include "render/scene_renderer.h"

namespace pcf {

namespace {

// What `pcfscope verify` needs to repeat the lookups of a --raw folder: the method and its
// parameters, the map's format (fixed-point clamps D_ref), the precision model, and the bias
// mode (receiver-plane, soft and interpolated change each tap's comparison; dzduv.exr holds the
// receiver planes).
std::string rawSettingsJson(const RenderSettings& s) {
    Json j = {{"method", methodInfo(s.method).name},
              {"kernel", s.kernel},
              {"radius", jsonNumber(s.radius)},
              {"rotate", s.rotatePerPixel},
              {"weights", weightsName(s.weights)},
              {"sigma", jsonNumber(s.sigma)},
              {"precision", precisionName(s.precision)},
              {"depth_format", depthFormatName(s.depthFormat)},
              {"map_size", s.mapSize},
              {"bias", biasModeName(s.bias)},
              {"soft_scale", jsonNumber(s.softScale)},
              {"rpdb_max", jsonNumber(s.rpdbMax)}};
    return jsonDump(j) + "\n";
}

// The CSV a chart step draws: its `chart` without the "#acne" that names a stability chart.
std::string chartCsvPath(const LessonStep& step) {
    return step.chart.substr(0, step.chart.rfind('#'));
}

struct RenderCommandOptions {
    RenderOptions render;
    std::string out;
    std::string rawDir;
    bool force = false;
    int timeRepeats = 0;
    bool verbose = false;
};

// The files of a --raw folder.
struct RawPaths {
    std::string shadow, lightSpace, visibility, positions, receiver, settings;
    std::vector<std::string> all() const {
        return {shadow, lightSpace, visibility, positions, receiver, settings};
    }
};

RawPaths rawPaths(const std::filesystem::path& dir) {
    return {(dir / "shadowmap.exr").string(),  (dir / "lightspace.exr").string(),
            (dir / "visibility.exr").string(), (dir / "positions.exr").string(),
            (dir / "dzduv.exr").string(),      (dir / "render.json").string()};
}

void writeRaw(const RawPaths& raw, SceneRenderer& renderer, const RenderSettings& settings) {
    glm::ivec2 size = renderer.frameSize();
    writeDepthImage(raw.shadow, renderer.readShadowMap());
    writeExr(raw.lightSpace, size.x, size.y, 4, renderer.readLightSpace(), {"R", "G", "B", "A"});
    writeExr(raw.visibility, size.x, size.y, 1, renderer.readVisibility(), {"Y"});
    writeExr(raw.positions, size.x, size.y, 4, renderer.readPositions(), {"R", "G", "B", "A"});
    writeExr(raw.receiver, size.x, size.y, 4, renderer.readReceiver(), {"R", "G", "B", "A"});
    writeTextFile(raw.settings, rawSettingsJson(settings));
}

// A lesson step that shows a chart: -o writes that chart, as `export` shows it in the scene's
// place (--raw still writes the scene's buffers at the step's settings). The lesson and the
// chart's CSV are the outputs' inputs (never overwritten).
std::optional<LessonStep> chartStepOf(const RenderCommandOptions& o, OutputFiles& outputs) {
    if (o.render.lesson.empty()) return std::nullopt;
    std::string path = resolveLesson(o.render.lesson);
    outputs.addInput("--lesson", path);
    Lesson lesson = loadLessonChecked(path);
    const LessonStep& step = lesson.steps[static_cast<size_t>(o.render.lessonStep - 1)];
    if (step.chart.empty()) return std::nullopt;
    outputs.addInput("chart", chartCsvPath(step));
    return step;
}

void printTiming(SceneRenderer& renderer, const RenderSettings& settings, int repeats) {
    TimingResult t = renderer.timeCameraPass(settings, repeats);
    const MethodInfo& m = methodInfo(settings.method);
    std::string kernel = m.usesKernel ? "N=" + std::to_string(settings.kernel) : "";
    std::printf("camera pass (%s %s, %dx%d, map %d): median %.3f ms over %d draws (%s)\n",
                std::string(m.name).c_str(), kernel.c_str(), settings.frameSize.x,
                settings.frameSize.y, settings.mapSize, t.medianMs, repeats, t.timer.c_str());
}

int runRender(const RenderCommandOptions& o) {
    // Every check first: nothing is written unless all of it can be.
    RenderSettings settings = o.render.settings();
    Scene scene = o.render.loadScene();
    if (o.out.empty() && o.rawDir.empty())
        throw UsageError("render needs -o FILE.png or --raw DIR");
    requireIntRange("--time", o.timeRepeats, 0, 10000);
    OutputFiles outputs(o.force);
    outputs.addInput("--scene-file", o.render.sceneFile);
    std::optional<LessonStep> chartStep = chartStepOf(o, outputs);
    if (!o.out.empty()) {
        requireExtension("-o", o.out, ".png");
        outputs.add("-o", o.out);
    }
    RawPaths raw;
    if (!o.rawDir.empty()) {
        outputs.addDirectory("--raw", o.rawDir);
        raw = rawPaths(o.rawDir);
        settings.writePositions = true;
        for (const std::string& p : raw.all()) outputs.add("--raw", p);
    }

    std::unique_ptr<GlContext> context = createHeadlessContext();
    SceneRenderer renderer(scene);
    renderer.render(settings);
    if (o.verbose)
        std::fprintf(stderr, "pcfscope: rendered on %s\n", context->description().c_str());
    if (o.timeRepeats > 0) printTiming(renderer, settings, o.timeRepeats);
    glm::ivec2 size = renderer.frameSize();
    if (!o.out.empty()) {
        std::vector<uint8_t> rgba =
            chartStep ? drawStepChart(*chartStep, size) : renderer.readColour();
        writePngRgba8(o.out, size.x, size.y, rgba);
    }
    if (!o.rawDir.empty()) writeRaw(raw, renderer, settings);
    outputs.commit();
    // Say what was written, like export does (a silent success left users looking for it).
    std::string method = std::string(methodInfo(settings.method).name);
    if (!o.out.empty() && chartStep) {
        std::fprintf(stderr, "render: wrote %s (%dx%d, the chart of lesson step %d: %s)\n",
                     o.out.c_str(), size.x, size.y, o.render.lessonStep,
                     chartCsvPath(*chartStep).c_str());
    } else if (!o.out.empty()) {
        std::fprintf(stderr, "render: wrote %s (%dx%d, %s, map %d)\n", o.out.c_str(), size.x,
                     size.y, method.c_str(), settings.mapSize);
    }
    if (!o.rawDir.empty()) {
        std::fprintf(stderr, "render: wrote %s, %s, %s and %s\n", raw.shadow.c_str(),
                     raw.lightSpace.c_str(), raw.visibility.c_str(), raw.positions.c_str());
    }
    return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<RenderCommandOptions>();
    CLI::App* sub = app.add_subcommand("render", "render one frame headless (no display needed)");
    o->render.addTo(sub, "");
    sub->add_option("-o,--out", o->out, "the frame as PNG");
    sub->add_option("--raw", o->rawDir,
                    "write shadowmap.exr, lightspace.exr (u, v, ref, receiver), "
                    "visibility.exr, positions.exr (world xyz, drawn), dzduv.exr (dz/du, "
                    "dz/dv of the receiver plane, z before bias, receiver) and render.json "
                    "(method, format, precision) into DIR");
    sub->add_flag("-f,--force", o->force, "overwrite existing output files");
    sub->add_option("--time", o->timeRepeats,
                    "time the camera pass over this many draws and print the median");
    sub->add_flag("-v,--verbose", o->verbose, "say which GL driver rendered");
    return {sub, [o] { return runRender(*o); }};
}

}  // namespace pcf
