// Every lesson in lessons/, however many: it parses, teaches in 3 to 6 steps, all its
// placeholders fill, the files are numbered in teaching order, and the README lists no lesson
// that is not there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "kernel/shadow_map.h"
#include "kernel/trace.h"
#include "lesson/lesson.h"
#include "lesson/lesson_text.h"

namespace pcf {
namespace {

std::vector<std::string> lessonFiles() {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(PCFSCOPE_SOURCE_DIR "/lessons")) {
        if (entry.path().extension() == ".toml") files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// 01-..., 02-...: the names sort in teaching order, numbered from 01 with no gap and no
// number twice, however many lessons there are.
TEST(LessonFiles, NumberedContiguouslyFromOneInTeachingOrder) {
    std::vector<std::string> files = lessonFiles();
    ASSERT_FALSE(files.empty());
    for (size_t i = 0; i < files.size(); ++i) {
        std::string stem = std::filesystem::path(files[i]).stem().string();
        char prefix[32];
        std::snprintf(prefix, sizeof prefix, "%02d-", static_cast<int>(i + 1));
        EXPECT_EQ(stem.substr(0, 3), prefix) << stem;
        EXPECT_GT(stem.size(), 3u) << stem << ": a number and no name";
    }
}

// The README's numbered list of lessons (under "The viewer and the lessons") names lessons that
// exist: item N is lesson NN-*.toml.
TEST(LessonFiles, EveryLessonTheReadmeListsExists) {
    std::ifstream readme(PCFSCOPE_SOURCE_DIR "/README.md");
    ASSERT_TRUE(readme);
    std::vector<std::string> files = lessonFiles();
    bool inSection = false;
    int listed = 0;
    for (std::string line; std::getline(readme, line);) {
        if (line.starts_with("### ")) inSection = line == "### The viewer and the lessons";
        if (!inSection || line.empty() || !std::isdigit(static_cast<unsigned char>(line[0]))) {
            continue;
        }
        size_t dot = line.find(". ");
        if (dot == std::string::npos || dot > 3) continue;
        int number = std::stoi(line.substr(0, dot));
        char prefix[32];
        std::snprintf(prefix, sizeof prefix, "%02d-", number);
        bool found = std::any_of(files.begin(), files.end(), [&](const std::string& f) {
            return std::filesystem::path(f).stem().string().starts_with(prefix);
        });
        EXPECT_TRUE(found) << "README lists lesson " << number << " (" << line << "), no " << prefix
                           << "*.toml in lessons/";
        ++listed;
    }
    EXPECT_GT(listed, 0)
        << "no numbered lesson list found under \"### The viewer and the lessons\"";
}

TEST(LessonFiles, EveryLessonParsesWithThreeToSixSteps) {
    for (const std::string& file : lessonFiles()) {
        SCOPED_TRACE(file);
        Lesson lesson;
        ASSERT_NO_THROW(lesson = parseLessonFile(file));
        EXPECT_FALSE(lesson.title.empty());
        EXPECT_GE(lesson.steps.size(), 3u);
        EXPECT_LE(lesson.steps.size(), 6u);
        EXPECT_FALSE(lesson.scene.objects.empty());
        for (const LessonStep& step : lesson.steps) {
            EXPECT_FALSE(step.title.empty());
            EXPECT_GT(step.line, 0);
            // The texels should be visible where the lessons show them.
            EXPECT_LE(step.settings.mapSize, 1024) << step.title;
        }
    }
}

TEST(LessonFiles, EveryPlaceholderIsKnownAndFillsFromATrace) {
    ShadowMap map = exampleShadowMap();
    for (const std::string& file : lessonFiles()) {
        Lesson lesson = parseLessonFile(file);
        for (const LessonStep& step : lesson.steps) {
            SCOPED_TRACE(file + ": " + step.title);
            const LessonSettings& s = step.settings;
            Trace trace =
                traceLookup(map, vec2(0.4625f, 0.3875f), 0.5f, 0.5f - s.depthBias(),
                            s.pcfParams(vec2(0.4625f, 0.3875f), map.width()), s.biasParams());
            int taps = static_cast<int>(trace.taps.size());
            int fetches = static_cast<int>(trace.fetches.size());
            EXPECT_FALSE(checkPlaceholders(step.text, taps, fetches));
            std::string text = fillText(step.text, trace, makeStepContext(step));
            EXPECT_EQ(text.find("n/a"), std::string::npos) << text;
        }
    }
}

}  // namespace
}  // namespace pcf
