// A lesson named by number on the command line (`pcfscope export 13`) is the file numbered 13,
// not the 13th file of the directory (src/app/session.h: findLesson, resolveLesson).
#include <gtest/gtest.h>

#include <filesystem>

#include "app/session.h"
#include "run_command.h"

namespace pcf {
namespace {

// A lesson directory with a gap: no 02, so the file numbered 13 is the 12th.
const std::vector<std::string> GAPPED = {"l/01-hard-shadows.toml",
                                         "l/03-bilinear-lerp.toml",
                                         "l/04-a.toml",
                                         "l/05-b.toml",
                                         "l/06-c.toml",
                                         "l/07-d.toml",
                                         "l/08-e.toml",
                                         "l/09-f.toml",
                                         "l/10-g.toml",
                                         "l/11-h.toml",
                                         "l/12-i.toml",
                                         "l/13-shimmer.toml",
                                         "l/14-trade-off.toml",
                                         "l/15-last.toml"};

TEST(LessonLookup, ANumberNamesTheFileNumberedSoNotTheNthFile) {
    EXPECT_EQ(findLesson(GAPPED, "13"), "l/13-shimmer.toml");
    EXPECT_EQ(findLesson(GAPPED, "013"), "l/13-shimmer.toml");
    EXPECT_EQ(findLesson(GAPPED, "3"), "l/03-bilinear-lerp.toml");
    EXPECT_EQ(findLesson(GAPPED, "03"), "l/03-bilinear-lerp.toml");
    EXPECT_EQ(findLesson(GAPPED, "15"), "l/15-last.toml");
    EXPECT_FALSE(findLesson(GAPPED, "2"));   // the gap: no file numbered 2
    EXPECT_FALSE(findLesson(GAPPED, "16"));  // the 14 files end at 15
    EXPECT_EQ(findLesson(GAPPED, "14-trade-off"), "l/14-trade-off.toml");
    EXPECT_FALSE(findLesson(GAPPED, "trade-off"));
    EXPECT_FALSE(findLesson(GAPPED, ""));
}

TEST(LessonLookup, TheBuiltInLessonsResolveByTheirOwnNumbers) {
    for (const std::string& path : builtInLessons()) {
        std::string stem = std::filesystem::path(path).stem().string();
        int number = std::stoi(stem.substr(0, stem.find('-')));
        EXPECT_EQ(resolveLesson(std::to_string(number)), path) << stem;
        EXPECT_EQ(resolveLesson(stem), path);
    }
    auto r = testutil::runPcfscope("export 99 -o /nonexistent-dir-pcfscope");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("unknown lesson '99'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace pcf
