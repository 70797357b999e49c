// The embedded shaders, the order the loader assembles them in, its error messages, and the
// shared PCF kernel header compiled as GLSL 4.50 by the driver.
#include "render/shader_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "kernel/pcf.h"
#include "render/gl_context.h"
#include "render/gl_objects.h"
#include "render/pcf_programs.h"

namespace pcf {
namespace {

std::string readSourceFile(const std::string& relative) {
    std::ifstream in(std::string(PCFSCOPE_SOURCE_DIR) + "/" + relative, std::ios::binary);
    EXPECT_TRUE(in.good()) << relative;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The 1-based line of the first line of `text` that contains `needle`; 0 when none does.
int lineOf(const std::string& text, const std::string& needle) {
    std::istringstream in(text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        if (line.find(needle) != std::string::npos) return n;
    }
    return 0;
}

class ShaderLoader : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    void SetUp() override { sContext->makeCurrent(); }

    static std::unique_ptr<GlContext> sContext;
};

std::unique_ptr<GlContext> ShaderLoader::sContext;

std::string buildError(const std::vector<ShaderStage>& stages) {
    try {
        buildProgram(stages);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    ADD_FAILURE() << "the program built, but it should not have";
    return "";
}

const char* FULL_VERT = R"(
const vec2 CORNERS[3] = vec2[3](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
void main() { gl_Position = vec4(CORNERS[gl_VertexID], 0.0, 1.0); }
)";

TEST(EmbeddedShaders, PreludeIsTheFileAsWritten) {
    EXPECT_EQ(embeddedShader("shared/pcf_prelude.h"),
              readSourceFile("shaders/shared/pcf_prelude.h"));
    EXPECT_EQ(embeddedShader("shared/pcf_kernel.h"), readSourceFile("shaders/shared/pcf_kernel.h"));
}

TEST(EmbeddedShaders, EveryFileUnderShadersIsEmbedded) {
    std::filesystem::path root = std::filesystem::path(PCFSCOPE_SOURCE_DIR) / "shaders";
    std::vector<std::string> onDisk;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        std::string name = entry.path().filename().string();
        if (!entry.is_regular_file() || name.starts_with('.') || name.ends_with('~')) continue;
        onDisk.push_back(std::filesystem::relative(entry.path(), root).generic_string());
    }
    std::sort(onDisk.begin(), onDisk.end());
    std::vector<std::string> embedded;
    for (const EmbeddedShader& s : embeddedShaders()) embedded.emplace_back(s.path);
    EXPECT_EQ(embedded, onDisk);
    for (const std::string& path : onDisk) {
        EXPECT_EQ(embeddedShader(path), readSourceFile("shaders/" + path)) << path;
    }
}

TEST(EmbeddedShaders, UnknownPathThrowsNamingIt) {
    try {
        embeddedShader("shared/no_such_file.glsl");
        FAIL() << "an unknown shader was found";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("shaders/shared/no_such_file.glsl"), std::string::npos)
            << e.what();
    }
}

TEST(AssembleStage, StringsComeInOrderWithLineMarkers) {
    ShaderStage stage{GL_FRAGMENT_SHADER,
                      {"shared/pcf_prelude.h", "shared/pcf_kernel.h"},
                      "#define PCF_TEST 1\n#define OTHER 2",
                      {{"inline.frag", "void main() {}"}}};
    AssembledStage a = assembleStage(stage);
    ASSERT_EQ(a.strings.size(), 5u);
    ASSERT_EQ(a.names.size(), 5u);
    EXPECT_EQ(a.strings[0], "#version 450 core\n");
    EXPECT_EQ(a.strings[1], "#line 10001 1\n#define PCF_TEST 1\n#define OTHER 2\n");
    EXPECT_EQ(a.strings[2],
              "#line 20001 2\n" + std::string(embeddedShader("shared/pcf_prelude.h")));
    EXPECT_EQ(a.strings[3], "#line 30001 3\n" + std::string(embeddedShader("shared/pcf_kernel.h")));
    EXPECT_EQ(a.strings[4], "#line 40001 4\nvoid main() {}\n");
    EXPECT_EQ(a.names[2], "shaders/shared/pcf_prelude.h");
    EXPECT_EQ(a.names[3], "shaders/shared/pcf_kernel.h");
    EXPECT_EQ(a.names[4], "inline.frag");
}

TEST(RewriteShaderLog, NamesFilesInEveryDriversFormat) {
    std::vector<std::string> names = {"<version>", "<defines>", "shaders/shared/pcf_kernel.h",
                                      "scene.frag"};
    // Mesa, with the string number it keeps for token errors and the 0 it gives for the rest.
    EXPECT_EQ(rewriteShaderLog("2:20012(5): error: `x' undeclared\n", names),
              "shaders/shared/pcf_kernel.h:12: error: `x' undeclared");
    EXPECT_EQ(rewriteShaderLog("0:30007(5): error: `x' undeclared\n", names),
              "scene.frag:7: error: `x' undeclared");
    EXPECT_EQ(rewriteShaderLog("3(30007) : error C1008: undefined variable \"y\"", names),
              "scene.frag:7: error C1008: undefined variable \"y\"");
    EXPECT_EQ(rewriteShaderLog("ERROR: 2:20040: 'z' : undeclared identifier", names),
              "shaders/shared/pcf_kernel.h:40: ERROR: 'z' : undeclared identifier");
    // A driver that ignored the line offset but kept the string number.
    EXPECT_EQ(rewriteShaderLog("2:12(5): error: w", names),
              "shaders/shared/pcf_kernel.h:12: error: w");
    // Unknown string numbers and other lines stay as the driver wrote them.
    EXPECT_EQ(rewriteShaderLog("9:90001(1): error: a\nlinker error: b", names),
              "9:90001(1): error: a\nlinker error: b");
}

TEST_F(ShaderLoader, CompileErrorNamesTheFileAndLine) {
    // Line 3 of the second raw text is wrong; the first text and a file come before it, so
    // only the #line markers can make the driver say "broken.frag:3".
    std::string message = buildError(
        {{GL_VERTEX_SHADER, {}, "", {{"full.vert", FULL_VERT}}},
         {GL_FRAGMENT_SHADER,
          {"shared/pcf_prelude.h"},
          "#define UNUSED 1",
          {{"first.frag", "float helper() { return 1.0f; }\n"},
           {"broken.frag",
            "out vec4 outColor;\nvoid main() {\n    outColor = undefinedThing;\n}\n"}}}});
    EXPECT_NE(message.find("fragment shader"), std::string::npos) << message;
    EXPECT_NE(message.find("broken.frag:3: "), std::string::npos) << message;
    EXPECT_NE(message.find("undefinedThing"), std::string::npos) << message;
    EXPECT_EQ(message.find("<version>"), std::string::npos) << message;
    std::printf("the loader reports:\n%s\n", message.c_str());
}

TEST_F(ShaderLoader, ErrorInsideAnEmbeddedFileNamesThatFile) {
    // A define that breaks the first line of the prelude using `textureLod`: the error lands in
    // shaders/shared/pcf_prelude.h, on that line.
    std::string prelude(embeddedShader("shared/pcf_prelude.h"));
    int line = lineOf(prelude, "textureLod(map");
    ASSERT_GT(line, 0);
    std::string message = buildError({{GL_FRAGMENT_SHADER,
                                       {"shared/pcf_prelude.h"},
                                       "#define textureLod no_such_function",
                                       {{"main.frag", "void main() {}"}}}});
    std::string where = "shaders/shared/pcf_prelude.h:" + std::to_string(line) + ": ";
    EXPECT_NE(message.find(where), std::string::npos) << "want " << where << " in\n" << message;
}

TEST_F(ShaderLoader, LinkErrorSaysItDidNotLink) {
    // Compiles alone, but the fragment stage reads an input no vertex stage writes.
    std::string message = buildError(
        {{GL_VERTEX_SHADER, {}, "", {{"full.vert", FULL_VERT}}},
         {GL_FRAGMENT_SHADER,
          {},
          "",
          {{"needs_input.frag",
            "in vec3 vNeverWritten;\nout vec4 c;\nvoid main() { c = vec4(vNeverWritten, 1); }"}}}});
    EXPECT_NE(message.find("does not link"), std::string::npos) << message;
}

// The point of shaders/shared/: the shared kernel's files (pcfSharedFiles: the prelude, the
// kernel, the disk methods, the moment methods, the dispatch) are valid GLSL 4.50.
const char* PCF_FRAG = R"(
uniform sampler2D uMap;
uniform int uMethod;
uniform int uKernel;
uniform float uRef;
layout(location = 0) out float outVisibility;
void main() {
    // uv from the pixel with power-of-two arithmetic only, so the CPU can repeat it exactly.
    vec2 uv = gl_FragCoord.xy * (1.0f / 32.0f) - vec2(0.125f);
    PcfParams prm = PcfParams(uMethod, uKernel, 1.0f, pcfPixelRotation(ivec2(gl_FragCoord.xy)), 0, 1.0f, 0.0f,
                              0.0f, 0.0f, 0.0f, 1.0e-7f, vec2(40.0f, 5.0f), 3.0e-5f);
    outVisibility = pcfFilter(uMap, uv, uRef, prm);
}
)";

TEST_F(ShaderLoader, SharedPcfKernelCompilesAndLinks) {
    GlProgram program =
        buildProgram({{GL_VERTEX_SHADER, {}, "", {{"full.vert", FULL_VERT}}},
                      {GL_FRAGMENT_SHADER, pcfSharedFiles(), "", {{"pcf_test.frag", PCF_FRAG}}}});
    ASSERT_TRUE(program);
    GLint linked = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
    EXPECT_EQ(linked, GL_TRUE);
    EXPECT_GE(glGetUniformLocation(program.id(), "uMethod"), 0);
    EXPECT_GE(glGetUniformLocation(program.id(), "uPcfCompare"), 0);
}

// Beyond compiling: the kernel run by the driver gives the CPU kernel's numbers
// (docs/architecture.md's parity, in small: one 16 x 16 map, every method, a 32 x 32 grid of
// lookups reaching past the map's edges). The renderer's own parity test covers scenes and sizes.
TEST_F(ShaderLoader, SharedPcfKernelMatchesTheCpuKernel) {
    GlProgram program =
        buildProgram({{GL_VERTEX_SHADER, {}, "", {{"full.vert", FULL_VERT}}},
                      {GL_FRAGMENT_SHADER, pcfSharedFiles(), "", {{"pcf_test.frag", PCF_FRAG}}}});
    const int mapSize = 16;
    ShadowMap map(mapSize, mapSize);
    uint32_t state = 12345u;
    for (int j = 0; j < mapSize; ++j) {
        for (int i = 0; i < mapSize; ++i) {
            state = state * 1664525u + 1013904223u;
            map.setDepth(i, j, static_cast<float>(state >> 8) / 16777216.0f);
        }
    }
    GlTexture depth = createDepthTexture(map);
    GlSampler nearest = createNearestSampler();
    GlSampler compare = createCompareSampler();
    glBindTextureUnit(0, depth.id());
    glBindSampler(0, nearest.id());
    glBindTextureUnit(1, depth.id());
    glBindSampler(1, compare.id());
    const int size = 32;
    const float ref = 0.5f;
    OffscreenTarget target = createOffscreenTarget(size, size, {GL_R32F});
    GlVertexArray vao = createVertexArray();
    glUseProgram(program.id());
    glUniform1i(glGetUniformLocation(program.id(), "uMap"), 0);
    glUniform1i(glGetUniformLocation(program.id(), "uPcfCompare"), 1);
    glUniform1f(glGetUniformLocation(program.id(), "uRef"), ref);

    struct Case {
        int method;
        int kernel;
    };
    std::vector<Case> cases = {{PCF_NEAREST, 1}, {PCF_BOX2X2, 1}, {PCF_BILINEAR2X2, 1},
                               {PCF_HW2X2, 1},   {PCF_TENT, 3},   {PCF_TENT, 5},
                               {PCF_TENT, 7},    {PCF_POISSON, 1}};
    for (int n = 1; n <= 8; ++n) {
        for (int method : {PCF_NAIVE, PCF_GATHER, PCF_HW}) cases.push_back({method, n});
    }
    const std::string& renderer = sContext->renderer();
    bool software = renderer.find("llvmpipe") != std::string::npos ||
                    renderer.find("softpipe") != std::string::npos;
    for (const Case& c : cases) {
        glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
        glViewport(0, 0, size, size);
        glUniform1i(glGetUniformLocation(program.id(), "uMethod"), c.method);
        glUniform1i(glGetUniformLocation(program.id(), "uKernel"), c.kernel);
        glBindVertexArray(vao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        std::vector<float> gpu =
            readPixelsFloat(target.framebuffer.id(), GL_COLOR_ATTACHMENT0, size, size, 1);
        float worst = 0.0f;
        float lowest = 1.0f;
        float highest = 0.0f;
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                // The shader's uv, exactly: pixel centre / 32 - 1/8 (powers of two only).
                vec2 fragCoord(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
                vec2 uv = fragCoord * (1.0f / 32.0f) - vec2(0.125f);
                PcfParams prm{
                    c.method, c.kernel, 1.0f, pcfPixelRotation(ivec2(x, y)), PCF_WEIGHTS_BOX, 0.0f,
                    0.0f,     0.0f,     0.0f};
                float cpu = filterVisibility(map, uv, ref, prm);
                // readPixelsFloat is top-down: GL row y is readback row size - 1 - y.
                float v = gpu[static_cast<size_t>(size - 1 - y) * size + x];
                worst = std::max(worst, std::abs(v - cpu));
                lowest = std::min(lowest, v);
                highest = std::max(highest, v);
            }
        }
        // llvmpipe lerps hardware taps with exact weights (docs/methods.md, "Conventions"); real
        // GPUs round them to about 8 bits, which moves a result by up to 1/256.
        bool hwTaps = c.method == PCF_HW2X2 || c.method == PCF_HW || c.method == PCF_TENT;
        float tolerance = hwTaps && !software ? 1.0f / 256.0f + 1e-5f : 1e-5f;
        EXPECT_LE(worst, tolerance) << "method " << c.method << " kernel " << c.kernel;
        // Random depths around ref: a grid of one value would mean nothing was compared.
        EXPECT_LT(lowest, 0.5f) << "method " << c.method << " kernel " << c.kernel;
        EXPECT_GT(highest, 0.5f) << "method " << c.method << " kernel " << c.kernel;
    }
    glUseProgram(0);
    glBindVertexArray(0);
    for (GLuint unit : {0u, 1u}) {
        glBindTextureUnit(unit, 0);
        glBindSampler(unit, 0);
    }
}

}  // namespace
}  // namespace pcf
