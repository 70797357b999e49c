// The lessons' picked pixels show what their text says. Each step is rendered as the viewer and
// the exporter render it (EGL, llvmpipe in CI), its pixel's lookup is traced with the CPU kernel,
// and the claims the step's words make about that pixel are checked on the trace.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "app/session.h"
#include "kernel/trace.h"
#include "lesson/lesson.h"
#include "render/gl_context.h"
#include "render/render_settings.h"
#include "render/scene_renderer.h"
#include "scene/raycast.h"

namespace pcf {
namespace {

// The frames the claims must hold in, every size a class is likely to see: the lessons'
// reference frame, the scene views of exports at 1600x900 (960x540) and 1280x720 (768x432), a
// larger one, and the scene views of presentation mode on a projector at 1280x720 (617x347) and
// 1024x768 (512x288) (inspector.h: inspectorLayout; Layout.PresentationScenesAreTheCheckedSizes
// in layout_test keeps these in step with it).
constexpr glm::ivec2 FRAME_SIZES[] = {{1280, 720}, {960, 540}, {768, 432},
                                      {1536, 864}, {617, 347}, {512, 288}};

struct RenderedStep {
    Trace trace;
    float gpuVisibility;
    bool receiver;
    bool onGround;  // the camera ray through the pixel's centre meets a plane first
};

// Whether the pixel shows the ground: the scene's own ray cast through the pixel centre.
bool pixelOnGround(const Scene& scene, glm::ivec2 px, glm::ivec2 frameSize) {
    glm::vec2 ndc{(px.x + 0.5f) / frameSize.x * 2.0f - 1.0f,
                  1.0f - (px.y + 0.5f) / frameSize.y * 2.0f};
    float aspect = static_cast<float>(frameSize.x) / static_cast<float>(frameSize.y);
    std::optional<Hit> hit = intersect(scene, cameraRay(scene.camera, ndc, aspect));
    return hit &&
           std::holds_alternative<Plane>(scene.objects[static_cast<size_t>(hit->object)].shape);
}

// Renders every step of a lesson and traces its pixel, as `pcfscope export` does.
std::vector<RenderedStep> renderLesson(const std::string& name, glm::ivec2 frameSize) {
    Lesson lesson = parseLessonFile(PCFSCOPE_SOURCE_DIR "/lessons/" + name + ".toml");
    SceneRenderer renderer(lesson.scene);
    std::vector<RenderedStep> out;
    for (const LessonStep& step : lesson.steps) {
        const LessonSettings& s = step.settings;
        // The step's texel grid (origin_shift, snap), as the viewer and export fit the map.
        renderer.setShadowClipFromWorld(lessonShadowFit(lesson.scene, s, s.mapSize));
        renderer.render(renderSettingsFor(s, frameSize));
        std::vector<float> lightSpace = renderer.readLightSpace();
        std::vector<float> visibility = renderer.readVisibility();
        std::vector<float> receiver = renderer.readReceiver();
        ShadowMap map = renderer.readShadowMap();
        glm::ivec2 px = scalePixel(s.pixel, frameSize);
        size_t at = static_cast<size_t>(px.y) * frameSize.x + px.x;
        const float* ls = &lightSpace[at * 4];
        float ref = ls[2];
        // The bias mode with the receiver plane and depth the shader used (receiver target).
        BiasParams bias = s.biasParams();
        bias.dzduv = vec2(receiver[at * 4], receiver[at * 4 + 1]);
        Trace trace = traceLookup(map, vec2(ls[0], ls[1]), receiver[at * 4 + 2], ref,
                                  s.pcfParams(px, frameSize), bias);
        out.push_back({std::move(trace), visibility[at], ls[3] > 0.5f,
                       pixelOnGround(lesson.scene, px, frameSize)});
    }
    return out;
}

int litCount(const Trace& t) {
    int n = 0;
    for (const TapRecord& tap : t.taps) n += tap.lit > 0.5f ? 1 : 0;
    return n;
}

bool near(float a, float b, float tolerance = 0.01f) { return std::fabs(a - b) <= tolerance; }

// What the words of a step say about its pixel: about its lookup (holds), or, with no lookup
// check, that the pixel is on the ground ("a pixel in the penumbra" of a box's shadow must not be
// one on the box).
struct Claim {
    std::string what;
    std::function<bool(const Trace&)> holds;
    // false: a property of the pixel the lesson picked at the reference sizes, which the words
    // do not depend on (they print the live numbers); in a presentation scene one screen pixel
    // spans about 0.2 texel, so such a match cannot hold there and is not claimed.
    bool presentationToo = true;
};

// The same claim, held only in the reference frames (FRAME_SIZES' first four).
Claim atReferenceSizes(Claim c) {
    c.presentationToo = false;
    return c;
}

// Two bits 1 0 in a row lerp to 1 - fx (lesson 3's "the same way" as the worked example).
Claim oneMinusFx() {
    return {"visibility = 1 - fx",
            [](const Trace& t) { return std::fabs(t.visibility - (1.0f - t.pos.frac.x)) < 1e-4f; }};
}

Claim onGround() { return {"on the ground", nullptr}; }

using Claims = std::vector<std::vector<Claim>>;  // per step

Claim shadowed() {
    return {"fully shadowed", [](const Trace& t) { return t.visibility == 0.0f; }};
}
// Every read that counts passes (the weights' float sum may round to 0.99999994, printed as 1).
Claim lit() {
    return {"fully lit", [](const Trace& t) {
                for (const TapRecord& tap : t.taps) {
                    if (tap.weight > 0.0f && tap.lit < 0.5f) return false;
                }
                return t.visibility > 0.99999f;
            }};
}
Claim penumbra() {
    return {"in the penumbra",
            [](const Trace& t) { return t.visibility > 0.3f && t.visibility < 0.7f; }};
}
Claim bits(std::string expected) {
    return {"bits " + expected, [expected](const Trace& t) {
                std::string got;
                for (const TapRecord& tap : t.taps) got += tap.lit > 0.5f ? '1' : '0';
                return got == expected;
            }};
}
// nearest reads texel floor(uv * size); the point sits clearly inside it (its position in the
// texel, fract(uv * size) = fract(frac + 0.5) per axis, is not within 0.1 of a border), so the
// inspector's lookup dot is not on a grid line and which texel is read is plain to see.
Claim insideTexel() {
    return {"inside a texel", [](const Trace& t) {
                for (int k = 0; k < 2; ++k) {
                    float inTexel = t.pos.frac[k] + 0.5f;
                    inTexel -= std::floor(inTexel);
                    if (inTexel < 0.1f || inTexel > 0.9f) return false;
                }
                return true;
            }};
}
Claim firstTapMargin(bool positive) {
    return {positive ? "depth - ref >= 0" : "depth - ref < 0", [positive](const Trace& t) {
                return (t.taps[0].depth - t.taps[0].ref >= 0.0f) == positive;
            }};
}

const std::map<std::string, Claims>& lessonClaims() {
    static const std::map<std::string, Claims> claims = {
        {"01-hard-shadows",
         {{shadowed(), firstTapMargin(false), insideTexel()},
          {lit(), firstTapMargin(true), insideTexel()},
          {shadowed(), insideTexel()},
          {{"0 or 1", [](const Trace& t) { return t.visibility == 0.0f || t.visibility == 1.0f; }},
           insideTexel()}}},
        {"02-box-average",
         {{bits("1010"), {"half", [](const Trace& t) { return t.visibility == 0.5f; }}},
          {{"three of four", [](const Trace& t) { return litCount(t) == 3; }}},
          // The point lies near the 2x2's shared corner (fract near 0.5 sits on a texel border
          // on screen, as every 2x2 point near its middle does); which four texels it reads is
          // plain as long as frac stays clear of 0 and 1, where the 2x2 would flip.
          {bits("0001"),
           {"the 2x2 read is plain (frac clear of 0 and 1)",
            [](const Trace& t) {
                return t.pos.frac.x > 0.1f && t.pos.frac.x < 0.9f && t.pos.frac.y > 0.1f &&
                       t.pos.frac.y < 0.9f;
            }}},
          {bits("1010"),
           {"near the shadowed column", [](const Trace& t) { return t.pos.frac.x > 0.7f; }}}}},
        {"03-bilinear-lerp",
         {{bits("1010")},
          // Close to "What Is PCF"'s example: one screen pixel moves the point by about 0.09 texel
          // here, so frames of other sizes land up to half of that to either side.
          {bits("1010"), oneMinusFx(),
           atReferenceSizes({"What Is PCF: fx near 0.2 gives near 0.8",
                             [](const Trace& t) {
                                 return near(t.pos.frac.x, 0.2f, 0.05f) &&
                                        near(t.visibility, 0.8f, 0.05f);
                             }})},
          {bits("1010")},
          {bits("1010"),
           {"further along the ramp",
            [](const Trace& t) { return t.pos.frac.x > 0.5f && t.visibility < 0.5f; }}},
          {{"one hardware tap, the bilinear2x2 answer",
            [](const Trace& t) { return t.counts.hwTaps == 1; }},
           bits("1010"),
           oneMinusFx(),
           atReferenceSizes(
               {"near 0.8", [](const Trace& t) { return near(t.visibility, 0.8f, 0.05f); }})},
          // The conventions step: the worked example's pixel, fx counted from the texel centre.
          {bits("1010"), oneMinusFx(),
           atReferenceSizes({"near 0.8, so a shadow amount near 0.2",
                             [](const Trace& t) { return near(t.visibility, 0.8f, 0.05f); }})}}},
        {"04-nxn-lookups",
         {{penumbra(), onGround()},
          {penumbra(), onGround()},
          {penumbra(), onGround()},
          {penumbra(), onGround()}}},
        {"05-gather-weights",
         {{penumbra(), onGround()},
          {penumbra(), onGround()},
          {penumbra(), onGround()},
          {penumbra(), onGround()},
          {penumbra(), onGround()}}},
        {"06-hardware-taps-and-tent",
         {{penumbra(), onGround()},
          {penumbra(), onGround()},
          {penumbra(), onGround()},
          {penumbra(), onGround()},
          {penumbra(), onGround()},
          {penumbra(), onGround()}}},
        {"07-poisson-disk",
         {{penumbra()},
          {penumbra()},
          {penumbra(),
           {"rotated", [](const Trace& t) { return t.params.rotation != vec2(1.0f, 0.0f); }}}}},
        {"08-acne-and-bias",
         {{shadowed(), firstTapMargin(false), insideTexel()},
          {lit(), firstTapMargin(true), insideTexel()},
          {lit(), firstTapMargin(true), insideTexel()},
          {{"faint acne",
            [](const Trace& t) { return t.visibility > 0.5f && t.visibility < 1.0f; }}},
          {lit()},
          {lit(),
           {"nothing drawn", [](const Trace& t) { return t.taps[0].depth == 1.0f; }},
           insideTexel()}}},
        {"09-peter-panning",
         {{{"acne", [](const Trace& t) { return t.visibility < 0.7f; }}},
          {shadowed()},
          {lit()},
          {shadowed()}}},
        {"10-perspective-aliasing",
         {{shadowed(), insideTexel()},
          {shadowed(), insideTexel()},
          {penumbra()},
          {shadowed(), insideTexel()}}},
        // The chart steps trace the lesson's pixel too: it stays in the penumbra throughout, and
        // the steps that show the scene say "a pixel on the ground in the penumbra".
        {"11-speed-and-accuracy",
         {{penumbra()},
          {penumbra()},
          {penumbra()},
          {penumbra(), onGround()},
          {penumbra(), onGround()},
          {penumbra()}}},
        // One ref for all reads: read 0 tests the ground's own texel and fails; with the
        // receiver plane the same read gets its own ref and passes, down to a tiny constant;
        // per gather the plane is too coarse for that constant.
        {"12-receiver-plane-bias",
         {{{"acne: read 0 behind its own surface",
            [](const Trace& t) {
                return t.visibility < 1.0f && t.taps[0].depth < t.ref && t.taps[0].ref == t.ref;
            }}},
          {lit(),
           firstTapMargin(true),
           {"read 0 rescued by its own ref",
            [](const Trace& t) { return t.taps[0].depth < t.ref && tapsChangedByPlane(t) > 0; }}},
          {lit(), firstTapMargin(true)},
          {{"per gather read 2 fails",
            [](const Trace& t) {
                return t.visibility < 1.0f && t.taps[2].depth < t.taps[2].ref &&
                       t.counts.gathers > 0;
            }}}}},
        // The lesson's pixel is on the ground in the penumbra of the box's shadow (it once sat on
        // the box's front face): filtered steps land between 0 and 1 there, nearest ones on one
        // bit, and every step's pixel shows the ground.
        // The nearest steps on the 256 map (as is, slid, slid and snapped) read a texel whose
        // borders are clear of the lookup point.
        {"13-shimmer-and-snapping",
         {{penumbra(), onGround()},
          {{"0 or 1", [](const Trace& t) { return t.visibility == 0.0f || t.visibility == 1.0f; }},
           onGround(),
           insideTexel()},
          {penumbra(), onGround()},
          // nearest with the grid slid, snapped, and under the heat map: one bit
          {{"0 or 1", [](const Trace& t) { return t.visibility == 0.0f || t.visibility == 1.0f; }},
           onGround(),
           insideTexel()},
          {{"0 or 1", [](const Trace& t) { return t.visibility == 0.0f || t.visibility == 1.0f; }},
           onGround(),
           insideTexel()},
          {{"0 or 1", [](const Trace& t) { return t.visibility == 0.0f || t.visibility == 1.0f; }},
           onGround()}}},
        {"14-bias-trade-off",
         {{{"faint acne",
            [](const Trace& t) { return t.visibility > 0.5f && t.visibility < 1.0f; }}},
          {{"faint acne",
            [](const Trace& t) { return t.visibility > 0.5f && t.visibility < 1.0f; }}},
          {lit()},
          {lit()}}},
        {"15-texture-unit-precision",
         {{bits("1010"), oneMinusFx(),
           atReferenceSizes(
               {"near 0.8", [](const Trace& t) { return near(t.visibility, 0.8f, 0.05f); }})},
          {bits("1010"),
           {"hw8: whole 256ths, within 1/512 of the float fraction",
            [](const Trace& t) {
                return t.fracHw8.x * 256.0f == std::round(t.fracHw8.x * 256.0f) &&
                       std::fabs(t.fracHw8.x - t.pos.frac.x) <= 1.0f / 512.0f &&
                       t.visibility == t.visibilityHw8;
            }}},
          // The inset's step: the same tap, rounded to a different step than the float one.
          {bits("1010"),
           {"hw8 moves the tap: a visibility other than the float one",
            [](const Trace& t) {
                return t.usesTextureUnit && t.visibility == t.visibilityHw8 &&
                       t.visibilityHw8 != t.visibilityExact;
            }}},
          {{"inside a magnified lerp",
            [](const Trace& t) { return t.visibility > 0.05f && t.visibility < 0.95f; }}},
          {penumbra(),
           {"corner gathers: hw8 = exact",
            [](const Trace& t) { return t.visibilityHw8 == t.visibilityExact; }}},
          {bits("1010")}}},
    };
    return claims;
}

class LessonPixels : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<GlContext> sContext;
};
std::unique_ptr<GlContext> LessonPixels::sContext;

TEST(LessonPixelClaims, CoverEveryLesson) {
    for (const auto& entry : std::filesystem::directory_iterator(PCFSCOPE_SOURCE_DIR "/lessons")) {
        if (entry.path().extension() != ".toml") continue;
        EXPECT_TRUE(lessonClaims().count(entry.path().stem().string()))
            << entry.path() << " has no claims here: say what its pixels must show";
    }
}

TEST_F(LessonPixels, EveryStepsPixelShowsWhatItsTextSays) {
    for (const auto& [name, steps] : lessonClaims()) {
        for (size_t f = 0; f < std::size(FRAME_SIZES); ++f) {
            glm::ivec2 frameSize = FRAME_SIZES[f];
            bool presentationScene = f >= 4;
            std::vector<RenderedStep> rendered = renderLesson(name, frameSize);
            ASSERT_EQ(rendered.size(), steps.size()) << name;
            for (size_t i = 0; i < steps.size(); ++i) {
                const RenderedStep& r = rendered[i];
                SCOPED_TRACE(name + " step " + std::to_string(i + 1) + " in " +
                             std::to_string(frameSize.x) + "x" + std::to_string(frameSize.y));
                // The picked point is on a receiver, and the picture agrees with the trace.
                EXPECT_TRUE(r.receiver);
                EXPECT_NEAR(r.gpuVisibility, r.trace.visibility, 1e-5f);
                for (const Claim& claim : steps[i]) {
                    if (presentationScene && !claim.presentationToo) continue;
                    EXPECT_TRUE(claim.holds ? claim.holds(r.trace) : r.onGround)
                        << claim.what << " (visibility " << r.trace.visibility << ", frac "
                        << r.trace.pos.frac.x << ", " << r.trace.pos.frac.y << ")";
                }
            }
        }
    }
}

}  // namespace
}  // namespace pcf
