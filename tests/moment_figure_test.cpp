// The moment methods' inspector figure (overlay/inspector_moments.h) and the footprint under it
// (kernel/moment_footprint.h): on a map whose depths are known (columns 0-63 at one depth,
// 64-127 at another, as in issue 33), the plan's histogram holds the texels the moments
// average, its curves pass through the trace's bounds at the receiver's t, msm's points are the
// trace's, and PCF of the same footprint is pcf-naive's; `trace --json` carries the footprint.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "json_lite.h"
#include "kernel/methods.h"
#include "kernel/moment_footprint.h"
#include "kernel/moments.h"
#include "kernel/trace.h"
#include "kernel/trace_explain.h"
#include "overlay/inspector.h"
#include "overlay/inspector_moments.h"
#include "render/image_io.h"
#include "run_command.h"

namespace pcf {
namespace {

ShadowMap twoColumns(float left, float right) {
    ShadowMap map(128, 128);
    for (int j = 0; j < 128; ++j) {
        for (int i = 0; i < 128; ++i) map.setDepth(i, j, i < 64 ? left : right);
    }
    return map;
}

// The lookup of issue 33: uv (0.5, 0.5), receiver z 0.6, no bias, N = 3, with the moments map
// the moments pass makes of `depth` and the footprint from `depth`.
Trace momentTrace(const ShadowMap& depth, PcfParams prm) {
    ShadowMap moments = momentsMap(depth, prm, mapTexelKind(prm.method, TexelKind::D32F));
    Trace tr = traceLookup(moments, vec2(0.5f), 0.6f, 0.6f, prm);
    addMomentFootprint(tr, depth);
    return tr;
}

PcfParams params(int method) {
    PcfParams prm = makeParams(method, 3);
    prm.evsmExponents = vec2(40.0f, 5.0f);
    prm.momentBias = 3e-5f;
    return prm;
}

// The plan a frame makes of the trace (1280x720, presentation), its first page.
MomentFigure plannedFigure(const Trace& tr) {
    InspectorModel m;
    m.trace = tr;
    m.presentation = true;
    InspectorLayout l = inspectorLayout({1280, 720}, true);
    m.sceneSize = glm::ivec2(l.scene.size());
    FramePlan plan = planFrame(l, m);
    EXPECT_TRUE(plan.moments.has_value());
    return plan.moments.value_or(MomentFigure{});
}

const MomentFigure::Bin* binOf(const MomentFigure& f, float depth) {
    for (const MomentFigure::Bin& b : f.bins) {
        if (depth >= b.lo && (depth < b.hi || b.hi == f.axisHi)) return &b;
    }
    return nullptr;
}

// The blur's 3 x 3 and the bilinear read at a texel corner cover 4 x 4 depths: two columns at
// 0.2, two at 0.5; the bilinear read halves the middle ones, so each depth carries half.
TEST(MomentFigure, TheHistogramHoldsTheFootprintsTexelsAndWeights) {
    Trace tr = momentTrace(twoColumns(0.2f, 0.5f), params(PCF_VSM));
    ASSERT_TRUE(tr.depths.present);
    EXPECT_EQ(tr.depths.texels.size(), 16u);
    MomentFigure f = plannedFigure(tr);
    ASSERT_TRUE(f.hasFootprint);
    const MomentFigure::Bin* near = binOf(f, 0.2f);
    const MomentFigure::Bin* far = binOf(f, 0.5f);
    ASSERT_TRUE(near && far);
    EXPECT_NE(near, far);
    EXPECT_EQ(near->texels, 8);
    EXPECT_EQ(far->texels, 8);
    EXPECT_NEAR(near->weight, 0.5f, 1e-6f);
    EXPECT_NEAR(far->weight, 0.5f, 1e-6f);
    int total = 0;
    for (const MomentFigure::Bin& b : f.bins) total += b.texels;
    EXPECT_EQ(total, 16);
    // The moments are the footprint's weighted moments: what the histogram shows is what they
    // average.
    double m1 = 0.0, m2 = 0.0;
    for (const FootprintTexel& t : tr.depths.texels) {
        m1 += t.weight * t.depth;
        m2 += t.weight * t.depth * t.depth;
    }
    EXPECT_NEAR(m1, tr.moments.moments.x, 1e-6);
    EXPECT_NEAR(m2, tr.moments.moments.y, 1e-6);
    // The receiver's t sits on the axis, right of both occluders.
    EXPECT_FLOAT_EQ(f.receiver, 0.6f);
    EXPECT_LE(f.axisLo, 0.2f);
    EXPECT_GE(f.axisHi, 0.6f);
}

// Off the texel corner the bilinear read weighs the columns unevenly: the footprint's weights
// are still the ones the moments average (the histogram's bars are their weights).
TEST(MomentFigure, TheFootprintsWeightsAreTheMomentsOffTheTexelCorner) {
    ShadowMap depth = twoColumns(0.2f, 0.5f);
    PcfParams prm = params(PCF_VSM);
    ShadowMap moments = momentsMap(depth, prm, mapTexelKind(prm.method, TexelKind::D32F));
    Trace tr = traceLookup(moments, vec2(0.5f + 0.3f / 128.0f, 0.5f), 0.6f, 0.6f, prm);
    addMomentFootprint(tr, depth);
    double m1 = 0.0, m2 = 0.0, nearWeight = 0.0;
    for (const FootprintTexel& t : tr.depths.texels) {
        m1 += t.weight * t.depth;
        m2 += t.weight * t.depth * t.depth;
        if (t.depth == 0.2f) nearWeight += t.weight;
    }
    EXPECT_NEAR(m1, tr.moments.moments.x, 1e-6);
    EXPECT_NEAR(m2, tr.moments.moments.y, 1e-6);
    // p.x = 63.8: the read takes 0.2 of moments texel 63 (two of its box's three columns at
    // 0.2) and 0.8 of texel 64 (one of three): 0.2 * 2/3 + 0.8 * 1/3 = 0.4.
    EXPECT_NEAR(nearWeight, 0.4, 1e-5);  // (uv in float: frac is 0.8 to 1e-6)
    MomentFigure f = plannedFigure(tr);
    EXPECT_NEAR(binOf(f, 0.2f)->weight, nearWeight, 1e-6);
}

// The curve passes through the trace's bound at t (0.2647, light bleeding), and with LBR 0.3
// the linstep's curve through the visibility (0); PCF of the same footprint says 0 (every
// depth is in front of the receiver).
TEST(MomentFigure, TheVsmCurveAtTIsTheTracesBoundAndPcfBesideIsBoxPcf) {
    ShadowMap depth = twoColumns(0.2f, 0.5f);
    Trace tr = momentTrace(depth, params(PCF_VSM));
    MomentFigure f = plannedFigure(tr);
    ASSERT_EQ(f.curves.size(), 1u);
    EXPECT_EQ(f.curves[0].atReceiver, tr.moments.bound);
    EXPECT_NEAR(f.curves[0].atReceiver, 0.2647f, 2e-3f);
    auto at = std::find_if(f.curves[0].points.begin(), f.curves[0].points.end(),
                           [&](glm::vec2 p) { return p.x == f.receiver; });
    ASSERT_NE(at, f.curves[0].points.end());
    EXPECT_EQ(at->y, tr.moments.bound);
    // 1 up to the mean (Chebyshev's bound says nothing there).
    EXPECT_EQ(f.curves[0].points.front().y, 1.0f);
    Trace box = traceLookup(depth, vec2(0.5f), 0.6f, 0.6f, makeParams(PCF_NAIVE, 3));
    EXPECT_EQ(f.pcfVisibility, box.visibility);
    EXPECT_EQ(f.pcfVisibility, 0.0f);

    PcfParams lbr = params(PCF_VSM);
    lbr.lbr = 0.3f;
    Trace cut = momentTrace(depth, lbr);
    MomentFigure g = plannedFigure(cut);
    ASSERT_EQ(g.curves.size(), 2u);
    EXPECT_TRUE(g.curves[1].afterLbr);
    EXPECT_EQ(g.curves[0].atReceiver, cut.moments.bound);
    EXPECT_EQ(g.curves[1].atReceiver, cut.visibility);
    EXPECT_EQ(cut.visibility, 0.0f);
}

// One occluder at 0.3 beside the lit receiver's own depth: the bound is exact, VSM's 0.5 is box
// PCF's.
TEST(MomentFigure, OneOccluderTheBoundEqualsPcfBeside) {
    Trace tr = momentTrace(twoColumns(0.3f, 0.6f), params(PCF_VSM));
    MomentFigure f = plannedFigure(tr);
    EXPECT_NEAR(f.curves[0].atReceiver, 0.5f, 2e-3f);
    EXPECT_NEAR(f.pcfVisibility, 0.5f, 1e-6f);
}

// evsm4: one curve per warp, each through its bound at t, the smaller taken, the exponents the
// ones used.
TEST(MomentFigure, Evsm4DrawsBothWarpsAndTakesTheSmaller) {
    Trace tr = momentTrace(twoColumns(0.2f, 0.5f), params(PCF_EVSM4));
    MomentFigure f = plannedFigure(tr);
    ASSERT_EQ(f.curves.size(), 2u);
    const MomentFigure::Curve& pos = f.curves[0];
    const MomentFigure::Curve& neg = f.curves[1];
    EXPECT_EQ(pos.warp, 1);
    EXPECT_EQ(neg.warp, -1);
    EXPECT_EQ(pos.atReceiver, tr.moments.bound);
    EXPECT_EQ(neg.atReceiver, tr.moments.negBound);
    EXPECT_EQ(pos.exponent, tr.params.evsmExponents.x);
    EXPECT_EQ(neg.exponent, tr.params.evsmExponents.y);
    EXPECT_NE(pos.taken, neg.taken);
    const MomentFigure::Curve& taken = pos.taken ? pos : neg;
    EXPECT_EQ(taken.atReceiver, std::min(tr.moments.bound, tr.moments.negBound));
    EXPECT_EQ(tr.visibility, taken.atReceiver);  // lbr 0: the smaller bound is the visibility
    EXPECT_LT(tr.visibility, 1e-3f);
}

// msm: the points stood on the histogram are the trace's reconstruction, depths and weights.
TEST(MomentFigure, MsmPointsAreTheTracesReconstruction) {
    for (int method : {PCF_MSM, PCF_MSM_HAUSDORFF}) {
        Trace tr = momentTrace(twoColumns(0.2f, 0.5f), params(method));
        MomentFigure f = plannedFigure(tr);
        EXPECT_TRUE(f.curves.empty());
        ASSERT_GE(f.points.size(), 3u);
        for (size_t k = 0; k < f.points.size(); ++k) {
            EXPECT_EQ(f.points[k].x, tr.moments.points[static_cast<int>(k)]);
            EXPECT_EQ(f.points[k].y, tr.moments.weights[static_cast<int>(k)]);
        }
        EXPECT_NEAR(tr.visibility, 0.0016f, 5e-4f);
    }
}

// A predict step that hides the result: the page draws the histogram and the curve but no value
// read off it, no number of the result anywhere, and says the numbers are hidden.
TEST(MomentFigure, AHiddenResultIsNotReadOffTheCurve) {
    Trace tr = momentTrace(twoColumns(0.2f, 0.5f), params(PCF_VSM));
    InspectorModel m;
    m.trace = tr;
    m.presentation = true;
    m.hidden.visibility = true;
    InspectorLayout l = inspectorLayout({1280, 720}, true);
    m.sceneSize = glm::ivec2(l.scene.size());
    int masked = 0, curves = 0;
    for (int page = 0; page < 2; ++page) {
        m.textPage = page;
        for (const LayoutBox& b : planFrame(l, m).boxes) {
            EXPECT_NE(b.role, "moment-value");
            EXPECT_EQ(b.text.find(formatNumber(tr.visibility)), std::string::npos) << b.text;
            masked += b.role == "masked";
            curves += b.role == "moment-curve";
        }
    }
    EXPECT_GT(masked, 0);
    EXPECT_GT(curves, 0);
}

// The header's counts say what a moment method reads: one bilinear read of the filtered moments,
// four texels of the moments map, not four depths compared as a depth method's texel reads are
// (pcf-naive beside it, on the same depths).
TEST(MomentFigure, TheHeaderSaysTheMomentsAreReadBilinearly) {
    auto counts = [](const Trace& tr) {
        InspectorModel m;
        m.trace = tr;
        InspectorLayout l = inspectorLayout({1600, 900}, false);
        m.sceneSize = glm::ivec2(l.scene.size());
        std::string words;
        for (const LayoutBox& b : planFrame(l, m).boxes) {
            if (b.role == "counts") words += b.text + " ";
        }
        return words;
    };
    int moments = 0;
    for (const MethodInfo& info : allMethods()) {
        if (!readsMoments(info.id)) continue;
        ++moments;
        std::string words = counts(momentTrace(twoColumns(0.2f, 0.5f), params(info.id)));
        EXPECT_NE(words.find("1 bilinear read of the filtered moments (4 texels)"),
                  std::string::npos)
            << info.name << ": " << words;
        EXPECT_EQ(words.find("texel reads"), std::string::npos) << info.name << ": " << words;
    }
    EXPECT_EQ(moments, 5);
    Trace naive = traceLookup(twoColumns(0.2f, 0.5f), vec2(0.5f), 0.6f, 0.6f, params(PCF_NAIVE));
    std::string words = counts(naive);
    EXPECT_NE(words.find("36 texel reads"), std::string::npos) << words;
    EXPECT_EQ(words.find("bilinear read"), std::string::npos) << words;
}

// `trace --map FILE --method vsm --json`: the moments made of FILE's depths, and the depths
// themselves with their weights and PCF of them; the text trace says PCF's value.
TEST(MomentFigure, TraceJsonCarriesTheFootprint) {
    std::filesystem::path dir = testutil::makeTempDir("moment_figure");
    std::string file = (dir / "map.exr").string();
    writeDepthImage(file, twoColumns(0.2f, 0.5f));
    auto r =
        testutil::runPcfscope("trace --map " + file + " --uv 0.5,0.5 --z 0.6 --method vsm --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    jsonlite::Value j = jsonlite::parse(r.out);
    const jsonlite::Value& fp = j["moments"]["footprint"];
    EXPECT_EQ(fp["pcf_method"].string, "pcf-naive");
    EXPECT_EQ(fp["pcf_visibility"].number, 0.0);
    ASSERT_EQ(fp["texels"].array.size(), 16u);
    int near = 0, far = 0;
    double weights = 0.0;
    for (const jsonlite::Value& t : fp["texels"].array) {
        near += std::abs(t["depth"].number - 0.2) < 1e-6;
        far += std::abs(t["depth"].number - 0.5) < 1e-6;
        weights += t["weight"].number;
    }
    EXPECT_EQ(near, 8);
    EXPECT_EQ(far, 8);
    EXPECT_NEAR(weights, 1.0, 1e-6);
    auto text = testutil::runPcfscope("trace --map " + file + " --uv 0.5,0.5 --z 0.6 --method vsm");
    EXPECT_NE(text.out.find("pcf-naive of the same 16 depth texels at the same ref: 0."),
              std::string::npos)
        << text.out;
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pcf
