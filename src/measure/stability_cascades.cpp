#include "measure/stability_cascades.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "kernel/cascades.h"
#include "kernel/methods.h"
#include "kernel/shading.h"
#include "measure/cascade_density.h"
#include "render/scene_renderer.h"
#include "scene/primitives.h"

namespace pcf {

Scene cascadeSweepScene() {
    Scene scene;
    scene.name = "cascades sweep: a wall and posts along a ground";
    scene.light.directionWs = glm::normalize(glm::vec3(0.9f, -1.0f, 0.15f));
    scene.objects.push_back(
        {"ground", *makePlane(glm::vec3(0.0f, 0.0f, -48.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                              glm::vec2(40.0f, 110.0f))});
    // The wall's shadow falls beside it, its edge running along the ground away from the camera.
    scene.objects.push_back(
        {"wall", Box{glm::vec3(-2.5f, 0.6f, -46.0f), glm::vec3(0.1f, 0.6f, 50.0f)}});
    for (int k = 0; k < 12; ++k) {
        float z = -3.0f - 8.0f * static_cast<float>(k);
        scene.objects.push_back({"post" + std::to_string(k),
                                 Box{glm::vec3(2.0f, 1.0f, z), glm::vec3(0.2f, 1.0f, 0.2f)}});
    }
    scene.camera.eyeWs = glm::vec3(0.0f, 1.6f, 4.0f);
    scene.camera.targetWs = glm::vec3(-0.6f, 0.4f, -20.0f);
    scene.camera.nearZ = 0.1f;
    scene.camera.farZ = 130.0f;
    return scene;
}

Camera cascadePathCamera(const Camera& start, int step, int steps) {
    float t = steps > 1 ? static_cast<float>(step) / static_cast<float>(steps - 1) : 0.0f;
    float yaw = glm::radians(CASCADE_PATH_TURN_DEG * t);
    glm::vec3 view = start.targetWs - start.eyeWs;
    glm::vec3 turned(std::cos(yaw) * view.x + std::sin(yaw) * view.z, view.y,
                     -std::sin(yaw) * view.x + std::cos(yaw) * view.z);
    Camera c = start;
    c.eyeWs = start.eyeWs + glm::vec3(0.6f * t, 0.0f, -2.0f * t);
    c.targetWs = c.eyeWs + turned;
    return c;
}

SeamProbe seamProbe(const ShadowMap& map, const Camera& camera, const ShadowSettings& s,
                    const PcfParams& prm, const FrameSurfaces& frame, int split) {
    SeamProbe probe;
    if (split < 0 || split + 1 >= map.layers()) return probe;
    glm::vec3 viewDir = cameraViewDirWs(camera);
    float at = map.spec().layers[static_cast<size_t>(split)].viewDepth.y;
    size_t pixels = static_cast<size_t>(frame.size.x) * frame.size.y;
    for (size_t k = 0; k < pixels; ++k) {
        if (frame.lightSpace[4 * k + 3] != 1.0f) continue;
        const float* p = &frame.positions[4 * k];
        const float* n = &frame.normals[4 * k];
        glm::vec3 pos(p[0], p[1], p[2]), normal(n[0], n[1], n[2]);
        // Along the surface, the direction in which the view depth grows fastest, and how fast.
        glm::vec3 along = viewDir - normal * glm::dot(viewDir, normal);
        float rate = glm::dot(along, viewDir);
        if (rate < 0.05f) continue;  // seen edge-on: the surface does not reach the split
        float d = pcfViewDepth(pos, camera.eyeWs, viewDir);
        glm::vec3 move = along * ((at - d) / rate);
        if (glm::length(move) > CASCADE_SEAM_REACH * at) continue;
        pos += move;
        float left = cascadeVisibilityIn(map, split, at, s, prm, pos, normal, n[3]).blended;
        float right = cascadeVisibilityIn(map, split + 1, at, s, prm, pos, normal, n[3]).blended;
        double jump = std::fabs(static_cast<double>(left) - right);
        auto penumbra = [](float v) { return v > 0.02f && v < 0.98f; };
        ++probe.points;
        probe.edgePoints += penumbra(left) || penumbra(right) || jump > 0.02 ? 1 : 0;
        probe.difference = std::max(probe.difference, jump);
    }
    return probe;
}

std::string_view cascadeSplitOfLambda(double lambda) {
    if (lambda == 0.0) return cascadeSplitName(CASCADE_SPLIT_UNIFORM);
    if (lambda == 1.0) return cascadeSplitName(CASCADE_SPLIT_LOG);
    return cascadeSplitName(CASCADE_SPLIT_PRACTICAL);
}

namespace {

struct StaticReceiver {
    glm::vec3 pos;
    glm::vec3 normal;
    float cosTheta;
};

std::vector<StaticReceiver> staticReceivers(const FrameSurfaces& frame) {
    std::vector<StaticReceiver> out;
    for (int y = 0; y < frame.size.y; y += CASCADE_RECEIVER_STRIDE) {
        for (int x = 0; x < frame.size.x; x += CASCADE_RECEIVER_STRIDE) {
            size_t k = static_cast<size_t>(y) * frame.size.x + x;
            if (frame.lightSpace[4 * k + 3] != 1.0f) continue;
            const float* p = &frame.positions[4 * k];
            const float* n = &frame.normals[4 * k];
            out.push_back({glm::vec3(p[0], p[1], p[2]), glm::vec3(n[0], n[1], n[2]), n[3]});
        }
    }
    return out;
}

// Whether a point lies inside a cascade's map, CASCADE_MAP_MARGIN texels from its edges (so that
// no tap of the filter reads a clamped texel).
bool insideLayer(const PcfMapLayer& layer, glm::vec3 posWs, int mapSize) {
    glm::vec4 c = layer.shadowClipFromWorld * glm::vec4(posWs, 1.0f);
    float margin = CASCADE_MAP_MARGIN * 2.0f / static_cast<float>(mapSize);  // in clip units
    return std::fabs(c.x) <= 1.0f - margin && std::fabs(c.y) <= 1.0f - margin;
}

// What one (lambda, fit, snap) path measured, per method and cascade.
struct PathResult {
    std::vector<double> texelMin, texelMax, texelsPerPixel;
    // [method][cascade]
    std::vector<std::vector<double>> flicker, staying;
    std::vector<std::vector<std::optional<double>>> seam, seamBlended;
};

// A receiver's visibility at every step of the path, for one method: the cascade it read (-1:
// outside the frustum at some step, or a cascade change) and its visibility's range.
struct ReceiverTrack {
    int layer = -2;  // -2: no step yet
    float lo = 2.0f;
    float hi = -1.0f;
};

class CascadePath {
  public:
    CascadePath(SceneRenderer& renderer, const Scene& scene, const StabilityOptions& options,
                RenderSettings settings)
        : mRenderer(renderer), mScene(scene), mOptions(options), mSettings(std::move(settings)) {}

    PathResult run() {
        PathResult r;
        const int count = CASCADE_SWEEP_CASCADES;
        r.texelMin.assign(count, 1e30);
        r.texelMax.assign(count, 0.0);
        size_t methods = mOptions.methods.size();
        r.flicker.assign(methods, std::vector<double>(count, 0.0));
        r.staying = r.flicker;
        r.seam.assign(methods, std::vector<std::optional<double>>(count));
        r.seamBlended = r.seam;
        firstFrame(r);
        std::vector<StaticReceiver> receivers = staticReceivers(mFrame);
        std::vector<std::vector<ReceiverTrack>> tracks(
            methods, std::vector<ReceiverTrack>(receivers.size()));
        for (int step = 0; step < mOptions.cascadePathSteps; ++step) {
            Camera camera = cascadePathCamera(mScene.camera, step, mOptions.cascadePathSteps);
            mRenderer.setCamera(camera);
            mRenderer.renderShadowPass(mSettings);
            ShadowMap map = mRenderer.readShadowMap();
            for (int c = 0; c < count; ++c) {
                double texel = map.spec().layers[static_cast<size_t>(c)].texelWs;
                r.texelMin[c] = std::min(r.texelMin[c], texel);
                r.texelMax[c] = std::max(r.texelMax[c], texel);
            }
            for (size_t m = 0; m < methods; ++m) {
                track(map, camera, methodSettings(m), receivers, tracks[m]);
            }
        }
        for (size_t m = 0; m < methods; ++m) {
            for (const ReceiverTrack& t : tracks[m]) {
                if (t.layer < 0 || t.layer >= count) continue;
                r.staying[m][t.layer] += 1.0;
                r.flicker[m][t.layer] += t.hi - t.lo > CASCADE_FLICKER_STEP ? 1.0 : 0.0;
            }
            for (int c = 0; c < count; ++c) {
                if (r.staying[m][c] > 0.0) r.flicker[m][c] /= r.staying[m][c];
            }
        }
        return r;
    }

  private:
    SceneRenderer& mRenderer;
    const Scene& mScene;
    const StabilityOptions& mOptions;
    RenderSettings mSettings;
    FrameSurfaces mFrame;

    RenderSettings methodSettings(size_t m) const {
        RenderSettings s = mSettings;
        s.method = mOptions.methods[m].method;
        s.kernel = mOptions.methods[m].kernel > 0 ? mOptions.methods[m].kernel : s.kernel;
        return s;
    }

    // Frame 0: the receivers' surfaces, the texel density and the seams, per method.
    void firstFrame(PathResult& r) {
        Camera camera = cascadePathCamera(mScene.camera, 0, mOptions.cascadePathSteps);
        mRenderer.setCamera(camera);
        mRenderer.render(mSettings);
        mFrame.size = mRenderer.frameSize();
        mFrame.lightSpace = mRenderer.readLightSpace();
        mFrame.positions = mRenderer.readPositions();
        mFrame.normals = mRenderer.readNormals();
        ShadowMap map = mRenderer.readShadowMap();
        for (const CascadeDensity& d : cascadeDensities(mFrame.lightSpace, mFrame.positions,
                                                        mFrame.size, map.spec(), camera)) {
            r.texelsPerPixel.push_back(d.texelsPerPixelMedian);
        }
        for (size_t m = 0; m < mOptions.methods.size(); ++m) {
            RenderSettings s = methodSettings(m);
            for (int split = 0; split + 1 < CASCADE_SWEEP_CASCADES; ++split) {
                s.cascadeBlend = 0.0f;
                SeamProbe off = seamProbe(map, camera, s, mRenderer.pcfParams(s), mFrame, split);
                s.cascadeBlend = mOptions.cascadeBlend;
                SeamProbe on = seamProbe(map, camera, s, mRenderer.pcfParams(s), mFrame, split);
                if (off.points > 0) r.seam[m][split] = off.difference;
                if (on.points > 0) r.seamBlended[m][split] = on.difference;
            }
        }
    }

    // Each receiver still in the one cascade it read so far, inside that cascade's map: its
    // visibility at this step; the others drop out (layer -1).
    void track(const ShadowMap& map, const Camera& camera, const RenderSettings& s,
               const std::vector<StaticReceiver>& receivers,
               std::vector<ReceiverTrack>& tracks) const {
        PcfParams prm = mRenderer.pcfParams(s);
        for (size_t k = 0; k < receivers.size(); ++k) {
            ReceiverTrack& t = tracks[k];
            if (t.layer == -1) continue;
            const StaticReceiver& p = receivers[k];
            CascadeLookup c = cascadeVisibilityAt(map, camera, s, prm, p.pos, p.normal, p.cosTheta);
            bool inside =
                c.layer < map.layers() &&
                insideLayer(map.spec().layers[static_cast<size_t>(c.layer)], p.pos, map.width());
            if (!inside || (t.layer != -2 && t.layer != c.layer)) {
                t.layer = -1;
                continue;
            }
            t.layer = c.layer;
            t.lo = std::min(t.lo, c.blended);
            t.hi = std::max(t.hi, c.blended);
        }
    }
};

std::string fitSnapName(const std::string& fit, bool snap) {
    return fit + (snap ? ":snap" : ":free");
}

void appendPathRows(const StabilityOptions& options, double lambda, const std::string& fitSnap,
                    const PathResult& r, std::vector<StabilityRow>& rows) {
    const std::string sweep(sweepName(Sweep::Cascades));
    for (size_t m = 0; m < options.methods.size(); ++m) {
        const StabilityMethod& method = options.methods[m];
        for (int c = 0; c < CASCADE_SWEEP_CASCADES; ++c) {
            std::string prefix = fitSnap + ":c" + std::to_string(c) + ":";
            auto row = [&](const char* metric, double y) {
                rows.push_back({sweep, method.method, method.kernel, "normal", "lambda", lambda,
                                prefix + metric, y});
            };
            row("texel_world_min", r.texelMin[c]);
            row("texel_world_max", r.texelMax[c]);
            row("flicker_rate", r.flicker[m][c]);
            row("static_receivers", r.staying[m][c]);
            if (r.seam[m][c]) row("seam_difference", *r.seam[m][c]);
            if (r.seamBlended[m][c]) row("seam_difference_blended", *r.seamBlended[m][c]);
            row("texels_per_pixel_median",
                c < static_cast<int>(r.texelsPerPixel.size()) ? r.texelsPerPixel[c] : 0.0);
        }
    }
}

// The run's methods that cascades work with (cascadeProblem), in its order.
std::vector<StabilityMethod> cascadeMethods(const StabilityOptions& options, const Scene& scene) {
    std::vector<StabilityMethod> out;
    for (const StabilityMethod& m : options.methods) {
        ShadowSettings s = options.base;
        s.method = m.method;
        s.cascades = CASCADE_SWEEP_CASCADES;
        s.shadowDistance = CASCADE_SWEEP_DISTANCE;
        if (!cascadeProblem(scene, s)) out.push_back(m);
    }
    return out;
}

}  // namespace

std::optional<ParamProblem> validateCascadeOptions(const StabilityOptions& o) {
    if (std::find(o.sweeps.begin(), o.sweeps.end(), Sweep::Cascades) == o.sweeps.end()) {
        return std::nullopt;
    }
    if (o.cascadeLambdas.empty()) return ParamProblem{"cascade_lambdas", "", " is empty"};
    for (float l : o.cascadeLambdas) {
        if (!(l >= 0.0f && l <= 1.0f)) {
            return ParamProblem{"cascade_lambdas", "",
                                " " + std::to_string(l) + " is out of range (0..1)"};
        }
    }
    if (o.cascadePathSteps < 2 || o.cascadePathSteps > 64) {
        return ParamProblem{"", "the cascade path's steps are out of range (2..64)", ""};
    }
    if (!(o.cascadeBlend > 0.0f && o.cascadeBlend <= 1.0f)) {
        return ParamProblem{"", "the cascade sweep's blend band is out of range (0..1]", ""};
    }
    if (cascadeMethods(o, cascadeSweepScene()).empty()) {
        return ParamProblem{"",
                            "the cascades sweep needs a method that cascades work with (not "
                            "pcss nor a moment method)",
                            ""};
    }
    return std::nullopt;
}

void runCascadeSweep(const StabilityOptions& options,
                     const std::function<void(const std::string&)>& say,
                     std::vector<StabilityRow>& rows) {
    Scene scene = cascadeSweepScene();
    StabilityOptions run = options;
    run.methods = cascadeMethods(options, scene);
    if (run.methods.empty()) throw std::invalid_argument(validateCascadeOptions(options)->text());
    SceneRenderer renderer(scene);
    RenderSettings base = options.base;
    base.bias = BiasMode::Normal;
    base.cascades = CASCADE_SWEEP_CASCADES;
    base.shadowDistance = CASCADE_SWEEP_DISTANCE;
    base.cascadeBlend = 0.0f;
    base.mapSize = options.mapSize;
    base.frameSize = options.frameSize;
    base.writePositions = true;
    base.method = run.methods.front().method;
    if (run.methods.front().kernel > 0) base.kernel = run.methods.front().kernel;
    int done = 0, total = static_cast<int>(options.cascadeLambdas.size()) * 4;
    for (float lambda : options.cascadeLambdas) {
        for (int fit : {CASCADE_FIT_BOX, CASCADE_FIT_SPHERE}) {
            for (bool snap : {false, true}) {
                RenderSettings s = base;
                s.cascadeSplit = CASCADE_SPLIT_PRACTICAL;
                s.cascadeLambda = lambda;
                s.cascadeFit = fit;
                s.cascadeSnap = snap;
                std::string fitSnap = fitSnapName(std::string(cascadeFitName(fit)), snap);
                if (say) {
                    char line[96];
                    std::snprintf(line, sizeof line, "cascades %d/%d: lambda %g, %s", ++done, total,
                                  static_cast<double>(lambda), fitSnap.c_str());
                    say(line);
                }
                PathResult r = CascadePath(renderer, scene, run, s).run();
                appendPathRows(run, lambda, fitSnap, r, rows);
            }
        }
    }
}

std::vector<CascadePoint> cascadePoints(std::span<const StabilityRow> rows) {
    std::vector<CascadePoint> points;
    std::map<std::string, size_t> index;
    const std::string sweep(sweepName(Sweep::Cascades));
    for (const StabilityRow& r : rows) {
        if (r.sweep != sweep) continue;
        // "FIT:SNAP:cN:METRIC"
        size_t a = r.metric.find(':'), b = r.metric.find(':', a + 1), c = r.metric.find(':', b + 1);
        if (c == std::string::npos || r.metric[b + 1] != 'c') continue;
        std::string key = std::to_string(r.method) + "," + std::to_string(r.kernel) + "," +
                          std::to_string(r.x) + "," + r.metric.substr(0, c);
        auto [it, added] = index.try_emplace(key, points.size());
        if (added) {
            CascadePoint p;
            p.method = r.method;
            p.kernel = r.kernel;
            p.lambda = r.x;
            p.fit = r.metric.substr(0, a);
            p.snap = r.metric.substr(a + 1, b - a - 1) == "snap";
            std::from_chars(r.metric.data() + b + 2, r.metric.data() + c, p.cascade);
            points.push_back(p);
        }
        CascadePoint& p = points[it->second];
        std::string metric = r.metric.substr(c + 1);
        if (metric == "texel_world_min") p.texelWorldMin = r.y;
        if (metric == "texel_world_max") p.texelWorldMax = r.y;
        if (metric == "flicker_rate") p.flickerRate = r.y;
        if (metric == "static_receivers") p.staticReceivers = r.y;
        if (metric == "seam_difference") p.seamDifference = r.y;
        if (metric == "seam_difference_blended") p.seamDifferenceBlended = r.y;
        if (metric == "texels_per_pixel_median") p.texelsPerPixelMedian = r.y;
    }
    return points;
}

std::string cascadeCsv(std::span<const StabilityRow> rows) {
    std::string out(CASCADE_CSV_HEADER);
    out += "\n";
    auto num = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.9g", v);
        return std::string(buf);
    };
    auto optional = [&](const std::optional<double>& v) { return v ? num(*v) : std::string(); };
    // A lambda as the options gave it (a float): "0.3", not "0.300000012".
    auto lambdaText = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", static_cast<double>(static_cast<float>(v)));
        return std::string(buf);
    };
    for (const CascadePoint& p : cascadePoints(rows)) {
        out += std::string(methodInfo(p.method).name) + "," + std::to_string(p.kernel) + "," +
               std::string(cascadeSplitOfLambda(p.lambda)) + "," + lambdaText(p.lambda) + "," +
               p.fit + "," + (p.snap ? "true" : "false") + "," + std::to_string(p.cascade) + "," +
               num(p.texelWorldMin) + "," + num(p.texelWorldMax) + "," + num(p.flickerRate) + "," +
               num(p.staticReceivers) + "," + optional(p.seamDifference) + "," +
               optional(p.seamDifferenceBlended) + "," + num(p.texelsPerPixelMedian) + "\n";
    }
    return out;
}

}  // namespace pcf
