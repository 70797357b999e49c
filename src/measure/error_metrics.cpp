#include "measure/error_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pcf {

ErrorRegions errorRegions(const GroundTruth& truth, std::span<const uint8_t> renderedReceiver,
                          int dilation) {
    size_t n = truth.pixelCount();
    if (!renderedReceiver.empty() && renderedReceiver.size() != n) {
        throw std::invalid_argument(
            "errorRegions: the rendered receiver mask is not the truth's "
            "size");
    }
    ErrorRegions r;
    r.size = truth.size;
    r.compared.assign(n, 0);
    r.edge.assign(n, 0);
    std::vector<uint8_t> crossed(n, 0);  // compared pixels the true shadow edge crosses
    for (size_t k = 0; k < n; ++k) {
        bool rendered = renderedReceiver.empty() || renderedReceiver[k] != 0;
        if (truth.receiver[k] != 0 && truth.facesLight[k] != 0 && rendered) {
            r.compared[k] = 1;
            ++r.comparedCount;
            float v = truth.visibility[k];
            crossed[k] = v > 0.0f && v < 1.0f ? 1 : 0;
        }
    }
    // Dilation by a (2d + 1)^2 square, done as two 1D passes (max along x, then along y).
    int w = truth.size.x;
    int h = truth.size.y;
    std::vector<uint8_t> alongX(n, 0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!crossed[truth.index(x, y)]) continue;
            for (int dx = std::max(0, x - dilation); dx <= std::min(w - 1, x + dilation); ++dx) {
                alongX[truth.index(dx, y)] = 1;
            }
        }
    }
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!alongX[truth.index(x, y)]) continue;
            for (int dy = std::max(0, y - dilation); dy <= std::min(h - 1, y + dilation); ++dy) {
                r.edge[truth.index(x, dy)] = 1;
            }
        }
    }
    for (size_t k = 0; k < n; ++k) {
        r.edge[k] = r.edge[k] && r.compared[k] ? 1 : 0;
        r.edgeCount += r.edge[k];
    }
    return r;
}

std::vector<uint8_t> receiverMaskFromLightSpace(std::span<const float> lightSpace) {
    std::vector<uint8_t> mask(lightSpace.size() / 4, 0);
    for (size_t k = 0; k < mask.size(); ++k) mask[k] = lightSpace[4 * k + 3] == 1.0f ? 1 : 0;
    return mask;
}

ErrorStats measureError(const GroundTruth& truth, const ErrorRegions& regions,
                        std::span<const float> visibility) {
    if (visibility.size() != truth.pixelCount() || regions.compared.size() != truth.pixelCount()) {
        throw std::invalid_argument("measureError: images of different sizes");
    }
    // Sums in double: a 1280 x 720 frame adds ~10^6 squares of ~10^-2.
    double sum = 0.0;
    double edgeSum = 0.0;
    ErrorStats s;
    for (size_t k = 0; k < visibility.size(); ++k) {
        if (!regions.compared[k]) continue;
        double e = static_cast<double>(visibility[k]) - static_cast<double>(truth.visibility[k]);
        double e2 = e * e;
        sum += e2;
        s.maxErr = std::max(s.maxErr, std::fabs(e));
        ++s.pixels;
        if (regions.edge[k]) {
            edgeSum += e2;
            s.edgeMaxErr = std::max(s.edgeMaxErr, std::fabs(e));
            ++s.edgePixels;
        }
    }
    if (s.pixels > 0) s.rmse = std::sqrt(sum / s.pixels);
    if (s.edgePixels > 0) s.edgeRmse = std::sqrt(edgeSum / s.edgePixels);
    return s;
}

}  // namespace pcf
