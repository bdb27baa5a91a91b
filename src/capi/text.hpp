// SPDX-License-Identifier: GPL-2.0-or-later
// Copying the library's texts into a caller's buffer, the same way for every call that
// returns one (see asp_algorithms in the public header).
#pragma once

#include <cstdint>
#include <string>

namespace asp {
namespace capi {

// Writes as much of text as fits (always NUL-terminated when size > 0), sets *length (if not
// NULL) to the text's full length, and throws Error(size_mismatch) if it was cut.
void copy_text(const std::string &text, char *buffer, std::int64_t size, std::int64_t *length);

}  // namespace capi
}  // namespace asp
