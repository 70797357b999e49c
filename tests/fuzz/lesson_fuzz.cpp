// Fuzz target: the lesson parser (lessons/*.toml) on arbitrary bytes. A lesson parses or is
// refused with one InputError line; nothing else may escape, crash or leak.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "base/input_error.h"
#include "lesson/lesson.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        pcf::Lesson lesson = pcf::parseLessonString(text, "fuzz.toml");
        (void)lesson;
    } catch (const pcf::InputError& e) {
        pcf::fuzz::requireOneLine(e.what());
    }
    return 0;
}
