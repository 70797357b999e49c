#include "overlay/flicker_trace.h"

#include <algorithm>
#include <cmath>

#include "draw/text_layout.h"

namespace pcf {

namespace {

constexpr Colour TRACE_PANEL{0.05f, 0.06f, 0.08f, 0.86f};
constexpr Colour AXIS{0.55f, 0.58f, 0.65f, 1.0f};
constexpr Colour TEXT{0.92f, 0.93f, 0.96f, 1.0f};

}  // namespace

Rect flickerTraceRect(const Rect& scene, float textPx) {
    // Wide enough for the title at textPx (about 34 characters), at most the scene less a margin.
    float w = std::floor(std::min(scene.w - 16.0f, std::max(scene.w * 0.42f, 19.0f * textPx)));
    // The title, two labels and a plot about as tall as the three of them.
    float h = std::floor(std::max(scene.h * 0.3f, 6.5f * textPx * 1.3f));
    h = std::min(h, scene.h - 16.0f);
    return {scene.x + 8.0f, scene.bottom() - 8.0f - h, w, h};
}

float flickerTraceHeight(float textPx, int curves) {
    float row = std::ceil(textPx * 1.3f);
    float pad = std::ceil(textPx * 0.5f);
    return std::ceil(row * static_cast<float>(1 + std::max(1, curves) + 3) + 3.0f * pad);
}

glm::vec2 flickerTracePoint(const Rect& plot, int frameCount, int k, float v) {
    float t = frameCount > 1 ? static_cast<float>(k) / static_cast<float>(frameCount - 1) : 0.0f;
    return {plot.x + t * plot.w, plot.bottom() - std::clamp(v, 0.0f, 1.0f) * plot.h};
}

std::vector<LayoutBox> drawFlickerTrace(Canvas& canvas, const Rect& box, const FlickerTrace& trace,
                                        float textPx) {
    canvas.fillRect(box, TRACE_PANEL);
    float row = std::ceil(textPx * 1.3f);
    float pad = std::ceil(textPx * 0.5f);
    std::vector<LayoutBox> boxes;
    // Each text whole where the panel is wide enough, else elided (and listed as shortened).
    auto text = [&](glm::vec2 at, const std::string& s, FontFace face, const std::string& role) {
        std::string shown = elideText(face, textPx, s, box.right() - pad - at.x);
        canvas.text(at, shown, {face, textPx, TEXT});
        glm::vec2 size = measureText(face, textPx, shown);
        boxes.push_back({BoxKind::Text,
                         {std::round(at.x), std::round(at.y), size.x, size.y},
                         "trace",
                         role,
                         textPx,
                         shown != s,
                         shown});
    };
    canvas.pushClip(box);
    text({box.x + pad, box.y + pad}, trace.title, FontFace::Sans, "trace-title");
    float y = box.y + pad + row;
    for (const FlickerCurve& c : trace.curves) {
        canvas.fillRect({box.x + pad, y + 0.3f * row, row, 0.4f * row}, c.colour);
        text({box.x + pad + 1.5f * row, y}, c.label, FontFace::Mono, "trace-label");
        y += row;
    }
    // The plot: 0 and 1 marked at the left, the frames across.
    float tickW = std::ceil(textPx * 1.2f);
    Rect plot{box.x + pad + tickW, y + 0.5f * pad, box.w - 2.0f * pad - tickW,
              box.bottom() - y - 1.5f * pad};
    if (plot.h >= 8.0f && plot.w >= 16.0f) {
        canvas.line({plot.x, plot.y}, {plot.right(), plot.y}, 1.0f, AXIS);
        canvas.line({plot.x, plot.bottom()}, {plot.right(), plot.bottom()}, 1.0f, AXIS);
        TextStyle tick{FontFace::Mono, textPx, AXIS, TextAlign::Right};
        canvas.text({plot.x - 0.3f * pad, plot.y - 0.6f * textPx}, "1", tick);
        canvas.text({plot.x - 0.3f * pad, plot.bottom() - 0.6f * textPx}, "0", tick);
        // The comparison first, so the method on screen is drawn over it.
        for (size_t i = trace.curves.size(); i-- > 0;) {
            const std::vector<float>& v = trace.curves[i].values;
            for (size_t k = 1; k < v.size(); ++k) {
                glm::vec2 a =
                    flickerTracePoint(plot, trace.frameCount, static_cast<int>(k - 1), v[k - 1]);
                glm::vec2 b = flickerTracePoint(plot, trace.frameCount, static_cast<int>(k), v[k]);
                canvas.line(a, b, 2.0f, trace.curves[i].colour);
            }
            if (v.size() == 1) {
                canvas.circle(flickerTracePoint(plot, trace.frameCount, 0, v[0]), 1.5f,
                              trace.curves[i].colour);
            }
        }
    }
    canvas.popClip();
    return boxes;
}

}  // namespace pcf
