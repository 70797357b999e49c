#include "app/frame_json.h"

#include <algorithm>

namespace pcf {

// The frame's layout (planFrame's boxes) as a JSON array: [{"kind", "panel", "role",
// "rect": [x, y, w, h], "font_px", "shortened", "text"}, ...]; font_px and shortened only for
// what draws text, "text" (the words drawn, as drawn) where the box knows them.
Json layoutJson(const std::vector<LayoutBox>& boxes) {
    Json out = Json::array();
    for (const LayoutBox& b : boxes) {
        Json box = {{"kind", boxKindName(b.kind)},
                    {"panel", b.panel},
                    {"role", b.role},
                    {"rect", Json::array({jsonNumber(b.rect.x), jsonNumber(b.rect.y),
                                          jsonNumber(b.rect.w), jsonNumber(b.rect.h)})}};
        if (b.kind == BoxKind::Text || b.kind == BoxKind::Number || b.kind == BoxKind::Label ||
            b.fontPx > 0.0f) {
            box["font_px"] = jsonNumber(b.fontPx);
            box["shortened"] = b.shortened;
        }
        if (!b.text.empty()) box["text"] = b.text;
        out.push_back(std::move(box));
    }
    return out;
}

// What this page of the frame drew against what the trace read: {"drawn": {"texels": [[i, j],
// ...], "fetches": [k, ...], "formula_whole": bool, "scene_texels": [[i, j], ...]}, "read":
// {"texels": [...], "fetches": [...]}}. Texels: the distinct texels of the taps, in read order;
// fetches: indices into the trace's fetches (its instructions: gathers, hardware taps, lookups,
// point reads); scene_texels: the texels tinted and outlined on the scene (empty where the scene
// shows no tint: an inset, the grid's marks off).
Json drawnAndReadJson(const Trace& tr, const std::vector<glm::ivec2>& texels,
                      const std::vector<int>& fetches, bool formulaWhole,
                      const std::vector<glm::ivec2>& sceneTexels) {
    Json readTexels = Json::array();
    std::vector<glm::ivec2> seen;
    for (const TapRecord& t : tr.taps) {
        if (std::find(seen.begin(), seen.end(), t.texel) != seen.end()) continue;
        seen.push_back(t.texel);
        readTexels.push_back(jsonPair(t.texel));
    }
    Json readFetches = Json::array();
    for (size_t k = 0; k < tr.fetches.size(); ++k) readFetches.push_back(k);
    Json drawnTexels = Json::array();
    for (glm::ivec2 t : texels) drawnTexels.push_back(jsonPair(t));
    Json scene = Json::array();
    for (glm::ivec2 t : sceneTexels) scene.push_back(jsonPair(t));
    return {{"drawn",
             {{"texels", drawnTexels},
              {"fetches", fetches},
              {"formula_whole", formulaWhole},
              {"scene_texels", scene}}},
            {"read", {{"texels", readTexels}, {"fetches", readFetches}}}};
}

Json cellsJson(const Neighbourhood& view, const Rect& r) {
    return {{"origin", jsonPair(view.origin)},
            {"size", jsonPair(view.size)},
            {"rect",
             Json::array({jsonNumber(r.x), jsonNumber(r.y), jsonNumber(r.w), jsonNumber(r.h)})}};
}

}  // namespace pcf
