// driver_pin.h: keeps the GL driver's libraries mapped until exit in sanitizer builds, so that
// LeakSanitizer can see (and tests/sanitize/lsan.supp can name) what the driver leaves allocated.
//
// LeakSanitizer reports what is still allocated at exit. By then the EGL vendor library (at
// eglTerminate) or GLFW (at glfwTerminate, which dlcloses libGL) has unloaded Mesa's driver, so a
// block the driver allocated has a stack of bare addresses in no mapped module: no suppression
// can name it, and llvmpipe's two 56-byte blocks held in its static data read as a leak. Marked
// RTLD_NODELETE, every library that making a context loaded (the vendor library, the DRI
// driver, LLVM) stays mapped, the blocks stay reachable from its data, and nothing is reported.
// Outside sanitizer builds both functions do nothing.
#pragma once

#include <set>
#include <string>

namespace pcf {

// The shared objects mapped into the process now, by path (empty outside sanitizer builds).
std::set<std::string> mappedLibraries();

// Marks RTLD_NODELETE every library mapped now that was not in `before`.
void pinLibrariesLoadedSince(const std::set<std::string>& before);

}  // namespace pcf
