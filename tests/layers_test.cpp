// layers_test.cpp: two rules of docs/architecture.md that the compiler cannot see, held on the
// sources: OpenGL is called only from src/render/ and src/draw/ (the layers above call their
// functions: render/frame_ops.h), and no code outside the method table (src/kernel/methods.*)
// compares method ids; a question about a method is a column of MethodInfo. And measuring draws
// nothing: no source of src/measure/ includes charts/ or draw/ (nor overlay/ or app/ above them).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path SRC = fs::path(PCFSCOPE_SOURCE_DIR) / "src";

// Each line of every C++ source under src/ with its comments taken out, as "path:line: text".
struct SourceLine {
    std::string where;
    std::string code;
};
std::vector<SourceLine> sourceLines(const std::vector<std::string>& skipPrefixes) {
    std::vector<SourceLine> out;
    for (const auto& e : fs::recursive_directory_iterator(SRC)) {
        std::string ext = e.path().extension().string();
        if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
        std::string rel = fs::relative(e.path(), SRC).generic_string();
        bool skip = false;
        for (const std::string& p : skipPrefixes) skip = skip || rel.rfind(p, 0) == 0;
        if (skip) continue;
        std::ifstream in(e.path());
        std::string line;
        for (int n = 1; std::getline(in, line); ++n) {
            size_t comment = line.find("//");
            if (comment != std::string::npos) line.erase(comment);
            out.push_back({rel + ":" + std::to_string(n), line});
        }
    }
    return out;
}

TEST(Layers, OpenGlIsCalledOnlyFromRenderAndDraw) {
    // glFoo( but not glfwFoo( (the window library) nor glm::, nor bench's own glRowLookups and
    // glRowDzDuv (measure/bench.cpp: a read-back target's rows in GL order, no GL call).
    const std::regex call(R"((^|[^A-Za-z0-9_:.])gl(?!Row)[A-Z][A-Za-z0-9]*\s*\()");
    int lines = 0;
    for (const SourceLine& l : sourceLines({"render/", "draw/"})) {
        ++lines;
        EXPECT_FALSE(std::regex_search(l.code, call)) << l.where << ": " << l.code;
    }
    EXPECT_GT(lines, 10000);  // the scan saw the sources
}

// The method ids as the shared kernel declares them (shaders/shared/pcf_kernel.h: "PCF_CONST int
// PCF_NEAREST = 0;" .. up to PCF_METHOD_COUNT), so a method added there is covered too.
std::vector<std::string> methodIds() {
    std::ifstream in(fs::path(PCFSCOPE_SOURCE_DIR) / "shaders/shared/pcf_kernel.h");
    const std::regex declared(R"(^PCF_CONST int (PCF_[A-Z0-9_]+) = \d+;)");
    std::vector<std::string> ids;
    std::string line;
    bool inIds = false;
    while (std::getline(in, line)) {
        std::smatch m;
        if (line.rfind("// Method ids", 0) == 0) inIds = true;
        if (!inIds || !std::regex_search(line, m, declared)) continue;
        if (m[1] == "PCF_METHOD_COUNT") break;
        ids.push_back(m[1]);
    }
    return ids;
}

TEST(Layers, NoMethodIdIsComparedOutsideTheMethodTable) {
    std::vector<std::string> ids = methodIds();
    ASSERT_GE(ids.size(), 10u);
    std::string pcfId = "(";
    for (const std::string& i : ids) pcfId += (pcfId.size() > 1 ? "|" : "") + i + "\\b";
    pcfId += ")";
    std::string id = "(Method::[A-Z][A-Za-z0-9]*|" + pcfId + ")";
    // Compared with == or !=, or an id named by a case label; the exhaustive switches over
    // Method (case Method::X) are the compiler's to check and stay allowed.
    const std::regex compared("[=!]=\\s*" + id + "|" + id + "\\s*[=!]=|case\\s+" + pcfId);
    int lines = 0;
    for (const SourceLine& l : sourceLines({"kernel/methods."})) {
        ++lines;
        EXPECT_FALSE(std::regex_search(l.code, compared)) << l.where << ": " << l.code;
    }
    EXPECT_GT(lines, 10000);
}

TEST(Layers, MeasureIncludesNothingThatDraws) {
    // An #include naming a folder above measure/ in the layers (docs/architecture.md).
    const std::regex upward(R"(^\s*#\s*include\s*[<"](charts|draw|overlay|app)/)");
    int files = 0;
    for (const auto& e : fs::directory_iterator(SRC / "measure")) {
        std::string ext = e.path().extension().string();
        if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
        ++files;
        std::ifstream in(e.path());
        std::string line;
        for (int n = 1; std::getline(in, line); ++n) {
            EXPECT_FALSE(std::regex_search(line, upward))
                << "measure/" << e.path().filename().string() << ":" << n << ": " << line;
        }
    }
    EXPECT_GT(files, 40);  // the scan saw the folder
}

}  // namespace
