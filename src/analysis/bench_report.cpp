#include "analysis/bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>

#include "analysis/pareto.h"
#include "kernel/methods.h"
#include "scene/input_error.h"

namespace pcf {

namespace {

std::string format(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

}  // namespace

std::string benchCsv(std::span<const BenchRow> rows) {
    std::string out(BENCH_CSV_HEADER);
    out += '\n';
    for (const BenchRow& r : rows) {
        out += std::string(methodInfo(r.point.method).name) + ',' + std::to_string(r.point.kernel) +
               ',' + std::to_string(r.point.mapSize) + ',' + format("%.4f", r.gpuMs) + ',' +
               format("%.2f", r.cpuNsPerPixel) + ',' + std::to_string(r.texelReads) + ',' +
               format("%.9g", r.error.rmse) + ',' + format("%.9g", r.error.maxErr) + ',' +
               format("%.9g", r.error.edgeRmse) + ',' + format("%.9g", r.error.edgeMaxErr) + ',' +
               r.timer + ',' + format("%.4f", r.gpuMsIqr) + ',' + format("%.4f", r.lookupMs) + ',' +
               format("%.4f", r.lookupMsIqr) + ',' + (r.noisy ? "1" : "0") + '\n';
    }
    return out;
}

std::vector<BenchRow> parseBenchCsv(std::string_view text, const std::string& source) {
    std::vector<BenchRow> rows;
    int line = 0;
    size_t pos = 0;
    size_t fieldCount = 15;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string row(text.substr(pos, end - pos));
        pos = end + 1;
        ++line;
        if (!row.empty() && row.back() == '\r') row.pop_back();
        if (line == 1) {
            if (row == BENCH_CSV_HEADER_V1) fieldCount = 11;
            if (row != BENCH_CSV_HEADER && row != BENCH_CSV_HEADER_V1) {
                throw InputError(
                    source, line,
                    "not a bench.csv header: expected '" + std::string(BENCH_CSV_HEADER) + "'");
            }
            continue;
        }
        if (row.empty()) continue;
        std::vector<std::string> fields;
        size_t start = 0;
        for (size_t comma; (comma = row.find(',', start)) != std::string::npos; start = comma + 1) {
            fields.push_back(row.substr(start, comma - start));
        }
        fields.push_back(row.substr(start));
        if (fields.size() != fieldCount) {
            throw InputError(source, line,
                             "expected " + std::to_string(fieldCount) + " fields, got " +
                                 std::to_string(fields.size()));
        }
        auto number = [&](size_t k) {
            char* endPtr = nullptr;
            double v = std::strtod(fields[k].c_str(), &endPtr);
            if (fields[k].empty() || *endPtr != '\0' || !std::isfinite(v)) {
                throw InputError(
                    source, line,
                    "field " + std::to_string(k + 1) + " '" + fields[k] + "' is not a number");
            }
            return v;
        };
        // Counts and sizes: a whole number an int holds (a cast of 1e30 is undefined behaviour).
        auto integer = [&](size_t k) {
            double v = number(k);
            if (v != std::floor(v) || std::fabs(v) > 1.0e9) {
                throw InputError(source, line, "field " + std::to_string(k + 1) + " '" +
                                                   fields[k] + "' is not a whole number");
            }
            return static_cast<int>(v);
        };
        std::optional<int> method = methodFromName(fields[0]);
        if (!method) throw InputError(source, line, "unknown method '" + fields[0] + "'");
        BenchRow r;
        r.point = {*method, integer(1), integer(2)};
        r.gpuMs = number(3);
        r.cpuNsPerPixel = number(4);
        r.texelReads = integer(5);
        r.error.rmse = number(6);
        r.error.maxErr = number(7);
        r.error.edgeRmse = number(8);
        r.error.edgeMaxErr = number(9);
        r.timer = fields[10];
        if (fieldCount == 15) {
            r.gpuMsIqr = number(11);
            r.lookupMs = number(12);
            r.lookupMsIqr = number(13);
            double noisy = number(14);
            if (noisy != 0.0 && noisy != 1.0) {
                throw InputError(source, line, "field 15 '" + fields[14] + "' is not 0 or 1");
            }
            r.noisy = noisy == 1.0;
        }
        rows.push_back(r);
    }
    if (line == 0) throw InputError(source, 1, "empty file: expected a bench.csv header");
    return rows;
}

std::vector<size_t> benchParetoFront(std::span<const BenchRow> rows, bool byLookup) {
    std::vector<glm::dvec2> points;
    for (const BenchRow& r : rows) {
        points.emplace_back(byLookup ? r.lookupMs : r.gpuMs, r.error.edgeRmse);
    }
    return paretoFront(points, PARETO_ERROR_TOLERANCE);
}

double noisyShare(std::span<const BenchRow> rows) {
    if (rows.empty()) return 0.0;
    size_t noisy = 0;
    for (const BenchRow& r : rows) noisy += r.noisy ? 1 : 0;
    return static_cast<double>(noisy) / static_cast<double>(rows.size());
}

bool benchMachineBusy(std::span<const BenchRow> rows, const BenchSetup& setup) {
    double half = 0.5 * std::max(setup.cores, 1);
    return setup.loadStart > half || setup.loadEnd > half || noisyShare(rows) > 0.0;
}

std::string benchMarkdown(std::span<const BenchRow> rows, const BenchSetup& setup) {
    std::string timer = rows.empty() ? std::string("none") : rows.front().timer;
    std::string frame = std::to_string(setup.frameSize.x) + "x" + std::to_string(setup.frameSize.y);
    std::string md = "# Speed against accuracy: " + setup.sceneName + ", " + frame + "\n\n";
    if (benchMachineBusy(rows, setup)) {
        size_t noisy = 0;
        for (const BenchRow& r : rows) noisy += r.noisy ? 1 : 0;
        md += "> **The machine was busy.** 1-minute load average " +
              (setup.loadStart >= 0.0 ? format("%.2f", setup.loadStart) : std::string("?")) +
              " at the start, " +
              (setup.loadEnd >= 0.0 ? format("%.2f", setup.loadEnd) : std::string("?")) +
              " at the end, on " + std::to_string(setup.cores) + " cores; " +
              std::to_string(noisy) + " of " + std::to_string(rows.size()) + " points (" +
              format("%.0f", 100.0 * noisyShare(rows)) +
              " %) are noisy (`!`: an interquartile range above 10 % of the median). The "
              "repeats ran round-robin over all points, so load hit every method alike; "
              "compare points by their medians and mind the spreads.\n\n";
    }
    md += "Measured on `" + setup.glRenderer + "` (OpenGL " + setup.glVersion + "). ";
    md += "Times are medians (with the interquartile range) of " +
          std::to_string(setup.gpuRepeats) +
          " samples per point, taken round-robin: each round times every point once. Scene ms "
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
    md += "Errors are of visibility against the ray-cast ground truth (" +
          std::to_string(setup.truthSpp) + "x" + std::to_string(setup.truthSpp) +
          " first-pass samples per pixel, then " + std::to_string(setup.truthRefined) +
          " edge pixels integrated along sub-scanlines; largest per-pixel bound " +
          format("%.5f", setup.truthMaxBound) + "), over the " +
          std::to_string(setup.comparedPixels) +
          " receiver pixels that face the light; the edge band is the " +
          std::to_string(setup.edgePixels) +
          " of them within 2 pixels of a pixel the true shadow edge crosses.\n\n";

    std::vector<size_t> front = benchParetoFront(rows, setup.frontByLookup);
    std::set<size_t> onFront(front.begin(), front.end());
    md +=
        "| method | N | map | scene ms | IQR | lookup ms | IQR | CPU ns/px | texel reads | RMSE | "
        "max err | edge RMSE | edge max err |\n";
    md += "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (size_t k = 0; k < rows.size(); ++k) {
        const BenchRow& r = rows[k];
        md += "| " + std::string(methodInfo(r.point.method).name) + (onFront.count(k) ? " *" : "") +
              (r.noisy ? " !" : "") + " | " +
              (r.point.kernel > 0 ? std::to_string(r.point.kernel) : std::string("-")) + " | " +
              std::to_string(r.point.mapSize) + " | " + format("%.3f", r.gpuMs) + " | " +
              format("%.3f", r.gpuMsIqr) + " | " + format("%.3f", r.lookupMs) + " | " +
              format("%.3f", r.lookupMsIqr) + " | " + format("%.1f", r.cpuNsPerPixel) + " | " +
              std::to_string(r.texelReads) + " | " + format("%.4f", r.error.rmse) + " | " +
              format("%.4f", r.error.maxErr) + " | " + format("%.4f", r.error.edgeRmse) + " | " +
              format("%.4f", r.error.edgeMaxErr) + " |\n";
    }
    md += "\n`*` marks the Pareto front of " +
          std::string(setup.frontByLookup ? "lookup" : "scene") +
          " time against edge RMSE: no other run is both "
          "faster and more accurate; `!` a noisy point (an IQR above 10 % of its median). "
          "`speed_vs_accuracy.png` plots the same; `diff/` holds each "
          "run's signed error (rendered - truth: red too bright, blue too dark, white exact).\n";
    return md;
}

}  // namespace pcf
