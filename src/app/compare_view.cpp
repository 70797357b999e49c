#include "app/compare_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/cli_util.h"
#include "app/frame_json.h"
#include "kernel/trace_json.h"
#include "render/frame_ops.h"
#include "render/gl_context.h"

namespace pcf {

namespace {

constexpr float GAP = 2.0f;  // pixels between the parts' scenes
constexpr Colour BACKGROUND{0.10f, 0.11f, 0.13f, 1.0f};
constexpr Colour TEXT{0.92f, 0.93f, 0.95f, 1.0f};
constexpr Colour DIM{0.70f, 0.72f, 0.76f, 1.0f};

bool sameLight(const Light& a, const Light& b) {
    return a.type == b.type && a.directionWs == b.directionWs && a.positionWs == b.positionWs &&
           a.coneDeg == b.coneDeg && a.angularDiameterDeg == b.angularDiameterDeg &&
           a.radius == b.radius;
}

bool sameCamera(const Camera& a, const Camera& b) {
    return a.eyeWs == b.eyeWs && a.targetWs == b.targetWs && a.upWs == b.upWs &&
           a.fovYDeg == b.fovYDeg && a.nearZ == b.nearZ && a.farZ == b.farZ;
}

std::string signedNumber(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%+.3f", static_cast<double>(v));
    return buf;
}

// The panels' type: the projector's number floor in presentation mode, the inspector's scaled
// type otherwise.
float panelTextPx(glm::ivec2 frame, bool presentation) {
    if (presentation) return 18.0f;
    float scale = std::max(0.5f, std::min(frame.x / 1600.0f, frame.y / 900.0f));
    return std::max(12.0f, std::round(14.0f * scale));
}

// Four rows under each part: the label, the visibility, the lookup, the difference.
float panelHeightOf(glm::ivec2 frame, bool presentation) {
    return std::round(panelTextPx(frame, presentation) * (4 * 1.4f + 1.0f));
}

// The status line along the bottom, as tall as the lesson frame's at this size.
float statusHeightOf(glm::ivec2 frame, bool presentation) {
    return inspectorLayout(frame, presentation).status.h;
}

glm::ivec2 partSceneSizeOf(glm::ivec2 frame, int parts, bool presentation, bool traceBand) {
    int n = std::max(1, parts);
    float band = panelHeightOf(frame, presentation) + statusHeightOf(frame, presentation) +
                 (traceBand ? std::round(frame.y * 0.24f) : 0.0f);
    int w = (frame.x - (n - 1) * static_cast<int>(GAP)) / n;
    return {w, frame.y - static_cast<int>(band)};
}

}  // namespace

std::optional<std::string> compareFrameProblem(glm::ivec2 frame, int parts, bool presentation,
                                               bool traceBand) {
    glm::ivec2 scene = partSceneSizeOf(frame, parts, presentation, traceBand);
    if (scene.x < MIN_COMPARE_PART_WIDTH) {
        return "a split view of " + std::to_string(parts) + " parts needs a frame at least " +
               std::to_string(parts * MIN_COMPARE_PART_WIDTH + (parts - 1) * int(GAP)) +
               " pixels wide, got " + std::to_string(frame.x);
    }
    if (scene.y < MIN_COMPARE_PART_HEIGHT) {
        return "a split view needs a frame at least " +
               std::to_string(frame.y - scene.y + MIN_COMPARE_PART_HEIGHT) + " pixels high, got " +
               std::to_string(frame.y);
    }
    return std::nullopt;
}

Colour comparePartColour(int part) {
    if (part == 0) return FLICKER_MAIN_COLOUR;
    return part == 1 ? FLICKER_COMPARE_COLOUR : COMPARE_THIRD_COLOUR;
}

CompareView::CompareView(glm::ivec2 frameSize, bool presentation, CompareSpec spec)
    : mSpec(std::move(spec)), mPresentation(presentation) {
    for (int i = 0; i < mSpec.parts(); ++i) {
        // Laid out at the smallest session frame, then as the scene alone at the part's size.
        auto s = std::make_unique<Session>(MIN_SESSION_SIZE, presentation);
        s->setSceneOnly(true);
        mParts.push_back(std::move(s));
    }
    setFrameSize(frameSize);
}

void CompareView::setTraceBand(bool on) {
    if (on == mTraceBand) return;
    mTraceBand = on;
    glm::ivec2 size = mFrameSize;
    mFrameSize = glm::ivec2(0);
    setFrameSize(size);
}

void CompareView::setFrameSize(glm::ivec2 frameSize) {
    if (frameSize == mFrameSize) return;
    if (auto problem = compareFrameProblem(frameSize, parts(), mPresentation, mTraceBand)) {
        throw UsageError(*problem);
    }
    mFrameSize = frameSize;
    mFrame = createOffscreenTarget(frameSize.x, frameSize.y, {GL_RGBA8});
    for (auto& p : mParts) p->setFrameSize(partSceneSize());
}

float CompareView::textPx() const { return panelTextPx(mFrameSize, mPresentation); }

float CompareView::panelHeight() const { return panelHeightOf(mFrameSize, mPresentation); }

glm::ivec2 CompareView::partSceneSize() const {
    return partSceneSizeOf(mFrameSize, parts(), mPresentation, mTraceBand);
}

Rect CompareView::partRect(int part) const {
    glm::vec2 s(partSceneSize());
    return {part * (s.x + GAP), 0.0f, s.x, s.y};
}

void CompareView::follow(const Session& main) {
    const std::optional<ScenePoint>& point = main.point();
    for (int i = 0; i < parts(); ++i) {
        Session& p = *mParts[static_cast<size_t>(i)];
        if (p.lesson().sourcePath != main.lesson().sourcePath) p.setLesson(main.lesson());
        if (p.step() != main.step()) p.goToStep(main.step());
        if (!sameLight(p.scene().light, main.scene().light)) p.setLight(main.scene().light);
        if (!sameCamera(p.scene().camera, main.scene().camera)) p.setCamera(main.scene().camera);
        p.setShadowFit(main.shadowFit());
        p.setSettings(comparePart(main.settings(), mSpec, i));
        bool samePoint = point && p.point() && p.point()->posWs == point->posWs;
        if (point && !samePoint) p.pinPoint(*point);
    }
    mStatus = main.statusText() + "   compare " + compareSpecText(mSpec);
    mHelp = main.help();
    mInteractive = main.interactive();
    mMotion = main.motion();
}

void CompareView::compose() { composeInto(mFrame.framebuffer.id()); }

void CompareView::composeInto(GLuint fbo) {
    for (auto& p : mParts) p->compose();
    clearColour(fbo, BACKGROUND);
    for (int i = 0; i < parts(); ++i) {
        Rect r = partRect(i);
        GLuint src = mParts[static_cast<size_t>(i)]->frameFramebuffer();
        int top = mFrameSize.y - static_cast<int>(r.y);
        int x = static_cast<int>(r.x), w = static_cast<int>(r.w), h = static_cast<int>(r.h);
        blitColour(src, {0, 0, w, h}, fbo, {x, top - h, x + w, top});
    }
    bindFramebuffer(fbo);
    mCanvas.begin(mFrameSize);
    // The status line and the help as the lesson's frame has them; the help over everything.
    FramePlan chrome =
        planStatusFrame(inspectorLayout(mFrameSize, mPresentation), mStatus, mHelp, mInteractive);
    mBoxes = chrome.boxes;
    drawPanels();
    drawTraceBand();
    drawPlan(mCanvas, chrome.base);
    drawPlan(mCanvas, chrome.top);
    mCanvas.flush();
    bindFramebuffer(0);
}

// The flicker trace across the frame, between the parts' panels and the status line.
void CompareView::drawTraceBand() {
    if (!mFlicker || !mTraceBand) return;
    float pad = std::round(textPx() * 0.5f);
    float top = partSceneSize().y + panelHeight();
    float bottom = mFrameSize.y - statusHeightOf(mFrameSize, mPresentation);
    Rect box{pad, top, mFrameSize.x - 2.0f * pad, bottom - top - pad};
    std::vector<LayoutBox> texts = drawFlickerTrace(mCanvas, box, mFlicker(), textPx());
    mBoxes.push_back({BoxKind::Panel, box, "trace", "trace", 0.0f, false, {}});
    mBoxes.insert(mBoxes.end(), texts.begin(), texts.end());
}

// Each part's compact inspector under its scene: what it sets, the point's visibility, its
// lookup (ref, lit taps), and its difference from the first part.
void CompareView::drawPanels() {
    float px = textPx();
    float labelPx = mPresentation ? 22.0f : std::round(px * 1.1f);
    float lineH = std::round(px * 1.4f);
    float pad = std::round(px * 0.5f);
    std::string first = comparePartLabel(mSpec, 0);
    for (int i = 0; i < parts(); ++i) {
        Rect r = partRect(i);
        float x = r.x + pad, y = r.bottom() + pad;
        // The part's colour ties its label to its curve in the flicker trace.
        mCanvas.fillRect({r.x, r.bottom(), r.w, std::round(px * 0.25f)}, comparePartColour(i));
        mCanvas.text({x, y}, comparePartLabel(mSpec, i),
                     {FontFace::Sans, labelPx, comparePartColour(i)});
        TextStyle mono{FontFace::Mono, px, TEXT};
        const std::optional<Trace>& t = part(i).trace();
        if (!t) {
            mCanvas.text({x, y + lineH}, "not on a shadow receiver", {FontFace::Sans, px, DIM});
            continue;
        }
        char buf[96];
        std::snprintf(buf, sizeof buf, "visibility %.3f", static_cast<double>(t->visibility));
        mCanvas.text({x, y + lineH}, buf, mono);
        int lit = 0;
        for (const TapRecord& tap : t->taps) lit += tap.lit > 0.5f ? 1 : 0;
        std::snprintf(buf, sizeof buf, "ref %.5f  lit %d/%zu", static_cast<double>(t->ref), lit,
                      t->taps.size());
        mCanvas.text({x, y + 2 * lineH}, buf, {FontFace::Mono, px, DIM});
        if (i == 0) continue;
        std::optional<float> d = difference(i);
        std::string diff = d ? "minus " + first + ": " + signedNumber(*d) : "";
        mCanvas.text({x, y + 3 * lineH}, diff, mono);
    }
}

std::vector<uint8_t> CompareView::readFrame() const {
    return readPixelsRgba8(mFrame.framebuffer.id(), GL_COLOR_ATTACHMENT0, mFrame.width,
                           mFrame.height);
}

std::optional<float> CompareView::visibility(int part) const {
    const std::optional<Trace>& t = this->part(part).trace();
    return t ? std::optional<float>(t->visibility) : std::nullopt;
}

std::optional<float> CompareView::difference(int part) const {
    std::optional<float> a = visibility(0), b = visibility(part);
    if (!a || !b) return std::nullopt;
    return *b - *a;
}

std::string CompareView::json() const {
    Json parts = Json::array();
    for (int i = 0; i < this->parts(); ++i) {
        std::optional<float> v = visibility(i), d = difference(i);
        const Session& p = part(i);
        Json j = {{"label", comparePartLabel(mSpec, i)},
                  {"visibility", v ? jsonNumber(*v) : Json(nullptr)},
                  {"difference", i > 0 && d ? jsonNumber(*d) : Json(nullptr)},
                  {"pixel", {p.pixel().x, p.pixel().y}},
                  {"trace", p.trace() ? traceJson(*p.trace()) : Json(nullptr)}};
        parts.push_back(j);
    }
    const Session& p0 = part(0);
    Json j = {{"lesson", p0.lesson().name},
              {"step", p0.step() + 1},
              {"compare", compareSpecText(mSpec)},
              {"point", p0.point() ? Json::array({jsonNumber(p0.point()->posWs.x),
                                                  jsonNumber(p0.point()->posWs.y),
                                                  jsonNumber(p0.point()->posWs.z)})
                                   : Json(nullptr)},
              {"frame_size", {mFrameSize.x, mFrameSize.y}},
              {"part_scene_size", {partSceneSize().x, partSceneSize().y}},
              {"parts", parts},
              {"status", mStatus},
              {"layout", layoutJson(mBoxes)}};
    if (mMotion) j["motion"] = motionJson(*mMotion);
    return jsonDump(j);
}

}  // namespace pcf
