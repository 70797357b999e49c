// bench_report.h: the bench's rows as the files `pcfscope bench` writes: bench.csv for tools,
// bench.md for people.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "analysis/bench.h"

namespace pcf {

// The CSV's first line, exactly (no trailing newline).
inline constexpr std::string_view BENCH_CSV_HEADER =
    "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,edge_rmse,"
    "edge_max_err,timer";

// The header, then one line per row in the given order. kernel is 0 for methods that take none;
// times in ms / ns with 4 / 2 decimals, errors with 9 significant digits (so equal errors read
// back equal), timer as gpu_timer.h names it. Every line ends with '\n'.
std::string benchCsv(std::span<const BenchRow> rows);

// Reads what benchCsv wrote (a lesson's chart comes from a shipped bench.csv). Throws
// pcf::InputError "SOURCE:LINE: problem" on a wrong header, a wrong field count, an unknown
// method or a field that is not a finite number.
std::vector<BenchRow> parseBenchCsv(std::string_view text, const std::string& source);

// What the table's sentence says about where and how the numbers were taken.
struct BenchSetup {
    std::string sceneName;
    std::string glRenderer;  // GL_RENDERER
    std::string glVersion;   // GL_VERSION
    glm::ivec2 frameSize{0, 0};
    int gpuRepeats = 0;
    int cpuLookups = 0;  // receiver pixels the CPU kernel was timed on
    int cpuPasses = 0;
    int truthSpp = 0;
    int comparedPixels = 0;
    int edgePixels = 0;
};

// A title, a paragraph on the machine (GL_RENDERER) and the timer, the table (one line per row,
// points on the Pareto front of gpu_ms against edge RMSE marked with *), and how to read it.
std::string benchMarkdown(std::span<const BenchRow> rows, const BenchSetup& setup);

// Edge RMSEs closer than this are a tie on the Pareto front: pcf-naive, pcf-gather and pcf-hw
// (and bilinear2x2 and hw2x2) compute one filter, and their errors differ by float rounding.
constexpr double PARETO_ERROR_TOLERANCE = 1e-6;

// Indices of the rows on the Pareto front of (gpu_ms, edge_rmse), cheapest first (pareto.h).
std::vector<size_t> benchParetoFront(std::span<const BenchRow> rows);

}  // namespace pcf
