#include "app/raw_folder.h"

#include <cmath>
#include <limits>
#include <type_traits>
#include <variant>

#include "app/cli_util.h"
#include "base/input_file.h"
#include "kernel/methods.h"
#include "kernel/shading.h"
#include "kernel/trace_json.h"

namespace pcf {

namespace {

// The render.json that `render --raw` writes, read by nlohmann-json. Throws UsageError naming
// the file when it is not JSON, or a key is missing or of the wrong type.
Json readRenderJson(const std::string& text, const std::string& path) {
    Json j = Json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        throw UsageError("render.json is not a JSON object (" + path + ")");
    }
    return j;
}

}  // namespace

namespace {

std::string jsonField(const Json& json, const std::string& key, const std::string& path) {
    auto it = json.find(key);
    if (it == json.end()) throw UsageError("render.json has no \"" + key + "\" (" + path + ")");
    if (!it->is_string()) {
        throw UsageError("render.json: \"" + key + "\" is not a string (" + path + ")");
    }
    return it->get<std::string>();
}

}  // namespace

namespace {

float jsonFloat(const Json& json, const std::string& key, const std::string& path) {
    auto it = json.find(key);
    if (it == json.end()) throw UsageError("render.json has no \"" + key + "\" (" + path + ")");
    // Asked as a double: 1e300 is a JSON number, but no float (the cast would be undefined).
    if (!it->is_number() || !std::isfinite(it->get<double>()) ||
        std::abs(it->get<double>()) > static_cast<double>(std::numeric_limits<float>::max())) {
        throw UsageError("render.json: \"" + key + "\" is not a number (" + path + ")");
    }
    return it->get<float>();
}

}  // namespace

namespace {

bool jsonBool(const Json& json, const std::string& key, const std::string& path) {
    auto it = json.find(key);
    if (it == json.end()) throw UsageError("render.json has no \"" + key + "\" (" + path + ")");
    if (!it->is_boolean()) {
        throw UsageError("render.json: \"" + key + "\" is not true or false (" + path + ")");
    }
    return it->get<bool>();
}

}  // namespace

namespace {

FloatImage readImage(const std::filesystem::path& path, int channels) {
    FloatImage img;
    try {
        img = readFloatImage(path.string());
    } catch (const ImageError& e) {
        throw UsageError(e.what());
    }
    if (img.channels != channels) {
        throw UsageError(path.string() + ": has " + std::to_string(img.channels) +
                         " channels, expected " + std::to_string(channels));
    }
    return img;
}

}  // namespace

namespace {

// A whole number in render.json, within the table's range of parameter p. Checked as a double
// before the cast: a float outside int's range (1e30) is undefined behaviour there.
int jsonInt(const Json& json, const ParamInfo& p, const std::string& path) {
    std::string key(p.key);
    double v = static_cast<double>(jsonFloat(json, key, path));
    if (!(v >= p.min && v <= p.max) || v != std::floor(v)) {
        throw UsageError("render.json: \"" + key + "\" is not a whole number in [" +
                         std::to_string(static_cast<int>(p.min)) + ", " +
                         std::to_string(static_cast<int>(p.max)) + "] (" + path + ")");
    }
    return static_cast<int>(v);
}

}  // namespace

namespace {

// Parameter p's value in render.json, into s: written as the table's field says
// (app/render_options.h settingsJson): a number, true or false, or a name.
void readParam(const Json& json, const ParamInfo& p, ShadowSettings& s, const std::string& path) {
    std::string key(p.key);
    std::visit(
        [&](const auto& field) {
            using F = std::decay_t<decltype(field)>;
            if constexpr (std::is_same_v<F, float ShadowSettings::*>) {
                s.*field = jsonFloat(json, key, path);
            } else if constexpr (std::is_same_v<F, int ShadowSettings::*>) {
                s.*field = jsonInt(json, p, path);
            } else if constexpr (std::is_same_v<F, bool ShadowSettings::*>) {
                s.*field = jsonBool(json, key, path);
            } else {
                std::string name = jsonField(json, key, path);
                auto value = field.fromName(name);
                if (!value) {
                    throw UsageError("render.json: unknown " + std::string(field.noun) + " '" +
                                     name + "' (" + path + ")");
                }
                s.*field.field = *value;
            }
        },
        p.field);
}

}  // namespace

const PcfMapLayer* lookupLayer(const RawSettings& r, int layer) {
    if (!r.map || layer < 0 || layer >= static_cast<int>(r.map->layers.size())) return nullptr;
    if (r.map->layers.size() > 1 && !r.cascadeEyeDir) return nullptr;
    const PcfMapLayer& l = r.map->layers[static_cast<size_t>(layer)];
    return l.texelWs > 0.0f ? &l : nullptr;
}

namespace {

// A vec3 of render.json: 3 finite numbers.
vec3 jsonVec3(const Json& json, const std::string& key, const std::string& path) {
    auto it = json.find(key);
    bool ok = it != json.end() && it->is_array() && it->size() == 3;
    for (size_t i = 0; ok && i < 3; ++i) {
        ok = (*it)[i].is_number() && std::isfinite((*it)[i].get<double>()) &&
             std::abs((*it)[i].get<double>()) <= 1e30;
    }
    if (!ok) throw UsageError("render.json: \"" + key + "\" is not 3 numbers (" + path + ")");
    return vec3((*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>());
}

}  // namespace

namespace {

// A cascaded map's "cascade_camera" (eye, view_dir), required: without it no pixel's cascade
// can be chosen again.
std::pair<vec3, vec3> readCascadeCamera(const Json& map, const std::string& where) {
    auto it = map.find("cascade_camera");
    if (it == map.end() || !it->is_object()) {
        throw UsageError(
            "render.json: a cascaded \"map\" needs \"cascade_camera\" (eye, "
            "view_dir) to choose each pixel's cascade (" +
            where + ")");
    }
    return {jsonVec3(*it, "eye", where), jsonVec3(*it, "view_dir", where)};
}

}  // namespace

RawSettings readRawSettings(const std::filesystem::path& dir) {
    std::filesystem::path jsonPath = dir / "render.json";
    std::string where = jsonPath.string();
    // The input path every text input takes (base/input_file.h): a FIFO or a device is
    // refused before it is opened, a file over the size limit before it is read.
    Json json = readRenderJson(readInputFile(where), where);

    RawSettings r;
    for (const ParamInfo& p : allParams()) {
        if (!p.rawJson) continue;
        // Keys that folders written before the parameter lack: its default (the table says which).
        if (p.rawJsonMayLack && !json.contains(std::string(p.key))) continue;
        readParam(json, p, r.settings, where);
    }
    // In the table's ranges, as every command line and lesson value is.
    if (std::optional<ParamProblem> why = checkSettingRanges(r.settings)) {
        throw UsageError("render.json: " + why->text() + " (" + where + ")");
    }
    // pcss's light size in the map; folders written before pcss have none (0: no method used it).
    float penumbraScale = 0.0f;
    if (json.contains("penumbra_scale")) penumbraScale = jsonFloat(json, "penumbra_scale", where);
    r.prm = r.settings.pcfParams(vec2(1.0f, 0.0f), penumbraScale);
    // A spot map's near and far for pcss; folders written before them have none (0: linear).
    if (json.contains("pcss_depth_near") || json.contains("pcss_depth_far")) {
        r.prm.depthNear = jsonFloat(json, "pcss_depth_near", where);
        r.prm.depthFar = jsonFloat(json, "pcss_depth_far", where);
    }
    r.bias = r.settings.kernelBias();
    if (json.contains("map")) {
        std::string why;
        r.map = mapSpecFromJson(json["map"], why);
        if (!r.map) throw UsageError("render.json: " + why + " (" + where + ")");
        if (r.map->layers.size() > 1) r.cascadeEyeDir = readCascadeCamera(json["map"], where);
    }
    // render.json's keys are the kernel's words.
    if (auto why = validateParams(r.prm))
        throw UsageError("render.json: " + *why + " (" + where + ")");
    return r;
}

namespace {

// The map shadowmap.exr holds: render.json's "map", which must match the image's size, in the
// texel kind the method reads in the folder's depth_format (checkMapTexels holds "map" to it
// once the image has been checked against that format); for a folder without one, the image's
// size, one layer.
MapSpec rawMapSpec(const ShadowMap& image, const RawSettings& r, const std::string& where) {
    TexelKind kind = mapTexelKind(r.settings.method, r.settings.depthFormat, r.settings.momentBits);
    MapSpec spec = r.map.value_or(MapSpec{image.size(), kind, {MapSpec::unfittedLayer()}});
    spec.texels = kind;
    if (texelKindInfo(kind).channels != image.spec().texel().channels) {
        throw UsageError("shadowmap.exr has " + std::to_string(image.spec().texel().channels) +
                         " channel(s), but " + std::string(methodInfo(r.settings.method).name) +
                         " reads a map of " + std::to_string(texelKindInfo(kind).channels) + " (" +
                         where + ")");
    }
    // A cascaded map's layers lie one above the other in the image (render/image_io.h).
    int layers = static_cast<int>(spec.layers.size());
    if (spec.size.x != image.width() || spec.size.y * layers != image.height()) {
        throw UsageError("render.json: \"map\" is " + std::to_string(spec.size.x) + "x" +
                         std::to_string(spec.size.y) + " in " + std::to_string(layers) +
                         " layer(s), but shadowmap.exr is " + std::to_string(image.width()) + "x" +
                         std::to_string(image.height()) + " (" + where + ")");
    }
    return spec;
}

}  // namespace

void checkMapTexels(const RawSettings& r, const std::string& where) {
    TexelKind kind = mapTexelKind(r.settings.method, r.settings.depthFormat, r.settings.momentBits);
    if (!r.map || r.map->texels == kind) return;
    throw UsageError("render.json: \"map\" holds texels " +
                     std::string(texelKindName(r.map->texels)) + ", but " +
                     std::string(methodInfo(r.settings.method).name) + " reads depth_format " +
                     std::string(texelKindName(kind)) + " (" + where + ")");
}

float pixelViewDepth(const RawImages& img, const RawSettings& r, size_t k) {
    const float* p = &img.positions.data[4 * k];
    return pcfViewDepth(vec3(p[0], p[1], p[2]), r.cascadeEyeDir->first, r.cascadeEyeDir->second);
}

int pixelLayer(const RawImages& img, const RawSettings& r, size_t k) {
    if (!r.map || r.map->layers.size() < 2) return 0;
    int count = static_cast<int>(r.map->layers.size());
    vec4 cascadeFar(1e30f);
    for (int c = 0; c < count; ++c)
        cascadeFar[c] = r.map->layers[static_cast<size_t>(c)].viewDepth.y;
    return pcfCascadeLayer(pixelViewDepth(img, r, k), cascadeFar, count);
}

std::optional<vec2> nextReceiverPlane(const RawImages& img, size_t k) {
    if (img.nextPlanes.data.empty()) return std::nullopt;
    return vec2(img.nextPlanes.data[4 * k], img.nextPlanes.data[4 * k + 1]);
}

bool recomputesWhole(const RawImages& img, const RawSettings& r) {
    if (!r.map) return false;
    for (int layer = 0; layer < static_cast<int>(r.map->layers.size()); ++layer) {
        if (!lookupLayer(r, layer)) return false;
    }
    return !img.positions.data.empty() && !img.normals.data.empty();
}

namespace {

// An image of the folder the size of lightspace.exr with 4 channels, or an empty one when the
// file does not exist.
FloatImage readOptionalImage(const std::filesystem::path& path, const FloatImage& like) {
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec))) return {};
    FloatImage img = readImage(path, 4);
    if (img.width != like.width || img.height != like.height) {
        throw UsageError(path.string() + " and lightspace.exr differ in size");
    }
    return img;
}

}  // namespace

RawImages readRawImages(const std::filesystem::path& dir, const RawSettings& r) {
    RawImages img;
    try {
        img.map = readMapImage((dir / "shadowmap.exr").string());
    } catch (const ImageError& e) {
        throw UsageError(e.what());
    }
    img.map.setSpec(rawMapSpec(img.map, r, (dir / "render.json").string()));
    img.lightSpace = readImage(dir / "lightspace.exr", 4);
    img.visibility = readImage(dir / "visibility.exr", 1);
    const FloatImage& ls = img.lightSpace;
    if (ls.width != img.visibility.width || ls.height != img.visibility.height) {
        throw UsageError("lightspace.exr and visibility.exr differ in size (" + dir.string() + ")");
    }
    // Each pixel's plane (dz/du, dz/dv, as the shader derived them) and depth before bias.
    img.planes = readImage(dir / "dzduv.exr", 4);
    if (img.planes.width != ls.width || img.planes.height != ls.height) {
        throw UsageError("dzduv.exr and lightspace.exr differ in size (" + dir.string() + ")");
    }
    img.positions = readOptionalImage(dir / "positions.exr", ls);
    img.normals = readOptionalImage(dir / "normals.exr", ls);
    img.nextPlanes = readOptionalImage(dir / "next_dzduv.exr", ls);
    for (int k = 0; k < img.map.layers(); ++k) img.layers.push_back(img.map.layerMap(k));
    return img;
}

float rawCascadeDensity(const std::filesystem::path& dir, int layer) {
    std::string where = (dir / "render.json").string();
    Json json = readRenderJson(readInputFile(where), where);
    auto map = json.find("map");
    if (map == json.end() || !map->contains("cascades")) return -1.0f;
    const Json& cascades = (*map)["cascades"];
    if (!cascades.is_array() || layer < 0 || static_cast<size_t>(layer) >= cascades.size() ||
        !cascades[static_cast<size_t>(layer)].contains("texels_per_pixel_max")) {
        return -1.0f;
    }
    return jsonFloat(cascades[static_cast<size_t>(layer)], "texels_per_pixel_max", where);
}

}  // namespace pcf
