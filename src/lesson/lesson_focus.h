// lesson_focus.h: a step's focus, the lesson's word for what the step's words are about
// (docs/lesson-authoring.md, key `focus`): the parts of the frame its words refer to. The lesson
// parser reads it (lesson.h: LessonStep::focus), so a lesson is checked without the frame; the
// inspector gives those parts the room and shows them whole (overlay/inspector.h: focusLayout).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace pcf {

// Names: "scene", "neighbourhood", "formula", "chart", or two joined by '+'
// ("neighbourhood+formula").
struct Focus {
    bool scene = false, neighbourhood = false, formula = false, chart = false;
    bool operator==(const Focus&) const = default;
};
// A focus from its name; nullopt for an unknown part, more than two, or none.
std::optional<Focus> parseFocus(std::string_view name);
std::string focusName(const Focus& focus);
// The names parseFocus knows, for an error message.
const char* focusNames();

}  // namespace pcf
