// error_metrics.h: how far a rendered shadow is from the ground truth (ground_truth.h).
//
// What is compared. The renderer's visibility target holds the raw PCF result on every receiver
// pixel, even on surfaces turned away from the light, where shading (n.l <= 0) makes the pixel
// dark whatever the shadow map says and the truth is 0. Comparing there would count shading as
// shadow error. So the error is measured over the COMPARED pixels only:
//   compared = truth.receiver && truth.facesLight && rendered receiver (light-space alpha = 1)
// (the last term drops the few silhouette pixels where the tessellated mesh and the analytic
// surface disagree about which object is there).
// The EDGE BAND is where filtering matters: compared pixels within `EDGE_BAND_DILATION` pixels
// (Chebyshev distance, i.e. a 5 x 5 square) of a compared pixel whose truth is strictly between
// 0 and 1 (a pixel the true shadow edge crosses).
//
// Per set, with e = rendered - truth per pixel (visibility in [0,1]):
//   rmse = sqrt(sum(e^2) / count),  max_err = max |e|           (0 for an empty set)
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "measure/ground_truth.h"

namespace pcf {

constexpr int EDGE_BAND_DILATION = 2;  // pixels

struct ErrorRegions {
    glm::ivec2 size{0, 0};
    std::vector<uint8_t> compared;  // 1 = compared (top-down, like the truth)
    std::vector<uint8_t> edge;      // 1 = compared and in the edge band
    int comparedCount = 0;
    int edgeCount = 0;
};

// renderedReceiver: 1 per pixel where the renderer looked the shadow map up (top-down), e.g.
// from the light-space target's alpha; empty = trust the truth's receiver mask alone. Throws
// std::invalid_argument when its size is not the truth's.
ErrorRegions errorRegions(const GroundTruth& truth, std::span<const uint8_t> renderedReceiver = {},
                          int dilation = EDGE_BAND_DILATION);

// The receiver mask of a light-space readback (4 floats per pixel, alpha 1 on receivers).
std::vector<uint8_t> receiverMaskFromLightSpace(std::span<const float> lightSpace);

struct ErrorStats {
    double rmse = 0.0;
    double maxErr = 0.0;
    double edgeRmse = 0.0;
    double edgeMaxErr = 0.0;
    int pixels = 0;      // compared pixels
    int edgePixels = 0;  // of those, in the edge band
};

// visibility: the rendered visibility, one float per pixel, top-down, the truth's size (throws
// std::invalid_argument otherwise).
ErrorStats measureError(const GroundTruth& truth, const ErrorRegions& regions,
                        std::span<const float> visibility);

}  // namespace pcf
