// The bleed sweep (stability_bleed.h): stacked-cards over the gap and the methods' settings,
// leak in the lower card's clean umbra and the signed error in the truth's penumbra.
#include "measure/stability_bleed.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "kernel/methods.h"
#include "kernel/settings.h"
#include "measure/error_metrics.h"
#include "measure/failure_measures.h"
#include "measure/ground_truth.h"
#include "measure/stability_pcss.h"
#include "render/scene_renderer.h"
#include "scene/light.h"
#include "scene/presets.h"
#include "scene/raycast.h"

namespace pcf {

namespace {

// The settings stability_bleed.csv has a column for: the column's name and the setting's key.
struct BleedColumn {
    std::string_view column;
    std::string_view key;
};
constexpr BleedColumn BLEED_COLUMNS[] = {{"lbr", "lbr"},
                                         {"exponents", "evsm_exponents"},
                                         {"moment_bias", "moment_bias"},
                                         {"moment_format", "moment_format"}};

constexpr std::string_view LEAK_MEAN = "leak_mean";
constexpr std::string_view LEAK_P99 = "leak_p99";
constexpr std::string_view PENUMBRA_ERROR = "penumbra_error";

int objectIndex(const Scene& scene, std::string_view name) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (scene.objects[i].name == name) return static_cast<int>(i);
    }
    throw std::logic_error("scene has no object " + std::string(name));
}

struct BleedMeasure {
    double leakMean = 0.0, leakP99 = 0.0, penumbraError = 0.0;
    int umbraPixels = 0, penumbraPixels = 0;
};

BleedMeasure measureBleed(const std::vector<float>& vis, const GroundTruth& truth,
                          const ErrorRegions& regions, const std::vector<uint8_t>& umbra) {
    BleedMeasure m;
    std::vector<float> leaks;
    double penumbraSum = 0.0;
    for (size_t k = 0; k < vis.size() && k < truth.visibility.size(); ++k) {
        if (umbra[k]) leaks.push_back(vis[k]);
        float t = truth.visibility[k];
        if (regions.compared[k] && t > PCSS_PENUMBRA_LO && t < PCSS_PENUMBRA_HI) {
            penumbraSum += static_cast<double>(vis[k]) - t;
            ++m.penumbraPixels;
        }
    }
    m.umbraPixels = static_cast<int>(leaks.size());
    double sum = 0.0;
    for (float v : leaks) sum += v;
    m.leakMean = leaks.empty() ? 0.0 : sum / static_cast<double>(leaks.size());
    m.leakP99 = quantileOf(leaks, 0.99);
    m.penumbraError = m.penumbraPixels ? penumbraSum / m.penumbraPixels : 0.0;
    return m;
}

// One point of a method: its settings, and the metric's prefix naming the swept setting and its
// value ("lbr=0.3:"; "" at the run's values).
struct BleedVariant {
    RenderSettings settings;
    std::string prefix;
};

// Each swept setting that acts for the method at each of its values, the others at the run's;
// the run's values alone when none acts for it (the options are checked: every key and value is
// valid).
std::vector<BleedVariant> bleedVariants(const StabilityOptions& o, const RenderSettings& base) {
    std::vector<BleedVariant> variants;
    for (const BleedSetting& swept : o.bleedSettings) {
        const ParamInfo& p = *findParam(swept.key);
        if (!paramActsFor(p, base.method)) continue;
        for (const std::string& value : swept.values) {
            // stability.csv's fields hold no comma: the exponents' POS,NEG is written POS;NEG.
            std::string field = value;
            std::replace(field.begin(), field.end(), ',', ';');
            BleedVariant v{base, swept.key + "=" + field + ":"};
            if (setParamFromText(v.settings, p, value)) {
                throw std::invalid_argument("bleed setting " + swept.key + " " + value);
            }
            variants.push_back(std::move(v));
        }
    }
    if (variants.empty()) variants.push_back({base, ""});
    return variants;
}

}  // namespace

Scene bleedScene(double gap) {
    const double values[] = {gap};
    return *presetScene(BLEED_PRESET, values);
}

std::vector<uint8_t> objectUmbra(const Scene& scene, const std::vector<std::optional<Hit>>& hits,
                                 int object) {
    std::vector<uint8_t> mask(hits.size(), 0);
    const Primitive& shape = scene.objects[static_cast<size_t>(object)].shape;
    for (size_t k = 0; k < hits.size(); ++k) {
        if (!hits[k] || hits[k]->object == object) continue;
        LightSample toLight = towardLight(scene.light, hits[k]->posWs);
        Ray ray{hits[k]->posWs, toLight.dirWs};
        mask[k] = intersect(shape, ray, 0.0f, toLight.distance).has_value() ? 1 : 0;
    }
    return mask;
}

std::optional<ParamProblem> validateBleedOptions(const StabilityOptions& o) {
    const PresetParam& gap = presetParams(BLEED_PRESET).front();
    if (o.bleedGaps.empty()) return ParamProblem{"bleed_gaps", "", " is empty"};
    for (float g : o.bleedGaps) {
        if (!(g >= gap.min && g <= gap.max)) {
            return ParamProblem{"bleed_gaps", "",
                                " " + exactNumberText(g) + " is out of range (" +
                                    exactNumberText(gap.min) + ".." + exactNumberText(gap.max) +
                                    ")"};
        }
    }
    for (const BleedSetting& swept : o.bleedSettings) {
        const ParamInfo* p = findParam(swept.key);
        if (!p) {
            return ParamProblem{"", "the bleed sweep's setting '" + swept.key + "' is unknown", ""};
        }
        if (swept.values.empty()) return ParamProblem{"bleed_settings", "", " is empty"};
        for (const std::string& value : swept.values) {
            ShadowSettings s;
            if (std::optional<ParamProblem> why = setParamFromText(s, *p, value)) return why;
        }
    }
    return std::nullopt;
}

namespace {

class BleedSweeper {
  public:
    BleedSweeper(const StabilityOptions& o, const std::function<void(const std::string&)>& say,
                 std::vector<StabilityRow>& rows)
        : mOptions(o), mSay(say), mRows(rows) {}

    void gap(size_t index) {
        float gap = mOptions.bleedGaps[index];
        char line[96];
        std::snprintf(line, sizeof line, "bleed %zu/%zu: stacked cards %g apart", index + 1,
                      mOptions.bleedGaps.size(), static_cast<double>(gap));
        if (mSay) mSay(line);
        Scene scene = bleedScene(gap);
        SceneRenderer renderer(scene);
        GroundTruthOptions g;
        g.spp = mOptions.truthSpp;
        g.threads = mOptions.threads;
        g.area = true;
        g.targetBound = mOptions.pcssTruthBound;
        GroundTruth truth = computeGroundTruth(scene, mOptions.frameSize, g);
        RenderSettings first = settings(mOptions.methods.front());
        renderer.renderShadowPass(first);
        renderer.renderCameraPass(first);
        ErrorRegions regions =
            errorRegions(truth, receiverMaskFromLightSpace(renderer.readLightSpace()));
        std::vector<std::optional<Hit>> hits =
            centreHits(scene, mOptions.frameSize, mOptions.threads);
        std::vector<uint8_t> lower = objectUmbra(scene, hits, lowerCard(scene));
        std::vector<StabilityMethod> methods = mOptions.methods;
        methods.insert(methods.end(), mOptions.bleedMethods.begin(), mOptions.bleedMethods.end());
        for (const StabilityMethod& m : methods) {
            float reach = footprintReachTexels(m, mOptions.base.radius) + 0.5f;
            std::vector<uint8_t> umbra =
                cleanPixelMask(scene, truth, regions, hits, renderer.shadowClipFromWorld(),
                               mOptions.mapSize, reach, false, mOptions.threads);
            for (size_t k = 0; k < umbra.size(); ++k) umbra[k] = umbra[k] && lower[k];
            for (const BleedVariant& v : bleedVariants(mOptions, settings(m))) {
                renderer.renderShadowPass(v.settings);
                renderer.renderCameraPass(v.settings);
                add(m, gap, v.prefix,
                    measureBleed(renderer.readVisibility(), truth, regions, umbra));
            }
        }
    }

  private:
    const StabilityOptions& mOptions;
    const std::function<void(const std::string&)>& mSay;
    std::vector<StabilityRow>& mRows;

    static int lowerCard(const Scene& scene) { return objectIndex(scene, BLEED_LOWER_CARD); }

    RenderSettings settings(const StabilityMethod& m) const {
        RenderSettings s = mOptions.base;
        s.method = m.method;
        s.kernel = m.kernel > 0 ? m.kernel : 3;
        s.mapSize = mOptions.mapSize;
        s.frameSize = mOptions.frameSize;
        s.writePositions = false;
        return s;
    }

    void add(const StabilityMethod& m, float gap, const std::string& prefix,
             const BleedMeasure& b) {
        const std::pair<std::string_view, double> measured[] = {
            {LEAK_MEAN, b.leakMean},
            {LEAK_P99, b.leakP99},
            {PENUMBRA_ERROR, b.penumbraError},
            {"umbra_pixels", b.umbraPixels},
            {"penumbra_pixels", b.penumbraPixels}};
        for (auto [metric, y] : measured) {
            mRows.push_back({std::string(sweepName(Sweep::Bleed)), m.method, m.kernel,
                             std::string(biasModeName(mOptions.base.bias)), "gap", gap,
                             prefix + std::string(metric), y});
        }
    }
};

}  // namespace

void runBleedSweep(const StabilityOptions& options,
                   const std::function<void(const std::string&)>& say,
                   std::vector<StabilityRow>& rows) {
    BleedSweeper sweeper(options, say, rows);
    for (size_t i = 0; i < options.bleedGaps.size(); ++i) sweeper.gap(i);
}

std::vector<BleedPoint> bleedPoints(std::span<const StabilityRow> rows) {
    std::vector<BleedPoint> points;
    const std::string sweep(sweepName(Sweep::Bleed));
    for (const StabilityRow& r : rows) {
        if (r.sweep != sweep) continue;
        size_t colon = r.metric.rfind(':');
        std::string setting = colon == std::string::npos ? "" : r.metric.substr(0, colon);
        std::string metric = colon == std::string::npos ? r.metric : r.metric.substr(colon + 1);
        size_t eq = setting.find('=');
        std::string key = eq == std::string::npos ? "" : setting.substr(0, eq);
        std::string value = eq == std::string::npos ? "" : setting.substr(eq + 1);
        std::replace(value.begin(), value.end(), ';', ',');
        if (metric == LEAK_MEAN) {
            points.push_back({r.method, r.kernel, r.x, key, value, r.y, 0.0, 0.0});
            continue;
        }
        if (points.empty()) continue;
        BleedPoint& p = points.back();
        if (p.method != r.method || p.gap != r.x || p.key != key || p.value != value) continue;
        if (metric == LEAK_P99) p.leakP99 = r.y;
        if (metric == PENUMBRA_ERROR) p.penumbraError = r.y;
    }
    return points;
}

namespace {

// The settings a point was measured with: the run's, and its swept value.
ShadowSettings bleedPointSettings(const BleedPoint& p, const ShadowSettings& base) {
    ShadowSettings s = base;
    if (const ParamInfo* param = p.key.empty() ? nullptr : findParam(p.key)) {
        if (setParamFromText(s, *param, p.value)) {
            throw std::invalid_argument("bleed setting " + p.key + " " + p.value);
        }
    }
    return s;
}

std::string bleedCsvNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

}  // namespace

std::string bleedCsv(std::span<const StabilityRow> rows, const ShadowSettings& base) {
    std::string out(BLEED_CSV_HEADER);
    out += "\n";
    for (const BleedPoint& p : bleedPoints(rows)) {
        std::string line = std::string(sweepName(Sweep::Bleed)) + "," +
                           std::string(methodInfo(p.method).name) + "," + std::to_string(p.kernel) +
                           "," + bleedCsvNumber(p.gap);
        const ShadowSettings used = bleedPointSettings(p, base);
        for (const BleedColumn& c : BLEED_COLUMNS) {
            const ParamInfo* param = findParam(c.key);
            std::string value;
            if (c.key == "evsm_exponents" && param && paramActsFor(*param, p.method)) {
                // What the warps used, not what was asked: the moment format clamps them.
                value = exponentsText(used.evsmExponentsUsed());
            } else if (p.key == c.key) {
                value = p.value;
            } else if (param && paramActsFor(*param, p.method)) {
                value = settingText(*param, used);
            }
            // A value with a comma (the exponents' POS,NEG) quoted, as CSV has it.
            line += "," + (value.find(',') != std::string::npos ? "\"" + value + "\"" : value);
        }
        line += "," + bleedCsvNumber(p.leakMean) + "," + bleedCsvNumber(p.leakP99) + "," +
                bleedCsvNumber(p.penumbraError);
        out += line + "\n";
    }
    return out;
}

double bleedChartGap(std::span<const StabilityRow> rows) {
    const double preferred = presetParams(BLEED_PRESET).front().defaultValue;
    double best = 0.0;
    for (const BleedPoint& p : bleedPoints(rows)) {
        if (best == 0.0 || std::abs(p.gap - preferred) < std::abs(best - preferred)) best = p.gap;
    }
    return best;
}

std::vector<BleedSeries> bleedSeries(std::span<const BleedPoint> points, double gap) {
    std::vector<BleedSeries> series;
    for (const BleedPoint& p : points) {
        if (p.gap != gap) continue;
        if (series.empty() || series.back().method != p.method ||
            series.back().kernel != p.kernel || series.back().key != p.key) {
            series.push_back({p.method, p.kernel, p.key, {}});
        }
        series.back().points.push_back(p);
    }
    return series;
}

std::vector<std::string> bleedKeys(std::span<const BleedSeries> series) {
    std::vector<std::string> keys;
    for (const BleedSeries& s : series) {
        if (!s.key.empty() && std::find(keys.begin(), keys.end(), s.key) == keys.end()) {
            keys.push_back(s.key);
        }
    }
    return keys;
}

const BleedPoint* firstCleanPoint(const BleedSeries& s) {
    for (const BleedPoint& p : s.points) {
        if (p.leakP99 < BLEED_LEAK_TARGET) return &p;
    }
    return nullptr;
}

namespace {

std::string bleedNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

// "- vsm 5x5, lbr 0 to 0.5: leak 0.31 at 0 (darkening 0.004); under 0.001 from 0.3 (darkening
// 0.052)"; a method at the run's settings alone: "- pcf-gather 3x3: leak 0 (darkening 0.01)".
std::string bleedSeriesLine(const BleedSeries& s) {
    std::string name = stabilityMethodName({s.method, s.kernel});
    const BleedPoint& first = s.points.front();
    auto at = [](const BleedPoint& p) {
        return "leak " + bleedNumber(p.leakP99) + " (darkening " + bleedNumber(-p.penumbraError) +
               ")";
    };
    if (s.key.empty()) return "- " + name + ": " + at(first) + "\n";
    std::string line = "- " + name + ", " + s.key + " " + first.value + " to " +
                       s.points.back().value + ": " + at(first) + " at " + first.value + "; ";
    const BleedPoint* clean = firstCleanPoint(s);
    if (clean) {
        line += "under " + bleedNumber(BLEED_LEAK_TARGET) + " from " + clean->value +
                ", darkening " + bleedNumber(-clean->penumbraError) + " there";
    } else {
        line += "never under " + bleedNumber(BLEED_LEAK_TARGET);
    }
    return line + "\n";
}

}  // namespace

std::string bleedMarkdown(std::span<const StabilityRow> rows) {
    std::vector<BleedPoint> points = bleedPoints(rows);
    if (points.empty()) return "";
    const double gap = bleedChartGap(rows);
    std::string md =
        "\nLight bleeding on " + std::string(BLEED_PRESET) + ", the cards " + bleedNumber(gap) +
        " apart (stability_bleed.h; stability_bleed.csv has every gap and value): "
        "leak, the 99th percentile of the visibility over the lower card's clean "
        "umbra (0 = no light leaks in); darkening, the mean of truth - v over the "
        "area truth's penumbra (what the light-bleeding reduction costs; negative: lighter "
        "than the truth).\n\n";
    for (const BleedSeries& s : bleedSeries(points, gap)) md += bleedSeriesLine(s);
    return md;
}

}  // namespace pcf
