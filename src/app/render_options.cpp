#include "app/render_options.h"

#include <filesystem>

#include "app/cli_util.h"
#include "app/session.h"
#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "lesson/lesson.h"
#include "scene/presets.h"
#include "scene/scene_file.h"

namespace pcf {

void addBiasOptions(CLI::App* sub, std::string& bias, float& constantBias, float& slopeBias,
                    float& slopeMax, float& normalOffset, float& softScale, float& rpdbMax) {
    sub->add_option("--bias", bias,
                    "bias mode: " + biasNameList() +
                        " (README \"Bias modes\"; every mode but none subtracts --constant-bias)");
    sub->add_option("--constant-bias", constantBias,
                    "depth subtracted from z in light depth units (ref = z - B), default 0.002");
    sub->add_option("--slope-bias", slopeBias,
                    "slope: S in ref = z - min(B + S * tan(theta), M), default 0.001");
    sub->add_option("--slope-max", slopeMax, "slope: the cap M, light depth units, default 0.01");
    sub->add_option("--normal-offset", normalOffset,
                    "normal: K, texels the receiver moves along its normal (times sin(theta)), "
                    "default 1.5");
    sub->add_option("--soft-scale", softScale,
                    "soft: lit = (depth > ref) * saturate((depth - ref) * SCALE), default 2048");
    sub->add_option("--rpdb-max", rpdbMax,
                    "receiver-plane: cap M on each component of dz/duv, light depth per uv unit "
                    "(the whole map), default 100");
}

void addFilterOptions(CLI::App* sub, std::string& method, int& kernel, float& radius,
                      std::string& weights, float& sigma, std::string& precision) {
    sub->add_option("--method", method, "PCF method id (see `pcfscope methods`)");
    sub->add_option("--kernel", kernel, kernelOptionHelp());
    sub->add_option("--radius", radius, "poisson: disk radius in texels");
    sub->add_option("--weights", weights,
                    "pcf-naive, pcf-gather: weights of the N x N lookups: box, binomial, gaussian");
    sub->add_option("--sigma", sigma, "gaussian weights: standard deviation in texels");
    sub->add_option("--precision", precision,
                    "texel position inside hardware taps and gathers: exact, hw8 (1/256 texel)");
}

int methodOption(const std::string& name) {
    std::optional<int> id = methodFromName(name);
    if (!id) throw UsageError("unknown method '" + name + "' (known: " + methodNameList() + ")");
    return *id;
}

int weightsOption(const std::string& name) {
    std::optional<int> w = weightsFromName(name);
    if (!w) throw UsageError("unknown --weights '" + name + "' (known: box, binomial, gaussian)");
    return *w;
}

int precisionOption(const std::string& name) {
    std::optional<int> p = precisionFromName(name);
    if (!p) throw UsageError("unknown --precision '" + name + "' (known: exact, hw8)");
    return *p;
}

BiasMode biasModeOption(const std::string& name) {
    std::optional<BiasMode> b = biasModeFromName(name);
    if (!b) throw UsageError("unknown bias mode '" + name + "' (known: " + biasNameList() + ")");
    return *b;
}

CullMode cullOption(const std::string& name) {
    std::optional<CullMode> c = cullModeFromName(name);
    if (!c) {
        throw UsageError("unknown --cull '" + name + "' (known: " + std::string(CULL_MODE_NAMES) +
                         ")");
    }
    return *c;
}

DepthFormat depthFormatOption(const std::string& name) {
    std::optional<DepthFormat> f = depthFormatFromName(name);
    if (!f) {
        throw UsageError("unknown --depth-format '" + name +
                         "' (known: " + std::string(DEPTH_FORMAT_NAMES) + ")");
    }
    return *f;
}

void checkBiasOptions(const BiasParams& bias, int method) {
    if (auto why = cliBiasProblem(bias)) throw UsageError(*why);
    if (auto why = validateBias(bias.mode, method)) throw UsageError(*why);
}

void RenderOptions::addTo(CLI::App* sub, const std::string& defaultScene) {
    mDefaultScene = defaultScene;
    mSub = sub;
    sub->add_option("--lesson", lesson,
                    "a lesson (path, number or name): its scene and its step's settings; "
                    "options given here override them");
    sub->add_option("--step", lessonStep, "with --lesson: the step whose settings to use");
    sub->add_option("--scene", scene,
                    "built-in scene: box-on-plane, sphere-over-plane, pole, "
                    "grazing, stairs");
    sub->add_option("--scene-file", sceneFile, "scene file (TOML)");
    addFilterOptions(sub, method, kernel, radius, weights, sigma, precision);
    sub->add_flag("--rotate", rotate, "poisson: rotate the disk per pixel");
    addBiasOptions(sub, bias, constantBias, slopeBias, slopeMax, normalOffset, softScale, rpdbMax);
    sub->add_option("--cull", cull, "faces culled in the shadow pass: back, front, none");
    sub->add_option("--polygon-offset", polygonOffset,
                    "slope-scaled bias in the shadow pass: FACTOR,UNITS for glPolygonOffset");
    sub->add_option("--map-size", mapSize, "shadow map size in texels (4..4096)");
    sub->add_option("--depth-format", depthFormat, "shadow map depth format: 16, 24, 32f");
    sub->add_option("--size", size, "frame size WxH");
}

bool RenderOptions::given(const char* option) const {
    return mSub != nullptr && mSub->count(option) > 0;
}

RenderSettings RenderOptions::settings() const {
    RenderSettings s;
    glm::ivec2 frame = parseSize("--size", size, MAX_FRAME_SIDE);
    bool fromLesson = !lesson.empty();
    if (fromLesson) {
        Lesson l = parseLessonFile(resolveLesson(lesson));
        requireIntRange("--step", lessonStep, 1, static_cast<int>(l.steps.size()));
        s = renderSettingsFor(l.steps[static_cast<size_t>(lessonStep - 1)].settings, frame);
    }
    auto use = [&](const char* option) { return !fromLesson || given(option); };
    if (use("--method")) s.method = methodOption(method);
    checkGivenKernelOptions(given("--kernel"), kernel, given("--radius"), radius);
    if (use("--kernel")) s.kernel = kernel;
    if (use("--radius")) s.radius = radius;
    if (use("--rotate")) s.rotatePerPixel = rotate;
    if (use("--weights")) s.weights = weightsOption(weights);
    if (use("--sigma")) s.sigma = sigma;
    if (use("--precision")) s.precision = precisionOption(precision);
    if (auto why = cliParamsProblem(s.pcfParams())) throw UsageError(*why);
    if (use("--bias")) s.bias = biasModeOption(bias);
    if (use("--constant-bias")) s.constantBias = constantBias;
    if (use("--slope-bias")) s.slopeBias = slopeBias;
    if (use("--slope-max")) s.slopeMax = slopeMax;
    if (use("--normal-offset")) s.normalOffset = normalOffset;
    if (use("--soft-scale")) s.softScale = softScale;
    if (use("--rpdb-max")) s.rpdbMax = rpdbMax;
    checkBiasOptions(s.biasParams(), s.method);
    if (use("--cull")) s.shadowCull = cullOption(cull);
    if (use("--polygon-offset") && !polygonOffset.empty()) {
        s.polygonOffset = parseVec2("--polygon-offset", polygonOffset);
        requireRange("--polygon-offset factor", s.polygonOffset.x, -64.0f, 64.0f);
        requireRange("--polygon-offset units", s.polygonOffset.y, -1.0e6f, 1.0e6f);
    }
    if (use("--map-size")) {
        requireIntRange("--map-size", mapSize, MIN_MAP_SIZE, MAX_MAP_SIZE);
        s.mapSize = mapSize;
    }
    if (use("--depth-format")) s.depthFormat = depthFormatOption(depthFormat);
    s.frameSize = frame;
    return s;
}

Scene RenderOptions::loadScene() const {
    if (static_cast<int>(!scene.empty()) + static_cast<int>(!sceneFile.empty()) +
            static_cast<int>(!lesson.empty()) >
        1) {
        throw UsageError("give one of --scene, --scene-file or --lesson");
    }
    if (!lesson.empty()) return parseLessonFile(resolveLesson(lesson)).scene;
    if (!sceneFile.empty()) return parseSceneFile(sceneFile);
    std::string name = scene.empty() ? mDefaultScene : scene;
    if (name.empty()) throw UsageError("needs --scene PRESET, --scene-file FILE or --lesson L");
    std::optional<Scene> preset = presetScene(name);
    if (!preset) {
        std::string known;
        for (std::string_view n : presetNames())
            known += (known.empty() ? "" : ", ") + std::string(n);
        throw UsageError("unknown scene '" + name + "' (known: " + known + ")");
    }
    return *preset;
}

}  // namespace pcf
