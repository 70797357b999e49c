#include "kernel/cascades.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcf {

std::string_view cascadeSplitName(int split) {
    if (split == CASCADE_SPLIT_UNIFORM) return "uniform";
    if (split == CASCADE_SPLIT_LOG) return "log";
    return "practical";
}

std::optional<int> cascadeSplitFromName(std::string_view name) {
    if (name == "uniform") return CASCADE_SPLIT_UNIFORM;
    if (name == "log") return CASCADE_SPLIT_LOG;
    if (name == "practical") return CASCADE_SPLIT_PRACTICAL;
    return std::nullopt;
}

std::string cascadeSplitNames() { return "uniform, log, practical"; }

std::string_view cascadeFitName(int fit) { return fit == CASCADE_FIT_SPHERE ? "sphere" : "box"; }

std::optional<int> cascadeFitFromName(std::string_view name) {
    if (name == "box") return CASCADE_FIT_BOX;
    if (name == "sphere") return CASCADE_FIT_SPHERE;
    return std::nullopt;
}

std::string cascadeFitNames() { return "box, sphere"; }

std::string_view cascadeBoundsName(int bounds) {
    return bounds == CASCADE_BOUNDS_DEPTH ? "depth" : "fixed";
}

std::optional<int> cascadeBoundsFromName(std::string_view name) {
    if (name == "fixed") return CASCADE_BOUNDS_FIXED;
    if (name == "depth") return CASCADE_BOUNDS_DEPTH;
    return std::nullopt;
}

std::string cascadeBoundsNames() { return "fixed, depth"; }

bool isCascadeSetting(std::string_view key) {
    return key == "cascades" || key == "cascade_split" || key == "cascade_lambda" ||
           key == "shadow_distance" || key == "cascade_fit" || key == "cascade_snap" ||
           key == "cascade_blend" || key == "cascade_bounds";
}

double splitLambda(int split, double lambda) {
    if (split == CASCADE_SPLIT_UNIFORM) return 0.0;
    if (split == CASCADE_SPLIT_LOG) return 1.0;
    return lambda;
}

double cascadeSplitDistance(double n, double f, int i, int count, double lambda) {
    double t = static_cast<double>(i) / static_cast<double>(count);
    double logSplit = n * std::pow(f / n, t);
    double uniformSplit = n + (f - n) * t;
    return lambda * logSplit + (1.0 - lambda) * uniformSplit;
}

std::vector<double> cascadeSplits(double n, double f, int count, int split, double lambda) {
    std::vector<double> splits;
    double l = splitLambda(split, lambda);
    for (int i = 1; i <= count; ++i) splits.push_back(cascadeSplitDistance(n, f, i, count, l));
    // The last is f itself, not f as the sum of two rounded terms.
    if (!splits.empty()) splits.back() = f;
    return splits;
}

std::optional<glm::vec2> visibleDepthRange(const float* depths, size_t count) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (size_t k = 0; k < count; ++k) {
        float d = depths[k];
        if (!(d > 0.0f)) continue;  // no receiver at this pixel (NaN too)
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    if (!(lo <= hi)) return std::nullopt;
    return glm::vec2(lo, hi);
}

glm::dvec2 cascadeSplitSpan(double n, double f, std::optional<glm::vec2> visible) {
    if (!visible) return {n, f};
    double lo = std::max(n, static_cast<double>(visible->x) * (1.0 - CASCADE_BOUNDS_MARGIN));
    double hi = std::min(f, static_cast<double>(visible->y) * (1.0 + CASCADE_BOUNDS_MARGIN));
    if (!(lo < hi)) return {n, f};
    return {lo, hi};
}

}  // namespace pcf
