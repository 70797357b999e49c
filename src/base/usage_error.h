// usage_error.h: bad input on the command line, or a name on it that names nothing (a lesson, a
// scene). The app prints what() on one line and exits 2 (docs/user-guide.md, "Files, errors and
// interrupts"), as for InputError.
#pragma once

#include <stdexcept>

namespace pcf {

class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace pcf
