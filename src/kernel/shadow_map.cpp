#include "kernel/shadow_map.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace pcf {

namespace {

constexpr TexelKind ALL_TEXEL_KINDS[] = {
    TexelKind::D16,         TexelKind::D24,         TexelKind::D32F,        TexelKind::Moments2F16,
    TexelKind::Moments2F32, TexelKind::Moments4F16, TexelKind::Moments4F32,
};

// The rows of texelKindInfo, one per kind.
constexpr TexelKindInfo D16_INFO{"16", 1, 16, true, true};
constexpr TexelKindInfo D24_INFO{"24", 1, 24, true, true};
constexpr TexelKindInfo D32F_INFO{"32f", 1, 32, false, true};
constexpr TexelKindInfo MOMENTS2_F16_INFO{"moments2-16f", 2, 16, false, false};
constexpr TexelKindInfo MOMENTS2_F32_INFO{"moments2-32f", 2, 32, false, false};
constexpr TexelKindInfo MOMENTS4_F16_INFO{"moments4-16f", 4, 16, false, false};
constexpr TexelKindInfo MOMENTS4_F32_INFO{"moments4-32f", 4, 32, false, false};

bool sameLayer(const PcfMapLayer& a, const PcfMapLayer& b) {
    return a.shadowClipFromWorld == b.shadowClipFromWorld && a.depthRange == b.depthRange &&
           a.texelWs == b.texelWs && a.viewDepth == b.viewDepth;
}

}  // namespace

const TexelKindInfo& texelKindInfo(TexelKind kind) {
    switch (kind) {
        case TexelKind::D16:
            return D16_INFO;
        case TexelKind::D24:
            return D24_INFO;
        case TexelKind::D32F:
            return D32F_INFO;
        case TexelKind::Moments2F16:
            return MOMENTS2_F16_INFO;
        case TexelKind::Moments2F32:
            return MOMENTS2_F32_INFO;
        case TexelKind::Moments4F16:
            return MOMENTS4_F16_INFO;
        case TexelKind::Moments4F32:
            return MOMENTS4_F32_INFO;
    }
    throw std::out_of_range("texelKindInfo: unknown texel kind");
}

std::string_view texelKindName(TexelKind kind) { return texelKindInfo(kind).name; }

std::optional<TexelKind> texelKindFromName(std::string_view name) {
    if (name == "32F" || name == "32") return TexelKind::D32F;
    for (TexelKind k : ALL_TEXEL_KINDS) {
        if (texelKindInfo(k).name == name) return k;
    }
    return std::nullopt;
}

std::span<const TexelKind> allTexelKinds() { return ALL_TEXEL_KINDS; }

PcfMapLayer MapSpec::unfittedLayer() { return PcfMapLayer{glm::mat4(1.0f), vec2(0.0f), 0.0f}; }

bool MapSpec::operator==(const MapSpec& o) const {
    if (size != o.size || texels != o.texels || layers.size() != o.layers.size() ||
        cascadeDepths != o.cascadeDepths || visibleDepths != o.visibleDepths) {
        return false;
    }
    for (size_t k = 0; k < layers.size(); ++k) {
        if (!sameLayer(layers[k], o.layers[k])) return false;
    }
    return true;
}

std::optional<std::string> checkMapSpec(const MapSpec& spec) {
    std::ostringstream s;
    if (spec.size.x <= 0 || spec.size.y <= 0) {
        s << "a map of " << spec.size.x << " x " << spec.size.y << " texels has no texels";
        return s.str();
    }
    if (spec.layers.empty() || spec.layers.size() > static_cast<size_t>(MAX_MAP_LAYERS)) {
        s << "a map has 1 to " << MAX_MAP_LAYERS << " layers, not " << spec.layers.size();
        return s.str();
    }
    return std::nullopt;
}

ShadowMap::ShadowMap(int width, int height, float fill) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("shadow map size must be positive");
    mSpec.size = {width, height};
    mTexels.assign(static_cast<size_t>(width) * height, fill);
}

ShadowMap::ShadowMap(int width, int height, std::vector<float> depths) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("shadow map size must be positive");
    if (depths.size() != static_cast<size_t>(width) * height) {
        throw std::invalid_argument("shadow map holds a wrong number of depths");
    }
    mSpec.size = {width, height};
    mTexels = std::move(depths);
}

ShadowMap::ShadowMap(MapSpec spec, std::vector<float> texels) : mTexels(std::move(texels)) {
    setSpec(std::move(spec));
}

void ShadowMap::setSpec(MapSpec spec) {
    if (auto why = checkMapSpec(spec)) throw std::invalid_argument(*why);
    size_t values =
        static_cast<size_t>(spec.size.x) * spec.size.y * spec.texel().channels * spec.layers.size();
    if (values != mTexels.size()) {
        throw std::invalid_argument("shadow map spec does not fit the texels stored");
    }
    mSpec = std::move(spec);
}

void ShadowMap::setTexelKind(TexelKind kind) {
    MapSpec spec = mSpec;
    spec.texels = kind;
    setSpec(std::move(spec));
}

const float* ShadowMap::layerTexels(int layer) const {
    if (layer < 0 || layer >= layers()) throw std::out_of_range("shadow map has no such layer");
    size_t perLayer = static_cast<size_t>(width()) * height() * mSpec.texel().channels;
    return mTexels.data() + perLayer * static_cast<size_t>(layer);
}

ShadowMap ShadowMap::layerMap(int layer) const {
    const float* texels = layerTexels(layer);
    size_t perLayer = static_cast<size_t>(width()) * height() * mSpec.texel().channels;
    MapSpec one = mSpec;
    one.layers = {mSpec.layers[static_cast<size_t>(layer)]};
    return ShadowMap(one, std::vector<float>(texels, texels + perLayer));
}

std::optional<std::string> ShadowMap::findInvalidTexel() const {
    size_t channels = static_cast<size_t>(mSpec.texel().channels);
    size_t w = static_cast<size_t>(width());
    size_t perLayer = w * static_cast<size_t>(height());
    for (size_t k = 0; k < mTexels.size(); ++k) {
        float d = mTexels[k];
        // A depth is in [0, 1]; moments (EVSM's warps) may be any finite number.
        bool inRange = !mSpec.texel().depth || (d >= 0.0f && d <= 1.0f);
        if (!std::isnan(d) && !std::isinf(d) && inRange) continue;
        size_t texel = k / channels;
        std::ostringstream s;
        s << "texel (" << texel % w << ", " << (texel % perLayer) / w << ") ";
        if (layers() > 1) s << "of layer " << texel / perLayer << " ";
        if (std::isnan(d)) return s.str() + "is NaN";
        if (std::isinf(d)) return s.str() + "is infinite";
        s << "has depth " << d << ", outside [0, 1]";
        return s.str();
    }
    return std::nullopt;
}

ShadowMap exampleShadowMap() {
    ShadowMap map(8, 8);
    for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
            bool occluder = i >= 4 && j >= 2;
            float ground = 0.55f + 0.01f * static_cast<float>(j);
            float caster = 0.30f + 0.01f * static_cast<float>(j - 2);
            map.setDepth(i, j, occluder ? caster : ground);
        }
    }
    return map;
}

}  // namespace pcf
