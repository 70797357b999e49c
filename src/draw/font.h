// font.h: which font files the overlay draws with, found through fontconfig.
//
// Two faces cover the inspector: DejaVu Sans for prose and DejaVu Sans Mono for numbers and
// formulas (digits line up in columns, which matters when a table of weights is read).
// Every machine that runs pcfscope draws with the same files, so a frame exported on CI is the
// frame a teacher sees: fontconfig may not substitute another family (see findFontFile).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pcf {

enum class FontFace { Sans, Mono };

// "DejaVu Sans" / "DejaVu Sans Mono": the family fontconfig is asked for.
std::string_view fontFamilyName(FontFace face);
// The paths tried when fontconfig finds nothing usable (Debian's and Ubuntu's layout).
std::vector<std::string> fallbackFontPaths(FontFace face);

// A font file FreeType can open, and where it came from.
struct FontFile {
    std::string path;    // absolute path of a .ttf / .otf
    int index = 0;       // face index inside the file (collections hold several)
    std::string family;  // family name as the file reports it
    bool fromFontconfig = false;
};

// The file for `face`, looked up once per process and cached (thread-safe).
// Throws std::runtime_error, as findFontFile(family, paths) below.
const FontFile& findFontFile(FontFace face);

// Asks fontconfig (FcFontMatch) for `family`; the match counts only when one of its family names
// equals `family` (case-insensitive; FcFontMatch always returns *some* font, and a substitute
// would change every exported frame) and FreeType opens it as a scalable face. Otherwise tries
// each of `fallbackPaths`. Throws std::runtime_error with one line naming every place searched:
//   "no font found: searched fontconfig 'DejaVu Sans', /usr/share/fonts/truetype/dejavu/..."
FontFile findFontFile(std::string_view family, const std::vector<std::string>& fallbackPaths);

}  // namespace pcf
