// The inspector's frame (inspector.h: planFrame): the ring round a Poisson disk, the texel grid
// and the legend on the scene, the step's focus (which part gets the room), and a moment method's
// pages at the sizes a class meets.
#include <gtest/gtest.h>

#include "layout_checks.h"

namespace pcf {
namespace {

using namespace testutil;

// The ring drawn round poisson's and pcss's points is the disk they fill: the widely copied
// 16-point set reaches 1.234 of its radius (8 points lie outside radius 1), and a ring of radius
// R left half of them outside it (lesson 7, "the disk, radius R").
TEST(PoissonDisk, TheDrawnRingHoldsEveryPointAndTouchesTheFarthest) {
    constexpr int MAP = 32;
    ShadowMap map(MAP, MAP, 0.9f);
    for (int j = 0; j < MAP; ++j) {
        for (int i = 0; i < MAP / 2; ++i) map.setDepth(i, j, 0.2f);
    }
    for (float radius : {1.0f, 2.5f}) {
        for (bool rotated : {false, true}) {
            PcfParams prm = makeParams(PCF_POISSON, 3, radius);
            if (rotated) prm.rotation = vec2(0.38268343f, 0.92387953f);  // 67.5 degrees
            Trace tr =
                traceLookup(map, (vec2(15.3f, 16.6f) + vec2(0.5f)) / float(MAP), 0.5f, 0.5f, prm);
            InspectorLayout l = inspectorLayout({1280, 720}, true);
            InspectorModel m;
            m.stepTitles = {"one"};
            m.stepText = "text";
            m.trace = tr;
            m.presentation = true;
            m.sceneSize = glm::ivec2(l.scene.size());
            FramePlan plan = planFrame(l, m);
            ASSERT_EQ(plan.diskRadii.size(), 1u);
            ASSERT_EQ(tr.fetches.size(), 16u);
            float farthest = 0.0f;
            for (const FetchRecord& f : tr.fetches) {
                vec2 p = f.uv * float(MAP) - vec2(0.5f);
                farthest = std::max(farthest, glm::length(p - tr.pos.p));
            }
            EXPECT_GT(farthest, 1.2f * radius);  // the set is not a unit disk
            EXPECT_GE(plan.diskRadii[0], farthest - 1e-4f) << radius << (rotated ? " rotated" : "");
            EXPECT_LE(plan.diskRadii[0], farthest + 1e-3f) << radius << (rotated ? " rotated" : "");
            // The cells reach round the whole ring (texel i spans p in [i - 0.5, i + 0.5)), so it
            // is never cut by the cells' edge (7.2 at 1280x720 lost its left and bottom).
            Neighbourhood view = neighbourhoodView(l, m);
            vec2 lo = tr.pos.p - vec2(plan.diskRadii[0]) + vec2(0.5f);
            vec2 hi = tr.pos.p + vec2(plan.diskRadii[0]) + vec2(0.5f);
            EXPECT_LE(view.origin.x, int(std::floor(lo.x))) << radius;
            EXPECT_LE(view.origin.y, int(std::floor(lo.y))) << radius;
            EXPECT_GE(view.origin.x + view.size.x - 1, int(std::floor(hi.x))) << radius;
            EXPECT_GE(view.origin.y + view.size.y - 1, int(std::floor(hi.y))) << radius;
        }
    }
}

// A light-space buffer (uv, depth, receiver) of the square of pixels `radius` round a picked
// pixel, `pixelsPerTexel` screen pixels to a texel of a 64 x 64 map, centred on uv 0.5.
std::vector<float> syntheticLightSpace(int radius, float pixelsPerTexel) {
    std::vector<float> ls;
    for (int y = -radius; y <= radius; ++y) {
        for (int x = -radius; x <= radius; ++x) {
            ls.push_back(0.5f + x / pixelsPerTexel / 64.0f);
            ls.push_back(0.5f + y / pixelsPerTexel / 64.0f);
            ls.push_back(0.4f);
            ls.push_back(1.0f);
        }
    }
    return ls;
}

// A model whose picked pixel is the scene's centre with a light-space buffer round it.
InspectorModel gridModel(const InspectorLayout& l, int& radius) {
    InspectorModel m;
    m.trace = syntheticTrace();
    m.stepTitles = {"Grid"};
    m.stepText = "Grid.";
    m.sceneSize = glm::ivec2(l.scene.size());
    m.pixel = m.sceneSize / 2;
    radius = gridRadius(m.sceneSize) + 1;
    m.lightSpaceOrigin = m.pixel - glm::ivec2(radius);
    m.lightSpaceSize = glm::ivec2(2 * radius + 1);
    return m;
}

// The texel grid is drawn where a texel spans several pixels, and hidden (or off) otherwise.
TEST_F(Layout, GridHiddenWhenTexelsAreSmallOrTurnedOff) {
    InspectorLayout l = inspectorLayout({1600, 900}, false);
    int radius = 0;
    InspectorModel m = gridModel(l, radius);
    std::vector<float> big = syntheticLightSpace(radius, 9.0f);
    std::vector<float> tiny = syntheticLightSpace(radius, 1.5f);
    m.lightSpace = &big;
    EXPECT_TRUE(planFrame(l, m).gridShown);
    m.lightSpace = &tiny;
    EXPECT_FALSE(planFrame(l, m).gridShown);
    m.lightSpace = &big;
    m.grid = false;
    EXPECT_FALSE(planFrame(l, m).gridShown);
}

// The legend names the texels read "on the scene" only where the scene shows them: tinted and
// outlined at any texel size, the grid on or off, but not on a scene drawn as a scaled inset,
// which leaves the tint out.
TEST_F(Layout, LegendNamesTheSceneTintOnlyWhereItIsDrawn) {
    InspectorLayout l = inspectorLayout({1600, 900}, false);
    int radius = 0;
    InspectorModel m = gridModel(l, radius);
    std::vector<float> tiny = syntheticLightSpace(radius, 1.5f);
    m.lightSpace = &tiny;
    auto named = [](const FramePlan& plan) {
        for (const LayoutBox& b : plan.boxes) {
            if (b.text == "texels read, on the scene") return true;
        }
        return false;
    };
    FramePlan full = planFrame(l, m);
    EXPECT_TRUE(full.footprintShown);
    EXPECT_TRUE(named(full));
    m.grid = false;
    EXPECT_TRUE(named(planFrame(l, m)));
    l.sceneInset = true;
    FramePlan inset = planFrame(l, m);
    EXPECT_FALSE(inset.footprintShown);
    EXPECT_FALSE(named(inset));
    // A scene whose pixels round the pick are not receivers: nothing tinted, nothing named.
    l.sceneInset = false;
    std::vector<float> none = tiny;
    for (size_t k = 3; k < none.size(); k += 4) none[k] = 0.0f;
    m.lightSpace = &none;
    FramePlan empty = planFrame(l, m);
    EXPECT_FALSE(empty.footprintShown);
    EXPECT_FALSE(named(empty));
}

// A focus names one or two parts; anything else is refused (loadLessonChecked turns that into
// one line at the key's file:line).
TEST(Focus, ParsesOneOrTwoKnownParts) {
    ASSERT_TRUE(parseFocus("neighbourhood"));
    EXPECT_EQ(*parseFocus("neighbourhood"), Focus{.neighbourhood = true});
    EXPECT_EQ(*parseFocus("scene+formula"), (Focus{.scene = true, .formula = true}));
    EXPECT_EQ(focusName(*parseFocus("formula+neighbourhood")), "neighbourhood+formula");
    EXPECT_FALSE(parseFocus(""));
    EXPECT_FALSE(parseFocus("neighborhood"));
    EXPECT_FALSE(parseFocus("scene+scene"));
    EXPECT_FALSE(parseFocus("scene+formula+chart"));
    EXPECT_FALSE(parseFocus("scene+"));
}

TEST(Focus, UnknownFocusInALessonNamesItsLine) {
    std::string dir = testing::TempDir() + "/focus_lesson";
    std::filesystem::create_directories(dir);
    std::string path = dir + "/bad.toml";
    std::ofstream(path) << "title = \"T\"\nscene = \"box-on-plane\"\n[[step]]\ntitle = \"S\"\n"
                           "text = \"x\"\nfocus = \"texels\"\n";
    try {
        loadLessonChecked(path);
        ADD_FAILURE() << "accepted focus = \"texels\"";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.toml:6"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("texels"), std::string::npos) << e.what();
    }
    // Derived where the lesson says nothing: a filter's step is about its neighbourhood.
    Lesson lesson = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/05-gather-weights.toml");
    EXPECT_EQ(stepFocus(lesson.steps[0]), (Focus{.neighbourhood = true, .formula = true}));
    Lesson acne = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/08-acne-and-bias.toml");
    EXPECT_TRUE(stepFocus(acne.steps[3]).scene);
}

// A neighbourhood focus gives the inspector the room and the scene an inset of the same 16:9,
// inside the frame and clear of the other panels; a scene focus keeps the frame as it was.
TEST(Focus, NeighbourhoodFocusGivesTheInspectorTheRoom) {
    for (glm::ivec2 size : SIZES) {
        for (bool presentation : {false, true}) {
            InspectorLayout base = inspectorLayout(size, presentation);
            InspectorLayout n = focusLayout(base, Focus{.neighbourhood = true});
            // (Presentation's inspector already has half the width; normal mode's 40%.)
            float gain = presentation ? 1.15f : 1.3f;
            EXPECT_GT(n.inspector.w * n.inspector.h, gain * base.inspector.w * base.inspector.h);
            EXPECT_TRUE(n.sceneInset);
            EXPECT_LT(n.scene.w, base.scene.w);
            EXPECT_NEAR(n.scene.w / n.scene.h, 16.0f / 9.0f, 0.02f);
            Rect frame{0, 0, static_cast<float>(size.x), n.status.y};
            EXPECT_TRUE(inside(n.scene, frame) && inside(n.steps, frame));
            EXPECT_TRUE(n.scene.intersect(n.inspector).empty());
            EXPECT_TRUE(n.steps.intersect(n.inspector).empty());
            EXPECT_TRUE(n.scene.intersect(n.steps).empty());
            InspectorLayout s = focusLayout(base, Focus{.scene = true, .neighbourhood = true});
            EXPECT_EQ(s.inspector.w, base.inspector.w);
            EXPECT_FALSE(s.sceneInset);
        }
    }
}

// A focus on the neighbourhood alone gives the cells the formula's room: bigger cells on the first
// page, the formula whole on the next (5.4, the four gathers, beside 5.3's table and sum).
TEST_F(Layout, NeighbourhoodAloneGivesTheCellsTheFormulasRoom) {
    InspectorModel m;
    m.title = "Focus";
    m.stepTitles = {"One", "Two"};
    m.stepText = "Short.";
    m.trace = syntheticTrace();
    int larger = 0;
    for (glm::ivec2 size : SIZES) {
        for (bool presentation : {false, true}) {
            std::string where = std::to_string(size.x) + "x" + std::to_string(size.y) +
                                (presentation ? " presentation" : "");
            InspectorLayout base = inspectorLayout(size, presentation);
            m.presentation = presentation;
            m.sceneSize = glm::ivec2(base.scene.size());
            auto formulaOn = [&](const InspectorLayout& l, int page) {
                m.textPage = page;
                FramePlan plan = planFrame(l, m);
                EXPECT_TRUE(problems(plan, l).empty()) << where << " page " << page + 1;
                bool formula = false;
                for (const LayoutBox& b : plan.boxes) formula |= b.role == "formula";
                return formula;
            };
            Focus both{.neighbourhood = true, .formula = true};
            InspectorLayout lb = focusLayout(base, both);
            m.focus = both;
            EXPECT_TRUE(formulaOn(lb, 0)) << where;
            Rect shared = neighbourhoodArea(lb, m);
            Focus cells{.neighbourhood = true};
            ASSERT_TRUE(cellsAlone(cells));
            EXPECT_FALSE(cellsAlone(both));
            InspectorLayout lc = focusLayout(base, cells);
            m.focus = cells;
            EXPECT_FALSE(formulaOn(lc, 0)) << where;
            EXPECT_TRUE(formulaOn(lc, 1)) << where;
            Rect alone = neighbourhoodArea(lc, m);
            EXPECT_GE(alone.w, shared.w) << where;
            larger += alone.w > shared.w + 8.0f;
        }
    }
    EXPECT_GE(larger, 6);
}

// ---- A moment method's page (overlay/inspector_moment_page.cpp). ----

// A moment method's step on box-on-plane, its point in the box's penumbra (the footprint
// straddles the box's edge), with `extra` settings lines.
Lesson momentLesson(const std::string& method, const std::string& extra) {
    std::string text = "title = \"moments\"\nscene = \"box-on-plane\"\n[settings]\nmethod = \"" +
                       method + "\"\nmap_size = 128\nkernel = 5\npoint = [0.9794, 0, -0.4338]\n" +
                       extra +
                       "\n[[step]]\ntitle = \"Look\"\ntext = \"visibility = {visibility}\"\n";
    return parseLessonString(text, "moments.toml");
}

// Every page of a moment method's frame at the sizes a class meets (1024x768 and 1280x720 on a
// projector, 1600x900 on a screen, and 960x540, where the bound goes on a page of its own): its
// texts inside the panel, over no other text or number, at or above their floors; the histogram
// holding every depth texel its moments average; its numbers and the "lit: ref <= depth" legend of
// cells it no longer draws gone.
TEST_F(Layout, MomentPagesFitAndShowTheFootprintAtEverySize) {
    struct Case {
        const char* method;
        const char* extra;
    };
    const Case cases[] = {{"vsm", ""},
                          {"vsm", "lbr = 0.3"},
                          {"evsm4", "evsm_exponents = \"40,5\""},
                          {"msm", ""},
                          {"msm-hausdorff", ""}};
    glm::ivec2 renderScene(inspectorLayout({1280, 720}, false).scene.size());
    int pagedFrames = 0;  // frames whose figure took two pages (960x540's, at least)
    for (const Case& c : cases) {
        Lesson lesson = momentLesson(c.method, c.extra);
        const LessonSettings& s = lesson.steps[0].settings;
        SceneRenderer renderer(lesson.scene);
        std::optional<ScenePoint> pinned = stepPoint(lesson.scene, s);
        renderStepView(renderer, stepView(lesson.scene, s, pinned, renderScene));
        ShadowMap map = renderer.readShadowMap();
        glm::ivec2 px = stepPick(lesson.scene, s, renderScene).pixel;
        std::optional<PixelLookup> lookup = tracePixel(renderer, map, s, px);
        ASSERT_TRUE(lookup) << c.method;
        const Trace& tr = lookup->trace;
        // The footprint straddles the edge: (N + 1)^2 texels, not all one depth.
        ASSERT_TRUE(tr.depths.present) << c.method;
        EXPECT_EQ(tr.depths.texels.size(), 36u) << c.method;
        InspectorModel m;
        m.title = lesson.title;
        m.stepTitles = {"Look"};
        m.map = &map;
        m.trace = tr;
        m.stepText = "visibility";
        for (auto [size, presentation] :
             {std::pair{glm::ivec2(1024, 768), true}, std::pair{glm::ivec2(1280, 720), true},
              std::pair{glm::ivec2(1600, 900), false},
              // (Too small for the whole: the bound goes on a page of its own.)
              std::pair{glm::ivec2(960, 540), true}}) {
            InspectorLayout l = inspectorLayout(size, presentation);
            m.presentation = presentation;
            m.sceneSize = glm::ivec2(l.scene.size());
            m.pixel = stepPick(lesson.scene, s, m.sceneSize).pixel;
            std::string where = std::string(c.method) + " " + c.extra + " at " +
                                std::to_string(size.x) + "x" + std::to_string(size.y);
            FramePlan first = planFrame(l, m);
            EXPECT_LE(first.textPages, 2) << where;
            pagedFrames += first.textPages > 1;
            std::vector<FramePlan> pages;
            int histograms = 0, curves = 0;
            // PCF of the same footprint, read off beside the bound at t (not for msm: no curve).
            std::string pcfLabel = "pcf " + formatNumber(tr.depths.pcfVisibility);
            bool pcfShown = false;
            for (int page = 0; page < first.textPages; ++page) {
                m.textPage = page;
                pages.push_back(planFrame(l, m));
                for (const std::string& problem : problems(pages.back(), l)) {
                    ADD_FAILURE() << where << " page " << page + 1 << ": " << problem;
                }
                for (const LayoutBox& b : pages.back().boxes) {
                    histograms += b.role == "moment-histogram";
                    curves += b.role == "moment-curve";
                    pcfShown |= b.role == "moment-value" && b.text == pcfLabel;
                    EXPECT_EQ(b.text.find("ref <= depth"), std::string::npos) << where;
                    EXPECT_FALSE(b.role.starts_with("cell-")) << where << ": " << b.role;
                }
                ASSERT_TRUE(pages.back().moments) << where;
            }
            m.textPage = 0;
            for (const std::string& problem : cropped(pages, tr)) {
                ADD_FAILURE() << where << ": " << problem;
            }
            EXPECT_EQ(histograms, 1) << where;
            // vsm one curve, evsm4 one per warp; msm none (its points stand on the histogram).
            bool msm = methodInfo(tr.params.method).reconstructs;
            int warps = methodInfo(tr.params.method).warps;
            EXPECT_EQ(curves, msm ? 0 : std::max(1, warps)) << where;
            EXPECT_EQ(pcfShown, !msm) << where;
        }
    }
    EXPECT_GT(pagedFrames, 0);
}

}  // namespace
}  // namespace pcf
