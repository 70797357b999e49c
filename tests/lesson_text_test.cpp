// The live text of a lesson step: placeholders filled from a real trace of the kernel.
#include "lesson/lesson_text.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "kernel/methods.h"
#include "kernel/moments.h"
#include "kernel/trace.h"
#include "lesson/lesson_pick.h"

namespace pcf {
namespace {

// "What Is PCF"'s worked example on the built-in map: lit texels left, shadowed right, fx = 0.2.
Trace exampleTrace(int method, int kernel = 3) {
    return traceLookup(exampleShadowMap(), vec2(0.4625f, 0.3875f), 0.5f, 0.5f,
                       makeParams(method, kernel));
}

StepContext context() {
    StepContext ctx;
    ctx.pixel = {612, 388};
    ctx.settings.bias = BiasMode::None;
    ctx.settings.constantBias = 0.0025f;
    ctx.settings.cull = CullMode::Front;
    ctx.settings.depthFormat = TexelKind::D24;
    ctx.lightAngleDeg = 51.25f;
    ctx.originShift = 0.375f;
    ctx.partVisibility = {0.25f, 1.0f};
    return ctx;
}

std::string fill(const std::string& text, const Trace& tr) { return fillText(text, tr, context()); }

TEST(LessonText, FillsTheBilinearExampleFromTheTrace) {
    Trace tr = exampleTrace(PCF_BILINEAR2X2);
    EXPECT_EQ(fill("{frac.x}", tr), "0.2");
    EXPECT_EQ(fill("{frac.y}", tr), "0.6");
    EXPECT_EQ(fill("{visibility}", tr), "0.8");
    EXPECT_EQ(fill("{shadow}", tr), "0.2");
    EXPECT_EQ(fill("lerp({tap[0].lit}, {tap[1].lit}, {frac.x}) = {visibility}", tr),
              "lerp(1, 0, 0.2) = 0.8");
    EXPECT_EQ(fill("{uv.x} {uv.y} {z} {ref} {depth_bias}", tr), "0.4625 0.3875 0.5 0.5 0");
    EXPECT_EQ(fill("p = ({texel.x}, {texel.y}), base = ({base.x}, {base.y})", tr),
              "p = (3.2, 2.6), base = (3, 2)");
    EXPECT_EQ(fill("{1-frac.x} {1-frac.y}", tr), "0.8 0.4");
    EXPECT_EQ(fill("{method} {map_size} {taps} {texels} {gathers} {hw_taps} {fetches}", tr),
              "bilinear2x2 8 4 4 0 0 1");
    EXPECT_EQ(fill("{lit_count} lit, {shadowed_count} shadowed, {distinct} distinct", tr),
              "2 lit, 2 shadowed, 4 distinct");
}

TEST(LessonText, TapFieldsComeFromTheReadsInOrder) {
    Trace tr = exampleTrace(PCF_BILINEAR2X2);
    ASSERT_EQ(tr.taps.size(), 4u);
    EXPECT_EQ(
        fill("({tap[0].i}, {tap[0].j}) ({tap[1].i}, {tap[1].j}) ({tap[3].i}, {tap[3].j})", tr),
        "(3, 2) (4, 2) (4, 3)");
    EXPECT_EQ(fill("{tap[0].depth} {tap[1].depth}", tr),
              formatNumber(tr.taps[0].depth) + " " + formatNumber(tr.taps[1].depth));
    EXPECT_EQ(fill("{tap[0].depth}", tr), "0.57");
    EXPECT_EQ(fill("{tap[1].depth}", tr), "0.3");
    EXPECT_EQ(fill("{tap[2].ref}", tr), "0.5");
    // Bilinear weights (1-fx)(1-fy), fx(1-fy), (1-fx)fy, fx fy = .32, .08, .48, .12.
    EXPECT_EQ(fill("{tap[0].weight} {tap[1].weight} {tap[2].weight} {tap[3].weight}", tr),
              "0.32 0.08 0.48 0.12");
    EXPECT_EQ(fill("{tap[0].lit}{tap[1].lit}{tap[2].lit}{tap[3].lit}", tr), "1010");
    EXPECT_EQ(fill("{fetch[0].value} {fetch[0].weight} {fetch[0].u}", tr), "0.8 1 0.4625");
}

TEST(LessonText, DecimalsAndFactors) {
    Trace tr = exampleTrace(PCF_BILINEAR2X2);
    EXPECT_EQ(fill("{frac.x:3}", tr), "0.200");
    EXPECT_EQ(fill("{visibility:0}", tr), "1");
    EXPECT_EQ(fill("{visibility:2}", tr), "0.80");
    EXPECT_EQ(fill("{base.x:1}", tr), "3.0");
    EXPECT_EQ(fill("{tap[1].weight*100}%", tr), "8%");
    EXPECT_EQ(fill("{frac.x*10:1}", tr), "2.0");
    EXPECT_EQ(fill("{depth_bias:3}", tr), "0.000");
}

TEST(LessonText, BracesAndLiterals) {
    Trace tr = exampleTrace(PCF_BILINEAR2X2);
    EXPECT_EQ(fill("{{0, .25, .5, .75, 1}}", tr), "{0, .25, .5, .75, 1}");
    EXPECT_EQ(fill("{{{visibility}}}", tr), "{0.8}");
    EXPECT_EQ(fill("no placeholders at all", tr), "no placeholders at all");
    EXPECT_EQ(fill("", tr), "");
}

TEST(LessonText, GatherWeightTableIsSeed001sTableOverNine) {
    Trace tr = exampleTrace(PCF_GATHER);
    // N = 3: the footprint fraction equals frac (the offset -1 is whole).
    EXPECT_EQ(fill("{g.x} {g.y}", tr), "0.2 0.6");
    EXPECT_EQ(fill("{weights.origin.x},{weights.origin.y} {weights.w}x{weights.h}", tr), "2,1 4x4");
    // Per axis (1-g, 1, 1, g): row 0 times 9 is (1-gx)(1-gy), (1-gy), (1-gy), gx(1-gy).
    EXPECT_EQ(fill("{weight[0,0]*9} {weight[1,0]*9} {weight[2,0]*9} {weight[3,0]*9}", tr),
              "0.32 0.4 0.4 0.08");
    EXPECT_EQ(fill("{weight[0,1]*9} {weight[1,1]*9} {weight[2,2]*9} {weight[3,3]*9}", tr),
              "0.8 1 1 0.12");
    EXPECT_EQ(fill("{weight[1,1]:4}", tr), formatNumber(1.0f / 9.0f));
    // Outside the grid a texel was not read: weight 0.
    EXPECT_EQ(fill("{weight[4,0]} {weight[9,9]}", tr), "0 0");
    EXPECT_EQ(fill("{taps} {texels} {gathers} {distinct} {fetches}", tr), "16 16 4 16 4");
    EXPECT_EQ(fill("{visibility}", tr), formatNumber(tr.visibility));
}

TEST(LessonText, NaiveReadsThirtySixTexelsOfSixteen) {
    Trace tr = exampleTrace(PCF_NAIVE);
    EXPECT_EQ(fill("{taps} reads of {distinct} texels in {fetches} lookups", tr),
              "36 reads of 16 texels in 9 lookups");
    EXPECT_EQ(fill("{fetch[4].value}", tr), "0.8");  // the centre lookup is the bilinear one
    EXPECT_EQ(fill("{visibility}", tr), fill("{visibility}", exampleTrace(PCF_GATHER)));
}

TEST(LessonText, HardwareAndTentCounts) {
    EXPECT_EQ(fill("{hw_taps} {texels}", exampleTrace(PCF_HW)), "9 36");
    EXPECT_EQ(fill("{hw_taps}", exampleTrace(PCF_TENT, 3)), "4");
    EXPECT_EQ(fill("{hw_taps}", exampleTrace(PCF_TENT, 5)), "9");
    EXPECT_EQ(fill("{hw_taps} {kernel}", exampleTrace(PCF_TENT, 7)), "16 7");
    // q = uv * size = (3.7, 3.1); s = q + 0.5 - floor(q + 0.5) = 0.2, t = 0.6.
    EXPECT_EQ(fill("{tent.s} {tent.t}", exampleTrace(PCF_TENT, 3)), "0.2 0.6");
}

TEST(LessonText, PoissonRadiusAndRotation) {
    Trace tr = traceLookup(exampleShadowMap(), vec2(0.4625f, 0.3875f), 0.5f, 0.5f,
                           makeParams(PCF_POISSON, 3, 1.5f, PCF_ROTATIONS[4]));
    EXPECT_EQ(fill("{taps} {radius} {rotation}", tr), "16 1.5 90");
    EXPECT_EQ(fill("{lit_count}", tr), std::to_string(static_cast<int>(tr.visibility * 16.0f)));
}

// The widely copied 16-point set reaches 1.2339 from its centre (its 8th point, (0.9748, 0.7565)):
// the words "the farthest X texels from the centre" scale that by the radius the points are given.
TEST(LessonText, PoissonReachIsTheFarthestPointNotTheRadius) {
    Trace tr = traceLookup(exampleShadowMap(), vec2(0.4625f, 0.3875f), 0.5f, 0.5f,
                           makeParams(PCF_POISSON, 3, 1.5f, PCF_ROTATIONS[4]));
    EXPECT_EQ(fill("{disk_reach:3}", tr), "1.851");
    EXPECT_EQ(fill("{pcss.search_reach}", tr), "0");
    // pcss: the filter's points are scaled by filter_radius, the search's by search_radius.
    tr.params.method = PCF_PCSS;
    tr.pcss.filterRadius = 4.0f;
    tr.pcss.searchRadius = 7.0f;
    EXPECT_EQ(fill("{disk_reach:3} {pcss.search_reach:3}", tr), "4.936 8.638");
    EXPECT_EQ(fill("{disk_reach}", exampleTrace(PCF_GATHER)), "0");
}

TEST(LessonText, ContextNamesThePixelAndTheState) {
    Trace tr = exampleTrace(PCF_NEAREST);
    EXPECT_EQ(fill("({pixel.x}, {pixel.y}) {bias} {constant_bias} {cull} {depth_format}", tr),
              "(612, 388) none 0.0025 front 24");
    EXPECT_EQ(fill("{tap[0].i},{tap[0].j} {taps}", tr), "3,3 1");
    EXPECT_EQ(fill("{light_angle} {origin_shift}", tr), "51.25 0.375");
}

TEST(LessonText, StepContextNamesThePixelAndTheState) {
    LessonStep step;
    step.settings.bias = BiasMode::None;
    step.settings.cull = CullMode::Front;
    step.settings.depthFormat = TexelKind::D16;
    StepContext ctx = makeStepContext(step, {306, 194});
    EXPECT_EQ(ctx.pixel, glm::ivec2(306, 194));
    EXPECT_EQ(ctx.settings.bias, BiasMode::None);
    EXPECT_EQ(ctx.settings.cull, CullMode::Front);
    EXPECT_EQ(ctx.settings.depthFormat, TexelKind::D16);
}

TEST(LessonText, AnIndexPastTheTraceIsNotAvailable) {
    // Possible only when the viewer changed the method under a step's text.
    Trace tr = exampleTrace(PCF_NEAREST);
    EXPECT_EQ(fill("{tap[3].depth} {fetch[2].u}", tr), "n/a n/a");
}

// A step with `compare` reads its split view's parts (StepContext::partVisibility, in the
// spec's order); a part not known (no split, a key the parts cannot take) is "n/a", and a text
// naming a part past the step's compare is refused.
TEST(LessonText, PartsOfTheSplitViewAreTheContextsVisibilities) {
    Trace tr = exampleTrace(PCF_NEAREST);
    StepContext ctx = context();
    ctx.partVisibility = {0.0f, 0.75f, 1.0f};
    EXPECT_EQ(fillText("{part[0].visibility} {part[1].visibility} {part[2].visibility:2}", tr, ctx),
              "0 0.75 1.00");
    EXPECT_EQ(placeholderNumber("part[1].visibility*4", tr, ctx), 3.0);
    ctx.partVisibility.clear();
    EXPECT_EQ(fillText("{part[0].visibility}", tr, ctx), "n/a");
    EXPECT_FALSE(checkPlaceholders("{part[2].visibility}", 1, 1, 3));
    EXPECT_TRUE(checkPlaceholders("{part[2].visibility}", 1, 1, 2));
    EXPECT_TRUE(checkPlaceholders("{part[0].depth}"));
}

// A trace's map given three cascades (view depths 0.1..5, 5..20, 20..60; texels 0.01, 0.04,
// 0.12 world units wide) and its lookup said to be in the middle one, measured at 2.5 texels
// per pixel.
void makeCascaded(Trace& tr) {
    PcfMapLayer layer = tr.map.layers.front();
    const float depths[] = {0.1f, 5.0f, 20.0f, 60.0f};
    const float texels[] = {0.01f, 0.04f, 0.12f};
    tr.map.layers.clear();
    for (int k = 0; k < 3; ++k) {
        layer.viewDepth = vec2(depths[k], depths[k + 1]);
        layer.texelWs = texels[k];
        tr.map.layers.push_back(layer);
    }
    tr.layer = 1;
    tr.cascadeTexelsPerPixelMax = 2.5f;
    // In the blend band: cascade 2 weighs 0.25 and sees 0.4.
    tr.cascadeBlend = {2, 0.25f, 0.4f, tr.visibility + 0.25f * (0.4f - tr.visibility)};
}

// The cascade placeholders read the layer the lookup read; n/a with one map, and the density
// n/a where no frame measured it.
TEST(LessonText, CascadesAreTheLayerRead) {
    Trace tr = exampleTrace(PCF_NAIVE);
    EXPECT_EQ(fill("{cascade} {cascade.near}", tr), "n/a n/a");
    makeCascaded(tr);
    EXPECT_EQ(fill("{cascade} of {cascade.count}: {cascade.near} to {cascade.far}, texel "
                   "{cascade.texel_world}, {cascade.texels_per_pixel_max} per pixel",
                   tr),
              "1 of 3: 5 to 20, texel 0.04, 2.5 per pixel");
    tr.cascadeTexelsPerPixelMax = -1.0f;
    EXPECT_EQ(fill("{cascade.texels_per_pixel_max}", tr), "n/a");
}

// Two occluders side by side, 0.2 | 0.5 over a receiver at 0.6 (issue 33's example): a 3x3 box
// of the moments read halfway between the columns holds each depth half: mean 0.35, E[z^2]
// (0.04 + 0.25) / 2 = 0.145, variance 0.15^2, Chebyshev's bound 0.0225 / (0.0225 + 0.25^2).
Trace twoOccluderVsmTrace() {
    ShadowMap depth(16, 16);
    for (int j = 0; j < 16; ++j) {
        for (int i = 0; i < 16; ++i) depth.setDepth(i, j, i < 8 ? 0.2f : 0.5f);
    }
    PcfParams prm = makeParams(PCF_VSM, 3);
    return traceLookup(mapForMethod(depth, prm), vec2(0.5f), 0.6f, 0.6f, prm);
}

TEST(LessonText, MomentNamesComeFromTheMomentMethodsTrace) {
    Trace tr = twoOccluderVsmTrace();
    EXPECT_EQ(fill("{moment[0]} {moment[1]} {mean} {variance} {receiver} {bound} {visibility}", tr),
              "0.35 0.145 0.35 0.0225 0.6 0.2647 0.2647");
    EXPECT_EQ(fill("{lbr} {neg_bound}", tr), "0 1");
    // vsm's map holds two moments; a depth-comparing method has none.
    EXPECT_EQ(fill("{moment[2]}", tr), "n/a");
    EXPECT_EQ(fill("{mean} {moment[0]}", exampleTrace(PCF_NAIVE)), "n/a n/a");
    EXPECT_TRUE(checkPlaceholders("{moment[4]}"));
    EXPECT_TRUE(checkPlaceholders("{moment[0].x}"));
}

// The blend band's names: the next cascade, its weight, its own visibility and the mix the pixel
// shows; outside the band the weight is 0, no next cascade is named and the result is the
// cascade's own visibility; n/a with one map.
TEST(LessonText, TheBlendBandNamesBothLookups) {
    Trace tr = exampleTrace(PCF_NAIVE);
    EXPECT_EQ(fill("{cascade.blend_weight} {cascade.blended}", tr), "n/a n/a");
    makeCascaded(tr);
    tr.visibility = 0.8f;
    tr.cascadeBlend.blended = 0.7f;
    EXPECT_EQ(fill("{cascade.next} {cascade.blend_weight} {cascade.next_visibility} "
                   "{cascade.blended}",
                   tr),
              "2 0.25 0.4 0.7");
    tr.cascadeBlend = {};
    EXPECT_EQ(fill("{cascade.next} {cascade.blend_weight} {cascade.next_visibility} "
                   "{cascade.blended}",
                   tr),
              "n/a 0 n/a 0.8");
}

TEST(LessonText, EveryListedNameFills) {
    Trace naive = exampleTrace(PCF_NAIVE);
    makeCascaded(naive);  // the cascade's names fill for a cascaded map only
    Trace vsm = twoOccluderVsmTrace();
    for (std::string name : placeholderNames()) {
        for (std::string_view from : {"[K]", "[I,J]"}) {
            size_t at = name.find(from);
            if (at != std::string::npos)
                name.replace(at, from.size(), from == "[K]" ? "[1]" : "[1,1]");
        }
        std::string text = "{" + name + "}";
        EXPECT_FALSE(checkPlaceholders(text)) << name;
        // The moment methods' names fill from a moment method's trace.
        const bool moments =
            name.starts_with("moment[") || (fill(text, naive) == "n/a" && fill(text, vsm) != "n/a");
        std::string filled = fill(text, moments ? vsm : naive);
        EXPECT_FALSE(filled.empty()) << name;
        EXPECT_EQ(filled.find('{'), std::string::npos) << name;
        EXPECT_NE(filled, "n/a") << name;
    }
    EXPECT_GE(placeholderNames().size(), 40u);
}

TEST(LessonText, ChecksFindTheFirstProblemAndItsOffset) {
    EXPECT_FALSE(checkPlaceholders("{frac.x} and {{literal}} {tap[3].depth:2}"));
    auto p = checkPlaceholders("ok {frac.x} then {frac.z}");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->offset, 17u);
    EXPECT_EQ(p->problem,
              "unknown placeholder {frac.z} (did you mean {frac.x}?) (the names: "
              "docs/lesson-authoring.md#placeholders; write {{ for a literal brace)");
    // Every problem, read on past each.
    std::vector<PlaceholderProblem> all = placeholderProblems("{a} ok {frac.x} } {b:x} { end");
    ASSERT_EQ(all.size(), 4u);
    EXPECT_EQ(all[0].offset, 0u);
    EXPECT_EQ(all[1].offset, 16u);  // the lone }
    EXPECT_EQ(all[2].offset, 18u);
    EXPECT_EQ(all[3].offset, 24u);  // a { with no }
    p = checkPlaceholders("a } b");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->offset, 2u);
    p = checkPlaceholders("a { b");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->offset, 2u);
    EXPECT_TRUE(checkPlaceholders("{frac.x:x}"));
    EXPECT_TRUE(checkPlaceholders("{frac.x:12}"));
    EXPECT_TRUE(checkPlaceholders("{frac.x*}"));
    EXPECT_TRUE(checkPlaceholders("{method:2}"));
    EXPECT_TRUE(checkPlaceholders("{tap[-1].depth}"));
    EXPECT_TRUE(checkPlaceholders("{tap[0].colour}"));
    EXPECT_TRUE(checkPlaceholders("{weight[1]}"));
    EXPECT_TRUE(checkPlaceholders("{ frac.x }"));
    EXPECT_FALSE(checkPlaceholders("{tap[3].lit}", 4, 1));
    EXPECT_TRUE(checkPlaceholders("{tap[4].lit}", 4, 1));
    EXPECT_TRUE(checkPlaceholders("{fetch[1].value}", 4, 1));
}

TEST(LessonText, FillRefusesWhatTheCheckRefuses) {
    Trace tr = exampleTrace(PCF_BILINEAR2X2);
    EXPECT_THROW(fill("{nope}", tr), std::invalid_argument);
    EXPECT_THROW(fill("{", tr), std::invalid_argument);
}

}  // namespace
}  // namespace pcf

namespace pcf {
namespace {

// A count of one reads in the singular, whatever the words were written for.
TEST(LessonTextPlurals, OneTakesTheSingular) {
    EXPECT_EQ(singularAfterOne("1 lookups, 1 hardware taps and 1 texel reads."),
              "1 lookup, 1 hardware tap and 1 texel read.");
    EXPECT_EQ(singularAfterOne("(1 gathers)"), "(1 gather)");
    // Not a whole 1, or not a count word: unchanged.
    EXPECT_EQ(singularAfterOne("0.1 lookups, 21 taps, 1 lookupsy, 2 reads"),
              "0.1 lookups, 21 taps, 1 lookupsy, 2 reads");
    EXPECT_EQ(singularAfterOne("9 lookups"), "9 lookups");
}

}  // namespace
}  // namespace pcf
