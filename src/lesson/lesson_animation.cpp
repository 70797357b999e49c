#include "lesson/lesson_animation.h"

#include "kernel/settings.h"
#include "kernel/trace_explain.h"

namespace pcf {

std::string_view animationSweepName(AnimationSweep sweep) {
    switch (sweep) {
        case AnimationSweep::Light:
            return "light";
        case AnimationSweep::Camera:
            return "camera";
        case AnimationSweep::Sun:
            return "sun";
        case AnimationSweep::Bias:
            return "bias";
        case AnimationSweep::MapSize:
            return "map-size";
        case AnimationSweep::Turn:
            return "turn";
    }
    return "?";
}

std::optional<AnimationSweep> animationSweepFromName(std::string_view name) {
    for (AnimationSweep s : {AnimationSweep::Light, AnimationSweep::Camera, AnimationSweep::Sun,
                             AnimationSweep::Bias, AnimationSweep::MapSize, AnimationSweep::Turn}) {
        if (animationSweepName(s) == name) return s;
    }
    return std::nullopt;
}

std::string_view animationSweepUnit(AnimationSweep sweep) {
    switch (sweep) {
        case AnimationSweep::Light:
            return "texel slide";
        case AnimationSweep::Camera:
            return "pixel slide";
        case AnimationSweep::Sun:
            return "deg elevation";
        case AnimationSweep::Bias:
            return "constant bias";
        case AnimationSweep::MapSize:
            return "texels a side";
        case AnimationSweep::Turn:
            return "deg turned";
    }
    return "";
}

std::optional<std::string> animationEndProblem(AnimationSweep sweep, double value) {
    std::string name(animationSweepName(sweep));
    // The ranges the sweeps can show: a sun above the ground, a bias a mode can subtract, a map
    // the renderer makes.
    double lo = 0.0, hi = 0.0;
    bool openLo = false;
    switch (sweep) {
        case AnimationSweep::Light:
        case AnimationSweep::Camera:
            return ": the " + name + " sweep has no from / to (it moves by " +
                   std::string(animationSweepUnit(sweep)) + " a frame)";
        case AnimationSweep::Sun:
            lo = 1.0, hi = 90.0;
            break;
        case AnimationSweep::Bias:
            lo = 0.0, hi = 1.0, openLo = true;
            break;
        case AnimationSweep::MapSize:
            lo = MIN_MAP_SIZE, hi = MAX_MAP_SIZE;
            break;
        case AnimationSweep::Turn:
            lo = -180.0, hi = 180.0;
            break;
    }
    if (value <= hi && value >= lo && !(openLo && value == lo)) return std::nullopt;
    return " from / to must be in " + std::string(openLo ? "(" : "[") +
           formatNumber(static_cast<float>(lo)) + ", " + formatNumber(static_cast<float>(hi)) +
           "] for the " + name + " sweep";
}

}  // namespace pcf
