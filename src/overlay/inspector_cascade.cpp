// inspector_cascade.cpp: what the inspector's header says of the cascade a lookup read (a
// cascaded map: kernel/trace.h cascadeOfTrace).
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

std::string cascadeHeaderText(const Trace& tr) {
    std::optional<TraceCascade> c = cascadeOfTrace(tr);
    if (!c) return "";
    // Texel sizes run from millimetres to metres: three significant digits.
    char texel[32];
    std::snprintf(texel, sizeof texel, "%.3g", static_cast<double>(c->texelWs));
    std::string text = "cascade " + std::to_string(c->index) + " of " + std::to_string(c->count) +
                       "  view " + fixed(c->nearZ, 2) + ".." + fixed(c->farZ, 2) + "  texel " +
                       texel;
    if (c->texelsPerPixelMax >= 0.0f) {
        text += "  max " + fixed(c->texelsPerPixelMax, 2) + " texels/pixel";
    }
    return text;
}

std::string cascadeBlendText(const Trace& tr, const HiddenNumbers& hidden) {
    std::optional<TraceCascade> c = cascadeOfTrace(tr);
    const TraceCascadeBlend& b = tr.cascadeBlend;
    if (!c || b.next < 0) return "";
    // The two lookups side by side, the next one's weight and the mix the pixel shows
    // (shared/pcf_shading.h pcfCascadeBlend); each hides with the result it would give away.
    auto shown = [&](float v) {
        return hidden.visibility ? std::string(HIDDEN_NUMBER) : fixed(v, 4);
    };
    // (w=0.93 and shown=0.41 one word each: a wrapped line never parts a number from its name.)
    return "blend: cascade " + std::to_string(c->index) + " " + shown(tr.visibility) +
           ", cascade " + std::to_string(b.next) + " " + shown(b.nextVisibility) +
           ", w=" + fixed(b.weight, 4) + ", shown=" + shown(b.blended);
}

}  // namespace pcf::inspector_detail
