// inspector.cpp: the frame's panels (inspectorLayout), its type sizes, and the plan that the
// panels' files (inspector_plan.h lists them) fill and the draw calls replay.
#include "overlay/inspector.h"

#include <algorithm>
#include <iterator>
#include <optional>

#include "overlay/flicker_trace.h"
#include "overlay/inspector_plan.h"
#include "render/frame_ops.h"

namespace pcf {

using namespace inspector_detail;

const char* boxKindName(BoxKind kind) {
    switch (kind) {
        case BoxKind::Panel:
            return "panel";
        case BoxKind::Text:
            return "text";
        case BoxKind::Number:
            return "number";
        case BoxKind::Label:
            return "label";
        case BoxKind::Mark:
            return "mark";
    }
    return "text";
}

TypeSizes typeSizes(const InspectorLayout& l) {
    TypeSizes t;
    float s = l.scale;
    if (l.presentation) {
        // A projector at 1024 x 768 or 1280 x 720 still gets 22 px text and 18 px numbers.
        t.bodyFloor = 22;
        t.itemFloor = 22;
        t.numberFloor = 18;
        t.labelFloor = 16;
        t.body = std::max(t.bodyFloor, std::round(17.0f * s * 1.35f));
        t.item = t.body;
        t.head = std::max(24.0f, std::round(20.0f * s * 1.35f));
        t.number = std::max(t.numberFloor, std::round(13.0f * s * 1.35f));
        t.label = std::max(t.labelFloor, std::round(12.0f * s * 1.35f));
        t.status = std::max(16.0f, std::round(13.0f * s * 1.35f));
    } else {
        // The handout's step text: 14 px at 1600 x 900 (scale 1), never below 12 (1600x900's
        // text fell to 12-13 px where it stepped down to a floor of 12).
        t.bodyFloor = std::max(12.0f, std::round(14.0f * s));
        t.itemFloor = 12;
        t.numberFloor = 12;
        t.labelFloor = 11;
        t.body = std::max(13.0f, std::round(15.0f * s));
        t.item = std::max(t.itemFloor, std::round(13.0f * s));
        t.head = std::max(16.0f, std::round(20.0f * s));
        t.number = std::max(t.numberFloor, std::round(14.0f * s));
        t.label = std::max(t.labelFloor, std::round(12.0f * s));
        t.status = std::max(12.0f, std::round(14.0f * s));
    }
    return t;
}

Rect thumbnailRect(const InspectorLayout& l, bool) { return l.thumbnail; }

std::vector<uint8_t> thumbnailImage(const ShadowMap& map, int side) {
    // Nearest texel per thumbnail pixel, depth as grey (near the light = dark). Rows top-down
    // with texel row 0 at the top, like the neighbourhood view.
    std::vector<uint8_t> rgba(static_cast<size_t>(side) * side * 4);
    for (int y = 0; y < side; ++y) {
        int j = std::min(map.height() - 1, y * map.height() / side);
        for (int x = 0; x < side; ++x) {
            int i = std::min(map.width() - 1, x * map.width() / side);
            float g = 0.15f + 0.8f * std::clamp(map.depth(i, j), 0.0f, 1.0f);
            uint8_t v = static_cast<uint8_t>(std::lround(g * 255.0f));
            size_t k = (static_cast<size_t>(y) * side + x) * 4;
            rgba[k] = v;
            rgba[k + 1] = v;
            rgba[k + 2] = static_cast<uint8_t>(std::min(255L, std::lround(g * 1.05f * 255.0f)));
            rgba[k + 3] = 255;
        }
    }
    return rgba;
}

InspectorLayout inspectorLayout(glm::ivec2 frameSize, bool presentation) {
    InspectorLayout l;
    l.frameSize = frameSize;
    l.presentation = presentation;
    float w = static_cast<float>(frameSize.x);
    float h = static_cast<float>(frameSize.y);
    l.scale = std::max(0.5f, std::min(w / 1600.0f, h / 900.0f));
    TypeSizes t = typeSizes(l);
    float statusH = std::round(std::max(28.0f * l.scale, lineHeightOf(t.status) + 8.0f));
    float bodyH = h - statusH;
    // Presentation gives the scene less room so that the step text and the cells can be large.
    // Tall frames too: the inspector's cells are as large as its width allows.
    float sceneShare = presentation || h > 0.75f * w ? 0.5f : 0.6f;
    float sceneW = std::round(w * sceneShare);
    float sceneH = std::round(sceneW * 9.0f / 16.0f);
    float maxSceneH = std::round(bodyH * (presentation ? 0.5f : 0.62f));
    if (sceneH > maxSceneH) {
        sceneH = maxSceneH;
        sceneW = std::round(sceneH * 16.0f / 9.0f);
    }
    l.status = {0.0f, h - statusH, w, statusH};
    if (w > 2.2f * h) {
        // Very wide frames: the scene at the full height on the left, then the step panel, then
        // the inspector, side by side (under the scene would leave a sliver).
        sceneH = bodyH;
        sceneW = std::round(sceneH * 16.0f / 9.0f);
        if (sceneW > w * 0.45f) {
            sceneW = std::round(w * 0.45f);
            sceneH = std::round(sceneW * 9.0f / 16.0f);
        }
        float rest = w - sceneW;
        float stepsW = std::round(rest * 0.45f);
        l.scene = {0.0f, 0.0f, sceneW, sceneH};
        l.steps = {sceneW, 0.0f, stepsW, bodyH};
        l.inspector = {sceneW + stepsW, 0.0f, w - sceneW - stepsW, bodyH};
        if (sceneH < bodyH) {
            // The space under the scene is the step panel's.
            l.steps = {0.0f, sceneH, sceneW + stepsW, bodyH - sceneH};
            l.inspector = {sceneW + stepsW, 0.0f, w - sceneW - stepsW, bodyH};
        }
    } else {
        l.scene = {0.0f, 0.0f, sceneW, sceneH};
        l.steps = {0.0f, sceneH, sceneW, bodyH - sceneH};
        l.inspector = {sceneW, 0.0f, w - sceneW, bodyH};
    }
    if (!presentation) {
        // The map's thumbnail, square, at the steps panel's right, under the lesson title.
        float margin = stepsMargin(l);
        float top = stepsBodyTop(l, t);
        float caption = lineHeightOf(t.label) + 6.0f;
        float side = std::floor(
            std::min(l.steps.bottom() - top - margin * 0.7f - caption, l.steps.w * 0.2f));
        if (side >= 48.0f) {
            l.thumbnail = {std::round(l.steps.right() - margin - side), std::round(top), side,
                           side};
        }
    }
    return l;
}

bool cellsAlone(const Focus& focus) { return focus == Focus{.neighbourhood = true}; }

InspectorLayout focusLayout(const InspectorLayout& l, const Focus& focus) {
    if (focus.chart) return chartStepLayout(l);
    if (focus.scene || !(focus.neighbourhood || focus.formula) || l.status.y <= 0.0f) return l;
    InspectorLayout c = l;
    float w = static_cast<float>(l.frameSize.x);
    float bodyH = l.status.y;
    // The inspector: the right of the frame, full height. The left column: the scene as an
    // inset (16:9, its width, at most a third of the height), the step text under it.
    float leftW = std::round(w * (l.presentation ? 0.38f : 0.42f));
    float insetH = std::round(std::min(leftW * 9.0f / 16.0f, bodyH / 3.0f));
    float insetW = std::round(insetH * 16.0f / 9.0f);
    c.inspector = {leftW, 0.0f, w - leftW, bodyH};
    c.scene = {std::round((leftW - insetW) * 0.5f), 0.0f, insetW, insetH};
    c.steps = {0.0f, insetH, leftW, bodyH - insetH};
    c.sceneInset = true;
    c.thumbnail = {};
    return c;
}

InspectorLayout motionLayout(const InspectorLayout& l, int curves) {
    if (l.inspector.empty()) return l;
    InspectorLayout c = l;
    // At the numbers' size (the projector's 18 px floor in presentation mode), at most 0.4 of
    // the column: the inspector keeps the rest for its cells.
    float h = std::min(std::round(flickerTraceHeight(typeSizes(l).number, curves)),
                       std::round(l.inspector.h * 0.4f));
    c.inspector.h = l.inspector.h - h;
    c.trace = {l.inspector.x, c.inspector.bottom(), l.inspector.w, h};
    return c;
}

InspectorLayout chartStepLayout(const InspectorLayout& l) {
    if (!l.presentation || l.status.y <= 0.0f) return l;
    InspectorLayout c = l;
    float w = static_cast<float>(l.frameSize.x);
    float bodyH = l.status.y;
    // The chart: the full width, 58% of the height over the status line; the step text under it.
    float chartH = std::round(bodyH * 0.58f);
    c.scene = {0.0f, 0.0f, w, chartH};
    c.steps = {0.0f, chartH, w, bodyH - chartH};
    c.inspector = {};
    c.thumbnail = {};
    return c;
}

FramePlan planFrame(const InspectorLayout& l, const InspectorModel& m) {
    FramePlan plan;
    Planner pl{plan};
    TypeSizes t = typeSizes(l);
    pl.box(BoxKind::Panel, l.scene, "scene", "scene");
    pl.box(BoxKind::Panel, l.steps, "steps", "steps");
    if (!l.inspector.empty()) pl.box(BoxKind::Panel, l.inspector, "inspector", "inspector");
    if (!l.trace.empty()) pl.box(BoxKind::Panel, l.trace, "trace", "trace");
    pl.box(BoxKind::Panel, l.status, "status", "status");
    if (m.showScene) planScene(pl, l, m, t);
    Rect steps = l.steps;
    pl.op([=](Canvas& c) { c.pushClip(steps); });
    planSteps(pl, l, m, t);
    pl.op([](Canvas& c) { c.popClip(); });
    if (!l.inspector.empty()) {
        Rect insp = l.inspector;
        pl.op([=](Canvas& c) { c.pushClip(insp); });
        planInspector(pl, l, m, t);
        pl.op([](Canvas& c) { c.popClip(); });
    }
    planStatus(pl, l, m, t);
    pl.onTop = true;
    planThumbnail(pl, l, m, t);
    if (m.help) planHelp(pl, l, t);
    return plan;
}

FramePlan planStatusFrame(const InspectorLayout& l, const std::string& status, bool help,
                          bool interactive) {
    FramePlan plan;
    Planner pl{plan};
    TypeSizes t = typeSizes(l);
    pl.box(BoxKind::Panel, l.status, "status", "status");
    pl.fill(l.status, STATUS);
    InspectorModel m;
    m.status = status;
    m.interactive = interactive;
    planStatus(pl, l, m, t);
    pl.onTop = true;
    if (help) planHelp(pl, l, t);
    return plan;
}

void drawPlan(Canvas& canvas, const std::vector<std::function<void(Canvas&)>>& ops) {
    for (const auto& op : ops) op(canvas);
}

void drawInspector(Canvas& c, const InspectorLayout& l, const InspectorModel& m) {
    drawPlan(c, planFrame(l, m).base);
}

void clearInspectorPanels(GLuint framebuffer, const InspectorLayout& l) {
    // Clears, not panel-sized quads through the overlay's blending shader. The largest panel's
    // colour goes over the whole frame first: llvmpipe fills whole tiles for a clear without a
    // scissor, while Mesa draws a scissored clear as a quad over its pixels (at 1600 x 900 the
    // three scissored clears cost about 3 ms). The other two panels are then cleared over it;
    // the scene's blit covers the rest. Same bytes either way: each pixel ends in its panel's
    // colour.
    struct Panel {
        const Rect* rect;
        Colour colour;
    };
    Panel panels[] = {
        {&l.inspector, PANEL}, {&l.steps, PANEL_LIGHT}, {&l.status, STATUS}, {&l.trace, PANEL}};
    auto area = [](const Panel& p) { return p.rect->w * p.rect->h; };
    Panel* largest =
        std::max_element(std::begin(panels), std::end(panels),
                         [&](const Panel& a, const Panel& b) { return area(a) < area(b); });
    clearColour(framebuffer, largest->colour);
    for (const Panel& p : panels) {
        if (&p == largest || p.rect->empty()) continue;  // a chart step has no inspector
        const Rect& r = *p.rect;
        int frameH = l.frameSize.y;
        int x = static_cast<int>(r.x), y = frameH - static_cast<int>(r.bottom());
        clearColourRect(framebuffer, {x, y, x + static_cast<int>(r.w), y + static_cast<int>(r.h)},
                        p.colour);
    }
}

void drawInspectorTop(Canvas& c, const InspectorLayout& l, const InspectorModel& m) {
    drawPlan(c, planFrame(l, m).top);
}

// The neighbourhood the cells show, and where (inspectorPanel decides it, as planFrame does).
namespace {

InspectorModel modelOf(const Trace& tr, bool presentation, int highlight) {
    InspectorModel m;
    m.trace = tr;
    m.presentation = presentation;
    m.highlightFetch = highlight;
    return m;
}

}  // namespace

Neighbourhood neighbourhoodView(const InspectorLayout& l, const InspectorModel& m) {
    return inspectorPanel(l, m, typeSizes(l)).layout.grid.view;
}

Rect neighbourhoodArea(const InspectorLayout& l, const InspectorModel& m) {
    return inspectorPanel(l, m, typeSizes(l)).layout.grid.area;
}

Neighbourhood neighbourhoodView(const InspectorLayout& l, const Trace& tr, int highlight) {
    return neighbourhoodView(l, modelOf(tr, l.presentation, highlight));
}

Rect neighbourhoodArea(const InspectorLayout& l, const Trace& tr, bool presentation,
                       int highlight) {
    return neighbourhoodArea(l, modelOf(tr, presentation, highlight));
}

Neighbourhood neighbourhoodOf(const Trace& tr) {
    glm::ivec2 lo = tr.pos.base;
    glm::ivec2 hi = tr.pos.base + glm::ivec2(1);
    if (!tr.weights.values.empty()) {
        lo = glm::min(lo, tr.weights.origin);
        hi = glm::max(hi, tr.weights.origin + tr.weights.size - glm::ivec2(1));
    }
    glm::ivec2 point(glm::floor(tr.uv * glm::vec2(tr.map.size)));
    lo = glm::min(lo, point);
    hi = glm::max(hi, point);
    return {lo, hi - lo + glm::ivec2(1)};
}

Rect texelCellRect(const Neighbourhood& n, const Rect& area, glm::ivec2 texel) {
    // The area is exactly as wide as the view's columns.
    float cell = area.w / static_cast<float>(std::max(1, n.size.x));
    return {area.x + static_cast<float>(texel.x - n.origin.x) * cell,
            area.y + static_cast<float>(texel.y - n.origin.y) * cell, cell, cell};
}

}  // namespace pcf
