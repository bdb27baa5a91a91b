// SPDX-License-Identifier: GPL-2.0-or-later
#include "formulations/control.hpp"

namespace asp {

const char *control_name(Control control) {
  switch (control) {
    case Control::mean_pressure: return "mean_pressure";
    case Control::penetration: return "penetration";
    case Control::mean_gap: return "mean_gap";
  }
  return "unknown";
}

}  // namespace asp
