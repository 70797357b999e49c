#include "lesson/lesson_catalogue.h"

#include <algorithm>
#include <filesystem>

#include "base/usage_error.h"

namespace pcf {

std::string lessonDirectory() { return PCFSCOPE_LESSON_DIR; }

std::vector<std::string> builtInLessons() {
    std::vector<std::string> paths;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(PCFSCOPE_LESSON_DIR, ec)) {
        if (entry.path().extension() == ".toml") paths.push_back(entry.path().string());
    }
    std::sort(paths.begin(), paths.end());
    return paths;
}

std::optional<std::string> findLesson(const std::vector<std::string>& lessons,
                                      const std::string& nameOrNumber) {
    // A number names the file numbered so (13 -> 13-*.toml, also "013"), never the 13th file:
    // a lesson directory with a gap (no 12) would shift every lesson after it.
    bool number = !nameOrNumber.empty() && nameOrNumber.size() <= 6 &&
                  std::all_of(nameOrNumber.begin(), nameOrNumber.end(),
                              [](char c) { return c >= '0' && c <= '9'; });
    for (const std::string& path : lessons) {
        std::string stem = std::filesystem::path(path).stem().string();
        if (stem == nameOrNumber) return path;
        if (!number) continue;
        size_t digits = 0;
        while (digits < stem.size() && digits < 6 && stem[digits] >= '0' && stem[digits] <= '9') {
            ++digits;
        }
        if (digits > 0 && std::stoi(stem.substr(0, digits)) == std::stoi(nameOrNumber)) {
            return path;
        }
    }
    return std::nullopt;
}

std::string resolveLesson(const std::string& nameOrPath) {
    if (nameOrPath.find('/') != std::string::npos || nameOrPath.ends_with(".toml")) {
        return nameOrPath;  // a path: parseLessonFile says what is wrong with it
    }
    std::vector<std::string> lessons = builtInLessons();
    if (std::optional<std::string> found = findLesson(lessons, nameOrPath)) return *found;
    std::string names;
    for (const std::string& path : lessons) {
        names += (names.empty() ? "" : ", ") + std::filesystem::path(path).stem().string();
    }
    throw UsageError("unknown lesson '" + nameOrPath + "' (a .toml path, a lesson's number, " +
                     "or one of: " + names + ")");
}

}  // namespace pcf
