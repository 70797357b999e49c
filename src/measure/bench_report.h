// bench_report.h: the bench's rows as the files `pcfscope bench` writes: bench.csv for tools,
// bench.md for people.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "measure/bench.h"

namespace pcf {

// The CSV's first line, exactly (no trailing newline). Newer columns come last, so a reader of
// the first eleven (or fifteen) columns keeps working. gl_renderer is GL_RENDERER with its
// commas written as ';' (the files carry no quoting), the same on every row of a run.
inline constexpr std::string_view BENCH_CSV_HEADER =
    "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,edge_rmse,"
    "edge_max_err,timer,gpu_ms_iqr,lookup_ms,lookup_ms_iqr,noisy,weights,sigma,acne_share,"
    "acne_darkening,acne_pixels,leak_share,leak_mean,leak_pixels,shimmer_mean,shimmer_p99,"
    "flicker_share,change_mean,gpu_cpu_ms,lookup_cpu_ms,gl_renderer,contact_edge_rmse,"
    "contact_edge_pixels,truth,contact_distance,gpu_cpu_ms_iqr,lookup_cpu_ms_iqr";
// The header before the CPU times' spreads: still read (their IQRs unknown: 0).
inline constexpr std::string_view BENCH_CSV_HEADER_V7 =
    "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,edge_rmse,"
    "edge_max_err,timer,gpu_ms_iqr,lookup_ms,lookup_ms_iqr,noisy,weights,sigma,acne_share,"
    "acne_darkening,acne_pixels,leak_share,leak_mean,leak_pixels,shimmer_mean,shimmer_p99,"
    "flicker_share,change_mean,gpu_cpu_ms,lookup_cpu_ms,gl_renderer,contact_edge_rmse,"
    "contact_edge_pixels,truth,contact_distance";
// The header before the truth and the contact distance: still read (the truth unknown: empty,
// the distance 0).
inline constexpr std::string_view BENCH_CSV_HEADER_V6 =
    "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,edge_rmse,"
    "edge_max_err,timer,gpu_ms_iqr,lookup_ms,lookup_ms_iqr,noisy,weights,sigma,acne_share,"
    "acne_darkening,acne_pixels,leak_share,leak_mean,leak_pixels,shimmer_mean,shimmer_p99,"
    "flicker_share,change_mean,gpu_cpu_ms,lookup_cpu_ms,gl_renderer,contact_edge_rmse,"
    "contact_edge_pixels";
// The header before the contact columns (bench.h: contactDistance): still read (what lacks: 0).
inline constexpr std::string_view BENCH_CSV_HEADER_V5 =
    "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,edge_rmse,"
    "edge_max_err,timer,gpu_ms_iqr,lookup_ms,lookup_ms_iqr,noisy,weights,sigma,acne_share,"
    "acne_darkening,acne_pixels,leak_share,leak_mean,leak_pixels,shimmer_mean,shimmer_p99,"
    "flicker_share,change_mean,gpu_cpu_ms,lookup_cpu_ms,gl_renderer";
// The header before the renderer: still read (the renderer unknown: empty).
inline constexpr std::string_view BENCH_CSV_HEADER_V4 =
    "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,edge_rmse,"
    "edge_max_err,timer,gpu_ms_iqr,lookup_ms,lookup_ms_iqr,noisy,weights,sigma,acne_share,"
    "acne_darkening,acne_pixels,leak_share,leak_mean,leak_pixels,shimmer_mean,shimmer_p99,"
    "flicker_share,change_mean,gpu_cpu_ms,lookup_cpu_ms";
// The header before the passes' CPU time: still read (what lacks: 0).
inline constexpr std::string_view BENCH_CSV_HEADER_V3 =
    "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,edge_rmse,"
    "edge_max_err,timer,gpu_ms_iqr,lookup_ms,lookup_ms_iqr,noisy,weights,sigma,acne_share,"
    "acne_darkening,acne_pixels,leak_share,leak_mean,leak_pixels,shimmer_mean,shimmer_p99,"
    "flicker_share,change_mean";
// The header before the weights, the error split and the shimmer: still read.
inline constexpr std::string_view BENCH_CSV_HEADER_V2 =
    "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,edge_rmse,"
    "edge_max_err,timer,gpu_ms_iqr,lookup_ms,lookup_ms_iqr,noisy";
// The header before the timing spread columns: still read (shipped lesson figures).
inline constexpr std::string_view BENCH_CSV_HEADER_V1 =
    "method,kernel,map_size,gpu_ms,cpu_ns_per_pixel,texel_reads,rmse,max_err,edge_rmse,"
    "edge_max_err,timer";

// The header, then one line per row in the given order. kernel is 0 for methods that take none;
// times in ms / ns with 4 / 2 decimals, errors, shares and shimmer with 9 significant digits (so
// equal values read back equal), timer as gpu_timer.h names it, noisy 0 or 1, weights box,
// binomial or gaussian, sigma 0 unless gaussian. Every line ends with '\n'.
std::string benchCsv(std::span<const BenchRow> rows);

// Reads what benchCsv wrote (a lesson's chart comes from a shipped bench.csv; contact_edge_rmse
// over contact_edge_pixels, 0 and 0 without --contact; truth in the report's words, with ';' for
// ','; contact_distance in world units; the CPU times' IQRs), or the 34 columns of
// BENCH_CSV_HEADER_V7, the 32 of BENCH_CSV_HEADER_V6, the 30 of
// BENCH_CSV_HEADER_V5,
// the 29 of BENCH_CSV_HEADER_V4, the 27 of BENCH_CSV_HEADER_V3, the fifteen of
// BENCH_CSV_HEADER_V2 or the eleven of BENCH_CSV_HEADER_V1 (what they lack: 0, box, not noisy,
// the renderer empty). The renderer reads back with ';' where GL_RENDERER had ','. Throws
// pcf::InputError "SOURCE:LINE: problem" on a wrong header, a wrong field count, an unknown method
// or a field that is not a finite number.
std::vector<BenchRow> parseBenchCsv(std::string_view text, const std::string& source);

// Which truth a row's errors were measured against: "hard" or "area" (the first word of
// BenchRow::truth), "" when its file does not say (older than the truth column).
std::string benchTruthKind(const BenchRow& row);

// What the table's sentence says about where and how the numbers were taken.
struct BenchSetup {
    std::string sceneName;
    std::string glRenderer;  // GL_RENDERER
    std::string glVersion;   // GL_VERSION
    glm::ivec2 frameSize{0, 0};
    int gpuRepeats = 0;
    int cpuLookups = 0;  // receiver pixels the CPU kernel was timed on
    int cpuPasses = 0;
    int cpuThreads = 1;
    int truthSpp = 0;
    // Which truth: "hard" (the light's centre) or the area light's, e.g. "area: a sun disk of
    // 2 degrees" (what the chart's title says too).
    std::string truthLight = "hard";
    int comparedPixels = 0;
    int edgePixels = 0;
    float truthMaxBound = 0.0f;  // the ground truth's largest per-pixel bound
    int truthRefined = 0;        // pixels the truth integrated finely
    // The machine while the bench ran: 1-minute load average at the start and the end
    // (getloadavg; < 0 when unknown), and its core count.
    double loadStart = -1.0;
    double loadEnd = -1.0;
    int cores = 0;
    int shimmerFrames = 0;       // frames of the shimmer slide
    bool frontByLookup = false;  // the table's Pareto front (as the chart's): lookup ms, not scene
};

// The share of rows flagged noisy, in [0,1] (0 without rows).
double noisyShare(std::span<const BenchRow> rows);

// Whether other work ran as the bench began: the 1-minute load average at the start above half
// the cores. The one at the end does not say: it counts the bench's own rasteriser threads
// (llvmpipe runs on the CPU), which alone take a 2-core machine to about 2.
bool benchMachineBusy(const BenchSetup& setup);

// Whether bench.md opens with the timing note: the machine was busy, or a point is noisy.
bool benchTimingNote(std::span<const BenchRow> rows, const BenchSetup& setup);

// A title, the timing note when benchTimingNote, a paragraph on the machine (GL_RENDERER),
// the timers and the truth's bound, the table (one line per row, both times with their IQR,
// noisy points marked with !, points on the Pareto front of gpu_ms against edge RMSE marked with
// *), and how to read it.
std::string benchMarkdown(std::span<const BenchRow> rows, const BenchSetup& setup);

// Edge RMSEs closer than this are a tie on the Pareto front: pcf-naive, pcf-gather and pcf-hw
// (and bilinear2x2 and hw2x2) compute one filter, and their errors differ by float rounding.
constexpr double PARETO_ERROR_TOLERANCE = 1e-6;

// The clock a row's times are charted and compared by. On a CPU rasteriser (llvmpipe, softpipe:
// render/gpu_timer.h, isSoftwareRenderer) whose CPU times were recorded, the process CPU time of
// all threads: there the GPU's work is the CPU's, and other processes on a shared machine stretch
// the wall clock (17.4's scene pass once read 11.6 ms for pcf-gather 3x3 and 8.5 ms for 7x7 by
// the wall clock, while its CPU time rose 6.3, 7.1, 9.2 ms with the kernel). Else the wall clock
// or the GPU's own query (BenchRow::timer).
bool benchTimesByCpu(const BenchRow& row);

// A row's time of the camera pass (the lookup pass when `lookup`) by that clock: median and
// interquartile range, ms.
double benchPassMs(const BenchRow& row, bool lookup);
double benchPassIqr(const BenchRow& row, bool lookup);

// Whether two rows' times, each drawn as its median +- half its IQR (speed_chart.h), overlap:
// then another run of the bench could order them either way, and neither a chart's front line nor
// a lesson's "faster than" may say which is cheaper.
bool benchSpreadsOverlap(const BenchRow& a, const BenchRow& b, bool lookup);

// Indices of the rows on the Pareto front of (benchPassMs, edge_rmse), cheapest first
// (pareto.h); of the lookup pass's time when byLookup. Every row takes part, by its median time,
// noisy or not: the charts draw each time's spread as a bar beside it (speed_chart.h), so a reader
// sees where two dots' order across could swap in another run instead of losing the dot from the
// front.
std::vector<size_t> benchParetoFront(std::span<const BenchRow> rows, bool byLookup = false);

}  // namespace pcf
