// Whether this test binary is built with AddressSanitizer: gcc defines
// __SANITIZE_ADDRESS__, clang answers __has_feature(address_sanitizer)
// (scripts/sanitize-tests.sh builds with clang).
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define PMAP_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PMAP_TEST_ASAN 1
#endif
#endif
#ifndef PMAP_TEST_ASAN
#define PMAP_TEST_ASAN 0
#endif
