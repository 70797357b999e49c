// shadow_map.h: a W x H grid of depths as the light saw them, the input of every PCF lookup.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

namespace pcf {

// Depths in [0,1], 0 = near the light. Texel (i, j) is column i, row j of the image as stored
// (row 0 = first scanline = GL texel row 0); its centre is at uv ((i + 0.5) / W, (j + 0.5) / H).
class ShadowMap {
  public:
    ShadowMap() = default;
    ShadowMap(int width, int height, float fill = 1.0f);
    ShadowMap(int width, int height, std::vector<float> depths);

    int width() const { return mSize.x; }
    int height() const { return mSize.y; }
    glm::ivec2 size() const { return mSize; }
    float depth(int i, int j) const { return mDepths[static_cast<size_t>(j) * mSize.x + i]; }
    void setDepth(int i, int j, float d) { mDepths[static_cast<size_t>(j) * mSize.x + i] = d; }
    const std::vector<float>& depths() const { return mDepths; }

    // The bits of the fixed-point format the depths were stored in (16 or 24), 0 for float.
    // A fixed-point map clamps D_ref to [0,1] in every comparison (GL 4.5, 8.23.1), and its
    // depths are the sampler's own floats for the stored integers (see readSampledDepth).
    int fixedPointBits() const { return mFixedPointBits; }
    bool isFixedPoint() const { return mFixedPointBits != 0; }
    void setFixedPointBits(int bits) { mFixedPointBits = bits; }

    // The first texel that is not a depth in [0,1] (NaN, infinite, out of range), described in
    // words ("texel (3, 4) is NaN"); nullopt when every texel is fine.
    std::optional<std::string> findInvalidTexel() const;

  private:
    glm::ivec2 mSize{0, 0};
    std::vector<float> mDepths;
    int mFixedPointBits = 0;
};

// The built-in example of `pcfscope trace --example`: an 8 x 8 map of a ground plane (depths
// 0.55 .. 0.62, rising by row) with an occluder over the corner i >= 4, j >= 2 (0.30 .. 0.35).
ShadowMap exampleShadowMap();

}  // namespace pcf
