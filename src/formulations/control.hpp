// SPDX-License-Identifier: GPL-2.0-or-later
// What a solve holds fixed: the mean pressure (load), the penetration, or the mean gap.
#pragma once

namespace asp {

enum class Control { mean_pressure, penetration, mean_gap };
const char *control_name(Control control);

}  // namespace asp
