// exr_header.h: an OpenEXR file whose header lies about its size, as a fuzzer or a hostile file
// would make it: the header of a real 16 x 16 depth map with dataWindow and displayWindow set to
// side x side, then an empty line-offset table and no pixels. A few KB on disk.
#pragma once

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "run_command.h"

namespace testutil {

// Rewrites `file` (an EXR written by pcf::writeDepthImage) so that its header claims side x side
// texels. False if the file is not an EXR header this understands.
inline bool makeExrClaimSize(const std::string& file, int32_t side) {
    std::string in = readAll(file);
    if (in.size() < 8) return false;
    std::string out = in.substr(0, 8);  // magic number and version
    size_t at = 8;
    // Attributes: name\0 type\0 int32 size, then the value; an empty name ends the header.
    for (;;) {
        size_t nameEnd = in.find('\0', at);
        if (nameEnd == std::string::npos) return false;
        if (nameEnd == at) break;
        size_t typeEnd = in.find('\0', nameEnd + 1);
        if (typeEnd == std::string::npos || typeEnd + 5 > in.size()) return false;
        int32_t size = 0;
        std::memcpy(&size, in.data() + typeEnd + 1, 4);
        std::string name = in.substr(at, nameEnd - at);
        std::string value = in.substr(typeEnd + 5, static_cast<size_t>(size));
        if (name == "dataWindow" || name == "displayWindow") {
            int32_t box[4] = {0, 0, side - 1, side - 1};
            value.assign(reinterpret_cast<const char*>(box), sizeof box);
        }
        out += in.substr(at, typeEnd + 5 - at) + value;
        at = typeEnd + 5 + static_cast<size_t>(size);
    }
    out += '\0';
    // An all-zero offset table (OpenEXR rebuilds it by scanning, and finds nothing).
    out.append(static_cast<size_t>(side / 16 + 1) * 8, '\0');
    std::ofstream(file, std::ios::binary | std::ios::trunc) << out;
    return true;
}

}  // namespace testutil
