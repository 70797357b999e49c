#include "video/av_library.h"

#include <dlfcn.h>

#include <mutex>
#include <string>

#include "video/video_writer.h"

namespace pcf {

namespace {

// "libavcodec.so.59": the soname of the major version the headers declare.
#define PCF_AV_SONAME(name, major) ("lib" #name ".so." + std::to_string(major))

void* openLibrary(const std::string& soname) {
    // RTLD_LOCAL: FFmpeg's symbols stay out of the global namespace, as they did not leak into
    // our own lookups when linked either.
    void* handle = ::dlopen(soname.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* why = ::dlerror();
        throw VideoError("cannot load FFmpeg's " + soname + " (" + (why ? why : "not found") +
                         "); `animate` and animated steps need it");
    }
    return handle;
}

AvLibrary loadAvLibrary() {
    void* avutil = openLibrary(PCF_AV_SONAME(avutil, LIBAVUTIL_VERSION_MAJOR));
    void* avcodec = openLibrary(PCF_AV_SONAME(avcodec, LIBAVCODEC_VERSION_MAJOR));
    void* avformat = openLibrary(PCF_AV_SONAME(avformat, LIBAVFORMAT_VERSION_MAJOR));
    void* swscale = openLibrary(PCF_AV_SONAME(swscale, LIBSWSCALE_VERSION_MAJOR));
    AvLibrary av;
#define PCF_AV_LOOKUP(library, function)                                                \
    av.function = reinterpret_cast<decltype(av.function)>(::dlsym(library, #function)); \
    if (!av.function) throw VideoError("FFmpeg's lib" #library " has no " #function);
    PCF_AV_FUNCTIONS(PCF_AV_LOOKUP)
#undef PCF_AV_LOOKUP
    return av;
}

}  // namespace

const AvLibrary& avLibrary() {
    // Loaded once; a failure is thrown to every caller that asks (call_once retries after an
    // exception, and the libraries that did open stay open).
    static std::once_flag once;
    static AvLibrary av;
    std::call_once(once, [] { av = loadAvLibrary(); });
    return av;
}

}  // namespace pcf
