#include "app/truth_option.h"

#include <cstdio>
#include <stdexcept>

#include "app/render_options.h"
#include "base/usage_error.h"
#include "measure/light_visibility.h"
#include "scene/pcss.h"

namespace pcf {

bool applyTruthOption(const std::string& truth, Scene& scene, const ShadowSettings& s) {
    if (truth != "hard" && truth != "area") {
        throw UsageError("unknown --truth '" + truth + "' (known: hard, area)");
    }
    Light& light = scene.light;
    checkLightSize(light, s);
    if (truth == "hard") return false;
    light = applyLightSize(light, s);
    if (light.type == LightType::Spot) {
        if (!hasSize(light)) {
            throw UsageError("--truth area takes a light with a size (scene '" + scene.name +
                             "' has a spot light without a radius)");
        }
        try {
            checkSpotDiskCasters(scene);
        } catch (const std::invalid_argument& e) {
            throw UsageError(scene.name + ": " + e.what());
        }
        return true;
    }
    light.angularDiameterDeg = effectiveLightSizeDeg(light, s.lightSize);
    return true;
}

std::string truthWordsFor(const Scene& scene, bool area) {
    if (!area) return "hard (the light's centre)";
    const Light& light = scene.light;
    char buf[80];
    if (light.type == LightType::Spot) {
        std::snprintf(buf, sizeof buf, "area (a spot disk of radius %g)",
                      static_cast<double>(light.radius));
    } else {
        std::snprintf(buf, sizeof buf, "area (a sun disk of %g degrees)",
                      static_cast<double>(light.angularDiameterDeg));
    }
    return buf;
}

}  // namespace pcf
