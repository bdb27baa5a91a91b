// SPDX-License-Identifier: GPL-2.0-or-later
// The warning the commands print before they solve a scene whose grid does not resolve its
// interaction (asp_system_check_resolution): run, run --check, compare and sweep.
#pragma once

#include <cstdio>

#include "contact.hpp"

namespace cli {

// One line, "warning           <the library's sentence>", when the scene's interaction is not
// resolved by its grid; nothing when it is, or when there is nothing to resolve.
void print_resolution(std::FILE *out, const Contact &contact);

}  // namespace cli
