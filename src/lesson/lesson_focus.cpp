#include "lesson/lesson_focus.h"

namespace pcf {

namespace {

// The parts of a focus, in the order names list them.
struct FocusPart {
    const char* name;
    bool Focus::*flag;
};
constexpr FocusPart FOCUS_PARTS[] = {{"scene", &Focus::scene},
                                     {"neighbourhood", &Focus::neighbourhood},
                                     {"formula", &Focus::formula},
                                     {"chart", &Focus::chart}};

}  // namespace

std::optional<Focus> parseFocus(std::string_view name) {
    Focus f;
    int parts = 0;
    while (true) {
        size_t plus = name.find('+');
        std::string_view part = name.substr(0, plus);
        bool known = false;
        for (const FocusPart& p : FOCUS_PARTS) {
            if (part == p.name && !(f.*p.flag)) {
                f.*p.flag = true;
                known = true;
            }
        }
        if (!known || ++parts > 2) return std::nullopt;
        if (plus == std::string_view::npos) break;
        name = name.substr(plus + 1);
    }
    return f;
}

std::string focusName(const Focus& focus) {
    std::string out;
    for (const FocusPart& p : FOCUS_PARTS) {
        if (!(focus.*p.flag)) continue;
        if (!out.empty()) out.push_back('+');
        out.append(p.name);
    }
    return out;
}

const char* focusNames() {
    return "scene, neighbourhood, formula, chart, or two joined by '+' "
           "(\"neighbourhood+formula\")";
}

}  // namespace pcf
