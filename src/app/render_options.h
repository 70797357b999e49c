// render_options.h: the options every rendering command shares (scene, method, bias, map), and
// their checks. Nothing is rendered or written before all of them have passed.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli_util.h"
#include "render/render_settings.h"
#include "scene/scene.h"

namespace pcf {

// The shadow settings' options, generated from the parameter table (kernel/settings.h): each
// parameter of the chosen groups as its flag (settingFlag) with its help and this command's
// default. Numbers and flags are bound as they are, names as text parsed by applyTo.
class SettingOptions {
  public:
    // Registers the parameters of `groups` on `sub` but those in `except`, `defaults` being this
    // command's.
    void addTo(CLI::App* sub, std::initializer_list<ParamGroup> groups,
               const ShadowSettings& defaults, std::initializer_list<std::string_view> except = {});
    // Registers only the parameters named by `keys` (e.g. a command that takes the light's size
    // and nothing else of the settings).
    void addKeys(CLI::App* sub, std::initializer_list<std::string_view> keys,
                 const ShadowSettings& defaults);
    // Whether the user gave the parameter's option.
    bool given(std::string_view key) const;
    // Whether the command takes the cascades' settings (kernel/cascades.h isCascadeSetting);
    // set before addTo.
    bool cascades = false;
    // The name given for a named parameter (or its default): "pcf-gather"; set it to override.
    std::string& name(std::string_view key);
    const std::string& name(std::string_view key) const;
    // The number given for a numeric parameter (or its default), e.g. to check it before use.
    const ShadowSettings& values() const { return mValues; }
    // Sets each registered parameter in `s` (only those given when onlyGiven): flags as given,
    // numbers given read from their text by the parameter table (kernel/settings.h
    // setParamFromText: decimal, in the table's range, the value as typed in the message),
    // names parsed; any problem a UsageError naming its option. What depends on the method
    // (tent's kernel sizes, the bias a method takes) is the caller's (cliParamsProblem,
    // checkBiasOptions).
    void applyTo(ShadowSettings& s, bool onlyGiven) const;

  private:
    void addParam(const ParamInfo& p, const ShadowSettings& defaults);

    CLI::App* mSub = nullptr;
    std::vector<const ParamInfo*> mParams;
    ShadowSettings mValues;
    std::map<std::string, std::string, std::less<>> mNames;
};

// What `pcfscope verify` needs to repeat the lookups of a --raw folder, as its render.json: the
// parameters the table marks rawJson (the method and its parameters, the map's format, the
// precision model, the bias mode and what changes each tap's comparison), one JSON object.
// pcss: the renderer's pcss parameters (scene/pcss.h), as the frame was rendered with them:
// penumbraScale as "penumbra_scale", a spot map's depthNear / depthFar as "pcss_depth_near" /
// "pcss_depth_far", so that `verify` repeats the very lookups; 0 for the other methods. Last,
// the map as a value (trace_json.h mapSpecJson), "map": its size, texel kind and layers' fits,
// when given (`verify` checks shadowmap.exr against it).
std::string settingsJson(const ShadowSettings& s, const PcfParams& pcss = PcfParams{},
                         const std::optional<MapSpec>& map = std::nullopt);

// The shared options' names parsed, each with one error for every command ("unknown method
// 'blur' (known: ...)", "unknown --weights 'sharp' (known: box, binomial, gaussian)").
int methodOption(const std::string& name);             // --method
int weightsOption(const std::string& name);            // --weights
BiasMode biasModeOption(const std::string& name);      // --bias
TexelKind depthFormatOption(const std::string& name);  // --depth-format
// The bias parameters' ranges, then whether the mode combines with the method: UsageError in
// the flags' words.
void checkBiasOptions(const ShadowSettings& s);
// --light-size on a spot light, or --light-radius on a directional one: UsageError in the flags'
// words (scene/light.h lightSizeProblem).
void checkLightSize(const Light& light, const ShadowSettings& s);
// --cascades on a spot light or with pcss, or a --shadow-distance before the camera's near
// plane: UsageError in the flags' words (scene/cascade_fit.h cascadeProblem).
void checkCascades(const Scene& scene, const ShadowSettings& s);

struct RenderOptions {
    std::string scene;      // preset name
    std::string sceneFile;  // TOML scene file
    std::string lesson;     // a lesson: its scene, and the settings of step `lessonStep`
    int lessonStep = 1;
    // The shadow settings' options; `defaults` are this command's, set before addTo.
    ShadowSettings defaults;
    SettingOptions shadow;
    std::string polygonOffset;  // "F,U": glPolygonOffset in the shadow pass
    std::string size = "1280x720";
    SizeRange frameRange;  // --size's range; set before addTo
    // Whether the command shows its frames (render): then it also takes the parameters of what
    // a frame draws (ParamGroup::View, --shading); the commands that measure do not.
    bool picture = false;
    // Whether the command renders a cascaded map (render): then it also takes --cascades and
    // the other cascade settings. The commands that measure a frame's lookups (bench,
    // stability, advise) read one layer, and lessons show one map.
    bool cascades = false;

    // Registers the options on `sub`; `defaultScene` is used when neither --scene nor
    // --scene-file is given (empty: one of them is required). The parameters named in `except`
    // are left out (a command that sets them itself).
    void addTo(CLI::App* sub, const std::string& defaultScene,
               std::initializer_list<std::string_view> except = {});

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
