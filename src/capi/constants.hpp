// SPDX-License-Identifier: GPL-2.0-or-later
// The families of public constants (planning, normalisations, scalar keys, fields, controls,
// history columns, termination reasons, detrending modes, solver report keys) and the one check every entry point uses: a value is
// accepted only where its own family is expected, and a value of another family is named as
// such in the message, never misread.
#pragma once

namespace asp {
namespace capi {

enum class Family {
  planning,
  normalisation,
  scalar_key,
  field,
  control,
  history_column,
  termination,
  detrend,
  report_key,
};

// Throws Error(invalid_argument) naming `argument`, the value, the family it belongs to (if
// any) and the members of `expected`, unless `value` is a member of `expected`.
void require_member(int value, Family expected, const char *argument);

}  // namespace capi
}  // namespace asp
