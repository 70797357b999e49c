#include "measure/bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>

#include "base/input_error.h"
#include "kernel/methods.h"
#include "measure/csv_lines.h"
#include "measure/pareto.h"
#include "render/gpu_timer.h"

namespace pcf {

namespace {

// A text field: the files carry no quoting, so a comma becomes ';' and a line break a space.
std::string csvWords(std::string text) {
    std::replace(text.begin(), text.end(), ',', ';');
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

std::string format(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

// An acne or leak share in percent, or "-" when its mask held no pixel (a footprint wider than
// every clean region of the frame): 0 of 0 is no measurement, not a clean 0.00 %.
std::string failurePercent(const FailureRate& f) {
    return f.count > 0 ? format("%.2f", 100.0 * f.share) : std::string("-");
}

// One line of bench.md's table.
std::string tableLine(const BenchRow& r, bool onFront) {
    std::string name(methodInfo(r.point.method).name);
    if (r.point.weights != PCF_WEIGHTS_BOX) name += " " + std::string(weightsName(r.point.weights));
    if (r.point.weights == PCF_WEIGHTS_GAUSSIAN) name += format(" %g", r.point.sigma);
    return "| " + name + (onFront ? " *" : "") + (r.noisy ? " !" : "") + " | " +
           (r.point.kernel > 0 ? std::to_string(r.point.kernel) : std::string("-")) + " | " +
           std::to_string(r.point.mapSize) + " | " + format("%.3f", r.gpuMs) + " | " +
           format("%.3f", r.gpuMsIqr) + " | " + format("%.3f", r.lookupMs) + " | " +
           format("%.3f", r.lookupMsIqr) + " | " + format("%.3f", r.gpuCpuMs) + " | " +
           format("%.3f", r.gpuCpuMsIqr) + " | " + format("%.3f", r.lookupCpuMs) + " | " +
           format("%.3f", r.lookupCpuMsIqr) + " | " + format("%.1f", r.cpuNsPerPixel) + " | " +
           std::to_string(r.texelReads) + " | " + format("%.4f", r.error.rmse) + " | " +
           format("%.4f", r.error.maxErr) + " | " + format("%.4f", r.error.edgeRmse) + " | " +
           format("%.4f", r.error.edgeMaxErr) + " | " + failurePercent(r.acne) + " | " +
           failurePercent(r.leak) + " | " + format("%.3f", r.shimmer.flickerP99) + " | " +
           format("%.2f", 100.0 * r.shimmer.flickerShare) + " |\n";
}

}  // namespace

std::string benchCsv(std::span<const BenchRow> rows) {
    std::string out(BENCH_CSV_HEADER);
    out += '\n';
    auto g = [](double v) { return ',' + format("%.9g", v); };
    for (const BenchRow& r : rows) {
        out += std::string(methodInfo(r.point.method).name) + ',' + std::to_string(r.point.kernel) +
               ',' + std::to_string(r.point.mapSize) + ',' + format("%.4f", r.gpuMs) + ',' +
               format("%.2f", r.cpuNsPerPixel) + ',' + std::to_string(r.texelReads) +
               g(r.error.rmse) + g(r.error.maxErr) + g(r.error.edgeRmse) + g(r.error.edgeMaxErr) +
               ',' + r.timer + ',' + format("%.4f", r.gpuMsIqr) + ',' + format("%.4f", r.lookupMs) +
               ',' + format("%.4f", r.lookupMsIqr) + ',' + (r.noisy ? "1" : "0") + ',' +
               std::string(weightsName(r.point.weights)) + g(r.point.sigma) + g(r.acne.share) +
               g(r.acne.mean) + ',' + std::to_string(r.acne.count) + g(r.leak.share) +
               g(r.leak.mean) + ',' + std::to_string(r.leak.count) + g(r.shimmer.flickerMean) +
               g(r.shimmer.flickerP99) + g(r.shimmer.flickerShare) + g(r.shimmer.mean) + ',' +
               format("%.4f", r.gpuCpuMs) + ',' + format("%.4f", r.lookupCpuMs) + ',' +
               csvWords(r.glRenderer) + g(r.contact.edgeRmse) + ',' +
               std::to_string(r.contact.edgePixels) + ',' + csvWords(r.truth) +
               g(r.contactDistance) + ',' + format("%.4f", r.gpuCpuMsIqr) + ',' +
               format("%.4f", r.lookupCpuMsIqr) + '\n';
    }
    return out;
}

namespace {

BenchRow parseBenchRow(const CsvFields& f) {
    std::optional<int> method = methodFromName(f.text(0));
    if (!method) f.fail("unknown method '" + f.text(0) + "'");
    BenchRow r;
    r.point = {*method, f.count(1), f.count(2)};
    r.gpuMs = f.measure(3);
    r.cpuNsPerPixel = f.measure(4);
    r.texelReads = f.count(5);
    r.error = {f.measure(6), f.measure(7), f.measure(8), f.measure(9), 0, 0};
    r.timer = f.text(10);
    if (f.size() == 11) return r;
    r.gpuMsIqr = f.measure(11);
    r.lookupMs = f.measure(12);
    r.lookupMsIqr = f.measure(13);
    r.noisy = f.flag(14);
    if (f.size() == 15) return r;
    std::optional<int> weights = weightsFromName(f.text(15));
    if (!weights) f.fail("unknown weights '" + f.text(15) + "'");
    r.point.weights = *weights;
    r.point.sigma = static_cast<float>(f.measure(16));
    r.acne = {f.measure(17), f.measure(18), f.count(19)};
    r.leak = {f.measure(20), f.measure(21), f.count(22)};
    r.shimmer.flickerMean = f.measure(23);
    r.shimmer.flickerP99 = f.measure(24);
    r.shimmer.flickerShare = f.measure(25);
    r.shimmer.mean = f.measure(26);
    if (f.size() == 27) return r;
    r.gpuCpuMs = f.measure(27);
    r.lookupCpuMs = f.measure(28);
    if (f.size() == 29) return r;
    r.glRenderer = f.text(29);
    if (f.size() == 30) return r;
    r.contact.edgeRmse = f.measure(30);
    r.contact.edgePixels = f.count(31);
    if (f.size() == 32) return r;
    r.truth = f.text(32);
    r.contactDistance = f.measure(33);
    if (f.size() == 34) return r;
    r.gpuCpuMsIqr = f.measure(34);
    r.lookupCpuMsIqr = f.measure(35);
    return r;
}

// The field count a header line promises, or 0 when it is not a bench.csv header.
size_t fieldsOfHeader(const std::string& header) {
    for (std::string_view h :
         {BENCH_CSV_HEADER, BENCH_CSV_HEADER_V7, BENCH_CSV_HEADER_V6, BENCH_CSV_HEADER_V5,
          BENCH_CSV_HEADER_V4, BENCH_CSV_HEADER_V3, BENCH_CSV_HEADER_V2, BENCH_CSV_HEADER_V1}) {
        if (header == h) return static_cast<size_t>(std::count(h.begin(), h.end(), ',')) + 1;
    }
    return 0;
}

}  // namespace

std::vector<BenchRow> parseBenchCsv(std::string_view text, const std::string& source) {
    std::vector<BenchRow> rows;
    size_t fieldCount = 0;
    std::vector<CsvLine> lines = csvLines(text);
    if (lines.empty()) throw InputError(source, 1, "empty file: expected a bench.csv header");
    for (const CsvLine& l : lines) {
        if (l.number == 1) {
            fieldCount = fieldsOfHeader(l.text);
            if (fieldCount == 0) {
                throw InputError(
                    source, l.number,
                    "not a bench.csv header: expected '" + std::string(BENCH_CSV_HEADER) + "'");
            }
            continue;
        }
        if (l.text.empty()) continue;
        CsvFields fields(l.text, source, l.number);
        if (fields.size() != fieldCount) {
            fields.fail("expected " + std::to_string(fieldCount) + " fields, got " +
                        std::to_string(fields.size()));
        }
        rows.push_back(parseBenchRow(fields));
    }
    return rows;
}

std::string benchTruthKind(const BenchRow& row) { return row.truth.substr(0, row.truth.find(' ')); }

bool benchTimesByCpu(const BenchRow& row) {
    return isSoftwareRenderer(row.glRenderer) && row.gpuCpuMs > 0.0 && row.lookupCpuMs > 0.0;
}

double benchPassMs(const BenchRow& row, bool lookup) {
    if (benchTimesByCpu(row)) return lookup ? row.lookupCpuMs : row.gpuCpuMs;
    return lookup ? row.lookupMs : row.gpuMs;
}

double benchPassIqr(const BenchRow& row, bool lookup) {
    if (benchTimesByCpu(row)) return lookup ? row.lookupCpuMsIqr : row.gpuCpuMsIqr;
    return lookup ? row.lookupMsIqr : row.gpuMsIqr;
}

bool benchSpreadsOverlap(const BenchRow& a, const BenchRow& b, bool lookup) {
    double aMs = benchPassMs(a, lookup), bMs = benchPassMs(b, lookup);
    double reach = 0.5 * (benchPassIqr(a, lookup) + benchPassIqr(b, lookup));
    return std::abs(aMs - bMs) <= reach;
}

std::vector<size_t> benchParetoFront(std::span<const BenchRow> rows, bool byLookup) {
    std::vector<glm::dvec2> points;
    for (const BenchRow& r : rows) points.emplace_back(benchPassMs(r, byLookup), r.error.edgeRmse);
    return paretoFront(points, PARETO_ERROR_TOLERANCE);
}

double noisyShare(std::span<const BenchRow> rows) {
    if (rows.empty()) return 0.0;
    size_t noisy = 0;
    for (const BenchRow& r : rows) noisy += r.noisy ? 1 : 0;
    return static_cast<double>(noisy) / static_cast<double>(rows.size());
}

bool benchMachineBusy(const BenchSetup& setup) {
    return setup.loadStart > 0.5 * std::max(setup.cores, 1);
}

bool benchTimingNote(std::span<const BenchRow> rows, const BenchSetup& setup) {
    return benchMachineBusy(setup) || noisyShare(rows) > 0.0;
}

namespace {

// The note above the table: whether other work ran as the bench began, and how many points came
// out noisy; "" when neither.
std::string busyNote(std::span<const BenchRow> rows, const BenchSetup& setup) {
    if (!benchTimingNote(rows, setup)) return "";
    size_t noisy = 0;
    for (const BenchRow& r : rows) noisy += r.noisy ? 1 : 0;
    auto load = [](double l) { return l >= 0.0 ? format("%.2f", l) : std::string("?"); };
    return std::string(benchMachineBusy(setup) ? "> **The machine was busy when the bench began.** "
                                               : "> **Noisy timings.** ") +
           "1-minute load average " + load(setup.loadStart) + " at the start and " +
           load(setup.loadEnd) +
           " at the end (which counts the bench's own rasteriser threads), on " +
           std::to_string(setup.cores) + " cores; " + std::to_string(noisy) + " of " +
           std::to_string(rows.size()) + " points (" + format("%.0f", 100.0 * noisyShare(rows)) +
           " %) are noisy (`!`: an interquartile range above 10 % of the median). The "
           "repeats ran round-robin over all points, so load hit every method alike; "
           "compare points by their medians and mind the spreads.\n\n";
}

// How each column was measured: the renderer, the timers, the CPU batch, the ground truth.
std::string methodsNote(const BenchSetup& setup, const std::string& timer,
                        const std::string& frame) {
    std::string md;
    md += "Measured on `" + setup.glRenderer + "` (OpenGL " + setup.glVersion + "). ";
    md += "Times are medians (with the interquartile range) of " +
          std::to_string(setup.gpuRepeats) +
          " samples per point, taken round-robin: each round times every point once; a point "
          "noisy after them gets as many rounds again before it is marked noisy. Scene ms "
          "is a colour-only camera pass at " +
          frame +
          "; lookup ms is the filter alone, the kernel as a bare full-screen pass over the "
          "frame's light-space target (as the GPU parity test runs it). Both timed with `" +
          timer + "`";
    if (timer == "glFinish+steady_clock") {
        md +=
            " (a software rasteriser runs the work when it is flushed, so a GL_TIME_ELAPSED "
            "query would measure submission only)";
    }
    md +=
        ". CPU time is the shared kernel's batch path (`filterVisibility`), wall time per "
        "lookup with " +
        std::to_string(setup.cpuThreads) + " thread" + (setup.cpuThreads == 1 ? "" : "s") +
        " sharing each pass, the median of " + std::to_string(setup.cpuPasses) + " passes over " +
        std::to_string(setup.cpuLookups) + " receiver pixels' light-space lookups. ";
    md += "Errors are of visibility against the ray-cast ground truth, " + setup.truthLight + " (" +
          std::to_string(setup.truthSpp) + "x" + std::to_string(setup.truthSpp) +
          " first-pass samples per pixel, then " + std::to_string(setup.truthRefined) +
          " edge pixels integrated along sub-scanlines; largest per-pixel bound " +
          format("%.5f", setup.truthMaxBound) + "), over the " +
          std::to_string(setup.comparedPixels) +
          " receiver pixels that face the light; the edge band is the " +
          std::to_string(setup.edgePixels) +
          " of them within 2 pixels of a pixel the true shadow edge crosses.\n\n";
    return md;
}

}  // namespace

std::string benchMarkdown(std::span<const BenchRow> rows, const BenchSetup& setup) {
    std::string timer = rows.empty() ? std::string("none") : rows.front().timer;
    std::string frame = std::to_string(setup.frameSize.x) + "x" + std::to_string(setup.frameSize.y);
    std::string md = "# Speed against accuracy: " + setup.sceneName + ", " + frame + "\n\n";
    md += busyNote(rows, setup);
    md += methodsNote(setup, timer, frame);

    std::vector<size_t> front = benchParetoFront(rows, setup.frontByLookup);
    std::set<size_t> onFront(front.begin(), front.end());
    md +=
        "| method | N | map | scene ms | IQR | lookup ms | IQR | scene CPU ms | IQR | lookup CPU "
        "ms "
        "| IQR | CPU ns/px | texel reads | RMSE | max err | edge RMSE | edge max err | acne % | "
        "leak % | shimmer p99 | flicker % |\n";
    md += "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (size_t k = 0; k < rows.size(); ++k) md += tableLine(rows[k], onFront.count(k) > 0);
    bool cpu = !rows.empty() && std::all_of(rows.begin(), rows.end(), benchTimesByCpu);
    md += "\n`*` marks the Pareto front of " +
          std::string(setup.frontByLookup ? "lookup" : "scene") +
          (cpu ? " process CPU time (the renderer is a CPU rasteriser: its work is the CPU's, "
                 "which other processes do not stretch as they do the wall clock)"
               : " time") +
          " against edge RMSE, by the median: no other run beats it on both "
          "(where two runs' IQRs overlap, another run of the bench may order them the other way); "
          "CPU ms are the passes' process CPU time, all threads (0: a GPU's own timer measured); "
          "`!` a noisy point (an IQR above 10 % of its median). "
          "Edge RMSE is the filter's aliasing error (the edge band, where the truth is partly "
          "lit); acne % is the share of the clean lit pixels (fully lit over the method's whole "
          "footprint) the method darkens below 0.99, leak % the share of the clean umbra pixels "
          "it lights above 0.01 (- where the method's footprint leaves no clean pixel to count): "
          "bias errors, kept apart from the filter's. Shimmer p99 is the "
          "99th percentile of a pixel's change per 1/32-texel slide of the map's grid (" +
          std::to_string(setup.shimmerFrames) +
          " frames) over the pixels that flicker (change by more than 1/512), flicker % their "
          "share of the receivers. `speed_vs_accuracy.png` plots edge RMSE, "
          "`speed_vs_stability.png` shimmer, "
          "against time; `diff/` holds each "
          "run's signed error (rendered - truth: red too bright, blue too dark, white exact).\n";
    return md;
}

}  // namespace pcf
