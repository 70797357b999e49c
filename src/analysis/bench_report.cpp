#include "analysis/bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <cstdio>
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
               r.timer + '\n';
    }
    return out;
}

std::vector<BenchRow> parseBenchCsv(std::string_view text, const std::string& source) {
    std::vector<BenchRow> rows;
    int line = 0;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string row(text.substr(pos, end - pos));
        pos = end + 1;
        ++line;
        if (!row.empty() && row.back() == '\r') row.pop_back();
        if (line == 1) {
            if (row != BENCH_CSV_HEADER) {
                throw InputError(source, line, "not a bench.csv header: expected '" +
                                                   std::string(BENCH_CSV_HEADER) + "'");
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
        if (fields.size() != 11) {
            throw InputError(source, line, "expected 11 fields, got " +
                                               std::to_string(fields.size()));
        }
        auto number = [&](size_t k) {
            char* endPtr = nullptr;
            double v = std::strtod(fields[k].c_str(), &endPtr);
            if (fields[k].empty() || *endPtr != '\0' || !std::isfinite(v)) {
                throw InputError(source, line, "field " + std::to_string(k + 1) + " '" +
                                                   fields[k] + "' is not a number");
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
        rows.push_back(r);
    }
    if (line == 0) throw InputError(source, 1, "empty file: expected a bench.csv header");
    return rows;
}

std::vector<size_t> benchParetoFront(std::span<const BenchRow> rows) {
    std::vector<glm::dvec2> points;
    for (const BenchRow& r : rows) points.emplace_back(r.gpuMs, r.error.edgeRmse);
    return paretoFront(points, PARETO_ERROR_TOLERANCE);
}

std::string benchMarkdown(std::span<const BenchRow> rows, const BenchSetup& setup) {
    std::string timer = rows.empty() ? std::string("none") : rows.front().timer;
    std::string frame = std::to_string(setup.frameSize.x) + "x" + std::to_string(setup.frameSize.y);
    std::string md = "# Speed against accuracy: " + setup.sceneName + ", " + frame + "\n\n";
    md += "Measured on `" + setup.glRenderer + "` (OpenGL " + setup.glVersion + "). ";
    md += "GPU time is the median of " + std::to_string(setup.gpuRepeats) +
          " colour-only camera passes at " + frame + ", timed with `" + timer + "`";
    if (timer == "glFinish+steady_clock") {
        md +=
            " (a software rasteriser runs the work when it is flushed, so a GL_TIME_ELAPSED "
            "query would measure submission only)";
    }
    md +=
        ". CPU time is the shared kernel's batch path (`filterVisibility`), one thread, the "
        "median of " +
        std::to_string(setup.cpuPasses) + " passes over " + std::to_string(setup.cpuLookups) +
        " receiver pixels' light-space lookups. ";
    md += "Errors are of visibility against the ray-cast ground truth (" +
          std::to_string(setup.truthSpp) + "x" + std::to_string(setup.truthSpp) +
          " samples per pixel), over the " + std::to_string(setup.comparedPixels) +
          " receiver pixels that face the light; the edge band is the " +
          std::to_string(setup.edgePixels) +
          " of them within 2 pixels of a pixel the true shadow edge crosses.\n\n";

    std::vector<size_t> front = benchParetoFront(rows);
    std::set<size_t> onFront(front.begin(), front.end());
    md +=
        "| method | N | map | GPU ms | CPU ns/px | texel reads | RMSE | max err | edge RMSE | "
        "edge max err |\n";
    md += "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (size_t k = 0; k < rows.size(); ++k) {
        const BenchRow& r = rows[k];
        md += "| " + std::string(methodInfo(r.point.method).name) + (onFront.count(k) ? " *" : "") +
              " | " + (r.point.kernel > 0 ? std::to_string(r.point.kernel) : std::string("-")) +
              " | " + std::to_string(r.point.mapSize) + " | " + format("%.3f", r.gpuMs) + " | " +
              format("%.1f", r.cpuNsPerPixel) + " | " + std::to_string(r.texelReads) + " | " +
              format("%.4f", r.error.rmse) + " | " + format("%.4f", r.error.maxErr) + " | " +
              format("%.4f", r.error.edgeRmse) + " | " + format("%.4f", r.error.edgeMaxErr) +
              " |\n";
    }
    md +=
        "\n`*` marks the Pareto front of GPU time against edge RMSE: no other run is both "
        "faster and more accurate. `speed_vs_accuracy.png` plots the same; `diff/` holds each "
        "run's signed error (rendered - truth: red too bright, blue too dark, white exact).\n";
    return md;
}

}  // namespace pcf
