// memory_budget.h: how much memory this process can still get, so that work too large for the
// machine is refused in one line before it starts, instead of swapping for minutes or ending
// in "internal error: std::bad_alloc".
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace pcf {

// The least of: MemAvailable (/proc/meminfo), a cgroup v2 limit's headroom (memory.max less
// memory.current, when a limit is set), and the address-space limit (ulimit -v) less what the
// process has mapped. nullopt when none of them can be read.
std::optional<std::uint64_t> availableMemoryBytes();

// Throws InputError(what, 0, "needs about 9.8 GiB of memory; 7.5 GiB is available") when
// `bytes` exceeds availableMemoryBytes(), unless `force` (-f/--force: start it anyway). `what`
// names the work, e.g. "--size 8192x8192".
void requireMemory(const std::string& what, std::uint64_t bytes, bool force = false);

// A command's estimate: `base` bytes (the process, the GL driver) plus `perPixel` bytes for each
// of width x height pixels (in 64 bits: 8192 x 8192 x 420 overflows 32).
constexpr std::uint64_t memoryEstimate(std::uint64_t base, std::uint64_t perPixel, int width,
                                       int height) {
    return base + perPixel * static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
}
constexpr std::uint64_t MIB = std::uint64_t{1} << 20;

}  // namespace pcf
