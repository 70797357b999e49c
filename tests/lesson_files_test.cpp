// Every lesson in lessons/: it parses, teaches in 3 to 6 steps, and all its placeholders fill.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
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

// Lessons 01-11 are the course; later numbers (15: the texture unit) may leave gaps for lessons
// still being written. The two-digit prefixes sort in teaching order and never repeat.
TEST(LessonFiles, NumberedInTeachingOrder) {
    std::vector<std::string> files = lessonFiles();
    ASSERT_GE(files.size(), 11u);
    int previous = 0;
    for (size_t i = 0; i < files.size(); ++i) {
        std::string stem = std::filesystem::path(files[i]).stem().string();
        ASSERT_GE(stem.size(), 4u) << stem;
        ASSERT_TRUE(std::isdigit(stem[0]) && std::isdigit(stem[1]) && stem[2] == '-') << stem;
        int number = std::stoi(stem.substr(0, 2));
        EXPECT_GT(number, previous) << stem;
        if (i < 11) EXPECT_EQ(number, static_cast<int>(i + 1)) << stem;
        previous = number;
    }
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
            Trace trace = traceLookup(map, vec2(0.4625f, 0.3875f), 0.5f, 0.5f - s.depthBias(),
                                      s.pcfParams(s.pixel, LESSON_FRAME_SIZE));
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
