// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/checks.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/error.hpp"

namespace asp {

std::string format_number(double value) {
  // The shortest of 15, 16 or 17 significant digits that reads back as the same double, so
  // that 1e300 prints as 1e+300 and not as 1.0000000000000001e+300.
  char buffer[64];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    if (std::strtod(buffer, nullptr) == value || !std::isfinite(value)) break;
  }
  return buffer;
}

void require_finite(double value, const char *name) {
  if (!std::isfinite(value))
    throw Error(Status::invalid_argument,
                std::string("argument '") + name + "' must be finite, got " + format_number(value));
}

void require_positive(double value, const char *name) {
  require_finite(value, name);
  if (!(value > 0.0))
    throw Error(Status::invalid_argument,
                std::string("argument '") + name + "' must be > 0, got " + format_number(value));
}

void require_non_negative(double value, const char *name) {
  require_finite(value, name);
  if (value < 0.0)
    throw Error(Status::invalid_argument,
                std::string("argument '") + name + "' must be >= 0, got " + format_number(value));
}

void require_at_least(std::int64_t value, std::int64_t minimum, const char *name) {
  if (value < minimum)
    throw Error(Status::invalid_argument, std::string("argument '") + name + "' must be >= " +
                                              std::to_string(minimum) + ", got " +
                                              std::to_string(value));
}

void require_not_null(const void *pointer, const char *name) {
  if (pointer == nullptr)
    throw Error(Status::null_pointer, std::string("argument '") + name + "' is NULL");
}

void require_array(const void *pointer, std::int64_t count, std::int64_t expected,
                   const char *name) {
  // A process without rows of a distributed grid passes no array (any pointer, count 0).
  if (expected == 0 && count == 0) return;
  require_not_null(pointer, name);
  if (count != expected)
    throw Error(Status::size_mismatch, std::string("array '") + name + "' has count " +
                                           std::to_string(count) + " but the grid needs " +
                                           std::to_string(expected));
}

void require_finite_array(const double *values, std::int64_t count, const char *name) {
  for (std::int64_t i = 0; i < count; ++i)
    if (!std::isfinite(values[i]))
      throw Error(Status::invalid_argument, std::string("array '") + name + "' has " +
                                                format_number(values[i]) + " at index " +
                                                std::to_string(i) + "; values must be finite");
}

}  // namespace asp
