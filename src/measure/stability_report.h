// stability_report.h: the stability sweeps' rows (stability.h) as the files `pcfscope stability`
// writes: stability.csv for tools (one row per measured point), stability.md for people (per
// method and bias: where acne starts, how wide the leak is, how much the picture shimmers).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "measure/stability.h"

namespace pcf {

// The CSV's first line, exactly (no trailing newline).
inline constexpr std::string_view STABILITY_CSV_HEADER =
    "sweep,method,kernel,bias,x_name,x,metric,y";

// The header, then one line per row in the given order: method by its id ("-" when the row is
// not per method), kernel 0 for methods that take none, x and y with 9 significant digits.
std::string stabilityCsv(std::span<const StabilityRow> rows);

// Reads what stabilityCsv wrote (the setup rows too). Throws pcf::InputError "SOURCE:LINE:
// problem" on a wrong header, a wrong field count, an unknown method or sweep, or a number that is
// not finite.
std::vector<StabilityRow> parseStabilityCsv(std::string_view text, const std::string& source);

// One line of the summary: a method with a bias.
struct StabilitySummary {
    StabilityMethod method;
    std::string bias;
    // Acne: the highest swept elevation (degrees) where the false-shadow rate exceeds 1 %,
    // scanning down from the highest; nullopt when it never does (or acne was not swept).
    std::optional<double> acneOnsetDeg;
    bool acneSwept = false;
    double acneWorstRate = 0.0;  // the largest false-shadow rate of the sweep
    // Leak at the swept constant bias nearest summarizeStability's leakBias (per leak scene).
    struct Leak {
        std::string scene;
        double bias = 0.0;
        double rate = 0.0;
        double widthWorld = 0.0;
        double widthTexels = 0.0;
    };
    std::vector<Leak> leaks;
    // Shimmer of the light's grid slid by 1/32 texel: mean and p99 of |v(t) - v(t-1)|; the same
    // snapped to whole texels; and the camera's change of error. Negative: not swept.
    double shimmerMean = -1.0, shimmerP99 = -1.0;
    double flickerP99 = -1.0, flickerShare = -1.0;  // over the pixels that change at all
    double snappedMax = -1.0;
    double snappedMean = -1.0, snappedP99 = -1.0;
    double cameraMean = -1.0, cameraP99 = -1.0;
};

// The summary lines in the rows' order of (method, bias); the leak entries are those at the
// swept constant bias nearest leakBias.
std::vector<StabilitySummary> summarizeStability(std::span<const StabilityRow> rows,
                                                 double leakBias);

// The value of one (sweep, method, kernel, bias, metric) at x, or nullopt.
std::optional<double> stabilityValue(std::span<const StabilityRow> rows, std::string_view sweep,
                                     const StabilityMethod& method, std::string_view bias,
                                     std::string_view metric, double x);

struct StabilitySetup {
    std::string sceneName;
    std::string glRenderer;
    glm::ivec2 frameSize{0, 0};
    int mapSize = 0;
    int truthSpp = 0;
    double constantBias = 0.0;      // what every bias mode but none subtracts
    std::string cull;               // cullModeName of the shadow pass
    std::string depthFormat;        // depthFormatName
    double precisionElevation = 0;  // degrees: the precision sweep's light
    double tradeoffElevation = 0;   // degrees: the tradeoff sweep's light (0: not recorded)
    std::string settings;           // e.g. "constant bias 0.002, cull back, depth 32f"
};

// The run's settings travel in stability.csv as rows of the pseudo-sweep "setup" (method "-",
// bias "-", x_name "-", x 0), first: numbers in y ("frame_width", "frame_height", "map_size",
// "truth_spp", "constant_bias", "precision_elevation_deg", "tradeoff_elevation_deg"), words after a
// colon in the metric
// ("scene:box-on-plane", "gl_renderer:llvmpipe (LLVM 15.0.6; 256 bits)", "cull:back",
// "depth:32f"; a comma in them is written ';'), so that a chart drawn later from the CSV (a
// lesson's) states the settings it was measured with.
inline constexpr std::string_view STABILITY_SETUP_SWEEP = "setup";
std::vector<StabilityRow> stabilitySetupRows(const StabilitySetup& setup);
// The setup the rows carry (settings: "constant bias B, cull C faces in the shadow pass,
// depth D"), or nullopt when they carry none (a CSV written before the setup rows).
std::optional<StabilitySetup> stabilitySetupOf(std::span<const StabilityRow> rows);

// Title, setup paragraph, the summary table, the aliasing line, pcss's lines and the light
// bleeding paragraph (stability_bleed.h: bleedMarkdown).
std::string stabilityMarkdown(std::span<const StabilityRow> rows, const StabilitySetup& setup,
                              double constantBias);

}  // namespace pcf
