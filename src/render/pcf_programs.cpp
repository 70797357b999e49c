#include "render/pcf_programs.h"

#include <iterator>
#include <span>
#include <type_traits>
#include <variant>
#include <vector>

#include "render/shader_loader.h"

namespace pcf {

namespace {

// The kernel member a uniform fills: the uniform's name without its "u", first letter lowered
// (settings.h ParamInfo::uniform).
std::string memberName(std::string_view uniform) {
    std::string name(uniform.substr(1));
    if (!name.empty()) name[0] = static_cast<char>(name[0] - 'A' + 'a');
    return name;
}

// "    p.radius = uRadius;\n" for each table uniform filling a member of kernel struct `Struct`.
template <class Struct>
std::string memberFills(const char* var) {
    std::string out;
    for (const ParamInfo& p : allParams()) {
        if (!std::holds_alternative<float Struct::*>(p.member)) continue;
        out += "    " + std::string(var) + "." + memberName(p.uniform) + " = " +
               std::string(p.uniform) + ";\n";
    }
    return out;
}

}  // namespace

std::string paramUniformsGlsl() {
    std::string out =
        "// The parameter table's uniforms (kernel/settings.cpp PARAMS) and the kernel's structs\n"
        "// built from them: render/pcf_programs.cpp, paramUniformsGlsl.\n";
    for (const ParamInfo& p : allParams()) {
        if (p.uniform.empty()) continue;
        bool isFloat = std::holds_alternative<float ShadowSettings::*>(p.field);
        out += std::string("uniform ") + (isFloat ? "float " : "int ") + std::string(p.uniform) +
               ";\n";
    }
    out += "uniform PcfMapLayer uPcfMapLayers[PCF_MAP_LAYERS];  // the map's layers (MapSpec)\n";
    out += "uniform float uPenumbraScale;  // pcss: texels of penumbra per unit of light depth\n";
    out += "uniform vec2 uPcssDepthRange;  // pcss: a spot map's near, far; 0: orthographic\n";
    out += "uniform vec2 uEvsmExponents;  // evsm: the exponents used (clamped to the format)\n";
    out +=
        "PcfParams pcfProgramParams(vec2 rotation) {\n"
        "    PcfParams p;\n"
        "    p.method = PCF_METHOD;\n"
        "    p.kernel = PCF_KERNEL;\n"
        "    p.weights = PCF_WEIGHTS;\n"
        "    p.rotation = rotation;\n"
        "    p.penumbraScale = uPenumbraScale;\n"
        "    p.evsmExponents = uEvsmExponents;\n"
        "#if PCF_PERSPECTIVE\n"
        "    p.depthNear = uPcssDepthRange.x;\n"
        "    p.depthFar = uPcssDepthRange.y;\n"
        "#else\n"
        "    p.depthNear = 0.0;\n"
        "    p.depthFar = 0.0;\n"
        "#endif\n" +
        memberFills<PcfParams>("p") +
        "    return p;\n"
        "}\n";
    out +=
        "PcfBias pcfProgramBias(int mode, vec2 dzduv) {\n"
        "    PcfBias b;\n"
        "    b.mode = mode;\n"
        "    b.dzduv = dzduv;\n" +
        memberFills<PcfBias>("b") +
        "    return b;\n"
        "}\n";
    return out;
}

ParamUniformLocations paramUniformLocations(GLuint program) {
    ParamUniformLocations out;
    for (const ParamInfo& p : allParams()) {
        out.params.push_back(
            p.uniform.empty() ? -1 : glGetUniformLocation(program, std::string(p.uniform).c_str()));
    }
    out.penumbraScale = glGetUniformLocation(program, "uPenumbraScale");
    out.pcssDepthRange = glGetUniformLocation(program, "uPcssDepthRange");
    out.evsmExponents = glGetUniformLocation(program, "uEvsmExponents");
    out.pcssReciprocals = glGetUniformLocation(program, "uPcssReciprocals");
    return out;
}

namespace {

// setParamUniforms with the program's locations in hand.
void setUniformsAt(GLuint program, const ParamUniformLocations& where, const PcfParams& prm,
                   const PcfBias& bias, const ShadowSettings* settings) {
    std::span<const ParamInfo> params = allParams();
    for (size_t k = 0; k < params.size(); ++k) {
        const ParamInfo& p = params[k];
        if (p.uniform.empty()) continue;
        GLint at = where.params[k];
        if (const auto* m = std::get_if<float PcfParams::*>(&p.member)) {
            glProgramUniform1f(program, at, prm.*(*m));
            continue;
        }
        if (const auto* m = std::get_if<float PcfBias::*>(&p.member)) {
            glProgramUniform1f(program, at, bias.*(*m));
            continue;
        }
        if (!settings) continue;
        const ShadowSettings& s = *settings;
        std::visit(
            [&](const auto& field) {
                using F = std::decay_t<decltype(field)>;
                if constexpr (std::is_same_v<F, float ShadowSettings::*>) {
                    glProgramUniform1f(program, at, s.*field);
                } else if constexpr (std::is_same_v<F, int ShadowSettings::*>) {
                    glProgramUniform1i(program, at, s.*field);
                } else if constexpr (std::is_same_v<F, bool ShadowSettings::*>) {
                    glProgramUniform1i(program, at, s.*field ? 1 : 0);
                } else if constexpr (std::is_same_v<F, NamedField<vec2>>) {
                    glProgramUniform2f(program, at, (s.*field.field).x, (s.*field.field).y);
                } else {
                    glProgramUniform1i(program, at, static_cast<int>(s.*field.field));
                }
            },
            p.field);
    }
    glProgramUniform1f(program, where.penumbraScale, prm.penumbraScale);
    glProgramUniform2f(program, where.pcssDepthRange, prm.depthNear, prm.depthFar);
    glProgramUniform2f(program, where.evsmExponents, prm.evsmExponents.x, prm.evsmExponents.y);
    glProgramUniform1fv(program, where.pcssReciprocals,
                        static_cast<GLsizei>(std::size(PCF_PCSS_RECIPROCALS)),
                        PCF_PCSS_RECIPROCALS);
}

}  // namespace

void setParamUniforms(const PcfProgram& program, const PcfParams& prm, const PcfBias& bias,
                      const ShadowSettings* settings) {
    setUniformsAt(program.id(), program.uniforms, prm, bias, settings);
}

void setParamUniforms(GLuint program, const PcfParams& prm, const PcfBias& bias,
                      const ShadowSettings* settings) {
    setUniformsAt(program, paramUniformLocations(program), prm, bias, settings);
}

PcfProgramCache::PcfProgramCache(std::string vertexFile, std::string fragmentFile,
                                 std::string extraDefines)
    : mVertexFile(std::move(vertexFile)),
      mFragmentFile(std::move(fragmentFile)),
      mExtraDefines(std::move(extraDefines)) {}

PcfVariant pcfVariant(const PcfParams& prm, bool rotatePerPixel, const MapSpec& map) {
    // depthNear first: an id outside the table (the dispatch's test) has none.
    int perspective = prm.depthNear > 0.0f && methodInfo(prm.method).searchesBlockers ? 1 : 0;
    PcfVariant v;
    v.method = prm.method;
    v.kernel = prm.kernel;
    v.weights = prm.weights;
    v.precision = prm.precision;
    v.fixedPoint = map.texel().fixedPoint ? 1 : 0;
    v.rotatePerPixel = rotatePerPixel ? 1 : 0;
    v.perspective = perspective;
    v.layers = static_cast<int>(map.layers.size());
    return v;
}

void setMapUniforms(GLuint program, const MapSpec& map) {
    for (size_t k = 0; k < map.layers.size(); ++k) {
        const PcfMapLayer& layer = map.layers[k];
        std::string at = "uPcfMapLayers[" + std::to_string(k) + "].";
        glProgramUniformMatrix4fv(
            program, glGetUniformLocation(program, (at + "shadowClipFromWorld").c_str()), 1,
            GL_FALSE, &layer.shadowClipFromWorld[0][0]);
        glProgramUniform2fv(program, glGetUniformLocation(program, (at + "depthRange").c_str()), 1,
                            &layer.depthRange.x);
        glProgramUniform1f(program, glGetUniformLocation(program, (at + "texelWs").c_str()),
                           layer.texelWs);
        glProgramUniform2fv(program, glGetUniformLocation(program, (at + "viewDepth").c_str()), 1,
                            &layer.viewDepth.x);
    }
}

std::string pcfVariantDefines(const PcfVariant& variant) {
    auto line = [](const char* name, int value) {
        return std::string("#define ") + name + " " + std::to_string(value) + "\n";
    };
    return line("PCF_METHOD", variant.method) + line("PCF_KERNEL", variant.kernel) +
           line("PCF_WEIGHTS", variant.weights) + line("PCF_PRECISION", variant.precision) +
           line("PCF_FIXED_POINT", variant.fixedPoint) +
           line("PCF_ROTATE_PER_PIXEL", variant.rotatePerPixel) +
           line("PCF_PERSPECTIVE", variant.perspective) + line("PCF_MAP_LAYERS", variant.layers) +
           line("PCF_CASCADE_BLEND", variant.cascadeBlend);
}

const PcfProgram& PcfProgramCache::get(const PcfVariant& variant) {
    auto it = mPrograms.find(variant);
    if (it != mPrograms.end()) return it->second;
    std::string defines = pcfVariantDefines(variant) + mExtraDefines;
    GlProgram program = buildProgram({
        ShaderStage{GL_VERTEX_SHADER, {mVertexFile}, "", {}},
        ShaderStage{GL_FRAGMENT_SHADER,
                    pcfSharedFiles({"shared/pcf_shading.h"}),
                    defines,
                    {{"<parameter uniforms>", paramUniformsGlsl()},
                     {"shaders/" + mFragmentFile, std::string(embeddedShader(mFragmentFile))}}},
    });
    ParamUniformLocations uniforms = paramUniformLocations(program.id());
    return mPrograms.emplace(variant, PcfProgram{std::move(program), std::move(uniforms)})
        .first->second;
}

std::vector<std::string> pcfSharedFiles(std::vector<std::string> after) {
    std::vector<std::string> files = {"shared/pcf_prelude.h", "shared/pcf_kernel.h",
                                      "shared/pcf_disk.h", "shared/pcf_moments.h",
                                      "shared/pcf_filter.h"};
    files.insert(files.end(), after.begin(), after.end());
    return files;
}

PcfSamplers createPcfSamplers() { return {createNearestSampler(), createCompareSampler()}; }

void bindShadowMap(GLuint program, GLuint depthTexture, const PcfSamplers& samplers) {
    bindShadowMap(program, depthTexture, depthTexture, samplers);
}

void bindShadowMap(GLuint program, GLuint mapTexture, GLuint depthTexture,
                   const PcfSamplers& samplers) {
    glBindTextureUnit(0, mapTexture);
    glBindSampler(0, samplers.nearest.id());
    glBindTextureUnit(1, depthTexture);
    glBindSampler(1, samplers.compare.id());
    glProgramUniform1i(program, glGetUniformLocation(program, "uPcfDepth"), 0);
    glProgramUniform1i(program, glGetUniformLocation(program, "uPcfCompare"), 1);
}

}  // namespace pcf
