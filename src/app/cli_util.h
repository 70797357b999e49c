// cli_util.h: parsing of the command line's small values, with one-line errors.
#pragma once

#include <stdexcept>
#include <string>

#include <glm/glm.hpp>

namespace pcf {

// Bad input on the command line or in a file: the app prints what() on one line and exits 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// "0.25,0.5" -> (0.25, 0.5); throws UsageError naming the option on anything else, NaN included.
glm::vec2 parseVec2(const std::string& option, const std::string& text);
// "1280x720" -> (1280, 720); each side 1..maxSide.
glm::ivec2 parseSize(const std::string& option, const std::string& text, int maxSide);
// "12,34" -> (12, 34).
glm::ivec2 parseIvec2(const std::string& option, const std::string& text);
// Throws UsageError unless lo <= v <= hi and v is finite.
void requireRange(const std::string& option, float v, float lo, float hi);

}  // namespace pcf
