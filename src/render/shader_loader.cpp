#include "render/shader_loader.h"

#include <algorithm>
#include <regex>
#include <stdexcept>

namespace pcf {

namespace {

// Index of the first file string: 0 is #version, 1 the defines.
constexpr size_t FIRST_FILE_STRING = 2;

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

std::string joinNames(const std::vector<std::string>& names) {
    std::string out;
    for (size_t k = FIRST_FILE_STRING; k < names.size(); ++k) {
        out += (out.empty() ? "" : ", ") + names[k];
    }
    return out;
}

// Lines of string `index` count from index * SHADER_LINE_STRIDE + 1 (shader_loader.h says why).
std::string lineMarker(size_t index) {
    return "#line " + std::to_string(index * SHADER_LINE_STRIDE + 1) + " " + std::to_string(index) +
           "\n";
}

GlShader compileStage(const ShaderStage& stage) {
    AssembledStage assembled = assembleStage(stage);
    std::vector<const GLchar*> pointers;
    std::vector<GLint> lengths;
    for (const std::string& s : assembled.strings) {
        pointers.push_back(s.data());
        lengths.push_back(static_cast<GLint>(s.size()));
    }
    GlShader shader(glCreateShader(stage.type));
    if (!shader) {
        throw std::runtime_error("GL: cannot create a " + shaderStageName(stage.type) + " shader");
    }
    glShaderSource(shader.id(), static_cast<GLsizei>(pointers.size()), pointers.data(),
                   lengths.data());
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        throw std::runtime_error("GL: " + shaderStageName(stage.type) + " shader (" +
                                 joinNames(assembled.names) + ") does not compile:\n" +
                                 rewriteShaderLog(shaderLog(shader.id()), assembled.names));
    }
    return shader;
}

}  // namespace

std::string_view embeddedShader(std::string_view path) {
    for (const EmbeddedShader& s : embeddedShaders()) {
        if (s.path == path) return s.text;
    }
    std::string known;
    for (const EmbeddedShader& s : embeddedShaders()) {
        known += (known.empty() ? "" : ", ") + std::string(s.path);
    }
    throw std::runtime_error("no shader shaders/" + std::string(path) +
                             " was embedded at build time (embedded: " + known + ")");
}

AssembledStage assembleStage(const ShaderStage& stage) {
    AssembledStage out;
    // Drivers concatenate the strings before preprocessing, so each must end its last line,
    // or the next #line would be glued to it.
    auto add = [&](std::string name, std::string_view text) {
        if (std::count(text.begin(), text.end(), '\n') >= SHADER_LINE_STRIDE - 1) {
            throw std::runtime_error(name + ": too long for the shader loader (" +
                                     std::to_string(SHADER_LINE_STRIDE - 1) + " lines at most)");
        }
        std::string s = out.strings.empty() ? std::string() : lineMarker(out.strings.size());
        s += text;
        if (!s.ends_with('\n')) s += '\n';
        out.strings.push_back(std::move(s));
        out.names.push_back(std::move(name));
    };
    add("<version>", "#version 450 core");
    add("<defines>", stage.defines);
    for (const std::string& file : stage.files) add("shaders/" + file, embeddedShader(file));
    for (const ShaderText& t : stage.texts) add(t.name, t.text);
    return out;
}

std::string rewriteShaderLog(std::string_view log, const std::vector<std::string>& names) {
    // Mesa: "2:12(5): error: ..."; NVIDIA: "2(12) : error C1008: ..."; AMD: "ERROR: 2:12: ...".
    static const std::regex MESA(R"(^(\d{1,9}):(\d{1,9})\(\d+\): (.*)$)");
    static const std::regex NVIDIA(R"(^(\d{1,9})\((\d{1,9})\) : (.*)$)");
    static const std::regex AMD(R"(^(ERROR|WARNING): (\d{1,9}):(\d{1,9}): (.*)$)");
    // "NAME:LINE" for a reported string number and line, or "" when neither names a string.
    auto place = [&](const std::string& sourceText, const std::string& lineText) {
        size_t source = std::stoul(sourceText);
        size_t line = std::stoul(lineText);
        if (line > static_cast<size_t>(SHADER_LINE_STRIDE)) {
            source = line / SHADER_LINE_STRIDE;
            line %= SHADER_LINE_STRIDE;
        }
        if (source >= names.size()) return std::string();
        return names[source] + ":" + std::to_string(line);
    };
    std::string out;
    size_t start = 0;
    while (start < log.size()) {
        size_t end = log.find('\n', start);
        if (end == std::string_view::npos) end = log.size();
        std::string line(log.substr(start, end - start));
        start = end + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::smatch m;
        if (std::regex_match(line, m, MESA) || std::regex_match(line, m, NVIDIA)) {
            std::string where = place(m[1].str(), m[2].str());
            if (!where.empty()) line = where + ": " + m[3].str();
        } else if (std::regex_match(line, m, AMD)) {
            std::string where = place(m[2].str(), m[3].str());
            if (!where.empty()) line = where + ": " + m[1].str() + ": " + m[4].str();
        }
        if (line.empty()) continue;
        out += line + "\n";
    }
    if (!out.empty()) out.pop_back();
    return out;
}

std::string shaderStageName(GLenum type) {
    switch (type) {
        case GL_VERTEX_SHADER:
            return "vertex";
        case GL_FRAGMENT_SHADER:
            return "fragment";
        case GL_GEOMETRY_SHADER:
            return "geometry";
        case GL_TESS_CONTROL_SHADER:
            return "tessellation control";
        case GL_TESS_EVALUATION_SHADER:
            return "tessellation evaluation";
        case GL_COMPUTE_SHADER:
            return "compute";
        default:
            return "unknown";
    }
}

GlProgram buildProgram(const std::vector<ShaderStage>& stages) {
    if (stages.empty()) throw std::invalid_argument("buildProgram: no stages");
    std::vector<GlShader> shaders;
    for (const ShaderStage& stage : stages) shaders.push_back(compileStage(stage));
    GlProgram program(glCreateProgram());
    for (const GlShader& s : shaders) glAttachShader(program.id(), s.id());
    glLinkProgram(program.id());
    // The program keeps the compiled code; the shaders can go with this scope.
    for (const GlShader& s : shaders) glDetachShader(program.id(), s.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::string what;
        for (const ShaderStage& stage : stages) {
            AssembledStage a = assembleStage(stage);
            what += (what.empty() ? "" : "; ") + shaderStageName(stage.type) + ": " +
                    joinNames(a.names);
        }
        throw std::runtime_error("GL: program (" + what + ") does not link:\n" +
                                 programLog(program.id()));
    }
    return program;
}

}  // namespace pcf
