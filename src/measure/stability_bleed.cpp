// The bleed sweep (stability_bleed.h): stacked-cards over the gap and the methods' settings,
// leak in the lower card's clean umbra and the signed error in the truth's penumbra.
#include "measure/stability_bleed.h"

#include <algorithm>
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

std::string bleedCsv(std::span<const StabilityRow> rows, const ShadowSettings& base) {
    std::string out(BLEED_CSV_HEADER);
    out += "\n";
    auto number = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.9g", v);
        return std::string(buf);
    };
    for (const BleedPoint& p : bleedPoints(rows)) {
        std::string line = std::string(sweepName(Sweep::Bleed)) + "," +
                           std::string(methodInfo(p.method).name) + "," + std::to_string(p.kernel) +
                           "," + number(p.gap);
        for (const BleedColumn& c : BLEED_COLUMNS) {
            const ParamInfo* param = findParam(c.key);
            std::string value;
            if (p.key == c.key) {
                value = p.value;
            } else if (param && paramActsFor(*param, p.method)) {
                value = settingText(*param, base);
            }
            // A value with a comma (the exponents' POS,NEG) quoted, as CSV has it.
            line += "," + (value.find(',') != std::string::npos ? "\"" + value + "\"" : value);
        }
        line += "," + number(p.leakMean) + "," + number(p.leakP99) + "," + number(p.penumbraError);
        out += line + "\n";
    }
    return out;
}

}  // namespace pcf
