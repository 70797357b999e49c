// stability_options.cpp: the stability sweeps' options (stability.h): the quick run's, and the
// checks every run's options pass before anything is rendered.
#include <optional>
#include <string>
#include <utility>

#include "kernel/bias.h"
#include "kernel/methods.h"
#include "measure/ground_truth.h"
#include "measure/stability.h"
#include "measure/stability_bleed.h"
#include "measure/stability_cascades.h"
#include "measure/stability_pcss.h"
#include "scene/presets.h"

namespace pcf {

StabilityOptions quickStabilityOptions() {
    StabilityOptions o;
    o.methods = {{PCF_NEAREST, 0}, {PCF_GATHER, 3}};
    o.biases = {BiasMode::None, BiasMode::Constant};
    o.frameSize = {160, 90};
    o.mapSize = 128;
    o.truthSpp = 1;
    o.elevations = {90, 45, 20, 10, 5, 2};
    o.leakBiases = {0.0005f, 0.002f, 0.032f};
    o.cameraFrames = 3;
    o.depthRanges = {1, 100, 1e4f};
    o.aliasingMapSizes = {128, 512};
    o.pcssPoleWidths = {1, 4};
    o.pcssPlankHeights = {3};
    o.pcssLightSizes = {2, 8};
    o.pcssRadii = {1, 4, 16};
    o.pcssTruthBound = 1.0f / 16.0f;
    o.bleedGaps = {0.25f, 1.0f};
    o.bleedMethods = {{PCF_VSM, 3}};
    o.bleedSettings = {{"lbr", {"0", "0.2", "0.3", "0.5"}}};
    o.cascadeLambdas = {0.5f, 1.0f};
    o.cascadePathSteps = 4;
    return o;
}

namespace {

// A sentence naming no option, one naming an option list once (said as its flag by the command
// line: app/cli_util.h's cliWords), and a value of a list out of its range.
ParamProblem plainProblem(std::string sentence) {
    return ParamProblem{"", std::move(sentence), ""};
}
ParamProblem emptyList(const char* setting) { return ParamProblem{setting, "", " is empty"}; }
ParamProblem outOfRange(const char* setting, const std::string& v, const std::string& range) {
    return ParamProblem{setting, "", " " + v + " is out of range (" + range + ")"};
}

// The methods and biases: each method's kernel fits it, and some pair of them exists.
std::optional<ParamProblem> validateStabilityPairs(const StabilityOptions& o) {
    auto plain = plainProblem;
    auto empty = emptyList;
    if (o.methods.empty()) return empty("methods");
    for (const StabilityMethod& m : o.methods) {
        if (m.method < 0 || m.method >= PCF_METHOD_COUNT) {
            return plain("unknown method id " + std::to_string(m.method));
        }
        RenderSettings s;
        s.method = m.method;
        s.kernel = m.kernel > 0 ? m.kernel : 3;
        s.radius = o.base.radius;
        if (std::optional<ParamProblem> p = checkParams(s.pcfParams())) {
            if (p->setting == "kernel") p->setting = "kernels";  // the list it came from
            return p;
        }
    }
    if (o.biases.empty()) return empty("biases");
    bool anyPair = false;
    for (BiasMode b : o.biases) {
        for (const StabilityMethod& m : o.methods) anyPair = anyPair || stabilityPairExists(m, b);
    }
    if (!anyPair) {
        BiasMode b = o.biases.front();
        return ParamProblem{"biases", "no method given combines with ",
                            ": " + *validateBias(static_cast<int>(b), o.methods.front().method)};
    }
    return std::nullopt;
}

// The sweeps' own options, in order: pcss's, the cascades', bleed's.
std::optional<ParamProblem> validateSweepOptions(const StabilityOptions& o) {
    if (std::optional<ParamProblem> p = validatePcssSweepOptions(o)) return p;
    if (std::optional<ParamProblem> p = validateCascadeOptions(o)) return p;
    return validateBleedOptions(o);
}

}  // namespace

std::optional<ParamProblem> validateStabilityOptions(const StabilityOptions& o) {
    auto plain = plainProblem;
    auto empty = emptyList;
    if (std::optional<ParamProblem> p = validateStabilityPairs(o)) return p;
    if (o.sweeps.empty()) return empty("sweep");
    if (o.frameSize.x < MIN_STABILITY_FRAME_SIDE || o.frameSize.y < MIN_STABILITY_FRAME_SIDE ||
        o.frameSize.x > MAX_FRAME_SIDE || o.frameSize.y > MAX_FRAME_SIDE) {
        const std::string lo = std::to_string(MIN_STABILITY_FRAME_SIDE);
        const std::string hi = std::to_string(MAX_FRAME_SIDE);
        return plain("the frame size is out of range (" + lo + "x" + lo + " up to " + hi + "x" +
                     hi + ")");
    }
    if (o.mapSize < MIN_MAP_SIZE || o.mapSize > MAX_MAP_SIZE) {
        return outOfRange("map_size", std::to_string(o.mapSize),
                          std::to_string(MIN_MAP_SIZE) + ".." + std::to_string(MAX_MAP_SIZE));
    }
    if (o.truthSpp < 1 || o.truthSpp > MAX_TRUTH_SPP) {
        return outOfRange("spp", std::to_string(o.truthSpp), "1.." + std::to_string(MAX_TRUTH_SPP));
    }
    for (float e : o.elevations) {
        if (!(e >= 1.0f && e <= 90.0f)) {
            return outOfRange("elevations", std::to_string(e), "1..90 degrees");
        }
    }
    if (o.elevations.empty()) return empty("elevations");
    for (float b : o.leakBiases) {
        if (!(b >= 0.0f && b <= 1.0f)) {
            return outOfRange("leak_biases", std::to_string(b), "0..1");
        }
    }
    if (o.leakBiases.empty()) return empty("leak_biases");
    for (const std::string& name : o.leakScenes) {
        if (!presetScene(name)) return plain("unknown leak scene '" + name + "'");
    }
    if (o.shimmerFrames < 2 || o.shimmerFrames > 4 * SHIMMER_STEPS) {
        return plain("the shimmer frames are out of range (2..128)");
    }
    if (o.cameraFrames < 0 || o.cameraFrames > 64) {
        return plain("the camera frames are out of range (0..64)");
    }
    for (float r : o.depthRanges) {
        if (!(r >= 1.0f && r <= 1e7f)) {
            return outOfRange("depth_ranges", std::to_string(r), "1..1e7");
        }
    }
    if (o.depthRanges.empty()) return empty("depth_ranges");
    if (!(o.precisionElevation >= 1.0f && o.precisionElevation <= 90.0f)) {
        return plain("the precision elevation is out of range (1..90 degrees)");
    }
    if (!(o.tradeoffElevation >= 1.0f && o.tradeoffElevation <= 90.0f)) {
        return plain("the trade-off elevation is out of range (1..90 degrees)");
    }
    for (int size : o.aliasingMapSizes) {
        if (size < MIN_MAP_SIZE || size > MAX_MAP_SIZE) {
            return plain("aliasing map size " + std::to_string(size) + " is out of range");
        }
    }
    return validateSweepOptions(o);
}

}  // namespace pcf
