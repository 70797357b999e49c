// lesson_catalogue.h: the lessons that ship with pcfscope (lessons/*.toml) and how the command
// line names one: a path, a built-in lesson's name, or its number.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace pcf {

// The folder of the built-in lessons (the source tree's lessons/).
std::string lessonDirectory();
// The lessons that ship with pcfscope, sorted (lessons/*.toml): 01-..., 02-...
std::vector<std::string> builtInLessons();
// A lesson named on the command line: a path to a .toml file, a built-in lesson's name
// ("03-bilinear-lerp"), or its number in the list ("3"). Throws UsageError naming the choices.
std::string resolveLesson(const std::string& nameOrPath);
// The lesson of `lessons` (paths) whose file name is nameOrNumber, or, for a number, the one
// whose file name starts with that number ("13" -> "13-shimmer-and-snapping.toml", whatever its
// place in the list); nullopt when none is.
std::optional<std::string> findLesson(const std::vector<std::string>& lessons,
                                      const std::string& nameOrNumber);

}  // namespace pcf
