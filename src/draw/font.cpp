#include "draw/font.h"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>

#include <array>
#include <cctype>
#include <mutex>
#include <optional>
#include <stdexcept>
#include FT_FREETYPE_H

namespace pcf {

namespace {

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t k = 0; k < a.size(); ++k) {
        if (std::tolower(static_cast<unsigned char>(a[k])) !=
            std::tolower(static_cast<unsigned char>(b[k]))) {
            return false;
        }
    }
    return true;
}

// "Usable" means FreeType opens it as a scalable face: the atlas rasterises at any pixel size,
// which a bitmap-only font (or a truncated file) cannot do. Returns the face's family name.
std::optional<std::string> openableScalableFace(const std::string& path, int index) {
    FT_Library library = nullptr;
    if (FT_Init_FreeType(&library) != 0) return std::nullopt;
    std::optional<std::string> family;
    FT_Face face = nullptr;
    if (FT_New_Face(library, path.c_str(), index, &face) == 0) {
        if (FT_IS_SCALABLE(face)) family = face->family_name ? face->family_name : "";
        FT_Done_Face(face);
    }
    FT_Done_FreeType(library);
    return family;
}

std::optional<FontFile> matchWithFontconfig(std::string_view family) {
    // FcConfigGetCurrent initialises fontconfig on first use; the config is process-wide.
    FcConfig* config = FcConfigGetCurrent();
    if (config == nullptr) return std::nullopt;
    FcPattern* pattern = FcPatternCreate();
    std::string familyString(family);
    FcPatternAddString(pattern, FC_FAMILY, reinterpret_cast<const FcChar8*>(familyString.c_str()));
    FcPatternAddBool(pattern, FC_SCALABLE, FcTrue);
    FcConfigSubstitute(config, pattern, FcMatchPattern);
    FcDefaultSubstitute(pattern);
    FcResult result = FcResultNoMatch;
    FcPattern* match = FcFontMatch(config, pattern, &result);
    FcPatternDestroy(pattern);
    if (match == nullptr) return std::nullopt;

    std::optional<FontFile> found;
    bool familyMatches = false;
    FcChar8* name = nullptr;
    for (int k = 0; FcPatternGetString(match, FC_FAMILY, k, &name) == FcResultMatch; ++k) {
        if (equalsIgnoreCase(reinterpret_cast<const char*>(name), family)) familyMatches = true;
    }
    FcChar8* file = nullptr;
    int index = 0;
    if (familyMatches && FcPatternGetString(match, FC_FILE, 0, &file) == FcResultMatch) {
        FcPatternGetInteger(match, FC_INDEX, 0, &index);
        std::string path = reinterpret_cast<const char*>(file);
        if (std::optional<std::string> faceFamily = openableScalableFace(path, index)) {
            found = FontFile{path, index, *faceFamily, true};
        }
    }
    FcPatternDestroy(match);
    return found;
}

}  // namespace

std::string_view fontFamilyName(FontFace face) {
    return face == FontFace::Mono ? "DejaVu Sans Mono" : "DejaVu Sans";
}

std::vector<std::string> fallbackFontPaths(FontFace face) {
    return {face == FontFace::Mono ? "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf"
                                   : "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"};
}

FontFile findFontFile(std::string_view family, const std::vector<std::string>& fallbackPaths) {
    if (std::optional<FontFile> f = matchWithFontconfig(family)) return *f;
    for (const std::string& path : fallbackPaths) {
        if (std::optional<std::string> faceFamily = openableScalableFace(path, 0)) {
            return FontFile{path, 0, *faceFamily, false};
        }
    }
    std::string searched = "fontconfig '" + std::string(family) + "'";
    for (const std::string& path : fallbackPaths) searched += ", " + path;
    throw std::runtime_error("no font found: searched " + searched);
}

const FontFile& findFontFile(FontFace face) {
    static std::mutex mutex;
    static std::array<std::optional<FontFile>, 2> cache;
    std::lock_guard lock(mutex);
    std::optional<FontFile>& slot = cache[face == FontFace::Mono ? 1 : 0];
    if (!slot) slot = findFontFile(fontFamilyName(face), fallbackFontPaths(face));
    return *slot;
}

}  // namespace pcf
