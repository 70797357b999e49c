// frame_options.h: the options of the commands that show a lesson's frames (view, export,
// animate), declared once so that their --help read alike.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace pcf {

// The lesson argument (export and animate mark it required).
CLI::Option* addLessonArgument(CLI::App* sub, std::string& lesson);
// --size WxH within the session's smallest frame and the largest side: `what` ("frame size",
// "window size") and `note` (its default) in the help.
CLI::Option* addFrameSizeOption(CLI::App* sub, std::string& size, const std::string& what,
                                const std::string& note);
// --presentation and --magnify, what the viewer's P and Z show.
CLI::Option* addPresentationFlag(CLI::App* sub, bool& on);
CLI::Option* addMagnifyFlag(CLI::App* sub, bool& on);

}  // namespace pcf
