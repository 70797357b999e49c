#include "render/driver_pin.h"

#include "render/sanitizer_build.h"

#if PCFSCOPE_ASAN
#include <dlfcn.h>
#include <link.h>
#endif

namespace pcf {

#if PCFSCOPE_ASAN

std::set<std::string> mappedLibraries() {
    std::set<std::string> out;
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* data) {
            if (info->dlpi_name != nullptr && info->dlpi_name[0] != '\0') {
                static_cast<std::set<std::string>*>(data)->insert(info->dlpi_name);
            }
            return 0;
        },
        &out);
    return out;
}

void pinLibrariesLoadedSince(const std::set<std::string>& before) {
    for (const std::string& path : mappedLibraries()) {
        if (before.count(path) != 0) continue;
        // RTLD_NOLOAD: only a library already mapped; the handle's extra reference is kept on
        // purpose (NODELETE makes the library outlive every dlclose anyway).
        dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
    }
}

#else

std::set<std::string> mappedLibraries() { return {}; }
void pinLibrariesLoadedSince(const std::set<std::string>&) {}

#endif

}  // namespace pcf
