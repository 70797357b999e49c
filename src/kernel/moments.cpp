#include "kernel/moments.h"

#include <glm/gtc/packing.hpp>
#include <stdexcept>

#include "kernel/methods.h"

namespace pcf {

float roundToHalf(float v) { return glm::unpackHalf1x16(glm::packHalf1x16(v)); }

ShadowMap momentsMap(const ShadowMap& depthMap, const PcfParams& prm, TexelKind kind) {
    const TexelKindInfo& info = texelKindInfo(kind);
    if (info.depth || depthMap.spec().texel().channels != 1) {
        throw std::invalid_argument("momentsMap: a depth map into a moments kind");
    }
    MapSpec spec = depthMap.spec();
    spec.texels = kind;
    int w = depthMap.width();
    int h = depthMap.height();
    size_t channels = static_cast<size_t>(info.channels);
    std::vector<float> texels(static_cast<size_t>(w) * h * channels * spec.layers.size());
    for (int layer = 0; layer < depthMap.layers(); ++layer) {
        PlainMap depth{depthMap.layerTexels(layer), depthMap.size(),
                       depthMap.isFixedPoint() ? 1 : 0, prm.precision, 1};
        float* out = texels.data() + static_cast<size_t>(layer) * w * h * channels;
        for (int j = 0; j < h; ++j) {
            for (int i = 0; i < w; ++i) {
                vec4 m = pcfMomentsTexel(depth, ivec2(i, j), prm);
                float* t = out + (static_cast<size_t>(j) * w + i) * channels;
                for (size_t c = 0; c < channels; ++c) {
                    t[c] = info.bits == 16 ? roundToHalf(m[static_cast<int>(c)])
                                           : m[static_cast<int>(c)];
                }
            }
        }
    }
    return ShadowMap(std::move(spec), std::move(texels));
}

ShadowMap mapForMethod(const ShadowMap& depthMap, const PcfParams& prm) {
    if (!readsMoments(prm.method)) return depthMap;
    return momentsMap(depthMap, prm, mapTexelKind(prm.method, TexelKind::D32F));
}

}  // namespace pcf
