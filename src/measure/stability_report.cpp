#include "measure/stability_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "base/input_error.h"
#include "kernel/methods.h"
#include "measure/csv_lines.h"
#include "measure/failure_measures.h"
#include "measure/number_text.h"
#include "measure/stability_bleed.h"

namespace pcf {

namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

std::string fixed(double v, int decimals) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string percent(double share) { return fixed(100.0 * share, share < 0.1 ? 2 : 1) + " %"; }

bool sameX(double a, double b) { return std::abs(a - b) <= 1e-6 * std::max(1.0, std::abs(b)); }

bool matches(const StabilityRow& r, const StabilityMethod& m, std::string_view bias) {
    return r.method == m.method && r.kernel == m.kernel && r.bias == bias;
}

}  // namespace

std::string stabilityCsv(std::span<const StabilityRow> rows) {
    std::string out(STABILITY_CSV_HEADER);
    out += '\n';
    for (const StabilityRow& r : rows) {
        out += r.sweep + ',';
        out += (r.method < 0 ? std::string("-") : std::string(methodInfo(r.method).name)) + ',';
        out += std::to_string(r.kernel) + ',' + r.bias + ',' + r.xName + ',' + number(r.x) + ',' +
               r.metric + ',' + number(r.y) + '\n';
    }
    return out;
}

std::vector<StabilityRow> parseStabilityCsv(std::string_view text, const std::string& source) {
    std::vector<StabilityRow> rows;
    std::vector<CsvLine> lines = csvLines(text);
    if (lines.empty()) throw InputError(source, 1, "empty file: expected a stability.csv header");
    for (const CsvLine& l : lines) {
        if (l.number == 1) {
            if (l.text != STABILITY_CSV_HEADER) {
                throw InputError(source, l.number,
                                 "not a stability.csv header: expected '" +
                                     std::string(STABILITY_CSV_HEADER) + "'");
            }
            continue;
        }
        if (l.text.empty()) continue;
        CsvFields f(l.text, source, l.number);
        if (f.size() != 8) f.fail("expected 8 fields, got " + std::to_string(f.size()));
        if (!sweepFromName(f.text(0)) && f.text(0) != STABILITY_SETUP_SWEEP)
            f.fail("unknown sweep '" + f.text(0) + "'");
        StabilityRow r;
        r.sweep = f.text(0);
        if (f.text(1) != "-") {
            std::optional<int> method = methodFromName(f.text(1));
            if (!method) f.fail("unknown method '" + f.text(1) + "'");
            r.method = *method;
        }
        r.kernel = f.integer(2);
        r.bias = f.text(3);
        r.xName = f.text(4);
        r.x = f.number(5);
        r.metric = f.text(6);
        r.y = f.number(7);
        rows.push_back(r);
    }
    return rows;
}

std::vector<StabilityRow> stabilitySetupRows(const StabilitySetup& setup) {
    std::string sweep(STABILITY_SETUP_SWEEP);
    auto value = [&](const std::string& name, double y) {
        return StabilityRow{sweep, -1, 0, "-", "-", 0.0, name, y};
    };
    auto words = [&](const std::string& name, std::string text) {
        std::replace(text.begin(), text.end(), ',', ';');
        std::replace(text.begin(), text.end(), '\n', ' ');
        return StabilityRow{sweep, -1, 0, "-", "-", 0.0, name + ":" + text, 0.0};
    };
    return {words("scene", setup.sceneName),
            words("gl_renderer", setup.glRenderer),
            value("frame_width", setup.frameSize.x),
            value("frame_height", setup.frameSize.y),
            value("map_size", setup.mapSize),
            value("truth_spp", setup.truthSpp),
            value("constant_bias", setup.constantBias),
            words("cull", setup.cull),
            words("depth", setup.depthFormat),
            value("precision_elevation_deg", setup.precisionElevation),
            value("tradeoff_elevation_deg", setup.tradeoffElevation)};
}

std::optional<StabilitySetup> stabilitySetupOf(std::span<const StabilityRow> rows) {
    StabilitySetup s;
    bool any = false;
    for (const StabilityRow& r : rows) {
        if (r.sweep != STABILITY_SETUP_SWEEP) continue;
        any = true;
        size_t colon = r.metric.find(':');
        std::string key = r.metric.substr(0, colon);
        std::string text = colon == std::string::npos ? "" : r.metric.substr(colon + 1);
        if (key == "scene") s.sceneName = text;
        if (key == "gl_renderer") s.glRenderer = text;
        if (key == "cull") s.cull = text;
        if (key == "depth") s.depthFormat = text;
        if (key == "frame_width") s.frameSize.x = static_cast<int>(r.y);
        if (key == "frame_height") s.frameSize.y = static_cast<int>(r.y);
        if (key == "map_size") s.mapSize = static_cast<int>(r.y);
        if (key == "truth_spp") s.truthSpp = static_cast<int>(r.y);
        if (key == "constant_bias") s.constantBias = r.y;
        if (key == "precision_elevation_deg") s.precisionElevation = r.y;
        if (key == "tradeoff_elevation_deg") s.tradeoffElevation = r.y;
    }
    if (!any) return std::nullopt;
    s.settings = "constant bias " + chartTickText(s.constantBias) + ", cull " + s.cull +
                 " faces in the shadow pass, depth " + s.depthFormat;
    return s;
}

std::optional<double> stabilityValue(std::span<const StabilityRow> rows, std::string_view sweep,
                                     const StabilityMethod& method, std::string_view bias,
                                     std::string_view metric, double x) {
    for (const StabilityRow& r : rows) {
        if (r.sweep == sweep && matches(r, method, bias) && r.metric == metric && sameX(r.x, x)) {
            return r.y;
        }
    }
    return std::nullopt;
}

std::vector<StabilitySummary> summarizeStability(std::span<const StabilityRow> rows,
                                                 double leakBias) {
    std::vector<StabilitySummary> out;
    auto find = [&](const StabilityRow& r) -> StabilitySummary* {
        for (StabilitySummary& s : out) {
            if (matches(r, s.method, s.bias)) return &s;
        }
        return nullptr;
    };
    for (const StabilityRow& r : rows) {
        // pcss's sweeps have their own lines (pcssLines), and the cascades sweep its own CSV
        // (stability_cascades.h): no row of the method-and-bias table.
        if (r.method < 0 || r.sweep.starts_with("pcss-") || r.sweep == "cascades") continue;
        StabilitySummary* s = find(r);
        if (s == nullptr) {
            out.push_back({});
            s = &out.back();
            s->method = {r.method, r.kernel};
            s->bias = r.bias;
        }
        if (r.sweep == "acne" && r.metric == "false_shadow_rate") {
            // Rows come in the sweep's order, elevations from high to low.
            s->acneSwept = true;
            s->acneWorstRate = std::max(s->acneWorstRate, r.y);
            if (r.y > 0.01 && (!s->acneOnsetDeg || r.x > *s->acneOnsetDeg)) s->acneOnsetDeg = r.x;
        } else if (r.sweep == "shimmer") {
            if (r.metric == "light_mean") s->shimmerMean = r.y;
            if (r.metric == "light_p99") s->shimmerP99 = r.y;
            if (r.metric == "snapped_mean") s->snappedMean = r.y;
            if (r.metric == "snapped_max") s->snappedMax = r.y;
            if (r.metric == "light_flicker_p99") s->flickerP99 = r.y;
            if (r.metric == "light_flicker_share") s->flickerShare = r.y;
            if (r.metric == "snapped_p99") s->snappedP99 = r.y;
            if (r.metric == "camera_mean") s->cameraMean = r.y;
            if (r.metric == "camera_p99") s->cameraP99 = r.y;
        } else if (r.sweep == "leak") {
            size_t colon = r.metric.find(':');
            if (colon == std::string::npos) continue;
            std::string scene = r.metric.substr(0, colon);
            std::string what = r.metric.substr(colon + 1);
            StabilitySummary::Leak* leak = nullptr;
            for (StabilitySummary::Leak& l : s->leaks) {
                if (l.scene == scene) leak = &l;
            }
            if (leak == nullptr) {
                s->leaks.push_back({scene, r.x, 0, 0, 0});
                leak = &s->leaks.back();
            }
            // Keep the bias nearest the run's constant bias.
            if (std::abs(r.x - leakBias) < std::abs(leak->bias - leakBias) - 1e-12) {
                *leak = {scene, r.x, 0, 0, 0};
            }
            if (!sameX(r.x, leak->bias)) continue;
            if (what == "leak_rate") leak->rate = r.y;
            if (what == "leak_width_world") leak->widthWorld = r.y;
            if (what == "leak_width_texels") leak->widthTexels = r.y;
        }
    }
    return out;
}

namespace {

// The leak columns show the largest bias swept: the run's own bias rarely leaks at all, and the
// chart shows the whole curve.
double largestLeakBias(std::span<const StabilityRow> rows, double constantBias) {
    double leakBias = constantBias;
    bool leakRows = false;
    for (const StabilityRow& r : rows) {
        if (r.sweep != "leak") continue;
        leakBias = leakRows ? std::max(leakBias, r.x) : r.x;
        leakRows = true;
    }
    return leakBias;
}

// The scenes any method leaked in, in the order first met: one column each.
std::vector<std::string> leakScenesOf(const std::vector<StabilitySummary>& summary) {
    std::vector<std::string> leakScenes;
    for (const StabilitySummary& s : summary) {
        for (const StabilitySummary::Leak& l : s.leaks) {
            if (std::find(leakScenes.begin(), leakScenes.end(), l.scene) == leakScenes.end()) {
                leakScenes.push_back(l.scene);
            }
        }
    }
    return leakScenes;
}

// One method and bias's row of the table.
std::string summaryRow(const StabilitySummary& s, const std::vector<std::string>& leakScenes) {
    auto opt = [](double v, int decimals) {
        return v < 0.0 ? std::string("-") : fixed(v, decimals);
    };
    std::string md = "| " + stabilityMethodName(s.method) + " | " + s.bias + " | ";
    if (!s.acneSwept) {
        md += "- | - |";
    } else {
        md += (s.acneOnsetDeg ? fixed(*s.acneOnsetDeg, 0) + " deg" : std::string("never")) + " | " +
              percent(s.acneWorstRate) + " |";
    }
    for (const std::string& sc : leakScenes) {
        const StabilitySummary::Leak* leak = nullptr;
        for (const StabilitySummary::Leak& l : s.leaks) {
            if (l.scene == sc) leak = &l;
        }
        if (leak == nullptr) {
            md += " - |";
        } else {
            md += ' ';
            md += percent(leak->rate) + ", " + fixed(leak->widthWorld, 3) + " (" +
                  fixed(leak->widthTexels, 1) + " tx) |";
        }
    }
    md += ' ';
    md += opt(s.shimmerMean, 4) + " | " + opt(s.shimmerP99, 3) + " | " + opt(s.flickerP99, 3) +
          (s.flickerShare < 0.0 ? std::string() : " (" + percent(s.flickerShare) + ")") + " | " +
          opt(s.snappedMax, 4) + " | " + opt(s.cameraP99, 3) + " |\n";
    return md;
}

// "map 256: median 0.5, p99 1.2; map 1024: ...": the aliasing sweep's pixels per texel.
std::string aliasingLine(std::span<const StabilityRow> rows) {
    std::string aliasing;
    for (const StabilityRow& r : rows) {
        if (r.sweep != "aliasing") continue;
        if (r.metric == "pixels_per_texel_median") {
            aliasing += (aliasing.empty() ? "" : "; ") + std::string("map ") +
                        std::to_string(static_cast<int>(r.x)) + ": median " + fixed(r.y, 2);
        } else if (r.metric == "pixels_per_texel_p99") {
            aliasing += ", p99 " + fixed(r.y, 2);
        }
    }
    return aliasing;
}

// One line per pcss sweep and x: "pcss-thin, pole_width_texels 2: pcss 12.0 %, pcf-gather N=5
// 0.0 %" with its headline metric (stability_pcss.h): pcss-thin missed_share_mean per method,
// pcss-overlap the penumbra pixel ratio alone and stacked, pcss-noise the roughness rotated and
// fixed, pcss-bias the false-shadow rate per bias.
std::string pcssLines(std::span<const StabilityRow> rows) {
    struct Headline {
        const char* sweep;
        const char* suffix;  // the metric, after an optional "label:"
        bool percent;
    };
    const Headline headlines[] = {{"pcss-thin", "missed_share_mean", true},
                                  {"pcss-overlap", "penumbra_pixels_ratio", false},
                                  {"pcss-noise", "penumbra_roughness", false},
                                  {"pcss-bias", "false_shadow_rate", true}};
    std::string md;
    for (const Headline& h : headlines) {
        std::string line;
        double x = std::nan("");
        for (const StabilityRow& r : rows) {
            if (r.sweep != h.sweep || !r.metric.ends_with(h.suffix)) continue;
            if (!sameX(r.x, x)) {
                if (!line.empty()) md += line + "\n";
                x = r.x;
                line = "- " + r.sweep + ", " + r.xName + " " + chartTickText(r.x) + ":";
            } else {
                line += ",";
            }
            std::string label = r.metric.substr(0, r.metric.find(':'));
            if (label == r.metric) label = stabilityMethodName({r.method, r.kernel}) + " " + r.bias;
            line += " " + label + " " + (h.percent ? percent(r.y) : fixed(r.y, 3));
        }
        if (!line.empty()) md += line + "\n";
    }
    if (md.empty()) return md;
    return "\npcss's failures (stability_pcss.h; docs/measurement.md says what each measures): "
           "thin, the share of the truth-shadowed pixels returned lit; overlap, pcss's penumbra "
           "pixels over the area truth's; noise, the pixel-to-pixel RMS of the error in the "
           "penumbra; bias, the false-shadow rate at the run's constant bias.\n\n" +
           md;
}

}  // namespace

std::string stabilityMarkdown(std::span<const StabilityRow> rows, const StabilitySetup& setup,
                              double constantBias) {
    std::string frame = std::to_string(setup.frameSize.x) + "x" + std::to_string(setup.frameSize.y);
    std::string md = "# Stability: " + setup.sceneName + ", " + frame + ", " +
                     std::to_string(setup.mapSize) + "^2 map\n\n";
    md += "Rendered on `" + setup.glRenderer + "`, measured against the ray-cast ground truth (" +
          std::to_string(setup.truthSpp) + "x" + std::to_string(setup.truthSpp) +
          " samples per pixel); " + setup.settings + ".\n\n";
    double leakBias = largestLeakBias(rows, constantBias);
    std::string leakAt = chartTickText(leakBias);
    std::vector<StabilitySummary> summary = summarizeStability(rows, leakBias);
    std::vector<std::string> leakScenes = leakScenesOf(summary);
    bool anyLeak = !leakScenes.empty();
    md += "| method | bias | acne onset | worst acne |";
    for (const std::string& sc : leakScenes) md += " leak " + sc + " @" + leakAt + " |";
    md += " shimmer mean | shimmer p99 | flicker p99 (share) | snapped max | camera p99 |\n";
    md += "|---|---|---:|---:|";
    for (size_t k = 0; k < leakScenes.size(); ++k) md += "---:|";
    md += "---:|---:|---:|---:|---:|\n";
    for (const StabilitySummary& s : summary) md += summaryRow(s, leakScenes);
    md +=
        "\nAcne onset: the highest light elevation (degrees above the ground, swept down from 90) "
        "where more than 1 % of the clean lit pixels (lit in the truth over the filter's whole "
        "footprint) come out darker than 0.99; worst acne: the largest such share. ";
    if (anyLeak) {
        md += std::string("Leak @") + leakAt +
              " (the largest constant bias swept; stability.csv and the leak chart have every "
              "bias): the share of clean umbra pixels brighter than 0.01, and how far from the "
              "caster the light reaches in connected runs of at least " +
              std::to_string(LEAK_MIN_RUN) +
              " leaking pixels (a stray pixel does not count), world units (shadow-map "
              "texels). ";
    }
    md +=
        "Shimmer: |v(t) - v(t-1)| over the receivers while the map's texel grid slides 1/32 "
        "texel a frame (the world's shadow does not move), mean and 99th percentile; flicker: the "
        "99th percentile over only the pixels that change at all (and their share of the "
        "receivers); snapped max: the largest change left with the grid snapped to whole "
        "texels; camera: the change of the error v - truth "
        "while the camera slides by sub-pixel steps.\n";
    std::string aliasing = aliasingLine(rows);
    if (!aliasing.empty()) {
        md += "\nPerspective aliasing (screen pixels per shadow-map texel, Lloyd et al.): " +
              aliasing + ".\n";
    }
    md += pcssLines(rows);
    md += bleedMarkdown(rows);
    return md;
}

}  // namespace pcf
