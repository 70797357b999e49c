#include "render/image_codec.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <system_error>

#include "render/image_io.h"

namespace pcf {

namespace {

constexpr const char* MODULE_NAME = "libpcfscope_oiio.so";

// Where to look for the module: beside the executable (pcfscope and the tests are built into
// one folder), then where this build put it (PCFSCOPE_OIIO_MODULE, CMakeLists.txt).
std::vector<std::string> modulePaths() {
    std::vector<std::string> paths;
    std::error_code ec;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) paths.push_back((self.parent_path() / MODULE_NAME).string());
#ifdef PCFSCOPE_OIIO_MODULE
    paths.push_back(PCFSCOPE_OIIO_MODULE);
#endif
    return paths;
}

const ImageCodec* loadCodecModule() {
    std::string why = "not found";
    for (const std::string& path : modulePaths()) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec)) continue;
        // RTLD_LOCAL: OpenImageIO's dependencies stay out of the global namespace.
        void* module = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!module) {
            const char* error = ::dlerror();
            why = error ? error : "cannot be loaded";
            continue;
        }
        auto entry = reinterpret_cast<ImageCodecEntry>(::dlsym(module, "pcfscopeImageCodec"));
        const ImageCodec* codec = entry ? entry() : nullptr;
        if (codec && codec->tableSize == sizeof(ImageCodec)) return codec;
        why = path + " is not this build's";
    }
    throw ImageError(std::string("cannot load image support, ") + MODULE_NAME + " (" + why + ")");
}

}  // namespace

const ImageCodec& imageCodec() {
    static std::once_flag once;
    static const ImageCodec* codec = nullptr;
    std::call_once(once, [] { codec = loadCodecModule(); });
    return *codec;
}

}  // namespace pcf
