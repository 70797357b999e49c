// shadow_map.h: the shadow map as a value. MapSpec says what a map holds (its size, its texel
// kind, and its layers, each with the fit the light saw it through); ShadowMap is a map's texels
// as the CPU reads them, with the spec they were made under. The spec travels whole from the
// depth pass (render/scene_renderer) to the shaders' uniforms (render/pcf_programs), the trace
// (kernel/trace), the inspector (overlay/), render.json and `verify` (app/).
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/pcf_shared.h"

namespace pcf {

// What one texel of a map holds: a depth in a fixed-point or float format, or the moments of
// the depths under it (E[z], E[z^2] for 2; the first four powers for 4) in half or single
// floats. Switches over TexelKind have no `default:`: a new kind is one entry here, its row of
// texelKindInfo (shadow_map.cpp) and its GL format (render/render_settings.cpp, glTexelFormat).
enum class TexelKind { D16, D24, D32F, Moments2F16, Moments2F32, Moments4F16, Moments4F32 };

// Everything the rest of pcfscope asks about a texel kind.
struct TexelKindInfo {
    std::string_view name;  // the command line's, render.json's and the trace's: "16", "32f"
    int channels;           // 1 for a depth; 2 or 4 moments
    int bits;               // per channel: 16, 24 or 32
    bool fixedPoint;        // unsigned normalised: D_ref clamped to [0,1] (GL 4.5, 8.23.1)
    bool depth;             // a depth the texture unit can compare (sampler2DShadow)
};
const TexelKindInfo& texelKindInfo(TexelKind kind);
std::string_view texelKindName(TexelKind kind);
// Any kind by its name ("16", "24", "32f", "moments2-16f", ...); "32" and "32F" are 32f.
std::optional<TexelKind> texelKindFromName(std::string_view name);
// Every kind, in the enum's order.
std::span<const TexelKind> allTexelKinds();

// How many layers a map may have (cascades: one per split); uniforms and render.json hold up to
// this many.
constexpr int MAX_MAP_LAYERS = 4;

// What a map holds: size and texel kind (the same for every layer) and its layers, each with its
// fit (PcfMapLayer, shaders/shared/pcf_kernel.h: the light's clip from world, a perspective
// map's depth range, a texel's world size). One layer today; a cascaded map has one per split.
struct MapSpec {
    glm::ivec2 size{0, 0};
    TexelKind texels = TexelKind::D32F;
    std::vector<PcfMapLayer> layers{unfittedLayer()};
    // A cascaded map (more than one layer, scene/cascade_fit.h): the view depths [n, f] the
    // settings name (the camera's near plane, the shadow distance), and with cascade_bounds
    // depth the view depths of the frame's visible receivers as measured (dmin, dmax), which
    // narrowed what the layers split (kernel/cascades.h cascadeSplitSpan). (0, 0) and nullopt
    // for one layer, or a map read from a file that does not say.
    glm::vec2 cascadeDepths{0.0f};
    std::optional<glm::vec2> visibleDepths;

    // The layer of a map with no light to it (a map read from a file, the built-in example):
    // identity fit, orthographic, texel size unknown (0).
    static PcfMapLayer unfittedLayer();
    const TexelKindInfo& texel() const { return texelKindInfo(texels); }
    int fixedPointBits() const { return texel().fixedPoint ? texel().bits : 0; }
    bool operator==(const MapSpec& o) const;
};

// Why a spec cannot be a map (a size below 1, no layers or more than MAX_MAP_LAYERS), in words;
// nullopt when it can.
std::optional<std::string> checkMapSpec(const MapSpec& spec);

// A map's texels as the CPU reads them: W x H per layer, each texel `channels` floats (a depth
// in [0,1], 0 = near the light, or its moments). Texel (i, j) is column i, row j of the image as
// stored (row 0 = first scanline = GL texel row 0); its centre is at uv ((i + 0.5) / W,
// (j + 0.5) / H). The constructors make a one-layer 32F depth map; setSpec says otherwise.
class ShadowMap {
  public:
    ShadowMap() = default;
    ShadowMap(int width, int height, float fill = 1.0f);
    ShadowMap(int width, int height, std::vector<float> depths);
    // The texels of a map of any spec: layer by layer, row by row, channels interleaved; as many
    // as the spec says (std::invalid_argument otherwise).
    ShadowMap(MapSpec spec, std::vector<float> texels);

    const MapSpec& spec() const { return mSpec; }
    // Replaces the spec; its size, channels and layers must hold exactly the texels stored
    // (std::invalid_argument otherwise).
    void setSpec(MapSpec spec);
    // The same spec with another texel kind of as many channels (a 32F map labelled 16-bit).
    void setTexelKind(TexelKind kind);

    int width() const { return mSpec.size.x; }
    int height() const { return mSpec.size.y; }
    glm::ivec2 size() const { return mSpec.size; }
    int layers() const { return static_cast<int>(mSpec.layers.size()); }
    // Layer 0's first channel: the depth of a depth map.
    float depth(int i, int j) const { return mTexels[index(i, j)]; }
    void setDepth(int i, int j, float d) { mTexels[index(i, j)] = d; }
    // Every texel of every layer: layer by layer, row by row, channels interleaved.
    const std::vector<float>& depths() const { return mTexels; }
    // One layer's texels (the kernel reads one layer at a time).
    const float* layerTexels(int layer) const;
    // One layer as a map of its own (its spec's layers: that one); std::out_of_range for none.
    ShadowMap layerMap(int layer) const;

    // The bits of the fixed-point format the depths were stored in (16 or 24), 0 for float.
    // A fixed-point map clamps D_ref to [0,1] in every comparison (GL 4.5, 8.23.1), and its
    // depths are the sampler's own floats for the stored integers (see readSampledDepth).
    int fixedPointBits() const { return mSpec.fixedPointBits(); }
    bool isFixedPoint() const { return mSpec.texel().fixedPoint; }

    // The first value that is not a depth in [0,1] (NaN, infinite, out of range), described in
    // words ("texel (3, 4) is NaN"); nullopt when every value is fine. A moments map's values
    // need only be finite.
    std::optional<std::string> findInvalidTexel() const;

  private:
    size_t index(int i, int j) const {
        return (static_cast<size_t>(j) * mSpec.size.x + i) * mSpec.texel().channels;
    }
    MapSpec mSpec;
    std::vector<float> mTexels;
};

// The built-in example of `pcfscope trace --example`: an 8 x 8 map of a ground plane (depths
// 0.55 .. 0.62, rising by row) with an occluder over the corner i >= 4, j >= 2 (0.30 .. 0.35).
ShadowMap exampleShadowMap();

}  // namespace pcf
