// full_disk_shim.cpp: a full disk on demand, for tests that cannot mount a small file system.
// Preloaded (LD_PRELOAD) into pcfscope, it makes write(2) to files under $PCF_FULL_DISK_DIR fail
// with ENOSPC once $PCF_FULL_DISK_BYTES bytes have gone there (a write that crosses the limit
// writes what still fits, as a file system does). Every other write passes through. pcfscope's
// own files (image_io's checked writes) and FFmpeg's file protocol both reach the disk through
// write(2), so one interposed symbol covers both.
#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

std::atomic<long long> gWritten{0};

// Whether `fd` is open on a path under `dir`.
bool underDir(int fd, const char* dir) {
    char link[64];
    char path[4096];
    std::snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    ssize_t n = readlink(link, path, sizeof path - 1);
    if (n <= 0) return false;
    path[n] = '\0';
    return std::strncmp(path, dir, std::strlen(dir)) == 0;
}

}  // namespace

extern "C" ssize_t write(int fd, const void* buf, size_t count) {
    using WriteFn = ssize_t (*)(int, const void*, size_t);
    static WriteFn realWrite = reinterpret_cast<WriteFn>(dlsym(RTLD_NEXT, "write"));
    const char* dir = std::getenv("PCF_FULL_DISK_DIR");
    if (dir != nullptr && *dir != '\0' && count > 0 && underDir(fd, dir)) {
        const char* limitText = std::getenv("PCF_FULL_DISK_BYTES");
        long long limit = limitText != nullptr ? std::atoll(limitText) : 0;
        long long before = gWritten.fetch_add(static_cast<long long>(count));
        if (before >= limit) {
            gWritten.fetch_sub(static_cast<long long>(count));
            errno = ENOSPC;
            return -1;
        }
        long long room = limit - before;
        if (static_cast<long long>(count) > room) {
            gWritten.fetch_sub(static_cast<long long>(count) - room);
            count = static_cast<size_t>(room);
        }
    }
    return realWrite(fd, buf, count);
}
