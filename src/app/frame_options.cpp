#include "app/frame_options.h"

#include "app/cli_util.h"
#include "app/session.h"

namespace pcf {

CLI::Option* addLessonArgument(CLI::App* sub, std::string& lesson) {
    return sub->add_option("lesson", lesson, "lesson: a .toml path, a number, or a built-in name");
}

CLI::Option* addFrameSizeOption(CLI::App* sub, std::string& size, const std::string& what,
                                const std::string& note) {
    return sub->add_option("--size", size, sizeHelp(what, {MIN_SESSION_SIZE}, note));
}

CLI::Option* addPresentationFlag(CLI::App* sub, bool& on) {
    return sub->add_flag("--presentation", on,
                         "presentation mode (P) for a projector: 22 px step text, 18 px numbers, "
                         "thick lines");
}

CLI::Option* addMagnifyFlag(CLI::App* sub, bool& on) {
    return sub->add_flag("--magnify", on,
                         "a close-up camera on each step's pinned point (Z): a shadow-map texel "
                         "many pixels wide");
}

}  // namespace pcf
