#pragma once
// CAPSIM_ADDRESS_SANITIZER is defined in a build under AddressSanitizer, with
// its LeakSanitizer: GCC says so with __SANITIZE_ADDRESS__, clang with
// __has_feature(address_sanitizer).

#if defined(__SANITIZE_ADDRESS__)
#define CAPSIM_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CAPSIM_ADDRESS_SANITIZER 1
#endif
#endif
