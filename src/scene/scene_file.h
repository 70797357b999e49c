// scene_file.h: scenes as TOML. The tables below may stand at the top level of a scene file or
// inside a lesson (which hands its own table to parseSceneToml); keys other than camera, light
// and object are left alone at that level, so a lesson can keep its own keys beside them.
//
//   [camera]
//   eye    = [6.0, 5.0, 7.0]       required, world position
//   target = [0.0, 0.5, 0.0]       required, the point looked at; must differ from eye
//   up     = [0.0, 1.0, 0.0]       optional (default +Y); not parallel to target - eye
//   fov    = 40.0                  optional, vertical field of view in degrees, in (1, 179)
//   near   = 0.1                   optional, > 0; fitted to the scene bounds when left out
//   far    = 50.0                  optional, > near; fitted likewise
//
//   [light]
//   type      = "directional"      required: "directional" or "spot"
//   direction = [-0.4, -1.0, -0.3] required, the way the light travels; not zero, need not be
//                                  unit
//   position  = [0.0, 6.0, 0.0]    spot only, required
//   cone      = 30.0               spot only, required: half-angle in degrees, in [0.01, 89]
//   angular_diameter = 0.53        directional only, optional (default 0, an ideal direction):
//                                  the light disk's angular diameter in degrees, in [0, 10]
//   radius    = 0.1                spot only, optional (default 0, a point): the radius of the
//                                  light's disk, centred on position and facing along
//                                  direction, world units, in [0, 100]
//                                  The size is for the area-light truth (`truth`, which then
//                                  integrates over the disk; a spot's casting spheres must lie
//                                  wholly in front of its disk) and pcss only; the shadow map
//                                  is rendered from the light's centre.
//
//   [[object]]                     one table per object, at least one
//   type     = "plane"             required: "plane", "box" or "sphere"
//   name     = "ground"            optional, unique (default type + index, e.g. "box1")
//   colour   = [0.8, 0.8, 0.8]     optional linear albedo, each in [0, 1] (default 0.8 grey)
//   casts_shadow    = true         optional (default true)
//   receives_shadow = true         optional (default true)
//   plane:  centre = [0, 0, 0]; normal = [0, 1, 0]; size = [10, 10]   (all required)
//           tangent = [1, 0, 0]    optional: the direction of size[0] (projected onto the
//                                  plane); default world X (world Z for a normal along X), so a
//                                  ground plane's size is [extent along x, extent along z]
//   box:    centre = [0, 0.5, 0]; half = [0.5, 0.5, 0.5]   (required; half extents > 0)
//           rotate_y = 20.0        optional, degrees about the box's vertical axis,
//                                  counter-clockwise seen from above
//   sphere: centre = [0, 1, 0]; radius = 0.5                (required; radius > 0)
//
// A scene file may instead be a built-in scene with its numbers set (presets.h), alone:
//   [preset]
//   name = "stacked-cards"         required, a preset's name
//   gap  = 0.5                     any of that preset's numbers (presets.h: presetParams), each
//                                  in its range; the others keep their defaults
//
// Numbers may be integers or floats; nan and inf are refused. Every problem throws InputError
// with the line of the offending value (or of its table when a key is missing), e.g.
// `scene.toml:7: sphere radius must be positive, got -1`.
#pragma once

#include <toml++/toml.h>

#include <cstddef>
#include <string>
#include <string_view>

#include "base/input_error.h"
#include "scene/scene.h"

namespace pcf {

// The most [[object]] tables a scene may have; more is refused with one line naming the limit.
// Every object is drawn in both passes and ray cast for the ground truth: 10,000 took 10 s and
// 1 GB, while a teaching scene has a handful.
constexpr std::size_t MAX_SCENE_OBJECTS = 256;
// The largest magnitude of any number in a scene file (positions, sizes, radii, camera planes).
constexpr double MAX_SCENE_NUMBER = 1.0e6;

// Reads and parses a scene file. A missing file: InputError `path: cannot open file`.
Scene parseSceneFile(const std::string& path);

// Parses TOML text; sourceName names it in error messages (a path, or e.g. "preset:pole").
Scene parseSceneString(std::string_view text, const std::string& sourceName);

// Reads a scene from an already parsed table (a scene file's root, or a lesson's table). The
// camera's missing near / far are fitted to the scene (fitCameraPlanes). Scene::name is
// sourceName.
Scene parseSceneToml(const toml::table& table, const std::string& sourceName);

// A [camera] table (the format above) read on its own, for a scene it views: its missing near /
// far are fitted to that scene. A lesson gives one beside a preset to look closer.
Camera parseCameraToml(const toml::table& cameraTable, const std::string& sourceName,
                       const Scene& scene);

// The scene as TOML text in the format above, numbers written so that parsing gives the same
// floats back (shortest round-trip form).
std::string formatSceneToml(const Scene& scene);

}  // namespace pcf
