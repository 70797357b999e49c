#include "app/render_options.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "app/cli_util.h"
#include "app/session.h"
#include "kernel/bias.h"
#include "kernel/cascades.h"
#include "kernel/methods.h"
#include "kernel/settings.h"
#include "kernel/trace_json.h"
#include "lesson/lesson.h"
#include "scene/cascade_fit.h"
#include "scene/presets.h"
#include "scene/scene_file.h"

namespace pcf {

namespace {

// A named parameter's name parsed. method and bias keep the words their errors have always had
// ("unknown method 'x'", "unknown bias mode 'x'"); the others name their flag.
template <class T>
T parseNamed(const ParamInfo& p, const NamedField<T>& named, const std::string& text) {
    if constexpr (!std::is_same_v<T, vec2>) {
        if (p.key == "method") return static_cast<T>(methodOption(text));
        if (p.key == "bias") return static_cast<T>(biasModeOption(text));
    }
    std::optional<T> v = named.fromName(text);
    if (!v && std::is_same_v<T, vec2>) {
        throw UsageError(settingFlag(p.key) + " takes " + named.known() + ", not '" + text + "'");
    }
    if (!v) {
        throw UsageError("unknown " + settingFlag(p.key) + " '" + text +
                         "' (known: " + named.known() + ")");
    }
    return *v;
}

}  // namespace

void SettingOptions::addTo(CLI::App* sub, std::initializer_list<ParamGroup> groups,
                           const ShadowSettings& defaults,
                           std::initializer_list<std::string_view> except) {
    mSub = sub;
    mValues = defaults;
    for (const ParamInfo& p : allParams()) {
        if (std::find(groups.begin(), groups.end(), p.group) == groups.end() ||
            std::find(except.begin(), except.end(), p.key) != except.end() ||
            (!cascades && isCascadeSetting(p.key))) {
            continue;
        }
        addParam(p, defaults);
    }
}

void SettingOptions::addKeys(CLI::App* sub, std::initializer_list<std::string_view> keys,
                             const ShadowSettings& defaults) {
    mSub = sub;
    mValues = defaults;
    for (std::string_view key : keys) addParam(*findParam(key), defaults);
}

void SettingOptions::addParam(const ParamInfo& p, const ShadowSettings& defaults) {
    mParams.push_back(&p);
    std::string flag = settingFlag(p.key);
    std::string help = std::string(p.help);
    std::visit(
        [&](const auto& field) {
            using F = std::decay_t<decltype(field)>;
            if constexpr (std::is_same_v<F, bool ShadowSettings::*>) {
                mSub->add_flag(flag, mValues.*field, help);
            } else if constexpr (std::is_same_v<F, int ShadowSettings::*> ||
                                 std::is_same_v<F, float ShadowSettings::*>) {
                mSub->add_option(flag, mValues.*field,
                                 help + ", default " + settingText(p, defaults));
            } else {
                std::string& text = mNames[std::string(p.key)];
                text = settingText(p, defaults);
                mSub->add_option(flag, text, help + ": " + field.known() + ", default " + text);
            }
        },
        p.field);
}

bool SettingOptions::given(std::string_view key) const {
    return mSub != nullptr && mSub->count(settingFlag(key)) > 0;
}

std::string& SettingOptions::name(std::string_view key) {
    auto at = mNames.find(key);
    if (at == mNames.end()) throw std::logic_error("no named option " + std::string(key));
    return at->second;
}

const std::string& SettingOptions::name(std::string_view key) const {
    return const_cast<SettingOptions*>(this)->name(key);
}

void SettingOptions::applyTo(ShadowSettings& s, bool onlyGiven) const {
    for (const ParamInfo* p : mParams) {
        bool isGiven = given(p->key);
        if (onlyGiven && !isGiven) continue;
        std::visit(
            [&](const auto& field) {
                using F = std::decay_t<decltype(field)>;
                if constexpr (std::is_same_v<F, bool ShadowSettings::*>) {
                    s.*field = mValues.*field;
                } else if constexpr (std::is_member_object_pointer_v<F>) {
                    // A number given is read again from the text as typed, by the table's reader:
                    // its range checked, the value in a message as given ("--light-size 11",
                    // not CLI11's float of it), whether or not the method uses it.
                    if (!isGiven) {
                        s.*field = mValues.*field;
                        return;
                    }
                    const std::string& typed =
                        mSub->get_option(settingFlag(p->key))->results().back();
                    if (std::optional<ParamProblem> why = setParamFromText(s, *p, typed)) {
                        throw UsageError(cliWords(*why));
                    }
                } else {
                    s.*field.field = parseNamed(*p, field, mNames.find(p->key)->second);
                }
            },
            p->field);
    }
}

int methodOption(const std::string& name) {
    std::optional<int> id = methodFromName(name);
    if (!id) throw UsageError("unknown method '" + name + "' (known: " + methodNameList() + ")");
    return *id;
}

int weightsOption(const std::string& name) {
    std::optional<int> w = weightsFromName(name);
    if (!w) throw UsageError("unknown --weights '" + name + "' (known: box, binomial, gaussian)");
    return *w;
}

BiasMode biasModeOption(const std::string& name) {
    std::optional<BiasMode> b = biasModeFromName(name);
    if (!b) throw UsageError("unknown bias mode '" + name + "' (known: " + biasNameList() + ")");
    return *b;
}

TexelKind depthFormatOption(const std::string& name) {
    std::optional<TexelKind> f = depthFormatFromName(name);
    if (!f) {
        throw UsageError("unknown --depth-format '" + name + "' (known: " + depthFormatNames() +
                         ")");
    }
    return *f;
}

std::string settingsJson(const ShadowSettings& s, const PcfParams& pcss,
                         const std::optional<MapSpec>& map) {
    Json j = paramsJson(s, ParamSet::Raw);
    j["penumbra_scale"] = jsonNumber(pcss.penumbraScale);
    j["pcss_depth_near"] = jsonNumber(pcss.depthNear);
    j["pcss_depth_far"] = jsonNumber(pcss.depthFar);
    if (map) j["map"] = mapSpecJson(*map);
    return jsonDump(j) + "\n";
}

void checkBiasOptions(const ShadowSettings& s) {
    if (auto why = cliRangeProblem(s)) throw UsageError(*why);
    if (auto why = validateBias(static_cast<int>(s.bias), s.method)) throw UsageError(*why);
}

void checkLightSize(const Light& light, const ShadowSettings& s) {
    if (std::optional<ParamProblem> why = lightSizeProblem(light, s)) {
        throw UsageError(cliWords(*why));
    }
}

void checkCascades(const Scene& scene, const ShadowSettings& s) {
    if (std::optional<ParamProblem> why = cascadeProblem(scene, s))
        throw UsageError(cliWords(*why));
}

void RenderOptions::addTo(CLI::App* sub, const std::string& defaultScene,
                          std::initializer_list<std::string_view> except) {
    mDefaultScene = defaultScene;
    mSub = sub;
    sub->add_option("--lesson", lesson,
                    "a lesson (path, number or name): its scene and its step's settings; "
                    "options given here override them");
    sub->add_option("--step", lessonStep, "with --lesson: the step whose settings to use");
    sub->add_option("--scene", scene, "built-in scene: " + presetNameList());
    sub->add_option("--scene-file", sceneFile, "scene file (TOML)");
    shadow.cascades = cascades;
    if (picture) {
        shadow.addTo(sub, {ParamGroup::Filter, ParamGroup::Bias, ParamGroup::Map, ParamGroup::View},
                     defaults, except);
    } else {
        shadow.addTo(sub, {ParamGroup::Filter, ParamGroup::Bias, ParamGroup::Map}, defaults,
                     except);
    }
    sub->add_option("--polygon-offset", polygonOffset,
                    "slope-scaled bias in the shadow pass: FACTOR,UNITS for glPolygonOffset");
    sub->add_option("--size", size, sizeHelp("frame size", frameRange, "default " + size));
}

bool RenderOptions::given(const char* option) const {
    return mSub != nullptr && mSub->count(option) > 0;
}

RenderSettings RenderOptions::settings() const {
    RenderSettings s;
    static_cast<ShadowSettings&>(s) = defaults;
    glm::ivec2 frame = parseSize("--size", size, frameRange);
    bool fromLesson = !lesson.empty();
    if (fromLesson) {
        Lesson l = parseLessonFile(resolveLesson(lesson));
        requireIntRange("--step", lessonStep, 1, static_cast<int>(l.steps.size()));
        s = renderSettingsFor(l.steps[static_cast<size_t>(lessonStep - 1)].settings, frame);
    }
    shadow.applyTo(s, fromLesson);
    if (auto why = cliParamsProblem(s.pcfParams())) throw UsageError(*why);
    checkBiasOptions(s);
    if (!fromLesson || given("--polygon-offset")) {
        if (!polygonOffset.empty()) {
            s.polygonOffset = parseVec2("--polygon-offset", polygonOffset);
            requireRange("--polygon-offset factor", s.polygonOffset.x, -64.0f, 64.0f);
            requireRange("--polygon-offset units", s.polygonOffset.y, -1.0e6f, 1.0e6f);
        }
    }
    if (!fromLesson || shadow.given("map_size")) {
        requireIntRange("--map-size", s.mapSize, MIN_MAP_SIZE, MAX_MAP_SIZE);
    }
    s.frameSize = frame;
    return s;
}

Scene RenderOptions::loadScene() const {
    if (static_cast<int>(!scene.empty()) + static_cast<int>(!sceneFile.empty()) +
            static_cast<int>(!lesson.empty()) >
        1) {
        throw UsageError("give one of --scene, --scene-file or --lesson");
    }
    if (!lesson.empty()) return parseLessonFile(resolveLesson(lesson)).scene;
    if (!sceneFile.empty()) return parseSceneFile(sceneFile);
    std::string name = scene.empty() ? mDefaultScene : scene;
    if (name.empty()) throw UsageError("needs --scene PRESET, --scene-file FILE or --lesson L");
    std::optional<Scene> preset = presetScene(name);
    if (!preset) {
        throw UsageError("unknown scene '" + name + "' (known: " + presetNameList() + ")");
    }
    return *preset;
}

}  // namespace pcf
