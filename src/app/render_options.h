// render_options.h: the options every rendering command shares (scene, method, bias, map), and
// their checks. Nothing is rendered or written before all of them have passed.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "render/render_settings.h"
#include "scene/scene.h"

namespace pcf {

// --bias NAME and its parameters' options, with one text for every command that takes them
// (render, bench, trace, ...). Values go into the given variables; checks are the caller's
// (checkBiasOptions).
void addBiasOptions(CLI::App* sub, std::string& bias, float& constantBias, float& slopeBias,
                    float& slopeMax, float& normalOffset, float& softScale, float& rpdbMax);

// The filter's options, --method, --kernel, --radius, --weights, --sigma and --precision, with
// one text each for every command that takes them (render, view, trace, ...).
void addFilterOptions(CLI::App* sub, std::string& method, int& kernel, float& radius,
                      std::string& weights, float& sigma, std::string& precision);

// The shared options' names parsed, each with one error for every command ("unknown method
// 'blur' (known: ...)", "unknown --weights 'sharp' (known: box, binomial, gaussian)").
int methodOption(const std::string& name);               // --method
int weightsOption(const std::string& name);              // --weights
int precisionOption(const std::string& name);            // --precision
BiasMode biasModeOption(const std::string& name);        // --bias
CullMode cullOption(const std::string& name);            // --cull
DepthFormat depthFormatOption(const std::string& name);  // --depth-format
// The bias parameters' ranges, then whether the mode combines with the method: UsageError in
// the flags' words.
void checkBiasOptions(const BiasParams& bias, int method);

struct RenderOptions {
    std::string scene;      // preset name
    std::string sceneFile;  // TOML scene file
    std::string lesson;     // a lesson: its scene, and the settings of step `lessonStep`
    int lessonStep = 1;
    std::string method = "pcf-gather";
    int kernel = 3;
    float radius = 1.0f;
    bool rotate = false;
    std::string bias = "constant";  // a bias mode name (kernel/bias.h)
    float constantBias = DEFAULT_CONSTANT_BIAS;
    float slopeBias = DEFAULT_SLOPE_BIAS;
    float slopeMax = DEFAULT_SLOPE_MAX;
    float normalOffset = DEFAULT_NORMAL_OFFSET;
    float softScale = DEFAULT_SOFT_SCALE;
    float rpdbMax = DEFAULT_RPDB_MAX;
    std::string cull = "back";
    std::string polygonOffset;  // "F,U": glPolygonOffset in the shadow pass
    int mapSize = 1024;
    std::string depthFormat = "32f";
    std::string size = "1280x720";
    std::string weights = "box";      // pcf-naive, pcf-gather: box, binomial, gaussian
    float sigma = 1.0f;               // gaussian weights, texels
    std::string precision = "exact";  // hardware taps and gathers: exact, hw8

    // Registers the options on `sub`; `defaultScene` is used when neither --scene nor
    // --scene-file is given (empty: one of them is required).
    void addTo(CLI::App* sub, const std::string& defaultScene);

    // The settings, checked; throws UsageError naming the option.
    RenderSettings settings() const;
    // The scene, loaded; throws UsageError (unknown preset) or InputError (scene file).
    Scene loadScene() const;

  private:
    // An option the user gave (not a default): it overrides the lesson's settings.
    bool given(const char* option) const;

    std::string mDefaultScene;
    CLI::App* mSub = nullptr;
};

}  // namespace pcf
