// SPDX-License-Identifier: GPL-2.0-or-later
#include "capi/text.hpp"

#include <algorithm>
#include <cstring>

#include "core/checks.hpp"
#include "core/error.hpp"

namespace asp {
namespace capi {

void copy_text(const std::string &text, char *buffer, std::int64_t size, std::int64_t *length) {
  require_at_least(size, 0, "size");
  if (size > 0) require_not_null(buffer, "buffer");
  const auto full = static_cast<std::int64_t>(text.size());
  if (length != nullptr) *length = full;
  if (size > 0) {
    const std::int64_t copied = std::min(full, size - 1);
    std::memcpy(buffer, text.data(), static_cast<std::size_t>(copied));
    buffer[copied] = '\0';
  }
  if (full >= size && !(size == 0 && length != nullptr))
    throw Error(Status::size_mismatch, "argument 'size' is " + std::to_string(size) +
                                           ": the text needs " + std::to_string(full + 1) +
                                           " bytes with its NUL");
}

}  // namespace capi
}  // namespace asp
