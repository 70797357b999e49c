// The bench's sweep on llvmpipe: every method's error falls as the shadow map grows, pcf-naive
// and pcf-gather (the same filter, read two ways) have the same error, and each row carries the
// fetch counts and timings it promises.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>
#include <variant>

#include "charts/speed_chart.h"
#include "kernel/methods.h"
#include "measure/bench.h"
#include "measure/bench_report.h"
#include "render/gl_context.h"
#include "scene/presets.h"

namespace pcf {
namespace {

// The problem's sentence in the sweep's own words, or "" for none.
std::string problemText(const std::optional<ParamProblem>& p) { return p ? p->text() : ""; }

class BenchSweep : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;

    // One sweep over the whole scene; cheap timings (the test is about errors).
    static std::vector<BenchRow> sweep(const std::string& sceneName, BenchOptions o, int spp) {
        return sweep(*presetScene(sceneName), o, spp);
    }
    static std::vector<BenchRow> sweep(const Scene& scene, BenchOptions o, int spp) {
        GroundTruthOptions t;
        t.spp = spp;
        GroundTruth truth = computeGroundTruth(scene, o.frameSize, t);
        SceneRenderer renderer(scene);
        BenchContext context;
        context.renderer = &renderer;
        context.truth = &truth;
        context.scene = &scene;
        int progress = 0;
        int points = 0;
        context.progress = [&](int index, int total, const BenchPoint&) {
            EXPECT_EQ(index, progress++);
            EXPECT_EQ(total, static_cast<int>(benchPoints(o).size()));
        };
        context.onPoint = [&](const BenchRow&, std::span<const float> visibility,
                              const ErrorRegions& regions) {
            EXPECT_EQ(visibility.size(), truth.pixelCount());
            EXPECT_GT(regions.comparedCount, 0);
            ++points;
        };
        int rounds = 0;
        context.roundProgress = [&](int round, int total) {
            EXPECT_EQ(round, rounds++);
            EXPECT_EQ(total, o.gpuRepeats);
        };
        std::vector<BenchRow> rows = runBench(context, o);
        EXPECT_EQ(points, static_cast<int>(rows.size()));
        EXPECT_EQ(rounds, o.gpuRepeats);
        return rows;
    }
};
std::unique_ptr<GlContext> BenchSweep::sContext;

BenchOptions cheapOptions() {
    BenchOptions o;
    o.frameSize = {480, 270};
    o.gpuRepeats = 1;
    o.cpuLookups = 2048;
    o.cpuPasses = 1;
    o.shimmerFrames = 0;
    o.cleanStride = 3;
    return o;
}

// box-on-plane without the box: the truth is fully lit everywhere, so every dark pixel is acne.
Scene bareGround() {
    Scene scene = *presetScene("box-on-plane");
    std::erase_if(scene.objects,
                  [](const SceneObject& o) { return !std::holds_alternative<Plane>(o.shape); });
    return scene;
}

// The error split (bench.h): with no bias a map holding the lit ground's own front faces shadows
// that ground (acne); a constant bias clears it. Nothing is umbra, so nothing can leak.
TEST_F(BenchSweep, AcneIsFalseShadowOnAFullyLitGroundAndABiasClearsIt) {
    BenchOptions o = cheapOptions();
    o.methods = {PCF_NEAREST, PCF_GATHER};
    o.kernels = {3};
    o.mapSizes = {256};
    o.base.cull = CullMode::Back;  // the ground is in the map
    o.base.bias = BiasMode::None;
    Scene ground = bareGround();
    std::vector<BenchRow> none = sweep(ground, o, 2);
    o.base.bias = BiasMode::Constant;
    o.base.constantBias = 0.01f;
    std::vector<BenchRow> biased = sweep(ground, o, 2);
    ASSERT_EQ(none.size(), 2u);
    ASSERT_EQ(biased.size(), 2u);
    for (size_t k = 0; k < 2; ++k) {
        std::string name = pointName(none[k].point);
        std::printf("%-16s acne none %.4f (darkening %.4f over %d), constant 0.01 %.4f\n",
                    name.c_str(), none[k].acne.share, none[k].acne.mean, none[k].acne.count,
                    biased[k].acne.share);
        EXPECT_GT(none[k].acne.count, 1000) << name;  // clean lit pixels: most of the ground
        EXPECT_EQ(none[k].leak.count, 0) << name;     // no umbra anywhere
        EXPECT_EQ(none[k].leak.share, 0.0) << name;
        EXPECT_GT(none[k].acne.share, 0.05) << name;
        EXPECT_GT(none[k].acne.mean, 0.0) << name;
        EXPECT_EQ(biased[k].acne.count, none[k].acne.count) << name;
        EXPECT_EQ(biased[k].acne.share, 0.0) << name;
        EXPECT_LT(biased[k].acne.mean, 1e-6) << name;  // float rounding of the weights only
    }
}

// Shimmer (bench.h): as the map's grid slides under the still world, a nearest pixel jumps all
// the way between 0 and 1, a 5x5 gather's by a small step, and both do move.
TEST_F(BenchSweep, ShimmerOfNearestIsAboveAGathersAndBothMove) {
    BenchOptions o = cheapOptions();
    o.methods = {PCF_NEAREST, PCF_GATHER};
    o.kernels = {5};
    o.mapSizes = {256};
    o.shimmerFrames = 6;
    std::vector<BenchRow> rows = sweep("box-on-plane", o, 2);
    ASSERT_EQ(rows.size(), 2u);
    const ShimmerStats& nearest = rows[0].shimmer;
    const ShimmerStats& gather = rows[1].shimmer;
    std::printf("shimmer p99 nearest %.4f gather5 %.4f; flicker share %.4f %.4f\n",
                nearest.flickerP99, gather.flickerP99, nearest.flickerShare, gather.flickerShare);
    EXPECT_FLOAT_EQ(nearest.flickerP99, 1.0f);
    EXPECT_GT(gather.flickerP99, 0.0);
    EXPECT_LT(gather.flickerP99, 0.5 * nearest.flickerP99);
    EXPECT_GT(nearest.flickerShare, 0.0);
    EXPECT_GT(gather.flickerShare, 0.0);
    EXPECT_LT(nearest.flickerShare, 0.5);  // only the pixels near the edge move
}

TEST_F(BenchSweep, ErrorFallsAsTheMapGrowsForEveryMethod) {
    BenchOptions o = cheapOptions();
    o.kernels = {3};
    o.mapSizes = {128, 256, 512, 1024};
    // The methods that compare depths under the bench's front culling; the moment methods with
    // the casters' lit faces in the map (back faces culled, their MethodInfo's
    // wantsLitFacesInMap), which their bound needs.
    std::vector<BenchRow> rows = sweep("box-on-plane", o, 4);
    ASSERT_EQ(rows.size(), allMethods().size() * 4u);
    for (size_t k = 0; k < rows.size(); k += 4) {
        std::string name = pointName(rows[k].point);
        std::printf("%-16s edge RMSE", name.c_str());
        for (size_t m = 0; m < 4; ++m) std::printf(" %.4f", rows[k + m].error.edgeRmse);
        std::printf("   RMSE");
        for (size_t m = 0; m < 4; ++m) std::printf(" %.4f", rows[k + m].error.rmse);
        std::printf("\n");
        for (size_t m = 0; m < 4; ++m) {
            ASSERT_EQ(rows[k + m].point.method, rows[k].point.method);
            EXPECT_EQ(rows[k + m].point.mapSize, o.mapSizes[m]);
        }
        // Non-increasing step by step (to a hair of noise from where texel edges happen to
        // fall), and clearly lower at 1024 than at 128.
        for (size_t m = 1; m < 4; ++m) {
            EXPECT_LE(rows[k + m].error.edgeRmse, rows[k + m - 1].error.edgeRmse * 1.02)
                << name << " map " << o.mapSizes[m];
            EXPECT_LE(rows[k + m].error.rmse, rows[k + m - 1].error.rmse * 1.02)
                << name << " map " << o.mapSizes[m];
        }
        EXPECT_LT(rows[k + 3].error.edgeRmse, 0.6 * rows[k].error.edgeRmse) << name;
        EXPECT_LT(rows[k + 3].error.rmse, rows[k].error.rmse) << name;
    }
}

// The moment methods are on the bench's chart and in its CSV beside the depth-comparing ones,
// measured with the faces their bound needs: by default bench culls back faces for them
// (MethodInfo::wantsLitFacesInMap) and front faces for the others; with one culling for all
// (--cull front) the light leaks under the box, whose bottom face rests on the ground.
TEST_F(BenchSweep, MomentMethodsAreMeasuredWithTheLitFacesInTheirMap) {
    BenchOptions o = cheapOptions();
    o.kernels = {3};
    o.mapSizes = {256};
    o.methods = {PCF_GATHER, PCF_VSM, PCF_MSM};
    EXPECT_EQ(benchCull(o, PCF_GATHER), CullMode::Front);
    EXPECT_EQ(benchCull(o, PCF_VSM), CullMode::Back);
    std::vector<BenchRow> byMethod = sweep("box-on-plane", o, 2);
    o.cullByMethod = false;
    EXPECT_EQ(benchCull(o, PCF_VSM), CullMode::Front);
    std::vector<BenchRow> front = sweep("box-on-plane", o, 2);
    ASSERT_EQ(byMethod.size(), 3u);
    ASSERT_EQ(front.size(), 3u);
    // pcf-gather: the same front culling either way, the same error.
    EXPECT_EQ(byMethod[0].error.edgeRmse, front[0].error.edgeRmse);
    for (size_t k : {1u, 2u}) {
        SCOPED_TRACE(pointName(byMethod[k].point));
        // Measured (480x270, a 256 map): vsm's edge RMSE 0.26 against 0.56, msm's 0.27
        // against 0.28; the share of the clean umbra leaking 0.03 and 0.04 against 0.64 and 0.66.
        EXPECT_LT(byMethod[k].error.edgeRmse, front[k].error.edgeRmse);
        EXPECT_LT(byMethod[k].leak.share, 0.2 * front[k].leak.share);
    }
    EXPECT_LT(byMethod[1].error.edgeRmse, 0.7 * front[1].error.edgeRmse);
    // On the chart: a dot per row inside the plot; in the CSV: a line per row, by name.
    SpeedChartLayout layout = layoutSpeedChart(byMethod, {1280, 720});
    for (size_t k = 0; k < byMethod.size(); ++k) {
        Rect dot = speedChartDotBox(layout, k);
        EXPECT_GT(dot.w, 0.0f);
        EXPECT_TRUE(dot.x >= 0.0f && dot.right() <= 1280.0f && dot.y >= 0.0f &&
                    dot.bottom() <= 720.0f);
    }
    std::string csv = benchCsv(byMethod);
    EXPECT_NE(csv.find("\nvsm,3,256,"), std::string::npos);
    EXPECT_NE(csv.find("\nmsm,3,256,"), std::string::npos);
}

TEST_F(BenchSweep, NaiveAndGatherHaveTheSameError) {
    BenchOptions o = cheapOptions();
    o.methods = {PCF_NAIVE, PCF_GATHER, PCF_HW};
    o.kernels = {2, 3, 5};
    o.mapSizes = {256, 1024};
    std::vector<BenchRow> rows = sweep("sphere-over-plane", o, 2);
    std::map<std::pair<int, int>, std::map<int, ErrorStats>> byPoint;
    for (const BenchRow& r : rows)
        byPoint[{r.point.kernel, r.point.mapSize}][r.point.method] = r.error;
    ASSERT_EQ(byPoint.size(), 6u);
    for (auto& [key, errors] : byPoint) {
        const ErrorStats& naive = errors.at(PCF_NAIVE);
        for (int other : {PCF_GATHER, PCF_HW}) {
            const ErrorStats& e = errors.at(other);
            std::string what = std::string(methodInfo(other).name) +
                               " N=" + std::to_string(key.first) + " map " +
                               std::to_string(key.second);
            EXPECT_NEAR(e.rmse, naive.rmse, 1e-6) << what;
            EXPECT_NEAR(e.edgeRmse, naive.edgeRmse, 1e-6) << what;
            EXPECT_NEAR(e.maxErr, naive.maxErr, 1e-5) << what;
            EXPECT_NEAR(e.edgeMaxErr, naive.edgeMaxErr, 1e-5) << what;
            EXPECT_EQ(e.pixels, naive.pixels);
        }
        EXPECT_GT(naive.edgeRmse, 0.0);
    }
}

TEST_F(BenchSweep, RowsCarryFetchCountsTimingsAndTheTimer) {
    BenchOptions o = cheapOptions();
    o.methods = {PCF_TENT, PCF_NEAREST, PCF_GATHER};
    o.kernels = {3, 4, 7};
    o.mapSizes = {64, 128};
    o.gpuRepeats = 3;
    std::vector<BenchRow> rows = sweep("box-on-plane", o, 2);
    // Report order: the methods as given; tent skips N = 4; nearest runs once per map.
    std::vector<BenchPoint> want = {
        {PCF_TENT, 3, 64},    {PCF_TENT, 3, 128},    {PCF_TENT, 7, 64},   {PCF_TENT, 7, 128},
        {PCF_NEAREST, 0, 64}, {PCF_NEAREST, 0, 128}, {PCF_GATHER, 3, 64}, {PCF_GATHER, 3, 128},
        {PCF_GATHER, 4, 64},  {PCF_GATHER, 4, 128},  {PCF_GATHER, 7, 64}, {PCF_GATHER, 7, 128},
    };
    ASSERT_EQ(rows.size(), want.size());
    for (size_t k = 0; k < rows.size(); ++k) {
        const BenchRow& r = rows[k];
        EXPECT_EQ(r.point, want[k]) << k;
        int n = r.point.kernel > 0 ? r.point.kernel : 3;
        EXPECT_EQ(r.texelReads, fetchCounts(r.point.method, n).texels) << k;
        EXPECT_GT(r.gpuMs, 0.0) << k;
        EXPECT_GE(r.gpuMsIqr, 0.0) << k;
        EXPECT_GT(r.lookupMs, 0.0) << k;
        EXPECT_GE(r.lookupMsIqr, 0.0) << k;
        EXPECT_EQ(r.noisy, r.gpuMsIqr > NOISY_IQR_SHARE * r.gpuMs ||
                               r.lookupMsIqr > NOISY_IQR_SHARE * r.lookupMs)
            << k;
        EXPECT_GT(r.cpuNsPerPixel, 0.0) << k;
        EXPECT_EQ(r.cpuPixels, 2048) << k;
        // The passes' CPU time where the CPU renders, and none where a GPU's timer measured.
        bool software = isSoftwareRenderer(sContext->renderer());
        EXPECT_EQ(r.gpuCpuMs > 0.0, software) << k;
        EXPECT_EQ(r.lookupCpuMs > 0.0, software) << k;
        EXPECT_EQ(r.timer,
                  isSoftwareRenderer(sContext->renderer()) ? TIMER_WALL_CLOCK : TIMER_GPU_QUERY);
    }
    EXPECT_EQ(rows[0].texelReads, 16);   // tent 3x3: 4 hardware taps
    EXPECT_EQ(rows[6].texelReads, 16);   // gather 3x3: 4 gathers
    EXPECT_EQ(rows[10].texelReads, 64);  // gather 7x7: 16 gathers
}

TEST(BenchOptionsCheck, NamesTheOptionThatIsOutOfRange) {
    BenchOptions o;
    o.kernels = {3, 9};
    EXPECT_EQ(problemText(validateBenchOptions(o)), "kernels 9 is out of range (1..8)");
    EXPECT_EQ(validateBenchOptions(o)->setting, "kernels");
    o = BenchOptions{};
    o.mapSizes = {3};
    EXPECT_EQ(problemText(validateBenchOptions(o)), "map_sizes 3 is out of range (4..4096)");
    o = BenchOptions{};
    o.methods = {PCF_TENT};
    o.kernels = {2, 4};
    EXPECT_NE(problemText(validateBenchOptions(o)).find("tent takes kernels 3, 5 or 7"),
              std::string::npos);
    EXPECT_FALSE(validateBenchOptions(BenchOptions{}).has_value());
    EXPECT_FALSE(validateBenchOptions(quickBenchOptions()).has_value());
    // The defaults: 6 one-shot methods (nearest, box2x2, bilinear2x2, hw2x2, poisson, pcss) + 9
    // kernel methods (pcf-naive, pcf-gather, pcf-hw, tent and the 5 moment methods) x 3 sizes,
    // at 4 map sizes; --quick: N = 3 at 2 map sizes.
    EXPECT_EQ(benchPoints(BenchOptions{}).size(), (6u + 9u * 3u) * 4u);
    EXPECT_EQ(benchPoints(quickBenchOptions()).size(), (6u + 9u) * 2u);
    // A weighting list repeats the methods that take weights (pcf-naive, pcf-gather and the 5
    // moment methods, whose moments pass blurs with them).
    o = BenchOptions{};
    o.weights = {PCF_WEIGHTS_BOX, PCF_WEIGHTS_BINOMIAL, PCF_WEIGHTS_GAUSSIAN};
    EXPECT_EQ(benchPoints(o).size(), (6u + 9u * 3u) * 4u + 7u * 2u * 3u * 4u);
    o.weights = {PCF_WEIGHTS_GAUSSIAN};
    EXPECT_NE(problemText(validateBenchOptions(o)).find("pcf-naive and pcf-gather only"),
              std::string::npos);
    o.methods = {PCF_GATHER};
    EXPECT_FALSE(validateBenchOptions(o).has_value());
    o.truthSpp = 1;
    EXPECT_EQ(problemText(validateBenchOptions(o)), "spp 1 is out of range (2..64)");
    // The kernel's own check of the weights, passed on with its setting named.
    o.truthSpp = DEFAULT_TRUTH_SPP;
    o.weights = {PCF_WEIGHTS_GAUSSIAN};
    o.sigma = 100.0f;
    EXPECT_EQ(validateBenchOptions(o)->setting, "sigma");
}

}  // namespace
}  // namespace pcf
