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

}  // namespace pcf::inspector_detail
