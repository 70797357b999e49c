#include "measure/stability_pcss.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "kernel/methods.h"
#include "measure/error_metrics.h"
#include "measure/failure_measures.h"
#include "measure/ground_truth.h"
#include "render/scene_renderer.h"
#include "scene/light.h"
#include "scene/pcss.h"
#include "scene/presets.h"
#include "scene/scene_file.h"

namespace pcf {

namespace {

// post-in-sun's camera, ground and sun direction (presets.cpp), so the sweeps' scenes read like
// the lesson's: the light travels (1, -0.7, 0.3), 56 degrees from the zenith.
constexpr const char* PCSS_SCENE_HEAD = R"([camera]
eye = [2.2, 4.2, 6.0]
target = [2.0, 0.4, 0.4]
fov = 45.0

[light]
type = "directional"
direction = [1.0, -0.7, 0.3]
angular_diameter = %g

[[object]]
type = "plane"
name = "ground"
centre = [1.5, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [9.0, 6.0]
)";

constexpr const char* PCSS_BOX = R"(
[[object]]
type = "box"
name = "%s"
centre = [%g, %g, %g]
half = [%g, %g, %g]
)";

// A wide sun, so that the blocker search's disk (radius ref * S / 2, S proportional to
// tan(diameter / 2) and to the map size) spreads its 16 taps wider than a texel even on
// --quick's 128 map: about 5 texels at the pole's foot there.
constexpr float THIN_POLE_SUN_DEG = 8.0f;
constexpr float PCSS_POLE_HALF_HEIGHT = 1.5f;
// A wider sun for the plank: its penumbra on the ground is 2 tan(2 deg) * 1.8 H = 0.13 H wide.
constexpr float OVERLAP_SUN_DEG = 4.0f;
constexpr float PCSS_TRUTH_SHADOWED = 0.5f;  // the thin pole's population: area truth below this

std::string pcssBoxToml(const char* name, glm::vec3 centre, glm::vec3 half) {
    char buf[256];
    std::snprintf(buf, sizeof buf, PCSS_BOX, name, centre.x, centre.y, centre.z, half.x, half.y,
                  half.z);
    return buf;
}

std::string pcssHeadToml(float sunDeg) {
    char buf[512];
    std::snprintf(buf, sizeof buf, PCSS_SCENE_HEAD, sunDeg);
    return buf;
}

RenderSettings pcssSettingsFor(const StabilityOptions& o, int method, int kernel, BiasMode bias) {
    RenderSettings s = o.base;
    s.method = method;
    s.kernel = kernel > 0 ? kernel : 3;
    s.bias = bias;
    s.mapSize = o.mapSize;
    s.frameSize = o.frameSize;
    s.writePositions = false;
    s.lightSize = 0.0f;  // the scene light's angular diameter
    return s;
}

std::vector<float> pcssRenderFrame(SceneRenderer& r, const RenderSettings& s) {
    r.renderShadowPass(s);
    r.renderCameraPass(s);
    return r.readVisibility();
}

GroundTruth pcssTruthOf(const Scene& scene, const StabilityOptions& o, bool area) {
    GroundTruthOptions g;
    g.spp = o.truthSpp;
    g.threads = o.threads;
    g.area = area;
    if (area) g.targetBound = o.pcssTruthBound;
    return computeGroundTruth(scene, o.frameSize, g);
}

ErrorRegions pcssRegionsOf(SceneRenderer& r, const GroundTruth& truth, const RenderSettings& s) {
    r.renderShadowPass(s);
    r.renderCameraPass(s);
    return errorRegions(truth, receiverMaskFromLightSpace(r.readLightSpace()));
}

class PcssSweeper {
  public:
    PcssSweeper(const StabilityOptions& o, const std::function<void(const std::string&)>& say)
        : mOptions(o), mSay(say) {}
    std::vector<StabilityRow> rows;

    void thin();
    void overlap();
    void noise();
    void bias(const Scene& scene);

  private:
    const StabilityOptions& mOptions;
    const std::function<void(const std::string&)>& mSay;

    void say(const std::string& line) const {
        if (mSay) mSay(line);
    }
    void add(Sweep sweep, int method, int kernel, BiasMode bias, const char* xName, double x,
             const std::string& metric, double y) {
        rows.push_back({std::string(sweepName(sweep)), method, kernel,
                        std::string(biasModeName(bias)), xName, x, metric, y});
    }
};

// The share of the population's pixels that pcss (or the reference filter) returns as fully lit,
// on PCSS_THIN_SHIFTS grids; and the share whose miss changes between consecutive grids.
void PcssSweeper::thin() {
    const float texelWs = shadowTexelWs(pcssThinPoleScene(1.0f), mOptions.mapSize);
    const BiasMode bias = BiasMode::ReceiverPlane;
    for (size_t i = 0; i < mOptions.pcssPoleWidths.size(); ++i) {
        float widthTexels = mOptions.pcssPoleWidths[i];
        char line[96];
        std::snprintf(line, sizeof line, "pcss-thin %zu/%zu: a pole %g texels wide", i + 1,
                      mOptions.pcssPoleWidths.size(), widthTexels);
        say(line);
        Scene scene = pcssThinPoleScene(widthTexels * texelWs);
        SceneRenderer renderer(scene);
        GroundTruth truth = pcssTruthOf(scene, mOptions, true);
        RenderSettings pcss = pcssSettingsFor(mOptions, PCF_PCSS, 0, bias);
        ErrorRegions regions = pcssRegionsOf(renderer, truth, pcss);
        glm::mat4 fitted = renderer.shadowClipFromWorld();
        // The search's radius at the pole's foot (the kernel's searchHalf: ref * S / 2).
        glm::vec3 foot = glm::vec3(1.0f, 0.0f, 0.3f) * (widthTexels * texelWs);
        float scale = penumbraScale(scene.light, fitted, mOptions.mapSize, 0.0f);
        float searchRadius = shadowCoord(fitted, foot).depth * scale * 0.5f;
        add(Sweep::PcssThin, PCF_PCSS, 0, bias, "pole_width_texels", widthTexels,
            "search_radius_texels", searchRadius);
        std::vector<uint8_t> shadowed(truth.pixelCount(), 0);
        int population = 0;
        for (size_t k = 0; k < shadowed.size(); ++k) {
            shadowed[k] = regions.compared[k] && truth.visibility[k] < PCSS_TRUTH_SHADOWED;
            population += shadowed[k];
        }
        for (StabilityMethod m : {StabilityMethod{PCF_PCSS, 0}, StabilityMethod{PCF_GATHER, 5}}) {
            RenderSettings s = pcssSettingsFor(mOptions, m.method, m.kernel, bias);
            std::vector<double> shares;
            std::vector<uint8_t> previous, changed(shadowed.size(), 0);
            for (int t = 0; t < PCSS_THIN_SHIFTS; ++t) {
                renderer.setShadowClipFromWorld(shimmerShadowFit(
                    fitted, mOptions.mapSize, t * SHIMMER_STEPS / PCSS_THIN_SHIFTS, false));
                std::vector<float> v = pcssRenderFrame(renderer, s);
                std::vector<uint8_t> missed(v.size(), 0);
                int count = 0;
                for (size_t k = 0; k < v.size(); ++k) {
                    missed[k] = shadowed[k] && v[k] >= FULLY_LIT_LEVEL;
                    count += missed[k];
                    if (!previous.empty() && previous[k] != missed[k]) changed[k] = 1;
                }
                shares.push_back(population > 0 ? double(count) / population : 0.0);
                previous = std::move(missed);
            }
            int flicker = static_cast<int>(std::count(changed.begin(), changed.end(), 1));
            double mean = 0.0;
            for (double x : shares) mean += x / static_cast<double>(shares.size());
            auto put = [&](const char* metric, double y) {
                add(Sweep::PcssThin, m.method, m.kernel, bias, "pole_width_texels", widthTexels,
                    metric, y);
            };
            put("missed_share_mean", mean);
            put("missed_share_min", *std::min_element(shares.begin(), shares.end()));
            put("missed_share_max", *std::max_element(shares.begin(), shares.end()));
            put("missed_flicker_share", population > 0 ? double(flicker) / population : 0.0);
            put("shadowed_pixels", population);
        }
    }
}

struct PcssPenumbraMeasure {
    double ratio = 0.0;  // pcss's penumbra pixels / the truth's
    double rmse = 0.0;   // over the pixels either calls penumbra
    int truthPixels = 0;
};

bool inPcssPenumbra(float v) { return v > PCSS_PENUMBRA_LO && v < PCSS_PENUMBRA_HI; }

PcssPenumbraMeasure pcssPenumbraOf(const std::vector<float>& v, const GroundTruth& truth,
                                   const ErrorRegions& regions) {
    PcssPenumbraMeasure out;
    int drawn = 0, union_ = 0;
    double sq = 0.0;
    for (size_t k = 0; k < v.size(); ++k) {
        if (!regions.compared[k]) continue;
        bool t = inPcssPenumbra(truth.visibility[k]), d = inPcssPenumbra(v[k]);
        out.truthPixels += t;
        drawn += d;
        if (!t && !d) continue;
        ++union_;
        double e = double(v[k]) - truth.visibility[k];
        sq += e * e;
    }
    out.ratio = out.truthPixels > 0 ? double(drawn) / out.truthPixels : 0.0;
    out.rmse = union_ > 0 ? std::sqrt(sq / union_) : 0.0;
    return out;
}

void PcssSweeper::overlap() {
    const BiasMode bias = BiasMode::ReceiverPlane;
    for (size_t i = 0; i < mOptions.pcssPlankHeights.size(); ++i) {
        float height = mOptions.pcssPlankHeights[i];
        for (bool block : {false, true}) {
            char line[96];
            std::snprintf(line, sizeof line, "pcss-overlap %zu/%zu: a plank %g high%s", i + 1,
                          mOptions.pcssPlankHeights.size(), height,
                          block ? " over a low block" : "");
            say(line);
            Scene scene = pcssOverlapScene(height, block);
            SceneRenderer renderer(scene);
            GroundTruth truth = pcssTruthOf(scene, mOptions, true);
            RenderSettings s = pcssSettingsFor(mOptions, PCF_PCSS, 0, bias);
            ErrorRegions regions = pcssRegionsOf(renderer, truth, s);
            PcssPenumbraMeasure p = pcssPenumbraOf(pcssRenderFrame(renderer, s), truth, regions);
            std::string prefix = block ? "stacked:" : "alone:";
            add(Sweep::PcssOverlap, PCF_PCSS, 0, bias, "plank_height", height,
                prefix + "penumbra_pixels_ratio", p.ratio);
            add(Sweep::PcssOverlap, PCF_PCSS, 0, bias, "plank_height", height,
                prefix + "penumbra_rmse", p.rmse);
            add(Sweep::PcssOverlap, PCF_PCSS, 0, bias, "plank_height", height,
                prefix + "truth_penumbra_pixels", p.truthPixels);
        }
    }
}

// Over the truth's penumbra: the RMS of e(x+1) - e(x) for horizontal neighbours both in it, and
// the RMSE of e = v - truth.
glm::dvec2 pcssRoughnessOf(const std::vector<float>& v, const GroundTruth& truth,
                           const ErrorRegions& regions) {
    double rough = 0.0, sq = 0.0;
    int pairs = 0, n = 0;
    auto in = [&](size_t k) { return regions.compared[k] && inPcssPenumbra(truth.visibility[k]); };
    for (int y = 0; y < truth.size.y; ++y) {
        for (int x = 0; x < truth.size.x; ++x) {
            size_t k = truth.index(x, y);
            if (!in(k)) continue;
            double e = double(v[k]) - truth.visibility[k];
            sq += e * e;
            ++n;
            if (x + 1 < truth.size.x && in(k + 1)) {
                double d = double(v[k + 1]) - truth.visibility[k + 1] - e;
                rough += d * d;
                ++pairs;
            }
        }
    }
    return {pairs > 0 ? std::sqrt(rough / pairs) : 0.0, n > 0 ? std::sqrt(sq / n) : 0.0};
}

void PcssSweeper::noise() {
    const BiasMode bias = BiasMode::ReceiverPlane;
    for (size_t i = 0; i < mOptions.pcssLightSizes.size(); ++i) {
        float sun = mOptions.pcssLightSizes[i];
        char line[96];
        std::snprintf(line, sizeof line, "pcss-noise %zu/%zu: post-in-sun under a %g degree sun",
                      i + 1, mOptions.pcssLightSizes.size(), sun);
        say(line);
        Scene scene = *presetScene("post-in-sun");
        scene.light.angularDiameterDeg = sun;
        SceneRenderer renderer(scene);
        GroundTruth truth = pcssTruthOf(scene, mOptions, true);
        RenderSettings s = pcssSettingsFor(mOptions, PCF_PCSS, 0, bias);
        ErrorRegions regions = pcssRegionsOf(renderer, truth, s);
        for (bool rotate : {true, false}) {
            s.rotate = rotate;
            glm::dvec2 r = pcssRoughnessOf(pcssRenderFrame(renderer, s), truth, regions);
            std::string prefix = rotate ? "rotated:" : "fixed:";
            add(Sweep::PcssNoise, PCF_PCSS, 0, bias, "sun_deg", sun, prefix + "penumbra_roughness",
                r.x);
            add(Sweep::PcssNoise, PCF_PCSS, 0, bias, "sun_deg", sun, prefix + "penumbra_rmse", r.y);
        }
    }
}

void PcssSweeper::bias(const Scene& base) {
    Scene scene = base;
    scene.light.directionWs =
        directionAtElevation(scene.light.directionWs, mOptions.pcssBiasElevation);
    say("pcss-bias: poisson's radius swept at one bias, " + scene.name);
    SceneRenderer renderer(scene);
    GroundTruth truth = pcssTruthOf(scene, mOptions, false);
    ErrorRegions regions = pcssRegionsOf(
        renderer, truth, pcssSettingsFor(mOptions, PCF_POISSON, 0, BiasMode::Constant));
    std::vector<std::optional<Hit>> hits = centreHits(scene, mOptions.frameSize, mOptions.threads);
    for (float radius : mOptions.pcssRadii) {
        // The clean-lit mask of this reach (stability.cpp's reachOf: the footprint + 1/2 texel).
        std::vector<uint8_t> lit =
            cleanPixelMask(scene, truth, regions, hits, renderer.shadowClipFromWorld(),
                           mOptions.mapSize, radius + 1.0f, true, mOptions.threads);
        for (BiasMode bias : {BiasMode::Constant, BiasMode::ReceiverPlane}) {
            RenderSettings s = pcssSettingsFor(mOptions, PCF_POISSON, 0, bias);
            s.radius = radius;
            FailureRate r = falseShadow(pcssRenderFrame(renderer, s), lit);
            add(Sweep::PcssBias, PCF_POISSON, 0, bias, "filter_radius_texels", radius,
                "false_shadow_rate", r.share);
            add(Sweep::PcssBias, PCF_POISSON, 0, bias, "filter_radius_texels", radius,
                "clean_lit_pixels", r.count);
        }
    }
}

}  // namespace

Scene pcssThinPoleScene(float width) {
    std::string toml = pcssHeadToml(THIN_POLE_SUN_DEG) +
                       pcssBoxToml("pole", {0.0f, PCSS_POLE_HALF_HEIGHT, 0.0f},
                                   {0.5f * width, PCSS_POLE_HALF_HEIGHT, 0.5f * width});
    return parseSceneString(toml, "pcss-thin pole");
}

Scene pcssOverlapScene(float height, bool withBlock) {
    // The plank's far edge (x = 0.6) casts its shadow edge 0.6 + H / 0.7 along x and 0.3 H / 0.7
    // along z; the block straddles it.
    std::string toml = pcssHeadToml(OVERLAP_SUN_DEG) +
                       pcssBoxToml("plank", {0.0f, height, 0.0f}, {0.6f, 0.05f, 0.8f});
    if (withBlock) {
        toml += pcssBoxToml("block", {0.6f + height / 0.7f, 0.15f, 0.3f * height / 0.7f},
                            {0.3f, 0.15f, 0.8f});
    }
    return parseSceneString(toml, "pcss-overlap plank");
}

std::optional<ParamProblem> validatePcssSweepOptions(const StabilityOptions& o) {
    auto bad = [](const char* setting, float v, const char* range) {
        return ParamProblem{setting, "",
                            " " + std::to_string(v) + " is out of range (" + range + ")"};
    };
    for (float w : o.pcssPoleWidths) {
        if (!(w >= 0.25f && w <= 64.0f)) return bad("pcss_pole_widths", w, "0.25..64 texels");
    }
    for (float h : o.pcssPlankHeights) {
        if (!(h >= 0.2f && h <= 3.0f)) return bad("pcss_plank_heights", h, "0.2..3");
    }
    for (float d : o.pcssLightSizes) {
        if (!(d > 0.0f && d <= 20.0f)) return bad("pcss_light_sizes", d, "0..20 degrees");
    }
    for (float r : o.pcssRadii) {
        if (!(r >= 0.0f && r <= MAX_POISSON_RADIUS)) return bad("pcss_radii", r, "0..64 texels");
    }
    if (!(o.pcssTruthBound > 0.0f && o.pcssTruthBound <= 0.5f)) {
        return ParamProblem{"", "the pcss truth bound is out of range (0..0.5)", ""};
    }
    if (!(o.pcssBiasElevation >= 1.0f && o.pcssBiasElevation <= 90.0f)) {
        return ParamProblem{"", "the pcss-bias elevation is out of range (1..90 degrees)", ""};
    }
    return std::nullopt;
}

void runPcssSweep(Sweep sweep, const StabilityOptions& options, const Scene& scene,
                  const std::function<void(const std::string&)>& say,
                  std::vector<StabilityRow>& rows) {
    PcssSweeper sweeper(options, say);
    switch (sweep) {
        case Sweep::PcssThin:
            sweeper.thin();
            break;
        case Sweep::PcssOverlap:
            sweeper.overlap();
            break;
        case Sweep::PcssNoise:
            sweeper.noise();
            break;
        case Sweep::PcssBias:
            sweeper.bias(scene);
            break;
        case Sweep::Acne:
        case Sweep::Leak:
        case Sweep::Tradeoff:
        case Sweep::Shimmer:
        case Sweep::Precision:
        case Sweep::Aliasing:
        case Sweep::Bleed:
        case Sweep::Cascades:
            throw std::invalid_argument("runPcssSweep: not a pcss sweep");
    }
    rows.insert(rows.end(), sweeper.rows.begin(), sweeper.rows.end());
}

}  // namespace pcf
