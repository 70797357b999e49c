// pcfscope render: one frame, headless (EGL); --raw writes the intermediate buffers as EXR.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/magnifier.h"
#include "app/output_files.h"
#include "app/render_options.h"
#include "app/session.h"
#include "base/memory_budget.h"
#include "kernel/methods.h"
#include "kernel/trace_json.h"
#include "lesson/lesson_pick.h"
#include "measure/cascade_density.h"
#include "render/gl_context.h"
#include "render/image_io.h"
#include "render/scene_renderer.h"
#include "scene/cascade_fit.h"

namespace pcf {

namespace {

struct RenderCommandOptions {
    RenderOptions render;
    std::string out;
    std::string rawDir;
    bool force = false;
    int timeRepeats = 0;
    bool verbose = false;
};

// The chart a lesson step shows in the scene's place, and the step's texel grid.
struct LessonRender {
    std::string chart;  // the chart's name, without its '#' fragment
    std::optional<LessonStep> chartStep;
    std::optional<glm::mat4> fit;
    // The step's pinned point where the frame shows it, as the viewer and export render it: the
    // camera's sub-pixel jitter and the point's own lookup at its pixel (lesson_pick.h).
    std::optional<CameraPick> pick;
    // The camera the step is seen through: a `magnify` step's close-up (magnifier.h: stepCamera).
    std::optional<Camera> camera;
    // The camera the cascades are fitted to: the lesson's own, whatever the step is seen through.
    std::optional<Camera> cascadeCamera;
};

// The lesson's step (-o writes its chart, as `export` shows it in the scene's place; --raw
// still writes the scene's buffers at the step's settings); its files join `outputs`' inputs.
LessonRender lessonRenderOf(const RenderCommandOptions& o, const RenderSettings& settings,
                            OutputFiles& outputs) {
    LessonRender out;
    if (o.render.lesson.empty()) return out;
    std::string path = resolveLesson(o.render.lesson);
    outputs.addInput("--lesson", path);
    Lesson lesson = loadLessonChecked(path);
    const LessonStep& step = lesson.steps[static_cast<size_t>(o.render.lessonStep - 1)];
    // The step's texel grid (origin_shift, snap) and pinned point, as the viewer and export
    // render it (step_view.h), with the settings rendered (the step's, or flags over them).
    LessonSettings s = step.settings;
    static_cast<ShadowSettings&>(s) = settings;
    std::optional<ScenePoint> point = stepPoint(lesson.scene, s);
    Scene seen = lesson.scene;
    seen.camera = stepCamera(lesson.scene, s, point, settings.frameSize);
    // The cascades stay fitted to the lesson's camera (a close-up or a frozen view moves away).
    StepView view = stepView(seen, s, point, settings.frameSize, std::nullopt, lesson.scene.camera);
    out.camera = seen.camera;
    out.cascadeCamera = lesson.scene.camera;
    out.fit = view.fit;
    out.pick = view.pick;
    if (!step.chart.empty()) {
        out.chartStep = step;
        out.chart = step.chart.substr(0, step.chart.rfind('#'));
        outputs.addInput("chart", out.chart);
    }
    return out;
}

// The files of a --raw folder; nextReceiver only with a blend band (empty without).
struct RawFiles {
    std::string shadow, lightSpace, visibility, positions, normals, receiver, settings;
    std::string nextReceiver;
};

// The --raw folder's files, each added to `outputs`; with cascades blended (`band`) the next
// cascade's receiver plane too.
RawFiles rawFilesIn(const std::string& rawDir, bool band, OutputFiles& outputs) {
    std::filesystem::path dir(rawDir);
    outputs.addDirectory("--raw", dir);
    RawFiles raw{(dir / "shadowmap.exr").string(),  (dir / "lightspace.exr").string(),
                 (dir / "visibility.exr").string(), (dir / "positions.exr").string(),
                 (dir / "normals.exr").string(),    (dir / "dzduv.exr").string(),
                 (dir / "render.json").string(),    ""};
    if (band) raw.nextReceiver = (dir / "next_dzduv.exr").string();
    for (const std::string& p : {raw.shadow, raw.lightSpace, raw.visibility, raw.positions,
                                 raw.normals, raw.receiver, raw.settings, raw.nextReceiver}) {
        if (!p.empty()) outputs.add("--raw", p);
    }
    return raw;
}

// What rendering `settings` into `raw` (empty: no --raw) may take. Measured peaks of
// `render --raw -o` (box-on-plane, map 1024): 339 MB at 1024x1024, 686 MB at 2048x2048, so 113
// bytes a pixel over about 220 MB; the encoded EXR held in memory while it is written adds up
// to 16 more. The next cascade's receiver target of --raw adds 16 bytes a pixel (measured at
// 1024x1024: 386 -> 403 MB); its read-back and next_dzduv.exr, made after the other files',
// did not raise the peak (long-ground, 4 cascades, band 0.3: 429 -> 445 MB). The map: depth,
// its read-back, its EXR, each as many times as it has layers (cascades).
std::uint64_t renderMemory(const RenderSettings& settings, const RawFiles& raw) {
    std::uint64_t pixelBytes = 130 + (raw.shadow.empty() ? 0u : 16u);
    return memoryEstimate(256 * MIB, pixelBytes, settings.frameSize.x, settings.frameSize.y) +
           memoryEstimate(0, 12 * settings.cascades, settings.mapSize, settings.mapSize);
}

// --time: the camera pass's median over `repeats` draws, on stdout.
void printCameraTiming(SceneRenderer& renderer, const RenderSettings& settings, int repeats) {
    TimingResult t = renderer.timeCameraPass(settings, repeats);
    std::printf("camera pass (%s %s, %dx%d, map %d): median %.3f ms over %d draws (%s)\n",
                std::string(methodInfo(settings.method).name).c_str(),
                methodInfo(settings.method).usesKernel
                    ? ("N=" + std::to_string(settings.kernel)).c_str()
                    : "",
                settings.frameSize.x, settings.frameSize.y, settings.mapSize, t.medianMs, repeats,
                t.timer.c_str());
}

// render.json with a cascaded map's measured texel density added to each of its "map" cascades
// (measure/cascade_density.h); as it is for a map of one layer.
std::string withCascadeDensities(const std::string& json, const SceneRenderer& renderer,
                                 const std::vector<float>& lightSpace,
                                 const std::vector<float>& positions) {
    if (renderer.mapSpec().layers.size() < 2) return json;
    Json j = Json::parse(json);
    const Camera& camera = renderer.cascadeCamera();
    std::vector<CascadeDensity> d =
        cascadeDensities(lightSpace, positions, renderer.frameSize(), renderer.mapSpec(), camera);
    // The camera as the camera pass measured view depths with (its uniforms): what `verify`
    // chooses each pixel's cascade again by.
    glm::vec3 dir = cameraViewDirWs(camera);
    j["map"]["cascade_camera"] = {
        {"eye",
         {jsonNumber(camera.eyeWs.x), jsonNumber(camera.eyeWs.y), jsonNumber(camera.eyeWs.z)}},
        {"view_dir", {jsonNumber(dir.x), jsonNumber(dir.y), jsonNumber(dir.z)}}};
    for (size_t k = 0; k < d.size(); ++k) {
        Json& cascade = j["map"]["cascades"][k];
        cascade["texels_per_pixel_max"] = jsonNumber(static_cast<float>(d[k].texelsPerPixelMax));
        cascade["texels_per_pixel_median"] =
            jsonNumber(static_cast<float>(d[k].texelsPerPixelMedian));
        cascade["texels_per_pixel_sv_max"] = jsonNumber(static_cast<float>(d[k].singularValueMax));
        cascade["texels_per_pixel_sv_median"] =
            jsonNumber(static_cast<float>(d[k].singularValueMedian));
        cascade["pixels_measured"] = d[k].pixels;
    }
    return jsonDump(j) + "\n";
}

// The intermediate buffers of the rendered frame, as EXR, and its settings as JSON.
void writeRawBuffers(SceneRenderer& renderer, const RawFiles& raw, const RenderSettings& settings,
                     glm::ivec2 size) {
    writeDepthImage(raw.shadow, renderer.readShadowMap());
    std::vector<float> ls = renderer.readLightSpace();
    writeExr(raw.lightSpace, size.x, size.y, 4, ls, {"R", "G", "B", "A"});
    std::vector<float> vis = renderer.readVisibility();
    writeExr(raw.visibility, size.x, size.y, 1, vis, {"Y"});
    std::vector<float> pos = renderer.readPositions();
    writeExr(raw.positions, size.x, size.y, 4, pos, {"R", "G", "B", "A"});
    std::vector<float> normals = renderer.readNormals();
    writeExr(raw.normals, size.x, size.y, 4, normals, {"R", "G", "B", "A"});
    std::vector<float> receiver = renderer.readReceiver();
    writeExr(raw.receiver, size.x, size.y, 4, receiver, {"R", "G", "B", "A"});
    if (!raw.nextReceiver.empty()) {
        writeExr(raw.nextReceiver, size.x, size.y, 4, renderer.readNextReceiver(),
                 {"R", "G", "B", "A"});
    }
    writeTextFile(raw.settings,
                  withCascadeDensities(
                      settingsJson(settings, renderer.pcfParams(settings), renderer.mapSpec()),
                      renderer, ls, pos));
}

// Says what was written, like export does (a silent success left users looking for it).
void sayRendered(const RenderCommandOptions& o, const LessonRender& lesson,
                 const RenderSettings& settings, const RawFiles& raw, glm::ivec2 size) {
    std::string method = std::string(methodInfo(settings.method).name);
    if (!o.out.empty() && lesson.chartStep) {
        std::fprintf(stderr, "render: wrote %s (%dx%d, the chart of lesson step %d: %s)\n",
                     o.out.c_str(), size.x, size.y, o.render.lessonStep, lesson.chart.c_str());
    } else if (!o.out.empty()) {
        std::fprintf(stderr, "render: wrote %s (%dx%d, %s, map %d)\n", o.out.c_str(), size.x,
                     size.y, method.c_str(), settings.mapSize);
    }
    if (!o.rawDir.empty()) {
        std::fprintf(stderr, "render: wrote %s, %s, %s and %s\n", raw.shadow.c_str(),
                     raw.lightSpace.c_str(), raw.visibility.c_str(), raw.positions.c_str());
    }
}

int runRender(const RenderCommandOptions& o) {
    // Every check first: nothing is written unless all of it can be.
    RenderSettings settings = o.render.settings();
    Scene scene = o.render.loadScene();
    checkLightSize(scene.light, settings);
    if (o.out.empty() && o.rawDir.empty())
        throw UsageError("render needs -o FILE.png or --raw DIR");
    requireIntRange("--time", o.timeRepeats, 0, 10000);
    OutputFiles outputs(o.force);
    outputs.addInput("--scene-file", o.render.sceneFile);
    LessonRender lesson = lessonRenderOf(o, settings, outputs);
    if (lesson.camera) scene.camera = *lesson.camera;
    checkCascades(scene, settings);
    if (lesson.chartStep && !o.out.empty() &&
        std::min(settings.frameSize.x, settings.frameSize.y) < MIN_CHART_SIDE) {
        throw UsageError("--size " + o.render.size + ": lesson step " +
                         std::to_string(o.render.lessonStep) + " shows a chart, which needs at " +
                         "least " + std::to_string(MIN_CHART_SIDE) + " x " +
                         std::to_string(MIN_CHART_SIDE) + " pixels");
    }
    if (!o.out.empty()) {
        requireExtension("-o", o.out, ".png");
        outputs.add("-o", o.out);
    }
    RawFiles raw;
    if (!o.rawDir.empty()) {
        raw = rawFilesIn(o.rawDir, settings.cascades > 1 && settings.cascadeBlend > 0.0f, outputs);
        settings.writePositions = true;
    }

    requireMemory("--size " + std::to_string(settings.frameSize.x) + "x" +
                      std::to_string(settings.frameSize.y),
                  renderMemory(settings, raw), o.force);
    std::unique_ptr<GlContext> context = createHeadlessContext();
    SceneRenderer renderer(scene);
    if (lesson.fit) renderer.setShadowClipFromWorld(*lesson.fit);
    renderer.setPick(lesson.pick);
    renderer.setCascadeCamera(lesson.cascadeCamera);
    renderer.render(settings);
    if (o.verbose)
        std::fprintf(stderr, "pcfscope: rendered on %s\n", context->description().c_str());
    if (o.timeRepeats > 0) printCameraTiming(renderer, settings, o.timeRepeats);
    glm::ivec2 size = renderer.frameSize();
    if (!o.out.empty()) {
        std::vector<uint8_t> rgba =
            lesson.chartStep ? drawStepChart(*lesson.chartStep, size) : renderer.readColour();
        writePngRgba8(o.out, size.x, size.y, rgba);
    }
    if (!o.rawDir.empty()) writeRawBuffers(renderer, raw, settings, size);
    outputs.commit();
    sayRendered(o, lesson, settings, raw, size);
    return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<RenderCommandOptions>();
    CLI::App* sub = app.add_subcommand("render", "render one frame headless (no display needed)");
    o->render.picture = true;  // --shading: what the frame draws
    o->render.cascades = true;
    o->render.addTo(sub, "");
    sub->add_option("-o,--out", o->out, "the frame as PNG");
    sub->add_option("--raw", o->rawDir,
                    "write shadowmap.exr, lightspace.exr (u, v, ref, receiver), "
                    "visibility.exr, positions.exr (world xyz, drawn), normals.exr (the normal "
                    "facing the camera, cos(theta) to the light), dzduv.exr (dz/du, dz/dv of "
                    "the receiver plane, z before bias, receiver), with --cascade-blend "
                    "next_dzduv.exr (the same in the next cascade) and render.json (the "
                    "settings, the light's clip matrix) into DIR");
    sub->add_flag("-f,--force", o->force,
                  "overwrite existing output files; start work larger than the memory estimate "
                  "says the machine holds");
    sub->add_option("--time", o->timeRepeats,
                    "time the camera pass over this many draws and print the median");
    sub->add_flag("-v,--verbose", o->verbose, "say which GL driver rendered");
    return {sub, [o] { return runRender(*o); }};
}

}  // namespace pcf
