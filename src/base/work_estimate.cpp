#include "base/work_estimate.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <thread>

#include "base/input_error.h"
#include "base/memory_budget.h"

namespace pcf {

namespace {

std::string gibText(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1u << 30));
    return text;
}

}  // namespace

double estimatedSeconds(const WorkEstimate& work) {
    int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    double scale = static_cast<double>(ESTIMATE_MEASURED_CORES) / cores;
    return work.fixedSeconds + (work.frameNs + work.truthNs) * 1e-9 * scale;
}

std::string durationText(double seconds) {
    char text[32];
    if (seconds >= 5400.0) {
        std::snprintf(text, sizeof text, "%.1f h", seconds / 3600.0);
    } else if (seconds >= 90.0) {
        std::snprintf(text, sizeof text, "%.0f min", seconds / 60.0);
    } else {
        std::snprintf(text, sizeof text, "%.0f s", seconds);
    }
    return text;
}

void announceWork(const std::string& command, const WorkEstimate& work, bool force) {
    double seconds = estimatedSeconds(work);
    std::optional<std::uint64_t> available = availableMemoryBytes();
    bool tooLarge = available && work.bytes > *available;
    if (tooLarge && !force) {
        throw InputError(work.what, 0,
                         "needs about " + gibText(work.bytes) + " of memory; " +
                             gibText(*available) +
                             " is available (a smaller size or fewer frames, or -f to start it "
                             "anyway)");
    }
    constexpr std::uint64_t GIB = std::uint64_t{1} << 30;
    if (seconds < 60.0 && work.bytes < GIB && !tooLarge) return;
    std::string over =
        tooLarge ? ", more than the " + gibText(*available) + " available: forced" : "";
    std::fprintf(stderr,
                 "%s: %s: about %s and %s of memory (an estimate%s; Ctrl-C stops it and leaves "
                 "nothing)\n",
                 command.c_str(), work.what.c_str(), durationText(seconds).c_str(),
                 gibText(work.bytes).c_str(), over.c_str());
}

}  // namespace pcf
