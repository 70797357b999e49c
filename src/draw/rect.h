// rect.h: an axis-aligned rectangle in the overlay's pixel coordinates (origin at the top-left
// of the target, x right, y DOWN; see canvas.h), and the RGBA colour the overlay draws with.
#pragma once

#include <algorithm>
#include <glm/glm.hpp>

namespace pcf {

// RGBA in [0,1], straight (not premultiplied) alpha, written to the target as is (no sRGB
// conversion): Colour{1, 0, 0, 1} becomes the bytes 255, 0, 0, 255.
using Colour = glm::vec4;

// Covers x in [x, x + w), y in [y, y + h). With whole-pixel edges that is exactly the pixels
// x .. x + w - 1, rows y .. y + h - 1 counted from the top.
struct Rect {
    float x = 0.0f;
    float y = 0.0f;
    float w = 0.0f;
    float h = 0.0f;

    float left() const { return x; }
    float top() const { return y; }
    float right() const { return x + w; }
    float bottom() const { return y + h; }
    glm::vec2 position() const { return {x, y}; }
    glm::vec2 size() const { return {w, h}; }
    glm::vec2 centre() const { return {x + 0.5f * w, y + 0.5f * h}; }
    bool empty() const { return !(w > 0.0f && h > 0.0f); }
    bool contains(glm::vec2 p) const {
        return p.x >= x && p.x < right() && p.y >= y && p.y < bottom();
    }

    // Grown by d on every side (shrunk for d < 0).
    Rect expanded(float d) const { return {x - d, y - d, w + 2.0f * d, h + 2.0f * d}; }
    // The overlap; empty (w = h = 0) when there is none.
    Rect intersect(const Rect& o) const {
        float x0 = std::max(x, o.x);
        float y0 = std::max(y, o.y);
        float x1 = std::min(right(), o.right());
        float y1 = std::min(bottom(), o.bottom());
        return {x0, y0, std::max(0.0f, x1 - x0), std::max(0.0f, y1 - y0)};
    }
    bool operator==(const Rect&) const = default;
};

}  // namespace pcf
