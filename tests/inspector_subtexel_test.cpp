// The inspector's hw8 view (inspector_subtexel.cpp, issue 10): with the texture unit's 8-bit
// position model on, the cells' panel gains an inset of the 1/256-texel lattice and the fx/fy
// labels add the 8-bit fraction k/256; with the float model the frame has neither. Planned
// without GL (planFrame measures text with FreeType only).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "kernel/methods.h"
#include "kernel/trace.h"
#include "overlay/inspector.h"

namespace pcf {
namespace {

constexpr int MAP = 16;

// A map whose left half is near the light (0.2) and right half far (0.9): a lookup between
// columns 7 and 8 has lit and shadowed taps.
ShadowMap stepMap() {
    ShadowMap map(MAP, MAP, 0.9f);
    for (int j = 0; j < MAP; ++j) {
        for (int i = 0; i < MAP / 2; ++i) map.setDepth(i, j, 0.2f);
    }
    return map;
}

// uv of the texel position p (GL's convention: p = uv * size - 0.5).
vec2 uvOf(vec2 p) { return (p + vec2(0.5f)) / float(MAP); }

struct Planned {
    Trace trace;
    FramePlan plan;
    InspectorLayout layout;
};

Planned plan(const ShadowMap& map, vec2 p, int method, int precision, glm::ivec2 size,
             bool presentation) {
    PcfParams prm = makeParams(method);
    prm.precision = precision;
    Planned out;
    out.trace = traceLookup(map, uvOf(p), 0.5f, 0.5f, prm);
    out.layout = inspectorLayout(size, presentation);
    InspectorModel m;
    m.title = "hw8";
    m.stepTitles = {"one"};
    m.stepText = "text";
    m.trace = out.trace;
    m.map = &map;
    m.sceneSize = glm::ivec2(out.layout.scene.size());
    m.pixel = m.sceneSize / 2;
    m.presentation = presentation;
    out.plan = planFrame(out.layout, m);
    return out;
}

const LayoutBox* find(const FramePlan& plan, const std::string& role) {
    for (const LayoutBox& b : plan.boxes) {
        if (b.role == role) return &b;
    }
    return nullptr;
}

bool overlaps(const Rect& a, const Rect& b) { return !a.intersect(b).empty(); }

TEST(InspectorSubtexel, Hw8LabelsShowTheKernelsEightBitFractionAsKOver256) {
    ShadowMap map = stepMap();
    // p = (7 + 48.4/256, 9 + 200.6/256): rounds to 48/256 and 201/256.
    vec2 p(7.0f + 48.4f / 256.0f, 9.0f + 200.6f / 256.0f);
    Planned h = plan(map, p, PCF_HW2X2, PCF_PRECISION_HW8, {1280, 720}, false);
    ASSERT_EQ(h.trace.fracHw8.x * 256.0f, 48.0f);
    ASSERT_EQ(h.trace.fracHw8.y * 256.0f, 201.0f);
    const LayoutBox* fx = find(h.plan, "fx-hw8");
    const LayoutBox* fy = find(h.plan, "fy-hw8");
    ASSERT_NE(fx, nullptr);
    ASSERT_NE(fy, nullptr);
    EXPECT_EQ(fx->text, "48/256");
    EXPECT_EQ(fy->text, "201/256");
    // The float fraction stays, with the four decimals that tell it from k/256.
    EXPECT_EQ(find(h.plan, "fx")->text, "fx 0.1891");
    EXPECT_EQ(find(h.plan, "fy")->text, "fy 0.7836");
    // The 8-bit line sits under the float one, in the same lane.
    EXPECT_GE(fx->rect.y, find(h.plan, "fx")->rect.bottom() - 0.01f);
    EXPECT_NEAR(fy->rect.x, find(h.plan, "fy")->rect.x, 0.01f);
}

TEST(InspectorSubtexel, RoundingUpToTheNextTexelShowsZeroSteps) {
    ShadowMap map = stepMap();
    // 255.7/256 rounds to the next texel's 0/256: the unit's base moves, its fraction is 0.
    vec2 p(7.0f + 255.7f / 256.0f, 9.25f);
    Planned h = plan(map, p, PCF_HW2X2, PCF_PRECISION_HW8, {1600, 900}, false);
    EXPECT_EQ(find(h.plan, "fx-hw8")->text, "0/256");
    EXPECT_EQ(find(h.plan, "fy-hw8")->text, "64/256");
}

TEST(InspectorSubtexel, InsetOnlyWhenTheTextureUnitRunsWithEightBits) {
    ShadowMap map = stepMap();
    vec2 p(7.3f, 9.6f);
    for (glm::ivec2 size : {glm::ivec2{1024, 768}, glm::ivec2{1280, 720}, glm::ivec2{1600, 900}}) {
        for (bool presentation : {false, true}) {
            // Hardware taps and gathers with 8 bits: the inset, its caption and the k/256 labels.
            for (int method : {PCF_HW2X2, PCF_TENT, PCF_GATHER}) {
                Planned h = plan(map, p, method, PCF_PRECISION_HW8, size, presentation);
                const LayoutBox* inset = find(h.plan, "hw8-inset");
                ASSERT_NE(inset, nullptr) << method << " " << size.x << presentation;
                EXPECT_EQ(inset->kind, BoxKind::Mark);
                EXPECT_EQ(inset->panel, "inspector");
                EXPECT_NE(find(h.plan, "hw8-caption"), nullptr);
                EXPECT_NE(find(h.plan, "fx-hw8"), nullptr);
                // Square, at least 60 px, inside the panel, right of the cells, level with them.
                EXPECT_EQ(inset->rect.w, inset->rect.h);
                EXPECT_GE(inset->rect.w, 60.0f);
                Rect panel = h.layout.inspector;
                EXPECT_LE(inset->rect.right(), panel.right());
                EXPECT_LE(inset->rect.bottom(), panel.bottom());
                Rect cells = neighbourhoodArea(h.layout, h.trace, presentation);
                EXPECT_GE(inset->rect.x, cells.right());
                EXPECT_EQ(inset->rect.y, cells.y);
                // Nothing written under it.
                for (const LayoutBox& b : h.plan.boxes) {
                    if (b.kind == BoxKind::Panel || b.kind == BoxKind::Mark) continue;
                    EXPECT_FALSE(overlaps(b.rect, inset->rect)) << b.role;
                }
                // The legend names the 8-bit position.
                bool legend =
                    std::any_of(h.plan.boxes.begin(), h.plan.boxes.end(), [](const LayoutBox& b) {
                        return b.role == "legend" && b.text.find("8-bit") != std::string::npos;
                    });
                EXPECT_TRUE(legend);
            }
            // The float model, or a method that never reaches the texture unit: none of it, and
            // the fractions keep two decimals.
            for (auto [method, precision] : {std::pair{PCF_HW2X2, PCF_PRECISION_EXACT},
                                             std::pair{PCF_BILINEAR2X2, PCF_PRECISION_HW8}}) {
                Planned e = plan(map, p, method, precision, size, presentation);
                EXPECT_EQ(find(e.plan, "hw8-inset"), nullptr) << method;
                EXPECT_EQ(find(e.plan, "hw8-caption"), nullptr);
                EXPECT_EQ(find(e.plan, "fx-hw8"), nullptr);
                EXPECT_EQ(find(e.plan, "fx")->text, "fx 0.30");
                EXPECT_TRUE(std::none_of(
                    e.plan.boxes.begin(), e.plan.boxes.end(),
                    [](const LayoutBox& b) { return b.role.find("hw8") != std::string::npos; }));
            }
        }
    }
}

// The inset's lattice is magnified: a 1/256 step spans many pixels there, while in the cells a
// whole texel holds all 256 steps.
TEST(InspectorSubtexel, InsetMagnifiesTheStepsBeyondThePixel) {
    ShadowMap map = stepMap();
    Planned h = plan(map, vec2(7.3f, 9.6f), PCF_HW2X2, PCF_PRECISION_HW8, {1280, 720}, false);
    Rect cells = neighbourhoodArea(h.layout, h.trace, false);
    Neighbourhood view = neighbourhoodView(h.layout, h.trace);
    float cellPx = cells.w / static_cast<float>(view.size.x);
    float stepInCells = cellPx / 256.0f;
    const LayoutBox* inset = find(h.plan, "hw8-inset");
    ASSERT_NE(inset, nullptr);
    EXPECT_LT(stepInCells, 1.0f);
    EXPECT_GE(inset->rect.w / 8.0f, 10.0f);  // at most 8 steps across, 10 px or more each
}

}  // namespace
}  // namespace pcf
