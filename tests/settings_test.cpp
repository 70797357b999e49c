// kernel/settings.h: the settings vocabulary the CLI, lesson files and renderer share, and the
// one parameter table each of them is generated from.
#include "kernel/settings.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "app/cli_util.h"
#include "app/render_options.h"
#include "json_lite.h"
#include "kernel/trace_json.h"
#include "lesson/lesson.h"

namespace pcf {
namespace {

TEST(Settings, TentTakesThreeFiveOrSevenAndTheOthersTheRange) {
    for (int n = -1; n <= MAX_KERNEL + 2; ++n) {
        EXPECT_EQ(kernelFits(PCF_TENT, n), n == 3 || n == 5 || n == 7) << n;
        EXPECT_EQ(kernelFits(PCF_GATHER, n), n >= MIN_KERNEL && n <= MAX_KERNEL) << n;
        EXPECT_TRUE(kernelFits(PCF_BILINEAR2X2, n)) << n;  // no kernel: any N is ignored
    }
    EXPECT_EQ(kernelSizesText(PCF_TENT), "3, 5 or 7");
    EXPECT_EQ(kernelSizesText(PCF_NAIVE), "1..8");
}

TEST(Settings, ValidateParamsFollowsTheSameRule) {
    for (int n = MIN_KERNEL; n <= MAX_KERNEL; ++n) {
        bool tentTakes = n == 3 || n == 5 || n == 7;
        EXPECT_EQ(validateParams(makeParams(PCF_TENT, n)).has_value(), !tentTakes) << n;
        EXPECT_FALSE(validateParams(makeParams(PCF_GATHER, n)).has_value()) << n;
    }
    EXPECT_TRUE(validateParams(makeParams(PCF_GATHER, MAX_KERNEL + 1)).has_value());
}

TEST(Settings, KernelKeysStepThroughWhatTheMethodTakes) {
    EXPECT_EQ(stepKernel(PCF_TENT, 3, 1), 5);
    EXPECT_EQ(stepKernel(PCF_TENT, 5, 1), 7);
    EXPECT_EQ(stepKernel(PCF_TENT, 7, 1), 7);
    EXPECT_EQ(stepKernel(PCF_TENT, 5, -1), 3);
    EXPECT_EQ(stepKernel(PCF_TENT, 3, -1), 3);
    EXPECT_EQ(stepKernel(PCF_TENT, 4, 1), 3);  // a size tent cannot take: its smallest
    EXPECT_EQ(stepKernel(PCF_GATHER, 3, 1), 4);
    EXPECT_EQ(stepKernel(PCF_GATHER, MAX_KERNEL, 1), MAX_KERNEL);
    EXPECT_EQ(stepKernel(PCF_GATHER, MIN_KERNEL, -1), MIN_KERNEL);
    EXPECT_EQ(fitKernel(PCF_TENT, 6), 3);
    EXPECT_EQ(fitKernel(PCF_TENT, 5), 5);
    EXPECT_EQ(fitKernel(PCF_GATHER, 6), 6);
}

TEST(Settings, NamesRoundTrip) {
    for (TexelKind f : {TexelKind::D16, TexelKind::D24, TexelKind::D32F}) {
        EXPECT_EQ(depthFormatFromName(depthFormatName(f)), f);
        EXPECT_NE(depthFormatNames().find(depthFormatName(f)), std::string::npos);
    }
    EXPECT_EQ(depthFormatFromName("32"), TexelKind::D32F);
    EXPECT_FALSE(depthFormatFromName("8").has_value());
    EXPECT_EQ(depthFormatNames(), "16, 24, 32f");
    // Moments are a map's texel kind, not a depth format.
    EXPECT_FALSE(depthFormatFromName("moments2-32f").has_value());
    EXPECT_EQ(nextDepthFormat(TexelKind::D32F), TexelKind::D16);
    EXPECT_EQ(nextDepthFormat(TexelKind::D16), TexelKind::D24);
    for (CullMode c : {CullMode::Back, CullMode::Front, CullMode::None}) {
        EXPECT_EQ(cullModeFromName(cullModeName(c)), c);
        EXPECT_NE(CULL_MODE_NAMES.find(cullModeName(c)), std::string_view::npos);
    }
    EXPECT_FALSE(cullModeFromName("both").has_value());
    for (Shading s : {Shading::Lit, Shading::Visibility, Shading::Cascades}) {
        EXPECT_EQ(shadingFromName(shadingName(s)), s);
        EXPECT_NE(SHADING_NAMES.find(shadingName(s)), std::string_view::npos);
    }
    EXPECT_FALSE(shadingFromName("flat").has_value());
    for (int m = 0; m < PCF_BIAS_COUNT; ++m) {
        BiasMode mode = static_cast<BiasMode>(m);
        EXPECT_EQ(biasModeFromName(biasModeName(mode)), mode);
        EXPECT_EQ(biasModeName(mode), biasName(m));  // one table of names: kernel/bias.h
    }
    EXPECT_FALSE(biasModeFromName("lots").has_value());
}

// The value of parameter p as a lesson file writes it: names quoted, numbers and flags bare.
std::string tomlValue(const ParamInfo& p, const ShadowSettings& s) {
    std::string text = settingText(p, s);
    bool named = p.field.index() >= 3;  // the NamedField alternatives follow the member pointers
    return named ? "\"" + text + "\"" : text;
}

// A lesson whose [settings] sets `key = value`, parsed: its first step's settings.
LessonSettings lessonWith(std::string_view key, const std::string& value) {
    // light_radius is a spot light's size: its scene has one.
    std::string scene = key == "light_radius" ? "post-under-spot" : "box-on-plane";
    std::string text = "title = \"t\"\nscene = \"" + scene + "\"\n[settings]\n" + std::string(key) +
                       " = " + value + "\n[[step]]\ntitle = \"s\"\ntext = \"x\"\n";
    return parseLessonString(text, "table.toml").steps.at(0).settings;
}

// Each numeric parameter at the top of its range (a value no default has).
ShadowSettings atMax(const ParamInfo& p) {
    ShadowSettings s;
    if (auto f = std::get_if<int ShadowSettings::*>(&p.field)) s.*(*f) = static_cast<int>(p.max);
    if (auto f = std::get_if<float ShadowSettings::*>(&p.field))
        s.*(*f) = static_cast<float>(p.max);
    if (auto f = std::get_if<bool ShadowSettings::*>(&p.field)) s.*(*f) = !(s.*(*f));
    return s;
}

// The address of p's field in s: two rows must not name the same field.
const void* fieldIn(const ParamInfo& p, const ShadowSettings& s) {
    return std::visit(
        [&](const auto& field) -> const void* {
            if constexpr (std::is_member_object_pointer_v<std::decay_t<decltype(field)>>) {
                return &(s.*field);
            } else {
                return &(s.*field.field);
            }
        },
        p.field);
}

TEST(ParameterTable, EveryParameterOnceWithItsKeyFlagAndRange) {
    std::set<std::string_view> keys;
    std::set<std::string> flags;
    ShadowSettings defaults;
    for (const ParamInfo& p : allParams()) {
        EXPECT_TRUE(keys.insert(p.key).second) << p.key;
        EXPECT_TRUE(flags.insert(settingFlag(p.key)).second) << p.key;
        EXPECT_EQ(findParam(p.key), &p) << p.key;
        EXPECT_FALSE(p.help.empty()) << p.key;
        for (const ParamInfo& q : allParams()) {
            if (&p != &q) {
                EXPECT_NE(fieldIn(p, defaults), fieldIn(q, defaults)) << p.key << q.key;
            }
        }
        if (std::holds_alternative<int ShadowSettings::*>(p.field) ||
            std::holds_alternative<float ShadowSettings::*>(p.field)) {
            double v = std::stod(settingText(p, defaults));
            EXPECT_LT(p.min, p.max) << p.key;
            EXPECT_TRUE((p.minOpen ? v > p.min : v >= p.min) && v <= p.max) << p.key << " " << v;
        }
    }
    EXPECT_EQ(settingFlag("constant_bias"), "--constant-bias");
    EXPECT_EQ(findParam("rpdbMax"), nullptr);
    EXPECT_EQ(settingText(*findParam("method"), defaults), "pcf-gather");
    EXPECT_EQ(settingText(*findParam("rpdb_max"), defaults), "100");
}

// The bias rows are the fields of BiasSettings, what the trace and the kernel take (trace.h
// traceLookup, kernelBias), and no others: a bias parameter declared beside them in
// ShadowSettings would reach the command line and the uniforms but never the trace.
TEST(ParameterTable, TheBiasRowsAreTheFieldsTheKernelAndTheTraceTake) {
    ShadowSettings defaults;
    const BiasSettings& bias = defaults;
    const char* lo = reinterpret_cast<const char*>(&bias);
    int rows = 0;
    for (const ParamInfo& p : allParams()) {
        const char* at = static_cast<const char*>(fieldIn(p, defaults));
        bool inBias = at >= lo && at < lo + sizeof(BiasSettings);
        EXPECT_EQ(inBias, p.group == ParamGroup::Bias) << p.key;
        rows += inBias ? 1 : 0;
        // A per-tap parameter's kernel member is filled from its setting.
        if (const auto* m = std::get_if<float PcfBias::*>(&p.member)) {
            ShadowSettings s = atMax(p);
            EXPECT_EQ(s.kernelBias().*(*m), static_cast<float>(p.max)) << p.key;
        }
    }
    EXPECT_GE(rows, 7);  // the mode and its six parameters, at least
}

// The modes a parameter acts under (biasModes): some for every bias parameter, none for the mode
// itself and for every parameter that is no bias's; none acts under `none`.
TEST(ParameterTable, EveryBiasParameterActsUnderTheModesItNames) {
    for (const ParamInfo& p : allParams()) {
        bool parameterOfBias = p.group == ParamGroup::Bias && p.key != "bias";
        EXPECT_EQ(p.biasModes != 0, parameterOfBias) << p.key;
        EXPECT_FALSE(paramActsUnder(p, BiasMode::None)) << p.key;
        EXPECT_EQ(p.biasModes >> PCF_BIAS_COUNT, 0u) << p.key;
    }
    EXPECT_TRUE(paramActsUnder(*findParam("rpdb_max"), BiasMode::ReceiverPlane));
    EXPECT_FALSE(paramActsUnder(*findParam("rpdb_max"), BiasMode::Soft));
    EXPECT_TRUE(paramActsUnder(*findParam("constant_bias"), BiasMode::Interpolated));
}

// The uniforms reach the programs: tests/pcf_programs_test.cpp.
TEST(ParameterTable, EveryUniformIsNamedForTheKernelMemberItFills) {
    int uniforms = 0;
    for (const ParamInfo& p : allParams()) {
        if (p.uniform.empty()) {
            EXPECT_TRUE(std::holds_alternative<std::monostate>(p.member)) << p.key;
            continue;
        }
        ++uniforms;
        // "u" and a capital: pcf_programs.cpp reads the member's name off the uniform's.
        ASSERT_GE(p.uniform.size(), 2u) << p.key;
        EXPECT_EQ(p.uniform[0], 'u') << p.key;
        EXPECT_TRUE(p.uniform[1] >= 'A' && p.uniform[1] <= 'Z') << p.key;
        // A member is a float; so is the setting that fills it.
        if (!std::holds_alternative<std::monostate>(p.member)) {
            EXPECT_TRUE(std::holds_alternative<float ShadowSettings::*>(p.field)) << p.key;
        }
    }
    EXPECT_GE(uniforms, 8);
}

TEST(ParameterTable, EveryParameterRoundTripsThroughALessonFile) {
    for (const ParamInfo& p : allParams()) {
        ShadowSettings defaults;
        EXPECT_EQ(settingText(p, lessonWith(p.key, tomlValue(p, defaults))),
                  settingText(p, defaults))
            << p.key;
        if (const auto* named = std::get_if<NamedField<int>>(&p.field)) {
            // Every name of the method, weights and precision tables reads back as itself, or is
            // refused for the default method (weights) but never as unknown.
            int read = 0;
            std::stringstream known(named->known());
            for (std::string name; std::getline(known >> std::ws, name, ',');) {
                try {
                    EXPECT_EQ(settingText(p, lessonWith(p.key, "\"" + name + "\"")), name);
                    ++read;
                } catch (const InputError& e) {
                    EXPECT_EQ(std::string(e.what()).find("unknown"), std::string::npos) << e.what();
                }
            }
            EXPECT_GE(read, 2) << p.key;
            continue;
        }
        if (p.field.index() >= 3) continue;  // the enums' names: NamesRoundTrip
        ShadowSettings top = atMax(p);
        EXPECT_EQ(settingText(p, lessonWith(p.key, tomlValue(p, top))), settingText(p, top))
            << p.key;
    }
}

// A command's parse of `args` with the shared options, as `render` registers them.
RenderSettings parseRenderOptions(std::vector<std::string> args) {
    CLI::App app;
    RenderOptions options;
    options.picture = true;   // render's: the View group too
    options.cascades = true;  // and the cascades
    options.addTo(&app, "box-on-plane");
    std::reverse(args.begin(), args.end());
    app.parse(args);
    return options.settings();
}

TEST(ParameterTable, EveryParameterHasAFlagThatParsesItsDefaultAndItsMax) {
    RenderSettings none = parseRenderOptions({});
    for (const ParamInfo& p : allParams()) {
        ShadowSettings defaults;
        std::string flag = settingFlag(p.key);
        EXPECT_EQ(settingText(p, none), settingText(p, defaults)) << p.key;
        if (std::holds_alternative<bool ShadowSettings::*>(p.field)) {
            EXPECT_EQ(settingText(p, parseRenderOptions({flag})), "true") << flag;
            continue;
        }
        EXPECT_EQ(settingText(p, parseRenderOptions({flag, settingText(p, defaults)})),
                  settingText(p, defaults))
            << flag;
        if (p.field.index() >= 3) continue;
        ShadowSettings top = atMax(p);
        EXPECT_EQ(settingText(p, parseRenderOptions({flag, settingText(p, top)})),
                  settingText(p, top))
            << flag;
    }
    EXPECT_THROW(parseRenderOptions({"--cull", "both"}), UsageError);
    EXPECT_THROW(parseRenderOptions({"--slope-max", "2"}), UsageError);
}

// `v` is row `p`'s value in `s`, as the status line and the lesson files say it (settingText).
void expectParamValue(const jsonlite::Value& v, const ParamInfo& p, const ShadowSettings& s) {
    switch (v.kind) {
        case jsonlite::Value::STRING:
            EXPECT_EQ(v.string, settingText(p, s)) << p.key;
            break;
        case jsonlite::Value::BOOL:
            EXPECT_EQ(v.boolean ? "true" : "false", settingText(p, s)) << p.key;
            break;
        default:
            EXPECT_EQ(v.number, std::stod(settingText(p, s))) << p.key;
    }
}

TEST(ParameterTable, TheRawJsonHoldsTheMarkedParametersWithTheirValues) {
    ShadowSettings s;
    s.method = PCF_POISSON;
    s.radius = 2.5f;
    s.bias = BiasMode::Soft;
    s.softScale = 1000.0f;
    jsonlite::Value j = jsonlite::parse(settingsJson(s));
    size_t marked = 0;
    for (const ParamInfo& p : allParams()) {
        if (!p.rawJson) {
            EXPECT_FALSE(j.has(std::string(p.key))) << p.key;
            continue;
        }
        ++marked;
        expectParamValue(j[std::string(p.key)], p, s);
    }
    // ... and three numbers that are not settings: pcss's penumbra scale and a spot map's near
    // and far, which the scene and the map give (scene/pcss.h), so that `verify` recomputes pcss
    // from the folder alone.
    EXPECT_EQ(j.size(), marked + 3);
    EXPECT_EQ(j["penumbra_scale"].number, 0.0);
    EXPECT_EQ(j["pcss_depth_near"].number, 0.0);
    EXPECT_EQ(j["pcss_depth_far"].number, 0.0);
    EXPECT_EQ(j["method"].string, "poisson");
    EXPECT_EQ(j["soft_scale"].number, 1000.0);
}

}  // namespace
}  // namespace pcf

namespace pcf {
namespace {

// An export's sidecar lists every setting the step is made with, from the table: a parameter
// added to the table appears there, in the table's order, with its value.
TEST(ParameterTable, TheStepSidecarHoldsEveryParameterInTheTablesOrder) {
    ShadowSettings s;
    s.method = PCF_NAIVE;
    s.weights = PCF_WEIGHTS_GAUSSIAN;
    s.sigma = 0.75f;
    s.bias = BiasMode::Slope;
    s.slopeBias = 0.003f;
    s.cull = CullMode::Front;
    s.depthFormat = TexelKind::D16;
    Json ordered = paramsJson(s, ParamSet::All);
    std::vector<std::string> keys;
    for (const auto& item : ordered.items()) keys.push_back(item.key());
    std::vector<std::string> want;
    for (const ParamInfo& p : allParams()) want.push_back(std::string(p.key));
    EXPECT_EQ(keys, want) << "every row, in the table's order";
    jsonlite::Value j = jsonlite::parse(jsonDump(ordered));
    for (const ParamInfo& p : allParams()) expectParamValue(j[std::string(p.key)], p, s);
    EXPECT_EQ(j["sigma"].number, 0.75);
    EXPECT_EQ(j["cull"].string, "front");
}

// A trace's `bias` is the table's bias rows under their lesson-file keys, then what the trace
// adds: the receiver plane as measured and as used, and where each tap's ref is taken.
TEST(ParameterTable, ATracesBiasIsTheTablesBiasRows) {
    ShadowMap map(4, 4);
    BiasSettings b;
    b.bias = BiasMode::Normal;
    b.normalOffset = 1.5f;
    Trace tr = traceLookup(map, vec2(0.5f), 0.5f, 0.49f, makeParams(PCF_BOX2X2), b);
    std::string text = traceToJson(tr);
    std::vector<std::string> keys;
    Json parsed = Json::parse(text);
    for (const auto& item : parsed["bias"].items()) keys.push_back(item.key());
    jsonlite::Value j = jsonlite::parse(text)["bias"];
    ShadowSettings s;
    static_cast<BiasSettings&>(s) = b;
    std::vector<std::string> want;
    for (const ParamInfo& p : allParams()) {
        if (p.group != ParamGroup::Bias) continue;
        want.push_back(std::string(p.key));
        expectParamValue(j[std::string(p.key)], p, s);
    }
    for (const char* extra : {"dzduv", "dzduv_used", "per_tap"}) want.push_back(extra);
    EXPECT_EQ(keys, want);
    EXPECT_EQ(j["bias"].string, "normal");
    EXPECT_EQ(j["normal_offset"].number, 1.5);
}

// The moment methods' parameters act for the methods that read them (the bleed sweep sweeps a
// setting only there): the light-bleeding reduction and the variance's floor for the Chebyshev
// bound's three, the exponents for evsm's two, the moment bias for msm's two, the moment format
// for all five; the other parameters for every method.
TEST(ParameterTable, EachMomentParameterActsForTheMethodsThatReadIt) {
    auto actsFor = [](const char* key) {
        std::set<std::string> names;
        for (const MethodInfo& m : allMethods()) {
            if (paramActsFor(*findParam(key), m.id)) names.insert(std::string(m.name));
        }
        return names;
    };
    using Names = std::set<std::string>;
    EXPECT_EQ(actsFor("lbr"), (Names{"vsm", "evsm2", "evsm4"}));
    EXPECT_EQ(actsFor("min_variance"), (Names{"vsm", "evsm2", "evsm4"}));
    EXPECT_EQ(actsFor("evsm_exponents"), (Names{"evsm2", "evsm4"}));
    EXPECT_EQ(actsFor("moment_bias"), (Names{"msm", "msm-hausdorff"}));
    EXPECT_EQ(actsFor("moment_format"), (Names{"vsm", "evsm2", "evsm4", "msm", "msm-hausdorff"}));
    EXPECT_EQ(actsFor("constant_bias").size(), allMethods().size());
}

}  // namespace
}  // namespace pcf
