#include "measure/stability.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <stdexcept>
#include <utility>

#include "kernel/bias.h"
#include "kernel/methods.h"
#include "measure/error_metrics.h"
#include "measure/failure_measures.h"
#include "measure/ground_truth.h"
#include "measure/stability_bleed.h"
#include "measure/stability_cascades.h"
#include "measure/stability_pcss.h"
#include "render/scene_renderer.h"
#include "scene/camera.h"
#include "scene/light.h"
#include "scene/presets.h"
#include "scene/raycast.h"

namespace pcf {

namespace {

constexpr float MAX_ALIASING_JUMP = 32.0f;  // texels between neighbours: another surface

class Sweeper {
  public:
    Sweeper(const StabilityContext& context, const StabilityOptions& options)
        : mContext(context), mOptions(options) {}

    StabilityResult result;

    void run(Sweep sweep) {
        switch (sweep) {
            case Sweep::Acne:
                acne();
                break;
            case Sweep::Leak:
                leak();
                break;
            case Sweep::Tradeoff:
                tradeoff();
                break;
            case Sweep::Shimmer:
                shimmer();
                break;
            case Sweep::Precision:
                precision();
                break;
            case Sweep::Aliasing:
                aliasing();
                break;
            case Sweep::PcssThin:
            case Sweep::PcssOverlap:
            case Sweep::PcssNoise:
            case Sweep::PcssBias:
                runPcssSweep(sweep, mOptions, *mContext.scene, mContext.progress, result.rows);
                break;
            case Sweep::Bleed:
                runBleedSweep(mOptions, mContext.progress, result.rows);
                break;
            case Sweep::Cascades:
                runCascadeSweep(mOptions, mContext.progress, result.rows);
                break;
        }
    }

  private:
    const StabilityContext& mContext;
    const StabilityOptions& mOptions;

    // The footprint's reach for the clean masks: the method's own, + half a texel for the
    // bilinear taps' rounding.
    float reachOf(const StabilityMethod& m) const {
        return footprintReachTexels(m, mOptions.base.radius) + 0.5f;
    }

    // The clean mask of each method's reach (methods of equal reach share one).
    std::vector<std::vector<uint8_t>> cleanMasks(const Scene& scene, const GroundTruth& truth,
                                                 const ErrorRegions& regions,
                                                 const std::vector<std::optional<Hit>>& hits,
                                                 const glm::mat4& shadowClip, bool wantLit) const {
        std::vector<std::vector<uint8_t>> masks;
        std::vector<float> reaches;
        for (const StabilityMethod& m : mOptions.methods) {
            float reach = reachOf(m);
            auto it = std::find(reaches.begin(), reaches.end(), reach);
            if (it != reaches.end()) {
                masks.push_back(masks[static_cast<size_t>(it - reaches.begin())]);
            } else {
                masks.push_back(cleanPixelMask(scene, truth, regions, hits, shadowClip,
                                               mOptions.mapSize, reach, wantLit, mOptions.threads));
            }
            reaches.push_back(reach);
        }
        return masks;
    }

    void say(const std::string& line) const {
        if (mContext.progress) mContext.progress(line);
    }

    RenderSettings settings(const StabilityMethod& m, BiasMode bias) const {
        RenderSettings s = mOptions.base;
        s.method = m.method;
        s.kernel = m.kernel > 0 ? m.kernel : 3;
        s.bias = bias;
        s.mapSize = mOptions.mapSize;
        s.frameSize = mOptions.frameSize;
        s.writePositions = false;
        return s;
    }

    void add(Sweep sweep, const StabilityMethod& m, BiasMode bias, const std::string& xName,
             double x, const std::string& metric, double y) {
        result.rows.push_back({std::string(sweepName(sweep)), m.method, m.kernel,
                               std::string(biasModeName(bias)), xName, x, metric, y});
    }

    GroundTruth truthOf(const Scene& scene) const {
        GroundTruthOptions o;
        o.spp = mOptions.truthSpp;
        o.threads = mOptions.threads;
        return computeGroundTruth(scene, mOptions.frameSize, o);
    }

    // Renders both passes with the renderer's current matrices and reads the visibility.
    std::vector<float> frame(SceneRenderer& r, const RenderSettings& s) const {
        r.renderShadowPass(s);
        r.renderCameraPass(s);
        return r.readVisibility();
    }

    ErrorRegions regionsOf(SceneRenderer& r, const GroundTruth& truth) const {
        // Any method: the light-space alpha marks the receivers, whatever was filtered.
        RenderSettings s = settings(mOptions.methods.front(), BiasMode::Constant);
        r.renderShadowPass(s);
        r.renderCameraPass(s);
        return errorRegions(truth, receiverMaskFromLightSpace(r.readLightSpace()));
    }

    Scene sceneAtElevation(float elevation) const {
        Scene s = *mContext.scene;
        s.light.directionWs = directionAtElevation(s.light.directionWs, elevation);
        return s;
    }

    void acne() {
        const std::vector<float>& elevations = mOptions.elevations;
        SceneRenderer renderer(*mContext.scene);
        std::vector<std::optional<Hit>> hits =
            centreHits(*mContext.scene, mOptions.frameSize, mOptions.threads);
        for (size_t e = 0; e < elevations.size(); ++e) {
            float elev = elevations[e];
            char line[96];
            std::snprintf(line, sizeof line, "acne %zu/%zu: light %.0f deg above the ground", e + 1,
                          elevations.size(), elev);
            say(line);
            Scene scene = sceneAtElevation(elev);
            renderer.setLight(scene.light);
            GroundTruth truth = truthOf(scene);
            ErrorRegions regions = regionsOf(renderer, truth);
            std::vector<std::vector<uint8_t>> lit =
                cleanMasks(scene, truth, regions, hits, renderer.shadowClipFromWorld(), true);
            for (BiasMode bias : mOptions.biases) {
                for (size_t mi = 0; mi < mOptions.methods.size(); ++mi) {
                    const StabilityMethod& m = mOptions.methods[mi];
                    if (!stabilityPairExists(m, bias)) continue;
                    FailureRate r = falseShadow(frame(renderer, settings(m, bias)), lit[mi]);
                    add(Sweep::Acne, m, bias, "elevation_deg", elev, "false_shadow_rate", r.share);
                    add(Sweep::Acne, m, bias, "elevation_deg", elev, "mean_darkening", r.mean);
                    add(Sweep::Acne, m, bias, "elevation_deg", elev, "clean_lit_pixels", r.count);
                }
            }
        }
    }

    // Acne against the constant bias at one elevation, over the leak sweep's biases (the
    // trade-off chart puts the two on one bias axis).
    void tradeoff() {
        say("tradeoff: acne against the constant bias at one elevation");
        SceneRenderer renderer(*mContext.scene);
        Scene scene = sceneAtElevation(mOptions.tradeoffElevation);
        renderer.setLight(scene.light);
        GroundTruth truth = truthOf(scene);
        std::vector<std::vector<uint8_t>> lit =
            cleanMasks(scene, truth, regionsOf(renderer, truth),
                       centreHits(scene, mOptions.frameSize, mOptions.threads),
                       renderer.shadowClipFromWorld(), true);
        for (float b : mOptions.leakBiases) {
            for (size_t mi = 0; mi < mOptions.methods.size(); ++mi) {
                const StabilityMethod& m = mOptions.methods[mi];
                if (!stabilityPairExists(m, BiasMode::Constant)) continue;
                RenderSettings s = settings(m, BiasMode::Constant);
                s.constantBias = b;
                FailureRate r = falseShadow(frame(renderer, s), lit[mi]);
                for (auto [metric, y] :
                     {std::pair<const char*, double>{"false_shadow_rate", r.share},
                      {"clean_lit_pixels", r.count}}) {
                    add(Sweep::Tradeoff, m, BiasMode::Constant, "constant_bias", b, metric, y);
                }
            }
        }
    }

    void leak() {
        for (size_t si = 0; si < mOptions.leakScenes.size(); ++si) {
            const std::string& name = mOptions.leakScenes[si];
            std::optional<Scene> preset = presetScene(name);
            if (!preset) throw std::invalid_argument("unknown leak scene " + name);
            Scene& scene = *preset;
            say("leak " + std::to_string(si + 1) + "/" +
                std::to_string(mOptions.leakScenes.size()) + ": " + name + " contact");
            SceneRenderer renderer(scene);
            GroundTruth truth = truthOf(scene);
            ErrorRegions regions = regionsOf(renderer, truth);
            std::vector<std::optional<Hit>> hits =
                centreHits(scene, mOptions.frameSize, mOptions.threads);
            glm::mat4 shadowClip = renderer.shadowClipFromWorld();
            std::vector<std::vector<uint8_t>> umbras =
                cleanMasks(scene, truth, regions, hits, shadowClip, false);
            // Per truth umbra pixel: its distance from the caster, world and texels.
            CasterDistances distances =
                casterDistances(scene, truth, regions, hits, shadowClip, mOptions.mapSize);
            for (float b : mOptions.leakBiases) {
                for (BiasMode bias : mOptions.biases) {
                    for (size_t mi = 0; mi < mOptions.methods.size(); ++mi) {
                        const StabilityMethod& m = mOptions.methods[mi];
                        if (!stabilityPairExists(m, bias)) continue;
                        const std::vector<uint8_t>& umbra = umbras[mi];
                        RenderSettings s = settings(m, bias);
                        s.constantBias = b;
                        std::vector<float> vis = frame(renderer, s);
                        FailureRate leaks = falseLight(vis, umbra);
                        LeakWidth width = leakWidth(vis, umbra, distances.texels, distances.world,
                                                    mOptions.frameSize);
                        const std::pair<const char*, double> measured[] = {
                            {"leak_rate", leaks.share},
                            {"leak_width_world", width.world},
                            {"leak_width_texels", width.texels},
                            {"leak_width_support", width.support},
                            {"leak_stray_pixels", width.stray},
                            {"clean_umbra_pixels", leaks.count}};
                        for (auto [metric, y] : measured) {
                            add(Sweep::Leak, m, bias, "constant_bias", b, name + ":" + metric, y);
                        }
                    }
                }
            }
        }
    }

    // The pinned pixel's visibility in each frame.
    std::vector<float> pinnedCurve(const std::vector<std::vector<float>>& frames) const {
        glm::ivec2 p =
            glm::clamp(*mOptions.pinnedPixel, glm::ivec2(0), mOptions.frameSize - glm::ivec2(1));
        size_t k = static_cast<size_t>(p.y) * static_cast<size_t>(mOptions.frameSize.x) +
                   static_cast<size_t>(p.x);
        std::vector<float> curve;
        for (const std::vector<float>& f : frames) curve.push_back(f[k]);
        return curve;
    }

    // |a - b| over the mask's pixels (the camera shimmer: the error's change between frames).
    static void addChanges(const std::vector<float>& a, const std::vector<float>& b,
                           const std::vector<uint8_t>& mask, std::vector<float>& out) {
        for (size_t k = 0; k < a.size(); ++k) {
            if (mask[k]) out.push_back(std::abs(a[k] - b[k]));
        }
    }

    void shimmer() {
        const Scene& scene = *mContext.scene;
        SceneRenderer renderer(scene);
        say("shimmer: ground truth");
        GroundTruth truth = truthOf(scene);
        ErrorRegions regions = regionsOf(renderer, truth);
        ShimmerPopulations pop = shimmerPopulations(scene, renderer, truth, regions);
        glm::mat4 fitted = renderer.shadowClipFromWorld();
        // The frames with the pinned point's jitter (no pixel's lookup replaced: pixel -1).
        if (mOptions.pinnedPixel && mOptions.pinnedJitter != glm::vec2(0.0f)) {
            renderer.setPick(CameraPick{glm::ivec2(-1), mOptions.pinnedJitter, glm::vec4(0.0f),
                                        glm::vec2(0.0f)});
        }
        for (bool snap : {false, true}) {
            say(std::string("shimmer: the light's texel grid slid in 1/32 texel steps") +
                (snap ? ", snapped to whole texels" : ""));
            for (BiasMode bias : mOptions.biases) {
                for (const StabilityMethod& m : mOptions.methods) {
                    if (!stabilityPairExists(m, bias)) continue;
                    RenderSettings s = settings(m, bias);
                    std::vector<std::vector<float>> frames;
                    for (int t = 0; t < mOptions.shimmerFrames; ++t) {
                        renderer.setShadowClipFromWorld(
                            shimmerShadowFit(fitted, mOptions.mapSize, t, snap));
                        frames.push_back(frame(renderer, s));
                    }
                    addShimmerRows(m, bias, snap, frames, regions, pop);
                }
            }
        }
        cameraShimmer(scene, pop.edge);
    }

    // The two fixed populations of the shimmer sweep, the same pixels for every method and bias:
    // the lit ground (clean lit at the widest footprint of the run: any change there is acne
    // flickering) and the edges (every other compared pixel: in or near a real shadow).
    struct ShimmerPopulations {
        std::vector<uint8_t> edge, lit;
        int edgeCount = 0, litCount = 0;
    };
    ShimmerPopulations shimmerPopulations(const Scene& scene, SceneRenderer& renderer,
                                          const GroundTruth& truth,
                                          const ErrorRegions& regions) const {
        float reach = 0.0f;
        for (const StabilityMethod& m : mOptions.methods) reach = std::max(reach, reachOf(m));
        std::vector<std::optional<Hit>> hits =
            centreHits(scene, mOptions.frameSize, mOptions.threads);
        ShimmerPopulations p;
        p.lit = cleanPixelMask(scene, truth, regions, hits, renderer.shadowClipFromWorld(),
                               mOptions.mapSize, reach, true, mOptions.threads);
        p.edge.assign(p.lit.size(), 0);
        for (size_t k = 0; k < p.lit.size(); ++k) {
            p.edge[k] = regions.compared[k] && !p.lit[k] ? 1 : 0;
            p.edgeCount += p.edge[k];
            p.litCount += p.lit[k];
        }
        return p;
    }

    // The shimmer sweep's rows of one method and bias: the error's change over the frames on the
    // compared pixels and on the two populations, and the pinned pixel's curve.
    void addShimmerRows(const StabilityMethod& m, BiasMode bias, bool snap,
                        const std::vector<std::vector<float>>& frames, const ErrorRegions& regions,
                        const ShimmerPopulations& pop) {
        ShimmerStats st = shimmerStats(frames, regions.compared);
        std::string prefix = snap ? "snapped_" : "light_";
        double step = 1.0 / SHIMMER_STEPS;
        ShimmerStats edge = shimmerStats(frames, pop.edge);
        ShimmerStats lit = shimmerStats(frames, pop.lit);
        auto addAll = [&](std::initializer_list<std::pair<const char*, double>> measured) {
            for (auto [metric, y] : measured) {
                add(Sweep::Shimmer, m, bias, "texel_step", step, prefix + metric, y);
            }
        };
        addAll({{"edge_mean", edge.mean},
                {"edge_p99", edge.p99},
                {"edge_peak_p99", edge.peakP99},
                {"lit_mean", lit.mean},
                {"edge_pixels", static_cast<double>(pop.edgeCount)},
                {"lit_pixels", static_cast<double>(pop.litCount)}});
        if (mOptions.pinnedPixel) {
            std::vector<float> curve = pinnedCurve(frames);
            addAll({{"pinned_flicker", curveFlicker(curve)}});
            for (size_t t = 0; t < curve.size(); ++t) {
                add(Sweep::Shimmer, m, bias, "frame", static_cast<double>(t),
                    prefix + "pinned_visibility", curve[t]);
            }
        }
        addAll({{"flicker_share", st.flickerShare},
                {"flicker_mean", st.flickerMean},
                {"flicker_p99", st.flickerP99},
                {"mean", st.mean},
                {"p99", st.p99},
                {"max", st.max}});
    }

    // The camera slid right and up by 1/F pixel a frame (at the distance of its target); the
    // truth moves with it, so what counts is the change of the error e = v - truth.
    void cameraShimmer(const Scene& scene, const std::vector<uint8_t>& edge) {
        int frames = mOptions.cameraFrames;
        if (frames < 2) return;
        glm::ivec2 size = mOptions.frameSize;
        SceneRenderer renderer(scene);
        size_t combos = mOptions.biases.size() * mOptions.methods.size();
        std::vector<std::vector<float>> changes(combos), previous(combos), edgeChanges(combos);
        // Per pair and pixel, the largest change of the error (-1: never compared).
        std::vector<std::vector<float>> edgePeak(
            combos, std::vector<float>(static_cast<size_t>(size.x) * size.y, -1.0f));
        std::vector<uint8_t> previousMask;
        for (int t = 0; t < frames; ++t) {
            say("shimmer: camera frame " + std::to_string(t + 1) + "/" + std::to_string(frames));
            Scene moved = scene;
            moved.camera = cameraSlidByPixels(scene.camera, mOptions.frameSize.y,
                                              static_cast<float>(t) / static_cast<float>(frames));
            renderer.setCamera(moved.camera);
            GroundTruth truth = truthOf(moved);
            ErrorRegions regions = regionsOf(renderer, truth);
            std::vector<uint8_t> both = regions.compared;
            if (!previousMask.empty()) {
                for (size_t k = 0; k < both.size(); ++k) both[k] &= previousMask[k];
            }
            std::vector<uint8_t> bothEdge = both;
            for (size_t k = 0; k < both.size(); ++k) bothEdge[k] &= edge[k];
            size_t c = 0;
            for (BiasMode bias : mOptions.biases) {
                for (const StabilityMethod& m : mOptions.methods) {
                    if (!stabilityPairExists(m, bias)) continue;
                    std::vector<float> err = frame(renderer, settings(m, bias));
                    for (size_t k = 0; k < err.size(); ++k) err[k] -= truth.visibility[k];
                    if (t > 0) addChanges(err, previous[c], both, changes[c]);
                    if (t > 0) addChanges(err, previous[c], bothEdge, edgeChanges[c]);
                    for (size_t k = 0; t > 0 && k < err.size(); ++k) {
                        if (!bothEdge[k]) continue;
                        float d = std::abs(err[k] - previous[c][k]);
                        edgePeak[c][k] = std::max(edgePeak[c][k], d);
                    }
                    previous[c++] = std::move(err);
                }
            }
            previousMask = regions.compared;
        }
        addCameraShimmerRows(1.0 / frames, changes, edgeChanges, edgePeak);
    }

    // The camera shimmer's rows: per method and bias, the error's change between frames on the
    // compared pixels and on the edges, and the 99th percentile of each edge pixel's largest.
    // (quantileOf sorts the changes it is given.)
    void addCameraShimmerRows(double step, std::vector<std::vector<float>>& changes,
                              std::vector<std::vector<float>>& edgeChanges,
                              const std::vector<std::vector<float>>& edgePeak) {
        size_t c = 0;
        for (BiasMode bias : mOptions.biases) {
            for (const StabilityMethod& m : mOptions.methods) {
                if (!stabilityPairExists(m, bias)) continue;
                std::vector<float> peaks;
                for (float p : edgePeak[c]) {
                    if (p >= 0.0f) peaks.push_back(p);
                }
                const std::pair<const char*, double> measured[] = {
                    {"camera_mean", meanOf(changes[c])},
                    {"camera_p99", quantileOf(changes[c], 0.99)},
                    {"camera_edge_mean", meanOf(edgeChanges[c])},
                    {"camera_edge_p99", quantileOf(edgeChanges[c], 0.99)},
                    {"camera_edge_peak_p99", quantileOf(peaks, 0.99)}};
                for (auto [metric, y] : measured) {
                    add(Sweep::Shimmer, m, bias, "pixel_step", step, metric, y);
                }
                ++c;
            }
        }
    }

    void precision() {
        Scene scene = sceneAtElevation(mOptions.precisionElevation);
        SceneRenderer renderer(scene);
        say("precision: ground truth at " +
            std::to_string(static_cast<int>(mOptions.precisionElevation)) + " deg");
        GroundTruth truth = truthOf(scene);
        ErrorRegions regions = regionsOf(renderer, truth);
        glm::mat4 fitted = renderer.shadowClipFromWorld();
        std::vector<std::optional<Hit>> hits =
            centreHits(scene, mOptions.frameSize, mOptions.threads);
        std::vector<std::vector<uint8_t>> lit =
            cleanMasks(scene, truth, regions, hits, fitted, true);
        for (TexelKind format : mOptions.depthFormats) {
            say("precision: depth format " + std::string(depthFormatName(format)));
            std::string suffix = "_d" + std::string(depthFormatName(format));
            for (float ratio : mOptions.depthRanges) {
                renderer.setShadowClipFromWorld(widenShadowDepthRange(fitted, ratio));
                for (BiasMode bias : mOptions.biases) {
                    for (size_t mi = 0; mi < mOptions.methods.size(); ++mi) {
                        const StabilityMethod& m = mOptions.methods[mi];
                        if (!stabilityPairExists(m, bias)) continue;
                        RenderSettings s = settings(m, bias);
                        s.depthFormat = format;
                        s.constantBias = mOptions.base.constantBias / ratio;
                        FailureRate r = falseShadow(frame(renderer, s), lit[mi]);
                        add(Sweep::Precision, m, bias, "depth_range", ratio,
                            "false_shadow_rate" + suffix, r.share);
                        add(Sweep::Precision, m, bias, "depth_range", ratio,
                            "mean_darkening" + suffix, r.mean);
                    }
                }
            }
        }
    }

    void aliasing() {
        const Scene& scene = *mContext.scene;
        say("aliasing: screen pixels per shadow-map texel");
        SceneRenderer renderer(scene);
        GroundTruth truth = truthOf(scene);
        ErrorRegions regions = regionsOf(renderer, truth);
        std::vector<float> lightSpace = renderer.readLightSpace();
        for (int size : mOptions.aliasingMapSizes) {
            std::vector<float> ppt = pixelsPerTexel(lightSpace, mOptions.frameSize, size);
            std::vector<float> values;
            for (size_t k = 0; k < ppt.size(); ++k) {
                if (regions.compared[k] && ppt[k] > 0.0f) values.push_back(ppt[k]);
            }
            std::string sweep(sweepName(Sweep::Aliasing));
            double median = quantileOf(values, 0.5);
            double p99 = quantileOf(values, 0.99);
            result.rows.push_back(
                {sweep, -1, 0, "-", "map_size", double(size), "pixels_per_texel_median", median});
            result.rows.push_back(
                {sweep, -1, 0, "-", "map_size", double(size), "pixels_per_texel_p99", p99});
            result.rows.push_back({sweep, -1, 0, "-", "map_size", double(size),
                                   "undersampled_share", undersampledShare(values)});
            if (size == mOptions.mapSize) {
                result.images.push_back(
                    {"aliasing_heatmap.png", mOptions.frameSize, aliasingHeatmap(ppt, regions)});
            }
        }
    }

    // Share of the measured pixels where one texel covers more than one pixel.
    static double undersampledShare(const std::vector<float>& values) {
        if (values.empty()) return 0.0;
        size_t n = 0;
        for (float v : values) n += v > 1.0f ? 1 : 0;
        return static_cast<double>(n) / values.size();
    }

    // aliasingHeatColour per pixel; grey where it is not measured.
    static std::vector<uint8_t> aliasingHeatmap(const std::vector<float>& ppt,
                                                const ErrorRegions& regions) {
        std::vector<uint8_t> rgba(ppt.size() * 4);
        for (size_t k = 0; k < ppt.size(); ++k) {
            glm::vec3 c = ALIASING_HEAT_NONE;
            if (regions.compared[k] && ppt[k] > 0.0f) c = aliasingHeatColour(ppt[k]);
            for (int i = 0; i < 3; ++i) {
                rgba[k * 4 + i] = static_cast<uint8_t>(std::lround(c[i] * 255.0f));
            }
            rgba[k * 4 + 3] = 255;
        }
        return rgba;
    }
};

}  // namespace

glm::vec3 aliasingHeatColour(float pixelsPerTexel) {
    float t = std::clamp(std::log2(pixelsPerTexel) / ALIASING_HEAT_LOG2_RANGE, -1.0f, 1.0f);
    glm::vec3 white(1.0f), red(0.75f, 0.05f, 0.1f), blue(0.1f, 0.25f, 0.75f);
    return t >= 0.0f ? glm::mix(white, red, t) : glm::mix(white, blue, -t);
}

std::string_view sweepName(Sweep sweep) {
    switch (sweep) {
        case Sweep::Acne:
            return "acne";
        case Sweep::Leak:
            return "leak";
        case Sweep::Tradeoff:
            return "tradeoff";
        case Sweep::Shimmer:
            return "shimmer";
        case Sweep::Precision:
            return "precision";
        case Sweep::PcssThin:
            return "pcss-thin";
        case Sweep::PcssOverlap:
            return "pcss-overlap";
        case Sweep::PcssNoise:
            return "pcss-noise";
        case Sweep::Aliasing:
            return "aliasing";
        case Sweep::PcssBias:
            return "pcss-bias";
        case Sweep::Bleed:
            return "bleed";
        case Sweep::Cascades:
            return "cascades";
    }
    return "";  // not reached: the switch names every sweep (the compiler checks it)
}

std::optional<Sweep> sweepFromName(std::string_view name) {
    for (Sweep s : allSweeps()) {
        if (sweepName(s) == name) return s;
    }
    return std::nullopt;
}

std::vector<Sweep> allSweeps() {
    return {Sweep::Acne,      Sweep::Leak,     Sweep::Tradeoff, Sweep::Shimmer,
            Sweep::Precision, Sweep::Aliasing, Sweep::PcssThin, Sweep::PcssOverlap,
            Sweep::PcssNoise, Sweep::PcssBias, Sweep::Bleed,    Sweep::Cascades};
}

std::string sweepNameList() {
    std::string names;
    for (Sweep s : allSweeps()) names += (names.empty() ? "" : ", ") + std::string(sweepName(s));
    return names;
}

bool stabilityPairExists(const StabilityMethod& m, BiasMode bias) {
    return !validateBias(static_cast<int>(bias), m.method).has_value();
}

std::string stabilityMethodName(const StabilityMethod& m) {
    std::string name(methodInfo(m.method).name);
    if (m.kernel > 0) name += " N=" + std::to_string(m.kernel);
    return name;
}

glm::mat4 shimmerShadowFit(const glm::mat4& fitted, int mapSize, int frame, bool snap) {
    float n = static_cast<float>(mapSize);
    glm::mat4 shrink(1.0f);
    shrink[0][0] = shrink[1][1] = (n - 4.0f) / n;
    float step = static_cast<float>(frame) / SHIMMER_STEPS;
    return shiftShadowOrigin(shrink * fitted, glm::vec2(step), mapSize, snap);
}

Camera cameraSlidByPixels(const Camera& camera, int frameHeight, float pixels) {
    glm::vec3 forward = glm::normalize(camera.targetWs - camera.eyeWs);
    glm::vec3 right = glm::normalize(glm::cross(forward, camera.upWs));
    glm::vec3 up = glm::cross(right, forward);
    float pixel = 2.0f * glm::length(camera.targetWs - camera.eyeWs) *
                  std::tan(glm::radians(camera.fovYDeg) * 0.5f) / static_cast<float>(frameHeight);
    glm::vec3 shift = (right + up) * (pixel * pixels);
    Camera moved = camera;
    moved.eyeWs += shift;
    moved.targetWs += shift;
    return moved;
}

float footprintReachTexels(const StabilityMethod& m, float poissonRadius) {
    return reachTexels(m.method, m.kernel, poissonRadius);
}

std::vector<std::optional<glm::mat2>> texelJacobians(const std::vector<float>& lightSpace,
                                                     glm::ivec2 size, int mapSize) {
    std::vector<std::optional<glm::mat2>> out(static_cast<size_t>(size.x) * size.y);
    float n = static_cast<float>(mapSize);
    auto at = [&](int x, int y) { return &lightSpace[(static_cast<size_t>(y) * size.x + x) * 4]; };
    auto receiver = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < size.x && y < size.y && at(x, y)[3] > 0.5f;
    };
    // The texel-space step to a neighbour (dx, dy), or nothing across a jump.
    auto delta = [&](int x, int y, int dx, int dy) -> std::optional<glm::vec2> {
        if (!receiver(x + dx, y + dy)) return std::nullopt;
        const float* a = at(x, y);
        const float* b = at(x + dx, y + dy);
        glm::vec2 d((b[0] - a[0]) * n, (b[1] - a[1]) * n);
        if (glm::length(d) > MAX_ALIASING_JUMP) return std::nullopt;
        return d;
    };
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            if (!receiver(x, y)) continue;
            std::optional<glm::vec2> dx = delta(x, y, 1, 0);
            if (!dx) {
                dx = delta(x, y, -1, 0);
                if (dx) *dx = -*dx;
            }
            // Rows are top-down: +y on screen (GL, up) is the row above.
            std::optional<glm::vec2> dy = delta(x, y, 0, -1);
            if (!dy) {
                dy = delta(x, y, 0, 1);
                if (dy) *dy = -*dy;
            }
            if (dx && dy) out[static_cast<size_t>(y) * size.x + x] = glm::mat2(*dx, *dy);
        }
    }
    return out;
}

std::vector<float> pixelsPerTexel(const std::vector<float>& lightSpace, glm::ivec2 size,
                                  int mapSize) {
    std::vector<std::optional<glm::mat2>> j = texelJacobians(lightSpace, size, mapSize);
    std::vector<float> out(j.size(), -1.0f);
    for (size_t k = 0; k < j.size(); ++k) {
        float det = j[k] ? std::abs(glm::determinant(*j[k])) : 0.0f;
        if (det > 0.0f) out[k] = 1.0f / det;
    }
    return out;
}

StabilityResult runStability(const StabilityContext& context, const StabilityOptions& options) {
    if (auto why = validateStabilityOptions(options)) throw std::invalid_argument(why->text());
    if (context.scene == nullptr) throw std::invalid_argument("runStability: no scene");
    Sweeper sweeper(context, options);
    for (Sweep s : options.sweeps) sweeper.run(s);
    return std::move(sweeper.result);
}

}  // namespace pcf
