// raw_folder.h: a `render --raw` folder read back: render.json's settings and map (with a
// cascaded map's camera), and its images (the map, each pixel's lookup, visibility, plane,
// position and normal). `verify` checks the folder with them; `trace --raw` traces one pixel.
// Bad input is a UsageError naming the file.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kernel/bias.h"
#include "kernel/settings.h"
#include "kernel/shadow_map.h"
#include "render/image_io.h"

namespace pcf {

// What `render --raw` rendered with, from its render.json: the settings the parameter table
// marks rawJson, what the kernel filtered with, and the map (whose layer's fit each pixel's
// lookup was computed from besides its position and normal).
struct RawSettings {
    ShadowSettings settings;
    // The map as render.json describes it ("map"); folders written before it have none.
    std::optional<MapSpec> map;
    PcfParams prm;
    PcfBias bias = PcfBias(PCF_BIAS_CONSTANT, vec2(0.0f), 0.0f, DEFAULT_RPDB_MAX);
    // A cascaded map's camera as the camera pass had it ("map" -> "cascade_camera"): the eye
    // and the unit view direction each receiver's view depth is measured along.
    std::optional<std::pair<vec3, vec3>> cascadeEyeDir;
};

// A layer scene.frag looked pixels up with besides their position and normal: its fit (the
// light's clip matrix) and one texel's world size at clip w = 1. None for a folder written before
// render.json held the map, or a map without a texel size; a cascaded map's layers only with
// the camera that picked them.
const PcfMapLayer* lookupLayer(const RawSettings& r, int layer = 0);

RawSettings readRawSettings(const std::filesystem::path& dir);

// render.json's "map" names the texel kind its method reads in its depth_format.
void checkMapTexels(const RawSettings& r, const std::string& where);

// The folder's images: the map compared with, each pixel's lookup and visibility, each pixel's
// plane (dzduv.exr), and where present what the lookup was computed from: the world position
// (positions.exr) and the normal with cos(theta) (normals.exr).
struct RawImages {
    ShadowMap map;
    FloatImage lightSpace;  // u, v, ref, receiver (1 or 0)
    FloatImage visibility;
    FloatImage planes;     // dz/du, dz/dv, z before bias, 1 on receivers (dzduv.exr)
    FloatImage positions;  // world x, y, z, 1 where drawn; empty when the folder has none
    FloatImage normals;    // n facing the camera, cos(theta); empty when the folder has none
    // With a blend band, each pixel's plane in the next cascade (next_dzduv.exr, as planes:
    // dz/du, dz/dv, z before bias, 1 on receivers); empty when the folder has none.
    FloatImage nextPlanes;
    // Each layer of the map as a map of its own (a cascade's, looked up by the envelope).
    std::vector<ShadowMap> layers;
};

// The layer of the map pixel k read: 0 for one layer; for cascades the one its view depth falls
// in (shared/pcf_shading.h pcfViewDepth and pcfCascadeLayer, as scene.frag picks it), from its
// world position and render.json's cascade camera; the layer count past the last.
int pixelLayer(const RawImages& img, const RawSettings& r, size_t k);

// Whether each pixel's lookup can be recomputed whole: the layer's fit, positions and normals.
bool recomputesWhole(const RawImages& img, const RawSettings& r);

// Pixel k's view depth (shared/pcf_shading.h pcfViewDepth), from its world position and
// render.json's cascade camera: what picks its cascade (pixelLayer) and weighs its blend band
// (pcfCascadeBlendWeight). For a cascaded map's folder with positions.exr.
float pixelViewDepth(const RawImages& img, const RawSettings& r, size_t k);

// Pixel k's receiver plane in the next cascade (next_dzduv.exr's dz/du, dz/dv), with which the
// camera pass filtered its blend band under receiver-plane bias; nullopt when the folder has
// no next_dzduv.exr (rendered without a band, or before render --raw wrote it).
std::optional<vec2> nextReceiverPlane(const RawImages& img, size_t k);

RawImages readRawImages(const std::filesystem::path& dir, const RawSettings& r);

// A cascaded map's measured density of cascade `layer` (render.json's "map" -> "cascades":
// texels_per_pixel_max); negative when the folder's render.json has none.
float rawCascadeDensity(const std::filesystem::path& dir, int layer);

}  // namespace pcf
