// trace_explain.cpp: the English of a trace. Reads the record only; see trace_explain.h.
#include "kernel/trace_explain.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "kernel/settings.h"
#include "kernel/trace_moments.h"

namespace pcf {

const char* stepTitle(TraceStepKind kind) {
    switch (kind) {
        case TraceStepKind::Project:
            return "Project the pixel into the shadow map";
        case TraceStepKind::PerTapRef:
            return "Each tap's own ref";
        case TraceStepKind::TexelPosition:
            return "Find the texel position and the sub-texel fraction";
        case TraceStepKind::ReadTexel:
            return "Read the one texel under the point";
        case TraceStepKind::CompareTexels:
            return "Compare the 2x2 texels";
        case TraceStepKind::HardwareTap:
            return "One hardware comparison tap";
        case TraceStepKind::AverageBits:
            return "Average the bits";
        case TraceStepKind::Lerp:
            return "Lerp the bits by the sub-texel fraction";
        case TraceStepKind::KernelLookups:
            return "Take the N x N bilinear lookups";
        case TraceStepKind::KernelHardwareTaps:
            return "Take the N x N hardware taps";
        case TraceStepKind::CountReads:
            return "Count the reads";
        case TraceStepKind::WeightTable:
            return "Build the weight table";
        case TraceStepKind::Gather:
            return "Gather the texels";
        case TraceStepKind::TentTaps:
            return "Place the tent's taps";
        case TraceStepKind::TentHardwareTaps:
            return "Take the hardware taps";
        case TraceStepKind::DiskPoints:
            return "Compare the disk's points";
        case TraceStepKind::BlockerSearch:
            return "Search for blockers";
        case TraceStepKind::PenumbraWidth:
            return "Estimate the penumbra's width";
        case TraceStepKind::InterpolatedCompare:
            return "Compare against the interpolated depth";
        case TraceStepKind::MomentsRead:
            return "Read the filtered moments";
        case TraceStepKind::MomentBound:
            return "Bound the lit fraction";
        case TraceStepKind::MomentReconstruct:
            return "Reconstruct the depths";
        case TraceStepKind::Precision:
            return "The texture unit's 256 steps";
        case TraceStepKind::Result:
            return "Result";
    }
    return "?";
}

const char* stepKindName(TraceStepKind kind) {
    switch (kind) {
        case TraceStepKind::Project:
            return "project";
        case TraceStepKind::PerTapRef:
            return "per_tap_ref";
        case TraceStepKind::TexelPosition:
            return "texel_position";
        case TraceStepKind::ReadTexel:
            return "read_texel";
        case TraceStepKind::CompareTexels:
            return "compare_texels";
        case TraceStepKind::HardwareTap:
            return "hardware_tap";
        case TraceStepKind::AverageBits:
            return "average_bits";
        case TraceStepKind::Lerp:
            return "lerp";
        case TraceStepKind::KernelLookups:
            return "kernel_lookups";
        case TraceStepKind::KernelHardwareTaps:
            return "kernel_hardware_taps";
        case TraceStepKind::CountReads:
            return "count_reads";
        case TraceStepKind::WeightTable:
            return "weight_table";
        case TraceStepKind::Gather:
            return "gather";
        case TraceStepKind::TentTaps:
            return "tent_taps";
        case TraceStepKind::TentHardwareTaps:
            return "tent_hardware_taps";
        case TraceStepKind::DiskPoints:
            return "disk_points";
        case TraceStepKind::BlockerSearch:
            return "blocker_search";
        case TraceStepKind::PenumbraWidth:
            return "penumbra_width";
        case TraceStepKind::InterpolatedCompare:
            return "interpolated_compare";
        case TraceStepKind::MomentsRead:
            return "moments_read";
        case TraceStepKind::MomentBound:
            return "moment_bound";
        case TraceStepKind::MomentReconstruct:
            return "moment_reconstruct";
        case TraceStepKind::Precision:
            return "precision";
        case TraceStepKind::Result:
            return "result";
    }
    return "?";
}

std::string formatNumber(float value) {
    if (value == 0.0f) return "0";  // also folds -0
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4f", static_cast<double>(value));
    std::string s = buf;
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    if (s == "-0") s = "0";
    return s;
}

std::string formatPair(vec2 value) {
    return "(" + formatNumber(value.x) + ", " + formatNumber(value.y) + ")";
}

std::string formatBit(float lit) {
    if (lit == 0.0f || lit == 1.0f) return lit >= 0.5f ? "1" : "0";
    return formatNumber(lit);
}

namespace {

using K = TraceStepKind;
using Steps = std::vector<TraceStep>;

std::string num(float v) { return formatNumber(v); }
std::string pair(vec2 v) { return formatPair(v); }
std::string pair(ivec2 v) { return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ")"; }
std::string bit(float lit) { return formatBit(lit); }

// The taps a fetch instruction read, in read order.
std::vector<TapRecord> tapsOf(const Trace& tr, int fetch) {
    std::vector<TapRecord> out;
    for (const TapRecord& t : tr.taps) {
        if (t.fetch == fetch) out.push_back(t);
    }
    return out;
}

std::string tapLine(const TapRecord& t) {
    if (t.lit != 0.0f && t.lit != 1.0f) {  // the soft comparison's fraction
        return "texel " + pair(t.texel) + ": depth " + num(t.depth) + ", ref " + num(t.ref) +
               " -> soft " + num(t.lit);
    }
    std::string cmp = t.lit >= 0.5f ? " <= " : " > ";
    return "texel " + pair(t.texel) + (t.clamped ? " (clamped to the edge)" : "") + ": depth " +
           num(t.depth) + ", ref " + num(t.ref) + cmp + num(t.depth) + " -> " +
           (t.lit >= 0.5f ? "lit (1)" : "shadowed (0)");
}

// The value one fetch instruction returned, rebuilt from its taps: sum(w * lit) / sum(w).
// For a bilinear lookup or a hardware tap that is the lerped result.
float fetchValue(const std::vector<TapRecord>& taps, float fetchWeight) {
    float sum = 0.0f;
    for (const TapRecord& t : taps) sum += t.weight * t.lit;
    return fetchWeight > 0.0f ? sum / fetchWeight : 0.0f;
}

// "weighted a_i * a_j, binomial: a = 0.25 0.5 0.25" for the weighted kernels.
std::string weightsSentence(const PcfParams& prm) {
    std::ostringstream s;
    s << "lookup (i, j) weighted a_i * a_j, " << weightsName(prm.weights);
    if (prm.weights == PCF_WEIGHTS_GAUSSIAN) s << " (sigma " << num(prm.sigma) << " texels)";
    s << ": a =";
    for (int k = 0; k < prm.kernel; ++k) {
        s << " " << num(pcfAxisWeight(k, prm.kernel, prm.weights, prm.sigma));
    }
    return s.str();
}

void addStep(Steps& out, K kind, std::string text) {
    out.push_back({kind, stepTitle(kind), std::move(text)});
}

// The parameter table's rows that act under the lookup's bias mode, with this lookup's values:
// "constant_bias = 0.002 light depth units (--constant-bias), rpdb_max = 100 ..." (none named by
// hand here; the kernel's PcfBias is made of the same values, Trace::lookup).
std::string modeSettings(const Trace& tr) {
    ShadowSettings set;
    static_cast<BiasSettings&>(set) = tr.bias;
    std::string out;
    for (const ParamInfo& p : allParams()) {
        if (!paramActsUnder(p, tr.bias.bias)) continue;
        out += (out.empty() ? "" : ", ") + std::string(p.key) + " = " + settingText(p, set) +
               (p.unit.empty() ? "" : " ") + std::string(p.unit) + " (" + settingFlag(p.key) + ")";
    }
    return out;
}

// What the bias mode did to this lookup's ref, in words: the mode's formula in the table's keys
// (kernel/bias.h, biasFormula), the ref it gave, and every setting it read with its value.
std::string biasSentence(const Trace& tr) {
    std::ostringstream s;
    int mode = tr.bias.modeId();
    if (tr.ref == tr.z && (mode == PCF_BIAS_NONE || mode == PCF_BIAS_CONSTANT)) {
        s << "No bias: the comparison depth is ref = z = " << num(tr.ref) << ".";
        if (mode == PCF_BIAS_NONE) return s.str();
    } else {
        s << "Bias " << biasName(mode) << ": " << biasFormula(mode)
          << ". Here ref = " << num(tr.ref) << " (z " << (tr.ref < tr.z ? "- " : "+ ")
          << num(std::fabs(tr.z - tr.ref)) << ").";
    }
    s << " Settings: " << modeSettings(tr) << ".";
    if (mode == PCF_BIAS_RECEIVER_PLANE) {
        s << " dz/duv = " << pair(tr.dzduv)
          << " is the receiver's slope in the map (the renderer derives it from screen-space "
             "derivatives); the taps use dz/duv = "
          << pair(tr.lookup.bias.dzduv)
          << (tr.lookup.bias.dzduv == tr.dzduv ? ", as given." : ", clamped.");
    }
    return s.str();
}

void stepProject(const Trace& tr, Steps& out) {
    std::ostringstream s;
    s << "The receiver point under this pixel projects to uv = " << pair(tr.uv) << " in the "
      << tr.map.size.x << " x " << tr.map.size.y << " shadow map, at light depth z = " << num(tr.z)
      << ". " << biasSentence(tr);
    addStep(out, K::Project, s.str());
}

// Receiver-plane bias: every tap's own ref, how far the plane moved it from the lookup's, and
// which bits that changed. Gathers and hardware taps compare four texels against one ref: the
// plane's depth at their own centre.
void stepPerTapRef(const Trace& tr, Steps& out) {
    if (tr.bias.bias != BiasMode::ReceiverPlane) return;
    int m = tr.params.method;
    std::ostringstream s;
    switch (methodInfo(m).reads) {
        case MethodReads::Gathers:
            s << "A comparison gather compares its four texels against one ref, so the plane is "
                 "applied per gather, at the centre of its 2x2 block:";
            break;
        case MethodReads::HwTaps:
            s << "The texture unit compares a hardware tap's four texels against one ref, so the "
                 "plane is applied per tap, at the tap's own uv:";
            break;
        case MethodReads::Texels:
            s << "Each texel is compared against the plane's depth at its own centre:";
            break;
    }
    std::map<std::pair<int, int>, bool> shown;
    for (const TapRecord& t : tr.taps) {
        auto key = std::make_pair(t.texel.x, t.texel.y);
        if (shown.count(key) != 0 && !methodInfo(m).overlappingLookups) continue;
        shown[key] = true;
        float alone = pcfCompare(t.depth, tr.ref);
        s << "\n  texel " << pair(t.texel) << ": ref " << num(t.ref) << " ("
          << (t.ref >= tr.ref ? "+" : "-") << num(std::fabs(t.ref - tr.ref)) << "), depth "
          << num(t.depth) << " -> " << bit(t.lit);
        if (alone != t.lit) s << "  (one ref for all: " << bit(alone) << ")";
        if (shown.size() >= 24) {
            s << "\n  ...";
            break;
        }
    }
    s << "\n"
      << tapsChangedByPlane(tr) << " of " << tr.taps.size()
      << " comparisons come out otherwise than with one ref for every tap.";
    addStep(out, K::PerTapRef, s.str());
}

void explainInterpolated(const Trace& tr, Steps& out) {
    std::ostringstream s;
    float depth = 0.0f;
    s << "The four texels at base " << pair(tr.pos.base) << " are not compared one by one; their "
      << "depths are lerped by frac " << pair(tr.pos.frac) << ":";
    for (const TapRecord& t : tr.taps) {
        s << "\n  texel " << pair(t.texel) << ": depth " << num(t.depth) << " * " << num(t.weight);
        depth += t.weight * t.depth;
    }
    s << "\ninterpolated depth = " << num(depth) << "; ref " << num(tr.ref)
      << (tr.visibility >= 0.5f ? " <= " : " > ") << num(depth) << " -> "
      << (tr.visibility >= 0.5f ? "lit (1)" : "shadowed (0)") << ".";
    addStep(out, K::InterpolatedCompare, s.str());
    addStep(out, K::Result,
            "visibility = " + num(tr.visibility) +
                ". One comparison, one bit: the fraction went into the depth, so nothing is "
                "left to soften the edge. This is why interpolation cannot be PCF.");
}

void stepTexelPosition(const Trace& tr, Steps& out) {
    std::ostringstream s;
    s << "Texel centres sit at half-integers, so the lookup's texel position is p = uv * size - "
         "0.5 = ("
      << num(tr.uv.x) << " * " << tr.map.size.x << " - 0.5, " << num(tr.uv.y) << " * "
      << tr.map.size.y << " - 0.5) = " << pair(tr.pos.p)
      << ". base = floor(p) = " << pair(tr.pos.base)
      << " is the lower corner of the 2x2 texels around the point; frac = p - "
         "base = "
      << pair(tr.pos.frac) << " is where the point sits between their centres.";
    addStep(out, K::TexelPosition, s.str());
}

void stepTapList(const Trace& tr, Steps& out, K kind, const std::string& intro) {
    std::ostringstream s;
    s << intro;
    for (const TapRecord& t : tr.taps) s << "\n  " << tapLine(t);
    addStep(out, kind, s.str());
}

void explainNearest(const Trace& tr, Steps& out) {
    const TapRecord& t = tr.taps.front();
    PCF_PRECISE vec2 p = tr.uv * vec2(tr.map.size);
    std::ostringstream s;
    s << "No filtering: the point falls in texel floor(uv * size) = floor" << pair(p) << " = "
      << pair(t.texel) << ". One comparison decides: " << tapLine(t) << ".";
    addStep(out, K::ReadTexel, s.str());
    addStep(out, K::Result,
            "visibility = " + num(tr.visibility) +
                ". Every pixel that lands in the same texel gets the same bit, so the shadow "
                "edge follows the texel grid: hard and blocky.");
}

void explainBox(const Trace& tr, Steps& out) {
    stepTapList(tr, out, K::CompareTexels,
                "The four texels at base " + pair(tr.pos.base) + " are each compared with ref:");
    std::ostringstream s;
    s << "visibility = (";
    for (size_t k = 0; k < tr.taps.size(); ++k) s << (k ? " + " : "") << bit(tr.taps[k].lit);
    s << ") / 4 = " << num(tr.visibility) << ". The fraction " << pair(tr.pos.frac)
      << " is ignored: four bits can only average to 0, .25, .5, .75 or 1, so the penumbra "
         "comes in five flat steps.";
    addStep(out, K::AverageBits, s.str());
}

void explainBilinear(const Trace& tr, Steps& out, bool hardware) {
    std::string intro =
        hardware
            ? "One texture instruction on the comparison sampler: the texture unit reads the 2x2 "
              "texels at base " +
                  pair(tr.pos.base) +
                  ", compares each with ref and lerps the bits. "
                  "pcfscope models it exactly as bilinear2x2 (real GPUs round the lerp weights, "
                  "often to "
                  "8 bits). The four comparisons:"
            : "The four texels at base " + pair(tr.pos.base) + " are each compared with ref:";
    stepTapList(tr, out, hardware ? K::HardwareTap : K::CompareTexels, intro);
    const std::vector<TapRecord>& t = tr.taps;
    // hw8: the texture unit lerps by its own rounded fraction (see the 256-steps step).
    bool hw8 = hardware && tr.params.precision == PCF_PRECISION_HW8;
    float fx = hw8 ? tr.fracHw8.x : tr.pos.frac.x;
    float fy = hw8 ? tr.fracHw8.y : tr.pos.frac.y;
    float row0 = glm::mix(t[0].lit, t[1].lit, fx);
    float row1 = glm::mix(t[2].lit, t[3].lit, fx);
    std::ostringstream s;
    s << "Along x by fx = " << num(fx) << ": row " << t[0].texel.y << ": lerp(" << bit(t[0].lit)
      << ", " << bit(t[1].lit) << ", " << num(fx) << ") = " << num(row0) << "; row " << t[2].texel.y
      << ": lerp(" << bit(t[2].lit) << ", " << bit(t[3].lit) << ", " << num(fx)
      << ") = " << num(row1) << ".\nAlong y by fy = " << num(fy) << ": lerp(" << num(row0) << ", "
      << num(row1) << ", " << num(fy) << ") = " << num(tr.visibility) << ".";
    addStep(out, K::Lerp, s.str());
    std::ostringstream w;
    w << "The same as weighting each bit by the area opposite it: visibility = ";
    for (size_t k = 0; k < 4; ++k) {
        w << (k ? " + " : "") << num(t[k].weight) << " * " << bit(t[k].lit);
    }
    w << " = " << num(tr.visibility)
      << ". The result now slides smoothly with the point's position inside the texel.";
    addStep(out, K::Result, w.str());
}

// The merged weights as rows of numbers, right-aligned in columns as wide as the widest number
// (and the row numbers as wide as the widest), so the table reads as a grid in a fixed-width font.
// A cell of a weight table: five characters at most, so that an 8-column table (tent 7x7) keeps
// each row on one line of a projector's inspector: four significant digits and three decimals at
// most, fixed for the magnitude ("0.196", "4.140", "20.96", "220.2"), and a weight below 0.0005 as
// its first digit and power of ten ("7e-05"): a weight that counts never reads 0.
std::string tableNumber(float v) {
    char buf[32];
    if (v > 0.0f && v < 0.0005f) {
        std::snprintf(buf, sizeof buf, "%.0e", static_cast<double>(v));
        return buf;
    }
    int decimals = v < 10.0f ? 3 : v < 100.0f ? 2 : v < 1000.0f ? 1 : 0;
    std::snprintf(buf, sizeof buf, "%.*f", decimals, static_cast<double>(v));
    return v == 0.0f ? "0" : buf;
}

// The merged weights as a table: a header of the texel columns i, then one line per texel row
// j, each cell right-aligned in its column.
std::string weightTable(const Trace& tr, float scale) {
    const WeightGrid& g = tr.weights;
    std::vector<std::string> cells;
    size_t width = 0;
    for (int i = 0; i < g.size.x; ++i) {
        width = std::max(width, std::to_string(g.origin.x + i).size());
    }
    for (float v : g.values) {
        cells.push_back(tableNumber(v * scale));
        width = std::max(width, cells.back().size());
    }
    const std::string corner = "j\\i";
    size_t rowWidth = std::max(corner.size(), std::to_string(g.origin.y + g.size.y - 1).size());
    auto pad = [](const std::string& s, size_t w) { return std::string(w - s.size(), ' ') + s; };
    std::ostringstream s;
    s << "\n  " << pad(corner, rowWidth);
    for (int i = 0; i < g.size.x; ++i) s << " " << pad(std::to_string(g.origin.x + i), width);
    for (int j = 0; j < g.size.y; ++j) {
        s << "\n  " << pad(std::to_string(g.origin.y + j), rowWidth);
        for (int i = 0; i < g.size.x; ++i) {
            s << " " << pad(cells[static_cast<size_t>(j) * g.size.x + i], width);
        }
    }
    return s.str();
}

void stepSum(const Trace& tr, Steps& out) {
    // Merge duplicates: one term per distinct texel, in the order first read.
    std::map<std::pair<int, int>, size_t> index;
    std::vector<std::pair<TapRecord, float>> terms;  // first tap, merged weight
    for (const TapRecord& t : tr.taps) {
        auto key = std::make_pair(t.texel.x, t.texel.y);
        auto it = index.find(key);
        if (it == index.end()) {
            index[key] = terms.size();
            terms.push_back({t, t.weight});
        } else {
            terms[it->second].second += t.weight;
        }
    }
    std::ostringstream s;
    s << "visibility = sum(weight * bit) =";
    bool first = true;
    for (const auto& [t, w] : terms) {
        if (w == 0.0f) continue;
        s << (first ? " " : " + ") << num(w) << "*" << bit(t.lit);
        first = false;
    }
    s << " = " << num(tr.visibility) << "  (1 = fully lit, 0 = fully shadowed).";
    addStep(out, K::Result, s.str());
}

void explainKernelLoop(const Trace& tr, Steps& out, bool hardware) {
    int n = tr.params.kernel;
    std::ostringstream head;
    head << n << " x " << n << (hardware ? " hardware comparison taps" : " bilinear lookups")
         << " at texel offsets k - (N-1)/2 = " << num(pcfKernelOffset(0, n)) << " .. "
         << num(pcfKernelOffset(n - 1, n)) << " around the point, ";
    if (tr.params.weights == PCF_WEIGHTS_BOX) {
        head << "each weighted 1/" << n * n << ":";
    } else {
        head << weightsSentence(tr.params) << ":";
    }
    std::ostringstream sum;
    for (size_t f = 0; f < tr.fetches.size(); ++f) {
        const FetchRecord& fr = tr.fetches[f];
        std::vector<TapRecord> taps = tapsOf(tr, static_cast<int>(f));
        int i = static_cast<int>(f) % n;
        int j = static_cast<int>(f) / n;
        float v = fetchValue(taps, fr.weight);
        head << "\n  offset " << pair(vec2(pcfKernelOffset(i, n), pcfKernelOffset(j, n)))
             << ": base " << pair(taps.front().texel) << ", bits " << bit(taps[0].lit)
             << bit(taps[1].lit) << bit(taps[2].lit) << bit(taps[3].lit) << " -> " << num(v);
        sum << (f ? " + " : "") << num(v);
    }
    addStep(out, hardware ? K::KernelHardwareTaps : K::KernelLookups, head.str());
    std::ostringstream reads;
    int distinct = tr.weights.size.x * tr.weights.size.y;
    reads << "The loop read " << tr.counts.texels << " texels"
          << (hardware ? " (4 per tap, inside the texture unit)" : "") << ", but only " << distinct
          << " are distinct: neighbouring lookups share texels. Merged, each texel's weight "
             "(times "
          << n * n << ") is:" << weightTable(tr, static_cast<float>(n * n))
          << "\npcf-gather reads each of them once and gives the same result.";
    addStep(out, K::CountReads, reads.str());
    if (tr.params.weights != PCF_WEIGHTS_BOX) {
        stepSum(tr, out);
        return;
    }
    std::ostringstream avg;
    avg << "visibility = (" << sum.str() << ") / " << n * n << " = " << num(tr.visibility)
        << "  (1 = fully lit, 0 = fully shadowed).";
    addStep(out, K::Result, avg.str());
}

void explainGather(const Trace& tr, Steps& out) {
    int n = tr.params.kernel;
    const PcfFootprint& fp = tr.footprint;  // as the kernel computed it (traceLookup)
    std::ostringstream s;
    s << "All " << n * n
      << " lookups of pcf-naive share one fraction. Footprint position q = uv "
         "* size - 0.5 - (N-1)/2 = "
      << pair(vec2(fp.origin) + fp.frac) << ", origin = floor(q) = " << pair(fp.origin)
      << ", g = q - origin = " << pair(fp.frac) << ". ";
    if (tr.params.weights == PCF_WEIGHTS_BOX) {
        s << "Per axis the " << n + 1 << " texels weigh (1-g, 1, ..., 1, g) / " << n
          << ", so the table (times " << n * n << ") is:" << weightTable(tr, float(n * n));
    } else {
        s << "The lookups are " << weightsSentence(tr.params)
          << "; footprint texel m weighs a_m (1-g) + a_(m-1) g per axis, so the table is:"
          << weightTable(tr, 1.0f);
    }
    addStep(out, K::WeightTable, s.str());
    std::ostringstream g;
    g << tr.counts.gathers << " comparison gathers cover the " << n + 1 << " x " << n + 1
      << " texels, 2x2 each; a gather returns its bits in GL's order x = (0,1), y = (1,1), "
         "z = (1,0), w = (0,0):";
    for (size_t f = 0; f < tr.fetches.size(); ++f) {
        std::vector<TapRecord> taps = tapsOf(tr, static_cast<int>(f));
        g << "\n  gather at texel " << pair(taps.back().texel) << ": bits";
        for (const TapRecord& t : taps) g << " " << bit(t.lit);
        g << ", weights";
        for (const TapRecord& t : taps) g << " " << num(t.weight);
    }
    addStep(out, K::Gather, g.str());
    stepSum(tr, out);
}

void explainTent(const Trace& tr, Steps& out) {
    int n = tr.params.kernel;
    const PcfFootprint& tb = tr.footprint;  // as the kernel computed it (traceLookup)
    PcfTentAxis ax = pcfTentAxis(tb.frac.x, n);
    PcfTentAxis ay = pcfTentAxis(tb.frac.y, n);
    float d = pcfTentNorm(n);
    std::ostringstream s;
    s << "q = uv * size = " << pair(vec2(tb.origin) + tb.frac - vec2(0.5f))
      << ", b = floor(q + 0.5) = " << pair(tb.origin)
      << ", (s, t) = q + 0.5 - b = " << pair(tb.frac) << ".\n  x weights:";
    for (int i = 0; i < ax.taps; ++i) s << " " << num(ax.w[i]);
    s << "  offsets:";
    for (int i = 0; i < ax.taps; ++i) s << " " << num(ax.o[i]);
    s << "\n  y weights:";
    for (int i = 0; i < ay.taps; ++i) s << " " << num(ay.w[i]);
    s << "  offsets:";
    for (int i = 0; i < ay.taps; ++i) s << " " << num(ay.o[i]);
    s << "\nEach tap sits between two texels at the spot where the texture unit's lerp gives "
         "them the ratio of weights the tent wants; tap (i, j) weighs w_i * w_j / "
      << num(d) << ".";
    addStep(out, K::TentTaps, s.str());
    std::ostringstream t;
    t << ax.taps * ay.taps << " hardware comparison taps:";
    std::ostringstream sum;
    for (size_t f = 0; f < tr.fetches.size(); ++f) {
        const FetchRecord& fr = tr.fetches[f];
        float v = fetchValue(tapsOf(tr, static_cast<int>(f)), fr.weight);
        t << "\n  uv " << pair(fr.uv) << ": value " << num(v) << ", weight " << num(fr.weight);
        sum << (f ? " + " : "") << num(fr.weight) << "*" << num(v);
    }
    addStep(out, K::TentHardwareTaps, t.str());
    std::ostringstream w;
    w << "Merged, the taps weigh the texels (times " << num(d) << "):" << weightTable(tr, d)
      << "\nvisibility = " << sum.str() << " = " << num(tr.visibility) << ".";
    addStep(out, K::Result, w.str());
}

void explainPoisson(const Trace& tr, Steps& out) {
    std::ostringstream s;
    float angle = std::atan2(tr.params.rotation.y, tr.params.rotation.x) * 57.2957795f;
    s << "16 points of a fixed Poisson disk, radius " << num(tr.params.radius)
      << " texels, rotated by " << num(angle)
      << " degrees; each point reads the nearest texel (no lerp):";
    int lit = 0;
    for (size_t k = 0; k < tr.taps.size(); ++k) {
        const TapRecord& t = tr.taps[k];
        vec2 off = pcfPoissonOffset(static_cast<int>(k), tr.params.radius, tr.params.rotation);
        s << "\n  offset " << pair(off) << " -> " << tapLine(t);
        if (t.lit >= 0.5f) ++lit;
    }
    addStep(out, K::DiskPoints, s.str());
    addStep(out, K::Result,
            "visibility = " + std::to_string(lit) + " lit / 16 = " + num(tr.visibility) +
                ". With 16 samples the result has 17 levels; rotating the disk per pixel trades "
                "banding for noise.");
}

// The distances pcss compares (pcf_disk.h): a spot's perspective map stores depth, not the
// distance along the light's axis, so its receiver and blockers are converted first; a
// directional light's map depth is the distance already.
struct PcssDistances {
    float nearD = 0.0f, farD = 0.0f;  // the spot's near and far planes (0: directional)
    bool spot = false;
    float receiver = 0.0f;  // d_receiver: the ref as a distance
    float of(float depth) const { return spot ? pcfPcssLinearDepth(depth, nearD, farD) : depth; }
};

PcssDistances pcssDistances(const Trace& tr) {
    PcssDistances d;
    d.nearD = tr.params.depthNear;
    d.farD = tr.params.depthFar;
    d.spot = d.nearD > 0.0f;
    d.receiver = d.of(tr.ref);
    return d;
}

// Why the search disk has its radius: the farthest a blocker can be and still hide some of the
// light (Fernando 2005), for a spot's perspective map or a directional light's.
void pcssSearchReach(const Trace& tr, const PcssDistances& d, std::ostringstream& s) {
    if (d.spot) {
        s << "The spot light has a size: S = " << num(tr.params.penumbraScale)
          << " (its width times texels per scene unit at distance 1). The map's depth is not "
             "the distance: d = n * f / (f - depth * (f - n)) with near n = "
          << num(d.nearD) << ", far f = " << num(d.farD) << ", so the receiver's ref "
          << num(tr.ref) << " lies at d_receiver = " << num(d.receiver)
          << ". A blocker further than S / 2 * (d_receiver - n) / (d_receiver * n) = "
          << num(tr.params.penumbraScale) << " / 2 * (" << num(d.receiver) << " - " << num(d.nearD)
          << ") / (" << num(d.receiver) << " * " << num(d.nearD)
          << ") texels away cannot hide any of the light";
    } else {
        s << "The light has a size: S = " << num(tr.params.penumbraScale)
          << " texels of penumbra per unit of light depth between receiver and blocker. A "
             "blocker further than ref * S / 2 = "
          << num(tr.ref) << " * " << num(tr.params.penumbraScale)
          << " / 2 texels away cannot hide any of the light";
    }
}

// The blocker search's taps, one line each (the first `searchTaps` reads of the trace). Returns
// the sum of the blockers' distances, in read order as the kernel adds them.
float pcssSearchTaps(const Trace& tr, const PcssDistances& d, size_t searchTaps,
                     std::ostringstream& s) {
    const PcfPcssEstimate& e = tr.pcss;
    float angle = std::atan2(tr.params.rotation.y, tr.params.rotation.x) * 57.2957795f;
    s << ", so 16 points of the Poisson disk, radius " << num(e.searchRadius)
      << " texels (kept within [" << num(PCF_PCSS_MIN_RADIUS) << ", " << num(PCF_PCSS_MAX_RADIUS)
      << "]), rotated by " << num(angle)
      << " degrees, read the nearest texel; a depth below ref is a blocker:";
    float sum = 0.0f;
    for (size_t k = 0; k < searchTaps; ++k) {
        const TapRecord& t = tr.taps[k];
        vec2 off = pcfPoissonOffset(static_cast<int>(k), e.searchRadius, tr.params.rotation);
        bool blocks = t.lit < 0.5f;
        if (blocks) sum += d.of(t.depth);
        s << "\n  offset " << pair(off) << " -> texel " << pair(t.texel) << " depth "
          << num(t.depth) << (blocks ? " < " : " >= ") << num(t.ref)
          << (blocks ? ": blocker" : ": not a blocker");
    }
    return sum;
}

// The penumbra's width from the mean blocker by similar triangles (Fernando 2005), and the
// filter disk's radius it gives.
void stepPcssPenumbra(const Trace& tr, const PcssDistances& d, Steps& out) {
    const PcfPcssEstimate& e = tr.pcss;
    std::ostringstream w;
    if (d.spot) {
        w << "Similar triangles (Fernando 2005), the light at the spot: the penumbra is "
             "S * (d_receiver - d_blocker) / (d_blocker * d_receiver) = "
          << num(tr.params.penumbraScale) << " * (" << num(d.receiver) << " - "
          << num(e.blockerDepth) << ") / (" << num(e.blockerDepth) << " * " << num(d.receiver)
          << ")";
    } else {
        w << "Similar triangles (Fernando 2005), the light at infinity: the penumbra is "
             "(ref - d_blocker) * S = ("
          << num(tr.ref) << " - " << num(e.blockerDepth) << ") * " << num(tr.params.penumbraScale);
    }
    w << " = " << num(e.penumbra) << " texels wide; the filter disk's radius is half that, "
      << num(e.filterRadius) << " texels (kept within [" << num(PCF_PCSS_MIN_RADIUS) << ", "
      << num(PCF_PCSS_MAX_RADIUS) << "]). Near its blocker a receiver gets a narrow, hard "
      << "penumbra; far from it a wide, soft one.";
    addStep(out, K::PenumbraWidth, w.str());
}

// The filter disk's taps (the reads after the search's) and the visibility they count.
void stepPcssFilter(const Trace& tr, size_t searchTaps, Steps& out) {
    const PcfPcssEstimate& e = tr.pcss;
    std::ostringstream f;
    f << "16 points of the same disk, radius " << num(e.filterRadius)
      << " texels, each compared with the nearest texel:";
    int lit = 0;
    for (size_t k = searchTaps; k < tr.taps.size(); ++k) {
        const TapRecord& t = tr.taps[k];
        vec2 off =
            pcfPoissonOffset(static_cast<int>(k - searchTaps), e.filterRadius, tr.params.rotation);
        f << "\n  offset " << pair(off) << " -> " << tapLine(t);
        if (t.lit >= 0.5f) ++lit;
    }
    addStep(out, K::DiskPoints, f.str());
    addStep(out, K::Result,
            "visibility = " + std::to_string(lit) + " lit / 16 = " + num(tr.visibility) + ".");
}

// pcss (Fernando 2005, see pcf_disk.h): the search disk's taps, the penumbra from the mean
// blocker depth, then the filter disk's taps; every number is the kernel's (tr.pcss, tr.taps).
void explainPcss(const Trace& tr, Steps& out) {
    const PcfPcssEstimate& e = tr.pcss;
    PcssDistances d = pcssDistances(tr);
    std::ostringstream s;
    pcssSearchReach(tr, d, s);
    size_t searchTaps = std::min(tr.taps.size(), static_cast<size_t>(PCF_PCSS_TAPS));
    float sum = pcssSearchTaps(tr, d, searchTaps, s);
    if (e.blockers == 0) {
        s << "\nNo blocker: the point sees the whole light.";
        addStep(out, K::BlockerSearch, s.str());
        addStep(out, K::Result, "visibility = 1, without filtering (no blocker, no penumbra).");
        return;
    }
    s << "\n"
      << e.blockers
      << (d.spot ? " blockers, mean distance d_blocker = "
                 : " blockers, mean depth "
                   "d_blocker = ")
      << num(sum) << " / " << e.blockers << " = " << num(e.blockerDepth) << ".";
    addStep(out, K::BlockerSearch, s.str());
    stepPcssPenumbra(tr, d, out);
    stepPcssFilter(tr, searchTaps, out);
}

// Issue 10: what an 8-bit texture unit does to this lookup.
void stepPrecision(const Trace& tr, Steps& out) {
    std::ostringstream s;
    s << "A real texture unit keeps the texel position with 8 fractional bits: it rounds p * 256 "
         "to the nearest integer before taking floor and frac. The float fraction "
      << pair(tr.pos.frac) << " becomes " << pair(tr.fracHw8)
      << " (steps of 1/256). Visibility with the float position: " << num(tr.visibilityExact)
      << "; with 8 bits: " << num(tr.visibilityHw8) << " (difference "
      << num(tr.visibilityHw8 - tr.visibilityExact) << ").";
    addStep(out, K::Precision, s.str());
}

}  // namespace

std::vector<TraceStep> explainTrace(const Trace& tr) {
    Steps out;
    stepProject(tr, out);
    stepPerTapRef(tr, out);
    if (tr.bias.bias == BiasMode::Interpolated && methodInfo(tr.params.method).hard) {
        stepTexelPosition(tr, out);
        explainInterpolated(tr, out);
        return out;
    }
    switch (methodOf(tr.params.method)) {
        case Method::Nearest:
            explainNearest(tr, out);
            break;
        case Method::Box2x2:
            stepTexelPosition(tr, out);
            explainBox(tr, out);
            break;
        case Method::Bilinear2x2:
        case Method::Hw2x2:
            stepTexelPosition(tr, out);
            explainBilinear(tr, out, methodInfo(tr.params.method).reads == MethodReads::HwTaps);
            break;
        case Method::Naive:
        case Method::Hw:
            stepTexelPosition(tr, out);
            explainKernelLoop(tr, out, methodInfo(tr.params.method).reads == MethodReads::HwTaps);
            break;
        case Method::Gather:
            explainGather(tr, out);
            break;
        case Method::Tent:
            explainTent(tr, out);
            break;
        case Method::Poisson:
            explainPoisson(tr, out);
            break;
        case Method::Pcss:
            explainPcss(tr, out);
            break;
        case Method::Vsm:
        case Method::Evsm2:
        case Method::Evsm4:
        case Method::Msm:
        case Method::MsmHausdorff:
            stepTexelPosition(tr, out);
            for (auto& [kind, text] : momentSteps(tr)) addStep(out, kind, std::move(text));
            break;
    }
    if (tr.usesTextureUnit && tr.params.precision == PCF_PRECISION_HW8) stepPrecision(tr, out);
    return out;
}

}  // namespace pcf
