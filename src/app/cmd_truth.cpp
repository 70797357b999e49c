// pcfscope truth: the exact shadow of a scene by ray casting (measure/ground_truth.h), as an
// EXR of visibility and its error bound per pixel, rows top-down like every image pcfscope writes.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/output_files.h"
#include "app/render_options.h"
#include "base/memory_budget.h"
#include "measure/ground_truth.h"
#include "measure/ground_truth_conics.h"
#include "measure/light_visibility.h"
#include "render/image_io.h"
#include "scene/presets.h"

namespace pcf {

namespace {

struct TruthCommandOptions {
    std::string scene;
    std::string sceneFile;
    std::string size = "1280x720";
    int spp = DEFAULT_TRUTH_SPP;
    int threads = 0;
    // Read as a double, so that a value below float's range is refused as given, not as 0.
    double bound = DEFAULT_TRUTH_TARGET_BOUND;
    // The light's size where given (--light-size, --light-radius: the parameter table's).
    SettingOptions light;
    bool mask = false;
    std::string out;
    bool force = false;
};

// The smallest --bound: a visibility near 1 is a float, whose steps there are 6e-8; a bound of
// 1e-6 is 16 of them, and nothing finer is meaningful (1e-300 was a float 0).
constexpr double MIN_TRUTH_BOUND = 1.0e-6;

// The options parseSize and the scene loading do not check.
void checkTruthOptions(const TruthCommandOptions& o) {
    requireIntRange("--spp", o.spp, 1, MAX_TRUTH_SPP);
    requireIntRange("--threads", o.threads, 0, 1024);
    if (!(o.bound >= MIN_TRUTH_BOUND && o.bound <= 1.0)) {
        throw UsageError("--bound " + exactNumberText(o.bound) + " is out of range [" +
                         exactNumberText(MIN_TRUTH_BOUND) + ", 1]");
    }
    if (o.scene.empty() && o.sceneFile.empty()) {
        throw UsageError("truth needs --scene PRESET or --scene-file FILE");
    }
    if (!o.scene.empty() && !o.sceneFile.empty()) {
        throw UsageError("give --scene or --scene-file, not both");
    }
    if (o.out.empty()) throw UsageError("truth needs -o FILE.exr");
    requireExtension("-o", o.out, ".exr");
}

// The EXR's channels: visibility, bound, and with --mask the receiver mask.
void writeTruthExr(const std::string& path, const GroundTruth& truth, bool mask) {
    std::vector<std::string> channels{"visibility", "bound"};
    if (mask) channels.push_back("mask");
    size_t n = channels.size();
    std::vector<float> data(n * truth.pixelCount());
    for (size_t k = 0; k < truth.pixelCount(); ++k) {
        data[n * k] = truth.visibility[k];
        data[n * k + 1] = truth.bound[k];
        if (mask) data[n * k + 2] = truth.receiver[k] ? 1.0f : 0.0f;
    }
    writeExr(path, truth.size.x, truth.size.y, static_cast<int>(n), data, channels);
}

// A bound above the target is honest (what the pixel's scanlines reached), but not what was asked
// for: said, with how many pixels.
void sayAboveTarget(const GroundTruth& truth) {
    if (!(truth.targetBound > 0.0f) || !(truth.maxBound > truth.targetBound)) return;
    long above = std::count_if(truth.bound.begin(), truth.bound.end(),
                               [&](float b) { return b > truth.targetBound; });
    std::fprintf(stderr,
                 "truth: %ld pixels did not reach the target within %d scanlines; their bound "
                 "is what they reached\n",
                 above, MAX_TRUTH_SCANLINES);
}

// The objects whose edges are not conics (a sphere in another sphere's shadow, a spot's rim on
// a sphere: ground_truth_conics.h) keep the 1/16 px walk, whose bound assumes no thinner sliver:
// said, by name, so that no bound is taken for more than it is.
void sayWalkedObjects(const Scene& scene) {
    EdgeConics conics(scene, glm::dvec3(scene.camera.eyeWs));
    for (size_t k = 0; k < scene.objects.size(); ++k) {
        if (conics.exact(static_cast<int>(k))) continue;
        std::fprintf(stderr,
                     "truth: %s may take shadow edges that are not conics (another sphere's "
                     "shadow or a spot's rim on a sphere): its scanlines are walked at 1/16 px, "
                     "and its bound assumes no lit or unlit sliver thinner than that\n",
                     scene.objects[k].name.c_str());
    }
}

// --light-size (a directional light's angular diameter, degrees) or --light-radius (a spot
// light's radius, world units): the parameter table's, each for its own kind of light, 0 the
// scene light's; then a spot disk's casters are checked for what its truth can integrate.
void applyTruthLightSize(const TruthCommandOptions& o, Scene& scene) {
    ShadowSettings given;
    o.light.applyTo(given, true);
    if (std::optional<ParamProblem> why = lightSizeProblem(scene.light, given)) {
        throw UsageError(cliWords(*why));
    }
    scene.light = applyLightSize(scene.light, given);
    try {
        checkSpotDiskCasters(scene);
    } catch (const std::invalid_argument& e) {
        throw UsageError(scene.name + ": " + e.what());
    }
}

// What is about to be computed, in one line on stderr.
void sayTruthPlan(const TruthCommandOptions& o, const Scene& scene, glm::ivec2 size, bool area) {
    int threads = resolveThreadCount(o.threads);
    char light[96];
    if (area && scene.light.type == LightType::Spot) {
        std::snprintf(light, sizeof light, "a spot disk of radius %g (integrated over the disk)",
                      static_cast<double>(scene.light.radius));
    } else if (area) {
        std::snprintf(light, sizeof light, "a sun disk of %g degrees (integrated over the disk)",
                      static_cast<double>(scene.light.angularDiameterDeg));
    } else {
        std::snprintf(light, sizeof light, "the light's centre (hard shadows)");
    }
    std::fprintf(stderr,
                 "truth: %s, %dx%d, %s, first pass %dx%d samples per pixel, edges refined to a "
                 "bound of %.5g, %d thread%s\n",
                 scene.name.c_str(), size.x, size.y, light, o.spp, o.spp, o.bound, threads,
                 threads == 1 ? "" : "s");
}

int runTruth(const TruthCommandOptions& o) {
    // Every check first: nothing is computed or written unless all of it can be.
    RenderOptions sceneOptions;
    sceneOptions.scene = o.scene;
    sceneOptions.sceneFile = o.sceneFile;
    glm::ivec2 size = parseSize("--size", o.size);
    checkTruthOptions(o);
    Scene scene = sceneOptions.loadScene();
    // Measured peaks of `truth --spp 1` (box-on-plane): 139 MB at 512x512, 152 MB at 1024x1024:
    // 17 bytes a pixel; 24 leaves room for --mask's channel and the EXR held in memory.
    requireMemory("--size " + o.size, memoryEstimate(160 * MIB, 24, size.x, size.y), o.force);
    applyTruthLightSize(o, scene);
    OutputFiles outputs(o.force);
    outputs.addInput("--scene-file", o.sceneFile);
    outputs.add("-o", o.out);

    GroundTruthOptions options;
    options.spp = o.spp;
    options.threads = o.threads;
    options.targetBound = static_cast<float>(o.bound);
    options.area = hasSize(scene.light);
    sayTruthPlan(o, scene, size, options.area);
    auto start = std::chrono::steady_clock::now();
    int lastTenth = 0;
    options.progress = [&](int done, int total) {
        int tenth = done * 10 / total;
        if (tenth > lastTenth && tenth < 10) {
            std::fprintf(stderr, "truth: %d%%\n", tenth * 10);
            lastTenth = tenth;
        }
    };
    GroundTruth truth = computeGroundTruth(scene, size, options);

    writeTruthExr(o.out, truth, o.mask);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "truth: %d pixels refined, largest bound %.6g (target %.6g), %.2f s\n",
                 truth.refinedPixels, truth.maxBound, truth.targetBound, seconds);
    sayAboveTarget(truth);
    if (!options.area) sayWalkedObjects(scene);
    outputs.commit();
    std::fprintf(stderr, "truth: wrote %s\n", o.out.c_str());
    return 0;
}

}  // namespace

Command addTruthCommand(CLI::App& app) {
    auto o = std::make_shared<TruthCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "truth",
        "exact shadow by ray casting: visibility per pixel with its error bound (edges "
        "integrated along sub-scanlines until two resolutions agree)");
    sub->add_option("--scene", o->scene, "built-in scene: " + presetNameList());
    sub->add_option("--scene-file", o->sceneFile, "scene file (TOML)");
    sub->add_option("--size", o->size, sizeHelp("frame size", {}, "default 1280x720"));
    sub->add_option("--spp", o->spp,
                    "first pass: K x K stratified samples per pixel that find the edges (1..64, "
                    "default 2)");
    sub->add_option("--bound", o->bound,
                    "refine edge pixels until the error bound is at most this (1e-06..1, default "
                    "1/512)");
    // With a size, the truth integrates over the light's disk as well as the pixel.
    o->light.addKeys(sub, {"light_size", "light_radius"}, ShadowSettings{});
    sub->add_option("--threads", o->threads, "worker threads (0 = all cores, the default)");
    sub->add_flag("--mask", o->mask,
                  "add a 'mask' channel: 1 where the pixel centre's camera ray hits a shadow "
                  "receiver (the renderer's receiver pixels)");
    sub->add_option("-o,--out", o->out,
                    "the truth as a float EXR: channels 'visibility' in [0,1] and 'bound' (the "
                    "stated bound on its error), rows top-down");
    sub->add_flag("-f,--force", o->force,
                  "overwrite an existing output file; start work larger than the memory estimate "
                  "says the machine holds");
    return {sub, [o] { return runTruth(*o); }};
}

}  // namespace pcf
