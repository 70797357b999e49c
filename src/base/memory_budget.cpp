#include "base/memory_budget.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "base/input_error.h"

namespace pcf {

namespace {

// The value (kB) of `key` in a /proc/meminfo-style file ("MemAvailable:  123456 kB").
std::optional<std::uint64_t> procField(const char* file, const std::string& key) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (!line.starts_with(key + ":")) continue;
        std::istringstream fields(line.substr(key.size() + 1));
        std::uint64_t kb = 0;
        if (fields >> kb) return kb * 1024;
    }
    return std::nullopt;
}

// A cgroup v2 file holding one number ("max" means no limit).
std::optional<std::uint64_t> cgroupNumber(const char* file) {
    std::ifstream in(file);
    std::uint64_t value = 0;
    if (in >> value) return value;
    return std::nullopt;
}

std::string gib(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1u << 30));
    return text;
}

}  // namespace

std::optional<std::uint64_t> availableMemoryBytes() {
    std::optional<std::uint64_t> least = procField("/proc/meminfo", "MemAvailable");
    auto lower = [&](std::uint64_t v) { least = least ? std::min(*least, v) : v; };
    std::optional<std::uint64_t> cgMax = cgroupNumber("/sys/fs/cgroup/memory.max");
    std::optional<std::uint64_t> cgNow = cgroupNumber("/sys/fs/cgroup/memory.current");
    if (cgMax && cgNow) lower(*cgMax > *cgNow ? *cgMax - *cgNow : 0);
    rlimit as{};
    if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
        std::uint64_t mapped = procField("/proc/self/status", "VmSize").value_or(0);
        lower(as.rlim_cur > mapped ? as.rlim_cur - mapped : 0);
    }
    return least;
}

void requireMemory(const std::string& what, std::uint64_t bytes, bool force) {
    std::optional<std::uint64_t> available = availableMemoryBytes();
    if (!available || bytes <= *available || force) return;
    throw InputError(what, 0,
                     "needs about " + gib(bytes) + " of memory; " + gib(*available) +
                         " is available (use a smaller size, or -f to start it anyway)");
}

}  // namespace pcf
