#include "app/render_options.h"

#include <filesystem>

#include "app/cli_util.h"
#include "kernel/methods.h"
#include "scene/presets.h"
#include "scene/scene_file.h"

namespace pcf {

void RenderOptions::addTo(CLI::App* sub, const std::string& defaultScene) {
    mDefaultScene = defaultScene;
    sub->add_option("--scene", scene, "built-in scene: box-on-plane, sphere-over-plane, pole, "
                                      "grazing, stairs");
    sub->add_option("--scene-file", sceneFile, "scene file (TOML)");
    sub->add_option("--method", method, "PCF method id (see `pcfscope methods`)");
    sub->add_option("--kernel", kernel, "kernel size N (1..8; tent: 3, 5, 7)");
    sub->add_option("--radius", radius, "poisson: disk radius in texels");
    sub->add_flag("--rotate", rotate, "poisson: rotate the disk per pixel");
    sub->add_option("--bias", bias, "bias mode: none, constant");
    sub->add_option("--constant-bias", constantBias,
                    "constant bias in light depth units (ref = z - bias)");
    sub->add_option("--cull", cull, "faces culled in the shadow pass: back, front, none");
    sub->add_option("--map-size", mapSize, "shadow map size in texels (4..4096)");
    sub->add_option("--depth-format", depthFormat, "shadow map depth format: 16, 24, 32f");
    sub->add_option("--size", size, "frame size WxH");
}

RenderSettings RenderOptions::settings() const {
    RenderSettings s;
    std::optional<int> id = methodFromName(method);
    if (!id) throw UsageError("unknown method '" + method + "' (known: " + methodNameList() + ")");
    s.method = *id;
    s.kernel = kernel;
    s.radius = radius;
    s.rotatePerPixel = rotate;
    if (auto why = validateParams(s.pcfParams())) throw UsageError(*why);
    std::optional<BiasMode> b = biasModeFromName(bias);
    if (!b) throw UsageError("unknown bias mode '" + bias + "' (known: none, constant)");
    s.bias = *b;
    requireRange("--constant-bias", constantBias, -1.0f, 1.0f);
    s.constantBias = constantBias;
    std::optional<CullMode> c = cullModeFromName(cull);
    if (!c) throw UsageError("unknown --cull '" + cull + "' (known: back, front, none)");
    s.shadowCull = *c;
    if (mapSize < MIN_MAP_SIZE || mapSize > MAX_MAP_SIZE) {
        throw UsageError("--map-size " + std::to_string(mapSize) + " is out of range (" +
                         std::to_string(MIN_MAP_SIZE) + ".." + std::to_string(MAX_MAP_SIZE) + ")");
    }
    s.mapSize = mapSize;
    std::optional<DepthFormat> f = depthFormatFromName(depthFormat);
    if (!f) throw UsageError("unknown --depth-format '" + depthFormat + "' (known: 16, 24, 32f)");
    s.depthFormat = *f;
    s.frameSize = parseSize("--size", size, MAX_FRAME_SIDE);
    return s;
}

Scene RenderOptions::loadScene() const {
    if (!scene.empty() && !sceneFile.empty()) {
        throw UsageError("give --scene or --scene-file, not both");
    }
    if (!sceneFile.empty()) return parseSceneFile(sceneFile);
    std::string name = scene.empty() ? mDefaultScene : scene;
    if (name.empty()) throw UsageError("needs --scene PRESET or --scene-file FILE");
    std::optional<Scene> preset = presetScene(name);
    if (!preset) {
        std::string known;
        for (std::string_view n : presetNames()) known += (known.empty() ? "" : ", ") + std::string(n);
        throw UsageError("unknown scene '" + name + "' (known: " + known + ")");
    }
    return *preset;
}

void requireWritable(const std::string& path, bool force) {
    std::error_code ec;
    if (!force && std::filesystem::exists(path, ec)) {
        throw UsageError(path + " already exists; pass --force to overwrite it");
    }
}

}  // namespace pcf
