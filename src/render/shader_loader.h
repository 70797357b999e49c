// shader_loader.h: the GLSL under shaders/, embedded in the binary at build time
// (cmake/embed_shaders.cmake), and the program builder that assembles it.
//
// One stage is handed to glShaderSource as separate strings, in this order (docs/architecture.md,
// "One kernel for the CPU and the GPU"):
//   0: "#version 450 core"
//   1: "#line 10001 1" and the stage's defines
//   K = 2, 3...: "#line K*10000+1 K" and each file, then each raw text
// The #line markers make the driver number the lines of string K from K*10000 + 1 and, where it
// keeps it, report K as the source-string number. Both are needed: Mesa (llvmpipe, our CI) drops
// the source number to 0 for any error located on a grammar rule rather than a token
// (YYLLOC_DEFAULT in glsl_parser_extras.h sets source = 0), which is most of them, e.g.
// "0:30003(6): error: `x' undeclared" for line 3 of string 3. The line alone still says which
// string, so buildProgram rewrites it into "shaders/FILE:3: error: ...".
#pragma once

#include <epoxy/gl.h>

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "render/gl_objects.h"

namespace pcf {

// One file of shaders/, path relative to it ("shared/pcf_kernel.h").
struct EmbeddedShader {
    std::string_view path;
    std::string_view text;
};

// Every embedded file, sorted by path. Defined in the generated embedded_shaders.cpp.
std::span<const EmbeddedShader> embeddedShaders();

// The text of shaders/<path> as it was at build time. Throws std::runtime_error naming the
// path when no such file was embedded.
std::string_view embeddedShader(std::string_view path);

// Source text that is not a file of shaders/ (tests, generated code); `name` is what error
// messages call it.
struct ShaderText {
    std::string name;
    std::string text;
};

struct ShaderStage {
    GLenum type;                     // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER...
    std::vector<std::string> files;  // embedded files, relative to shaders/, in order
    std::string defines;             // "#define NAME VALUE" lines, used as they are
    std::vector<ShaderText> texts;   // raw sources, after the files
};

// The strings glShaderSource gets for `stage` (see the top of this file) and, for each string
// index, the name errors should use ("shaders/shared/pcf_kernel.h", "<defines>", ...). Throws
// std::runtime_error for a file of SHADER_LINE_STRIDE lines or more.
struct AssembledStage {
    std::vector<std::string> strings;
    std::vector<std::string> names;
};
AssembledStage assembleStage(const ShaderStage& stage);

// Lines of string K start at K * SHADER_LINE_STRIDE + 1; a file may have fewer lines than that.
inline constexpr int SHADER_LINE_STRIDE = 10000;

// Rewrites the driver's references to source strings into file names, line by line:
//   Mesa   "2:20012(5): error: x"      -> "NAME:12: error: x"
//   NVIDIA "2(20012) : error C1008: x" -> "NAME:12: error C1008: x"
//   AMD    "ERROR: 2:20012: x"         -> "NAME:12: ERROR: x"
// where NAME = names[2], the string found from the line number (the reported string number is
// only used for lines below SHADER_LINE_STRIDE). Lines it does not recognise stay as they are.
std::string rewriteShaderLog(std::string_view log, const std::vector<std::string>& names);

// "vertex", "fragment", ...
std::string shaderStageName(GLenum type);

// Compiles every stage and links them. Throws std::runtime_error when a stage does not compile
// or the program does not link; the message's first line says which, the rest is the driver's
// log with file names and lines (rewriteShaderLog).
GlProgram buildProgram(const std::vector<ShaderStage>& stages);

}  // namespace pcf
