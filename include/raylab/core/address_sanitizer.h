#pragma once
/// \file
/// Whether this translation unit is compiled with AddressSanitizer: RAYLAB_ADDRESS_SANITIZER is
/// defined (as 1) under GCC's and clang's -fsanitize=address and left undefined otherwise. GCC
/// says so with __SANITIZE_ADDRESS__, clang with __has_feature(address_sanitizer).

#if defined(__SANITIZE_ADDRESS__)
#define RAYLAB_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RAYLAB_ADDRESS_SANITIZER 1
#endif
#endif
