// SPDX-License-Identifier: GPL-2.0-or-later
// ASPERITY_TEST_UNDER_ASAN is defined in a build with AddressSanitizer (GCC's
// __SANITIZE_ADDRESS__, Clang's __has_feature), for the cases that cannot run there.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define ASPERITY_TEST_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ASPERITY_TEST_UNDER_ASAN 1
#endif
#endif
