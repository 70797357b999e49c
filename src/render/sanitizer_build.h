// sanitizer_build.h: PCFSCOPE_ASAN is 1 in AddressSanitizer builds (scripts/test --sanitize,
// scripts/fuzz) and 0 otherwise, for the few places that behave differently there
// (render/driver_pin.cpp, render/image_io.cpp, and the tests that expect it).
#pragma once

// gcc defines __SANITIZE_ADDRESS__; clang has the feature test.
#if defined(__SANITIZE_ADDRESS__)
#define PCFSCOPE_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PCFSCOPE_ASAN 1
#endif
#endif
#ifndef PCFSCOPE_ASAN
#define PCFSCOPE_ASAN 0
#endif
