// inspector_subtexel.cpp: the hw8 inset. A texture unit that keeps the texel position with 8
// fractional bits (Direct3D 12 functional spec, D3D12_SUBTEXEL_FRACTIONAL_BIT_COUNT = 8; Inigo
// Quilez, "hardware interpolation", 2008: 24.8 fixed point) can only stand on a lattice of
// 1/256 texel. At the cells' scale (a texel is 100 to 300 px) one step is under a pixel, so the
// inset magnifies a few steps around the position a fetch hands the unit (unitPosition): the
// lattice, the float position, and the lattice point it rounds to,
//   q = floor(p * 256 + 0.5) / 256        (pcfQuantiseTexelPos, the kernel's own rounding)
// with the square of positions that round to q.
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

namespace {

constexpr int INSET_STEPS = 6;               // the inset spans this many 1/256 steps per side
constexpr float CAPTION_GAP_PX = 4.0f;       // the caption below its lane's top
constexpr float LATTICE_LINE_PX = 1.0f;      // a 1/256 line
constexpr float SUBTEXEL_DOT_MIN_PX = 3.0f;  // the float position's dot: at least this,
constexpr float POINT_PER_STEP = 0.16f;      // else this share of a step
constexpr float QUANT_PER_STEP = 0.4f;       // the 8-bit position's square: this share of a step
constexpr float QUANT_LINE_PX = 2.0f;        // its outline
constexpr Colour INSET_BACK{0.06f, 0.07f, 0.09f, 1.0f};
constexpr Colour LATTICE{0.66f, 0.69f, 0.76f, 0.45f};
constexpr Colour TEXEL_EDGE{0.95f, 0.95f, 0.98f, 0.9f};   // a lattice line on a texel border
constexpr Colour ROUNDS_HERE{0.72f, 1.0f, 0.28f, 0.22f};  // positions that round to q

// The texel position the texture unit rounds, as the inset shows it: the highlighted fetch's when
// it is a hardware tap or a gather, else the tap or gather nearest the lookup point (hw2x2's
// one tap is the lookup point itself; pcf-gather's gathers sit on texel corners).
vec2 unitPosition(const Trace& tr, int highlight) {
    vec2 size(tr.map.size);
    auto isUnit = [](const FetchRecord& f) {
        return f.kind == PCF_FETCH_HW || f.kind == PCF_FETCH_GATHER;
    };
    if (highlight >= 0 && highlight < static_cast<int>(tr.fetches.size()) &&
        isUnit(tr.fetches[static_cast<size_t>(highlight)])) {
        return tr.fetches[static_cast<size_t>(highlight)].uv * size - vec2(0.5f);
    }
    vec2 best = tr.pos.p;
    float bestDist = 1e30f;
    for (const FetchRecord& f : tr.fetches) {
        if (!isUnit(f)) continue;
        vec2 p = f.uv * size - vec2(0.5f);
        float d = glm::length(p - tr.pos.p);
        if (d < bestDist) {
            bestDist = d;
            best = p;
        }
    }
    return best;
}

}  // namespace

std::string hw8Steps(float fracHw8) {
    // fracHw8 is a multiple of 1/256 in [0, 1): k is exact.
    long k = std::lround(fracHw8 * PCF_SUBTEXEL_STEPS);
    return std::to_string(k) + "/256";
}

void planSubtexelInset(Planner& pl, const InspectorLayout& l, const Trace& tr, const Grid& g,
                       const TypeSizes& t, int highlight) {
    if (!g.hw8 || g.inset.empty()) return;
    const std::string panel = "inspector";
    const Rect box = g.inset;
    // Lattice coordinates: texel position * 256. The 8-bit position sits in the inset's middle.
    vec2 unit = unitPosition(tr, highlight);
    glm::vec2 s = unit * PCF_SUBTEXEL_STEPS;
    glm::vec2 q = pcfQuantiseTexelPos(unit) * PCF_SUBTEXEL_STEPS;
    glm::vec2 origin = q - glm::vec2(static_cast<float>(INSET_STEPS / 2));
    float step = box.w / static_cast<float>(INSET_STEPS);
    auto at = [&](glm::vec2 lattice) {
        return glm::vec2(box.x, box.y) + (lattice - origin) * step;
    };
    float line = lineOf(l);
    std::vector<std::pair<glm::vec2, glm::vec2>> lattice, edges;
    for (int k = 0; k <= INSET_STEPS; ++k) {
        glm::vec2 u = origin + glm::vec2(static_cast<float>(k));
        float x = box.x + static_cast<float>(k) * step;
        float y = box.y + static_cast<float>(k) * step;
        // A multiple of 256 is a texel border: drawn as the cells' borders are.
        (std::fmod(u.x, PCF_SUBTEXEL_STEPS) == 0.0f ? edges : lattice)
            .push_back({{x, box.y}, {x, box.bottom()}});
        (std::fmod(u.y, PCF_SUBTEXEL_STEPS) == 0.0f ? edges : lattice)
            .push_back({{box.x, y}, {box.right(), y}});
    }
    glm::vec2 fp = at(s);
    glm::vec2 qp = at(q);
    Rect rounds{qp.x - step * 0.5f, qp.y - step * 0.5f, step, step};
    float pr = std::max(SUBTEXEL_DOT_MIN_PX, std::round(step * POINT_PER_STEP));
    float qs = std::round(step * QUANT_PER_STEP);
    pl.op([=](Canvas& c) {
        c.fillRect(box, INSET_BACK);
        c.pushClip(box);
        c.fillRect(rounds, ROUNDS_HERE);
        for (const auto& [a, b] : lattice) c.line(a, b, LATTICE_LINE_PX, LATTICE);
        for (const auto& [a, b] : edges) c.line(a, b, line + 1.0f, TEXEL_EDGE);
        c.line(fp, qp, std::max(1.0f, line), POINT);
        c.strokeRect({qp.x - qs * 0.5f, qp.y - qs * 0.5f, qs, qs}, QUANT_LINE_PX, HW8_POINT);
        c.circle(fp, pr + 1.5f, Colour{0, 0, 0, 0.9f});
        c.circle(fp, pr, POINT);
        c.popClip();
        c.strokeRect(box, 1.0f, TEXT_DIM);
    });
    pl.box(BoxKind::Mark, box, panel, "hw8-inset");
    // The caption: the longest that fits over the inset.
    TextStyle st{FontFace::Sans, t.label, HW8_POINT};
    for (const char* caption : {"1/256-texel steps", "1/256 texel", "1/256"}) {
        if (measureText(FontFace::Sans, t.label, caption).x <= g.insetCaption.w) {
            pl.text({g.insetCaption.x, g.insetCaption.y + CAPTION_GAP_PX}, caption, st,
                    BoxKind::Label, panel, "hw8-caption");
            break;
        }
    }
}

}  // namespace pcf::inspector_detail
