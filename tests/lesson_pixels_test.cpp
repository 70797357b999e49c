// The lessons' picked points show what their text says. Each step is rendered as the viewer and
// the exporter render it (EGL, llvmpipe in CI), its point's pixel's lookup is traced with the CPU
// kernel, and the claims the step's words make (the lesson file's `claims`) are checked on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "app/magnifier.h"
#include "app/session.h"
#include "app/step_view.h"
#include "kernel/trace.h"
#include "lesson/lesson.h"
#include "lesson/lesson_claims.h"
#include "lesson/lesson_pick.h"
#include "overlay/inspector.h"
#include "render/gl_context.h"
#include "render/render_settings.h"
#include "render/scene_renderer.h"
#include "scene/raycast.h"

namespace pcf {
namespace {

// The frames the claims must hold in: the scene views of every frame size a class is likely to
// see, normal (the handouts) and presentation (the projector), as the session lays them out.
std::vector<glm::ivec2> sceneSizes() {
    std::vector<glm::ivec2> out;
    for (glm::ivec2 frame : {glm::ivec2(1024, 768), glm::ivec2(1280, 720), glm::ivec2(1600, 900),
                             glm::ivec2(1920, 1080)}) {
        for (bool presentation : {false, true}) {
            out.emplace_back(inspectorLayout(frame, presentation).scene.size());
        }
    }
    return out;
}

struct RenderedStep {
    Trace trace;
    float gpuVisibility;
    bool onGround;    // the pinned point lies on a plane
    bool inFrame;     // the point shows in the frame
    float pointMiss;  // how far the world point the GPU drew at the pixel is from it
    Trace cpuTrace;   // tracePinned: the point traced without the camera pass
    glm::ivec2 pixel;
    float lightAngle;
    std::vector<float> parts;  // a `compare` step's part[K].visibility (step_view.h)
};

// Renders every step of a lesson as the session does (the step's point pinned, the camera
// jittered onto its pixel) and traces the pixel's lookup from what the GPU wrote there.
std::vector<RenderedStep> renderLesson(const std::string& name, glm::ivec2 frameSize) {
    Lesson lesson = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/" + name + ".toml");
    SceneRenderer renderer(lesson.scene);
    std::vector<RenderedStep> out;
    for (const LessonStep& step : lesson.steps) {
        const LessonSettings& s = step.settings;
        // The step rendered and traced as the viewer and export do it (step_view.h): its texel
        // grid (origin_shift, snap), its point pinned to its pixel, its bias.
        std::optional<ScenePoint> point = stepPoint(lesson.scene, s);
        EXPECT_TRUE(point) << name;
        if (!point) return out;
        // A `magnify` step is seen through the magnifier's close-up (magnifier.h: stepCamera).
        Scene seen = lesson.scene;
        seen.camera = stepCamera(lesson.scene, s, point, frameSize);
        renderer.setCamera(seen.camera);
        FramePick pick = framePick(seen.camera, point->posWs, frameSize);
        glm::ivec2 px = pick.pixel;
        // Cascades are fitted to the lesson's camera, also where the view moves away from it
        // (magnify, freeze_cascades), as the session fits them.
        StepView view = stepView(seen, s, point, frameSize, std::nullopt, lesson.scene.camera);
        view.render.writePositions = true;
        renderStepView(renderer, view);
        std::vector<float> visibility = renderer.readVisibility();
        std::vector<float> positions = renderer.readPositions();
        ShadowMap map = renderer.readShadowMap();
        size_t at0 = static_cast<size_t>(px.y) * frameSize.x + px.x;
        std::optional<PixelLookup> lookup = tracePixel(renderer, map, s, px);
        EXPECT_TRUE(lookup) << name << ": the step's point is on no receiver";
        if (!lookup) return out;
        // In a cascaded map's blend band the pixel shows the mix of two cascades' lookups: the
        // trace names both, as the viewer's does (session.cpp traceAtPixel).
        if (map.layers() > 1 && lookup->cascade.covered) {
            lookup->trace.cascadeBlend =
                pinnedCascadeBlend(map, lesson.scene.light, s, lookup->trace.params, *point,
                                   lookup->cascade.index, lookup->dzduv, lesson.scene.camera);
        }
        glm::vec3 drawn(positions[at0 * 4], positions[at0 * 4 + 1], positions[at0 * 4 + 2]);
        bool plane = std::holds_alternative<Plane>(
            lesson.scene.objects[static_cast<size_t>(point->object)].shape);
        out.push_back({lookup->trace,
                       visibility[at0],
                       plane,
                       pick.inFrame,
                       glm::length(drawn - point->posWs),
                       tracePinned(map, lesson.scene, view.fit, s, *point),
                       px,
                       lightAngleDeg(lesson.scene, *point),
                       {}});
        // Last: it renders each part's map into the renderer.
        if (!step.compare.empty()) {
            out.back().parts =
                comparePartVisibilities(renderer, lesson.scene, view.fit, s, step.compare, *point);
        }
        renderer.setPick(std::nullopt);
    }
    return out;
}

class LessonPixels : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> LessonPixels::sContext;

std::vector<std::string> lessonNames() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(PCFSCOPE_SOURCE_DIR "/lessons")) {
        if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

// Every step says what its point must show, as claims in the lesson file (lesson_claims.h).
TEST(LessonPixelClaims, EveryStepStatesItsClaims) {
    for (const std::string& name : lessonNames()) {
        Lesson lesson = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/" + name + ".toml");
        for (size_t i = 0; i < lesson.steps.size(); ++i) {
            EXPECT_FALSE(lesson.steps[i].claims.empty())
                << name << " step " << i + 1 << " has no claims: say what its point must show";
        }
    }
}

// The pick belongs to the scene: every step traces the same lookup (uv, ref, frac within 1e-6)
// at the scene sizes of 1024x768, 1280x720, 1600x900 and 1920x1080, normal and presentation;
// the pixel shows its point (the camera's jitter puts the point on the pixel's centre), the
// picture agrees with the trace, and every claim of the step's words holds there.
TEST_F(LessonPixels, EveryStepsPixelShowsWhatItsTextSays) {
    std::vector<glm::ivec2> sizes = sceneSizes();
    for (const std::string& name : lessonNames()) {
        Lesson lesson = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/" + name + ".toml");
        std::vector<RenderedStep> first;
        for (glm::ivec2 frameSize : sizes) {
            std::vector<RenderedStep> rendered = renderLesson(name, frameSize);
            ASSERT_EQ(rendered.size(), lesson.steps.size()) << name;
            if (first.empty()) first = rendered;
            for (size_t i = 0; i < rendered.size(); ++i) {
                const RenderedStep& r = rendered[i];
                const Trace& t = r.trace;
                const Trace& t0 = first[i].trace;
                SCOPED_TRACE(name + " step " + std::to_string(i + 1) + " in " +
                             std::to_string(frameSize.x) + "x" + std::to_string(frameSize.y));
                EXPECT_TRUE(r.inFrame);
                EXPECT_LT(r.pointMiss, 1e-3f);
                // What the pixel shows: the lookup's visibility, or in a blend band the mix.
                float shown = t.cascadeBlend.next >= 0 ? t.cascadeBlend.blended : t.visibility;
                EXPECT_NEAR(r.gpuVisibility, shown, 1e-5f);
                for (int k = 0; k < 2; ++k) {
                    EXPECT_NEAR(t.uv[k], t0.uv[k], 1e-6f);
                    EXPECT_NEAR(t.pos.frac[k], t0.pos.frac[k], 1e-6f);
                }
                EXPECT_NEAR(t.ref, t0.ref, 1e-6f);
                EXPECT_EQ(t.visibility, t0.visibility);
                // `lesson check` traces the point on the CPU without the camera pass: the very
                // lookup the frame shows.
                EXPECT_EQ(r.cpuTrace.uv, t.uv);
                EXPECT_EQ(r.cpuTrace.ref, t.ref);
                EXPECT_EQ(r.cpuTrace.visibility, t.visibility);
                const LessonStep& step = lesson.steps[i];
                StepContext ctx = makeStepContext(step, r.pixel);
                ctx.lightAngleDeg = r.lightAngle;
                ctx.partVisibility = r.parts;
                EXPECT_EQ(r.parts, first[i].parts);  // the split view's numbers at every size
                ClaimWorld world;
                world.onPlane = r.onGround;
                for (const StepClaim& claim : step.claims) {
                    std::string why;
                    EXPECT_TRUE(claimHolds(claim, t, ctx, world, &why))
                        << "line " << claim.line << ": \"" << claim.text << "\": " << why;
                }
            }
        }
    }
}

// Lesson 9 step 3 is about the strip of light that too much bias opens between the pole's foot and
// its shadow: the ground that step 2's small bias shadows (visibility < 0.5) and step 3's lights
// fully, both seen through step 3's camera at its point. At every frame size and mode the strip
// lies inside the scene (it is seen whole) and the pick's ring (radius max(11, 14 x the layout's
// scale) plus its line) covers at most a tenth of it (about 2 % here). In the lesson's own view
// the strip was about as long as the ring was wide: the ring covered 13 to 28 % of it.
TEST_F(LessonPixels, PeterPanningsStripShowsWholeBesideTheRing) {
    Lesson lesson = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/09-peter-panning.toml");
    ASSERT_GE(lesson.steps.size(), 3u);
    const LessonSettings& lifted = lesson.steps[2].settings;
    LessonSettings attached = lesson.steps[1].settings;
    attached.point = lifted.point;
    std::optional<ScenePoint> point = stepPoint(lesson.scene, lifted);
    ASSERT_TRUE(point);
    SceneRenderer renderer(lesson.scene);
    for (glm::ivec2 frame : {glm::ivec2(1024, 768), glm::ivec2(1280, 720), glm::ivec2(1600, 900),
                             glm::ivec2(1920, 1080)}) {
        for (bool presentation : {false, true}) {
            InspectorLayout layout = inspectorLayout(frame, presentation);
            glm::ivec2 size(layout.scene.size());
            SCOPED_TRACE(std::to_string(frame.x) + "x" + std::to_string(frame.y) +
                         (presentation ? " presentation" : ""));
            Scene seen = lesson.scene;
            seen.camera = stepCamera(lesson.scene, lifted, point, size);
            renderer.setCamera(seen.camera);
            auto render = [&](const LessonSettings& s) {
                StepView view = stepView(seen, s, point, size);
                view.render.writePositions = true;
                renderStepView(renderer, view);
                return std::make_pair(renderer.readVisibility(), renderer.readPositions());
            };
            auto [before, positions] = render(attached);
            std::vector<float> after = render(lifted).first;
            glm::vec2 ring = glm::vec2(framePick(seen.camera, point->posWs, size).pixel) + 0.5f;
            float ringR = std::max(11.0f, 14.0f * layout.scale) + (presentation ? 3.0f : 2.0f);
            size_t strip = 0, underRing = 0, onBorder = 0;
            for (int y = 0; y < size.y; ++y) {
                for (int x = 0; x < size.x; ++x) {
                    size_t k = static_cast<size_t>(y) * size.x + x;
                    bool ground =
                        positions[k * 4 + 3] != 0.0f && std::abs(positions[k * 4 + 1]) < 1e-3f;
                    if (!ground || !(before[k] < 0.5f && after[k] == 1.0f)) continue;
                    ++strip;
                    if (glm::length(glm::vec2(x, y) + 0.5f - ring) <= ringR) ++underRing;
                    if (x == 0 || y == 0 || x == size.x - 1 || y == size.y - 1) ++onBorder;
                }
            }
            EXPECT_GT(strip, 0u);
            EXPECT_EQ(onBorder, 0u) << "the strip runs out of the scene";
            EXPECT_LE(10 * underRing, strip)
                << underRing << " of the strip's " << strip << " pixels under the ring";
        }
    }
}

}  // namespace
}  // namespace pcf
