#include "app/cascade_lines.h"

#include <array>

namespace pcf {

Colour cascadeLineColour(int k) {
    // shaders/scene.frag's CASCADE_TINTS, at full strength so that thin lines read.
    static const std::array<Colour, 4> colours = {
        Colour{1.0f, 0.25f, 0.25f, 1.0f}, Colour{0.2f, 0.9f, 0.2f, 1.0f},
        Colour{0.35f, 0.5f, 1.0f, 1.0f}, Colour{1.0f, 0.85f, 0.1f, 1.0f}};
    return colours[static_cast<size_t>(std::clamp(k, 0, 3))];
}

// Liang and Barsky, "A New Concept and Method for Line Clipping" (ACM TOG 1984): the segment
// a + t (b - a), t in [0, 1], kept where p_i t <= q_i for the four edges.
bool clipSegment(const Rect& r, glm::vec2& a, glm::vec2& b) {
    glm::vec2 d = b - a;
    const float p[4] = {-d.x, d.x, -d.y, d.y};
    const float q[4] = {a.x - r.x, r.right() - a.x, a.y - r.y, r.bottom() - a.y};
    float t0 = 0.0f, t1 = 1.0f;
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0f) {
            if (q[i] < 0.0f) return false;
            continue;
        }
        float t = q[i] / p[i];
        if (p[i] < 0.0f) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
        if (t0 > t1) return false;
    }
    glm::vec2 start = a + t0 * d;
    b = a + t1 * d;
    a = start;
    return true;
}

void drawCascadeLines(Canvas& canvas, const Rect& sceneRect, glm::ivec2 sceneSize,
                      const Camera& view, const std::vector<CascadeLine>& lines, float scale) {
    if (lines.empty() || sceneSize.x <= 0 || sceneSize.y <= 0) return;
    glm::vec2 toRect = sceneRect.size() / glm::vec2(sceneSize);
    for (bool split : {false, true}) {
        for (const CascadeLine& line : lines) {
            if (line.splitPlane != split) continue;
            std::array<glm::vec2, 2> ends;
            if (!projectSegment(view, sceneSize, line.a, line.b, ends)) continue;
            glm::vec2 a = sceneRect.position() + ends[0] * toRect;
            glm::vec2 b = sceneRect.position() + ends[1] * toRect;
            if (!clipSegment(sceneRect, a, b)) continue;
            Colour colour = cascadeLineColour(line.cascade);
            if (!split) {
                // The light boxes run deep (every caster of the scene): thin and see-through, so
                // that the split planes, what the frame is about, stand out.
                colour.a = 0.6f;
                canvas.line(a, b, 1.0f * scale, colour);
                continue;
            }
            // A dark edge under a split plane's line keeps it apart from a ground of its colour.
            canvas.line(a, b, 5.0f * scale, Colour{0.0f, 0.0f, 0.0f, 0.6f});
            canvas.line(a, b, 3.0f * scale, colour);
        }
    }
}

}  // namespace pcf
