// run_command.h: runs the pcfscope executable from a test and captures what it said.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace testutil {

struct CommandResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

inline std::string readAll(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

// A fresh, empty directory under the system temp dir, removed by the caller (or left for
// inspection when a test fails).
inline std::filesystem::path makeTempDir(const std::string& tag) {
    std::string pattern =
        (std::filesystem::temp_directory_path() / ("pcfscope-" + tag + "-XXXXXX")).string();
    char* made = mkdtemp(pattern.data());
    if (!made) throw std::runtime_error("mkdtemp failed");
    return made;
}

// Runs `PCFSCOPE_EXE args` through the shell; args are already shell-quoted by the caller.
inline CommandResult runPcfscope(const std::string& args, const std::string& env = "") {
    static int counter = 0;
    std::filesystem::path dir = std::filesystem::temp_directory_path();
    std::string tag = std::to_string(getpid()) + "-" + std::to_string(counter++);
    std::filesystem::path out = dir / ("pcfscope-out-" + tag);
    std::filesystem::path err = dir / ("pcfscope-err-" + tag);
    std::string cmd = env + " " + PCFSCOPE_EXE + std::string(" ") + args + " >" + out.string() +
                      " 2>" + err.string() + " </dev/null";
    int status = std::system(cmd.c_str());
    CommandResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readAll(out);
    r.err = readAll(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return r;
}

// Number of lines in s (a trailing newline does not start a new line).
inline int lineCount(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    if (!s.empty() && s.back() != '\n') ++n;
    return n;
}

}  // namespace testutil
