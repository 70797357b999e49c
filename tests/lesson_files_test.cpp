// Every lesson in lessons/, however many: it parses, teaches in 3 to 6 steps, all its
// placeholders fill, the files are numbered in teaching order, and the README lists every lesson
// and no other.
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
#include "lesson/lesson_pick.h"
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

// The README's table of lessons (under "## The lessons", rows "| N | title | M | title |") names
// exactly the lessons that exist: number N is lesson NN-*.toml, and every lesson is listed.
TEST(LessonFiles, TheReadmeListsEveryLessonAndNoOther) {
    std::ifstream readme(PCFSCOPE_SOURCE_DIR "/README.md");
    ASSERT_TRUE(readme);
    std::vector<std::string> files = lessonFiles();
    bool inSection = false;
    std::vector<int> listed;
    for (std::string line; std::getline(readme, line);) {
        if (line.starts_with("#")) inSection = line == "## The lessons";
        if (!inSection || !line.starts_with("|")) continue;
        // Cells 0 and 2 of a row hold lesson numbers (the header and the rule hold none).
        std::vector<std::string> cells;
        for (size_t at = 1, bar; (bar = line.find('|', at)) != std::string::npos; at = bar + 1) {
            std::string cell = line.substr(at, bar - at);
            cell.erase(0, cell.find_first_not_of(' '));
            cell.erase(cell.find_last_not_of(' ') + 1);
            cells.push_back(cell);
        }
        for (size_t c = 0; c < cells.size(); c += 2) {
            const std::string& cell = cells[c];
            if (cell.empty() || !std::all_of(cell.begin(), cell.end(), ::isdigit)) continue;
            int number = std::stoi(cell);
            char prefix[32];
            std::snprintf(prefix, sizeof prefix, "%02d-", number);
            bool found = std::any_of(files.begin(), files.end(), [&](const std::string& f) {
                return std::filesystem::path(f).stem().string().starts_with(prefix);
            });
            EXPECT_TRUE(found) << "README lists lesson " << number << ", no " << prefix
                               << "*.toml in lessons/";
            listed.push_back(number);
        }
    }
    for (const std::string& f : files) {
        int number = std::stoi(std::filesystem::path(f).stem().string().substr(0, 2));
        EXPECT_NE(std::find(listed.begin(), listed.end(), number), listed.end())
            << f << " is not in the README's table of lessons";
    }
}

// Short enough for one sitting: three to seven steps (an animation step makes the seventh).
TEST(LessonFiles, EveryLessonParsesWithThreeToSevenSteps) {
    for (const std::string& file : lessonFiles()) {
        SCOPED_TRACE(file);
        Lesson lesson;
        ASSERT_NO_THROW(lesson = parseLessonFile(file));
        EXPECT_FALSE(lesson.title.empty());
        EXPECT_GE(lesson.steps.size(), 3u);
        EXPECT_LE(lesson.steps.size(), 7u);
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
            Trace trace = traceLookup(map, vec2(0.4625f, 0.3875f), 0.5f, 0.5f - s.baseBias(),
                                      s.pcfParams(vec2(0.4625f, 0.3875f), map.width()), s);
            // A cascaded step's trace names its cascade and the blend band: the example map's
            // layer stands in for each cascade, the lookup in the first, in its band.
            if (s.cascades > 1) {
                PcfMapLayer layer = trace.map.layers.front();
                trace.map.layers.assign(static_cast<size_t>(s.cascades), layer);
                for (int k = 0; k < s.cascades; ++k) {
                    trace.map.layers[static_cast<size_t>(k)].viewDepth = vec2(k, k + 1);
                }
                trace.cascadeTexelsPerPixelMax = 1.0f;
                trace.cascadeBlend = {1, 0.5f, 0.5f, 0.5f * (trace.visibility + 0.5f)};
            }
            int taps = static_cast<int>(trace.taps.size());
            int fetches = static_cast<int>(trace.fetches.size());
            EXPECT_FALSE(checkPlaceholders(step.text, taps, fetches, step.compare.parts()));
            // The context the viewer gives: the step's point's light angle too.
            StepContext ctx = makeStepContext(step);
            std::optional<ScenePoint> point = stepPoint(lesson.scene, s);
            ASSERT_TRUE(point);
            ctx.lightAngleDeg = lightAngleDeg(lesson.scene, *point);
            // A step with `compare` reads its parts (rendered by the viewer and lesson check):
            // here each part stands in with this trace's visibility.
            ctx.partVisibility.assign(static_cast<size_t>(step.compare.parts()), trace.visibility);
            std::string text = fillText(step.text, trace, ctx);
            EXPECT_EQ(text.find("n/a"), std::string::npos) << text;
        }
    }
}

// A step that brings a map size the lesson's scene has not shown before says so in its words
// with {map_size} (8.7 went from 256 to 128 texels without a word: its acne stripes doubled in
// width unexplained). A chart step's map is the one its figures were measured with, and the
// status line under it says so.
TEST(LessonFiles, ANewMapSizeIsNamedInTheWords) {
    int checked = 0;
    for (const std::string& file : lessonFiles()) {
        Lesson lesson = parseLessonFile(file);
        std::vector<int> seen;
        for (size_t k = 0; k < lesson.steps.size(); ++k) {
            const LessonStep& step = lesson.steps[k];
            if (!step.chart.empty()) continue;
            int size = step.settings.mapSize;
            bool fresh = std::find(seen.begin(), seen.end(), size) == seen.end();
            if (fresh && !seen.empty()) {
                ++checked;
                EXPECT_NE(step.text.find("{map_size"), std::string::npos)
                    << file << " step " << k + 1 << " changes the map to " << size
                    << " texels without a word";
            }
            if (fresh) seen.push_back(size);
        }
    }
    EXPECT_GE(checked, 5);
}

}  // namespace
}  // namespace pcf
