// stability_pcss_figures.h: the charts of pcss's sweeps (stability_pcss.h), each one population
// and one metric, drawn by stability_chart.h and listed in stability_figures.h's sweepCharts:
//   pcss-thin     the missed share against the pole's width: pcss's mean and worst grid shift,
//                 and pcf-gather 5x5 as the reference (the map holds the pole); the notes give
//                 the search's radius at the pole's foot;
//   pcss-overlap  pcss's penumbra pixels over the truth's against the plank's height, the plank
//                 alone and over the low block;
//   pcss-noise    the penumbra's pixel-to-pixel error RMS against the sun's size, the disk
//                 rotated and not;
//   pcss-bias     the false-shadow rate against poisson's radius, constant and receiver-plane.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <vector>

#include "charts/stability_chart.h"
#include "measure/stability.h"

namespace pcf {

// Each empty of panels when the rows hold none of its sweep. `subtitle`: the source line, used
// when the rows carry no setup.
LineChartSpec pcssThinChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                float minFontPx = 8.0f);
LineChartSpec pcssOverlapChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                   float minFontPx = 8.0f);
LineChartSpec pcssNoiseChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                 float minFontPx = 8.0f);
LineChartSpec pcssBiasChartSpec(std::span<const StabilityRow> rows, const std::string& subtitle,
                                float minFontPx = 8.0f);

// The chart as RGBA8 (empty when the spec has no panel).
std::vector<uint8_t> drawPcssChart(const LineChartSpec& spec, glm::ivec2 size);

template <LineChartSpec (*SPEC)(std::span<const StabilityRow>, const std::string&, float)>
std::vector<uint8_t> drawPcssSweepChart(std::span<const StabilityRow> rows, glm::ivec2 size,
                                        const std::string& subtitle, float minFontPx) {
    return drawPcssChart(SPEC(rows, subtitle, minFontPx), size);
}

}  // namespace pcf
