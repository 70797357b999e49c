// The GLSL equals the CPU kernel: the same shared source, compiled twice, gives the same
// visibility on the same inputs (docs/architecture.md, "One kernel for the CPU and the GPU"). Runs
// on llvmpipe through EGL in CI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "kernel/bias.h"
#include "kernel/methods.h"
#include "kernel/moments.h"
#include "kernel/pcf.h"
#include "measure/conformance.h"
#include "random_map.h"
#include "render/depth_readback.h"
#include "render/gl_context.h"
#include "render/gpu_lookup.h"
#include "render/gpu_timer.h"
#include "render/scene_renderer.h"
#include "scene/presets.h"

namespace pcf {
namespace {

constexpr float PARITY_TOLERANCE = 1e-5f;

// The moment methods are held to MOMENT_TOLERANCE (measure/conformance.h): their visibility
// goes through exp (EVSM's warps) and divisions whose last bits a GLSL compiler may round
// otherwise (llvmpipe: up to 2.5e-5 from the CPU on the rendered scenes); the others to 1e-5.
float parityTolerance(int method) {
    return readsMoments(method) ? MOMENT_TOLERANCE : PARITY_TOLERANCE;
}

class GpuParity : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        sContext = createHeadlessContext();
        const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        sSoftware = isSoftwareRenderer(renderer ? renderer : "");
    }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
    static bool sSoftware;  // llvmpipe and friends: the GPU computes exactly the CPU's model
};
std::unique_ptr<GlContext> GpuParity::sContext;
bool GpuParity::sSoftware = true;

// How far the GPU is from the CPU kernel over many lookups. On a software renderer (llvmpipe:
// float texel positions, float weights) the CPU's `exact` model must match to 1e-5; on any
// other GPU the texture unit may round positions and weights (8 bits on NVIDIA and AMD, 4 are
// allowed), so there every result must lie inside the conformance envelope instead.
struct Agreement {
    float worst = 0.0f;  // max |GPU - CPU exact|
    float tolerance = PARITY_TOLERANCE;
    int outside = 0;  // results outside the conformance envelope (checked off llvmpipe only)
    void add(const ShadowMap& map, glm::vec2 uv, float ref, const PcfParams& p, float gpu,
             bool software) {
        float cpu = filterVisibility(map, uv, ref, p);
        worst = std::max(worst, std::fabs(cpu - gpu));
        tolerance = parityTolerance(p.method);
        if (!software && !visibilityEnvelope(map, uv, ref, p).contains(gpu)) ++outside;
    }
    void expectOk(bool software, const std::string& what) const {
        if (software) {
            EXPECT_LE(worst, tolerance) << what;
        } else {
            EXPECT_EQ(outside, 0) << what << " (max |GPU - CPU exact| " << worst << ")";
        }
    }
};

std::vector<PcfParams> parityCases(std::initializer_list<int> kernels) {
    std::vector<PcfParams> cases;
    for (const MethodInfo& m : allMethods()) {
        if (!m.kernelSizes.empty()) {
            for (int n : m.kernelSizes) cases.push_back(makeParams(m.id, n));
        } else if (m.usesKernel) {
            for (int n : kernels) cases.push_back(makeParams(m.id, n));
        } else if (m.usesRadius) {
            cases.push_back(makeParams(m.id, 1, 1.0f));
            cases.push_back(makeParams(m.id, 1, 2.5f));
        } else if (m.searchesBlockers) {
            // A light of no size (radius 1 throughout) and one whose disks span many texels.
            for (float scale : {0.0f, 30.0f}) {
                PcfParams p = makeParams(m.id, 1);
                p.penumbraScale = scale;
                cases.push_back(p);
            }
        } else {
            cases.push_back(makeParams(m.id, 1));
        }
    }
    return cases;
}

// The map's depth kinds from the table (kernel/shadow_map.h), so a kind added there is
// rendered and compared here with no change to this file; the fixed-point ones on their own.
std::vector<TexelKind> depthKinds(bool fixedPointOnly) {
    std::vector<TexelKind> kinds;
    for (TexelKind k : allTexelKinds()) {
        const TexelKindInfo& info = texelKindInfo(k);
        if (info.depth && (info.fixedPoint || !fixedPointOnly)) kinds.push_back(k);
    }
    return kinds;
}

std::string describe(const PcfParams& prm) {
    return std::string(methodInfo(prm.method).name) + " N=" + std::to_string(prm.kernel) +
           " R=" + std::to_string(prm.radius) + " S=" + std::to_string(prm.penumbraScale);
}

TEST_F(GpuParity, RandomLookupsOnRandomMapsMatchTheCpuKernel) {
    GpuLookup gpu;
    for (glm::ivec2 size : {glm::ivec2(37, 23), glm::ivec2(64, 64)}) {
        ShadowMap depth = randomMap(size.x, size.y, 17 + size.x);
        const int width = 64;
        std::vector<glm::vec4> lookups = randomLookups(size, width, 64, 18 + size.x);
        for (bool rotate : {false, true}) {
            for (const PcfParams& prm : parityCases({1, 2, 3, 5, 8})) {
                if (rotate && !methodInfo(prm.method).hasDisk) continue;
                // A moment method reads the moments pass's map of these depths (the CPU's).
                ShadowMap read =
                    readsMoments(prm.method)
                        ? momentsMap(depth, prm, mapTexelKind(prm.method, TexelKind::D32F))
                        : depth;
                const ShadowMap& map = read;
                std::vector<float> got = gpu.run(map, lookups, width, prm, rotate);
                Agreement a;
                for (size_t k = 0; k < lookups.size(); ++k) {
                    PcfParams p = prm;
                    if (rotate) {
                        p.rotation = pcfTexelRotation(glm::vec2(lookups[k]), size);
                    }
                    a.add(map, glm::vec2(lookups[k]), lookups[k].z, p, got[k], sSoftware);
                }
                a.expectOk(sSoftware, describe(prm) + " map " + std::to_string(size.x) + "x" +
                                          std::to_string(size.y) + (rotate ? " rotated" : ""));
            }
        }
    }
}

// The shader's dispatch (pcf_filter.h pcfFilterRef, compiled as GLSL with the method a define)
// has a branch for every method of the table and every weighting: none gives PCF_UNDISPATCHED,
// which an id without a branch gets on the GPU as on the CPU (so parity alone cannot tell).
TEST_F(GpuParity, TheShadersDispatchHasABranchForEveryMethod) {
    GpuLookup gpu;
    ShadowMap map = randomMap(32, 32, 5);
    const int width = 16;
    std::vector<glm::vec4> lookups = randomLookups(glm::ivec2(32), width, 16, 6);
    for (const MethodInfo& m : allMethods()) {
        for (int weights : {PCF_WEIGHTS_BOX, PCF_WEIGHTS_BINOMIAL, PCF_WEIGHTS_GAUSSIAN}) {
            if (weights != PCF_WEIGHTS_BOX && !m.takesWeights) continue;
            PcfParams prm = makeParams(m.id, fitKernel(m.id, 3));
            prm.weights = weights;
            std::vector<float> got = gpu.run(map, lookups, width, prm, false);
            auto [lo, hi] = std::minmax_element(got.begin(), got.end());
            EXPECT_GE(*lo, 0.0f) << m.name << " weights " << weights;
            EXPECT_LE(*hi, 1.0f) << m.name << " weights " << weights;
        }
    }
    std::vector<float> unknown =
        gpu.run(map, lookups, width, makeParams(PCF_METHOD_COUNT, 3), false);
    for (float v : unknown) ASSERT_EQ(v, PCF_UNDISPATCHED);
}

// textureGather's components are texels (0,1), (1,1), (1,0), (0,0) of the 2x2 block: a map
// with one lit texel at a time, looked up at a known fraction, must give exactly that texel's
// bilinear weight, on the GPU as on the CPU.
TEST_F(GpuParity, GatherComponentOrderTapByTap) {
    GpuLookup gpu;
    const glm::vec2 frac(0.2f, 0.7f);
    const glm::ivec2 base(1, 1);
    glm::vec2 uv = (glm::vec2(base) + frac + 0.5f) / 4.0f;
    const float weights[2][2] = {{(1 - frac.x) * (1 - frac.y), frac.x * (1 - frac.y)},
                                 {(1 - frac.x) * frac.y, frac.x * frac.y}};
    for (int dj = 0; dj < 2; ++dj) {
        for (int di = 0; di < 2; ++di) {
            ShadowMap map(4, 4, 0.1f);  // everything shadows a receiver at 0.5 ...
            // ... except one texel, and every texel gets a distinct depth so a mix-up shows.
            for (int j = 0; j < 4; ++j) {
                for (int i = 0; i < 4; ++i) map.setDepth(i, j, 0.01f * (i + 4 * j));
            }
            map.setDepth(base.x + di, base.y + dj, 0.9f);
            std::vector<glm::vec4> lookups(4, glm::vec4(uv, 0.5f, 0.0f));
            for (int method : {PCF_GATHER, PCF_BILINEAR2X2, PCF_HW2X2}) {
                std::vector<float> got = gpu.run(map, lookups, 2, makeParams(method, 1), false);
                EXPECT_NEAR(got[0], weights[dj][di], 1e-5f)
                    << methodInfo(method).name << " lit texel " << di << "," << dj;
                EXPECT_NEAR(filterVisibility(map, uv, 0.5f, makeParams(method, 1)), weights[dj][di],
                            1e-6f);
            }
        }
    }
}

// The map the CPU reads is the map the sampler compares against (issue 10). For each texel of a
// 16- and 24-bit map, a hardware tap at its centre (fraction 0: the texel alone) is lit for
// ref = the read-back depth and shadowed for the next float up: the comparison sampler holds
// exactly that float. On llvmpipe that float is float(k) * float(1 / (2^bits - 1)).
TEST_F(GpuParity, FixedPointReadbackIsTheSamplersFloat) {
    GpuLookup gpu;
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (TexelKind kind : depthKinds(true)) {
        const int bits = texelKindInfo(kind).bits;
        const glm::ivec2 size(64, 32);
        ShadowMap map(size.x, size.y);
        for (int j = 0; j < size.y; ++j) {
            for (int i = 0; i < size.x; ++i) map.setDepth(i, j, 0.05f + 0.9f * unit(rng));
        }
        map.setTexelKind(kind);
        std::vector<glm::vec4> probe(static_cast<size_t>(size.x) * size.y);
        gpu.run(map, probe, size.x, makeParams(PCF_HW2X2), false);
        ShadowMap stored = gpu.storedMap();
        ASSERT_EQ(stored.fixedPointBits(), bits);
        std::vector<glm::vec4> at(probe.size());
        std::vector<glm::vec4> above(probe.size());
        int convertedDifferently = 0;
        for (int j = 0; j < size.y; ++j) {
            for (int i = 0; i < size.x; ++i) {
                size_t k = static_cast<size_t>(j) * size.x + i;
                glm::vec2 uv((i + 0.5f) / size.x, (j + 0.5f) / size.y);
                float d = stored.depth(i, j);
                at[k] = glm::vec4(uv, d, 0.0f);
                above[k] = glm::vec4(uv, std::nextafter(d, 2.0f), 0.0f);
                // The stored integer: the k whose sampler float is d (d * scale alone can round
                // to a neighbour, the product being off by up to half a float step).
                double scale = static_cast<double>((1u << bits) - 1u);
                auto guess = static_cast<int64_t>(std::lround(static_cast<double>(d) * scale));
                int64_t found = -1;
                for (int64_t k2 = guess - 1; k2 <= guess + 1; ++k2) {
                    if (k2 >= 0 && unormDepthAsSampled(static_cast<uint32_t>(k2), bits) == d) {
                        found = k2;
                    }
                }
                if (sSoftware) {
                    EXPECT_GE(found, 0) << bits << "-bit texel " << i << "," << j;
                }
                if (found >= 0 && d != static_cast<float>(static_cast<double>(found) / scale)) {
                    ++convertedDifferently;
                }
            }
        }
        // The same float map uploaded again (GL rounds it to the same integers).
        std::vector<float> lit = gpu.run(map, at, size.x, makeParams(PCF_HW2X2), false);
        std::vector<float> shadowed = gpu.run(map, above, size.x, makeParams(PCF_HW2X2), false);
        for (size_t k = 0; k < at.size(); ++k) {
            EXPECT_EQ(lit[k], 1.0f) << bits << "-bit texel " << k;
            EXPECT_EQ(shadowed[k], 0.0f) << bits << "-bit texel " << k;
        }
        // The experiment behind issue 10: for 24 bits the sampler's float is not the correctly
        // rounded k / (2^24 - 1) in a good share of texels (16 bits: the two agree).
        if (sSoftware && bits == 24) {
            EXPECT_GT(convertedDifferently, 64) << "of 2048";
        }
    }
}

// All three formats, refs below 0 and above 1 (clamped on fixed-point maps only), non-power-of-
// two maps, weighted kernels and both precision models.
TEST_F(GpuParity, EveryFormatAndOutOfRangeRefsMatchTheCpuKernel) {
    GpuLookup gpu;
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_real_distribution<float> around(-0.03f, 1.03f);
    std::uniform_real_distribution<float> refs(-0.4f, 1.4f);
    for (TexelKind kind : depthKinds(false)) {
        for (glm::ivec2 size : {glm::ivec2(37, 23), glm::ivec2(50, 50)}) {
            ShadowMap map(size.x, size.y);
            for (int j = 0; j < size.y; ++j) {
                for (int i = 0; i < size.x; ++i) {
                    map.setDepth(i, j, unit(rng) < 0.1f ? 1.0f : unit(rng));
                }
            }
            map.setTexelKind(kind);
            const int width = 64;
            std::vector<glm::vec4> lookups(width * 16);
            for (glm::vec4& l : lookups) l = glm::vec4(around(rng), around(rng), refs(rng), 0.0f);
            std::vector<PcfParams> all = parityCases({1, 3, 4});
            for (int w : {PCF_WEIGHTS_BINOMIAL, PCF_WEIGHTS_GAUSSIAN}) {
                for (int method : {PCF_NAIVE, PCF_GATHER}) {
                    PcfParams p = makeParams(method, 4);
                    p.weights = w;
                    p.sigma = 1.3f;
                    all.push_back(p);
                }
            }
            for (PcfParams prm : all) {
                for (int precision : {PCF_PRECISION_EXACT, PCF_PRECISION_HW8}) {
                    prm.precision = precision;
                    std::vector<float> got = gpu.run(map, lookups, width, prm, false);
                    const ShadowMap& stored = gpu.storedMap();
                    Agreement a;
                    for (size_t k = 0; k < lookups.size(); ++k) {
                        a.add(stored, glm::vec2(lookups[k]), lookups[k].z, prm, got[k], sSoftware);
                    }
                    a.expectOk(sSoftware, describe(prm) + " w" + std::to_string(prm.weights) + " " +
                                              std::string(precisionName(precision)) + " " +
                                              std::string(texelKindName(kind)) + " " +
                                              std::to_string(size.x) + "x" +
                                              std::to_string(size.y));
                }
            }
        }
    }
}

// Rendered frames in every format with biases that push refs below 0 and above 1, on a
// non-power-of-two map: the GPU's visibility against the CPU kernel on the read-back map.
TEST_F(GpuParity, RenderedFixedPointFramesMatchWithAnyBias) {
    for (const char* preset : {"grazing", "sphere-over-plane"}) {
        Scene scene = *presetScene(preset);
        SceneRenderer renderer(scene);
        for (TexelKind format : depthKinds(false)) {
            for (float bias : {0.0f, -0.5f, 0.5f}) {
                for (int method : {PCF_NEAREST, PCF_BILINEAR2X2, PCF_HW2X2, PCF_GATHER, PCF_TENT}) {
                    RenderSettings s;
                    s.method = method;
                    s.kernel = method == PCF_TENT ? 5 : 3;
                    s.mapSize = 100;
                    s.depthFormat = format;
                    s.bias = bias == 0.0f ? BiasMode::None : BiasMode::Constant;
                    s.constantBias = bias;
                    s.frameSize = {200, 112};
                    renderer.render(s);
                    ShadowMap map = renderer.readShadowMap();
                    std::vector<float> ls = renderer.readLightSpace();
                    std::vector<float> vis = renderer.readVisibility();
                    Agreement a;
                    for (size_t k = 0; k < vis.size(); ++k) {
                        if (ls[4 * k + 3] != 1.0f) continue;
                        a.add(map, glm::vec2(ls[4 * k], ls[4 * k + 1]), ls[4 * k + 2],
                              s.pcfParams(), vis[k], sSoftware);
                    }
                    a.expectOk(sSoftware, std::string(preset) + " " +
                                              std::string(depthFormatName(format)) + " bias " +
                                              std::to_string(bias) + " " +
                                              std::string(methodInfo(method).name));
                }
            }
        }
    }
}

TEST_F(GpuParity, RenderedScenesMatchTheCpuKernelOnTheirOwnLightSpaceTarget) {
    // post-under-spot: a spot light's perspective map (its pcss works in linearised depth: the
    // map's near and far reach the shader), on the smaller map only, to keep the test lean.
    for (const char* preset : {"box-on-plane", "sphere-over-plane", "stairs", "post-under-spot"}) {
        Scene scene = *presetScene(preset);
        SceneRenderer renderer(scene);
        for (int mapSize : {128, 512}) {
            if (scene.light.type == LightType::Spot && mapSize > 128) continue;
            for (const PcfParams& prm : parityCases({3, 5})) {
                if (prm.method == PCF_TENT && prm.kernel == 7) continue;
                RenderSettings s;
                s.method = prm.method;
                s.kernel = prm.kernel;
                s.radius = prm.radius;
                s.rotate = prm.method == PCF_POISSON && prm.radius > 2.0f;
                s.mapSize = mapSize;
                s.frameSize = {240, 136};
                renderer.render(s);
                ShadowMap map = renderer.readShadowMap();
                std::vector<float> ls = renderer.readLightSpace();
                std::vector<float> vis = renderer.readVisibility();
                int receivers = 0;
                int shadowed = 0;
                Agreement a;
                for (int y = 0; y < s.frameSize.y; ++y) {
                    for (int x = 0; x < s.frameSize.x; ++x) {
                        size_t k = static_cast<size_t>(y) * s.frameSize.x + x;
                        if (ls[4 * k + 3] != 1.0f) continue;
                        ++receivers;
                        // pcss: the light's size in this map, as the renderer measured it.
                        PcfParams p = renderer.pcfParams(s);
                        // The disk turns with the texel looked up (pcfTexelRotation).
                        if (s.rotate) {
                            p.rotation = pcfTexelRotation(glm::vec2(ls[4 * k], ls[4 * k + 1]),
                                                          glm::ivec2(map.width(), map.height()));
                        }
                        a.add(map, glm::vec2(ls[4 * k], ls[4 * k + 1]), ls[4 * k + 2], p, vis[k],
                              sSoftware);
                        if (vis[k] < 0.5f) ++shadowed;
                    }
                }
                std::string what =
                    std::string(preset) + " map " + std::to_string(mapSize) + " " + describe(prm);
                a.expectOk(sSoftware, what);
                EXPECT_GT(receivers, s.frameSize.x * s.frameSize.y / 4) << what;
                EXPECT_GT(shadowed, 50) << what;  // there is a shadow to agree about
            }
        }
    }
}

// Every bias mode's per-tap part (receiver plane, soft, interpolated) with every method it
// combines with, on random maps and lookups with a random receiver plane each: the GLSL and the
// CPU compare each tap against the same ref and give the same visibility.
TEST_F(GpuParity, BiasModesOnRandomLookupsMatchTheCpuKernel) {
    GpuLookup gpu;
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_real_distribution<float> around(-0.03f, 1.03f);
    std::uniform_real_distribution<float> slope(-3.0f, 3.0f);
    const glm::ivec2 size(41, 32);
    ShadowMap map(size.x, size.y);
    // A sloped plane with noise: neighbours differ by about what a receiver plane corrects.
    for (int j = 0; j < size.y; ++j) {
        for (int i = 0; i < size.x; ++i) {
            map.setDepth(i, j, 0.2f + 0.5f * (i + 0.5f) / size.x + 0.02f * unit(rng));
        }
    }
    const int width = 64;
    std::vector<glm::vec4> lookups(width * 48);
    std::vector<glm::vec2> planes(lookups.size());
    for (size_t k = 0; k < lookups.size(); ++k) {
        glm::vec2 uv(around(rng), around(rng));
        lookups[k] = glm::vec4(uv, 0.2f + 0.5f * uv.x + 0.02f * unit(rng) - 0.01f, 0.0f);
        planes[k] = glm::vec2(slope(rng), slope(rng));
    }
    for (int mode : {PCF_BIAS_RECEIVER_PLANE, PCF_BIAS_SOFT, PCF_BIAS_INTERPOLATED}) {
        float worstMode = 0.0f;
        // soft at two scales; receiver-plane as measured and under a cap (--rpdb-max) that
        // binds on most lookups (the slopes reach 3 depth per uv unit).
        std::vector<PcfBias> variants;
        if (mode == PCF_BIAS_SOFT) {
            for (float softScale : {40.0f, 2048.0f}) {
                variants.push_back(PcfBias(mode, glm::vec2(0.0f), softScale, PCF_DZDUV_UNCLAMPED));
            }
        } else if (mode == PCF_BIAS_RECEIVER_PLANE) {
            for (float cap : {PCF_DZDUV_UNCLAMPED, 1.0f}) {
                variants.push_back(PcfBias(mode, glm::vec2(0.0f), 40.0f, cap));
            }
            int capped = 0;
            for (const glm::vec2& g : planes) capped += pcfClampDzDuv(g, 1.0f) != g;
            EXPECT_GT(capped, static_cast<int>(planes.size()) / 2);
        } else {
            variants.push_back(PcfBias(mode, glm::vec2(0.0f), 40.0f, PCF_DZDUV_UNCLAMPED));
        }
        for (const PcfBias& bias : variants) {
            float softScale = bias.softScale;
            for (const PcfParams& prm : parityCases({1, 2, 3, 5})) {
                if (validateBias(mode, prm.method)) continue;
                std::vector<float> got = gpu.run(map, lookups, width, prm, false, bias, planes);
                float worst = 0.0f;
                int lit = 0;
                int dark = 0;
                for (size_t k = 0; k < lookups.size(); ++k) {
                    PcfBias b = bias;
                    b.dzduv = planes[k];
                    float cpu = filterVisibility(map, glm::vec2(lookups[k]), lookups[k].z, prm, b);
                    worst = std::max(worst, std::fabs(cpu - got[k]));
                    lit += cpu > 0.5f ? 1 : 0;
                    dark += cpu < 0.5f ? 1 : 0;
                }
                EXPECT_LE(worst, parityTolerance(prm.method))
                    << biasName(mode) << " scale " << softScale << " cap " << bias.rpdbMax << " "
                    << describe(prm);
                // Neither all lit nor all dark: there are comparisons to disagree about.
                EXPECT_GT(lit, 100) << describe(prm);
                EXPECT_GT(dark, 100) << describe(prm);
                worstMode = std::max(worstMode, worst);
            }
        }
        std::printf("parity random lookups, bias %s: max |GPU - CPU| = %g\n",
                    std::string(biasName(mode)).c_str(), static_cast<double>(worstMode));
    }
}

// Renders `s`, then runs the CPU kernel on the GPU's own targets: each receiver pixel's
// light-space lookup (u, v, ref after the per-lookup bias) with the receiver plane the shader
// wrote. Counts the receivers, those with a plane, and those whose plane the cap binds on.
struct RenderedParity {
    float worst = 0.0f;
    int receivers = 0;
    int planes = 0;
    int capped = 0;
};

RenderedParity renderAndCompare(SceneRenderer& renderer, const RenderSettings& s) {
    renderer.render(s);
    ShadowMap map = renderer.readShadowMap();
    std::vector<float> ls = renderer.readLightSpace();
    std::vector<float> rc = renderer.readReceiver();
    std::vector<float> vis = renderer.readVisibility();
    PcfBias bias = s.kernelBias();
    RenderedParity r;
    for (size_t k = 0; k < vis.size(); ++k) {
        if (ls[4 * k + 3] != 1.0f) continue;
        ++r.receivers;
        PcfBias b = bias;
        b.dzduv = glm::vec2(rc[4 * k], rc[4 * k + 1]);
        if (b.dzduv != glm::vec2(0.0f)) ++r.planes;
        if (pcfClampDzDuv(b.dzduv, s.rpdbMax) != b.dzduv) ++r.capped;
        float cpu = filterVisibility(map, glm::vec2(ls[4 * k], ls[4 * k + 1]), ls[4 * k + 2],
                                     renderer.pcfParams(s), b);
        r.worst = std::max(r.worst, std::fabs(cpu - vis[k]));
    }
    return r;
}

// Every bias mode rendered: the CPU kernel, run on the GPU's own light-space target (u, v, ref
// after the per-lookup bias) and receiver target (the dz/duv the shader derived), gives the
// visibility the shader gave, for every method the mode combines with.
// 32F with every method; the fixed-point formats (their D_ref clamp and read-back map) with one
// method of each fetch kind, so that every bias mode x format pair is rendered.
TEST_F(GpuParity, BiasModesRenderedMatchTheCpuKernelOnTheGpusOwnTargets) {
    Scene scene = *presetScene("grazing");
    SceneRenderer renderer(scene);
    for (int mode = 0; mode < PCF_BIAS_COUNT; ++mode) {
        float worstMode = 0.0f;
        for (TexelKind format : depthKinds(false)) {
            for (const PcfParams& prm : parityCases({3})) {
                if (validateBias(mode, prm.method)) continue;
                if (prm.method == PCF_TENT && prm.kernel != 5) continue;
                if (format != TexelKind::D32F && prm.method != PCF_NEAREST &&
                    prm.method != PCF_BILINEAR2X2 && prm.method != PCF_HW2X2 &&
                    prm.method != PCF_GATHER && prm.method != PCF_TENT)
                    continue;
                RenderSettings s;
                s.depthFormat = format;
                s.method = prm.method;
                s.kernel = prm.kernel;
                s.radius = prm.radius;
                s.bias = static_cast<BiasMode>(mode);
                s.mapSize = 256;
                s.frameSize = {200, 112};
                RenderedParity r = renderAndCompare(renderer, s);
                std::string what = std::string(biasName(mode)) + " " + describe(prm) + " " +
                                   std::string(depthFormatName(format));
                EXPECT_LE(r.worst, parityTolerance(prm.method)) << what;
                EXPECT_GT(r.receivers, s.frameSize.x * s.frameSize.y / 4) << what;
                // the shader wrote its receiver planes
                EXPECT_GT(r.planes, r.receivers / 2) << what;
                worstMode = std::max(worstMode, r.worst);
            }
        }
        std::printf("parity rendered grazing, bias %s, formats 32f/16/24: max |GPU - CPU| = %g\n",
                    std::string(biasName(mode)).c_str(), static_cast<double>(worstMode));
    }
}

// The receiver plane's cap (--rpdb-max) rendered: the receiver target holds the slope as the
// shader measured it, the kernel caps it on both sides, and the CPU gives what the GPU gave, with
// no cap, the default (it binds on no pixel of this small frame; bias_test's grazing test finds
// the outline pixels it binds on) and a cap below the ground's slope (most pixels).
TEST_F(GpuParity, ReceiverPlaneCapRenderedMatchesTheCpuKernel) {
    Scene scene = *presetScene("grazing");
    SceneRenderer renderer(scene);
    for (float cap : {PCF_DZDUV_UNCLAMPED, DEFAULT_RPDB_MAX, 0.5f}) {
        for (const PcfParams& prm : {makeParams(PCF_GATHER, 5), makeParams(PCF_NAIVE, 3),
                                     makeParams(PCF_HW, 3), makeParams(PCF_TENT, 5)}) {
            RenderSettings s;
            s.method = prm.method;
            s.kernel = prm.kernel;
            s.bias = BiasMode::ReceiverPlane;
            s.rpdbMax = cap;
            s.mapSize = 256;
            s.frameSize = {200, 112};
            RenderedParity r = renderAndCompare(renderer, s);
            std::string what = "cap " + std::to_string(cap) + " " + describe(prm);
            EXPECT_LE(r.worst, PARITY_TOLERANCE) << what;
            if (cap == 0.5f) {  // the ground: 1.3
                EXPECT_GT(r.capped, r.receivers / 2) << what;
            }
            std::printf(
                "parity rendered grazing, receiver-plane cap %g, %s: %d of %d capped, "
                "max |GPU - CPU| = %g\n",
                static_cast<double>(cap), describe(prm).c_str(), r.capped, r.receivers,
                static_cast<double>(r.worst));
        }
    }
}

}  // namespace
}  // namespace pcf

namespace pcf {
namespace {

// The moments pass (shaders/moments.frag) equals the CPU's (kernel/moments.h momentsMap) on
// the GPU's own depth map: every moment of every texel, for every moment method, both formats,
// box and Gaussian blurs. Relative to the moment's size: EVSM's warps reach 2e17 in 32F.
// 32F: within 1e-5 of the value (exp's last bits); 16F: within one half-float step (2^-10
// relative), where a last-bit difference before the rounding lands on the neighbouring half.
TEST_F(GpuParity, TheMomentsPassMatchesTheCpuOnTheGpusDepths) {
    Scene scene = *presetScene("box-on-plane");
    SceneRenderer renderer(scene);
    RenderSettings depthSettings;
    depthSettings.method = PCF_NAIVE;
    depthSettings.mapSize = 128;
    depthSettings.frameSize = {64, 48};
    renderer.render(depthSettings);
    ShadowMap depth = renderer.readShadowMap();
    int checked = 0;
    for (const MethodInfo& m : allMethods()) {
        if (!readsMoments(m.id)) continue;
        for (int bits : {32, 16}) {
            for (int weights : {PCF_WEIGHTS_BOX, PCF_WEIGHTS_GAUSSIAN}) {
                RenderSettings s = depthSettings;
                s.method = m.id;
                s.momentBits = bits;
                s.weights = weights;
                s.kernel = 5;
                renderer.render(s);
                ShadowMap gpu = renderer.readShadowMap();
                PcfParams prm = s.pcfParams();
                ShadowMap cpu = momentsMap(depth, prm, mapTexelKind(m.id, s.depthFormat, bits));
                ASSERT_EQ(gpu.spec(), cpu.spec()) << m.name;
                double relative = bits == 32 ? 1e-5 : std::ldexp(1.0, -10);
                float worst = 0.0f;
                for (size_t k = 0; k < cpu.depths().size(); ++k) {
                    float want = cpu.depths()[k];
                    float got = gpu.depths()[k];
                    float scale = std::max(1.0f, std::fabs(want));
                    worst = std::max(worst, std::fabs(got - want) / scale);
                    ++checked;
                }
                EXPECT_LE(worst, relative) << m.name << " " << bits << " weights " << weights;
            }
        }
    }
    EXPECT_GT(checked, 5 * 4 * 128 * 128 * 2);
}

}  // namespace
}  // namespace pcf
