#include "scene/presets.h"

#include <glm/glm.hpp>
#include <stdexcept>
#include <variant>

#include "scene/scene_file.h"

namespace pcf {

namespace {

struct Preset {
    std::string_view name;
    std::string_view toml;
    // The numbers a scene file's [preset] table may set, and what sets them on the parsed scene
    // (one value per parameter, in order, each in its range); none for most presets.
    std::span<const PresetParam> params{};
    void (*apply)(Scene& scene, std::span<const double> values) = nullptr;
};

Box& boxNamed(Scene& scene, std::string_view name) {
    for (SceneObject& o : scene.objects) {
        if (o.name == name) return std::get<Box>(o.shape);
    }
    throw std::logic_error("preset has no box named " + std::string(name));
}

constexpr PresetParam STACKED_CARDS_PARAMS[] = {
    {"gap", 1.0, 0.05, 2.0, "world units",
     "the clear height between the lower card's top and the upper card's underside"},
};

// stacked-cards' gap: the upper card's underside `gap` above the lower card's top, its centre
// on the light's ray through the lower card's centre (moved along the light, so its shadow on
// the ground stays put).
void placeUpperCard(Scene& scene, std::span<const double> values) {
    const Box& lower = boxNamed(scene, "lower-card");
    Box& upper = boxNamed(scene, "upper-card");
    float rise = lower.halfExtents.y + static_cast<float>(values[0]) + upper.halfExtents.y;
    glm::vec3 toLight = -glm::normalize(scene.light.directionWs);
    upper.centreWs = lower.centreWs + toLight * (rise / toLight.y);
}

// Every camera frames its shadow in a 16:9 image. The light directions are given as the way the
// light travels; the angle from the ground's normal is acos(-direction.y / |direction|).
constexpr Preset PRESETS[] = {
    {"box-on-plane",
     R"(# A box resting on the ground; the sun 50 degrees from the zenith, so the shadow reaches
# tan(50) = 1.2 box heights across the ground toward the camera's right.
[camera]
eye = [0.8, 3.0, 5.0]
target = [0.6, 0.35, 0.3]
fov = 40.0

[light]
type = "directional"
direction = [1.1, -1.0, 0.45]

[[object]]
type = "plane"
name = "ground"
centre = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [12.0, 12.0]
colour = [0.8, 0.8, 0.8]

[[object]]
type = "box"
name = "box"
centre = [0.0, 0.5, 0.0]
half = [0.5, 0.5, 0.5]
rotate_y = 25.0
colour = [0.85, 0.45, 0.25]
)"},
    {"sphere-over-plane",
     R"(# A sphere floating above the ground. The light comes in 45 degrees from
# the zenith, so the shadow is an ellipse stretched 1 / cos(45) = 1.41 times along the light.
[camera]
eye = [3.0, 3.0, 4.5]
target = [0.7, 0.5, 0.3]
fov = 40.0

[light]
type = "directional"
direction = [0.8, -1.0, 0.6]

[[object]]
type = "plane"
name = "ground"
centre = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [12.0, 12.0]
colour = [0.8, 0.8, 0.8]

[[object]]
type = "sphere"
name = "ball"
centre = [0.0, 1.2, 0.0]
radius = 0.6
colour = [0.3, 0.5, 0.85]
)"},
    {"pole", R"(# A thin pole standing on the ground. Its shadow must start at its foot; a depth
# bias large enough to cure acne lifts the shadow off the foot (peter panning). The camera
# looks down the shadow from close to the foot; the sun is 51 degrees from the zenith, so the
# 2-unit pole throws a shadow 2 tan(51) = 2.5 units long.
[camera]
eye = [3.0, 1.6, 2.6]
target = [1.1, 0.2, 0.3]
fov = 40.0

[light]
type = "directional"
direction = [1.2, -1.0, 0.3]

[[object]]
type = "plane"
name = "ground"
centre = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [8.0, 8.0]
colour = [0.8, 0.8, 0.8]

[[object]]
type = "box"
name = "pole"
centre = [0.0, 1.0, 0.0]
half = [0.08, 1.0, 0.08]
rotate_y = 30.0
colour = [0.85, 0.75, 0.3]
)"},
    {"post-in-sun",
     R"(# A square post in a sun of 2 degrees (four suns wide): its shadow is sharp at the foot and
# soft at the tip, the penumbra as wide as 2 tan(1) = 0.035 times the distance to the post
# (contact hardening). The sun is 56 degrees from the zenith, so the 3-unit post throws a
# shadow 3 tan(56) = 4.4 units long, whose tip is 3 / cos(56) = 5.4 units from the post's top:
# a penumbra 0.19 units wide there.
[camera]
eye = [2.2, 4.2, 6.0]
target = [2.0, 0.4, 0.4]
fov = 45.0

[light]
type = "directional"
direction = [1.0, -0.7, 0.3]
angular_diameter = 2.0

[[object]]
type = "plane"
name = "ground"
centre = [1.5, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [9.0, 6.0]
colour = [0.8, 0.8, 0.8]

[[object]]
type = "box"
name = "post"
centre = [0.0, 1.5, 0.0]
half = [0.2, 1.5, 0.2]
rotate_y = 20.0
colour = [0.55, 0.6, 0.8]
)"},
    {"post-under-spot",
     R"(# A post under a spot light with a radius (a disk 0.3 units wide each way from its centre):
# the spot 4.5 units up and 3 to the side, so the 2-unit post throws a shadow 2.4 units long whose
# penumbra, the disk seen past the post's edge, widens from the foot to the tip (contact
# hardening at a finite distance). The map is perspective; the cone (45 degrees) holds the
# whole ground and post (38.9 degrees off the axis at most). Its depth is coarse far from the
# light: with back faces culled, the default constant bias leaves rings of acne on the ground
# (bench culls front faces, and the ground is clean).
[camera]
eye = [2.2, 4.2, 6.0]
target = [1.2, 0.3, 0.2]
fov = 45.0

[light]
type = "spot"
position = [-3.0, 4.5, 0.3]
direction = [5.5, -4.5, -0.1]
cone = 45.0
radius = 0.3

[[object]]
type = "plane"
name = "ground"
centre = [2.25, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [7.5, 6.0]
colour = [0.8, 0.8, 0.8]

[[object]]
type = "box"
name = "post"
centre = [0.0, 1.0, 0.0]
half = [0.25, 1.0, 0.25]
rotate_y = 20.0
colour = [0.55, 0.6, 0.8]
)"},
    {"grazing",
     R"(# The light 82 degrees from the ground's normal: direction = (sin 82, -cos 82, 0).
# Depth changes fast across each shadow-map texel, the classic setting for shadow acne. A low
# box casts a long shadow, tan(82) = 7.1 times its height.
[camera]
eye = [-2.5, 3.0, 6.0]
target = [1.5, 0.0, 0.0]
fov = 40.0

[light]
type = "directional"
direction = [0.990268, -0.139173, 0.0]

[[object]]
type = "plane"
name = "ground"
centre = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [10.0, 10.0]
colour = [0.8, 0.8, 0.8]

[[object]]
type = "box"
name = "block"
centre = [-1.5, 0.2, 0.0]
half = [0.4, 0.2, 0.6]
colour = [0.85, 0.45, 0.25]
)"},
    {"stairs",
     R"(# Four steps, each 0.3 higher than the one before, lit from the high side and from behind:
# each step shadows the tread of the next lower one, and the whole flight throws a stepped
# shadow on the ground in front, so the receivers lie at several depths from the light.
[camera]
eye = [-3.5, 3.0, 4.0]
target = [0.0, 0.4, 0.0]
fov = 40.0

[light]
type = "directional"
direction = [-1.2, -1.0, 0.5]

[[object]]
type = "plane"
name = "ground"
centre = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [12.0, 12.0]
colour = [0.8, 0.8, 0.8]

[[object]]
type = "box"
name = "step1"
centre = [-0.9, 0.15, 0.0]
half = [0.3, 0.15, 1.0]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "step2"
centre = [-0.3, 0.3, 0.0]
half = [0.3, 0.3, 1.0]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "step3"
centre = [0.3, 0.45, 0.0]
half = [0.3, 0.45, 1.0]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "step4"
centre = [0.9, 0.6, 0.0]
half = [0.3, 0.6, 1.0]
colour = [0.75, 0.55, 0.4]
)"},
    {"stacked-cards",
     R"(# Two thin square cards, the upper one smaller, centred over the lower one along the light,
# over the ground; the sun 45 degrees from the zenith and 1 degree wide. The upper card's edges
# throw their shadow inside the lower card's umbra on the ground, where the depth map holds
# both cards: a filter that blurs depths mixes the two there and lets light through (light
# bleeding). The gap between the cards is the scene file's [preset] gap (presets.h); the upper
# card slides along the light with it, so its shadow stays where it is.
[camera]
eye = [3.0, 2.4, 3.2]
target = [-0.1, 0.55, 0.0]
fov = 40.0

[light]
type = "directional"
direction = [1.0, -1.0, 0.0]
angular_diameter = 1.0

[[object]]
type = "plane"
name = "ground"
centre = [0.5, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
size = [3.0, 3.0]
colour = [0.8, 0.8, 0.8]

[[object]]
type = "box"
name = "lower-card"
centre = [0.0, 0.5, 0.0]
half = [0.4, 0.01, 0.4]
colour = [0.85, 0.45, 0.25]

[[object]]
type = "box"
name = "upper-card"
centre = [-1.02, 1.52, 0.0]
half = [0.2, 0.01, 0.2]
colour = [0.3, 0.5, 0.85]
)",
     STACKED_CARDS_PARAMS, placeUpperCard},
    {"long-ground",
     R"(# What a game sees: a ground running 100 units ahead of a camera 1.6 units above it, and a
# row of 2-unit posts on either side every 8 units, from 4 to 92 units away. The camera's near
# and far planes are 0.1 and 100, so cascades over its whole view depth split [0.1, 100] (at
# practical lambda 0.5, 4 cascades: 12.8187, 26.6061, 46.4039, 100). The sun is 58 degrees from
# the zenith, ahead and to the right: each post's shadow falls 3.2 units back across the ground.
[camera]
eye = [0.0, 1.6, 2.0]
target = [0.0, 0.9, -18.0]
fov = 40.0
near = 0.1
far = 100.0

[light]
type = "directional"
direction = [-1.4, -1.0, 0.8]

[[object]]
type = "plane"
name = "ground"
centre = [0.0, 0.0, -48.0]
normal = [0.0, 1.0, 0.0]
tangent = [1.0, 0.0, 0.0]
size = [24.0, 100.0]
colour = [0.8, 0.8, 0.8]

[[object]]
type = "box"
name = "post-left-1"
centre = [-2.5, 1.0, -4.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-1"
centre = [2.5, 1.0, -4.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-left-2"
centre = [-2.5, 1.0, -12.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-2"
centre = [2.5, 1.0, -12.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-left-3"
centre = [-2.5, 1.0, -20.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-3"
centre = [2.5, 1.0, -20.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-left-4"
centre = [-2.5, 1.0, -28.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-4"
centre = [2.5, 1.0, -28.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-left-5"
centre = [-2.5, 1.0, -36.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-5"
centre = [2.5, 1.0, -36.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-left-6"
centre = [-2.5, 1.0, -44.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-6"
centre = [2.5, 1.0, -44.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-left-7"
centre = [-2.5, 1.0, -52.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-7"
centre = [2.5, 1.0, -52.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-left-8"
centre = [-2.5, 1.0, -60.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-8"
centre = [2.5, 1.0, -60.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-left-9"
centre = [-2.5, 1.0, -68.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-9"
centre = [2.5, 1.0, -68.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-left-10"
centre = [-2.5, 1.0, -76.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-10"
centre = [2.5, 1.0, -76.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-left-11"
centre = [-2.5, 1.0, -84.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-11"
centre = [2.5, 1.0, -84.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-left-12"
centre = [-2.5, 1.0, -92.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]

[[object]]
type = "box"
name = "post-right-12"
centre = [2.5, 1.0, -92.0]
half = [0.15, 1.0, 0.15]
colour = [0.75, 0.55, 0.4]
)"},
};

}  // namespace

std::vector<std::string_view> presetNames() {
    std::vector<std::string_view> names;
    for (const Preset& p : PRESETS) names.push_back(p.name);
    return names;
}

std::string presetNameList() {
    std::string list;
    for (const Preset& p : PRESETS) list += (list.empty() ? "" : ", ") + std::string(p.name);
    return list;
}

std::optional<std::string_view> presetSceneToml(std::string_view name) {
    for (const Preset& p : PRESETS) {
        if (p.name == name) return p.toml;
    }
    return std::nullopt;
}

std::span<const PresetParam> presetParams(std::string_view name) {
    for (const Preset& p : PRESETS) {
        if (p.name == name) return p.params;
    }
    return {};
}

std::optional<Scene> presetScene(std::string_view name, std::span<const double> values) {
    const Preset* preset = nullptr;
    for (const Preset& p : PRESETS) {
        if (p.name == name) preset = &p;
    }
    if (!preset) return std::nullopt;
    if (values.size() != preset->params.size()) {
        throw std::invalid_argument("preset " + std::string(name) + " takes " +
                                    std::to_string(preset->params.size()) + " parameters");
    }
    for (size_t i = 0; i < values.size(); ++i) {
        const PresetParam& p = preset->params[i];
        if (!(values[i] >= p.min && values[i] <= p.max)) {
            throw std::invalid_argument("preset " + std::string(name) + " " + std::string(p.key) +
                                        " out of range");
        }
    }
    std::string source = "preset:" + std::string(name);
    Scene scene = parseSceneString(preset->toml, source);
    if (preset->apply) {
        preset->apply(scene, values);
        // The objects moved: the camera's planes (left to the fit in every preset) fitted anew.
        scene.camera.nearZ = scene.camera.farZ = 0.0f;
        fitCameraPlanes(scene.camera, sceneBounds(scene));
    }
    scene.name = std::string(name);
    return scene;
}

std::optional<Scene> presetScene(std::string_view name) {
    std::vector<double> defaults;
    for (const PresetParam& p : presetParams(name)) defaults.push_back(p.defaultValue);
    return presetScene(name, defaults);
}

}  // namespace pcf
