// render/pcf_programs.h: the parameter table's uniforms (kernel/settings.h, PARAMS' uniform
// column) reach both programs that filter, the scene pass (scene.frag) and the lookup pass
// (lookup.frag): each is declared from the table, read by the GLSL (a uniform the program never
// reads has no location), and set to the settings' value by setParamUniforms.
#include "render/pcf_programs.h"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "kernel/methods.h"
#include "kernel/settings.h"
#include "render/gl_context.h"

namespace pcf {
namespace {

class PcfPrograms : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> PcfPrograms::sContext;

// Every float setting a value of its own, none its default: a uniform set from another
// setting's value, or from another member, reads back wrong. The one named setting with a
// uniform (the shading) is not its default either.
ShadowSettings distinctSettings() {
    ShadowSettings s;
    float next = 0.375f;
    for (const ParamInfo& p : allParams()) {
        if (const auto* field = std::get_if<float ShadowSettings::*>(&p.field)) {
            s.*(*field) = next;
            next += 0.5f;
        }
    }
    s.shading = Shading::Visibility;
    return s;
}

// The setting's value as its uniform holds it: a number, or a name's id (an int uniform).
float settingValue(const ParamInfo& p, const ShadowSettings& s) {
    return std::visit(
        [&](const auto& field) -> float {
            using F = std::decay_t<decltype(field)>;
            if constexpr (std::is_member_object_pointer_v<F>) {
                return static_cast<float>(s.*field);
            } else if constexpr (std::is_same_v<F, NamedField<vec2>>) {
                return (s.*field.field).x;  // no uniform: the exponents are uEvsmExponents
            } else {
                return static_cast<float>(static_cast<int>(s.*field.field));
            }
        },
        p.field);
}

// The variants that between them read every parameter: gaussian weights read sigma, poisson
// its radius; soft bias its scale on both (texel reads), receiver-plane its cap.
std::vector<PcfParams> variantParams(const ShadowSettings& s) {
    ShadowSettings gather = s;
    gather.method = PCF_GATHER;
    gather.weights = PCF_WEIGHTS_GAUSSIAN;
    ShadowSettings poisson = s;
    poisson.method = PCF_POISSON;
    // The moment methods read lbr and min_variance (evsm4) and moment_bias (msm).
    ShadowSettings evsm = s;
    evsm.method = PCF_EVSM4;
    evsm.kernel = 3;
    ShadowSettings msm = evsm;
    msm.method = PCF_MSM;
    return {gather.pcfParams(), poisson.pcfParams(), evsm.pcfParams(), msm.pcfParams()};
}

// For each table uniform, the values it read back with in the programs where it is live.
using LiveUniforms = std::map<std::string, std::vector<float>>;

void collectLive(GLuint program, LiveUniforms& live) {
    for (const ParamInfo& p : allParams()) {
        if (p.uniform.empty()) continue;
        std::string name(p.uniform);
        GLint at = glGetUniformLocation(program, name.c_str());
        if (at < 0) continue;
        float v = -1.0f;
        glGetUniformfv(program, at, &v);
        live[name].push_back(v);
    }
}

TEST_F(PcfPrograms, EveryTableUniformIsReadAndSetInTheSceneAndTheLookupPass) {
    ShadowSettings s = distinctSettings();
    LiveUniforms scene;
    LiveUniforms lookup;
    for (int mode = PCF_BIAS_NONE; mode < PCF_BIAS_COUNT; ++mode) {
        s.bias = static_cast<BiasMode>(mode);
        PcfBias bias = s.kernelBias();
        PcfProgramCache scenePrograms("scene.vert", "scene.frag",
                                      "#define PCF_ALL_TARGETS 1\n#define PCF_SCENE_BIAS " +
                                          std::to_string(mode) + "\n#define PCF_SCENE_SPOT 0\n");
        PcfProgramCache lookupPrograms("fullscreen.vert", "lookup.frag",
                                       "#define PCF_LOOKUP_BIAS " + std::to_string(mode) + "\n");
        for (const PcfParams& prm : variantParams(s)) {
            const PcfProgram& sceneProgram = scenePrograms.get(pcfVariant(prm, false, MapSpec{}));
            setParamUniforms(sceneProgram, prm, bias, &s);
            collectLive(sceneProgram.id(), scene);
            // The lookup pass has no settings: its ref comes with each lookup.
            const PcfProgram& lookupProgram = lookupPrograms.get(pcfVariant(prm, false, MapSpec{}));
            setParamUniforms(lookupProgram, prm, bias);
            collectLive(lookupProgram.id(), lookup);
        }
        // Cascades with a blend band: the scene program that reads uCascadeBlend.
        PcfVariant blended = pcfVariant(variantParams(s).front(), false, MapSpec{});
        blended.layers = MAX_CASCADES;
        blended.cascadeBlend = 1;
        const PcfProgram& blendedProgram = scenePrograms.get(blended);
        setParamUniforms(blendedProgram, variantParams(s).front(), bias, &s);
        collectLive(blendedProgram.id(), scene);
    }
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    for (const ParamInfo& p : allParams()) {
        if (p.uniform.empty()) continue;
        std::string name(p.uniform);
        bool member = !std::holds_alternative<std::monostate>(p.member);
        float want = settingValue(p, s);
        ASSERT_TRUE(scene.count(name)) << name << " is read by no scene program";
        for (float v : scene[name]) EXPECT_EQ(v, want) << name;
        // A uniform that fills a kernel member is the filter's: the lookup pass reads it too.
        // One that fills none is the scene's per-lookup bias, which the lookup pass has no use
        // for (and setParamUniforms, without settings, leaves unset).
        EXPECT_EQ(lookup.count(name) > 0, member) << name;
        for (float v : lookup[name]) EXPECT_EQ(v, want) << name;
    }
}

// pcss's program reads a spot map's depth range only where the map is perspective (the define
// PCF_PERSPECTIVE folds the linear-depth branch away elsewhere, issue 23), and its table of
// 1 / k from the uniform array setParamUniforms fills from the kernel's C++ table.
TEST_F(PcfPrograms, PcssReadsTheDepthRangeOnlyOnAPerspectiveMapAndTheReciprocalsFromTheTable) {
    PcfProgramCache programs("fullscreen.vert", "lookup.frag",
                             "#define PCF_LOOKUP_BIAS " + std::to_string(PCF_BIAS_CONSTANT) + "\n");
    ShadowSettings s;
    s.method = PCF_PCSS;
    PcfParams ortho = s.pcfParams(vec2(1.0f, 0.0f), 24.0f);
    PcfParams spot = ortho;
    spot.depthNear = 1.0f;
    spot.depthFar = 4.0f;
    EXPECT_EQ(pcfVariant(ortho, false, MapSpec{}).perspective, 0);
    EXPECT_EQ(pcfVariant(spot, false, MapSpec{}).perspective, 1);
    // Only pcss reads near and far: another method keeps its one program under a spot.
    PcfParams gatherUnderSpot = spot;
    gatherUnderSpot.method = PCF_GATHER;
    EXPECT_EQ(pcfVariant(gatherUnderSpot, false, MapSpec{}).perspective, 0);

    PcfBias bias = s.kernelBias();
    const PcfProgram& orthoCached = programs.get(pcfVariant(ortho, false, MapSpec{}));
    const PcfProgram& spotCached = programs.get(pcfVariant(spot, false, MapSpec{}));
    GLuint orthoProgram = orthoCached.id();
    GLuint spotProgram = spotCached.id();
    ASSERT_NE(orthoProgram, spotProgram);
    EXPECT_LT(glGetUniformLocation(orthoProgram, "uPcssDepthRange"), 0);
    GLint range = glGetUniformLocation(spotProgram, "uPcssDepthRange");
    ASSERT_GE(range, 0);
    setParamUniforms(spotCached, spot, bias);
    float nearFar[2] = {0.0f, 0.0f};
    glGetUniformfv(spotProgram, range, nearFar);
    EXPECT_EQ(nearFar[0], 1.0f);
    EXPECT_EQ(nearFar[1], 4.0f);

    setParamUniforms(orthoCached, ortho, bias);
    for (int k = 1; k <= PCF_PCSS_TAPS; ++k) {
        std::string name = "uPcssReciprocals[" + std::to_string(k) + "]";
        GLint at = glGetUniformLocation(orthoProgram, name.c_str());
        ASSERT_GE(at, 0) << name;
        float v = 0.0f;
        glGetUniformfv(orthoProgram, at, &v);
        EXPECT_EQ(v, PCF_PCSS_RECIPROCALS[k]) << name;
    }
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace pcf
