// pcfscope truth: the exact shadow of a scene by ray casting (analysis/ground_truth.h), as an
// EXR of visibility per pixel, rows top-down like every image pcfscope writes.
#include <cstdio>
#include <memory>
#include <string>

#include "analysis/ground_truth.h"
#include "app/cli_util.h"
#include "app/commands.h"
#include "app/output_files.h"
#include "app/render_options.h"
#include "render/image_io.h"

namespace pcf {

namespace {

struct TruthCommandOptions {
    std::string scene;
    std::string sceneFile;
    std::string size = "1280x720";
    int spp = DEFAULT_TRUTH_SPP;
    int threads = 0;
    bool mask = false;
    std::string out;
    bool force = false;
};

int runTruth(const TruthCommandOptions& o) {
    // Every check first: nothing is computed or written unless all of it can be.
    RenderOptions sceneOptions;
    sceneOptions.scene = o.scene;
    sceneOptions.sceneFile = o.sceneFile;
    glm::ivec2 size = parseSize("--size", o.size, MAX_FRAME_SIDE);
    requireIntRange("--spp", o.spp, 1, MAX_TRUTH_SPP);
    requireIntRange("--threads", o.threads, 0, 1024);
    if (o.scene.empty() && o.sceneFile.empty()) {
        throw UsageError("truth needs --scene PRESET or --scene-file FILE");
    }
    if (!o.scene.empty() && !o.sceneFile.empty()) {
        throw UsageError("give --scene or --scene-file, not both");
    }
    if (o.out.empty()) throw UsageError("truth needs -o FILE.exr");
    requireExtension("-o", o.out, ".exr");
    Scene scene = sceneOptions.loadScene();
    OutputFiles outputs(o.force);
    outputs.addInput("--scene-file", o.sceneFile);
    outputs.add("-o", o.out);

    GroundTruthOptions options;
    options.spp = o.spp;
    options.threads = o.threads;
    int threads = resolveThreadCount(o.threads);
    std::fprintf(stderr, "truth: %s, %dx%d, %dx%d samples per pixel, %d thread%s\n",
                 scene.name.c_str(), size.x, size.y, o.spp, o.spp, threads,
                 threads == 1 ? "" : "s");
    int lastTenth = 0;
    options.progress = [&](int done, int total) {
        int tenth = done * 10 / total;
        if (tenth > lastTenth && tenth < 10) {
            std::fprintf(stderr, "truth: %d%%\n", tenth * 10);
            lastTenth = tenth;
        }
    };
    GroundTruth truth = computeGroundTruth(scene, size, options);

    if (!o.mask) {
        writeExr(o.out, size.x, size.y, 1, truth.visibility, {"Y"});
    } else {
        std::vector<float> data(2 * truth.pixelCount());
        for (size_t k = 0; k < truth.pixelCount(); ++k) {
            data[2 * k] = truth.visibility[k];
            data[2 * k + 1] = truth.receiver[k] ? 1.0f : 0.0f;
        }
        writeExr(o.out, size.x, size.y, 2, data, {"Y", "mask"});
    }
    outputs.commit();
    std::fprintf(stderr, "truth: wrote %s\n", o.out.c_str());
    return 0;
}

}  // namespace

Command addTruthCommand(CLI::App& app) {
    auto o = std::make_shared<TruthCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "truth", "exact shadow by ray casting: visibility per pixel, averaged over K x K samples");
    sub->add_option("--scene", o->scene,
                    "built-in scene: box-on-plane, sphere-over-plane, pole, grazing, stairs");
    sub->add_option("--scene-file", o->sceneFile, "scene file (TOML)");
    sub->add_option("--size", o->size, "frame size WxH (default 1280x720)");
    sub->add_option("--spp", o->spp, "K: K x K stratified samples per pixel (1..64, default 8)");
    sub->add_option("--threads", o->threads, "worker threads (0 = all cores, the default)");
    sub->add_flag("--mask", o->mask,
                  "add a 'mask' channel: 1 where the pixel centre's camera ray hits a shadow "
                  "receiver (the renderer's receiver pixels)");
    sub->add_option("-o,--out", o->out,
                    "the truth as a float EXR: channel Y = visibility in "
                    "[0,1], rows top-down");
    sub->add_flag("-f,--force", o->force, "overwrite an existing output file");
    return {sub, [o] { return runTruth(*o); }};
}

}  // namespace pcf
