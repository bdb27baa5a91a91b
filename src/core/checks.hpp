// SPDX-License-Identifier: GPL-2.0-or-later
// Argument checks shared by the library's entry points. Each throws Error with a message that
// names the argument, the value and the rule it broke.
#pragma once

#include <cstdint>
#include <string>

namespace asp {

void require_finite(double value, const char *name);
void require_positive(double value, const char *name);      // finite and > 0
void require_non_negative(double value, const char *name);  // finite and >= 0
void require_at_least(std::int64_t value, std::int64_t minimum, const char *name);
void require_not_null(const void *pointer, const char *name);
// A caller's array: not NULL, count equal to what the grid needs, and (for inputs) finite.
void require_array(const void *pointer, std::int64_t count, std::int64_t expected,
                   const char *name);
void require_finite_array(const double *values, std::int64_t count, const char *name);

std::string format_number(double value);

}  // namespace asp
