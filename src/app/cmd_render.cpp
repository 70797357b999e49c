// pcfscope render: one frame, headless (EGL); --raw writes the intermediate buffers as EXR.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

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

struct RenderCommandOptions {
    RenderOptions render;
    std::string out;
    std::string rawDir;
    bool force = false;
    int timeRepeats = 0;
    bool verbose = false;
};

int runRender(const RenderCommandOptions& o) {
    // Every check first: nothing is written unless all of it can be.
    RenderSettings settings = o.render.settings();
    Scene scene = o.render.loadScene();
    if (o.out.empty() && o.rawDir.empty())
        throw UsageError("render needs -o FILE.png or --raw DIR");
    requireIntRange("--time", o.timeRepeats, 0, 10000);
    OutputFiles outputs(o.force);
    outputs.addInput("--scene-file", o.render.sceneFile);
    // A lesson step that shows a chart: -o writes that chart, as `export` shows it in the
    // scene's place (--raw still writes the scene's buffers at the step's settings).
    std::string chart;
    std::optional<LessonStep> chartStep;
    std::optional<glm::mat4> lessonFit;
    if (!o.render.lesson.empty()) {
        std::string path = resolveLesson(o.render.lesson);
        outputs.addInput("--lesson", path);
        Lesson lesson = loadLessonChecked(path);
        const LessonStep& step = lesson.steps[static_cast<size_t>(o.render.lessonStep - 1)];
        // The step's texel grid (origin_shift, snap), as the viewer and export render it.
        lessonFit = lessonShadowFit(lesson.scene, step.settings, settings.mapSize);
        if (!step.chart.empty()) {
            chartStep = step;
            chart = step.chart.substr(0, step.chart.rfind('#'));
            outputs.addInput("chart", chart);
        }
    }
    if (!o.out.empty()) {
        requireExtension("-o", o.out, ".png");
        outputs.add("-o", o.out);
    }
    std::string rawShadow, rawLightSpace, rawVisibility, rawPositions, rawReceiver, rawSettings;
    if (!o.rawDir.empty()) {
        std::filesystem::path dir(o.rawDir);
        outputs.addDirectory("--raw", dir);
        rawShadow = (dir / "shadowmap.exr").string();
        rawLightSpace = (dir / "lightspace.exr").string();
        rawVisibility = (dir / "visibility.exr").string();
        rawPositions = (dir / "positions.exr").string();
        rawReceiver = (dir / "dzduv.exr").string();
        rawSettings = (dir / "render.json").string();
        settings.writePositions = true;
        for (const std::string& p :
             {rawShadow, rawLightSpace, rawVisibility, rawPositions, rawReceiver, rawSettings}) {
            outputs.add("--raw", p);
        }
    }

    std::unique_ptr<GlContext> context = createHeadlessContext();
    SceneRenderer renderer(scene);
    if (lessonFit) renderer.setShadowClipFromWorld(*lessonFit);
    renderer.render(settings);
    if (o.verbose)
        std::fprintf(stderr, "pcfscope: rendered on %s\n", context->description().c_str());
    if (o.timeRepeats > 0) {
        TimingResult t = renderer.timeCameraPass(settings, o.timeRepeats);
        std::printf("camera pass (%s %s, %dx%d, map %d): median %.3f ms over %d draws (%s)\n",
                    std::string(methodInfo(settings.method).name).c_str(),
                    methodInfo(settings.method).usesKernel
                        ? ("N=" + std::to_string(settings.kernel)).c_str()
                        : "",
                    settings.frameSize.x, settings.frameSize.y, settings.mapSize, t.medianMs,
                    o.timeRepeats, t.timer.c_str());
    }
    glm::ivec2 size = renderer.frameSize();
    if (!o.out.empty()) {
        std::vector<uint8_t> rgba =
            chartStep ? drawStepChart(*chartStep, size) : renderer.readColour();
        writePngRgba8(o.out, size.x, size.y, rgba);
    }
    if (!o.rawDir.empty()) {
        writeDepthImage(rawShadow, renderer.readShadowMap());
        std::vector<float> ls = renderer.readLightSpace();
        writeExr(rawLightSpace, size.x, size.y, 4, ls, {"R", "G", "B", "A"});
        std::vector<float> vis = renderer.readVisibility();
        writeExr(rawVisibility, size.x, size.y, 1, vis, {"Y"});
        std::vector<float> pos = renderer.readPositions();
        writeExr(rawPositions, size.x, size.y, 4, pos, {"R", "G", "B", "A"});
        std::vector<float> receiver = renderer.readReceiver();
        writeExr(rawReceiver, size.x, size.y, 4, receiver, {"R", "G", "B", "A"});
        writeTextFile(rawSettings, rawSettingsJson(settings));
    }
    outputs.commit();
    // Say what was written, like export does (a silent success left users looking for it).
    std::string method = std::string(methodInfo(settings.method).name);
    if (!o.out.empty() && chartStep) {
        std::fprintf(stderr, "render: wrote %s (%dx%d, the chart of lesson step %d: %s)\n",
                     o.out.c_str(), size.x, size.y, o.render.lessonStep, chart.c_str());
    } else if (!o.out.empty()) {
        std::fprintf(stderr, "render: wrote %s (%dx%d, %s, map %d)\n", o.out.c_str(), size.x,
                     size.y, method.c_str(), settings.mapSize);
    }
    if (!o.rawDir.empty()) {
        std::fprintf(stderr, "render: wrote %s, %s, %s and %s\n", rawShadow.c_str(),
                     rawLightSpace.c_str(), rawVisibility.c_str(), rawPositions.c_str());
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
