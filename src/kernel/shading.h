// shading.h: the CPU side of shaders/shared/pcf_shading.h, the camera pass's gamma encoding,
// compiled here as C++ (in pcf.h's dialect) and by the GL driver as GLSL, so tests bound the
// function the fragment shader runs.
#pragma once

#include "kernel/pcf.h"
#include "kernel/settings.h"

namespace pcf {

#include "shaders/shared/pcf_shading.h"

// Where a receiver point is looked up in one layer of a map under the settings' bias, as
// scene.frag's layerLookup does it: pcfReceiverLookup with the layer's fit and texel size, on a
// cascade's exact grid (pcfLightClip) when the map holds cascades.
inline PcfReceiverLookup layerReceiverLookup(const PcfMapLayer& layer, const ShadowSettings& s,
                                             glm::vec3 posWs, glm::vec3 normalWs, float cosTheta,
                                             bool cascaded) {
    return pcfReceiverLookup(layer.shadowClipFromWorld, posWs, normalWs, cosTheta, s.modeId(),
                             s.constantBias, s.slopeBias, s.slopeMax, s.normalOffset, layer.texelWs,
                             cascaded);
}

}  // namespace pcf
