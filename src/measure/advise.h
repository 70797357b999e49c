// advise.h: the cheapest shadow settings that meet a budget, found by measuring as few of them as
// the measurements allow. No GL here: the search asks a callback to measure each setting it
// wants (advise_measure.h measures with bench's sweep on a scene; the tests with known numbers).
//
// A setting is a filter (method, N, weights), a map size and a bias (a mode and its amount). Its
// cost is the lookup pass's process CPU time (bench.h: lookupCpuMs; where a GPU timer measured,
// the pass's own time), a median with its IQR. The budget bounds four measures, each bench's or
// the stability sweeps' own: the edge band's RMSE against the truth (aliasing), the share of
// clean lit pixels darkened (acne, at the scene's own light), how far false light reaches from
// the casters in map texels (the leak width) and how far a flickering pixel jumps as the map's
// grid creeps under the world (shimmer p99).
//
// The search walks each filter ("family": method, N, weights) from the fewest texel reads up,
// and within it the map sizes from the smallest up, and at each size the biases in the order
// given (meant as less bias to more):
//   - the first setting of a family that meets the budget ends the family's walk: a larger map
//     costs no less and is not needed;
//   - a setting that breaks only the acne budget moves on to the next bias at the same size
//     (more bias, less acne); any other failure is one more bias does not mend (the leak grows
//     with the bias, the edge error and shimmer are the filter's), so the walk goes to the next
//     map size, starting the biases again from the first when the leak broke, else from the
//     bias reached;
//   - the walk stops at a size where a measure that broke the budget did not fall below its
//     value at the size before: the error falls with the map size where it falls at all, so a
//     measure that a doubled map did not lower (nearest's shimmer p99 of 1) will not meet it;
//   - a setting that cannot beat the best one met so far ends the family's walk (a larger map
//     costs no less): its whole cost spread (median -+ IQR/2) lies above the best one's, or the
//     two overlap and it reads more texels (the tie rule below picks fewer reads); when that
//     happens at the family's first size, the same method with the same weights and a larger N
//     is skipped too (the cost and the reads rise with the kernel).
// The grid is every setting the walk could reach (pairs of a bias mode and a method that cannot
// combine left out), and the result says how many were measured.
//
// Timings taken one setting at a time are at the mercy of the machine's load between them (on a
// shared machine two runs of the same pass apart in time differ by more than either's IQR), so
// the settings that meet the budget are timed again together, round-robin (AdviseRetime), and
// the choice is made on those costs.
//
// The choice is reproducible against timing noise: of the settings that meet the budget, those
// whose cost spreads overlap the cheapest median's spread cannot be ordered by the timer, so the
// one with the fewest texel reads (kernel/methods.h fetchCounts) among them is chosen (then the
// lower median), and the runner-up is the cheapest of the others; the note names both.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kernel/bias.h"
#include "kernel/methods.h"

namespace pcf {

// A filter: the method, N (0 for a method that takes none) and the weights of its taps.
struct AdviseFilter {
    int method = PCF_NEAREST;
    int kernel = 0;
    int weights = PCF_WEIGHTS_BOX;
    float sigma = 0.0f;  // gaussian weights' sigma in texels; 0 for the others
    bool operator==(const AdviseFilter&) const = default;
};

// A bias mode and its amount: the constant bias (light depth units) for every mode but none
// (0) and normal (the normal offset in texels; the constant bias stays the settings' own).
struct AdviseBias {
    BiasMode mode = BiasMode::None;
    float amount = 0.0f;
    bool operator==(const AdviseBias&) const = default;
};

// The parameter table's key of a mode's amount: "constant_bias", "normal_offset", or "" (none).
const char* adviseBiasKey(BiasMode mode);
// "none", "constant 0.002", "normal 1.5".
std::string adviseBiasName(const AdviseBias& bias);

struct AdviseSetting {
    AdviseFilter filter;
    int mapSize = 0;
    AdviseBias bias;
    bool operator==(const AdviseSetting&) const = default;
};

// "pcf-gather N=3 map 512 bias constant 0.002".
std::string adviseSettingName(const AdviseSetting& s);
// Texel reads per lookup: the method table's (fetchCounts).
int adviseTexelReads(const AdviseFilter& f);

// What the search may choose from: filters, map sizes (ascending) and biases (in walk order).
struct AdviseSpace {
    std::vector<AdviseFilter> filters;
    std::vector<int> mapSizes;
    std::vector<AdviseBias> biases;
};

// The settings of the space, pairs that cannot combine (kernel/bias.h validateBias) left out.
std::vector<AdviseSetting> adviseGrid(const AdviseSpace& space);

// The budget; an absent bound is not checked.
struct AdviseBudget {
    double maxEdgeRmse = 0.0;
    std::optional<double> maxAcne;        // share of clean lit pixels darkened, 0..1
    std::optional<double> maxLeakTexels;  // leak width, map texels
    std::optional<double> maxShimmer;     // shimmer p99 (a flickering pixel's jump), 0..1
};

enum class AdviseConstraint { Edge, Acne, Leak, Shimmer };
constexpr AdviseConstraint ALL_ADVISE_CONSTRAINTS[] = {
    AdviseConstraint::Edge, AdviseConstraint::Acne, AdviseConstraint::Leak,
    AdviseConstraint::Shimmer};
// "edge", "acne", "leak", "shimmer": the chart's labels.
const char* adviseConstraintName(AdviseConstraint c);

// One setting's measures.
struct AdviseMetrics {
    double edgeRmse = 0.0;
    double acneShare = 0.0;
    double leakTexels = 0.0;
    double shimmerP99 = 0.0;
    double costMs = 0.0;  // median
    double costIqr = 0.0;
    double value(AdviseConstraint c) const;
};

// The bound of `c` in the budget, nullopt when the budget leaves it free.
std::optional<double> adviseLimit(const AdviseBudget& budget, AdviseConstraint c);
// The constraints the metrics break, in ALL_ADVISE_CONSTRAINTS' order.
std::vector<AdviseConstraint> adviseBroken(const AdviseBudget& budget, const AdviseMetrics& m);

struct AdviseCandidate {
    AdviseSetting setting;
    AdviseMetrics metrics;
    int texelReads = 0;
    std::vector<AdviseConstraint> broken;  // empty: meets the budget
    bool retimed = false;                  // its cost is from the round-robin timing
    bool feasible() const { return broken.empty(); }
};

// Whether two cost spreads (median -+ IQR/2) overlap: the timer cannot order the two.
bool adviseSpreadsOverlap(const AdviseMetrics& a, const AdviseMetrics& b);

struct AdviseResult {
    std::vector<AdviseCandidate> measured;  // in the order measured
    size_t gridSize = 0;
    std::optional<size_t> choice;    // into measured; none when nothing met the budget
    std::optional<size_t> runnerUp;  // the cheapest other setting that met it
    // The candidates whose spreads overlap the cheapest (choice and runner-up among them) when
    // the timer could not order them; empty otherwise.
    std::vector<size_t> tied;
    std::optional<size_t> closest;  // with no choice: the one nearest to the budget
};

using AdviseMeasure = std::function<AdviseMetrics(const AdviseSetting&)>;
// Times the settings again, together, round-robin: per setting its cost's median and IQR.
struct AdviseCost {
    double ms = 0.0;
    double iqr = 0.0;
};
using AdviseRetime = std::function<std::vector<AdviseCost>(const std::vector<AdviseSetting>&)>;

// The search described at the top; with `retime`, the settings that met the budget (when more
// than one did) are timed again together before the choice. Throws std::invalid_argument for an
// empty space, map sizes not ascending or a budget bound that is negative or not a number.
AdviseResult searchAdvice(const AdviseSpace& space, const AdviseBudget& budget,
                          const AdviseMeasure& measure, const AdviseRetime& retime = {});

// The choice among measured candidates (AdviseResult's choice, runnerUp, tied, closest), on
// its own: searchAdvice ends with it.
void chooseAdvice(AdviseResult& result, const AdviseBudget& budget);

// Why the choice is what it is, one sentence: the constraint that binds, as "map 512 is needed
// for the leak budget; 256 leaks 3.1 texels", or what the cheaper settings measured broke.
std::string adviseBinding(const AdviseResult& result, const AdviseBudget& budget);
// With timing ties, the sentence that names them; else "".
std::string adviseTieNote(const AdviseResult& result);
// A broken constraint in words: "leaks 3.1 texels (budget 2)".
std::string adviseBreakText(const AdviseCandidate& c, AdviseConstraint k,
                            const AdviseBudget& budget);

}  // namespace pcf
