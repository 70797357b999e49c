// pcf.h: the CPU side of the shared PCF kernel. The math itself is in
// shaders/shared/pcf_kernel.h, compiled here as C++ (kernel/pcf_shared.h) and by the GL driver
// as GLSL.
#pragma once

#include "kernel/pcf_shared.h"
#include "kernel/shadow_map.h"

namespace pcf {

// The map as the batch path sees it, with the texture unit's state the lookup needs.
inline PlainMap plainMap(const ShadowMap& map, const PcfParams& prm) {
    return PlainMap{map.depths().data(), map.size(), map.isFixedPoint() ? 1 : 0, prm.precision,
                    map.spec().texel().channels};
}

// The map as the tracer sees it, recording into `out`.
inline RecordingMap recordingMap(const ShadowMap& map, const PcfParams& prm, Recording& out) {
    return RecordingMap{map.depths().data(),        map.size(),    &out,
                        map.isFixedPoint() ? 1 : 0, prm.precision, map.spec().texel().channels};
}

// Visibility of one lookup on the CPU, nothing recorded (the batch path).
inline float filterVisibility(const ShadowMap& map, vec2 uv, float ref, const PcfParams& prm) {
    return pcfFilter(plainMap(map, prm), uv, ref, prm);
}

// Visibility of one lookup with every tap and fetch recorded (the tracing path: the same code).
inline float filterRecorded(const ShadowMap& map, vec2 uv, float ref, const PcfParams& prm,
                            Recording& out) {
    return pcfFilter(recordingMap(map, prm, out), uv, ref, prm);
}

// The same two paths under a bias mode: ref is the lookup's (per-lookup bias applied), `bias`
// says how each tap's comparison varies from it (receiver plane, soft, interpolated).
inline float filterVisibility(const ShadowMap& map, vec2 uv, float ref, const PcfParams& prm,
                              const PcfBias& bias) {
    return pcfFilterRef(plainMap(map, prm), uv, PcfRef(ref, uv, bias), prm);
}
inline float filterRecorded(const ShadowMap& map, vec2 uv, float ref, const PcfParams& prm,
                            const PcfBias& bias, Recording& out) {
    return pcfFilterRef(recordingMap(map, prm, out), uv, PcfRef(ref, uv, bias), prm);
}

}  // namespace pcf
