// Font discovery: fontconfig first, then the known paths, then one line naming every place.
#include "draw/font.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

namespace pcf {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

TEST(FontDiscovery, FindsDejaVuSansThroughFontconfig) {
    const FontFile& f = findFontFile(FontFace::Sans);
    EXPECT_EQ(f.family, "DejaVu Sans");
    EXPECT_TRUE(endsWith(f.path, "/DejaVuSans.ttf")) << f.path;
    EXPECT_TRUE(f.fromFontconfig);
    EXPECT_EQ(f.index, 0);
}

TEST(FontDiscovery, FindsDejaVuSansMonoThroughFontconfig) {
    const FontFile& f = findFontFile(FontFace::Mono);
    EXPECT_EQ(f.family, "DejaVu Sans Mono");
    EXPECT_TRUE(endsWith(f.path, "/DejaVuSansMono.ttf")) << f.path;
    EXPECT_TRUE(f.fromFontconfig);
}

TEST(FontDiscovery, CachesTheLookup) {
    EXPECT_EQ(&findFontFile(FontFace::Sans), &findFontFile(FontFace::Sans));
    EXPECT_NE(findFontFile(FontFace::Sans).path, findFontFile(FontFace::Mono).path);
}

TEST(FontDiscovery, FamilyNamesAndFallbackPaths) {
    EXPECT_EQ(fontFamilyName(FontFace::Sans), "DejaVu Sans");
    EXPECT_EQ(fontFamilyName(FontFace::Mono), "DejaVu Sans Mono");
    EXPECT_EQ(fallbackFontPaths(FontFace::Sans),
              std::vector<std::string>{"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"});
    EXPECT_EQ(fallbackFontPaths(FontFace::Mono),
              std::vector<std::string>{"/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf"});
}

// fontconfig always returns its best match; a different family must not count as found.
TEST(FontDiscovery, UnknownFamilyFallsBackToTheKnownPath) {
    FontFile f = findFontFile(
        "No Such Family pcfscope",
        {"/nonexistent/pcfscope/A.ttf", "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf"});
    EXPECT_EQ(f.path, "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf");
    EXPECT_EQ(f.family, "DejaVu Sans Mono");
    EXPECT_FALSE(f.fromFontconfig);
}

TEST(FontDiscovery, FamilyMatchIgnoresCase) {
    FontFile f = findFontFile("dejavu sans", {});
    EXPECT_TRUE(f.fromFontconfig);
    EXPECT_EQ(f.family, "DejaVu Sans");
}

TEST(FontDiscovery, NothingUsableThrowsOneLineNamingEveryPlaceSearched) {
    // A file that exists but is no font is not usable either.
    std::string junk = ::testing::TempDir() + "pcfscope_not_a_font.ttf";
    {
        std::ofstream out(junk);
        out << "not a font\n";
    }
    try {
        findFontFile("No Such Family pcfscope", {"/nonexistent/pcfscope/A.ttf", junk});
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "no font found: searched fontconfig 'No Such Family pcfscope', "
                  "/nonexistent/pcfscope/A.ttf, " +
                      junk);
    }
    std::remove(junk.c_str());
}

TEST(FontDiscovery, MessageWithoutFallbacksNamesFontconfigAlone) {
    EXPECT_THROW(
        {
            try {
                findFontFile("No Such Family pcfscope", {});
            } catch (const std::runtime_error& e) {
                EXPECT_EQ(std::string(e.what()),
                          "no font found: searched fontconfig 'No Such Family pcfscope'");
                throw;
            }
        },
        std::runtime_error);
}

}  // namespace
}  // namespace pcf
