// pcf_shared.h: the shared kernel (shaders/shared/pcf_kernel.h) compiled as C++, over the two map
// types the CPU reads through (plain and recording) and their hooks. kernel/pcf.h adds the entry
// points over a ShadowMap; kernel/shadow_map.h takes PcfMapLayer from here.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <vector>

namespace pcf {

using glm::abs;
using glm::clamp;
using glm::dot;
using glm::exp;
using glm::floor;
using glm::isnan;
using glm::ivec2;
using glm::mat4;
using glm::max;
using glm::min;
using glm::mix;
using glm::sqrt;
using glm::uint;
using glm::vec2;
using glm::vec3;
using glm::vec4;

// The map as the batch path sees it: reads depths, records nothing. Cheap to copy.
// mFixedPoint: 1 for a 16/24-bit map (D_ref clamped to [0,1]); mPrecision: PCF_PRECISION_*.
// mChannels: floats per texel (1 for a depth map, 2 or 4 for a moments map).
struct PlainMap {
    const float* mDepths;
    ivec2 mSize;
    int mFixedPoint = 0;
    int mPrecision = 0;
    int mChannels = 1;
};

// The map as the tracer sees it: the same reads, and every tap and fetch written down.
struct TapRecord {
    ivec2 texel;           // the texel read (after clamping to the edge)
    float depth;           // its stored depth
    float ref;             // the receiver depth it was compared with
    float lit;             // the comparison bit: 1 lit, 0 shadowed
    float weight;          // its share of the final visibility
    int fetch;             // index of the fetch instruction that read it
    bool clamped = false;  // the texel asked for was outside the map (clamped to the edge)
};

struct FetchRecord {
    int kind;      // PCF_FETCH_POINT, _LOOKUP, _GATHER or _HW
    vec2 uv;       // where the instruction sampled
    float weight;  // the weight the method gives the instruction's result
};

struct Recording {
    std::vector<TapRecord> taps;
    std::vector<FetchRecord> fetches;
    ivec2 wanted{0, 0};  // the texel of the tap being read, before clamping
};

struct RecordingMap {
    const float* mDepths;
    ivec2 mSize;
    Recording* mRecording;
    int mFixedPoint = 0;
    int mPrecision = 0;
    int mChannels = 1;
};

// A moments map's texel t as a texture reads it: channels it lacks are GL's (0, 0, 0, 1).
inline vec4 texelMoments(const float* texels, ivec2 size, int channels, ivec2 t) {
    const float* p = texels + (static_cast<size_t>(t.y) * size.x + t.x) * channels;
    return vec4(p[0], channels > 1 ? p[1] : 0.0f, channels > 2 ? p[2] : 0.0f,
                channels > 3 ? p[3] : 1.0f);
}

// The hooks pcf_kernel.h reads the map through (see pcf_prelude.h). Texels arrive clamped.
inline ivec2 mapSize(const PlainMap& m) { return m.mSize; }
inline ivec2 mapSize(const RecordingMap& m) { return m.mSize; }
inline int mapFixedPoint(const PlainMap& m) { return m.mFixedPoint; }
inline int mapFixedPoint(const RecordingMap& m) { return m.mFixedPoint; }
inline int mapPrecision(const PlainMap& m) { return m.mPrecision; }
inline int mapPrecision(const RecordingMap& m) { return m.mPrecision; }
inline float fetchDepth(const PlainMap& m, ivec2 t) { return m.mDepths[t.y * m.mSize.x + t.x]; }
inline float fetchDepth(const RecordingMap& m, ivec2 t) { return m.mDepths[t.y * m.mSize.x + t.x]; }
inline vec4 fetchMoments(const PlainMap& m, ivec2 t) {
    return texelMoments(m.mDepths, m.mSize, m.mChannels, t);
}
inline vec4 fetchMoments(const RecordingMap& m, ivec2 t) {
    return texelMoments(m.mDepths, m.mSize, m.mChannels, t);
}
inline void pcfTap(const PlainMap&, ivec2, float, float, float, float) {}
inline void pcfTap(const RecordingMap& m, ivec2 texel, float depth, float ref, float lit,
                   float weight) {
    int fetch = static_cast<int>(m.mRecording->fetches.size()) - 1;
    bool clamped = m.mRecording->wanted != texel;
    m.mRecording->taps.push_back({texel, depth, ref, lit, weight, fetch, clamped});
}
inline void pcfTapWanted(const PlainMap&, ivec2) {}
inline void pcfTapWanted(const RecordingMap& m, ivec2 texel) { m.mRecording->wanted = texel; }
inline void pcfFetch(const PlainMap&, int, vec2, float) {}
inline void pcfFetch(const RecordingMap& m, int kind, vec2 uv, float weight) {
    m.mRecording->fetches.push_back({kind, uv, weight});
}

// The prelude must come first: it defines what the kernel is written in.
// clang-format off
#include "shaders/shared/pcf_prelude.h"
#include "shaders/shared/pcf_kernel.h"
#include "shaders/shared/pcf_disk.h"
#include "shaders/shared/pcf_moments.h"
#include "shaders/shared/pcf_filter.h"
// clang-format on

}  // namespace pcf
