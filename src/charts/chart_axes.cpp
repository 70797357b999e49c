#include "charts/chart_axes.h"

#include <cmath>
#include <cstdio>

namespace pcf {

double chartNiceStep(double rough) {
    double p = std::pow(10.0, std::floor(std::log10(rough)));
    double m = rough / p;
    return (m <= 1.0 ? 1.0 : m <= 2.0 ? 2.0 : m <= 5.0 ? 5.0 : 10.0) * p;
}

std::string chartRendererLine(const std::string& glRenderer) {
    if (glRenderer.empty()) return std::string(RENDERER_UNKNOWN);
    std::string line = "rendered on " + glRenderer;
    if (glRenderer.find("llvmpipe") != std::string::npos) {
        line += " (" + std::string(LLVMPIPE_NOTE) + ")";
    }
    return line;
}

}  // namespace pcf
