#include "kernel/cascades.h"

#include <cmath>

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

bool isCascadeSetting(std::string_view key) {
    return key == "cascades" || key == "cascade_split" || key == "cascade_lambda" ||
           key == "shadow_distance" || key == "cascade_fit" || key == "cascade_snap" ||
           key == "cascade_blend";
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

}  // namespace pcf
