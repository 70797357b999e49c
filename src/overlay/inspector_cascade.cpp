// inspector_cascade.cpp: what the inspector's header says of the cascade a lookup read (a
// cascaded map: kernel/trace.h cascadeOfTrace).
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

std::string cascadeHeaderText(const Trace& tr, bool hideVisibility) {
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
    // In the blend band the frame mixes in the next cascade's lookup of the point
    // (shared/pcf_shading.h pcfCascadeBlend): both, the weight and what the frame shows.
    const TraceCascadeBlend& b = tr.cascadeBlend;
    if (b.next >= 0 && b.weight > 0.0f) {
        auto shown = [&](float v) {
            return hideVisibility ? std::string(HIDDEN_NUMBER) : fixed(v, 4);
        };
        text += "\nblend band: cascade " + std::to_string(tr.layer) + " " + shown(tr.visibility) +
                ", cascade " + std::to_string(b.next) + " " + shown(b.nextVisibility) + ", w " +
                fixed(b.weight, 3) + " -> " + shown(b.blended);
    }
    return text;
}

}  // namespace pcf::inspector_detail
